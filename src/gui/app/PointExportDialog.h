#pragma once
// PointExportDialog (layer 3, GUI): File > Export Points. The user picks the file (CSV, or PLY
// for a point cloud; the suffix decides) and the depth k of F^k(X0), seeing how many points
// that makes. exportPoints() then writes them through the model's PointExport (the code of
// attractor-cli points / export) on a worker thread, with a cancellable progress dialog.
#include <QColor>
#include <QDialog>
#include <functional>

class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace awb {

class AttractorItem;

class PointExportDialog : public QDialog {
    Q_OBJECT
public:
    PointExportDialog(const AttractorItem *item, const QString &fileName,
                      QWidget *parent = nullptr);

    QString fileName() const;
    void setFileName(const QString &fileName);
    int depth() const;
    void setDepth(int depth);
    // The points the choice makes (-1: unknown, an automaton).
    double pointCount() const;

    // Writes F^depth(X0) of `item` to `fileName` (.csv or .ply); false with *error on failure
    // or cancel (then nothing is written). `color`: the map colours for PLY. With a `parent`,
    // a progress dialog appears after a moment.
    static bool exportPoints(const AttractorItem *item, const QString &fileName, int depth,
                             const std::function<QColor(int)> &color, QWidget *parent,
                             QString *error);

    // More points than this are refused (a file of gigabytes is never what was meant).
    static constexpr double maxPoints = 50'000'000;

private:
    void updateCount();

    const AttractorItem *m_item;
    QLineEdit *m_file = nullptr;
    QComboBox *m_format = nullptr;
    QSpinBox *m_depth = nullptr;
    QLabel *m_count = nullptr;
};

} // namespace awb
