#include "gui/app/UserGuideDialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QFile>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace awb {

UserGuideDialog::UserGuideDialog(const QList<QAction *> &actions, QWidget *parent)
    : QDialog(parent), m_browser(new QTextBrowser)
{
    setObjectName(QStringLiteral("userGuide"));
    // The desktop adds the application's name to the title.
    setWindowTitle(tr("User Guide"));
    m_browser->setOpenExternalLinks(true);
    m_browser->setHtml(html(actions));
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_browser);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(720, 640);
}

QString UserGuideDialog::html(const QList<QAction *> &actions)
{
    QFile file(QStringLiteral(":/guide/user-guide.html"));
    QString text = file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll())
                                                  : tr("<p>The guide is missing.</p>");
    QString table = QStringLiteral("<table border='0' cellspacing='2' cellpadding='2'>");
    for (const QAction *a : actions) {
        if (!a || a->shortcut().isEmpty())
            continue;
        QString what = a->text();
        what.remove(QLatin1Char('&'));
        what.remove(QStringLiteral("…"));
        table += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>")
                     .arg(a->shortcut().toString(QKeySequence::NativeText).toHtmlEscaped(),
                          what.toHtmlEscaped());
    }
    // Keys of the attractor view itself (not actions).
    const QList<QPair<QString, QString>> viewKeys{
        {tr("Home or F"), tr("Fit the attractor view to its content")},
        {tr("+ / −"), tr("Zoom the attractor view in / out")},
        {tr("Mouse wheel"), tr("Zoom at the cursor (view); scroll (panels)")}};
    for (const auto &[key, what] : viewKeys)
        table += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>")
                     .arg(key.toHtmlEscaped(), what.toHtmlEscaped());
    table += QStringLiteral("</table>");
    text.replace(QStringLiteral("<!--SHORTCUTS-->"), table);
    return text;
}

} // namespace awb
