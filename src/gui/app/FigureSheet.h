#pragma once
// FigureSheet: the printed figure of the current item, one page: a caption (item name, scheme,
// parameters), the attractor with its control polygon, the spectrum plot and the matrices.
// It paints on any QPainter (printer, print preview, PDF writer, SVG), keeping vector content
// vector: the attractor's overlays come from AttractorView::renderTo, the spectrum plot is
// recorded as a QPicture of QCustomPlot's own drawing, and the matrices are text.
#include "core/Types.h"
#include "model/NamedMatrix.h"

#include <QCoreApplication>
#include <QFont>
#include <QList>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QStringList>

class QPainter;
class QPagedPaintDevice;

namespace awb {

class AttractorView;
class CharacteristicMapView;
class Item;
class MatrixView;
class SpectrumView;
class SurfaceView;

class FigureSheet {
    Q_DECLARE_TR_FUNCTIONS(awb::FigureSheet)
public:
    // `surface` draws the figure of items with 3D points (at its current camera).
    FigureSheet(Item *item, AttractorView *attractor, SpectrumView *spectrum,
                SurfaceView *surface = nullptr);

    // A mesh's focused extraordinary vertex (issue 31): its local subdivision matrix replaces
    // the mesh's matrices, and its characteristic map is drawn in a corner of the figure.
    void setVertex(QList<NamedMatrix> matrices, const CharacteristicMapView *map)
    {
        m_vertexMatrices = std::move(matrices);
        m_characteristic = map;
    }

    // The caption's lines: item name and kind, then "label = value" of every parameter.
    QStringList caption() const;
    // Paints the sheet into `page` (device coordinates of `painter`).
    void paint(QPainter *painter, const QRectF &page) const;
    // Paints one page on a printer or PDF writer (begins and ends its own painter). False
    // when the device fails or the user cancelled drawing the attractor (a printer job is
    // then aborted).
    bool print(QPagedPaintDevice *device) const;
    // Whether the last paint lost its attractor to a cancel (AttractorView::exportCancelled).
    bool cancelled() const;
    // Writes the sheet as a one-page A4 landscape PDF. False with a message on failure.
    bool writePdf(const QString &fileName, QString *error = nullptr) const;

    // The matrices' font size in device pixels and how many were shown, at the last paint.
    int matrixFontPixels() const { return m_matrixFontPixels; }
    int matricesShown() const { return m_matricesShown; }

private:
    // One block per matrix: its text lines, or for a large one (a surface's 19 x 19 S_i) a
    // title line and the matrix drawn as a heat map of its entries.
    struct MatrixBlock {
        QStringList lines;
        Mat heat;
    };
    QList<MatrixBlock> matrixBlocks() const;
    // Where the matrices go in `box`: blocks placed in columns at the largest font that fits,
    // not below 8 pt; `shown` of them fit.
    struct MatrixLayout {
        QRectF box;
        QFont font;
        QList<MatrixBlock> blocks;
        QList<QPointF> at;
        int shown = 0;
        double cell = 0;  // a heat map's cell in device pixels
    };
    MatrixLayout layoutMatrices(QPainter *painter, const QRectF &box, QFont mono) const;
    void paintMatrices(QPainter *painter, const MatrixLayout &layout) const;

    Item *m_item;
    AttractorView *m_attractor;
    SpectrumView *m_spectrum;
    SurfaceView *m_surface;
    QList<NamedMatrix> m_vertexMatrices;
    const CharacteristicMapView *m_characteristic = nullptr;
    mutable int m_matrixFontPixels = 0;
    mutable int m_matricesShown = 0;
};

// Paints the spectrum plot into `target` as vectors (QCustomPlot records into a QPicture).
void paintSpectrum(SpectrumView *view, QPainter *painter, const QRectF &target);

} // namespace awb
