#pragma once
// The figure of one item (layer 3, render; QtGui only): how `attractor-cli render` and
// `animate`, Python's Item.render() and the benches draw an item to a file -- a plane attractor
// with its control polygons, a surface or mesh in an orthographic view, or the raw density of
// an attractor (float32 EXR, 16-bit PNG). One implementation behind every face: the CLI reads
// its options into a FigureOptions, Python fills one from its arguments.

#include <QRectF>
#include <QString>

#include <atomic>
#include <cstdint>
#include <optional>
#include <utility>

#include "render/DensityFile.h"

namespace awb {

struct RawDensity {
    AttractorDensity density;
    DensityFileInfo info;   // the frame's world rectangle, caption and project
};

class AttractorItem;
class Project;

struct FigureOptions {
    int width = 900, height = 700;
    bool sizeGiven = false;  // width and height asked for (not the default)
    std::optional<int> depth;               // default: the item's
    std::optional<std::uint64_t> samples;   // random iteration with this many points
    std::optional<std::uint64_t> seed;      // its seed (default: the item's)
    QString tone;  // "", "hits" or "density"
    std::optional<double> gamma;
    double vibrancy = 1.0;
    int supersample = 1;
    int threads = 0;
    // Surfaces and meshes: azimuth and elevation in degrees (|elevation| <= 90); none: the
    // item's camera.
    std::optional<std::pair<double, double>> view;
    QRectF bounds;  // the world rectangle to frame; invalid: fit the content
    QString captionSuffix;  // e.g. an animation frame's time and values
    QString format;  // "", "png", "svg", "pdf" or "exr" (empty: the file's suffix)
    int bits = 8;    // PNG: 8 (the figure) or 16 (the raw log density, render/DensityFile.h)
    // Set to stop the attractor's raster early (Python's render on Ctrl+C): the figure is then
    // not written and renderItemFigure throws.
    const std::atomic<bool> *cancel = nullptr;
    // Called with the fraction of the attractor's iteration done, from worker threads (the
    // CLI's progress line).
    std::function<void(double)> progress;
    // Set: the raw density (format "exr") is returned here instead of written to a file --
    // one chunk of a render split over a cluster's workers (python/attractor_workbench/
    // render.py), whose sum the module writes with writeDensityExr / writeDensityPng16.
    struct RawDensity *rawDensity = nullptr;
};

// Draws `item` (of `project`, or a copy of one of its items: an animation frame) and writes
// the figure to `outFile` (PNG, SVG, PDF by o.format or the suffix; EXR and 16-bit PNG: the
// attractor's raw density in the figure's frame, render/DensityFile.h); with `measure`, only
// the world rectangle of the content is measured into it (invalid for surfaces). Throws
// InputError with a message for the user (the item cannot be drawn, the file cannot be
// written, the drawing was cancelled).
void renderItemFigure(const Project &project, AttractorItem *item, const FigureOptions &o,
                      const QString &outFile, QRectF *measure = nullptr);

} // namespace awb
