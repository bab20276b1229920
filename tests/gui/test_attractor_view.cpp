// The attractor view: dragging control points and start-set vertices (one press, moves, one
// release, in world coordinates), wheel zoom about the cursor, pan, fit, the rendered raster,
// cancelling a long render and rendering again, and the vector export (SVG) of the control
// polygon.

#include "gui/views/AttractorView.h"

#include <QBuffer>
#include <QPainter>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSvgGenerator>
#include <QtTest>

#include "TestMain.h"

#include "TestTime.h"

using namespace awb;

namespace {

Mat fig2()
{
    Mat P(5, 2);
    P << 0, 0, 1, 2, 3, 2.5, 4.5, 1, 6, 2;
    return P;
}

QPointF row(const Mat &P, int i) { return {P(i, 0), P(i, 1)}; }

// The widget as painted on screen (status overlay included), as SVG: its texts are readable.
QString screenSvg(AttractorView &view)
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    QSvgGenerator gen;
    gen.setOutputDevice(&buffer);
    gen.setSize(view.size());
    gen.setViewBox(view.rect());
    view.render(&gen);
    return QString::fromUtf8(buffer.data());
}

bool near(const QPointF &a, const QPointF &b, double tol)
{
    return QLineF(a, b).length() < tol;
}

// A shown view with the cubic B-spline of 000 Fig. 2 and a triangle as the start set.
struct Fixture {
    SubdivisionIfs s = buildSubdivisionIfs(bsplineScheme(3), fig2());
    Mat triangle;
    AttractorView view;

    Fixture()
    {
        triangle.resize(3, 2);
        triangle << 1, -1, 5, -1, 3, 0.5;
        view.resize(480, 320);
        view.setIfs(std::make_shared<const Ifs>(s.ifs),
                    StartSet::polygon(s.toIfsSpace(triangle)));
        view.setControlPoints(fig2());
        view.setExactCurve(*bsplineScheme(3).exactCurve(fig2(), 400));
        view.show();
    }
};

} // namespace

class TestAttractorView : public QObject {
    Q_OBJECT
private slots:
    void fitShowsEverythingWithEqualScale();
    void dragControlPoint();
    void dragStartVertex();
    void clickWithoutMoveIsOneStep();
    void wheelZoomsAboutTheCursor();
    void panWithMiddleAndRightButton();
    void rendersTheAttractor();
    void cancelAndRenderAgain();
    void hutchinsonStep();
    void svgExportHasVectorPaths();
    void hiddenViewExportsTheRaster();
    void fittedExportIgnoresZoom();
};

void TestAttractorView::fitShowsEverythingWithEqualScale()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.view));
    const QRectF vis = f.view.visibleWorldRect();
    for (int i = 0; i < 5; ++i)
        QVERIFY(vis.contains(row(fig2(), i)));
    QVERIFY(vis.contains(QPointF(1, -1)) && vis.contains(QPointF(5, -1)));
    // Equal scale: one world unit is as many pixels across as up.
    const QPointF a = f.view.worldToScreen({0, 0}), b = f.view.worldToScreen({1, 1});
    QCOMPARE(b.x() - a.x(), a.y() - b.y());
    QCOMPARE(f.view.screenToWorld(f.view.worldToScreen({2.5, -0.75})), QPointF(2.5, -0.75));
}

