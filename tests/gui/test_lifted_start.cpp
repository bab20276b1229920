// The Properties dock edits a start set of the lifted space (000 Fig. 2: "a random homogeneous
// point in five dimensions"): choosing "Lifted points" lifts the control points' centroid,
// typed coordinates are checked against the lifted dimension, and each edit is one undo step.

#include "TestPaths.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Messages.h"
#include "gui/app/PropertiesDock.h"
#include "model/AttractorItem.h"
#include "model/Project.h"

#include <QComboBox>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"

using namespace awb;

class TestLiftedStart : public QObject {
    Q_OBJECT
private slots:
    void editLiftedStartPoints();

private:
    QTemporaryDir m_dir;
};

void TestLiftedStart::editLiftedStartPoints()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    const QString file = awb::test::sourceDir()
                         + "/examples/000-fig02-cubic-bspline-from-point.awb";
    QVERIFY(w.openFile(file));
    auto *item = qobject_cast<AttractorItem *>(
        w.project()->findItem("000 Fig. 2: cubic B-spline from a point"));
    QVERIFY(item);
    w.setCurrentItem(item);
    auto *kind = qobject_cast<QComboBox *>(w.propertiesWidget()->editor("start_set.kind"));
    auto *lifted = qobject_cast<QLineEdit *>(w.propertiesWidget()->editor("start_set.lifted"));
    QVERIFY(kind && lifted);
    QVERIFY(!lifted->isEnabled());
    const StartSetSpec original = item->startSet();
    const int steps = w.project()->undoStack()->index();

    // Lifted points: the centroid of the 5 control points, lifted (x, y and 2 more).
    kind->setCurrentIndex(int(StartSetSpec::Kind::Lifted));
    QCOMPARE(item->startSet().kind, StartSetSpec::Kind::Lifted);
    QCOMPARE(int(item->startSet().lifted.size()), 1);
    QCOMPARE(int(item->startSet().lifted.front().size()), 4);
    QCOMPARE(w.project()->undoStack()->index(), steps + 1);
    QVERIFY(lifted->isEnabled());
    QCOMPARE(lifted->text().split(',').size(), 4);

    // A point with the wrong number of coordinates is refused with the reason.
    lifted->setText("0.5, 0.5, 0.25");
    emit lifted->editingFinished();
    QCOMPARE(int(item->startSet().lifted.front().size()), 4);
    QVERIFY(!messages.errors.isEmpty());
    QVERIFY2(messages.errors.last().contains("has 4 coordinates"),
             qPrintable(messages.errors.last()));

    // Two good points: one undo step, the attractor still draws.
    lifted->setText("0.5, 0.5, 0.25, 0.25; 1, 2, -1, 3/8");
    emit lifted->editingFinished();
    QCOMPARE(int(item->startSet().lifted.size()), 2);
    QCOMPARE(item->startSet().lifted[1][3], 0.375);
    QCOMPARE(w.project()->undoStack()->index(), steps + 2);
    const auto d = item->derivedIfs();
    QVERIFY(d);
    QCOMPARE(int(item->coreStartSet(*d).vertices.cols()), 4);

    w.project()->undoStack()->undo();
    w.project()->undoStack()->undo();
    QCOMPARE(item->startSet(), original);
    QVERIFY(!lifted->isEnabled());
}

AWB_TEST_MAIN(TestLiftedStart)
#include "test_lifted_start.moc"
