#pragma once
// A window charting the certified Hölder regularity of the four-point scheme against its
// tension omega (issue 16): the lower and upper bound curves, and the values known exactly
// (omega = 0: piecewise linear, 1; omega = 1/16: Dubuc-Deslauriers, 2). The sweep runs on a
// worker thread, one time budget per omega, with progress and cancel; Qt Charts stays out of
// this header.

#include "gui/views/CancellableWorker.h"

#include <QWidget>

#include <vector>

class QChart;
class QChartView;
class QLabel;
class QProgressBar;
class QPushButton;

namespace awb {

class RegularityChart : public QWidget {
    Q_OBJECT
public:
    struct Sample {
        double omega = 0.0;
        double lower = 0.0;
        double upper = 0.0;
    };

    explicit RegularityChart(QWidget *parent = nullptr);
    ~RegularityChart() override;

    // One band: the omega interval where the scheme is certified C^k, each end bracketed
    // [inner, outer] by bisection on certified bounds (core RegularityFamily, the computation
    // of `attractor-cli regularity-interval`).
    struct Band {
        int smoothness = 1;
        double from = 0.0, fromOuter = 0.0;  // inner end certified C^k, outer certified not
        double to = 0.0, toOuter = 0.0;
    };

    // Sweeps omega over [omegaMin, omegaMax] in `count` evenly spaced values (restarting a
    // running sweep), each with `budget` seconds for its joint spectral radius; then the bands
    // of the classes C^k, k in `classes`.
    void compute(double omegaMin = -0.125, double omegaMax = 0.375, int count = 81,
                 double budget = 0.1, const std::vector<int> &classes = {0, 1});
    void cancel();
    bool isRunning() const { return m_running; }
    const std::vector<Sample> &samples() const { return m_samples; }
    const std::vector<Band> &bands() const { return m_bands; }
    QChart *chart() const;
    QChartView *chartView() const { return m_view; }

signals:
    void progressed(int done, int total);
    void finished();

private:
    void addSample(const Sample &s, int total, quint64 generation);
    void addBands(const std::vector<Band> &bands, quint64 generation);
    void done(quint64 generation);

    QChartView *m_view = nullptr;
    QLabel *m_status = nullptr;
    QProgressBar *m_progress = nullptr;
    QPushButton *m_cancel = nullptr;
    CancellableWorker m_worker{this};
    std::vector<Sample> m_samples;
    std::vector<Band> m_bands;
    bool m_running = false;
};

} // namespace awb
