#include "gui/views/AtlasPlot.h"

#include "gui/views/RegularityPanel.h"
#include "model/NumberFormat.h"

#include <QHelpEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QTimer>
#include <QToolTip>
#include <QVBoxLayout>

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace awb {

// The 2D map's rectangles, drawn in one pass under the axes (thousands of QCPItemRects would
// each be a layerable of their own).
class AtlasCells : public QCPLayerable {
public:
    AtlasCells(QCustomPlot *plot, const AtlasPlot *owner)
        : QCPLayerable(plot, QStringLiteral("main")), m_owner(owner)
    {
    }
    std::vector<QRectF> rects;   // in plot coordinates, one per row
    std::vector<QColor> fills;
    std::vector<bool> outlined;

protected:
    // Inside the axes only: a cell at the grid's edge reaches half a cell beyond it.
    QRect clipRect() const override { return parentPlot()->axisRect()->rect(); }
    void applyDefaultAntialiasingHint(QCPPainter *painter) const override
    {
        painter->setAntialiasing(false);
    }
    void draw(QCPPainter *painter) override
    {
        QCPAxis *x = parentPlot()->xAxis, *y = parentPlot()->yAxis;
        const auto px = [&](const QPointF &p) {
            return QPointF(x->coordToPixel(p.x()), y->coordToPixel(p.y()));
        };
        // Coarse cells first: a refined row's smaller cell is drawn over its neighbours'.
        std::vector<size_t> order(rects.size());
        for (size_t i = 0; i < order.size(); ++i)
            order[i] = i;
        std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
            return rects[a].width() * rects[a].height() > rects[b].width() * rects[b].height();
        });
        const QPen outline(QColor(200, 60, 20), 1.2);
        for (size_t i : order) {
            const QRectF r = QRectF(px(rects[i].topLeft()), px(rects[i].bottomRight()))
                                 .normalized();
            painter->fillRect(r.adjusted(0, 0, 1, 1), fills[i]);
            if (outlined[i]) {
                painter->setPen(outline);
                painter->setBrush(Qt::NoBrush);
                painter->drawRect(r.adjusted(1, 1, -1, -1));
            }
        }
    }

private:
    const AtlasPlot *m_owner;
};

namespace {

constexpr double kShownTop = 6.0;   // r above this (C^infinity) is drawn at the top

double shown(double r)
{
    return std::isfinite(r) ? std::min(r, kShownTop) : kShownTop;
}

} // namespace

AtlasPlot::AtlasPlot(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_plot = new QCustomPlot(this);
    m_plot->setObjectName(QStringLiteral("atlasPlot"));
    m_plot->setMinimumSize(360, 260);
    m_plot->setMouseTracking(true);
    m_plot->installEventFilter(this);
    m_cells = new AtlasCells(m_plot, this);
    layout->addWidget(m_plot, 1);
    m_legend = new QLabel(this);
    m_legend->setObjectName(QStringLiteral("atlasLegend"));
    m_legend->setWordWrap(true);
    m_legend->setTextFormat(Qt::RichText);
    layout->addWidget(m_legend);
}

AtlasPlot::~AtlasPlot() = default;

QColor AtlasPlot::classColour(int smoothness)
{
    // Light to dark with the class: not certified C^0, C^0, C^1, C^2, C^3 and more.
    static const QColor colours[] = {QColor(236, 236, 236), QColor(253, 224, 160),
                                     QColor(150, 205, 160), QColor(70, 150, 190),
                                     QColor(40, 70, 150)};
    return colours[std::clamp(smoothness + 1, 0, 4)];
}

void AtlasPlot::start(const std::vector<AtlasAxis> &axes, int smoothness)
{
    m_axes = axes;
    m_smoothness = smoothness;
    m_rows.clear();
    m_cellSizes.clear();
    m_runs.clear();
    redraw();
}

void AtlasPlot::addRows(const std::vector<AtlasRow> &rows,
                        const std::vector<std::vector<double>> &cells)
{
    m_rows.insert(m_rows.end(), rows.begin(), rows.end());
    m_cellSizes.insert(m_cellSizes.end(), cells.begin(), cells.end());
    m_cellSizes.resize(m_rows.size());
    // Rows arrive a task at a time, thousands of them in a large atlas: the chart is drawn
    // again at most ten times a second, not once per task.
    if (!m_redrawPending) {
        m_redrawPending = true;
        QTimer::singleShot(100, this, [this] {
            if (m_redrawPending)
                redraw();
        });
    }
}

