// FrameBudget (issue 28): during a gesture the docks are updated at most every interval and
// only while visible, at once when it ends; at rest once per turn of the event loop. And in the
// window: a drag of a control point leaves the Matrices dock alone until the pause or the
// release, then brings it up to date.

#include "TestPaths.h"
#include "gui/app/FrameBudget.h"
#include "gui/app/ItemController.h"
#include "gui/app/MainWindow.h"
#include "gui/views/AttractorView.h"
#include "gui/views/MatrixView.h"
#include "model/AttractorItem.h"
#include "model/Project.h"

#include "WindowTestSupport.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"

using namespace awb;

class TestFrameBudget : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::useTestSettings("test-frame-budget"); }

    void atRestOncePerTurn()
    {
        FrameBudget budget;
        int runs = 0;
        const int id = budget.addPanel(nullptr, [&] { ++runs; });
        budget.markDirty(id);
        budget.markDirty(id);
        budget.markDirty(id);
        QCOMPARE(runs, 0); // not within the edit
        QTRY_COMPARE(runs, 1);
        QTest::qWait(20);
        QCOMPARE(runs, 1);
        QVERIFY(!budget.isDirty(id));
    }

    void gestureThrottlesAndFlushes()
    {
        FrameBudget budget;
        budget.setPanelInterval(200);
        int runs = 0;
        const int id = budget.addPanel(nullptr, [&] { ++runs; });
        QSignalSpy gesture(&budget, &FrameBudget::gestureChanged);
        budget.beginGesture();
        budget.beginGesture(); // counted
        QCOMPARE(gesture.size(), 1);
        // Changes every 10 ms for 600 ms: an update per 200 ms at most (the first at once).
        QElapsedTimer t;
        t.start();
        int changes = 0;
        while (t.elapsed() < 600) {
            budget.markDirty(id);
            ++changes;
            QTest::qWait(10);
        }
        const int most = 1 + int(t.elapsed() / 200);
        QVERIFY2(runs >= 1 && runs <= most && runs < changes,
                 qPrintable(QStringLiteral("%1 updates for %2 changes").arg(runs).arg(changes)));
        budget.markDirty(id);
        const int before = runs;
        budget.endGesture();
        QCOMPARE(runs, before); // one gesture still open
        budget.endGesture();
        QCOMPARE(runs, before + 1); // brought up to date at once
        QCOMPARE(gesture.size(), 2);
        budget.endGesture(); // unbalanced: nothing
        QCOMPARE(gesture.size(), 2);
    }

    void hiddenPanelsWaitDuringGestures()
    {
        FrameBudget budget;
        budget.setPanelInterval(0);
        QWidget shown, hidden;
        shown.show();
        int shownRuns = 0, hiddenRuns = 0;
        const int a = budget.addPanel(&shown, [&] { ++shownRuns; });
        const int b = budget.addPanel(&hidden, [&] { ++hiddenRuns; });
        budget.beginGesture();
        budget.markDirty(a);
        budget.markDirty(b);
        QTRY_COMPARE(shownRuns, 1);
        QTest::qWait(20);
        QCOMPARE(hiddenRuns, 0);
        QVERIFY(budget.isDirty(b));
        // Shown during the gesture: it catches up.
        hidden.show();
        QTRY_COMPARE(hiddenRuns, 1);
        hidden.hide();
        budget.markDirty(b);
        QTest::qWait(20);
        QCOMPARE(hiddenRuns, 1);
        // The end of the gesture updates everything, hidden or not (exports read them).
        budget.endGesture();
        QCOMPARE(hiddenRuns, 2);
        // At rest a hidden panel follows too.
        budget.markDirty(b);
        QTRY_COMPARE(hiddenRuns, 3);
    }

    // The window: while a control point is dragged the matrices of the lifted maps M_i are
    // not reformatted on every move; on release they show the final position.
    void dragDefersTheMatricesDock()
    {
        QTemporaryDir recovery;
        test::ShownWindow shown(recovery.path(), QSize(1400, 900));
        MainWindow &w = shown.window;
        QVERIFY(w.openFile(awb::test::sourceDir()
                           + QStringLiteral("/examples/000-fig11-sierpinski-with-control-points.awb")));
        auto *item = qobject_cast<AttractorItem *>(w.currentItem());
        QVERIFY(item);
        QTRY_VERIFY(!w.controller()->frameBudget()->inGesture());
        AttractorView *view = w.attractorView();
        QVERIFY(test::waitForFinalImage(view));
        const QList<NamedMatrix> before = w.matrixView()->matrices();
        QVERIFY(!before.isEmpty());
        w.controller()->frameBudget()->setPanelInterval(100000); // no update mid-drag
        const QPoint grab = view->worldToScreen(view->controlPointPosition(4)).toPoint();
        QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, grab);
        QVERIFY(w.controller()->frameBudget()->inGesture());
        for (int k = 1; k <= 10; ++k) {
            QTest::mouseMove(view, grab + QPoint(-4 * k, 2 * k));
            QCoreApplication::processEvents();
        }
        // The document moved, the view follows; the dock waits.
        QVERIFY(item->controlPoints()[4].x < 0.5 - 1e-3);
        const QList<NamedMatrix> during = w.matrixView()->matrices();
        QCOMPARE(during.size(), before.size());
        for (int i = 0; i < during.size(); ++i)
            QVERIFY(during[i].values == before[i].values);
        QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, grab + QPoint(-40, 20));
        QVERIFY(!w.controller()->frameBudget()->inGesture());
        // Released: up to date with the document at once.
        const auto d = item->derivedIfs();
        const QList<NamedMatrix> after = w.matrixView()->matrices();
        const QList<NamedMatrix> expected = namedMatrices(*d);
        QCOMPARE(after.size(), expected.size());
        bool changed = false;
        for (int i = 0; i < after.size(); ++i) {
            QVERIFY(after[i].values.isApprox(expected[i].values));
            changed = changed || !(after[i].values == before[i].values);
        }
        QVERIFY(changed); // the M_i moved with the point
        QCOMPARE(w.project()->undoStack()->count(), 1);
    }
};

AWB_TEST_MAIN(TestFrameBudget)
#include "test_frame_budget.moc"
