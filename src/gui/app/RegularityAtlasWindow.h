#pragma once
// View > Regularity Atlas (issue 48): where the family of the selected curve's scheme is C^k,
// over a grid of one or two of its parameters (the four-point omega, a corner cutting's a and b,
// names written into a mask), drawn as the rows arrive (AtlasPlot). The computation is the
// Python module's atlas, run as a process -- `python3 -m attractor_workbench.atlas` on a local
// Dask cluster, on the scheduler named in Preferences, or in that one process -- so the window,
// a script and a cluster job compute the same rows the same way. Cancel stops it (and the
// cluster's tasks). A click on a row adds an item with that member's scheme (one undo step).

#include "core/analysis/RegularityAtlas.h"

#include <QPointer>
#include <QProcess>
#include <QWidget>

#include <memory>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTemporaryDir;

namespace awb {

class AtlasPlot;
class Item;
class Project;
class SubdivisionCurveItem;

class RegularityAtlasWindow : public QWidget {
    Q_OBJECT
public:
    enum class Where { LocalCluster, Scheduler, InProcess };

    RegularityAtlasWindow(Project *project, QWidget *parent = nullptr);
    ~RegularityAtlasWindow() override;

    // The curve whose family the form describes; fills the form with its parameters.
    void setItem(SubdivisionCurveItem *item);
    SubdivisionCurveItem *item() const;

    // The form, for scripts and tests: the axes (one or two), the mask (mask items), k.
    void setAxes(const std::vector<AtlasAxis> &axes);
    std::vector<AtlasAxis> axes() const;
    void setMask(const QString &mask);
    void setSmoothness(int k);
    void setTolerance(double tolerance);
    void setRefinement(int levels);
    void setWhere(Where where);
    Where where() const;

    // Starts the run (refused with a message in the status line when the form is incomplete).
    bool start();
    void cancel();
    bool isRunning() const;
    QString statusText() const;
    AtlasPlot *plot() const { return m_plot; }

    // Adds a copy of the item with the member at `params` to the project (one undo step);
    // nullptr with the reason in the status line when there is no such member.
    Item *addItemAt(const std::vector<double> &params);

    // The Python interpreter and the folder of the package attractor_workbench it is given.
    static QString pythonProgram();
    static QString modulePath();

signals:
    void finished(bool ok);

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void readOutput();
    void processFinished(int code, QProcess::ExitStatus status);
    void showStatus(const QString &text, bool error = false);
    void updateForm();
    void offerItemAt(int row, const QPoint &globalPos);

    Project *m_project;
    QPointer<SubdivisionCurveItem> m_item;
    AtlasPlot *m_plot = nullptr;
    QLabel *m_itemLabel = nullptr;
    QLineEdit *m_mask = nullptr;
    struct AxisFields {
        QLineEdit *name = nullptr;
        QDoubleSpinBox *from = nullptr, *to = nullptr;
        QSpinBox *count = nullptr;
    } m_fields[2];
    QCheckBox *m_second = nullptr;
    QSpinBox *m_smoothness = nullptr;
    QLineEdit *m_tolerance = nullptr;
    QSpinBox *m_refine = nullptr;
    QComboBox *m_where = nullptr;
    QPushButton *m_startButton = nullptr;
    QPushButton *m_cancelButton = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_status = nullptr;

    QProcess *m_process = nullptr;
    std::unique_ptr<QTemporaryDir> m_dir;
    QByteArray m_pending;     // a partial line of the process's output
    QByteArray m_errors;      // its standard error
    std::vector<AtlasAxis> m_runAxes;
    int m_runSmoothness = 1;
    int m_round = 0;
    bool m_cancelled = false;
};

} // namespace awb
