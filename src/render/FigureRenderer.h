#pragma once
// Renders attractor figures the way the papers show them: one or more panels with the control
// polygon(s) and the iterates X_0, F(X_0), ..., F^k(X_0) of a start set, or a random-iteration
// picture. Paints on any QPainter, so the same figure goes to PNG, SVG or PDF (vector shapes
// where the content is vector: polygons, shallow levels; a raster for deep levels). Used by
// the CLI; QtGui (+ QtSvg for SVG files) only, no widgets.

#include "core/ifs/Attractor.h"
#include "render/AttractorImage.h"
#include "render/FigureFile.h"

#include <QColor>
#include <QImage>
#include <QRectF>
#include <QString>
#include <atomic>
#include <functional>
#include <vector>

class QPainter;

namespace awb {

struct FigurePanel {
    QString caption;
    int depth = 0;
};

// Streams F^depth(start) to sinks (one per thread), like awb::iterateParallel.
using IterateFn = std::function<IterationStats(const StartSet &, int, const std::vector<AttractorSink *> &,
                                               const IterationControl &)>;

struct FigureSpec {
    QString title;
    const Ifs *ifs = nullptr;          // maps (may be empty when `iterate` or `polygon` is set)
    std::vector<Projection> views;     // how IFS points are drawn (defaults to ifs->views)
    IterateFn iterate;                 // custom deterministic iteration (automata)
    CustomChaos chaos;                 // a chaos game of the item's own (a flame), random only
    StartSet start;
    bool random = false;               // chaos game instead of deterministic iteration
    std::uint64_t samples = 200000;
    std::uint64_t seed = 1;
    std::vector<Mat> controlPolygons;  // m x 2 each, drawn dashed with square handles
    std::vector<bool> controlClosed;   // per control polygon: closed (missing entries: open)
    std::vector<Mat> overlays;         // e.g. the exact curve (n x 2), a grey band underneath
    std::vector<Mat> polygons;         // figures that are polygons (normal-vector curves)
    std::vector<bool> polygonsClosed;  // per polygon: closed (missing entries: open)
    std::vector<FigurePanel> panels;
    AttractorColouring colouring;      // the attractor's colours (default: by map)
    // Raster panels (deep levels, random iteration): hits or log density, anti-aliasing, threads.
    ToneSettings tone;
    int supersample = 1;
    int threads = 0;
    int panelWidth = 420;
    int panelHeight = 360;
    // The world rectangle to frame (padded like the content); invalid: fit the content. Frames
    // of an animation share one, so that the attractor moves and the frame stays.
    QRectF bounds;
    FigureMetadata metadata;           // written into PNG and SVG files (the item's project)
    const std::atomic<bool> *cancel = nullptr;  // stops the raster panels' iteration
    std::function<void(double)> progress;       // their fraction done (from worker threads)
};

// Colour of map i (by address): a qualitative palette that reads on white and in print.
QColor mapColor(int i);

// The world rectangle of what the figure draws (attractor at a shallow level, start set,
// polygons), unpadded; a negative size when there is nothing.
QRectF contentBounds(const FigureSpec &spec);
// The world rectangle a panel of `target` pixels shows of `content` (contentBounds or the
// --bounds): padded by 6% of its larger side, centred, one scale on both axes (y up).
QRectF figureWorld(const QRectF &content, const QSizeF &target);
// Size of the whole figure in pixels (panels side by side, title, captions).
QSize figureSize(const FigureSpec &spec);
// Paints the figure into the rectangle (0, 0, figureSize) of the painter's device.
void paintFigure(QPainter &painter, const FigureSpec &spec);
QImage renderFigure(const FigureSpec &spec);
// Writes PNG, SVG or PDF by the file's suffix; false with *error set on failure.
// `format` (png, svg, pdf) defaults to the file's suffix.
bool writeFigure(const FigureSpec &spec, const QString &fileName, QString *error,
                 const QString &format = {});

} // namespace awb
