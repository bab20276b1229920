#include "gui/console/PythonConsole.h"

#include "model/Item.h"
#include "model/Project.h"
#include "model/ScriptRecorder.h"
#include "python/Bindings.h"

#include <QEvent>
#include <QFile>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextCursor>
#include <QVBoxLayout>

// Python's headers name a struct member `slots`, Qt's a macro: hide the macro from them.
#pragma push_macro("slots")
#undef slots
#include <pybind11/embed.h>
#pragma pop_macro("slots")

namespace py = pybind11;

// The module the console imports: the bindings of the standalone module, compiled into the
// application (an embedded module comes before any attractor_workbench on sys.path).
PYBIND11_EMBEDDED_MODULE(attractor_workbench, m)
{
    awb::python::defineModule(m);
}

namespace awb {

struct PythonConsole::Interpreter {
    py::dict globals;
    py::object project;
};

namespace {

// Runs `source` (a complete statement or block) in `globals` like Python's interactive
// prompt: expression values are printed (sys.displayhook), output and tracebacks are captured.
const char *const runner = R"PY(
def _awb_console_run(source, globals):
    import codeop, io, sys, traceback
    out = io.StringIO()
    old = sys.stdout, sys.stderr
    sys.stdout = sys.stderr = out
    try:
        code = codeop.compile_command(source, "<console>", "single")
        if code is None:
            return None
        exec(code, globals)
    except SystemExit:
        print("(exit() is not available in the console)")
    except BaseException:
        etype, value, tb = sys.exc_info()
        while tb is not None and tb.tb_frame.f_code.co_filename != "<console>":
            tb = tb.tb_next
        traceback.print_exception(etype, value, tb)
    finally:
        sys.stdout, sys.stderr = old
    return out.getvalue()

def _awb_console_exec(source, filename, globals):
    import io, sys, traceback
    out = io.StringIO()
    old = sys.stdout, sys.stderr, sys.argv
    sys.stdout = sys.stderr = out
    sys.argv = [filename]
    globals["__file__"] = filename
    try:
        exec(compile(source, filename, "exec"), globals)
    except SystemExit as e:
        if e.code not in (None, 0):
            print("(the script exited with %r)" % (e.code,))
    except BaseException:
        etype, value, tb = sys.exc_info()
        traceback.print_exception(etype, value, tb.tb_next if tb else None)
    finally:
        sys.stdout, sys.stderr, sys.argv = old
        globals.pop("__file__", None)
    return out.getvalue()

def _awb_console_complete(source):
    import codeop
    try:
        return codeop.compile_command(source, "<console>", "single") is not None
    except (SyntaxError, ValueError, OverflowError):
        return True
)PY";

} // namespace

