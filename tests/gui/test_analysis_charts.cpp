// The analysis charts: series and axes for the distance to the exact curve (log axis), the
// polygon length per subdivision step, the box-counting fit of a cubic B-spline attractor
// (dimension 1) and |λ| per map.

#include "gui/views/AnalysisCharts.h"

#include "core/ifs/Attractor.h"
#include "core/analysis/Geometry.h"

#include <QChart>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QScatterSeries>
#include <QTabWidget>
#include <QValueAxis>
#include <QChartView>
#include <QtTest>

#include "TestMain.h"

#include <cmath>

using namespace awb;

class TestAnalysisCharts : public QObject {
    Q_OBJECT
private slots:
    void distances();
    void polygonLengths();
    void boxCounting();
    void moduli();
    void replacingDataReplacesSeries();
};

void TestAnalysisCharts::distances()
{
    AnalysisCharts charts;
    std::vector<double> depth, a, b;
    for (int k = 4; k <= 12; ++k) {
        depth.push_back(k);
        a.push_back(3 * std::pow(0.5, k));
        b.push_back(k == 8 ? 0.0 : 5 * std::pow(0.5, k)); // 0 cannot go on a log axis
    }
    charts.setDistances({{QStringLiteral("point"), depth, a},
                         {QStringLiteral("triangle"), depth, b}},
                        0.5);
    QChart *c = charts.chart(AnalysisCharts::DistanceTab);
    QCOMPARE(c->series().size(), 3); // two measured series and the λ^k reference
    auto *first = qobject_cast<QLineSeries *>(c->series().at(0));
    auto *second = qobject_cast<QLineSeries *>(c->series().at(1));
    QVERIFY(first && second);
    QCOMPARE(first->count(), 9);
    QCOMPARE(second->count(), 8);
    const auto vertical = c->axes(Qt::Vertical);
    QCOMPARE(vertical.size(), 1);
    auto *log = qobject_cast<QLogValueAxis *>(vertical.first());
    QVERIFY(log);
    QVERIFY(log->min() <= 3 * std::pow(0.5, 12) && log->max() >= 5 * std::pow(0.5, 4));
    // Without a rate there is no reference line.
    charts.setDistances({{QStringLiteral("point"), depth, a}});
    QCOMPARE(c->series().size(), 1);
}

void TestAnalysisCharts::polygonLengths()
{
    AnalysisCharts charts;
    charts.setPolygonLengths({10.2, 9.1, 8.8, 8.75, 8.73}, 8.72);
    QChart *c = charts.chart(AnalysisCharts::LengthTab);
    QCOMPARE(c->series().size(), 2);
    auto *s = qobject_cast<QLineSeries *>(c->series().at(0));
    QVERIFY(s);
    QCOMPARE(s->count(), 5);
    QCOMPARE(s->at(4), QPointF(4, 8.73));
    charts.setPolygonLengths({10.2, 9.1});
    QCOMPARE(c->series().size(), 1);
}

void TestAnalysisCharts::boxCounting()
{
    Mat P(5, 2);
    P << 0, 0, 1, 2, 3, 2.5, 4.5, 1, 6, 2;
    const SubdivisionIfs s = buildSubdivisionIfs(bsplineScheme(3), P);
    PointCollector points(s.ifs.views.front());
    iterate(s.ifs, StartSet::points(s.toIfsSpace(P.topRows(1))), 16, points);
    const BoxDimension box = boxCountingDimension(points.points());
    QVERIFY(box.valid);
    AnalysisCharts charts;
    charts.setBoxCounting(box);
    QChart *c = charts.chart(AnalysisCharts::BoxCountingTab);
    QCOMPARE(c->series().size(), 3); // levels left out, fitted levels, fitted line
    auto *left = qobject_cast<QScatterSeries *>(c->series().at(0));
    auto *fitted = qobject_cast<QScatterSeries *>(c->series().at(1));
    QVERIFY(left && fitted);
    QCOMPARE(fitted->count(), box.levelTo - box.levelFrom + 1);
    QCOMPARE(left->count() + fitted->count(), int(box.logCount.size()));
    QVERIFY2(c->title().contains(QStringLiteral("D = %1").arg(box.dimension, 0, 'f', 4)),
             qPrintable(c->title()));
    QVERIFY(c->title().contains(QStringLiteral("R²")));
    QVERIFY(std::abs(box.dimension - 1.0) < 0.1);
    // The line passes through the fit.
    auto *line = qobject_cast<QLineSeries *>(c->series().at(2));
    QVERIFY(line);
    const QPointF p0 = line->at(0);
    QVERIFY(std::abs(p0.y() - (box.intercept + box.dimension * p0.x())) < 1e-12);

    BoxDimension none;
    none.note = "too few points";
    charts.setBoxCounting(none);
    QCOMPARE(c->series().size(), 2);
    // A short title (a long one squeezes the axis labels to "…"); the reason in the tooltip.
    QCOMPARE(c->title(), QStringLiteral("No fit"));
    QVERIFY(charts.chartView(AnalysisCharts::BoxCountingTab)->toolTip().contains(
        QLatin1String("too few points")));
}

void TestAnalysisCharts::moduli()
{
    AnalysisCharts charts;
    charts.setModuli({{QStringLiteral("S_1"), {1, 0.5, 0.25, 0.125, 0.0}},
                      {QStringLiteral("S_2"), {1, 0.5, 0.25, 0.125, 0.0}},
                      {QStringLiteral("S_3"), {1.2, 0.3}}});
    QChart *c = charts.chart(AnalysisCharts::ModuliTab);
    QCOMPARE(c->series().size(), 4); // one per map and the line |λ| = 1
    auto *third = qobject_cast<QScatterSeries *>(c->series().at(2));
    QVERIFY(third);
    QCOMPARE(third->count(), 2);
    QCOMPARE(third->at(0), QPointF(3, 1.2));
    auto *y = qobject_cast<QValueAxis *>(c->axes(Qt::Vertical).first());
    QVERIFY(y && y->max() >= 1.2);
}

void TestAnalysisCharts::replacingDataReplacesSeries()
{
    AnalysisCharts charts;
    for (int i = 0; i < 3; ++i)
        charts.setModuli({{QStringLiteral("S_1"), {1, 0.5}}});
    QChart *c = charts.chart(AnalysisCharts::ModuliTab);
    QCOMPARE(c->series().size(), 2);
    QCOMPARE(c->axes().size(), 2);
    QCOMPARE(charts.tabs()->count(), 4);
}

AWB_TEST_MAIN(TestAnalysisCharts)
#include "test_analysis_charts.moc"
