#include "gui/app/Messages.h"

#include <cstdio>

namespace awb {

void Messages::error(QWidget *parent, const QString &title, const QString &text)
{
    QMessageBox::critical(parent, title, text);
}

void Messages::information(QWidget *parent, const QString &title, const QString &text)
{
    QMessageBox::information(parent, title, text);
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