PythonConsole::PythonConsole(Project *project, ScriptRecorder *recorder,
                             std::function<Item *()> currentItem, QWidget *parent)
    : QWidget(parent), m_project(project), m_recorder(recorder),
      m_currentItem(std::move(currentItem))
{
    setObjectName(QStringLiteral("pythonConsole"));
    m_output = new QPlainTextEdit;
    m_output->setObjectName(QStringLiteral("pythonOutput"));
    m_output->setReadOnly(true);
    m_output->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_output->setMaximumBlockCount(20000);
    m_input = new QLineEdit;
    m_input->setObjectName(QStringLiteral("pythonInput"));
    m_input->setFont(m_output->font());
    m_input->setPlaceholderText(tr("Python: project, item, awb (attractor_workbench) and np"));
    m_input->installEventFilter(this);
    m_prompt = new QLabel(QStringLiteral(">>>"));
    m_prompt->setFont(m_output->font());
    auto *row = new QHBoxLayout;
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(m_prompt);
    row->addWidget(m_input, 1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(m_output, 1);
    layout->addLayout(row);
    connect(m_input, &QLineEdit::returnPressed, this, [this] {
        const QString line = m_input->text();
        m_input->clear();
        enter(line);
    });
}

void PythonConsole::begin()
{
    // On the first show (not at the application's start, whose New and Open would otherwise
    // be the first things shown): the welcome, then the recording so far, then what follows.
    if (m_begun)
        return;
    m_begun = true;
    print(tr("# Python %1 console: `project` is the open document, `item` the current item, "
             "`awb` the attractor_workbench module (help(awb)). Edits are undoable; every edit "
             "made in the window is shown below as the line that makes it (Tools > Save "
             "Recording).")
              .arg(QStringLiteral(PY_VERSION)),
          QStringLiteral("#6a737d"), true);
    if (!m_recorder)
        return;
    auto started = [this](const QString &file) {
        print(file.isEmpty() ? tr("# The recording starts again, from a new project.")
                             : tr("# The recording starts again, from %1.").arg(file),
              QStringLiteral("#6a737d"), true);
    };
    started(m_recorder->baseFile());
    for (const QString &step : m_recorder->steps())
        onRecorded(step);
    connect(m_recorder, &ScriptRecorder::recorded, this, &PythonConsole::onRecorded);
    connect(m_recorder, &ScriptRecorder::lastReplaced, this, &PythonConsole::onLastReplaced);
    connect(m_recorder, &ScriptRecorder::restarted, this, started);
}

void PythonConsole::showEvent(QShowEvent *event)
{
    begin();
    QWidget::showEvent(event);
}

PythonConsole::~PythonConsole()
{
    if (m_python) {
        // The interpreter stays (it cannot restart safely); the document's objects go.
        m_python->globals.clear();
        m_python.reset();
    }
}

void PythonConsole::startInterpreter()
{
    if (m_python)
        return;
    if (!Py_IsInitialized())
        py::initialize_interpreter(false);
    m_python = std::make_unique<Interpreter>();
    py::module_ awbModule = py::module_::import("attractor_workbench");
    py::dict globals;
    globals["__builtins__"] = py::module_::import("builtins");
    globals["__name__"] = "__console__";
    globals["awb"] = awbModule;
    try {
        globals["np"] = py::module_::import("numpy");
    } catch (const py::error_already_set &) {
        PyErr_Clear();
    }
    m_python->project = python::borrowProject(m_project);
    globals["project"] = m_python->project;
    py::exec(runner, globals);
    m_python->globals = globals;
}

bool PythonConsole::enter(const QString &line)
{
    begin();
    if (!line.trimmed().isEmpty() && (m_history.isEmpty() || m_history.last() != line))
        m_history << line;
    m_historyPos = int(m_history.size());
    print((m_pending.isEmpty() ? QStringLiteral(">>> ") : QStringLiteral("... ")) + line,
          QStringLiteral("#1f4e9b"));
    m_pending << line;
    const QString source = m_pending.join('\n');
    try {
        startInterpreter();
        const bool complete =
            m_python->globals["_awb_console_complete"](source.toStdString()).cast<bool>();
        // A block ends with an empty line, as at Python's own prompt.
        const bool block = m_pending.size() > 1 || source.trimmed().endsWith(':');
        if (!complete || (block && !line.trimmed().isEmpty())) {
            m_prompt->setText(QStringLiteral("..."));
            return false;
        }
    } catch (const std::exception &e) {
        print(QString::fromUtf8(e.what()), QStringLiteral("#b31d28"));
        m_pending.clear();
        m_prompt->setText(QStringLiteral(">>>"));
        return true;
    }
    m_pending.clear();
    m_prompt->setText(QStringLiteral(">>>"));
    run(source);
    return true;
}

void PythonConsole::run(const QString &source)
{
    try {
        Item *current = m_currentItem ? m_currentItem() : nullptr;
        m_python->globals["item"] = python::itemObject(m_python->project, current);
        const py::object out =
            m_python->globals["_awb_console_run"](source.toStdString() + "\n", m_python->globals);
        if (!out.is_none()) {
            QString text = QString::fromStdString(out.cast<std::string>());
            if (text.endsWith('\n'))
                text.chop(1);
            if (!text.isEmpty())
                print(text, text.contains(QStringLiteral("Traceback")) || text.contains("Error:")
                                ? QStringLiteral("#b31d28")
                                : QStringLiteral("#24292e"));
        }
    } catch (const std::exception &e) {
        print(QString::fromUtf8(e.what()), QStringLiteral("#b31d28"));
    }
}

void PythonConsole::print(const QString &text, const QString &colour, bool italic)
{
    QTextCharFormat format;
    format.setForeground(QColor(colour));
    format.setFontItalic(italic);
    QTextCursor c(m_output->document());
    c.movePosition(QTextCursor::End);
    if (!m_output->document()->isEmpty())
        c.insertBlock();
    c.insertText(text, format);
    m_output->verticalScrollBar()->setValue(m_output->verticalScrollBar()->maximum());
    m_lastRecordedStart = -1;
}

void PythonConsole::onRecorded(const QString &lines)
{
    QTextCursor c(m_output->document());
    c.movePosition(QTextCursor::End);
    const bool empty = m_output->document()->isEmpty();
    print(lines, QStringLiteral("#22863a"));
    m_lastRecordedStart = empty ? 0 : c.position() + 1;
}

void PythonConsole::onLastReplaced(const QString &lines)
{
    if (m_lastRecordedStart < 0) {
        onRecorded(lines);
        return;
    }
    QTextCursor c(m_output->document());
    c.setPosition(m_lastRecordedStart);
    c.movePosition(QTextCursor::End, QTextCursor::KeepAnchor);
    QTextCharFormat format;
    format.setForeground(QColor(QStringLiteral("#22863a")));
    c.insertText(lines, format);
}

bool PythonConsole::runFile(const QString &fileName, QString *error)
{
    QFile file(fileName);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error)
            *error = tr("cannot read %1: %2").arg(fileName, file.errorString());
        return false;
    }
    const QByteArray source = file.readAll();
    begin();
    print(tr("# Running %1").arg(fileName), QStringLiteral("#6a737d"), true);
    try {
        startInterpreter();
        Item *current = m_currentItem ? m_currentItem() : nullptr;
        m_python->globals["item"] = python::itemObject(m_python->project, current);
        const py::object out = m_python->globals["_awb_console_exec"](
            py::bytes(source.constData(), size_t(source.size())).attr("decode")("utf-8"),
            fileName.toStdString(), m_python->globals);
        QString text = QString::fromStdString(out.cast<std::string>());
        if (text.endsWith('\n'))
            text.chop(1);
        if (!text.isEmpty())
            print(text, text.contains(QStringLiteral("Traceback")) ? QStringLiteral("#b31d28")
                                                                   : QStringLiteral("#24292e"));
    } catch (const std::exception &e) {
        print(QString::fromUtf8(e.what()), QStringLiteral("#b31d28"));
    }
    return true;
}

QString PythonConsole::transcript() const
{
    return m_output->toPlainText();
}

bool PythonConsole::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_input && event->type() == QEvent::KeyPress) {
        const auto *key = static_cast<QKeyEvent *>(event);
        if (key->key() == Qt::Key_Up || key->key() == Qt::Key_Down) {
            if (m_history.isEmpty())
                return true;
            m_historyPos += key->key() == Qt::Key_Up ? -1 : 1;
            m_historyPos = std::clamp(m_historyPos, 0, int(m_history.size()));
            m_input->setText(m_historyPos < m_history.size() ? m_history[m_historyPos]
                                                             : QString());
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace awb
