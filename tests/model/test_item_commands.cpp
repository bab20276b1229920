// The structural undo commands (items: add, remove, rename, move; control points: move, insert,
// remove): apply, assert, undo, assert the original state exactly, redo, assert again
// (STYLE.md §11). A drag is one undo step, a multi-point edit one compound step, and refused
// edits change nothing.

#include "TestProjects.h"

#include "model/Commands.h"

#include <QSignalSpy>
#include <QtTest>

#include "TestMain.h"

using namespace awb;
using awb::test::curve;
using awb::test::curveNamed;
using awb::test::roundTrip;
using awb::test::scheme;

class TestItemCommands : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        m_project = std::make_unique<Project>();
        test::fillSampleProject(*m_project);
        m_project->undoStack()->clear();
        m_c = curveNamed(*m_project, "B-spline");
        QVERIFY(m_c);
    }

    // ---- structural commands on items -------------------------------------------------------

    void addItem()
    {
        Item *added = nullptr;
        const int count = m_project->childCount();
        roundTrip(
            *m_project,
            [&] { added = m_project->addItem(curve("New", scheme(SchemeSpec::Kind::Chaikin),
                                                   test::fivePoints()), nullptr, 1); },
            [&] {
                QCOMPARE(m_project->childCount(), count + 1);
                QCOMPARE(m_project->child(1), added);
                QCOMPARE(added->project(), m_project.get());
            },
            [&] {
                QCOMPARE(m_project->childCount(), count);
                QVERIFY(!m_project->findItem("New"));
                if (added) // detached, owned by the command, and the very same object
                    QCOMPARE(added->project(), nullptr);
            });
    }

    void addChildItemAndUniqueNames()
    {
        Item *parent = m_project->findItem("Chaikin");
        Item *added = nullptr;
        roundTrip(
            *m_project,
            [&] { added = m_project->addItem(curve("B-spline", scheme(SchemeSpec::Kind::BSpline),
                                                   test::fivePoints()), parent); },
            [&] {
                QCOMPARE(parent->childCount(), 1);
                QCOMPARE(parent->child(0), added);
                QCOMPARE(added->name(), QString("B-spline 2")); // names stay unique
            },
            [&] { QCOMPARE(parent->childCount(), 0); });
    }

    void removeItemWithChildren()
    {
        Item *item = m_project->findItem("End-interpolating");
        Item *child = item->child(0);
        const int row = m_project->rowOf(item);
        roundTrip(
            *m_project, [&] { QVERIFY(m_project->removeItem(item)); },
            [&] {
                QVERIFY(!m_project->findItem("End-interpolating"));
                QVERIFY(!m_project->findItem("Chaikin"));
                QCOMPARE(item->project(), nullptr);
                QCOMPARE(child->parentItem(), item); // the subtree travels whole
            },
            [&] {
                QCOMPARE(m_project->child(row), item); // the same object, at the same row
                QCOMPARE(item->child(0), child);
                QCOMPARE(child->project(), m_project.get());
            });
    }

    void removeSeveralItemsIsOneStep()
    {
        const QList<Item *> items{m_project->findItem("Four-point"),
                                  m_project->findItem("Matrices"),
                                  m_project->findItem("End-interpolating"),
                                  m_project->findItem("Chaikin")}; // inside the one before
        const int count = m_project->items().size();
        roundTrip(
            *m_project, [&] { QVERIFY(m_project->removeItems(items)); },
            [&] { QCOMPARE(m_project->items().size(), count - 4); },
            [&] { QCOMPARE(m_project->items().size(), count); });
    }

    void renameItem()
    {
        roundTrip(
            *m_project, [&] { QVERIFY(m_c->setName("Cubic")); },
            [&] {
                QCOMPARE(m_c->name(), QString("Cubic"));
                QCOMPARE(m_project->findItem("Cubic"), m_c);
            },
            [&] { QCOMPARE(m_c->name(), QString("B-spline")); });
    }

    void renameUpdatesReferencesInTheSameStep()
    {
        auto *plot = dynamic_cast<EigenvaluePlotItem *>(m_project->findItem("Spectrum"));
        QSignalSpy sourceSpy(plot, &EigenvaluePlotItem::sourceChanged);
        roundTrip(
            *m_project, [&] { QVERIFY(m_project->renameItem(m_c, "Cubic")); },
            [&] { QCOMPARE(plot->source(), QString("Cubic")); },
            [&] { QCOMPARE(plot->source(), QString("B-spline")); });
        QVERIFY(sourceSpy.count() >= 3);
        QVERIFY(plot->eigenvalues());
    }

    void renameRefusals()
    {
        const int index = m_project->undoStack()->index();
        QVERIFY(!m_c->setName("Chaikin"));   // taken (by an item deeper in the tree)
        QVERIFY(!m_c->setName("  "));        // empty
        QVERIFY(m_c->setName("B-spline"));   // unchanged: accepted, no step
        QCOMPARE(m_project->undoStack()->index(), index);
        QCOMPARE(m_c->name(), QString("B-spline"));
    }

    void moveItemWithinParent()
    {
        const QList<Item *> order = topLevel();
        roundTrip(
            *m_project, [&] { QVERIFY(m_project->moveItem(order[0], nullptr, 3)); },
            [&] {
                QCOMPARE(m_project->rowOf(order[0]), 3);
                QCOMPARE(m_project->child(0), order[1]);
            },
            [&] { QCOMPARE(topLevel(), order); });
    }

    void moveItemToAnotherParent()
    {
        Item *target = m_project->findItem("Matrices");
        Item *item = m_project->findItem("Chaikin");
        Item *oldParent = item->parentItem();
        roundTrip(
            *m_project, [&] { QVERIFY(m_project->moveItem(item, target, 0)); },
            [&] {
                QCOMPARE(item->parentItem(), target);
                QCOMPARE(oldParent->childCount(), 0);
            },
            [&] {
                QCOMPARE(item->parentItem(), oldParent);
                QCOMPARE(target->childCount(), 0);
            });
    }

    void moveItemRefusals()
    {
        Item *parent = m_project->findItem("End-interpolating");
        Item *child = parent->child(0);
        const int index = m_project->undoStack()->index();
        QVERIFY(!m_project->moveItem(parent, child, 0));   // into its own descendant
        QVERIFY(!m_project->moveItem(parent, parent, 0));  // into itself
        QVERIFY(!m_project->moveItem(parent, nullptr, m_project->rowOf(parent))); // no-op
        QVERIFY(!m_project->moveItem(parent, nullptr, 99));
        QCOMPARE(m_project->undoStack()->index(), index);
    }

    // ---- control points ---------------------------------------------------------------------

    void moveControlPoint()
    {
        const PointList original = m_c->controlPoints();
        QSignalSpy moved(m_c, &AttractorItem::controlPointMoved);
        roundTrip(
            *m_project, [&] { QVERIFY(m_c->moveControlPoint(1, {1.5, -2.25})); },
            [&] { QCOMPARE(m_c->controlPoints()[1], (Point{1.5, -2.25})); },
            [&] { QVERIFY(m_c->controlPoints() == original); });
        QCOMPARE(moved.count(), 5);
        QCOMPARE(moved.first().at(1).toInt(), 1);
    }

    void dragIsOneUndoStep()
    {
        const PointList original = m_c->controlPoints();
        const int index = m_project->undoStack()->index();
        const int drag = m_project->beginGesture();
        for (int k = 1; k <= 50; ++k)
            QVERIFY(m_c->moveControlPoint(3, {4.0 + k * 0.1, 1.0 - k * 0.05}, drag));
        QCOMPARE(m_project->undoStack()->index(), index + 1);
        QCOMPARE(m_c->controlPoints()[3], (Point{4.0 + 50 * 0.1, 1.0 - 50 * 0.05}));
        m_project->undoStack()->undo();
        QVERIFY(m_c->controlPoints() == original);
        m_project->undoStack()->redo();
        QCOMPARE(m_c->controlPoints()[3], (Point{4.0 + 50 * 0.1, 1.0 - 50 * 0.05}));

        // A second drag of the same point is a second step; a drag of another point too.
        const int second = m_project->beginGesture();
        m_c->moveControlPoint(3, {0, 0}, second);
        m_c->moveControlPoint(3, {1, 1}, second);
        m_c->moveControlPoint(0, {7, 7}, second);
        QCOMPARE(m_project->undoStack()->index(), index + 3);
        m_project->undoStack()->undo();
        m_project->undoStack()->undo();
        QCOMPARE(m_c->controlPoints()[3], (Point{4.0 + 50 * 0.1, 1.0 - 50 * 0.05}));
    }

    void gesturesOpenUntilEnded()
    {
        QSignalSpy active(m_project.get(), &Project::gestureActiveChanged);
        QVERIFY(!m_project->gestureActive());
        const int drag = m_project->beginGesture();
        QVERIFY(m_project->gestureActive());
        const int slider = m_project->beginGesture(); // a second one meanwhile
        QVERIFY(drag != slider);
        QCOMPARE(active.size(), 1);
        m_project->endGesture(drag);
        QVERIFY(m_project->gestureActive()); // the slider is still held
        m_project->endGesture(drag);         // twice: nothing
        m_project->endGesture(12345);        // unknown: nothing
        m_project->endGesture(slider);
        QVERIFY(!m_project->gestureActive());
        QCOMPARE(active.size(), 2);
        QCOMPARE(active.at(0).at(0).toBool(), true);
        QCOMPARE(active.at(1).at(0).toBool(), false);
        // A gesture open when the content is replaced ends with it.
        m_project->beginGesture();
        m_project->clear();
        QVERIFY(!m_project->gestureActive());
        QCOMPARE(active.size(), 4);
    }

    void dragBackToTheStartLeavesNoStep()
    {
        const PointList original = m_c->controlPoints();
        const int index = m_project->undoStack()->index();
        const int drag = m_project->beginGesture();
        m_c->moveControlPoint(2, {9, 9}, drag);
        m_c->moveControlPoint(2, {8, 8}, drag);
        m_c->moveControlPoint(2, original[2], drag);
        QCOMPARE(m_project->undoStack()->index(), index);
        QVERIFY(m_c->controlPoints() == original);
        QVERIFY(!m_project->isModified());
    }

    void multiPointMoveIsOneStepAndDragsMerge()
    {
        const PointList original = m_c->controlPoints();
        const int drag = m_project->beginGesture();
        roundTrip(
            *m_project,
            [&] {
                for (int k = 1; k <= 10; ++k)
                    m_c->moveControlPoints({{0, {k * 0.5, 0}}, {4, {5, k * 0.25}}}, drag);
            },
            [&] {
                QCOMPARE(m_c->controlPoints()[0], (Point{5, 0}));
                QCOMPARE(m_c->controlPoints()[4], (Point{5, 2.5}));
                QCOMPARE(m_c->controlPoints()[2], original[2]);
            },
            [&] { QVERIFY(m_c->controlPoints() == original); });
    }

    void insertControlPoint()
    {
        const PointList original = m_c->controlPoints();
        QSignalSpy inserted(m_c, &AttractorItem::controlPointInserted);
        roundTrip(
            *m_project, [&] { QVERIFY(m_c->insertControlPoint(2, {-1, -1})); },
            [&] {
                QCOMPARE(m_c->controlPoints().size(), original.size() + 1);
                QCOMPARE(m_c->controlPoints()[2], (Point{-1, -1}));
                QCOMPARE(m_c->controlPoints()[3], original[2]);
            },
            [&] { QVERIFY(m_c->controlPoints() == original); });
        QCOMPARE(inserted.count(), 3);
    }

    void removeControlPoint()
    {
        const PointList original = m_c->controlPoints();
        roundTrip(
            *m_project, [&] { QVERIFY(m_c->removeControlPoint(0)); },
            [&] {
                QCOMPARE(m_c->controlPoints().size(), original.size() - 1);
                QCOMPARE(m_c->controlPoints()[0], original[1]);
            },
            [&] { QVERIFY(m_c->controlPoints() == original); });
    }

    void removeSeveralControlPointsIsOneStep()
    {
        const PointList original = m_c->controlPoints();
        roundTrip(
            *m_project, [&] { QVERIFY(m_c->removeControlPoints({3, 0, 3, 1})); },
            [&] {
                QVERIFY(m_c->controlPoints() == (PointList{original[2], original[4]}));
            },
            [&] { QVERIFY(m_c->controlPoints() == original); });
    }

    void controlPointRefusals()
    {
        const int index = m_project->undoStack()->index();
        QVERIFY(!m_c->moveControlPoint(5, {0, 0}));
        QVERIFY(!m_c->moveControlPoint(0, {qQNaN(), 0}));
        QVERIFY(!m_c->moveControlPoint(0, {0, qInf()}));
        QVERIFY(!m_c->insertControlPoint(6, {0, 0}));
        QVERIFY(!m_c->insertControlPoint(0, {0, 0}, 1)); // no point set 1
        QVERIFY(!m_c->removeControlPoint(-1));
        QVERIFY(!m_c->removeControlPoints({}));
        QVERIFY(m_c->moveControlPoint(0, m_c->controlPoints()[0])); // no-op: accepted, no step
        QCOMPARE(m_project->undoStack()->index(), index);
    }

private:
    QList<Item *> topLevel() const
    {
        QList<Item *> out;
        for (int i = 0; i < m_project->childCount(); ++i)
            out << m_project->child(i);
        return out;
    }

    std::unique_ptr<Project> m_project;
    SubdivisionCurveItem *m_c = nullptr;
};

AWB_TEST_GUILESS_MAIN(TestItemCommands)
#include "test_item_commands.moc"
