#include "gui/views/AnalysisCharts.h"

#include "core/analysis/Geometry.h"
#include "gui/views/AttractorRenderer.h"
#include "gui/views/ThemeColours.h"
#include "model/NumberFormat.h"

#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QCursor>
#include <QLineF>
#include <QLabel>
#include <QLineSeries>
#include <QFontMetrics>
#include <QLogValueAxis>
#include <QScatterSeries>
#include <QTabWidget>
#include <QToolTip>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

void clearChart(QChart *chart)
{
    chart->removeAllSeries();
    for (QAbstractAxis *a : chart->axes()) {
        chart->removeAxis(a);
        delete a;
    }
}

void attach(QChart *chart, QAbstractSeries *s, QAbstractAxis *x, QAbstractAxis *y)
{
    chart->addSeries(s);
    s->attachAxis(x);
    s->attachAxis(y);
}

// Integer ticks for a step/depth axis, at most about ten of them.
QValueAxis *integerAxis(const QString &title, double lo, double hi)
{
    auto *axis = new QValueAxis;
    axis->setTitleText(title);
    axis->setLabelFormat(QStringLiteral("%.0f"));
    if (hi <= lo)
        hi = lo + 1;
    axis->setRange(lo - 0.3, hi + 0.3);
    axis->setTickType(QValueAxis::TicksDynamic);
    axis->setTickAnchor(0.0);
    axis->setTickInterval(std::max(1.0, std::ceil((hi - lo) / 10.0)));
    return axis;
}

// A value axis over exactly [lo, hi] with ticks at round numbers (applyNiceNumbers() would
// widen the range to the next round numbers and leave much of a small chart empty).
QValueAxis *valueAxis(const QString &title, double lo, double hi)
{
    auto *axis = new QValueAxis;
    axis->setTitleText(title);
    if (!(hi > lo))
        hi = lo + 1;
    axis->setRange(lo, hi);
    const double approx = (hi - lo) / 6.0;
    const double e = std::pow(10.0, std::floor(std::log10(approx)));
    const double f = approx / e;
    const double step = (f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0) * e;
    axis->setTickType(QValueAxis::TicksDynamic);
    axis->setTickAnchor(0.0);
    axis->setTickInterval(step);
    axis->setLabelFormat(QStringLiteral("%.4g"));
    return axis;
}

QPen dashed(const QColor &c) { return QPen(c, 1.5, Qt::DashLine); }

} // namespace

AnalysisCharts::AnalysisCharts(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_note = new QLabel(this);
    m_note->setObjectName(QStringLiteral("analysisNote"));
    m_note->setWordWrap(true);
    m_note->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_note->setContentsMargins(6, 4, 6, 4);
    m_note->setStyleSheet(noteStyleSheet(palette()));
    m_note->setVisible(false);
    layout->addWidget(m_note);
    m_tabs = new QTabWidget(this);
    layout->addWidget(m_tabs);
    m_tabs->addTab(makeView(tr("Distance to the exact curve")), tr("Distance"));
    m_tabs->addTab(makeView(tr("Control polygon length")), tr("Length"));
    m_tabs->addTab(makeView(tr("Box counting")), tr("Box counting"));
    m_tabs->addTab(makeView(tr("Eigenvalue moduli")), tr("|λ| per map"));
}

AnalysisCharts::~AnalysisCharts() = default;

QChartView *AnalysisCharts::makeView(const QString &title)
{
    auto *chart = new QChart;
    chart->setTitle(title);
    QFont f = chart->titleFont();
    f.setPointSizeF(f.pointSizeF() * 1.15);
    f.setBold(true);
    chart->setTitleFont(f);
    chart->legend()->setAlignment(Qt::AlignBottom);
    chart->setMargins(QMargins(6, 6, 6, 6));
    auto *view = new QChartView(chart);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumSize(160, 140); // the dock may be narrow; the chart scales
    view->installEventFilter(this);
    m_views << view;
    return view;
}