void TestAttractorView::dragControlPoint()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.view));
    QSignalSpy pressed(&f.view, &AttractorView::controlPointPressed);
    QSignalSpy dragged(&f.view, &AttractorView::controlPointDragged);
    QSignalSpy released(&f.view, &AttractorView::controlPointReleased);
    QSignalSpy startPressed(&f.view, &AttractorView::startVertexPressed);
    QSignalSpy cursor(&f.view, &AttractorView::cursorMoved);

    const QPointF p2 = row(fig2(), 2);
    // Grab the handle 2 pixels off its centre: the point moves with the cursor, no jump.
    const QPoint grab = (f.view.worldToScreen(p2) + QPointF(2, 1)).toPoint();
    const QPointF grabWorld = f.view.screenToWorld(grab);
    QTest::mousePress(&f.view, Qt::LeftButton, Qt::NoModifier, grab);
    QTest::mouseMove(&f.view, grab + QPoint(10, 0));
    QTest::mouseMove(&f.view, grab + QPoint(25, -10));
    const QPoint end = grab + QPoint(40, -30);
    QTest::mouseMove(&f.view, end);
    QTest::mouseRelease(&f.view, Qt::LeftButton, Qt::NoModifier, end);

    const QPointF expected = p2 + (f.view.screenToWorld(end) - grabWorld);
    QCOMPARE(pressed.size(), 1);
    QCOMPARE(pressed.first().at(0).toInt(), 2);
    QVERIFY(dragged.size() >= 1);
    for (const auto &args : dragged)
        QCOMPARE(args.at(0).toInt(), 2);
    QVERIFY(near(dragged.last().at(1).toPointF(), expected, 1e-9));
    QCOMPARE(released.size(), 1);
    QCOMPARE(released.first().at(0).toInt(), 2);
    QCOMPARE(released.first().at(1).toPointF(), p2);
    QVERIFY(near(released.first().at(2).toPointF(), expected, 1e-9));
    // The moved point went up and right by 40 and 30 pixels.
    const double s = f.view.pixelsPerUnit();
    QVERIFY(near(expected - p2, QPointF(40 / s, 30 / s), 1e-9));
    QVERIFY(startPressed.isEmpty());
    QVERIFY(!cursor.isEmpty());
    // The view does not own the data: after the drag it shows the owner's points again.
    QCOMPARE(f.view.controlPointPosition(2), p2);
}

void TestAttractorView::dragStartVertex()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.view));
    QSignalSpy pressed(&f.view, &AttractorView::startVertexPressed);
    QSignalSpy dragged(&f.view, &AttractorView::startVertexDragged);
    QSignalSpy released(&f.view, &AttractorView::startVertexReleased);
    QSignalSpy controlPressed(&f.view, &AttractorView::controlPointPressed);
    QCOMPARE(f.view.startVertexCount(), 3);
    QVERIFY(near(f.view.startVertexPosition(1), QPointF(5, -1), 1e-12));

    const QPoint grab = f.view.worldToScreen(QPointF(5, -1)).toPoint();
    const QPointF grabWorld = f.view.screenToWorld(grab);
    QTest::mousePress(&f.view, Qt::LeftButton, Qt::NoModifier, grab);
    QTest::mouseMove(&f.view, grab + QPoint(-15, 20));
    // While dragging, the view draws the vertex where the cursor took it.
    const QPointF during = QPointF(5, -1) + f.view.screenToWorld(grab + QPoint(-15, 20))
                           - grabWorld;
    QVERIFY(near(f.view.startVertexPosition(1), during, 1e-9));
    QTest::mouseRelease(&f.view, Qt::LeftButton, Qt::NoModifier, grab + QPoint(-15, 20));
    QCOMPARE(pressed.size(), 1);
    QCOMPARE(pressed.first().at(0).toInt(), 1);
    QCOMPARE(dragged.size(), 1);
    QCOMPARE(released.size(), 1);
    QVERIFY(near(released.first().at(1).toPointF(), QPointF(5, -1), 1e-12));
    QVERIFY(near(released.first().at(2).toPointF(), during, 1e-9));
    QVERIFY(controlPressed.isEmpty());
}

