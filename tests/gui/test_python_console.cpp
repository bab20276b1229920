// The Python console (issue 33): View > Python Console runs the attractor_workbench module on
// the open document (`project`, `item`), its edits are undoable like any other; every edit made
// in the window is recorded as the Python line that makes it, and Tools > Save Recording
// writes a script that replays the session on the original file to the same bytes as the
// window's save.
#include "TestPaths.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Messages.h"
#include "gui/app/PropertiesDock.h"
#include "gui/console/PythonConsole.h"
#include "gui/views/AttractorView.h"
#include "model/Project.h"
#include "model/ProjectTreeModel.h"
#include "model/ScriptRecorder.h"
#include "model/SubdivisionCurveItem.h"

#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QLineEdit>
#include <QProcess>
#include <QTreeView>
#include <QtTest>

#include "TestMain.h"

#include "WindowTestSupport.h"

using namespace awb;

class TestPythonConsole : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void consoleEditsTheOpenDocument();
    void literalsReadBackInPython();
    void recordedSessionReplaysToTheSameFile();

private:
    QTemporaryDir m_dir;
    QString m_recovery;
    QString m_example;
};

namespace {

QString python() { return qEnvironmentVariable("AWB_PYTHON", QStringLiteral("python3")); }

// Runs `args` with the standalone module on the path; its output, or "" after a failure that
// the test reports.
bool runPython(const QStringList &args, QString *output)
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("PYTHONPATH"),
               qEnvironmentVariable("AWB_BIN_DIR") + QStringLiteral("/../python"));
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    // The AddressSanitizer build's module needs the sanitizer's runtime, which Debian's Python
    // does not have: preloaded, without leak detection (tests/CMakeLists.txt).
    if (const QString preload = qEnvironmentVariable("AWB_PYTHON_PRELOAD"); !preload.isEmpty()) {
        env.insert(QStringLiteral("LD_PRELOAD"), preload);
        env.insert(QStringLiteral("ASAN_OPTIONS"),
                   env.value(QStringLiteral("ASAN_OPTIONS")) + QStringLiteral(":detect_leaks=0"));
    }
    p.setProcessEnvironment(env);
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(python(), args);
    if (!p.waitForFinished(120000))
        return false;
    *output = QString::fromUtf8(p.readAll());
    return p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
}

} // namespace

void TestPythonConsole::initTestCase()
{
    test::useTestSettings("test-python-console");
    m_recovery = m_dir.path() + QStringLiteral("/recovery");
    m_example = m_dir.path() + QStringLiteral("/four-point.awb");
    QVERIFY(QFile::copy(awb::test::sourceDir()
                            + QStringLiteral("/examples/000-fig05-four-point-from-segment.awb"),
                        m_example));
    QFile::setPermissions(m_example, QFile::ReadOwner | QFile::WriteOwner);
}