bool AnalysisCharts::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Resize)
        if (auto *view = qobject_cast<QChartView *>(watched))
            fitToView(view);
    return QWidget::eventFilter(watched, event);
}

void AnalysisCharts::fitToView(QChartView *view)
{
    // A chart in a small dock spends its height on titles and labels until the plot area is
    // gone and the axis labels are elided to "...": below these sizes it drops the axis titles
    // (the tab and the tooltips name the quantities), then the legend, and uses smaller labels.
    QChart *c = view->chart();
    const bool compact = view->height() < 260 || view->width() < 320;
    const bool tiny = view->height() < 190;
    QFont title = font();
    title.setBold(true);
    if (!compact)
        title.setPointSizeF(title.pointSizeF() * 1.15);
    c->setTitleFont(title);
    QFont labels = font();
    if (compact)
        labels.setPointSizeF(std::max(7.0, labels.pointSizeF() * 0.85));
    for (QAbstractAxis *axis : c->axes()) {
        axis->setTitleVisible(!compact);
        axis->setLabelsFont(labels);
    }
    c->legend()->setVisible(!tiny && c->series().size() > 1);
    // Qt Charts elides a vertical axis' labels to "…" when the ticks are closer than a label's
    // height: ticks of a round step with room for each label.
    const QFontMetrics fm(labels);
    const double plotHeight = std::max(40.0, view->height() * (tiny ? 0.7 : 0.55));
    const int most = std::max(2, int(plotHeight / (2.2 * fm.height())));
    for (QAbstractAxis *axis : c->axes(Qt::Vertical)) {
        auto *v = qobject_cast<QValueAxis *>(axis);
        if (!v || v->tickType() != QValueAxis::TicksDynamic || !(v->max() > v->min()))
            continue;
        const double approx = (v->max() - v->min()) / most;
        const double e = std::pow(10.0, std::floor(std::log10(approx)));
        const double f = approx / e;
        v->setTickInterval((f <= 1 ? 1.0 : f <= 2 ? 2.0 : f <= 5 ? 5.0 : 10.0) * e);
    }
    c->legend()->setFont(labels);
    c->setMargins(compact ? QMargins(2, 2, 2, 2) : QMargins(6, 6, 6, 6));
}

void AnalysisCharts::setNote(const QString &text)
{
    m_note->setStyleSheet(noteStyleSheet(palette())); // the theme may have changed
    m_note->setText(text);
    m_note->setVisible(!text.isEmpty());
}

QString AnalysisCharts::note() const { return m_note->text(); }

QString AnalysisCharts::pointToolTip(Tab tab, const QString &series, const QPointF &p)
{
    // Measured values in decimals; |λ| as the spectrum shows it (exact fractions where simple).
    const auto number = [](double v) { return QString::number(v, 'g', 6); };
    const QString name = series.toHtmlEscaped();
    switch (tab) {
    case DistanceTab:
        return tr("<b>%1</b><br>depth k = %2<br>d<sub>H</sub> = %3")
            .arg(name).arg(int(std::lround(p.x()))).arg(number(p.y()));
    case LengthTab:
        return tr("<b>%1</b><br>step k = %2<br>length = %3")
            .arg(name).arg(int(std::lround(p.x()))).arg(number(p.y()));
    case BoxCountingTab:
        // Natural logarithms: ε = e^-x, N = e^y.
        return tr("<b>%1</b><br>log(1/ε) = %2 (ε = %3)<br>log N(ε) = %4 (N = %5)")
            .arg(name, number(p.x()), QString::number(std::exp(-p.x()), 'g', 4), number(p.y()))
            .arg(std::llround(std::exp(p.y())));
    case ModuliTab:
        return tr("<b>%1</b><br>|λ| = %2").arg(name, formatNumber(p.y(), 8));
    }
    return {};
}

