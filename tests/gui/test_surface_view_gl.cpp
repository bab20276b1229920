// The 3D view's OpenGL path (Mesa llvmpipe) under a virtual X server, CTest's
// gui_test_surface_view_gl (tests/CMakeLists.txt runs it under xvfb-run with
// QT_QPA_PLATFORM=xcb and AWB_REQUIRE_GL=1): the GL path draws test_surface_view's Loop patch
// as the CPU path does, reports its frame times rotating and at rest at 10 k and 400 k
// primitives, and a drag of a control point in the main window is one undo step whose frames
// follow the mouse (latency per move printed).
#include "gui/app/ItemController.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Messages.h"
#include "gui/views/SurfaceView.h"
#include "model/Project.h"
#include "model/SubdivisionSurfaceItem.h"

#include <QElapsedTimer>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include "ImageCompare.h"
#include "SurfaceViewTestSupport.h"
#include "TestMain.h"

#include "TestTime.h"

using namespace awb;
using awb::test::compare;
using awb::test::feed;
using awb::test::ImageDiff;
using awb::test::loopItem;

class TestSurfaceViewGl : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void glPathUnderXvfb();
    void glDragUnderXvfb();

private:
    QTemporaryDir m_dir;
};

void TestSurfaceViewGl::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("awb-test"));
    QCoreApplication::setApplicationName(QStringLiteral("test-surface-view-gl"));
    QVERIFY(m_dir.isValid());
}

// Under CTest (Xvfb, AWB_REQUIRE_GL=1) a missing display or GL context is a failure; run by
// hand on the offscreen platform, which draws with the CPU path (test_surface_view), the cases
// skip.
static bool glTestCanRun()
{
    const bool required = qEnvironmentVariableIsSet("AWB_REQUIRE_GL");
    if (QGuiApplication::platformName() != QLatin1String("xcb")) {
        if (required)
            QTest::qFail("AWB_REQUIRE_GL is set but the platform is not xcb", __FILE__, __LINE__);
        else
            QTest::qSkip("the GL path runs under Xvfb (QT_QPA_PLATFORM=xcb); offscreen uses the "
                         "CPU path", __FILE__, __LINE__);
        return false;
    }
    // This machine's GL is a software one (llvmpipe), which the view leaves for the CPU
    // path: the GL path is tested by asking for it.
    qputenv("AWB_GL", "1");
    if (!SurfaceView::glAvailable()) {
        if (required)
            QTest::qFail("no OpenGL context on the Xvfb display", __FILE__, __LINE__);
        else
            QTest::qSkip("no OpenGL context on this display", __FILE__, __LINE__);
        return false;
    }
    return true;
}

