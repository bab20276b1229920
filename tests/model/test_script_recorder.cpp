// The recording of edits as Python (model/ScriptRecorder, issue 33): each undo step of the
// project, whoever made it, becomes the attractor_workbench lines that make it; a drag is one
// step, a compound edit one `with project.edit(...)` block, undo and redo are recorded as
// such, and what no finer line says goes into one item.update({...}). (The replay of a
// recording through Python: gui/test_python_console.)
#include "TestPaths.h"
#include "TestMain.h"

#include "model/FractalItem.h"
#include "model/ItemRegistry.h"
#include "model/Project.h"
#include "model/ProjectIO.h"
#include "model/ScriptRecorder.h"
#include "model/SubdivisionCurveItem.h"

#include <QSignalSpy>
#include <QtTest>

using namespace awb;

class TestScriptRecorder : public QObject {
    Q_OBJECT
private slots:
    void init();
    void pointsAndParameters();
    void aDragIsOneStep();
    void undoRedoAndStructure();
    void compoundIsOneBlock();
    void otherFieldsGoIntoUpdate();
    void openingRestarts();
    void literals();

private:
    std::unique_ptr<Project> m_project;
    SubdivisionCurveItem *m_curve = nullptr;
};

void TestScriptRecorder::init()
{
    m_project = std::make_unique<Project>();
    QVERIFY(m_project->open(awb::test::sourceDir()
                            + QStringLiteral("/examples/000-fig05-four-point-from-segment.awb")));
    m_curve = qobject_cast<SubdivisionCurveItem *>(m_project->child(0));
    QVERIFY(m_curve);
}

void TestScriptRecorder::pointsAndParameters()
{
    ScriptRecorder r(m_project.get());
    QSignalSpy recorded(&r, &ScriptRecorder::recorded);
    const QString ref =
        QStringLiteral("project.item(\"000 Fig. 5: four-point scheme from a segment\")");
    QVERIFY(m_curve->moveControlPoint(3, Point{3.25, 0.5, 0}));
    QCOMPARE(r.steps(), QStringList{ref + ".control_points[3] = [3.25, 0.5]"});
    QCOMPARE(recorded.size(), 1);
    QVERIFY(m_curve->setParameter(QStringLiteral("scheme.omega"), 0.125));
    QCOMPARE(r.steps().last(), ref + ".parameters[\"scheme.omega\"] = 0.125");
    QVERIFY(m_curve->setParameter(QStringLiteral("scheme.omega"), 1.0));
    QCOMPARE(r.steps().last(), ref + ".parameters[\"scheme.omega\"] = 1.0");
    // A point inserted: the whole set, one line.
    QVERIFY(m_curve->insertControlPoint(1, Point{0.5, 1, 0}));
    QVERIFY2(r.steps().last().startsWith(ref + ".control_points = [[0, 0], [0.5, 1], [1, 2]"),
             qPrintable(r.steps().last()));
    QCOMPARE(r.steps().size(), 4);
}

void TestScriptRecorder::aDragIsOneStep()
{
    ScriptRecorder r(m_project.get());
    const int gesture = m_project->beginGesture();
    for (int k = 1; k <= 20; ++k)
        QVERIFY(m_curve->moveControlPoint(1, Point{1.0 + k / 10.0, 2.0, 0}, gesture));
    QVERIFY(r.steps().isEmpty());  // recorded when the drag ends
    m_project->endGesture(gesture);
    QCOMPARE(r.steps().size(), 1);
    QVERIFY2(r.steps()[0].endsWith(".control_points[1] = [3, 2]"), qPrintable(r.steps()[0]));
    QCOMPARE(m_project->undoStack()->count(), 1);
}

void TestScriptRecorder::undoRedoAndStructure()
{
    ScriptRecorder r(m_project.get());
    auto fractal = ItemRegistry::instance().create(QStringLiteral("fractal"));
    QVERIFY(fractal);
    Item *added = m_project->addItem(std::move(fractal));
    QVERIFY2(r.steps().last().startsWith(QStringLiteral("project.add({")),
             qPrintable(r.steps().last()));
    QVERIFY(r.steps().last().contains(QStringLiteral("\"type\": \"fractal\"")));
    QVERIFY(m_project->renameItem(added, QStringLiteral("K")));
    QCOMPARE(r.steps().last(), QStringLiteral("project.item(\"Fractal\").name = \"K\""));
    m_project->undoStack()->undo();
    m_project->undoStack()->undo();
    QCOMPARE(r.steps().mid(2), (QStringList{"project.undo()", "project.undo()"}));
    m_project->undoStack()->redo();
    QCOMPARE(r.steps().last(), QStringLiteral("project.redo()"));
    QVERIFY(m_project->removeItem(m_project->findItem(QStringLiteral("Fractal"))));
    QCOMPARE(r.steps().last(), QStringLiteral("project.remove(\"Fractal\")"));
    // A child moved to the top level.
    Item *plot = m_curve->child(0);
    QVERIFY(m_project->moveItem(plot, nullptr, 0));
    QCOMPARE(r.steps().last(),
             QStringLiteral("project.move(\"000 Fig. 5: spectra of A_i\", parent=None, index=0)"));
}