void TestAttractorView::clickWithoutMoveIsOneStep()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.view));
    QSignalSpy pressed(&f.view, &AttractorView::controlPointPressed);
    QSignalSpy dragged(&f.view, &AttractorView::controlPointDragged);
    QSignalSpy released(&f.view, &AttractorView::controlPointReleased);
    const QPoint at = f.view.worldToScreen(row(fig2(), 0)).toPoint();
    QTest::mouseClick(&f.view, Qt::LeftButton, Qt::NoModifier, at);
    QCOMPARE(pressed.size(), 1);
    QCOMPARE(dragged.size(), 0);
    QCOMPARE(released.size(), 1);
    QCOMPARE(released.first().at(1).toPointF(), released.first().at(2).toPointF());
    // Far from every handle nothing is pressed.
    QTest::mouseClick(&f.view, Qt::LeftButton, Qt::NoModifier, QPoint(3, 3));
    QCOMPARE(pressed.size(), 1);
    QCOMPARE(released.size(), 1);
    // Read-only control points cannot be grabbed.
    f.view.setControlPointsEditable(false);
    QTest::mouseClick(&f.view, Qt::LeftButton, Qt::NoModifier, at);
    QCOMPARE(pressed.size(), 1);
}

void TestAttractorView::wheelZoomsAboutTheCursor()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.view));
    QSignalSpy changed(&f.view, &AttractorView::viewChanged);
    const QPointF cursor(100, 80);
    const QPointF under = f.view.screenToWorld(cursor);
    const QPointF farPoint = f.view.screenToWorld(QPointF(400, 250));
    const double s0 = f.view.pixelsPerUnit();
    QWheelEvent wheel(cursor, f.view.mapToGlobal(cursor), QPoint(), QPoint(0, 120),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&f.view, &wheel);
    QCOMPARE(f.view.pixelsPerUnit(), s0 * 1.2);
    QVERIFY(near(f.view.screenToWorld(cursor), under, 1e-12));
    QVERIFY(!near(f.view.screenToWorld(QPointF(400, 250)), farPoint, 1e-3));
    QVERIFY(!changed.isEmpty());
    // Zooming out by the same amount brings the mapping back.
    QWheelEvent back(cursor, f.view.mapToGlobal(cursor), QPoint(), QPoint(0, -120),
                     Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&f.view, &back);
    QVERIFY(std::abs(f.view.pixelsPerUnit() - s0) < 1e-9 * s0);
    QVERIFY(near(f.view.screenToWorld(QPointF(400, 250)), farPoint, 1e-9));
    // The user zoomed: new data no longer refits the view; fitToContents() does.
    f.view.zoomBy(3.0, cursor);
    const double zoomed = f.view.pixelsPerUnit();
    f.view.setControlPoints(fig2() * 2.0);
    QCOMPARE(f.view.pixelsPerUnit(), zoomed);
    f.view.fitToContents();
    QVERIFY(f.view.visibleWorldRect().contains(QPointF(12, 4)));
}

void TestAttractorView::panWithMiddleAndRightButton()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.view));
    for (Qt::MouseButton b : {Qt::MiddleButton, Qt::RightButton}) {
        const QPointF c0 = f.view.viewCenter();
        const double s = f.view.pixelsPerUnit();
        QTest::mousePress(&f.view, b, Qt::NoModifier, QPoint(200, 150));
        QTest::mouseMove(&f.view, QPoint(230, 140));
        QTest::mouseRelease(&f.view, b, Qt::NoModifier, QPoint(230, 140));
        // The content follows the cursor: 30 px right and 10 px up.
        QVERIFY(near(f.view.viewCenter(), c0 + QPointF(-30 / s, -10 / s), 1e-9));
    }
}

