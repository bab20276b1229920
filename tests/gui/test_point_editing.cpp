// Adding, inserting and deleting control points (issue 17, part 7): in the attractor view by its
// context menu and by a double click on an edge of the control polygon, and in the Properties
// table by its buttons; one undo step each; a Bézier curve's degree follows; kinds whose number
// of points is fixed refuse, with the reason shown.
#include "gui/app/ControlPointEdits.h"
#include "gui/app/ItemController.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Messages.h"
#include "gui/app/PropertiesDock.h"
#include "gui/views/AttractorView.h"
#include "model/CifsItem.h"
#include "model/FractalItem.h"
#include "model/NormalVectorItem.h"
#include "model/Project.h"
#include "model/SubdivisionCurveItem.h"
#include "model/SubdivisionSurfaceItem.h"

#include <QMenu>
#include <QTableWidget>
#include <QToolButton>
#include <QtTest>

#include "TestMain.h"

#include "WindowTestSupport.h"

using namespace awb;

namespace {

QAction *menuAction(QMenu &menu, const char *name)
{
    for (QAction *a : menu.actions())
        if (a->objectName() == QLatin1String(name))
            return a;
    return nullptr;
}

} // namespace

class TestPointEditing : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void contextMenuInsertsAndDeletes();
    void doubleClickOnAnEdgeInserts();
    void tableButtonsEditPoints();
    void bezierDegreeFollows();
    void fixedKindsRefuse();

private:
    QTemporaryDir m_dir;
    QString m_recovery;
};

void TestPointEditing::initTestCase()
{
    test::useTestSettings("test-point-editing");
    m_recovery = m_dir.path() + QStringLiteral("/recovery");
}

void TestPointEditing::contextMenuInsertsAndDeletes()
{
    test::ShownWindow shown(m_recovery, {1300, 850});
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    auto *item = qobject_cast<SubdivisionCurveItem *>(w.currentItem());
    AttractorView *view = w.attractorView();
    QUndoStack *stack = w.project()->undoStack();
    const PointList before = item->controlPoints();
    QCOMPARE(before.size(), std::size_t(5));
    // On point 3: insert before / after, delete.
    const QPointF p3 = view->worldToScreen(view->controlPointPosition(2));
    {
        QMenu menu;
        w.controller()->fillContextMenu(&menu, p3);
        QVERIFY(menuAction(menu, "actionInsertPointBefore"));
        QVERIFY(menuAction(menu, "actionInsertPointAfter"));
        QAction *del = menuAction(menu, "actionDeletePoint");
        QVERIFY(del && del->isEnabled());
        del->trigger();
    }
    QCOMPARE(item->controlPoints().size(), std::size_t(4));
    QCOMPARE(stack->count(), 1);
    QCOMPARE(item->controlPoints()[2].x, before[3].x);
    stack->undo();
    QVERIFY(item->controlPoints() == before);
    {
        QMenu menu;
        w.controller()->fillContextMenu(&menu, p3);
        menuAction(menu, "actionInsertPointAfter")->trigger();
    }
    QCOMPARE(item->controlPoints().size(), std::size_t(6));
    // Halfway between points 3 and 4.
    QCOMPARE(item->controlPoints()[3].x, 0.5 * (before[2].x + before[3].x));
    QCOMPARE(stack->count(), 1); // the undone delete is gone, the insert is one step
    stack->undo();
    // On an edge: insert there, at the point of the edge nearest to the click.
    w.controller()->refreshNow();
    const QPointF a = view->worldToScreen(view->controlPointPosition(0));
    const QPointF b = view->worldToScreen(view->controlPointPosition(1));
    const QPointF mid = 0.5 * (a + b);
    {
        QMenu menu;
        w.controller()->fillContextMenu(&menu, mid);
        QVERIFY(!menuAction(menu, "actionDeletePoint"));
        QAction *here = menuAction(menu, "actionInsertPointHere");
        QVERIFY(here);
        here->trigger();
    }
    QCOMPARE(item->controlPoints().size(), std::size_t(6));
    const QPointF world = view->screenToWorld(mid);
    QVERIFY(std::abs(item->controlPoints()[1].x - world.x()) < 0.05);
    QVERIFY(std::abs(item->controlPoints()[1].y - world.y()) < 0.05);
    stack->undo();
    // Far from the polygon: append at the cursor.
    w.controller()->refreshNow();
    const QPointF empty = view->worldToScreen(QPointF(before.back().x + 1, before.back().y - 3));
    {
        QMenu menu;
        w.controller()->fillContextMenu(&menu, empty);
        QAction *append = menuAction(menu, "actionAppendPoint");
        QVERIFY(append);
        append->trigger();
    }
    QCOMPARE(item->controlPoints().size(), std::size_t(6));
    QVERIFY(std::abs(item->controlPoints().back().x - (before.back().x + 1)) < 0.05);
    QVERIFY(shown.messages.errors.isEmpty());
}

