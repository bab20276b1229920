#pragma once
// The certified Hölder regularity of the current curve scheme (issue 16), shown under the
// Analysis dock's charts: the smoothness class, the interval [lower, upper] and its width, the
// method; computed on a worker thread within a time budget, with progress and a cancel button.
// It observes: ItemController hands it the scheme, it never touches the document.

#include "gui/views/CancellableWorker.h"

#include <QWidget>

#include <memory>

class QLabel;
class QProgressBar;
class QToolButton;

namespace awb {

struct SchemeSpec;
struct Regularity;

class RegularityPanel : public QWidget {
    Q_OBJECT
public:
    explicit RegularityPanel(QWidget *parent = nullptr);
    ~RegularityPanel() override;

    // Starts the analysis of the scheme `spec` with m control points -- the model's
    // specRegularity(), as attractor-cli analyse and Python compute it -- unless `key` (the
    // scheme's parameters and m) is what is shown or being computed already. Cancels a
    // running one.
    void analyse(const SchemeSpec &spec, int m, const QString &key);
    // No scheme to analyse (another kind of item): show why.
    void showMessage(const QString &message);
    void cancel();

    void setTimeBudget(double seconds) { m_budget = seconds; }
    bool isRunning() const { return m_running; }
    QString summary() const;      // the text of the result line
    QString method() const;       // the text of the method line
    // The last result shown (null while computing or when nothing applies), and the key of
    // the scheme it belongs to.
    std::shared_ptr<const Regularity> result() const { return m_result; }
    QString resultKey() const { return m_result ? m_key : QString(); }

signals:
    void finished();
    // The result is exact and the user asked to save its certificate.
    void saveCertificateRequested();

private:
    void showResult(const Regularity &r, quint64 generation);
    void showProgress(double lower, double upper, double fraction, quint64 generation);

    QLabel *m_summary = nullptr;
    QLabel *m_method = nullptr;
    QProgressBar *m_progress = nullptr;
    QToolButton *m_cancel = nullptr;
    QToolButton *m_save = nullptr;
    std::shared_ptr<const Regularity> m_result;
    CancellableWorker m_worker{this};
    QString m_key;
    double m_budget = 2.0;
    bool m_running = false;
};

// "C^1, r in [1.9999, 2] (width 1e-06)" or the reason the analysis does not apply.
QString regularityText(const Regularity &r);
// The core's ASCII formulas as the papers write them: log_2 -> log₂, rho_n -> ρₙ, ^4 -> ⁴.
QString mathText(const QString &ascii);

} // namespace awb