void TestAttractorView::rendersTheAttractor()
{
    Fixture f;
    QSignalSpy finished(&f.view, &AttractorView::renderFinished);
    AttractorView::RenderSettings rs;
    rs.depth = 12;
    f.view.setRenderSettings(rs);
    QVERIFY(QTest::qWaitForWindowExposed(&f.view));
    QVERIFY(finished.wait(awb::test::ms(30000)));
    const QImage img = f.view.currentImage();
    QCOMPARE(img.size(), f.view.size() * f.view.devicePixelRatio());
    QVERIFY(f.view.currentImageInfo().final);
    QCOMPARE(f.view.currentImageInfo().depth, 12);
    QVERIFY(f.view.currentImageInfo().litPixels > 200);
    QVERIFY(f.view.lastError().isEmpty());
    // The raster covers the visible rectangle: an attractor pixel lies where the curve is.
    QCOMPARE(f.view.currentImageInfo().world, f.view.visibleWorldRect());

    // A change of data renders again (once, coalesced).
    finished.clear();
    f.view.setControlPoints(fig2());
    f.view.setRenderSettings(rs);
    QVERIFY(finished.wait(awb::test::ms(30000)));
    QTest::qWait(100);
    QCOMPARE(finished.size(), 1);

    // An IFS without an attractor: an error instead of a stale picture.
    auto bad = std::make_shared<Ifs>(f.s.ifs);
    bad->maps[0].A *= 4.0;
    QSignalSpy failed(&f.view, &AttractorView::renderFailed);
    f.view.setIfs(bad, StartSet::points(f.s.toIfsSpace(fig2().topRows(1))));
    QVERIFY(failed.wait(awb::test::ms(30000)));
    QVERIFY(f.view.currentImage().isNull());
    QVERIFY(f.view.lastError().contains(QLatin1String("not contractive")));
}

void TestAttractorView::cancelAndRenderAgain()
{
    Fixture f;
    QSignalSpy finished(&f.view, &AttractorView::renderFinished);
    QSignalSpy cancelled(&f.view, &AttractorView::renderCancelled);
    QSignalSpy progress(&f.view, &AttractorView::renderProgress);
    // 2^27 triangles take far longer than this test waits for anything: only a cancel ends it.
    AttractorView::RenderSettings heavy;
    heavy.depth = 27;
    f.view.setRenderSettings(heavy);
    QVERIFY(QTest::qWaitForWindowExposed(&f.view));
    // The coarse preview (2^14 images) arrives first; the full pass is then running.
    QTRY_VERIFY_WITH_TIMEOUT(!f.view.currentImage().isNull()
                                 && f.view.currentImageInfo().depth == 14, awb::test::ms(30000));
    QVERIFY(!f.view.currentImageInfo().final);
    QVERIFY(f.view.isRendering());
    QVERIFY(!screenSvg(f.view).contains(QLatin1String("cancelled")));
    const qint64 coarseKey = f.view.currentImage().cacheKey();

    // Esc stops it; the coarse picture stays on screen and the overlay says what happened.
    QTest::keyClick(&f.view, Qt::Key_Escape);
    QCOMPARE(cancelled.size(), 1);
    QTRY_VERIFY_WITH_TIMEOUT(!f.view.isRendering(), awb::test::ms(2000));
    QVERIFY(!f.view.renderer()->isBusy());
    QCOMPARE(f.view.currentImage().cacheKey(), coarseKey);
    const QString svg = screenSvg(f.view);
    QVERIFY2(svg.contains(QLatin1String("Rendering cancelled at")), qPrintable(svg.right(2000)));
    QVERIFY(svg.contains(QLatin1String("F5")));
    // Nothing of the cancelled render arrives later.
    progress.clear();
    QTest::qWait(500);
    QVERIFY(finished.isEmpty());
    QVERIFY(progress.isEmpty());
    QCOMPARE(f.view.currentImage().cacheKey(), coarseKey);
    QVERIFY(!f.view.isRendering());
    // With nothing running, Esc is left to the parent and cancels nothing.
    QKeyEvent esc(QEvent::KeyPress, Qt::Key_Escape, Qt::NoModifier);
    QApplication::sendEvent(&f.view, &esc);
    QVERIFY(!esc.isAccepted());
    f.view.cancelRender();
    QCOMPARE(cancelled.size(), 1);

    // renderAgain() starts the same render at once; cancelRender() stops it again.
    f.view.renderAgain();
    QVERIFY(f.view.isRendering());
    QVERIFY(!screenSvg(f.view).contains(QLatin1String("cancelled")));
    QTRY_VERIFY_WITH_TIMEOUT(f.view.currentImage().cacheKey() != coarseKey, awb::test::ms(30000));
    QCOMPARE(f.view.currentImageInfo().depth, 14);
    QVERIFY(f.view.isRendering());
    f.view.cancelRender();
    QCOMPARE(cancelled.size(), 2);
    QVERIFY(!f.view.isRendering());
    QVERIFY(screenSvg(f.view).contains(QLatin1String("Rendering cancelled at")));

    // An edit after the cancel renders normally: to the end, and the note is gone.
    AttractorView::RenderSettings light;
    light.depth = 10;
    f.view.setRenderSettings(light);
    QVERIFY(finished.wait(awb::test::ms(30000)));
    QCOMPARE(finished.size(), 1);
    QVERIFY(f.view.currentImageInfo().final);
    QCOMPARE(f.view.currentImageInfo().depth, 10);
    QVERIFY(!f.view.isRendering());
    QVERIFY(!screenSvg(f.view).contains(QLatin1String("cancelled")));

    // F5 renders the unchanged data again.
    const qint64 lightKey = f.view.currentImage().cacheKey();
    QTest::keyClick(&f.view, Qt::Key_F5);
    QVERIFY(f.view.isRendering());
    QVERIFY(finished.wait(awb::test::ms(30000)));
    QCOMPARE(finished.size(), 2);
    QVERIFY(f.view.currentImage().cacheKey() != lightKey);
    QCOMPARE(f.view.currentImageInfo().depth, 10);
    QCOMPARE(cancelled.size(), 2);
}

