#pragma once
// The Python console dock (View > Python Console): the attractor_workbench module (the same
// bindings as the standalone module, src/python) in an interpreter embedded in the
// application, with `project` bound to the open document and `item` to the current item, so
// that what a script changes is one more undoable edit the views follow. It also shows the
// ScriptRecorder's lines: every edit made in the window appears as the Python that makes it.
// The interpreter starts on the first command, not with the application. Only this file's
// .cpp includes pybind11 (compile time).

#include <QWidget>

#include <functional>
#include <memory>

class QLineEdit;
class QPlainTextEdit;
class QLabel;

namespace awb {

class Item;
class Project;
class ScriptRecorder;

class PythonConsole : public QWidget {
    Q_OBJECT
public:
    PythonConsole(Project *project, ScriptRecorder *recorder,
                  std::function<Item *()> currentItem, QWidget *parent = nullptr);
    ~PythonConsole() override;

    // Runs one line typed at the prompt (or a block: lines until the statement is complete),
    // as pressing Return does; returns false while a block waits for more lines.
    bool enter(const QString &line);
    // Runs a script file in the console's namespace (`project`, `item`, `awb`; sys.argv is
    // [file]), its output and errors shown; false (with *error) when the file cannot be read.
    bool runFile(const QString &fileName, QString *error = nullptr);
    // The whole text shown (prompts, output, recorded lines).
    QString transcript() const;
    QLineEdit *input() const { return m_input; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    void begin();
    void startInterpreter();
    void run(const QString &source);
    // Appends `text` to the output in `colour` (not QWidget::show).
    void print(const QString &text, const QString &colour, bool italic = false);
    void onRecorded(const QString &lines);
    void onLastReplaced(const QString &lines);

    struct Interpreter;
    std::unique_ptr<Interpreter> m_python;
    Project *m_project;
    ScriptRecorder *m_recorder;
    std::function<Item *()> m_currentItem;
    QPlainTextEdit *m_output;
    QLineEdit *m_input;
    QLabel *m_prompt;
    QStringList m_pending;  // lines of an incomplete block
    QStringList m_history;
    int m_historyPos = 0;
    int m_lastRecordedStart = -1;
    bool m_begun = false;  // the welcome and the recording shown (on the first show)  // where the last recorded step's text starts (replaceable)
};

} // namespace awb