void TestPointEditing::doubleClickOnAnEdgeInserts()
{
    test::ShownWindow shown(m_recovery, {1300, 850});
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    auto *item = qobject_cast<SubdivisionCurveItem *>(w.currentItem());
    AttractorView *view = w.attractorView();
    w.controller()->refreshNow();
    const QPointF a = view->worldToScreen(view->controlPointPosition(3));
    const QPointF b = view->worldToScreen(view->controlPointPosition(4));
    const QPoint mid = (0.5 * (a + b)).toPoint();
    QCOMPARE(view->controlEdgeAt(mid), 3);
    QTest::mouseDClick(view, Qt::LeftButton, {}, mid);
    QCOMPARE(item->controlPoints().size(), std::size_t(6));
    QCOMPARE(w.project()->undoStack()->count(), 1);
    const QPointF world = view->screenToWorld(mid);
    QVERIFY(std::abs(item->controlPoints()[4].x - world.x()) < 0.05);
    // A right click that does not move asks for the menu; a right drag pans.
    QSignalSpy menu(view, &AttractorView::contextMenuRequested);
    const QPointF centre = view->viewCenter();
    QTest::mousePress(view, Qt::RightButton, {}, QPoint(30, 30));
    QTest::mouseMove(view, QPoint(90, 80));
    QTest::mouseRelease(view, Qt::RightButton, {}, QPoint(90, 80));
    QCOMPARE(menu.count(), 0);
    QVERIFY(view->viewCenter() != centre);
}

void TestPointEditing::tableButtonsEditPoints()
{
    test::ShownWindow shown(m_recovery);
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    auto *item = qobject_cast<SubdivisionCurveItem *>(w.currentItem());
    auto *table = qobject_cast<QTableWidget *>(w.propertiesWidget()->editor("points"));
    auto *add = qobject_cast<QToolButton *>(w.propertiesWidget()->editor("points.add"));
    auto *insert = qobject_cast<QToolButton *>(w.propertiesWidget()->editor("points.insert"));
    auto *remove = qobject_cast<QToolButton *>(w.propertiesWidget()->editor("points.delete"));
    QVERIFY(table && add && insert && remove);
    QVERIFY(add->isEnabled());
    QUndoStack *stack = w.project()->undoStack();
    const PointList before = item->controlPoints();
    add->click();
    QCOMPARE(table->rowCount(), 6);
    QCOMPARE(stack->count(), 1);
    // Beyond the last point by half the last edge.
    QCOMPARE(item->controlPoints().back().x, before[4].x + 0.5 * (before[4].x - before[3].x));
    table->selectRow(1);
    insert->click();
    QCOMPARE(table->rowCount(), 7);
    QCOMPARE(stack->count(), 2);
    QCOMPARE(item->controlPoints()[1].x, 0.5 * (before[0].x + before[1].x));
    // Two selected rows deleted together: one step.
    table->clearSelection();
    table->setSelectionMode(QAbstractItemView::MultiSelection);
    table->selectRow(0);
    table->selectRow(6);
    remove->click();
    QCOMPARE(table->rowCount(), 5);
    QCOMPARE(stack->count(), 3);
    stack->undo();
    stack->undo();
    stack->undo();
    QVERIFY(item->controlPoints() == before);
    QCOMPARE(table->rowCount(), 5);
    // The same actions in the table's context menu.
    QCOMPARE(table->contextMenuPolicy(), Qt::ActionsContextMenu);
    QCOMPARE(table->actions().size(), 3);
    QVERIFY(shown.messages.errors.isEmpty());
}

