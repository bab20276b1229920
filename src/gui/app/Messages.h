#pragma once
// Messages: the one place the application tells the user something or asks a question.
// Modal message boxes block a test, so every window reports through a Messages object; tests
// install a subclass that records the texts and returns scripted answers.
#include <QMessageBox>
#include <QString>
#include <QStringList>

class QWidget;

namespace awb {

class Messages {
public:
    // The box Messages shows for a text (not shown): a long text -- the warnings of a flame
    // pack, hundreds of lines -- keeps its first lines in the box and the whole in the
    // scrollable "Show Details…" part, so that the box fits the screen and its buttons stay on
    // it (issue 47).
    static QMessageBox *makeBox(QMessageBox::Icon icon, QWidget *parent, const QString &title,
                                const QString &text);

    virtual ~Messages() = default;
    virtual void error(QWidget *parent, const QString &title, const QString &text);
    virtual void information(QWidget *parent, const QString &title, const QString &text);
    // Returns one of `buttons` (QMessageBox standard buttons).
    virtual QMessageBox::StandardButton question(QWidget *parent, const QString &title,
                                                 const QString &text,
                                                 QMessageBox::StandardButtons buttons,
                                                 QMessageBox::StandardButton defaultButton);
};

// Writes errors and notes to standard error and takes every question's default answer: for
// runs without a user (attractor-workbench --print-pdf / --screenshot), where a modal box would
// wait forever.
class ConsoleMessages : public Messages {
public:
    void error(QWidget *, const QString &title, const QString &text) override;
    void information(QWidget *, const QString &title, const QString &text) override;
    QMessageBox::StandardButton question(QWidget *, const QString &title, const QString &text,
                                         QMessageBox::StandardButtons,
                                         QMessageBox::StandardButton defaultButton) override;
    int errorCount() const { return m_errors; }

private:
    int m_errors = 0;
};

// Records everything and answers with `answer`; for tests and scripted runs.
class RecordingMessages : public Messages {
public:
    void error(QWidget *, const QString &title, const QString &text) override
    {
        errors << title + QStringLiteral(": ") + text;
    }
    void information(QWidget *, const QString &title, const QString &text) override
    {
        infos << title + QStringLiteral(": ") + text;
    }
    QMessageBox::StandardButton question(QWidget *, const QString &title, const QString &text,
                                         QMessageBox::StandardButtons,
                                         QMessageBox::StandardButton) override
    {
        questions << title + QStringLiteral(": ") + text;
        return answer;
    }
    QStringList errors, infos, questions;
    QMessageBox::StandardButton answer = QMessageBox::Discard;
};

} // namespace awb
