// The main window's Python: the console dock (gui/console/PythonConsole) and the recording of
// the document's edits as Python (model/ScriptRecorder), saved by Tools > Save Recording.

#include "gui/app/MainWindow.h"

#include "gui/app/Messages.h"
#include "gui/console/PythonConsole.h"
#include "model/FileWriting.h"
#include "model/Project.h"
#include "model/ScriptRecorder.h"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLineEdit>
#include <QStatusBar>

namespace awb {

void MainWindow::createPythonConsole()
{
    m_recorder = new ScriptRecorder(m_project.get(), this);
    m_console = new PythonConsole(m_project.get(), m_recorder, [this] { return currentItem(); });
    auto *dock = new QDockWidget(tr("Python Console"), this);
    dock->setObjectName(QStringLiteral("dockPython"));
    dock->setWidget(m_console);
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    m_docks.append(dock);
    dock->hide();
    QAction *show = dock->toggleViewAction();
    show->setObjectName(QStringLiteral("actionPythonConsole"));
    show->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    connect(dock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible)
            m_console->input()->setFocus();
    });

    auto *save = new QAction(QIcon::fromTheme(QStringLiteral("document-save-as")),
                             tr("Save &Recording…"), this);
    save->setObjectName(QStringLiteral("actionSaveRecording"));
    save->setStatusTip(tr("Save the edits since the project was opened as a Python script "
                          "that replays them on the file"));
    connect(save, &QAction::triggered, this, &MainWindow::saveRecordingDialog);
    auto *run = new QAction(QIcon::fromTheme(QStringLiteral("system-run")),
                            tr("Run Python &Script…"), this);
    run->setObjectName(QStringLiteral("actionRunScript"));
    run->setStatusTip(tr("Run a Python script on the open document, in the Python console"));
    connect(run, &QAction::triggered, this, [this, dock] {
        const QString file = QFileDialog::getOpenFileName(this, tr("Run Python Script"), {},
                                                          tr("Python scripts (*.py)"));
        if (file.isEmpty())
            return;
        dock->show();
        QString error;
        if (!m_console->runFile(file, &error))
            m_messages->error(this, tr("Run Python Script"), error);
    });
    auto *clear = new QAction(tr("&Clear Recording"), this);
    clear->setObjectName(QStringLiteral("actionClearRecording"));
    clear->setStatusTip(tr("Start the recording again from the document as it is now"));
    connect(clear, &QAction::triggered, m_recorder, &ScriptRecorder::restart);
}

bool MainWindow::saveRecording(const QString &fileName, QString *error)
{
    return writeWholeFile(fileName, m_recorder->script().toUtf8(), error);
}

void MainWindow::saveRecordingDialog()
{
    const QString base = m_project->fileName().isEmpty()
                             ? QStringLiteral("recording.py")
                             : QFileInfo(m_project->fileName()).completeBaseName()
                                   + QStringLiteral("-recording.py");
    const QString file = QFileDialog::getSaveFileName(this, tr("Save Recording"), base,
                                                      tr("Python scripts (*.py)"));
    if (file.isEmpty())
        return;
    QString error;
    if (!saveRecording(file, &error))
        m_messages->error(this, tr("Save Recording"), error);
    else
        statusBar()->showMessage(tr("Saved %n recorded edit(s) to %1", nullptr,
                                    int(m_recorder->steps().size()))
                                     .arg(file),
                                 5000);
}

} // namespace awb
