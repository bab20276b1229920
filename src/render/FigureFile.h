#pragma once
// Writing a painted figure to a file: PNG (a raster of the figure's pixel size), SVG (vector,
// the figure's pixels as user units) or PDF (a page of the figure's proportions, 180 mm wide,
// 300 dpi), chosen by the file's suffix. Layer: render (QtGui + QtSvg). Used by every figure
// writer so that the formats behave the same everywhere.

#include <QSize>
#include <QString>

#include <functional>

class QPainter;

namespace awb {

// `paint` draws the figure into the rectangle (0, 0, size) of the painter. False with *error
// set when the suffix is unknown or the file cannot be written.
bool writePaintedFigure(const QString &fileName, QSize size, const QString &title,
                        const std::function<void(QPainter &)> &paint, QString *error);

} // namespace awb