void TestPythonConsole::consoleEditsTheOpenDocument()
{
    test::ShownWindow shown(m_recovery, {1300, 850});
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    QVERIFY(w.openFile(m_example));
    auto *item = qobject_cast<SubdivisionCurveItem *>(w.project()->child(0));
    QVERIFY(item);
    w.setCurrentItem(item);
    QAction *show = w.action(QStringLiteral("actionPythonConsole"));
    QVERIFY(show);
    show->trigger();
    PythonConsole *console = w.pythonConsole();
    QVERIFY(console);
    QTRY_VERIFY(console->isVisible());

    // `item` is the current item, `project` the open document.
    QVERIFY(console->enter(QStringLiteral("item.name")));
    QVERIFY2(console->transcript().contains(QStringLiteral("'000 Fig. 5: four-point scheme")),
             qPrintable(console->transcript()));
    QVERIFY(console->enter(QStringLiteral("len(project.items)")));
    QVERIFY(console->transcript().endsWith(QStringLiteral("\n2")));

    // An edit from the console is one undo step of the document, and the views follow.
    QUndoStack *stack = w.project()->undoStack();
    const int steps = stack->count();
    const PointList before = item->controlPoints();
    QVERIFY(console->enter(QStringLiteral("item.control_points[1] = [1.0, 2.5]")));
    QCOMPARE(item->controlPoints()[1], (Point{1.0, 2.5, 0.0}));
    QCOMPARE(stack->count(), steps + 1);
    stack->undo();
    QCOMPARE(item->controlPoints(), before);

    // The spectrum as numpy: the eigenvalues of S_1 of the four-point scheme, 1 first.
    QVERIFY(console->enter(
        QStringLiteral("print(round(float(item.maps()[0]['eigenvalues'][1].real), 12))")));
    QVERIFY2(console->transcript().endsWith(QStringLiteral("\n0.5")),
             qPrintable(console->transcript().right(200)));

    // A refused edit shows the application's message, nothing changes.
    QVERIFY(console->enter(QStringLiteral("item.control_points[0] = [float('nan'), 0]")));
    QVERIFY2(console->transcript().contains(QStringLiteral("not a finite number")),
             qPrintable(console->transcript().right(400)));
    QCOMPARE(item->controlPoints(), before);
    QVERIFY(console->enter(QStringLiteral("item.parameters['scheme.nothing'] = 1")));
    QVERIFY(console->transcript().contains(QStringLiteral("KeyError")));

    // A block runs when an empty line ends it, as at Python's prompt.
    QVERIFY(!console->enter(QStringLiteral("for k in range(3):")));
    QVERIFY(!console->enter(QStringLiteral("    print('k =', k)")));
    QVERIFY(console->enter(QString()));
    QVERIFY2(console->transcript().endsWith(QStringLiteral("k = 0\nk = 1\nk = 2")),
             qPrintable(console->transcript().right(200)));

    // A syntax error is a message, not a crash; the console goes on.
    QVERIFY(console->enter(QStringLiteral("1 +* 2")));
    QVERIFY(console->transcript().contains(QStringLiteral("SyntaxError")));
    QVERIFY(console->enter(QStringLiteral("6 * 7")));
    QVERIFY(console->transcript().endsWith(QStringLiteral("\n42")));

    // Tools > Run Python Script: a file in the same namespace, one edit block, undoable.
    const QString script = m_dir.path() + QStringLiteral("/sweep.py");
    QFile f(script);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("import sys\n"
            "with project.edit('Sweep'):\n"
            "    for w in (0.05, 0.1):\n"
            "        item.parameters['scheme.omega'] = w\n"
            "print('swept', sys.argv[0].endswith('sweep.py'), item.parameters['scheme.omega'])\n");
    f.close();
    const int before2 = stack->index();
    QVERIFY(console->runFile(script));
    QVERIFY2(console->transcript().endsWith(QStringLiteral("swept True 0.1")),
             qPrintable(console->transcript().right(300)));
    QCOMPARE(stack->index(), before2 + 1);
    QCOMPARE(item->parameter(QStringLiteral("scheme.omega")).toDouble(), 0.1);
    stack->undo();
    QCOMPARE(item->parameter(QStringLiteral("scheme.omega")).toDouble(), 0.0625);
    QString error;
    QVERIFY(!console->runFile(m_dir.path() + QStringLiteral("/missing.py"), &error));
    QVERIFY(error.contains(QStringLiteral("missing.py")));
}

void TestPythonConsole::literalsReadBackInPython()
{
    // The recorder's literals are Python that reads back to the same values.
    const QJsonObject o{{"a", 0.1},       {"b", 1e-300},  {"c", -2.5e20}, {"d", QJsonValue::Null},
                        {"e", true},      {"f", "é \"q\" \\ \n"}, {"g", QJsonArray{1, 2.5, "x"}},
                        {"h", 1.0 / 3.0}};
    const QString literal = ScriptRecorder::pyValue(o);
    if (qEnvironmentVariableIsSet("AWB_PYTHON_UNUSABLE"))
        QSKIP(qPrintable(qEnvironmentVariable("AWB_PYTHON_UNUSABLE")
                         + QStringLiteral(": this build's module does not run in Python")));
    QString out;
    QVERIFY2(runPython({QStringLiteral("-c"),
                        QStringLiteral("import json; print(json.dumps(%1, sort_keys=True))")
                            .arg(literal)},
                       &out),
             qPrintable(out));
    const QJsonObject back = QJsonDocument::fromJson(out.toUtf8()).object();
    QCOMPARE(back, o);
    QCOMPARE(back.value("h").toDouble(), 1.0 / 3.0);
}

