#pragma once
// The application's small dialogs: ExportDialog (which view, format by file suffix, size in
// pixels and resolution) and PreferencesDialog (default depth, palette, autosave interval),
// whose values live in QSettings through the Preferences value type. Their layouts are the
// Qt Designer forms ui/exportdialog.ui and ui/preferencesdialog.ui.
#include <QColor>
#include <QDialog>
#include <QList>
#include <QSize>

#include <memory>

class QToolButton;

namespace Ui {
class ExportDialog;
class PreferencesDialog;
} // namespace Ui

namespace awb {

// The user's preferences, stored in QSettings under "preferences/".
struct Preferences {
    int defaultDepth = 10;           // given to new items
    int maxRenderDepth = 0;          // caps the drawn depth (0: no cap)
    QList<QColor> palette;           // empty: the views' defaults
    int autosaveSeconds = 30;
    QString daskScheduler;           // the Regularity Atlas's cluster; empty: a local one
    int atlasWorkers = 0;            // its local cluster's workers (0: one per core)
    static Preferences load();
    void save() const;
};

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    enum class Target { Attractor, Spectrum, Matrices, Analysis, FigureSheet };
    struct Options {
        Target target = Target::Attractor;
        QString fileName;            // suffix .png, .svg or .pdf picks the format
        QSize size{1600, 1200};      // pixels (PNG) or pixel units at `dpi` (SVG, PDF)
        int dpi = 300;
        bool grid = true;            // attractor view: grid and labels
        bool handles = true;         // attractor view: control polygons, start set, labels
        bool crop = false;           // attractor view: frame the content, height to fit
        QString fontFamily;          // empty: the view's font
        double fontPoints = 0;       // 0: as on screen
    };
    explicit ExportDialog(const Options &initial, QWidget *parent = nullptr);
    ~ExportDialog() override;
    Options options() const;

private:
    void browse();
    std::unique_ptr<Ui::ExportDialog> m_ui;
};

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    explicit PreferencesDialog(const Preferences &initial, QWidget *parent = nullptr);
    ~PreferencesDialog() override;
    Preferences preferences() const;

private:
    QList<QToolButton *> colourButtons() const;  // the form's, in map order
    void showColours();
    std::unique_ptr<Ui::PreferencesDialog> m_ui;
    QList<QColor> m_palette;
};

} // namespace awb