void AnalysisCharts::addToolTips(Tab tab)
{
    QChartView *view = chartView(tab);
    fitToView(view); // the axes are new
    for (QAbstractSeries *s : view->chart()->series()) {
        auto *xy = qobject_cast<QXYSeries *>(s);
        if (!xy)
            continue;
        connect(xy, &QXYSeries::hovered, view, [view, xy, tab](const QPointF &p, bool on) {
            if (!on) {
                QToolTip::hideText();
                return;
            }
            // The data point nearest to the hovered position (a line series reports points
            // on its segments too).
            QPointF best = p;
            double bestD = INFINITY;
            const QPointF at = view->chart()->mapToPosition(p, xy);
            for (const QPointF &q : xy->points()) {
                const double d = QLineF(view->chart()->mapToPosition(q, xy), at).length();
                if (d < bestD) {
                    bestD = d;
                    best = q;
                }
            }
            if (bestD > 12.0)
                return;
            QToolTip::showText(QCursor::pos(), pointToolTip(tab, xy->name(), best), view);
        });
    }
}

QChartView *AnalysisCharts::chartView(Tab tab) const { return m_views.value(int(tab)); }

QChart *AnalysisCharts::chart(Tab tab) const
{
    QChartView *v = chartView(tab);
    return v ? v->chart() : nullptr;
}

void AnalysisCharts::setDistances(const QList<DistanceSeries> &series, double rate)
{
    QChart *c = chart(DistanceTab);
    clearChart(c);
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    QList<QLineSeries *> made;
    for (int i = 0; i < series.size(); ++i) {
        const DistanceSeries &d = series[i];
        auto *s = new QLineSeries;
        s->setName(d.name);
        s->setPointsVisible(true);
        s->setColor(AttractorRenderer::mapColor(i));
        for (std::size_t k = 0; k < std::min(d.depth.size(), d.distance.size()); ++k) {
            // A log axis cannot show 0 (an exact hit) or a failed measurement.
            if (!(d.distance[k] > 0) || !std::isfinite(d.distance[k]))
                continue;
            s->append(d.depth[k], d.distance[k]);
            xlo = std::min(xlo, d.depth[k]);
            xhi = std::max(xhi, d.depth[k]);
            ylo = std::min(ylo, d.distance[k]);
            yhi = std::max(yhi, d.distance[k]);
        }
        made << s;
    }
    QLineSeries *reference = nullptr;
    if (rate > 0 && rate != 1 && !made.isEmpty() && made.front()->count() > 0) {
        // C rate^k through the first measured point: the convergence the eigenvalue predicts.
        const QPointF p0 = made.front()->at(0);
        reference = new QLineSeries;
        reference->setName(tr("∝ (%1)ᵏ").arg(formatNumber(rate, 4)));
        reference->setPen(dashed(QColor(120, 120, 120)));
        for (double k = xlo; k <= xhi + 1e-9; k += 0.25) {
            const double y = p0.y() * std::pow(rate, k - p0.x());
            reference->append(k, y);
            ylo = std::min(ylo, y);
            yhi = std::max(yhi, y);
        }
    }
    // An empty chart says why rather than showing bare axes.
    const bool empty = !std::isfinite(xlo);
    c->setTitle(empty ? tr("No exact curve known for this item")
                      : tr("Distance to the exact curve"));
    chartView(DistanceTab)->setToolTip(
        empty ? tr("The Hausdorff distance is measured against an exact curve: B-spline, Bézier "
                   "and complex de Casteljau curves have one.")
              : m_distanceReference);
    if (!std::isfinite(xlo)) {
        xlo = 0, xhi = 1, ylo = 0.1, yhi = 1;
    }
    auto *x = integerAxis(tr("depth k"), xlo, xhi);
    auto *y = new QLogValueAxis;
    y->setTitleText(tr("Hausdorff distance"));
    y->setBase(10.0);
    y->setLabelFormat(QStringLiteral("%.0e"));
    y->setRange(std::pow(10.0, std::floor(std::log10(ylo))),
                std::pow(10.0, std::ceil(std::log10(yhi * 1.0001))));
    y->setMinorTickCount(0); // minor lines per decade clutter a small chart
    c->addAxis(x, Qt::AlignBottom);
    c->addAxis(y, Qt::AlignLeft);
    for (QLineSeries *s : made)
        attach(c, s, x, y);
    if (reference)
        attach(c, reference, x, y);
    addToolTips(DistanceTab);
}

