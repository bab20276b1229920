#include "gui/app/FigureSheet.h"

#include "gui/views/VertexPanel.h"

#include "gui/views/MatrixHeatMap.h"

#include "render/FigureFile.h"

#include "gui/app/ItemController.h"
#include "gui/views/AttractorView.h"
#include "gui/views/SurfaceView.h"
#include "gui/views/MatrixView.h"
#include "model/NumberFormat.h"
#include "gui/views/SpectrumView.h"
#include "model/AttractorItem.h"
#include "model/AutomatonAnalysisJson.h"
#include "model/CifsItem.h"

#include <QFile>
#include <QFileInfo>
#include <QFontMetricsF>
#include <QPageLayout>
#include <QPainter>
#include <QPdfWriter>
#include <QPicture>
#include <QPrinter>
#include <qcustomplot.h>
#include <cmath>

namespace awb {

namespace {

QString valueText(const ParameterInfo &p, const QVariant &v)
{
    switch (p.type) {
    case ParameterInfo::Type::Choice: {
        const int i = v.toInt();
        return i >= 0 && i < p.choices.size() ? p.choices[i] : QString::number(i);
    }
    case ParameterInfo::Type::Complex: {
        const QPointF z = v.toPointF();
        return QStringLiteral("%1 %2 %3i")
            .arg(z.x(), 0, 'g', 6)
            .arg(z.y() < 0 ? QLatin1Char('-') : QLatin1Char('+'))
            .arg(std::abs(z.y()), 0, 'g', 6);
    }
    case ParameterInfo::Type::Bool:
        return v.toBool() ? FigureSheet::tr("yes") : FigureSheet::tr("no");
    case ParameterInfo::Type::Integer: return QString::number(v.toInt());
    case ParameterInfo::Type::Real: return QString::number(v.toDouble(), 'g', 8);
    case ParameterInfo::Type::Text: return v.toString();
    }
    return v.toString();
}

} // namespace

void paintSpectrum(SpectrumView *view, QPainter *painter, const QRectF &target)
{
    if (!view || target.isEmpty())
        return;
    // Record the plot at a pixel size like the screen's so fonts and markers keep their
    // proportions, then scale the recording into the target.
    const double aspect = target.width() / target.height();
    // 320 pixels high: the legend's and the labels' text stays legible on paper.
    const int h = 320, w = std::max(200, int(h * aspect));
    QPicture picture;
    {
        QCPPainter recorder(&picture);
        view->paintPlot(&recorder, w, h);
    }
    painter->save();
    painter->translate(target.topLeft());
    painter->scale(target.width() / w, target.height() / h);
    // Playing a picture scales it by the device's resolution over the recording's: undo that,
    // the scale above already maps the recorded pixels onto the target.
    if (QPaintDevice *device = painter->device()) {
        const double k = double(picture.logicalDpiX()) / double(device->logicalDpiX());
        const double l = double(picture.logicalDpiY()) / double(device->logicalDpiY());
        painter->scale(k, l);
    }
    painter->drawPicture(0, 0, picture);
    painter->restore();
}

FigureSheet::FigureSheet(Item *item, AttractorView *attractor, SpectrumView *spectrum,
                         SurfaceView *surface)
    : m_item(item), m_attractor(attractor), m_spectrum(spectrum), m_surface(surface)
{
}

QStringList FigureSheet::caption() const
{
    if (!m_item)
        return {tr("No item")};
    QStringList lines;
    lines << tr("%1 (%2)").arg(m_item->name(), m_item->typeName());
    QStringList params;
    for (const ParameterInfo &p : m_item->parameters())
        params << QStringLiteral("%1 = %2").arg(p.label, valueText(p, m_item->parameter(p.key)));
    if (const auto *a = qobject_cast<const AttractorItem *>(m_item)) {
        params << tr("maps = %1").arg(a->mapCount());
        if (a->controlPointSetCount() > 0) {
            QStringList counts; // per point set: "4 + 3" for the two curves of a junction
            for (int k = 0; k < a->controlPointSetCount(); ++k)
                counts << QString::number(a->controlPoints(k).size());
            params << tr("control points = %1").arg(counts.join(QStringLiteral(" + ")));
        }
        params << (a->algorithm().mode == AlgorithmSpec::Mode::Deterministic
                       ? tr("depth = %1").arg(a->algorithm().depth)
                       : tr("samples = %1").arg(a->algorithm().samples));
    }
    lines << params.join(QStringLiteral(";  "));
    // An automaton: what it contracts by (issue 46), one line each.
    if (const auto *cifs = qobject_cast<const CifsItem *>(m_item))
        lines << automatonSummary(*cifs, 0);
    return lines;
}

QList<FigureSheet::MatrixBlock> FigureSheet::matrixBlocks() const
{
    QList<MatrixBlock> blocks;
    const auto *a = qobject_cast<const AttractorItem *>(m_item);
    const auto d = a ? a->derivedIfs() : nullptr;
    if (!d)
        return blocks;
    // The matrix view's matrices, as text with right-aligned columns: fractions where exact
    // (3/8 reads better than 0.375), complex entries as a + bi. One block per matrix.
    for (const NamedMatrix &m : m_vertexMatrices.isEmpty() ? namedMatrices(*d) : m_vertexMatrices) {
        // A surface's S_i (16 x 16 and up) as text would shrink the page's text to dust: as a
        // heat map of its entries, as the Matrices dock shows them above their tables.
        if (m.rows() > 12 && !m.isComplex()) {
            blocks << MatrixBlock{{tr("%1 (%2 × %3):").arg(subscriptName(m.name)).arg(m.rows())
                                       .arg(m.cols())},
                                  m.values};
            continue;
        }
        QList<QStringList> cells;
        int width = 1;
        for (Eigen::Index r = 0; r < m.rows(); ++r) {
            QStringList row;
            for (Eigen::Index c = 0; c < m.cols(); ++c) {
                const QString t = m.isComplex() ? formatComplex(m.complexValues(r, c), 5)
                                                : formatNumber(m.values(r, c), 5);
                width = std::max(width, int(t.size()));
                row << t;
            }
            cells << row;
        }
        QStringList block{subscriptName(m.name) + QLatin1Char(':')};
        for (const QStringList &row : std::as_const(cells)) {
            QString line;
            for (const QString &t : row)
                line += t.rightJustified(width + 2);
            block << line;
        }
        blocks << MatrixBlock{block, {}};
    }
    return blocks;
}

void FigureSheet::paint(QPainter *painter, const QRectF &area) const
{
    painter->save();
    const double unit = area.width() / 100.0;  // 1% of the page width
    // A margin on every side: a picture has none of its own (a printer's page adds its own).
    const QRectF page = area.adjusted(1.5 * unit, 1.5 * unit, -1.5 * unit, -1.5 * unit);
    QFont title = painter->font();
    title.setPixelSize(std::max(8, int(unit * 1.8)));
    title.setBold(true);
    QFont body = title;
    body.setBold(false);
    body.setPixelSize(std::max(6, int(unit * 1.2)));
    const QStringList cap = caption();

    // Caption at the top: the title wraps (long item names), the parameters below it. Metrics
    // come from the painter's device (a printer's resolution differs from the screen's).
    painter->setPen(Qt::black);
    painter->setFont(title);
    const QFontMetricsF titleMetrics(title, painter->device());
    const QRectF titleBox = titleMetrics.boundingRect(
        QRectF(page.left(), page.top(), page.width(), page.height() / 4),
        Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, cap.value(0));
    QRectF r(page.left(), page.top(), page.width(), std::max(unit * 3, titleBox.height()));
    painter->drawText(r, Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap, cap.value(0));
    painter->setFont(body);
    const QFontMetricsF bodyMetrics(body, painter->device());
    const QString params = cap.mid(1).join(QLatin1Char('\n'));
    const QRectF paramsBox = bodyMetrics.boundingRect(
        QRectF(page.left(), r.bottom(), page.width(), page.height() / 4),
        Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, params);
    QRectF capRect(page.left(), r.bottom() + unit * 0.5, page.width(),
                   std::max(unit * 2, paramsBox.height()));
    painter->drawText(capRect, Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, params);

    // Attractor left (large), spectrum and matrices right.
    const double top = capRect.bottom() + unit;
    const QRectF figure(page.left(), top, page.width() * 0.6, page.bottom() - top);
    painter->setPen(QPen(Qt::gray, 0));
    painter->drawRect(figure);
    const auto *attractorItem = qobject_cast<const AttractorItem *>(m_item);
    if (m_surface && attractorItem && attractorItem->pointDimension() == 3)
        m_surface->renderTo(painter, figure.adjusted(1, 1, -1, -1));
    else if (m_attractor)
        m_attractor->renderTo(painter, figure.adjusted(1, 1, -1, -1),
                              AttractorView::Framing::FitContents);
    const double rightX = figure.right() + unit * 2;
    // A focused vertex's characteristic map: at the foot of the right column, beside its
    // matrix, never over the surface (issue 47: the inset covered the picture).
    double columnBottom = page.bottom();
    if (m_characteristic && !m_characteristic->map().cells.empty()) {
        const double w = std::min(page.right() - rightX, 0.3 * (page.bottom() - top));
        const QRectF inset(page.right() - w, page.bottom() - w, w, w);
        m_characteristic->paintMap(*painter, inset);
        painter->setPen(QPen(Qt::gray, 0));
        painter->setBrush(Qt::NoBrush);
        painter->drawRect(inset);
        columnBottom = inset.top() - unit;
    }
    QFont mono = body;
    mono.setFamily(QStringLiteral("monospace"));
    mono.setStyleHint(QFont::TypeWriter);
    // The spectrum takes half the column, less when the matrices need the room to stay at
    // 8 pt or more.
    const double column = columnBottom - top;
    MatrixLayout layout;
    double share = 0.5;
    for (const double s : {0.5, 0.42, 0.35}) {
        share = s;
        const QRectF text(rightX, top + column * s + unit, page.right() - rightX,
                          column * (1 - s) - unit);
        layout = layoutMatrices(painter, text, mono);
        if (layout.shown == layout.blocks.size())
            break;
    }
    const QRectF spec(rightX, top, page.right() - rightX, column * share);
    paintSpectrum(m_spectrum, painter, spec);
    paintMatrices(painter, layout);
    painter->restore();
}

FigureSheet::MatrixLayout FigureSheet::layoutMatrices(QPainter *painter, const QRectF &box,
                                                      QFont mono) const
{
    // The matrices flow into columns, each matrix kept whole, at the largest size from the
    // body text's down to 8 pt (a journal's smallest legible size). What does not fit at 8 pt
    // is named in a last line instead of shrinking everything into dust.
    // Heat maps (large matrices) then shrink further, to cells of a fifth of a line: they are
    // pictures, not text.
    MatrixLayout layout;
    layout.box = box;
    layout.blocks = matrixBlocks();
    if (layout.blocks.isEmpty())
        return layout;
    const double dpi = std::max(1, painter->device()->logicalDpiY());
    const int minPx = std::max(1, int(std::ceil(8.0 / 72.0 * dpi)));
    double cellShare = 0.5;
    for (int px = std::max(minPx, mono.pixelSize());;) {
        mono.setPixelSize(px);
        const QFontMetricsF fm(mono, painter->device());
        const double line = fm.lineSpacing(), gap = fm.horizontalAdvance(QStringLiteral("MM"));
        layout.font = mono;
        layout.at.clear();
        double x = box.left(), y = box.top(), columnWidth = 0;
        // A heat map's cell: half a line high (19 x 19 cells are 9.5 lines square).
        const double cell = cellShare * line;
        layout.cell = cell;
        for (const MatrixBlock &block : std::as_const(layout.blocks)) {
            double w = 0;
            for (const QString &l : block.lines)
                w = std::max(w, fm.horizontalAdvance(l));
            double h = line * block.lines.size();
            if (block.heat.size() > 0) {
                w = std::max(w, cell * double(block.heat.cols()));
                h += cell * double(block.heat.rows());
            }
            // A line stays free at the bottom for the note on matrices left out.
            if (y > box.top() && y + h > box.bottom() - line) {
                x += columnWidth + gap;   // next column
                y = box.top();
                columnWidth = 0;
            }
            if (x + w > box.right() + 0.5 || y + h > box.bottom() - line + 0.5)
                break;
            layout.at.append(QPointF(x, y));
            columnWidth = std::max(columnWidth, w);
            y += h + 0.6 * line;
        }
        layout.shown = int(layout.at.size());
        if (layout.shown == layout.blocks.size())
            break;
        if (px > minPx)
            --px;
        else if (cellShare > 0.2)
            cellShare -= 0.05;
        else
            break;
    }
    return layout;
}

void FigureSheet::paintMatrices(QPainter *painter, const MatrixLayout &layout) const
{
    if (layout.blocks.isEmpty())
        return;
    painter->setFont(layout.font);
    painter->setPen(Qt::black);
    const QFontMetricsF fm(layout.font, painter->device());
    const QRectF &box = layout.box;
    for (int i = 0; i < layout.shown; ++i) {
        const MatrixBlock &block = layout.blocks[i];
        const QPointF at = layout.at[i];
        const double textHeight = fm.lineSpacing() * block.lines.size();
        painter->drawText(QRectF(at, QSizeF(box.right() - at.x(), textHeight)),
                          Qt::AlignLeft | Qt::AlignTop, block.lines.join(QLatin1Char('\n')));
        if (block.heat.size() > 0) {
            // The colour of each entry on the Matrices dock's scale, a hairline frame.
            const double cell = layout.cell;
            const double largest = std::max(1e-300, block.heat.cwiseAbs().maxCoeff());
            const QPointF origin = at + QPointF(0, textHeight);
            for (Eigen::Index r = 0; r < block.heat.rows(); ++r)
                for (Eigen::Index c = 0; c < block.heat.cols(); ++c)
                    painter->fillRect(QRectF(origin.x() + double(c) * cell,
                                             origin.y() + double(r) * cell, cell, cell),
                                      MatrixHeatMap::colour(block.heat(r, c), largest));
            painter->save();
            painter->setPen(QPen(QColor(160, 160, 160), 0));
            painter->drawRect(QRectF(origin, QSizeF(cell * double(block.heat.cols()),
                                                    cell * double(block.heat.rows()))));
            painter->restore();
        }
    }
    if (layout.shown < layout.blocks.size()) {
        const QString note = tr("… and %n more: see the Matrices dock, or copy them as LaTeX.",
                                nullptr, int(layout.blocks.size()) - layout.shown);
        // In the text's font, not the matrices' typewriter one: it is a sentence.
        QFont text = layout.font;
        text.setFamily(QFont().family());
        text.setStyleHint(QFont::SansSerif);
        painter->setFont(text);
        const QFontMetricsF tm(text, painter->device());
        painter->drawText(QRectF(box.left(), box.bottom() - fm.lineSpacing(), box.width(),
                                 fm.lineSpacing()),
                          Qt::AlignLeft | Qt::AlignVCenter,
                          tm.elidedText(note, Qt::ElideRight, box.width()));
    }
    m_matrixFontPixels = layout.font.pixelSize();
    m_matricesShown = layout.shown;
}

bool FigureSheet::print(QPagedPaintDevice *device) const
{
    QPainter painter;
    if (!painter.begin(device))
        return false;
    painter.setRenderHint(QPainter::LosslessImageRendering); // rasters not as JPEG
    // The printable area in device pixels: the printer's resolution applies.
    const QRectF page = device->pageLayout().paintRectPixels(device->logicalDpiX());
    paint(&painter, QRectF(QPointF(0, 0), page.size()));
    if (cancelled()) {
        // The user stopped drawing the attractor: no sheet without its figure.
        if (auto *printer = dynamic_cast<QPrinter *>(device))
            printer->abort();
        painter.end();
        return false;
    }
    return painter.end();
}

bool FigureSheet::cancelled() const
{
    return m_attractor && m_attractor->exportCancelled();
}

bool FigureSheet::writePdf(const QString &fileName, QString *error) const
{
    // Written whole or not at all: a cancelled print leaves an existing file as it was.
    QString writeError;
    const bool ok = writeFigureFile(fileName, [&](QIODevice &out, QString *) {
        QPdfWriter pdf(&out);
        pdf.setResolution(300);
        pdf.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Landscape,
                                      QMarginsF(12, 12, 12, 12), QPageLayout::Millimeter));
        pdf.setTitle(caption().value(0));
        pdf.setCreator(QCoreApplication::applicationName());
        return print(&pdf) && !cancelled();
    }, &writeError);
    if (!ok && error)
        *error = cancelled() ? tr("Printing %1 was cancelled while the attractor was drawn.")
                                   .arg(QFileInfo(fileName).fileName())
                             : writeError;
    return ok;
}

} // namespace awb
