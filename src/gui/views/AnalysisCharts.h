#pragma once
// Analysis charts (Qt Charts) of the current item, one tab each: the Hausdorff distance to the
// exact curve against the depth (log scale), the control-polygon length against the
// subdivision step, the box-counting fit with its dimension, and |λ| per map. Inputs are plain
// vectors computed elsewhere (off the GUI thread when heavy); Qt Charts stays out of this header.
// Pointing at a data point shows its values in a tooltip. A note above the tabs carries what
// the status bar has no room for (why an item cannot be drawn, what its IFS is).

#include <QList>
#include <QPointF>
#include <QString>
#include <QWidget>

#include <vector>

class QChart;
class QChartView;
class QLabel;
class QTabWidget;

namespace awb {

struct BoxDimension;

class AnalysisCharts : public QWidget {
    Q_OBJECT
public:
    enum Tab { DistanceTab, LengthTab, BoxCountingTab, ModuliTab };

    struct DistanceSeries {
        QString name;                   // e.g. "from a point", "from a triangle"
        std::vector<double> depth;
        std::vector<double> distance;   // non-positive values cannot be shown on a log axis
    };
    struct MapModuli {
        QString label;                  // "S_1"
        std::vector<double> moduli;     // |λ| of each eigenvalue
    };

    explicit AnalysisCharts(QWidget *parent = nullptr);
    ~AnalysisCharts() override;

    // (a) d_H(F^k(X0), curve) against k. With rate > 0 a dashed reference line
    // C rate^k through the first point of the first series shows the expected convergence.
    // What the distances are measured against, for the chart's tooltip ("Fᵏ(X₀) to the
    // exact curve: uniform B-spline ...").
    void setDistanceReference(const QString &text) { m_distanceReference = text; }
    void setDistances(const QList<DistanceSeries> &series, double rate = 0.0);
    // (b) length of the control polygon after k classic subdivision steps (lengths[k]);
    // exactLength > 0 adds the exact curve's length as a dashed line.
    void setPolygonLengths(const std::vector<double> &lengths, double exactLength = 0.0);
    // (c) log N(ε) against log 1/ε for every level, the fitted line over the fitted levels,
    // the dimension and R² in the title.
    void setBoxCounting(const BoxDimension &box);
    // (d) |λ| of each eigenvalue, one column per map, with the line |λ| = 1.
    void setModuli(const QList<MapModuli> &maps);

    // A note on the current item above the charts (hidden when empty).
    void setNote(const QString &text);
    QString note() const;

    // The tooltip of data point `p` of the series named `series` in chart `tab`.
    static QString pointToolTip(Tab tab, const QString &series, const QPointF &p);

    QChart *chart(Tab tab) const;
    QChartView *chartView(Tab tab) const;
    QTabWidget *tabs() const { return m_tabs; }

private:
    QChartView *makeView(const QString &title);
    // Hover tooltips on every series of chart `tab` (after its series were made).
    void addToolTips(Tab tab);
    void fitToView(QChartView *view);
    bool eventFilter(QObject *watched, QEvent *event) override;

    QLabel *m_note = nullptr;
    QTabWidget *m_tabs = nullptr;
    QList<QChartView *> m_views;
    QList<MapModuli> m_moduli;   // what the moduli chart shows
    QString m_distanceReference;
    bool m_moduliShown = false;
};

} // namespace awb