void TestPointEditing::bezierDegreeFollows()
{
    Project p;
    auto owned = std::make_unique<SubdivisionCurveItem>();
    auto *c = owned.get();
    p.addItem(std::move(owned));
    SchemeSpec s = c->scheme();
    s.kind = SchemeSpec::Kind::Bezier;
    s.degree = int(c->controlPoints().size()) - 1;
    QVERIFY(c->setScheme(s));
    QVERIFY(c->derivedIfs());
    const int steps = p.undoStack()->count();
    const int degree = c->scheme().degree;
    QString error;
    QVERIFY2(control_points::insert(c, 0, 1, {0.5, 0.5}, &error), qPrintable(error));
    QCOMPARE(c->scheme().degree, degree + 1);
    QVERIFY2(c->derivedIfs(), qPrintable(c->derivedError()));
    QCOMPARE(p.undoStack()->count(), steps + 1);
    QVERIFY(control_points::remove(c, 0, {0, 1}, &error));
    QCOMPARE(c->scheme().degree, degree - 1);
    QVERIFY(c->derivedIfs());
    p.undoStack()->undo();
    QCOMPARE(c->scheme().degree, degree + 1);
    p.undoStack()->undo();
    QCOMPARE(c->scheme().degree, degree);
    QCOMPARE(p.undoStack()->count(), steps + 2);
    // Never below two points.
    while (c->controlPoints().size() > 2)
        QVERIFY(control_points::remove(c, 0, {0}, &error));
    QVERIFY(!control_points::remove(c, 0, {0}, &error));
    QVERIFY2(error.contains(QStringLiteral("at least 2")), qPrintable(error));
}

void TestPointEditing::fixedKindsRefuse()
{
    test::ShownWindow shown(m_recovery);
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    // Each kind: whether its points can be added or removed.
    auto fractal = std::make_unique<FractalItem>();   // the Koch preset: 5 points
    auto cifs = std::make_unique<CifsItem>();         // the frame triangle
    auto surface = std::make_unique<SubdivisionSurfaceItem>();
    auto normal = std::make_unique<NormalVectorItem>();  // a polygon: any number
    QVERIFY(!fractal->pointCountEditable(0));
    QVERIFY(!cifs->pointCountEditable(0));
    QVERIFY(!surface->pointCountEditable(0));
    QVERIFY(normal->pointCountEditable(0));
    auto *koch = fractal.get();
    w.project()->addItem(std::move(fractal));
    w.setCurrentItem(koch);
    w.controller()->refreshNow();
    auto *add = qobject_cast<QToolButton *>(w.propertiesWidget()->editor("points.add"));
    QVERIFY(add && !add->isEnabled());
    const int steps = w.project()->undoStack()->count();
    QMenu menu;
    w.controller()->fillContextMenu(
        &menu, w.attractorView()->worldToScreen(w.attractorView()->controlPointPosition(1)));
    QAction *del = menuAction(menu, "actionDeletePoint");
    QVERIFY(del && !del->isEnabled());
    QVERIFY2(del->toolTip().contains(QStringLiteral("fixed number")), qPrintable(del->toolTip()));
    // A double click on an edge reports the reason instead of inserting.
    QString error;
    QVERIFY(!control_points::insert(koch, 0, 1, {0, 0}, &error));
    QVERIFY(error.contains(QStringLiteral("fixed number")));
    QCOMPARE(w.project()->undoStack()->count(), steps);
    // Own matrices fix m; the other curve schemes do not.
    SubdivisionCurveItem curve;
    QVERIFY(curve.pointCountEditable(0));
}

AWB_TEST_MAIN(TestPointEditing)
#include "test_point_editing.moc"
