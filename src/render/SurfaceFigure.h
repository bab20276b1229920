#pragma once
// Pictures of surface attractors (000 §3) for files, print and tests: the core's CPU
// SurfaceRaster (z-buffered, shaded, coloured by map) filled on worker threads, with the
// control net drawn over it and a caption naming the view. Layer: render (QtGui + QtSvg, no
// widgets), shared by the CLI and the desktop application's print and export, so that every
// route draws the same figure from the same camera.

#include "render/FigureFile.h"
#include "core/ifs/Attractor.h"
#include "core/render/SurfaceRaster.h"

#include <QColor>
#include <QImage>
#include <QString>

#include <atomic>
#include <functional>
#include <vector>

namespace awb {

struct SurfaceFigureSpec {
    QString caption;                 // under the picture; empty: none
    const Ifs *ifs = nullptr;        // views project to R^3
    // Items drawn by their own iteration (mesh items, DerivedIfs::iterate): used instead of
    // iterating `ifs`, whose views still say how a point is drawn.
    std::function<IterationStats(const StartSet &, int, const std::vector<AttractorSink *> &,
                                 const IterationControl &)>
        iterate;
    StartSet start;
    int depth = 6;                   // deterministic iteration
    bool random = false;             // chaos game instead
    std::uint64_t samples = 200000;
    std::uint64_t seed = 1;
    std::vector<int> mapColors;      // colour index of each IFS map (empty: the map index)
    std::vector<QColor> palette;     // colour of each colour index (cycled)
    double pointRadius = 1.0;        // pixels, for point start sets
    double azimuth = -60.0;          // degrees (OrthoCamera)
    double elevation = 30.0;
    Mat framePoints;                 // n x 3 that the camera must show (e.g. the net); optional
    Mat netPoints;                   // control net drawn over the picture (m x 3), optional
    std::vector<std::vector<int>> netFaces;  // its faces (indices into netPoints)
    int width = 900;
    int height = 700;
    int threads = 0;                 // 0: the machine's cores
    FigureMetadata metadata;         // written into PNG and SVG files (the item's project)
    IterationControl control;        // the iteration's cancel flag and progress
};

// The camera SurfaceFigureSpec's picture uses: fitted to framePoints and a coarse iterate.
OrthoCamera surfaceCamera(const SurfaceFigureSpec &spec, int pictureHeight);
// The picture (width x height, caption included). Returns a null image when spec.control's
// cancel flag stopped it.
QImage renderSurfaceFigure(const SurfaceFigureSpec &spec, IterationStats *stats = nullptr);
// PNG, or SVG/PDF with the picture embedded as a lossless raster, by the file's suffix.
// `format` (png, svg, pdf) defaults to the file's suffix.
bool writeSurfaceFigure(const SurfaceFigureSpec &spec, const QString &fileName, QString *error,
                        const QString &format = {});

} // namespace awb
