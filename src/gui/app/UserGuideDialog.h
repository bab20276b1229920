#pragma once
// UserGuideDialog (layer 3, GUI): Help > User Guide. The bundled guide (:/guide/user-guide.html,
// Qt resource system) in a QTextBrowser, its keyboard shortcut table made from the actions
// themselves so that it never disagrees with the menus.
#include <QDialog>
#include <QList>

class QAction;
class QTextBrowser;

namespace awb {

class UserGuideDialog : public QDialog {
    Q_OBJECT
public:
    // `actions`: those whose shortcuts are listed (in this order; ones without a shortcut are
    // left out).
    explicit UserGuideDialog(const QList<QAction *> &actions, QWidget *parent = nullptr);

    QTextBrowser *browser() const { return m_browser; }
    // The guide's HTML with the shortcut table filled in.
    static QString html(const QList<QAction *> &actions);

private:
    QTextBrowser *m_browser;
};

} // namespace awb
