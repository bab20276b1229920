// Addresses you can point at (issue 16, part 3) in the window: hovering the attractor shows the
// address and t in the status bar, a typed address highlights the sub-copy with its control
// points S_w P, a click on the attractor pins its address and selects a prefix, a parameter
// interval selects a piece of the curve; a bad address is refused with the reason. The
// selection is view state: no undo step.
#include "gui/app/AddressPanel.h"
#include "gui/app/ItemController.h"
#include "gui/app/MainWindow.h"
#include "gui/app/StatusText.h"
#include "gui/views/AttractorView.h"
#include "model/AttractorItem.h"
#include "model/ItemAddress.h"
#include "model/Project.h"
#include "model/SubdivisionCurveItem.h"

#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QStatusBar>
#include <QUndoStack>
#include <QtTest>

#include "TestMain.h"

#include "TestTime.h"

#include "WindowTestSupport.h"

using namespace awb;

namespace {

void moveMouse(QWidget *w, const QPointF &pos)
{
    QMouseEvent e(QEvent::MouseMove, pos, w->mapToGlobal(pos), Qt::NoButton, Qt::NoButton,
                  Qt::NoModifier);
    QApplication::sendEvent(w, &e);
}

void click(QWidget *w, const QPointF &pos)
{
    QMouseEvent press(QEvent::MouseButtonPress, pos, w->mapToGlobal(pos), Qt::LeftButton,
                      Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(w, &press);
    QMouseEvent release(QEvent::MouseButtonRelease, pos, w->mapToGlobal(pos), Qt::LeftButton,
                        Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(w, &release);
}

// The status bar's text of all its labels and readouts.
QString statusText(MainWindow &w)
{
    QStringList texts;
    for (QLabel *l : w.statusBar()->findChildren<QLabel *>())
        texts << l->text();
    for (StatusText *l : w.statusBar()->findChildren<StatusText *>())
        texts << l->text();
    return texts.join(QStringLiteral(" | "));
}

// The curve point of address w (its start, t = t0(w)) as the view draws it.
QPointF pointOf(const DerivedIfs &d, const StartSet &start, const Address &w)
{
    const AddressedPoints a = sampleAddresses(d.ifs, start.vertices.row(0), 1 << 12);
    const AffineMap f = composeAddress(d.ifs, w);
    // f_w(x*), x* the fixed point of map 0 (the first sample).
    const Mat x = project(d.ifs.views[0], Mat(a.space.row(0) * f.A + f.b));
    return {x(0, 0), x(0, 1)};
}

// Whether `points` (n x 2) has a point within 1% of the extent of `polygon` from the curve
// point of address `end`.
bool drawsNear(const Mat &points, const Mat &polygon, const DerivedIfs &d, const StartSet &start,
               const Address &end)
{
    const double extent = (polygon.colwise().maxCoeff() - polygon.colwise().minCoeff()).norm();
    const QPointF q = pointOf(d, start, end);
    const RowVec e = (RowVec(2) << q.x(), q.y()).finished();
    return (points.rowwise() - e).rowwise().norm().minCoeff() < 0.01 * extent;
}

} // namespace

class TestAddressPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void hoverShowsAddressAndT();
    void typedAddressHighlightsSubCopy();
    void clickPinsAddressAndSelectsPrefix();
    void intervalSelectsPiece();

private:
    // A shown window on a new project (one cubic B-spline) with its views filled.
    std::unique_ptr<test::ShownWindow> openWindow();

    QTemporaryDir m_dir;
    QString m_recovery;
};

std::unique_ptr<test::ShownWindow> TestAddressPanel::openWindow()
{
    auto shown = std::make_unique<test::ShownWindow>(m_recovery, QSize(1300, 850));
    shown->window.controller()->refreshNow();
    return shown;
}

void TestAddressPanel::initTestCase()
{
    test::useTestSettings("test-address-panel");
    m_recovery = m_dir.path() + QStringLiteral("/recovery");
}

void TestAddressPanel::hoverShowsAddressAndT()
{
    const auto shown = openWindow();
    QVERIFY(shown->exposed);
    MainWindow &w = shown->window;
    auto *item = qobject_cast<SubdivisionCurveItem *>(w.currentItem());
    QVERIFY(item && item->scheme().kind == SchemeSpec::Kind::BSpline);
    AttractorView *view = w.attractorView();
    const auto d = item->derivedIfs();
    // t = 0.34375 + 1/64: the middle of the piece 0,1,0,1,1 (far from coarser boundaries).
    const Address w0{0, 1, 0, 1, 1, 1};
    const QPointF screen = view->worldToScreen(pointOf(*d, item->coreStartSet(*d), w0));
    QElapsedTimer timer;
    timer.start();
    moveMouse(view, screen);
    const double firstMs = timer.nsecsElapsed() / 1e6;   // samples the attractor once
    QVERIFY2(statusText(w).contains(QStringLiteral("address 0,1,0,1,1,")),
             qPrintable(statusText(w)));
    QVERIFY2(statusText(w).contains(QStringLiteral("t ≈ 0.35")), qPrintable(statusText(w)));
    timer.restart();
    for (int k = 0; k < 20; ++k)
        moveMouse(view, screen + QPointF(k % 3, 0));
    const double hoverMs = timer.nsecsElapsed() / 1e6 / 20.0;
    qInfo("first hover %.1f ms, then %.3f ms per hover", firstMs, hoverMs);
    QVERIFY2(hoverMs < 5.0 * awb::test::ms(1), qPrintable(QString::number(hoverMs)));
    // Far from the curve: coordinates only.
    moveMouse(view, QPointF(3, 3));
    QVERIFY(!statusText(w).contains(QStringLiteral("address")));
    QVERIFY(statusText(w).contains(QStringLiteral("x = ")));
}

void TestAddressPanel::typedAddressHighlightsSubCopy()
{
    const auto shown = openWindow();
    QVERIFY(shown->exposed);
    MainWindow &w = shown->window;
    auto *item = qobject_cast<AttractorItem *>(w.currentItem());
    const int undoBefore = w.project()->undoStack()->count();
    auto *edit = w.findChild<QLineEdit *>(QStringLiteral("addressEdit"));
    QVERIFY(edit);
    edit->setText(QStringLiteral("0,1,1"));
    QTest::keyClick(edit, Qt::Key_Return);
    AttractorView *view = w.attractorView();
    const AttractorView::Highlight &h = view->highlight();
    QVERIFY(h.points.rows() > 1000);
    QCOMPARE(h.controlPolygons.size(), std::size_t(1));
    const auto d = item->derivedIfs();
    const Mat expected = *addressControlPoints(*d, {0, 1, 1});
    QVERIFY((h.controlPolygons[0] - expected).cwiseAbs().maxCoeff() < 1e-12);
    QVERIFY(h.caption.contains(QStringLiteral("w = 0,1,1")));
    QVERIFY(h.caption.contains(QStringLiteral("t in [0.375, 0.5]")));
    // A cubic B-spline piece lies in the convex hull of its control points.
    const RowVec lo = expected.colwise().minCoeff().array() - 1e-9;
    const RowVec hi = expected.colwise().maxCoeff().array() + 1e-9;
    for (Eigen::Index i = 0; i < h.points.rows(); ++i)
        QVERIFY((h.points.row(i).array() >= lo.array()).all()
                && (h.points.row(i).array() <= hi.array()).all());
    QVERIFY(w.addressPanel()->details().contains(QStringLiteral("S_2 S_2 S_1 P")));
    // The whole piece is drawn: points near both of its ends, t = 0.375 and t = 0.5.
    for (const Address &end : {Address{0, 1, 1}, Address{1}})
        QVERIFY(drawsNear(h.points, expected, *d, item->coreStartSet(*d), end));
    // The view draws it: highlight pixels appear.
    const QImage image = view->grab().toImage().convertToFormat(QImage::Format_RGB32);
    int magenta = 0;   // (200, 0, 120), antialiased
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            magenta += c.red() > 150 && c.green() < 80 && c.blue() > 70 && c.blue() < 170;
        }
    QVERIFY2(magenta > 50, qPrintable(QString::number(magenta)));
    // View state: no undo step, no unsaved change.
    QCOMPARE(w.project()->undoStack()->count(), undoBefore);
    // A bad address is refused with the reason; the selection stays.
    QString error;
    QVERIFY(!w.addressPanel()->select(QStringLiteral("0,5"), &error));
    QVERIFY2(error.contains(QStringLiteral("map 5")), qPrintable(error));
    QCOMPARE(w.addressPanel()->selection(), QStringLiteral("0,1,1"));
    // A moved control point moves the sub-copy's control points with it.
    QVERIFY(item->moveControlPoint(0, Point{-1.0, -1.0}));
    w.controller()->refreshNow();
    const Mat moved = *addressControlPoints(*item->derivedIfs(), {0, 1, 1});
    QVERIFY((view->highlight().controlPolygons[0] - moved).cwiseAbs().maxCoeff() < 1e-12);
    QVERIFY((moved - expected).cwiseAbs().maxCoeff() > 1e-3);
    w.addressPanel()->clearSelection();
    QVERIFY(view->highlight().empty());
}

