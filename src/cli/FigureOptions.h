#pragma once
// How a figure of an item is drawn (attractor-cli render and animate): the options both take,
// and the drawing of one item to a file -- a plane attractor, a surface or a mesh.

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QList>
#include <QRectF>
#include <QString>

#include <atomic>
#include <cstdint>
#include <optional>

namespace awb {
class AttractorItem;
class Project;
} // namespace awb

namespace awb::cli {

struct FigureOptions {
    int width = 900, height = 700;
    std::optional<int> depth;
    std::optional<std::uint64_t> samples;
    QString tone;  // "", "hits" or "density"
    std::optional<double> gamma;
    double vibrancy = 1.0;
    int supersample = 1;
    int threads = 0;
    QString view;  // "az,el" or empty
    QRectF bounds;  // the world rectangle to frame; invalid: fit the content
    QString captionSuffix;  // e.g. an animation frame's time and values
    QString format;  // "", "png", "svg", "pdf" or "exr"
    int bits = 8;    // PNG: 8 (the figure) or 16 (the raw log density, render/DensityFile.h)
    // Set to stop the attractor's raster early (attractor_workbench's render on Ctrl+C): the
    // figure is then not written and renderFigure throws Failure.
    const std::atomic<bool> *cancel = nullptr;
};

// The options of `render` that `animate` shares.
QList<QCommandLineOption> figureOptionList();
// The frame's two of them, --size and --bounds (export --format flame takes these too), and
// their reading into o.width, o.height and o.bounds.
QList<QCommandLineOption> frameOptionList();
void readFrameOptions(const QCommandLineParser &parser, FigureOptions &o);
// Reads them (Failure for a value out of range).
FigureOptions figureOptions(const QCommandLineParser &parser);
// Draws `item` into `outFile` (PNG, SVG, PDF by o.format or the suffix; EXR and 16-bit PNG:
// the attractor's raw density in the figure's frame); with `measure`, only the bounds of the
// content are measured into it.
void renderFigure(const Project &project, AttractorItem *item, const FigureOptions &o,
                  const QString &outFile, QRectF *measure = nullptr);

} // namespace awb::cli
