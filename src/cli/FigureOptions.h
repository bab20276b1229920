#pragma once
// The command-line options of attractor-cli render and animate: how a figure of an item is
// drawn, read into the FigureOptions of render/ItemFigure.h (which draws it).

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QList>

#include "render/ItemFigure.h"

namespace awb::cli {

// The options of `render` that `animate` shares.
QList<QCommandLineOption> figureOptionList();
// The frame's two of them, --size and --bounds (export --format flame takes these too), and
// their reading into o.width, o.height and o.bounds.
QList<QCommandLineOption> frameOptionList();
void readFrameOptions(const QCommandLineParser &parser, FigureOptions &o);
// Reads them (Failure for a value out of range).
FigureOptions figureOptions(const QCommandLineParser &parser);

} // namespace awb::cli