void TestAddressPanel::clickPinsAddressAndSelectsPrefix()
{
    const auto shown = openWindow();
    QVERIFY(shown->exposed);
    MainWindow &w = shown->window;
    auto *item = qobject_cast<AttractorItem *>(w.currentItem());
    AttractorView *view = w.attractorView();
    const auto d = item->derivedIfs();
    const Address w0{1, 0, 1, 1, 0, 1};
    click(view, view->worldToScreen(pointOf(*d, item->coreStartSet(*d), w0)));
    const Address pinned = w.addressPanel()->pinnedAddress();
    QVERIFY(pinned.size() >= 12);
    QCOMPARE(Address(pinned.begin(), pinned.begin() + 5), (Address{1, 0, 1, 1, 0}));
    QCOMPARE(w.addressPanel()->selection(), QStringLiteral("1,0,1"));   // 3 symbols at first
    QVERIFY(!view->highlight().empty());
    auto *links = w.findChild<QLabel *>(QStringLiteral("addressPrefixes"));
    QVERIFY(links && links->text().contains(QStringLiteral("href=\"5\"")));
    // The link of symbol 5 selects the prefix of five symbols.
    emit links->linkActivated(QStringLiteral("5"));
    QCOMPARE(w.addressPanel()->selection(), QStringLiteral("1,0,1,1,0"));
    // A new item drops the selection.
    w.setCurrentItem(nullptr);
    w.controller()->refreshNow();
    QVERIFY(w.addressPanel()->selection().isEmpty());
    QVERIFY(view->highlight().empty());
}