void TestAttractorView::hutchinsonStep()
{
    Fixture f;
    f.view.setHutchinsonStep(0);
    QCOMPARE(f.view.hutchinsonImageCount(), 1);   // X0 itself
    f.view.setHutchinsonStep(3);
    QCOMPARE(f.view.hutchinsonImageCount(), 8);   // 2^3 triangles
    f.view.setHutchinsonStep(30);                 // 2^30 images: not as vectors
    QCOMPARE(f.view.hutchinsonImageCount(), 0);
    f.view.setHutchinsonStep(-1);
    QCOMPARE(f.view.hutchinsonImageCount(), 0);
}

void TestAttractorView::svgExportHasVectorPaths()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.view));
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    QSvgGenerator gen;
    gen.setOutputDevice(&buffer);
    gen.setSize(QSize(600, 400));
    gen.setViewBox(QRect(0, 0, 600, 400));
    {
        QPainter p(&gen);
        f.view.renderTo(&p, QRectF(0, 0, 600, 400));
    }
    const QString svg = QString::fromUtf8(buffer.data());
    QVERIFY(svg.contains(QLatin1String("<path")));
    // The control polygon: a group stroked in its colour holding one path through the five
    // control points (M + 4 L), at the export's scale.
    const QRegularExpression group(
        QStringLiteral("<g [^>]*stroke=\"#282828\"[^>]*>\\s*<path [^>]*d=\"([^\"]*)\""));
    bool found = false;
    for (auto it = group.globalMatch(svg); it.hasNext();) {
        const QString d = it.next().captured(1);
        if (d.count(QLatin1Char('M')) == 1 && d.count(QLatin1Char('L')) == 4) {
            found = true;
            break;
        }
    }
    QVERIFY2(found, qPrintable(svg.left(3000)));
    // Few points at depth 8 from a triangle: the attractor is drawn as vector shapes too.
    AttractorView::RenderSettings rs;
    rs.depth = 6;
    f.view.setRenderSettings(rs);
    QBuffer buffer2;
    buffer2.open(QIODevice::WriteOnly);
    QSvgGenerator gen2;
    gen2.setOutputDevice(&buffer2);
    gen2.setSize(QSize(600, 400));
    {
        QPainter p(&gen2);
        f.view.renderTo(&p, QRectF(0, 0, 600, 400));
    }
    const QString svg2 = QString::fromUtf8(buffer2.data());
    QVERIFY(!svg2.contains(QLatin1String("<image")));
    QVERIFY(svg2.count(QLatin1String("<path")) >= 64); // the 2^6 triangles
}