void AnalysisCharts::setPolygonLengths(const std::vector<double> &lengths, double exactLength)
{
    QChart *c = chart(LengthTab);
    clearChart(c);
    auto *s = new QLineSeries;
    s->setName(tr("control polygon"));
    s->setPointsVisible(true);
    s->setColor(AttractorRenderer::mapColor(0));
    double ylo = INFINITY, yhi = -INFINITY;
    for (std::size_t k = 0; k < lengths.size(); ++k) {
        if (!std::isfinite(lengths[k]))
            continue;
        s->append(double(k), lengths[k]);
        ylo = std::min(ylo, lengths[k]);
        yhi = std::max(yhi, lengths[k]);
    }
    QLineSeries *exact = nullptr;
    const double last = lengths.empty() ? 1.0 : double(lengths.size() - 1);
    if (exactLength > 0 && std::isfinite(exactLength)) {
        exact = new QLineSeries;
        exact->setName(tr("exact curve"));
        exact->setPen(dashed(QColor(20, 150, 60)));
        exact->append(0, exactLength);
        exact->append(last, exactLength);
        ylo = std::min(ylo, exactLength);
        yhi = std::max(yhi, exactLength);
    }
    if (!std::isfinite(ylo))
        ylo = 0, yhi = 1;
    const double pad = std::max(1e-12, 0.08 * (yhi - ylo));
    auto *x = integerAxis(tr("subdivision step k"), 0, last);
    auto *y = valueAxis(tr("length"), ylo - pad, yhi + pad);
    c->addAxis(x, Qt::AlignBottom);
    c->addAxis(y, Qt::AlignLeft);
    attach(c, s, x, y);
    if (exact)
        attach(c, exact, x, y);
    addToolTips(LengthTab);
}

void AnalysisCharts::setBoxCounting(const BoxDimension &box)
{
    QChart *c = chart(BoxCountingTab);
    clearChart(c);
    // Short titles and legends: a title wider than the view makes Qt Charts squeeze the
    // y axis to its minimum and elide its labels to "…". The fit's numbers are in the tooltip.
    if (box.valid) {
        c->setTitle(tr("D = %1 (R² = %2)")
                        .arg(QString::number(box.dimension, 'f', 4),
                             QString::number(box.r2, 'f', 5)));
        chartView(BoxCountingTab)->setToolTip(
            tr("Box-counting dimension D = %1: the slope of log N(ε) against log(1/ε) over the "
               "fitted levels, log N = %1 log(1/ε) + %2, R² = %3")
                .arg(QString::number(box.dimension, 'f', 4),
                     QString::number(box.intercept, 'f', 3), QString::number(box.r2, 'f', 5)));
    } else {
        c->setTitle(tr("No fit"));
        chartView(BoxCountingTab)->setToolTip(
            tr("Box counting: no fit (%1)").arg(QString::fromStdString(box.note)));
    }
    auto *all = new QScatterSeries;
    all->setName(tr("not fitted"));
    all->setMarkerSize(7);
    all->setColor(QColor(170, 170, 170));
    all->setBorderColor(QColor(170, 170, 170));
    auto *fitted = new QScatterSeries;
    fitted->setName(tr("fitted levels"));
    fitted->setMarkerSize(9);
    fitted->setColor(AttractorRenderer::mapColor(0));
    fitted->setBorderColor(AttractorRenderer::mapColor(0).darker(130));
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    const std::size_t n = std::min(box.logInverseEps.size(), box.logCount.size());
    for (std::size_t l = 0; l < n; ++l) {
        const double x = box.logInverseEps[l], y = box.logCount[l];
        const bool inFit = box.valid && int(l) >= box.levelFrom && int(l) <= box.levelTo;
        (inFit ? fitted : all)->append(x, y);
        xlo = std::min(xlo, x), xhi = std::max(xhi, x);
        ylo = std::min(ylo, y), yhi = std::max(yhi, y);
    }
    QLineSeries *line = nullptr;
    if (box.valid && n > 0) {
        line = new QLineSeries;
        line->setName(tr("slope %1").arg(QString::number(box.dimension, 'f', 3)));
        line->setPen(QPen(QColor(200, 0, 60), 1.6));
        for (double x : {xlo, xhi}) {
            const double y = box.intercept + box.dimension * x;
            line->append(x, y);
            ylo = std::min(ylo, y), yhi = std::max(yhi, y);
        }
    }
    if (!std::isfinite(xlo))
        xlo = 0, xhi = 1, ylo = 0, yhi = 1;
    const double px = std::max(1e-9, 0.05 * (xhi - xlo)), py = std::max(1e-9, 0.05 * (yhi - ylo));
    auto *x = valueAxis(tr("log(1/ε)"), xlo - px, xhi + px);
    auto *y = valueAxis(tr("log N(ε)"), ylo - py, yhi + py);
    c->addAxis(x, Qt::AlignBottom);
    c->addAxis(y, Qt::AlignLeft);
    attach(c, all, x, y);
    attach(c, fitted, x, y);
    if (line)
        attach(c, line, x, y);
    addToolTips(BoxCountingTab);
}

