#include "gui/views/RegularityChart.h"

#include "core/analysis/Regularity.h"
#include "core/schemes/Scheme.h"

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
    known->setName(tr("known: ω = 0 → 1, ω = 1/16 → 2"));
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

void RegularityChart::compute(double omegaMin, double omegaMax, int count, double budget)
{
    m_worker.stop();
    m_samples.clear();
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
            const Regularity r = schemeRegularity(fourPointScheme(omega), 8, o);
            if (!r.applies)
                continue;
            const Sample s{omega, r.lower, r.upper};
            m_worker.post([=, this] { addSample(s, count, generation); });
        }
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

void RegularityChart::done(quint64 generation)
{
    if (!m_worker.isCurrent(generation))
        return;
    m_running = false;
    m_cancel->setEnabled(false);
    double widest = 0.0;
    for (const Sample &s : m_samples)
        widest = std::max(widest, s.upper - s.lower);
    m_status->setText(tr("%1 values of ω; widest interval %2 (bounds certified; the upper "
                         "bound is exact for this interpolatory scheme)")
                          .arg(m_samples.size())
                          .arg(widest, 0, 'g', 2));
    emit finished();
}

} // namespace awb