void TestScriptRecorder::compoundIsOneBlock()
{
    ScriptRecorder r(m_project.get());
    {
        CompoundEdit edit(m_project.get(), QStringLiteral("Two things"));
        QVERIFY(m_curve->moveControlPoint(0, Point{-1, 0, 0}));
        QVERIFY(m_curve->setParameter(QStringLiteral("scheme.omega"), 0.05));
    }
    QCOMPARE(r.steps().size(), 1);
    const QStringList lines = r.steps()[0].split('\n');
    QCOMPARE(lines.size(), 3);
    QCOMPARE(lines[0], QStringLiteral("with project.edit(\"Two things\"):"));
    QVERIFY(lines[1].startsWith(QStringLiteral("    project.item(")));
    QVERIFY(lines[1].endsWith(QStringLiteral(".parameters[\"scheme.omega\"] = 0.05")));
    QVERIFY(lines[2].endsWith(QStringLiteral(".control_points[0] = [-1, 0]")));
}

void TestScriptRecorder::otherFieldsGoIntoUpdate()
{
    ScriptRecorder r(m_project.get());
    // A declared scalar (the style's point size) is a parameter line; a structured value
    // (the palette) goes into update().
    StyleSpec style = m_curve->style();
    style.pointSize = 4;
    QVERIFY(m_curve->setStyle(style));
    QCOMPARE(r.steps().size(), 1);
    QVERIFY2(r.steps()[0].endsWith(QStringLiteral(".parameters[\"style.point_size\"] = 4.0")),
             qPrintable(r.steps()[0]));
    style.colors = {"#112233", "#445566"};
    QVERIFY(m_curve->setStyle(style));
    QCOMPARE(r.steps().size(), 2);
    QVERIFY2(r.steps()[1].contains(QStringLiteral(".update({\"style\": {")),
             qPrintable(r.steps()[1]));
    QVERIFY(r.steps()[1].contains(QStringLiteral("\"#445566\"")));
    // A step with no effect a file holds is not a line.
    QVERIFY(m_curve->setStyle(style) || true);
    QCOMPARE(r.steps().size(), 2);
}

void TestScriptRecorder::openingRestarts()
{
    ScriptRecorder r(m_project.get());
    QVERIFY(m_curve->moveControlPoint(3, Point{3.25, 0.5, 0}));
    QCOMPARE(r.steps().size(), 1);
    const QString file = awb::test::sourceDir()
                         + QStringLiteral("/examples/000-fig10-koch-with-control-points.awb");
    QVERIFY(m_project->open(file));
    QVERIFY(r.steps().isEmpty());
    QCOMPARE(r.baseFile(), file);
    const QString script = r.script();
    QVERIFY(script.contains(QStringLiteral("import attractor_workbench as awb")));
    QVERIFY(script.contains(
        QStringLiteral("project = awb.open(sys.argv[1] if len(sys.argv) > 1 else \"") + file
        + "\")"));
    QVERIFY(script.contains(QStringLiteral("    project.save(sys.argv[2])")));

    // An example opened as a copy (no file name; issue 47): the recording's default is the
    // example, also after Clear Recording; the next document forgets it.
    ProjectData data;
    QString error;
    QVERIFY2(ProjectIO::readFile(file, &data, &error), qPrintable(error));
    m_project->adopt(std::move(data), QString(), false);
    QCOMPARE(r.baseFile(), QString());
    r.setOrigin(file);
    QCOMPARE(r.baseFile(), file);
    QVERIFY(r.script().contains(QStringLiteral("else \"") + file + "\")"));
    QVERIFY(r.script().contains(QStringLiteral("the edits of \"") + file + "\""));
    r.restart();
    QCOMPARE(r.baseFile(), file);
    m_project->clear();
    QCOMPARE(r.baseFile(), QString());
    QVERIFY(r.script().contains(QStringLiteral("else awb.Project()")));
}

void TestScriptRecorder::literals()
{
    QCOMPARE(ScriptRecorder::pyString(QStringLiteral("a \"b\" \\ é\n")),
             QStringLiteral("\"a \\\"b\\\" \\\\ é\\n\""));
    QCOMPARE(ScriptRecorder::pyNumber(0.1), QStringLiteral("0.1"));
    QCOMPARE(ScriptRecorder::pyNumber(1.0 / 3.0), QStringLiteral("0.3333333333333333"));
    QCOMPARE(ScriptRecorder::pyNumber(-2.5e-300), QStringLiteral("-2.5e-300"));
    QCOMPARE(ScriptRecorder::pyValue(QJsonObject{{"a", QJsonArray{1, true, QJsonValue::Null}},
                                                 {"b", 100000.0}}),
             QStringLiteral("{\"a\": [1, True, None], \"b\": 100000}"));
}

AWB_TEST_MAIN(TestScriptRecorder)
#include "test_script_recorder.moc"