void TestSurfaceViewGl::glPathUnderXvfb()
{
    if (!glTestCanRun())
        return;
    auto item = loopItem(8);
    SurfaceView view;
    QCOMPARE(view.path(), SurfaceView::Path::OpenGL);
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    // The full mesh has more primitives than the coarse one drawn while rotating: depth 7
    // (280 000 triangles) against depth 5 in the normal build, depth 6 against 5 in an
    // instrumented one, whose depth-7 mesh alone takes minutes.
    const std::size_t large = awb::test::ms(1) > 1 ? 60'000 : 400'000;
    for (const std::size_t budget : {std::size_t(10'000), large}) {
        QSignalSpy ready(&view, &SurfaceView::frameReady);
        view.setDetailBudget(budget, 10'000);
        feed(view, *item);
        view.resetCamera();
        QTRY_VERIFY_WITH_TIMEOUT(view.isFullDetail() && !view.isRendering(),
                                 awb::test::ms(60000));
        QTest::qWait(300);
        // Frame times: rotating (the coarse mesh) and at rest (the full one).
        QList<double> moving, still;
        int frames = 0;
        double last = 0;
        const auto c = connect(&view, &SurfaceView::frameDrawn, this,
                               [&](double ms) { ++frames; last = ms; });
        for (int k = 0; k < 12; ++k) {
            const int before = frames;
            view.orbit(5, 1);
            QTRY_VERIFY_WITH_TIMEOUT(frames > before, awb::test::ms(5000));
            moving << last;
        }
        QTest::qWait(400); // settles: full detail
        for (int k = 0; k < 5; ++k) {
            const int before = frames;
            view.requestGlFrame();
            QTRY_VERIFY_WITH_TIMEOUT(frames > before, awb::test::ms(5000));
            still << last;
        }
        disconnect(c);
        std::sort(moving.begin(), moving.end());
        std::sort(still.begin(), still.end());
        qInfo("GL llvmpipe %zu primitives (depth %d): rotating median %.1f ms, still median "
              "%.1f ms, mesh built in %.2f s",
              view.mesh().size(), view.mesh().depth, moving[moving.size() / 2],
              still[still.size() / 2], view.meshSeconds());
        QCOMPARE(view.lastFramePrimitives(), view.mesh().size());
    }
    // The GL frame is the CPU figure within a tolerance (the same primitives and colours;
    // lit by their own normals in GL, by the depth buffer's on the CPU).
    view.setLayerVisible(SurfaceView::Layer::ControlNet, false);
    view.setLayerVisible(SurfaceView::Layer::Axes, false);
    QTest::qWait(300);
    const QImage frame = view.grabGlFrame();
    QVERIFY(!frame.isNull());
    const QImage cpu = view.renderImage(frame.size(), false);
    const ImageDiff d = compare(cpu, frame);
    QVERIFY2(d.coverageMismatch < 0.15,
             qPrintable(QStringLiteral("coverage %1").arg(d.coverageMismatch)));
}

void TestSurfaceViewGl::glDragUnderXvfb()
{
    if (!glTestCanRun())
        return;
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.resize(1400, 900);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.project()->addItem(loopItem(8));
    auto *item = qobject_cast<SubdivisionSurfaceItem *>(w.currentItem());
    SurfaceView *view = w.surfaceView();
    QCOMPARE(view->path(), SurfaceView::Path::OpenGL);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isRendering() && view->isFullDetail(), awb::test::ms(60000));
    QTest::qWait(300);
    QElapsedTimer refresh;
    refresh.start();
    for (int k = 0; k < 5; ++k)
        w.controller()->refreshNow();
    qInfo("ItemController::refreshNow of the surface item (docks included): %.0f ms",
          double(refresh.nsecsElapsed()) / 5e6);
    // `shown`: the number of clouds made when the last frame was drawn.
    int clouds = 0, shown = 0;
    QElapsedTimer timer;
    double shownAt = 0;
    connect(view, &SurfaceView::frameReady, this, [&] { ++clouds; });
    connect(view, &SurfaceView::frameDrawn, this, [&] {
        if (shown != clouds)
            shownAt = double(timer.nsecsElapsed()) / 1e6;
        shown = clouds;
    });
    const int steps = w.project()->undoStack()->count();
    const Point original = item->controlPoints(0)[9];
    const QPoint grab = view->controlPointScreen(9).toPoint();
    QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, grab);
    refresh.start();
    for (int k = 0; k < 5; ++k)
        w.controller()->refreshNow();
    qInfo("... during a drag (the 3D view only): %.0f ms", double(refresh.nsecsElapsed()) / 5e6);
    // Time from a mouse move to the frame showing the surface it made: edit, derived IFS,
    // the decimated cloud on the worker, upload and draw.
    QList<double> latency;
    for (int k = 1; k <= 8; ++k) {
        const int c0 = clouds;
        timer.start();
        QTest::mouseMove(view, grab + QPoint(0, -5 * k));
        QTRY_VERIFY_WITH_TIMEOUT(shown > c0, awb::test::ms(10000));
        latency << shownAt;
        qInfo("  move %d: frame at %.0f ms (cloud %.0f ms on the worker, draw %.0f ms)", k,
              shownAt, 1000 * view->meshSeconds(), view->lastFrameMs());
    }
    const std::size_t dragPrimitives = view->lastFramePrimitives();
    QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, grab + QPoint(0, -40));
    QCOMPARE(w.project()->undoStack()->count(), steps + 1);
    QVERIFY(item->controlPoints(0)[9].z > original.z);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isRendering() && view->isFullDetail()
                                 && view->mesh().size() > dragPrimitives,
                             awb::test::ms(60000));
    std::sort(latency.begin(), latency.end());
    qInfo("GL llvmpipe drag: move -> new frame median %.0f ms, max %.0f ms (%zu primitives while "
          "dragging, %zu after release)", latency[latency.size() / 2], latency.last(),
          dragPrimitives, view->mesh().size());
    w.project()->undoStack()->undo();
    QCOMPARE(item->controlPoints(0)[9], original);
}

AWB_TEST_MAIN(TestSurfaceViewGl)
#include "test_surface_view_gl.moc"