void AnalysisCharts::setModuli(const QList<MapModuli> &maps)
{
    // The moduli of the S_i do not move while a control point is dragged: keep the chart.
    const auto same = [](const QList<MapModuli> &a, const QList<MapModuli> &b) {
        if (a.size() != b.size())
            return false;
        for (int i = 0; i < a.size(); ++i) {
            if (a[i].label != b[i].label || a[i].moduli.size() != b[i].moduli.size())
                return false;
            for (std::size_t k = 0; k < a[i].moduli.size(); ++k)
                if (!(std::abs(a[i].moduli[k] - b[i].moduli[k])
                      <= 1e-12 * std::max(1.0, std::abs(a[i].moduli[k]))))
                    return false;
        }
        return true;
    };
    if (m_moduliShown && same(maps, m_moduli))
        return;
    m_moduli = maps;
    m_moduliShown = true;
    QChart *c = chart(ModuliTab);
    clearChart(c);
    auto *x = new QCategoryAxis;
    x->setTitleText(tr("map"));
    x->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
    x->setStartValue(0.5);
    double ymax = 1.0;
    QList<QScatterSeries *> made;
    for (int i = 0; i < maps.size(); ++i) {
        auto *s = new QScatterSeries;
        s->setName(subscriptName(maps[i].label));
        s->setMarkerSize(10);
        s->setColor(AttractorRenderer::mapColor(i));
        s->setBorderColor(AttractorRenderer::mapColor(i).darker(130));
        for (double m : maps[i].moduli) {
            if (!std::isfinite(m))
                continue;
            s->append(i + 1, m);
            ymax = std::max(ymax, m);
        }
        // Category labels sit at the category's end value: put it on the map's column.
        // Category labels must be unique.
        QString label = subscriptName(maps[i].label);
        if (x->categoriesLabels().contains(label))
            label += QStringLiteral(" (%1)").arg(i + 1);
        x->append(label, i + 1);
        made << s;
    }
    x->setRange(0.5, std::max(1, int(maps.size())) + 0.5);
    auto *unit = new QLineSeries;
    unit->setName(tr("|λ| = 1"));
    unit->setPen(dashed(QColor(200, 0, 60)));
    unit->append(0.5, 1.0);
    unit->append(std::max(1, int(maps.size())) + 0.5, 1.0);
    auto *y = valueAxis(tr("|λ|"), 0.0, ymax * 1.08);
    c->addAxis(x, Qt::AlignBottom);
    c->addAxis(y, Qt::AlignLeft);
    for (QScatterSeries *s : made)
        attach(c, s, x, y);
    attach(c, unit, x, y);
    addToolTips(ModuliTab);
}

} // namespace awb
