#include "gui/views/RegularityChart.h"

#include "core/analysis/Regularity.h"
#include "core/analysis/RegularityFamily.h"
#include "core/schemes/Scheme.h"
#include "model/SchemeRegularity.h"
#include "model/SubdivisionCurveItem.h"

#include <QAreaSeries>
#include <QChart>
#include <QChartView>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineSeries>
#include <QProgressBar>
#include <QPushButton>
#include <QScatterSeries>
#include <QVBoxLayout>
#include <QValueAxis>

#include <cmath>

namespace awb {

namespace {
// The curve's points and the family's members: the four-point scheme's regularity as an item
// of it has it (model/SchemeRegularity).
Regularity fourPointRegularity(double omega, const RegularityOptions &o)
{
    SchemeSpec four;
    four.kind = SchemeSpec::Kind::FourPoint;
    four.omega = omega;
    return specRegularity(four, 8, o);
}

QLineSeries *lineSeries(QChart *chart, const QString &name)
{
    for (QAbstractSeries *s : chart->series())
        if (s->name() == name)
            return qobject_cast<QLineSeries *>(s);
    return nullptr;
}
} // namespace

RegularityChart::RegularityChart(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("regularityChart"));
    setWindowTitle(tr("Regularity of the four-point scheme"));
    auto *chart = new QChart;
    chart->setTitle(tr("Certified Hölder regularity r(ω) of the four-point scheme"));
    auto *lower = new QLineSeries;
    lower->setName(tr("lower bound"));
    auto *upper = new QLineSeries;
    upper->setName(tr("upper bound"));
    QPen dashed = upper->pen();
    dashed.setStyle(Qt::DashLine);
    upper->setPen(dashed);
    auto *known = new QScatterSeries;
    known->setName(tr("r(0) = 1, r(1/16) = 2"));
    known->append(0.0, 1.0);
    known->append(1.0 / 16.0, 2.0);
    known->setMarkerSize(10);
    for (QAbstractSeries *s : {static_cast<QAbstractSeries *>(lower),
                               static_cast<QAbstractSeries *>(upper),
                               static_cast<QAbstractSeries *>(known)})
        chart->addSeries(s);
    auto *x = new QValueAxis;
    x->setTitleText(tr("tension ω"));
    // Ticks at multiples of 1/16, the tension of the C^1 scheme whose regularity is 2.
    x->setLabelFormat(QStringLiteral("%.4g"));
    x->setTickType(QValueAxis::TicksDynamic);
    x->setTickAnchor(0.0);
    x->setTickInterval(0.0625);
    auto *y = new QValueAxis;
    y->setTitleText(tr("regularity r"));
    y->setRange(0.0, 2.5);
    y->setTickType(QValueAxis::TicksDynamic);
    y->setTickAnchor(0.0);
    y->setTickInterval(0.5);
    y->setLabelFormat(QStringLiteral("%.1f"));
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    for (QAbstractSeries *s : chart->series()) {
        s->attachAxis(x);
        s->attachAxis(y);
    }
    m_view = new QChartView(chart);
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->setMinimumSize(520, 360);
    resize(820, 560);
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("regularityChartStatus"));
    m_progress = new QProgressBar;
    m_progress->setMaximumWidth(180);
    m_cancel = new QPushButton(tr("Cancel"));
    connect(m_cancel, &QPushButton::clicked, this, &RegularityChart::cancel);
    auto *row = new QHBoxLayout;
    row->addWidget(m_status, 1);
    row->addWidget(m_progress);
    row->addWidget(m_cancel);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_view, 1);
    layout->addLayout(row);
}

RegularityChart::~RegularityChart() { m_worker.stop(); }

QChart *RegularityChart::chart() const { return m_view->chart(); }

void RegularityChart::cancel() { m_worker.cancel(); }

