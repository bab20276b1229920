#pragma once
// Writing a painted figure to a file: PNG (a raster of the figure's pixel size), SVG (vector,
// the figure's pixels as user units) or PDF (a page of the figure's proportions, 180 mm wide,
// 300 dpi), chosen by the file's suffix. Layer: render (QtGui + QtSvg). Used by every figure
// writer so that the formats behave the same everywhere.

#include <QByteArray>
#include <QList>
#include <QPair>
#include <QRectF>
#include <QSize>
#include <QString>

#include <functional>

class QIODevice;
class QImage;
class QPainter;

namespace awb {

class Item;
class Project;

// What a figure file carries besides the picture (model/FigureMetadata.h makes it: the item's
// project, the program's version): PNG text chunks, an SVG <metadata> element.
struct FigureMetadata {
    QList<QPair<QString, QString>> pngText;
    QByteArray svgElement;
};

// The metadata of a figure of `item`: its project (the item with the items it reads), so that
// File > Open and every attractor-cli command open the PNG or SVG as the project it was made
// from. Every face writes it through this one function.
FigureMetadata itemFigureMetadata(const Project &project, const Item &item);

// How a painted figure goes into its file besides its pixels.
struct PaintedFigureOptions {
    QString title;
    FigureMetadata metadata;
    QString format;  // "png", "svg", "pdf"; empty: the file's suffix
    // A print resolution (the window's export): the PNG's dots per metre, the SVG's
    // resolution, a PDF page of `size` at this many dots per inch. None: a PDF page 180 mm
    // wide at 300 dpi (the command line's figures).
    int dpi = 0;
    // What `paint` draws into, in its own coordinates (the SVG's viewBox); empty: (0, 0, size).
    QRectF viewBox;
    bool antialias = false;  // the PNG painter's hint (figure painters set their own)
    // Asked after painting: true drops the file (a cancelled export).
    std::function<bool()> cancelled;
};

// `paint` draws the figure into the rectangle (0, 0, size) of the painter: PNG, SVG or PDF by
// the format or the file's suffix -- the one switch of the formats, for every figure writer.
// False with *error set when the format is unknown, the drawing was cancelled or the file
// cannot be written (an existing file is then left as it was).
bool writePaintedFigure(const QString &fileName, QSize size,
                        const std::function<void(QPainter &)> &paint, QString *error,
                        const PaintedFigureOptions &options = {});

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
