#include "gui/app/Messages.h"

#include <QCoreApplication>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace awb {

QMessageBox *Messages::makeBox(QMessageBox::Icon icon, QWidget *parent, const QString &title,
                               const QString &text)
{
    constexpr int shownLines = 12;
    constexpr int shownCharacters = 1500;
    auto *box = new QMessageBox(icon, title, text, QMessageBox::Ok, parent);
    const QStringList lines = text.split(QLatin1Char('\n'));
    if (lines.size() > shownLines || text.size() > shownCharacters) {
        QString head = lines.mid(0, shownLines).join(QLatin1Char('\n'));
        if (head.size() > shownCharacters)
            head = head.left(shownCharacters) + QStringLiteral("…");
        const int rest = int(lines.size()) - std::min(int(lines.size()), shownLines);
        head += QLatin1Char('\n')
                + (rest > 0 ? QCoreApplication::translate(
                                  "awb::Messages", "… and %1 more lines: Show Details… lists "
                                                   "them all.")
                                  .arg(rest)
                            : QCoreApplication::translate("awb::Messages",
                                                          "Show Details… shows the whole text."));
        box->setText(head);
        box->setDetailedText(text);
    }
    return box;
}

namespace {
void showBox(QMessageBox::Icon icon, QWidget *parent, const QString &title, const QString &text)
{
    std::unique_ptr<QMessageBox> box(Messages::makeBox(icon, parent, title, text));
    box->exec();
}
} // namespace

void Messages::error(QWidget *parent, const QString &title, const QString &text)
{
    showBox(QMessageBox::Critical, parent, title, text);
}

void Messages::information(QWidget *parent, const QString &title, const QString &text)
{
    showBox(QMessageBox::Information, parent, title, text);
}

QMessageBox::StandardButton Messages::question(QWidget *parent, const QString &title,
                                               const QString &text,
                                               QMessageBox::StandardButtons buttons,
                                               QMessageBox::StandardButton defaultButton)
{
    return QMessageBox::question(parent, title, text, buttons, defaultButton);
}

void ConsoleMessages::error(QWidget *, const QString &title, const QString &text)
{
    ++m_errors;
    std::fprintf(stderr, "attractor-workbench: %s: %s\n", qPrintable(title), qPrintable(text));
}

void ConsoleMessages::information(QWidget *, const QString &title, const QString &text)
{
    std::fprintf(stderr, "attractor-workbench: %s: %s\n", qPrintable(title), qPrintable(text));
}

QMessageBox::StandardButton ConsoleMessages::question(QWidget *, const QString &title,
                                                      const QString &text,
                                                      QMessageBox::StandardButtons,
                                                      QMessageBox::StandardButton defaultButton)
{
    std::fprintf(stderr, "attractor-workbench: %s: %s (answered by default)\n",
                 qPrintable(title), qPrintable(text));
    return defaultButton;
}

} // namespace awb