void TestAttractorView::hiddenViewExportsTheRaster()
{
    // Never shown, so never rendered: the export draws the attractor itself.
    const SubdivisionIfs s = buildSubdivisionIfs(bsplineScheme(3), fig2());
    AttractorView view;
    view.resize(400, 300);
    view.setIfs(std::make_shared<const Ifs>(s.ifs), StartSet::points(s.toIfsSpace(
                                                        fig2().topRows(1))));
    view.setControlPoints(fig2());
    AttractorView::RenderSettings rs;
    rs.depth = 15; // 2^15 points: too many for vector dots, so a raster
    view.setRenderSettings(rs);
    QVERIFY(view.currentImage().isNull());
    QImage out(400, 300, QImage::Format_ARGB32);
    out.fill(Qt::white);
    {
        QPainter p(&out);
        view.renderTo(&p, QRectF(0, 0, 400, 300));
    }
    // The two map colours appear in the export.
    int blue = 0, red = 0;
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) {
            blue += out.pixel(x, y) == AttractorRenderer::mapColor(0).rgb();
            red += out.pixel(x, y) == AttractorRenderer::mapColor(1).rgb();
        }
    QVERIFY2(blue > 50 && red > 50, qPrintable(QStringLiteral("%1 %2").arg(blue).arg(red)));
}

void TestAttractorView::fittedExportIgnoresZoom()
{
    // The printed figure frames the content whatever the screen shows: zoomed far into one
    // corner, an "as shown" export lacks most of the attractor, a fitted one has all of it.
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.view));
    AttractorView::RenderSettings rs;
    rs.depth = 14; // a raster, not vector dots
    f.view.setRenderSettings(rs);
    f.view.setView(QPointF(0.2, 0.2), f.view.pixelsPerUnit() * 12);
    QTRY_VERIFY_WITH_TIMEOUT(f.view.currentImageInfo().final, awb::test::ms(20000));
    const auto colouredColumns = [](const QImage &img, int *left, int *right) {
        int count = 0;
        *left = img.width();
        *right = -1;
        for (int x = 0; x < img.width(); ++x)
            for (int y = 0; y < img.height(); ++y)
                if (img.pixel(x, y) == AttractorRenderer::mapColor(0).rgb()
                    || img.pixel(x, y) == AttractorRenderer::mapColor(1).rgb()) {
                    ++count;
                    *left = std::min(*left, x);
                    *right = std::max(*right, x);
                    break;
                }
        return count;
    };
    const auto exportWith = [&](AttractorView::Framing framing) {
        QImage out(800, 400, QImage::Format_ARGB32);
        out.fill(Qt::white);
        QPainter p(&out);
        f.view.renderTo(&p, QRectF(0, 0, 800, 400), framing);
        return out;
    };
    int l1, r1, l2, r2;
    const int shown = colouredColumns(exportWith(AttractorView::Framing::AsShown), &l1, &r1);
    const QImage fittedImage = exportWith(AttractorView::Framing::FitContents);
    if (qEnvironmentVariableIsSet("AWB_KEEP_TEST_FILES"))
        fittedImage.save(QStringLiteral("/tmp/fitted-export.png"));
    const int fitted = colouredColumns(fittedImage, &l2, &r2);
    // The content is x in 0..6, y in -1..2.5 (control polygon and triangle), so the 800 x 400
    // target is filled in height: ~100 px per unit. The curve runs from x ~ 1 to ~ 4.5, so
    // ~330 columns show it.
    QVERIFY2(fitted > 250 && fitted < 420 && l2 > 150 && r2 < 650,
             qPrintable(QStringLiteral("%1 %2..%3").arg(fitted).arg(l2).arg(r2)));
    QVERIFY2(shown < fitted / 2, qPrintable(QStringLiteral("%1 vs %2").arg(shown).arg(fitted)));
    // The screen's framing is untouched by the export.
    QCOMPARE(f.view.viewCenter(), QPointF(0.2, 0.2));
}

AWB_TEST_MAIN(TestAttractorView)
#include "test_attractor_view.moc"
