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

class QIODevice;
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
// set when the format is unknown or the file cannot be written. `format` ("png", "svg",
// "pdf") defaults to the file's suffix (give it for a name without one, such as /dev/full).
bool writePaintedFigure(const QString &fileName, QSize size, const QString &title,
                        const std::function<void(QPainter &)> &paint, QString *error,
                        const FigureMetadata &metadata = {}, const QString &format = {});

// Every figure file is written through this: `write` writes the figure into `out` (a buffer
// in memory, open for writing: Qt's image, SVG and PDF writers do not all report a failed
// write to a file), and the bytes then replace `fileName` whole (model/FileWriting.h): a
// failed or cancelled export leaves an existing file as it was. `write` returns false, with
// *error set or left empty ("cannot write"). On failure *error reads "cannot write FILE: …".
// A missing folder or a read-only file is refused before `write` runs.
bool writeFigureFile(const QString &fileName,
                     const std::function<bool(QIODevice &out, QString *error)> &write,
                     QString *error);

// PNG bytes of `image` (its text chunks included) into `out`.
bool writePng(const QImage &image, QIODevice &out);

// The writers' halves: text chunks into an image about to be written as PNG; the metadata
// element inserted after <svg ...> of SVG bytes (false when they hold no <svg> element).
void addPngText(QImage &image, const FigureMetadata &metadata);
bool addSvgMetadata(QByteArray &svg, const FigureMetadata &metadata);

} // namespace awb
