// The Automaton dock (issue 46): the fern of gaskets (003 Fig. 5) opened from its example shows
// its graph; a user adds a state and an arc into it, gives the arc a plane affine map, points
// the arc elsewhere, removes the state -- each one undo step -- and the window draws the union
// of the states; the Analysis dock's Automaton tab gives the constrained JSR.
#include "TestPaths.h"
#include "gui/app/AutomatonPanel.h"
#include "gui/app/FigureSheet.h"
#include "gui/app/MainWindow.h"
#include "gui/views/AttractorView.h"
#include "gui/views/AutomatonGraph.h"
#include "model/CifsItem.h"
#include "model/Project.h"

#include <QComboBox>
#include <QDockWidget>
#include <QFileInfo>
#include <QPushButton>
#include <QTemporaryDir>
#include <QSignalSpy>
#include <QTextBrowser>
#include <QUndoStack>
#include <QtTest>

#include "TestMain.h"

#include "WindowTestSupport.h"

using namespace awb;

namespace {

QString examplePath()
{
    return test::sourceDir() + QStringLiteral("/examples/003-fig05-fern-of-sierpinski-gaskets.awb");
}

} // namespace

class TestAutomatonPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::useTestSettings("test_automaton_panel"); }

    void aUserBuildsOnTheFern()
    {
        QTemporaryDir recovery;
        test::ShownWindow shown(recovery.path(), QSize(1400, 950));
        MainWindow &w = shown.window;
        QVERIFY(w.openFile(examplePath()));
        auto *item = qobject_cast<CifsItem *>(w.project()->child(0));
        QVERIFY(item);
        w.setCurrentItem(item);
        AutomatonPanel *panel = w.automatonPanel();
        QCOMPARE(panel->item(), item);
        auto *dock = w.findChild<QDockWidget *>(QStringLiteral("dockAutomaton"));
        QVERIFY(dock);
        dock->show();
        dock->raise();
        QCoreApplication::processEvents();
        AutomatonGraph *graph = panel->graph();
        // A click on a state's disc selects it; on an arc's label, the arc.
        QTest::mouseClick(graph, Qt::LeftButton, {}, graph->stateCentre(1).toPoint());
        QCOMPARE(graph->selectedState(), 1);
        QCOMPARE(graph->arcAt(graph->stateCentre(1)), -1);
        const int steps = w.project()->undoStack()->index();

        // Add a segment state (2 points), then an arc from it into itself: still drawn.
        QVERIFY(panel->addState(2));
        QCOMPARE(item->spec().states.size(), size_t(3));
        QCOMPARE(item->controlPointSetCount(), 3);
        QVERIFY2(item->derivedIfs(), qPrintable(item->derivedError()));
        QVERIFY(panel->addArc(2, 2));
        QCOMPARE(graph->selectedArc(), 7);
        QCOMPARE(item->spec().arcs[7].S.rows(), 2);
        QVERIFY(panel->addArc(2, 2));
        // The fern's main frond now leads into the segment: a 2 x 3 arc, the matrix replaced.
        QVERIFY(panel->setArcStates(1, 0, 2));
        QCOMPARE(item->spec().arcs[1].S.rows(), 2);
        QCOMPARE(item->spec().arcs[1].S.cols(), 3);
        // An affine map between two frame triangles is kept as its matrix.
        QString error;
        QVERIFY(!panel->setArcMap(1, QJsonObject{{"affine",
                                                  QJsonObject{{"A", QJsonArray{QJsonArray{0.5, 0},
                                                                               QJsonArray{0, 0.5}}},
                                                              {"b", QJsonArray{0, 0}}}}},
                                  &error));
        QVERIFY2(error.contains("3 control points"), qPrintable(error));
        QVERIFY(panel->setArcMap(0, QJsonObject{{"affine",
                                                 QJsonObject{{"A", QJsonArray{QJsonArray{0.5, 0},
                                                                              QJsonArray{0, 0.5}}},
                                                             {"b", QJsonArray{0, 1}}}}}));
        // Draw all states: the union.
        QSignalSpy analysed(panel, &AutomatonPanel::analysed);
        QVERIFY(panel->setDrawn(CifsSpec::allStates));
        QVERIFY2(item->derivedIfs(), qPrintable(item->derivedError()));
        // One step per edit: add state, 2 arcs, ends, map, drawn; undone and redone whole.
        QCOMPARE(w.project()->undoStack()->index(), steps + 6);
        const CifsSpec built = item->spec();
        while (w.project()->undoStack()->index() > steps)
            w.project()->undoStack()->undo();
        QVERIFY(item->spec() == CifsSpec::fernOfGaskets(2));
        while (w.project()->undoStack()->canRedo())
            w.project()->undoStack()->redo();
        QVERIFY(item->spec() == built);
        QVERIFY(test::waitForFinalImage(w.attractorView()));
        auto *drawn = panel->findChild<QComboBox *>(QStringLiteral("automatonDrawn"));
        QCOMPARE(drawn->currentText(), QString("All states"));
        // The Automaton tab of the Analysis dock, computed off the GUI thread.
        QVERIFY(analysed.count() > 0 || analysed.wait(20000));
        auto *analysis = w.findChild<QTextBrowser *>(QStringLiteral("automatonAnalysis"));
        QVERIFY(analysis);
        QVERIFY2(analysis->toPlainText().contains("constrained JSR"),
                 qPrintable(analysis->toPlainText()));
        QVERIFY(analysis->toPlainText().contains("cycle Fern -T0-> Fern"));
        // The printed sheet says it too.
        const FigureSheet sheet(item, w.attractorView(), nullptr, nullptr);
        QVERIFY2(sheet.caption().join('\n').contains("constrained JSR"),
                 qPrintable(sheet.caption().join('\n')));
        // Saved, reopened and printed as the user left it.
        QTemporaryDir dir;
        const QString file = dir.filePath("own-automaton.awb");
        QVERIFY(w.saveFile(file));
        const CifsSpec saved = item->spec();
        QVERIFY(w.openFile(file));
        auto *reopened = qobject_cast<CifsItem *>(w.project()->child(0));
        QVERIFY(reopened);
        QVERIFY(reopened->spec() == saved);
        QString printError;
        QVERIFY2(w.printToPdf(dir.filePath("own-automaton.pdf"), &printError),
                 qPrintable(printError));
        QVERIFY(QFileInfo(dir.filePath("own-automaton.pdf")).size() > 1000);
        QVERIFY(w.openFile(file)); // the edits below go on in this window's project
        item = qobject_cast<CifsItem *>(w.project()->child(0));
        w.setCurrentItem(item);
        QCOMPARE(panel->item(), item);
        // A wrong edit is refused with its reason and leaves no step.
        const int before = w.project()->undoStack()->count();
        QVERIFY(!panel->renameState(0, QStringLiteral("Sierpinski"), &error));
        QVERIFY2(error.contains("two states"), qPrintable(error));
        QCOMPARE(w.project()->undoStack()->count(), before);
        // Removing the segment state removes its arcs: one step, undone.
        QVERIFY(panel->removeState(2));
        QCOMPARE(item->spec().states.size(), size_t(2));
        QCOMPARE(item->spec().arcs.size(), size_t(6));
        w.project()->undoStack()->undo();
        QVERIFY(item->spec() == saved);
    }

    void otherItemsExplainThePanel()
    {
        AutomatonPanel panel;
        panel.setItem(nullptr);
        QVERIFY(!panel.item());
        QVERIFY(!panel.addState(3));
    }
};

AWB_TEST_MAIN(TestAutomatonPanel)
#include "test_automaton_panel.moc"