void AtlasPlot::finish(const std::vector<AtlasRow> &rows,
                       const std::vector<std::vector<double>> &cells,
                       const std::vector<AtlasRun> &runs)
{
    m_rows = rows;
    m_cellSizes = cells;
    m_cellSizes.resize(m_rows.size());
    m_runs = runs;
    redraw();
}

void AtlasPlot::redraw()
{
    m_redrawPending = false;
    m_plot->clearGraphs();
    m_plot->clearItems();
    m_cells->rects.clear();
    m_cells->fills.clear();
    m_cells->outlined.clear();
    if (m_axes.empty()) {
        m_legend->clear();
        m_plot->replot();
        return;
    }
    const AtlasAxis &ax = m_axes[0];
    m_plot->xAxis->setLabel(QString::fromStdString(ax.name));
    const double pad = 0.02 * (ax.to - ax.from);
    m_plot->xAxis->setRange(ax.from - pad, ax.to + pad);
    const QString k = QString::number(m_smoothness);
    if (m_axes.size() == 1) {
        // Bounds on r, sorted by the parameter.
        std::vector<size_t> order(m_rows.size());
        for (size_t i = 0; i < order.size(); ++i)
            order[i] = i;
        std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
            return m_rows[a].params[0] < m_rows[b].params[0];
        });
        QVector<double> x, lo, hi;
        double top = m_smoothness + 1.0, bottom = 0.0;
        for (size_t i : order) {
            const AtlasRow &r = m_rows[i];
            if (!r.applies)
                continue;
            x << r.params[0];
            lo << shown(r.lower);
            hi << shown(r.upper);
            top = std::max(top, shown(r.upper));
            bottom = std::min(bottom, shown(r.lower));
        }
        for (const auto &[values, name, colour] :
             {std::tuple{&hi, tr("upper bound on r"), QColor(200, 80, 40)},
              std::tuple{&lo, tr("lower bound on r (certified)"), QColor(30, 90, 170)}}) {
            QCPGraph *g = m_plot->addGraph();
            g->setName(name);
            g->setPen(QPen(colour, 1.6));
            g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, colour, colour, 4));
            g->setData(x, *values, true);
        }
        auto *line = new QCPItemStraightLine(m_plot);
        line->point1->setCoords(ax.from, m_smoothness);
        line->point2->setCoords(ax.to, m_smoothness);
        line->setPen(QPen(Qt::darkGray, 1, Qt::DashLine));
        for (const AtlasRun &run : m_runs) {
            auto *band = new QCPItemRect(m_plot);
            band->setLayer(QStringLiteral("background"));
            band->topLeft->setCoords(std::min(run.from.inner, run.to.inner), 1e9);
            band->bottomRight->setCoords(std::max(run.from.inner, run.to.inner), -1e9);
            band->setPen(Qt::NoPen);
            band->setBrush(QColor(150, 205, 160, 90));
        }
        m_plot->yAxis->setLabel(tr("Hölder exponent r"));
        m_plot->yAxis->setRange(bottom - 0.1, top + 0.2);
        m_plot->legend->setVisible(!m_rows.empty());
        m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
        m_legend->setText(
            m_runs.empty() && m_rows.empty()
                ? QString()
                : tr("Shaded: certified C<sup>%1</sup> (lower bound &gt; %1). %2 points.")
                      .arg(k)
                      .arg(m_rows.size()));
    } else {
        const AtlasAxis &ay = m_axes[1];
        m_plot->legend->setVisible(false);
        m_plot->yAxis->setLabel(QString::fromStdString(ay.name));
        // The grid's edge cells whole: half a cell beyond each end.
        m_plot->xAxis->setRange(ax.from - 0.5 * (ax.to - ax.from) / (ax.count - 1),
                                ax.to + 0.5 * (ax.to - ax.from) / (ax.count - 1));
        m_plot->yAxis->setRange(ay.from - 0.5 * (ay.to - ay.from) / (ay.count - 1),
                                ay.to + 0.5 * (ay.to - ay.from) / (ay.count - 1));
        for (size_t i = 0; i < m_rows.size(); ++i) {
            const AtlasRow &r = m_rows[i];
            const std::vector<double> &c = m_cellSizes[i];
            const double w = c.size() == 2 ? c[0] : (ax.to - ax.from) / (ax.count - 1);
            const double h = c.size() == 2 ? c[1] : (ay.to - ay.from) / (ay.count - 1);
            m_cells->rects.push_back(
                QRectF(r.params[0] - w / 2, r.params[1] - h / 2, w, h));
            m_cells->fills.push_back(r.applies ? classColour(std::min(r.smoothness, 3))
                                               : QColor(255, 255, 255));
            m_cells->outlined.push_back(r.verdict == 0);
        }
        QString legend;
        const QStringList names{tr("not certified C⁰"), tr("C⁰"), tr("C¹"), tr("C²"),
                                tr("C³ or more")};
        for (int s = -1; s <= 3; ++s)
            legend += QStringLiteral("<span style=\"background:%1; color:#888\">▕&nbsp;&nbsp;"
                                     "▏</span>&nbsp;%2&nbsp;&nbsp; ")
                          .arg(classColour(s).name(), names[s + 1]);
        legend += tr("<span style=\"color:#c83c14\">□</span> the bounds cannot tell "
                     "C<sup>%1</sup>; white: no member. %2 points.")
                      .arg(k)
                      .arg(m_rows.size());
        m_legend->setText(legend);
    }
    m_plot->replot();
}