void TestAddressPanel::intervalSelectsPiece()
{
    const auto shown = openWindow();
    QVERIFY(shown->exposed);
    MainWindow &w = shown->window;
    auto *item = qobject_cast<AttractorItem *>(w.currentItem());
    QVERIFY(w.addressPanel()->select(QStringLiteral("[0.25, 0.5]")));
    const AttractorView::Highlight &h = w.attractorView()->highlight();
    QCOMPARE(h.controlPolygons.size(), std::size_t(1));   // exactly the piece 0,1
    const Mat expected = *addressControlPoints(*item->derivedIfs(), {0, 1});
    QVERIFY((h.controlPolygons[0] - expected).cwiseAbs().maxCoeff() < 1e-12);
    QVERIFY(h.points.rows() > 100);
    QVERIFY(w.addressPanel()->details().contains(QStringLiteral("0,1")));
    // From t = 0.25 to t = 0.5.
    const auto d = item->derivedIfs();
    for (const Address &end : {Address{0, 1}, Address{1}})
        QVERIFY(drawsNear(h.points, expected, *d, item->coreStartSet(*d), end));
    QVERIFY(w.addressPanel()->select(QStringLiteral("[0.25, 0.625]")));
    QCOMPARE(w.attractorView()->highlight().controlPolygons.size(), std::size_t(2));
    QString error;
    QVERIFY(!w.addressPanel()->select(QStringLiteral("[0.5, 0.2]"), &error));
    QVERIFY(error.contains(QStringLiteral("0 <= t0 < t1 <= 1")));
}

AWB_TEST_MAIN(TestAddressPanel)
#include "test_address_panel.moc"