void TestPythonConsole::recordedSessionReplaysToTheSameFile()
{
    test::ShownWindow shown(m_recovery, {1300, 850});
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    QVERIFY(w.openFile(m_example));
    auto *item = qobject_cast<SubdivisionCurveItem *>(w.project()->child(0));
    QVERIFY(item);
    w.setCurrentItem(item);
    AttractorView *view = w.attractorView();
    QVERIFY(test::waitForFinalImage(view));
    ScriptRecorder *recorder = w.recorder();
    QVERIFY(recorder->steps().isEmpty());
    QCOMPARE(recorder->baseFile(), m_example);

    // 1. A drag of control point 2 with the mouse: one step, recorded when it ends.
    const QPoint grab = view->worldToScreen(view->controlPointPosition(2)).toPoint();
    QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, grab);
    for (int k = 1; k <= 6; ++k)
        QTest::mouseMove(view, grab + QPoint(6 * k, -4 * k));
    QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, grab + QPoint(36, -24));
    QTRY_COMPARE(recorder->steps().size(), 1);
    QVERIFY2(recorder->steps()[0].startsWith(QStringLiteral(
                 "project.item(\"000 Fig. 5: four-point scheme from a segment\")"
                 ".control_points[2] = [")),
             qPrintable(recorder->steps()[0]));

    // 2. The tension in the Properties dock.
    w.controller();
    auto *omega = w.propertiesWidget()->editor("scheme.omega");
    QVERIFY(omega);
    QVERIFY(item->setParameter(QStringLiteral("scheme.omega"), 0.1));
    QTRY_COMPARE(recorder->steps().size(), 2);
    QVERIFY2(recorder->steps()[1].endsWith(QStringLiteral(".parameters[\"scheme.omega\"] = 0.1")),
             qPrintable(recorder->steps()[1]));

    // 3. The scheme switched to its mask in the dock, then a mask typed.
    auto *kind = qobject_cast<QComboBox *>(w.propertiesWidget()->editor("scheme.kind"));
    QVERIFY(kind);
    kind->setCurrentIndex(int(SchemeSpec::Kind::Mask));
    QCOMPARE(item->scheme().kind, SchemeSpec::Kind::Mask);
    auto *mask = qobject_cast<QLineEdit *>(w.propertiesWidget()->editor("scheme.mask"));
    QVERIFY(mask);
    mask->setText(QStringLiteral("-1/32, 0, 17/32, 1, 17/32, 0, -1/32"));
    emit mask->editingFinished();
    QVERIFY2(shown.messages.errors.isEmpty(), qPrintable(shown.messages.errors.join('\n')));

    // 4. A rename in the project tree, an item added from the Item menu, undo, redo.
    QTreeView *tree = w.projectTree();
    const QModelIndex first = tree->model()->index(0, 0);
    QVERIFY(tree->model()->setData(first, QStringLiteral("Four-point, recorded")));
    QCOMPARE(item->name(), QStringLiteral("Four-point, recorded"));
    QAction *addFractal = w.action(QStringLiteral("actionAdd_fractal"));
    QVERIFY(addFractal);
    addFractal->trigger();
    QCOMPARE(w.project()->childCount(), 2);
    w.action(QStringLiteral("actionUndo"))->trigger();
    QCOMPARE(w.project()->childCount(), 1);
    w.action(QStringLiteral("actionRedo"))->trigger();
    QCOMPARE(w.project()->childCount(), 2);
    // 5. A drag of point 0, then the eigenvalue plot deleted.
    w.setCurrentItem(item);
    QVERIFY(test::waitForFinalImage(view));
    const QPoint grab0 = view->worldToScreen(view->controlPointPosition(0)).toPoint();
    QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, grab0);
    QTest::mouseMove(view, grab0 + QPoint(10, 10));
    QTest::mouseMove(view, grab0 + QPoint(20, 5));
    QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, grab0 + QPoint(20, 5));
    Item *plot = item->child(0);
    QVERIFY(plot);
    w.setCurrentItem(plot);
    w.action(QStringLiteral("actionDelete"))->trigger();
    QCOMPARE(item->childCount(), 0);

    // Every edit is in the console, as the recorder wrote it, when it is first opened.
    w.action(QStringLiteral("actionPythonConsole"))->trigger();
    QTRY_VERIFY(w.pythonConsole()->isVisible());
    const QString transcript = w.pythonConsole()->transcript();
    QVERIFY(transcript.contains(QStringLiteral("# The recording starts again, from ") + m_example));
    for (const QString &step : recorder->steps())
        QVERIFY2(transcript.contains(step), qPrintable(step));
    QVERIFY(recorder->steps().contains(QStringLiteral("project.undo()")));
    QVERIFY(recorder->steps().contains(QStringLiteral("project.redo()")));

    // Saved by the window, and replayed by the saved recording on the original file.
    const QString windowSave = m_dir.path() + QStringLiteral("/window.awb");
    const QString replayed = m_dir.path() + QStringLiteral("/replayed.awb");
    const QString script = m_dir.path() + QStringLiteral("/session.py");
    QString error;
    QVERIFY2(w.project()->saveAs(windowSave, &error), qPrintable(error));
    QVERIFY2(w.saveRecording(script, &error), qPrintable(error));
    if (qEnvironmentVariableIsSet("AWB_PYTHON_UNUSABLE"))
        QSKIP(qPrintable(qEnvironmentVariable("AWB_PYTHON_UNUSABLE")
                         + QStringLiteral(": the replay needs the module in Python; the "
                                          "recording itself was checked")));
    QString out;
    const bool ran = runPython({script, m_example, replayed}, &out);
    QFile s(script);
    QVERIFY(s.open(QIODevice::ReadOnly));
    QVERIFY2(ran, qPrintable(out + "\n" + QString::fromUtf8(s.readAll())));
    QFile a(windowSave), b(replayed);
    QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
    const QByteArray bytesA = a.readAll(), bytesB = b.readAll();
    QVERIFY2(bytesA == bytesB, qPrintable(QString::fromUtf8(s.readAll())));
}

AWB_TEST_MAIN(TestPythonConsole)
#include "test_python_console.moc"