void RegularityChart::compute(double omegaMin, double omegaMax, int count, double budget,
                              const std::vector<int> &classes)
{
    m_worker.stop();
    m_samples.clear();
    m_bands.clear();
    for (QAbstractSeries *s : chart()->series())
        if (qobject_cast<QAreaSeries *>(s)) {
            chart()->removeSeries(s);
            delete s;
        }
    lineSeries(chart(), tr("lower bound"))->clear();
    lineSeries(chart(), tr("upper bound"))->clear();
    auto *x = qobject_cast<QValueAxis *>(chart()->axes(Qt::Horizontal).value(0));
    if (x)
        x->setRange(omegaMin, omegaMax);
    count = std::max(2, count);
    m_progress->setRange(0, count);
    m_progress->setValue(0);
    m_cancel->setEnabled(true);
    m_status->setText(tr("Computing %1 values of ω…").arg(count));
    m_running = true;
    m_worker.start([=, this](const std::atomic<bool> *cancel, quint64 generation) {
        for (int i = 0; i < count && !cancel->load(); ++i) {
            const double omega = omegaMin + (omegaMax - omegaMin) * i / (count - 1);
            RegularityOptions o;
            o.timeBudget = budget;
            o.cancel = cancel;
            const Regularity r = fourPointRegularity(omega, o);
            if (!r.applies)
                continue;
            const Sample s{omega, r.lower, r.upper};
            m_worker.post([=, this] { addSample(s, count, generation); });
        }
        // The bands: where the scheme is certified C^k, the ends bisected.
        std::vector<Band> bands;
        for (const int k : classes) {
            if (cancel->load())
                break;
            FamilyOptions f;
            f.grid = 24;
            f.tolerance = 1e-5;
            f.maxBisections = 30;
            f.budgetPerValue = budget;
            f.cancel = cancel;
            const FamilyResult family =
                regularityInterval(fourPointRegularity, omegaMin, omegaMax, k, f);
            for (const FamilyRun &run : family.runs)
                bands.push_back({k, run.from.inner, run.from.outer, run.to.inner, run.to.outer});
        }
        m_worker.post([=, this] { addBands(bands, generation); });
        m_worker.post([=, this] { done(generation); });
    });
}

void RegularityChart::addSample(const Sample &s, int total, quint64 generation)
{
    if (!m_worker.isCurrent(generation))
        return;
    m_samples.push_back(s);
    // Below the axis (not convergent) the curve is clipped at 0 rather than lost.
    lineSeries(chart(), tr("lower bound"))->append(s.omega, std::max(-0.2, s.lower));
    lineSeries(chart(), tr("upper bound"))->append(s.omega, std::max(-0.2, s.upper));
    m_progress->setValue(int(m_samples.size()));
    emit progressed(int(m_samples.size()), total);
}

void RegularityChart::addBands(const std::vector<Band> &bands, quint64 generation)
{
    if (!m_worker.isCurrent(generation))
        return;
    m_bands = bands;
    auto *x = chart()->axes(Qt::Horizontal).value(0);
    auto *y = chart()->axes(Qt::Vertical).value(0);
    for (const Band &b : bands) {
        // From the axis up to k: "r > k here", tinted by class (C^1 over C^0).
        // QAreaSeries does not own its boundary series: they are its children, deleted with it.
        auto *area = new QAreaSeries;
        auto *top = new QLineSeries(area), *bottom = new QLineSeries(area);
        const double height = std::max(double(b.smoothness), 0.15);  // C^0: a strip on the axis
        top->append(b.from, height);
        top->append(b.to, height);
        bottom->append(b.from, 0.0);
        bottom->append(b.to, 0.0);
        area->setUpperSeries(top);
        area->setLowerSeries(bottom);
        const QString sup = b.smoothness == 0 ? QStringLiteral("⁰")
                            : b.smoothness == 1 ? QStringLiteral("¹")
                                                : QStringLiteral("^%1").arg(b.smoothness);
        // The legend stays short; the status line gives the ends with their brackets.
        area->setName(tr("C%1 (certified)").arg(sup));
        QColor fill = b.smoothness == 0 ? QColor(120, 120, 120, 70) : QColor(40, 160, 80, 60);
        area->setBrush(fill);
        area->setPen(Qt::NoPen);
        chart()->addSeries(area);
        if (x && y) {
            area->attachAxis(x);
            area->attachAxis(y);
        }
    }
}

void RegularityChart::done(quint64 generation)
{
    if (!m_worker.isCurrent(generation))
        return;
    m_running = false;
    m_cancel->setEnabled(false);
    double widest = 0.0;
    for (const Sample &s : m_samples)
        widest = std::max(widest, s.upper - s.lower);
    QString c1;
    for (const Band &b : m_bands)
        if (b.smoothness == 1)
            c1 = tr("; C¹ for ω in (%1, %2), the ends in [%3, %4] and [%5, %6]")
                     .arg(b.from, 0, 'g', 6)
                     .arg(b.to, 0, 'g', 6)
                     .arg(std::min(b.from, b.fromOuter), 0, 'g', 6)
                     .arg(std::max(b.from, b.fromOuter), 0, 'g', 6)
                     .arg(std::min(b.to, b.toOuter), 0, 'g', 6)
                     .arg(std::max(b.to, b.toOuter), 0, 'g', 6);
    m_status->setText(tr("%1 values of ω; widest interval %2 (bounds certified; the upper "
                         "bound is exact for this interpolatory scheme)%3")
                          .arg(m_samples.size())
                          .arg(widest, 0, 'g', 2)
                          .arg(c1));
    m_status->setWordWrap(true);
    emit finished();
}

} // namespace awb
