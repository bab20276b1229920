#pragma once
// The application's small dialogs: ExportDialog (which view, format by file suffix, size in
// pixels and resolution) and PreferencesDialog (default depth, palette, autosave interval),
// whose values live in QSettings through the Preferences value type.
#include <QColor>
#include <QDialog>
#include <QList>
#include <QSize>

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;
class QToolButton;

namespace awb {

// The user's preferences, stored in QSettings under "preferences/".
struct Preferences {
    int defaultDepth = 10;           // given to new items
    int maxRenderDepth = 0;          // caps the drawn depth (0: no cap)
    QList<QColor> palette;           // empty: the views' defaults
    int autosaveSeconds = 30;
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
    };
    explicit ExportDialog(const Options &initial, QWidget *parent = nullptr);
    Options options() const;

private:
    void browse();
    QComboBox *m_target;
    QLineEdit *m_file;
    QSpinBox *m_width, *m_height, *m_dpi;
};

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    explicit PreferencesDialog(const Preferences &initial, QWidget *parent = nullptr);
    Preferences preferences() const;

private:
    void showColours();
    QSpinBox *m_depth, *m_maxDepth, *m_autosave;
    QList<QToolButton *> m_colourButtons;
    QList<QColor> m_palette;
};

} // namespace awb