std::optional<size_t> AtlasPlot::rowAt(const QPointF &pos) const
{
    if (m_rows.empty() || m_axes.empty())
        return std::nullopt;
    const double x = m_plot->xAxis->pixelToCoord(pos.x());
    const double y = m_plot->yAxis->pixelToCoord(pos.y());
    if (m_axes.size() == 2) {
        // The finest cell containing the point (a refined row's cell lies inside its
        // neighbours' coarser ones).
        std::optional<size_t> best;
        double area = std::numeric_limits<double>::infinity();
        for (size_t i = 0; i < m_cells->rects.size(); ++i) {
            const QRectF &r = m_cells->rects[i];
            if (r.contains(x, y) && r.width() * r.height() < area) {
                area = r.width() * r.height();
                best = i;
            }
        }
        return best;
    }
    std::optional<size_t> best;
    double distance = 12.0;   // pixels
    for (size_t i = 0; i < m_rows.size(); ++i) {
        const double d = std::abs(m_plot->xAxis->coordToPixel(m_rows[i].params[0]) - pos.x());
        if (d < distance) {
            distance = d;
            best = i;
        }
    }
    return best;
}

QPointF AtlasPlot::rowPosition(size_t index) const
{
    const AtlasRow &r = m_rows.at(index);
    const double y = m_axes.size() == 2 ? r.params[1] : shown(r.lower);
    return {m_plot->xAxis->coordToPixel(r.params[0]), m_plot->yAxis->coordToPixel(y)};
}

QString AtlasPlot::rowText(const AtlasRow &r) const
{
    QStringList where;
    for (size_t a = 0; a < m_axes.size() && a < r.params.size(); ++a)
        where << QStringLiteral("%1 = %2").arg(QString::fromStdString(m_axes[a].name),
                                               QString::number(r.params[a], 'g', 10));
    QString text = where.join(QStringLiteral(", "));
    if (!r.applies)
        return text + "\n" + tr("no member here: %1").arg(QString::fromStdString(r.message));
    const bool infinite = std::isinf(r.lower);
    text += "\n" + (infinite ? tr("C^∞ (a polynomial piece)")
                             : tr("Hölder exponent r in [%1, %2]%3")
                                   .arg(formatNumber(r.lower), formatNumber(r.upper),
                                        r.exact ? tr(", exact (invariant polytope)")
                                                : QString()));
    text += "\n" + (r.smoothness < 0 ? tr("not certified C⁰")
                    : infinite       ? QString()
                                     : tr("certified C^%1").arg(r.smoothness));
    text += "; " + (r.verdict > 0   ? tr("C^%1 as asked: yes").arg(m_smoothness)
                    : r.verdict < 0 ? tr("C^%1 as asked: certified no").arg(m_smoothness)
                                    : tr("C^%1 as asked: the bounds cannot tell")
                                          .arg(m_smoothness));
    if (r.sobolev >= 0)
        text += "\n" + tr("Sobolev exponent s₂ = %1").arg(formatNumber(r.sobolev));
    if (r.timedOut)
        text += "\n" + tr("stopped by the safety clock: may differ on another machine");
    return mathText(text + "\n" + tr("Click to add an item with these parameters."));
}

bool AtlasPlot::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_plot) {
        if (event->type() == QEvent::ToolTip) {
            auto *help = static_cast<QHelpEvent *>(event);
            if (const auto i = rowAt(help->pos()))
                QToolTip::showText(help->globalPos(), rowText(m_rows[*i]), m_plot);
            else
                QToolTip::hideText();
            return true;
        }
        if (event->type() == QEvent::MouseButtonRelease) {
            auto *mouse = static_cast<QMouseEvent *>(event);
            if (mouse->button() == Qt::LeftButton)
                if (const auto i = rowAt(mouse->position()))
                    emit rowClicked(int(*i), mouse->globalPosition().toPoint());
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace awb
