#pragma once
// Writing a painted figure to a file: PNG (a raster of the figure's pixel size), SVG (vector,
// the figure's pixels as user units) or PDF (a page of the figure's proportions, 180 mm wide,
// 300 dpi), chosen by the file's suffix. Layer: render (QtGui + QtSvg). Used by every figure
// writer so that the formats behave the same everywhere.

#include <QByteArray>
#include <QList>
#include <QPair>
#include <QSize>
#include <QString>

#include <functional>

class QImage;
class QPainter;

namespace awb {

// What a figure file carries besides the picture (model/FigureMetadata.h makes it: the item's
// project, the program's version): PNG text chunks, an SVG <metadata> element.
struct FigureMetadata {
    QList<QPair<QString, QString>> pngText;
    QByteArray svgElement;
};

// `paint` draws the figure into the rectangle (0, 0, size) of the painter. False with *error
// set when the suffix is unknown or the file cannot be written.
bool writePaintedFigure(const QString &fileName, QSize size, const QString &title,
                        const std::function<void(QPainter &)> &paint, QString *error,
                        const FigureMetadata &metadata = {});
// The two halves, for writers of their own: text chunks into an image about to be saved as
// PNG; the element inserted after <svg ...> of a written SVG file (false with *error).
void addPngText(QImage &image, const FigureMetadata &metadata);
bool addSvgMetadata(const QString &svgFile, const FigureMetadata &metadata, QString *error);

} // namespace awb
