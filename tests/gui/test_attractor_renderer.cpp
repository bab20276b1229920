// The off-GUI-thread attractor renderer: a cubic B-spline attractor (000 Fig. 2) drawn
// progressively, cancellation by a newer request or by cancel(), pixel-identical output for
// equal requests,
// and a clear message for an IFS without an attractor.

#include "gui/views/AttractorRenderer.h"

#include "core/analysis/Geometry.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QtTest>

#include "TestMain.h"

#include "TestTime.h"

using namespace awb;

namespace {

// 000 Fig. 2: a cubic B-spline on five control points.
Mat fig2()
{
    Mat P(5, 2);
    P << 0, 0, 1, 2, 3, 2.5, 4.5, 1, 6, 2;
    return P;
}

RenderRequest cubicRequest(int depth)
{
    const SubdivisionIfs s = buildSubdivisionIfs(bsplineScheme(3), fig2());
    RenderRequest r;
    r.ifs = std::make_shared<const Ifs>(s.ifs);
    Mat x0(1, 2);
    x0 << 7, -3;
    r.start = StartSet::points(s.toIfsSpace(x0));
    r.depth = depth;
    r.world = QRectF(-0.5, -0.5, 7.0, 3.5);
    r.size = QSize(280, 140);
    return r;
}

int litPixels(const QImage &img)
{
    int n = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            n += qAlpha(img.pixel(x, y)) > 0;
    return n;
}

// Waits for the final image; returns every info received on the way.
QList<RenderInfo> waitFinal(QSignalSpy &spy, int timeoutMs = 60000)
{
    QElapsedTimer t;
    t.start();
    for (;;) {
        if (!spy.isEmpty() && spy.last().at(1).value<RenderInfo>().final)
            break;
        if (t.elapsed() > timeoutMs || !spy.wait(timeoutMs - int(t.elapsed())))
            break;
    }
    QList<RenderInfo> out;
    for (const auto &args : spy)
        out << args.at(1).value<RenderInfo>();
    return out;
}

} // namespace

class TestAttractorRenderer : public QObject {
    Q_OBJECT
private slots:
    void cubicBSplineIsDrawnOnTheCurve();
    void coarseLevelComesFirst();
    void newerRequestCancelsTheRunningOne();
    void newerRequestBeforeAnyResult();
    void cancelStopsTheRunningRender();
    void equalRequestsGiveIdenticalPixels();
    void colourModes();
    void dotRadiusGrowsTheCurve();
    void nonContractiveIfsFails();
    void badStartSetFails();
    void costModelFitsTheLatestPasses();
    void interactivePassFitsTheBudget();
    void interactivePassIsNotCancelled();
    void refineSkipsTheCoarseLevel();
};

void TestAttractorRenderer::cubicBSplineIsDrawnOnTheCurve()
{
    AttractorRenderer renderer;
    QSignalSpy ready(&renderer, &AttractorRenderer::imageReady);
    QSignalSpy failed(&renderer, &AttractorRenderer::failed);
    QSignalSpy progress(&renderer, &AttractorRenderer::progress);
    const RenderRequest r = cubicRequest(12);
    renderer.request(r);
    const QList<RenderInfo> infos = waitFinal(ready);
    QVERIFY(failed.isEmpty());
    QVERIFY(!infos.isEmpty() && infos.last().final);
    const QImage img = ready.last().at(0).value<QImage>();
    QCOMPARE(img.size(), r.size);
    QCOMPARE(infos.last().depth, 12);
    QCOMPARE(infos.last().images, 4096.0);
    const int lit = litPixels(img);
    QVERIFY2(lit > 150, qPrintable(QString::number(lit)));
    QCOMPARE(std::uint64_t(lit), infos.last().litPixels);
    QVERIFY(!progress.isEmpty());
    QCOMPARE(progress.last().at(0).toDouble(), 1.0);
    QVERIFY(!renderer.isBusy());

    // Every lit pixel lies on the exact cubic B-spline (within a pixel and a half).
    const Mat exact = *bsplineScheme(3).exactCurve(fig2(), 20000);
    const double px = r.world.width() / r.size.width();
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            if (qAlpha(img.pixel(x, y)) == 0)
                continue;
            Mat c(1, 2);
            c << r.world.left() + (x + 0.5) * px, r.world.bottom() - (y + 0.5) * px;
            const double d = distanceToPolyline(c, exact);
            QVERIFY2(d < 1.5 * px, qPrintable(QStringLiteral("pixel %1,%2 is %3 away")
                                                  .arg(x).arg(y).arg(d)));
        }
}

void TestAttractorRenderer::coarseLevelComesFirst()
{
    AttractorRenderer renderer;
    QSignalSpy ready(&renderer, &AttractorRenderer::imageReady);
    renderer.request(cubicRequest(17));
    const QList<RenderInfo> infos = waitFinal(ready);
    QCOMPARE(infos.size(), 2);
    // 2^14 = 16384 images <= 30000 < 2^15.
    QCOMPARE(infos[0].depth, 14);
    QVERIFY(!infos[0].final);
    QCOMPARE(infos[1].depth, 17);
    QVERIFY(infos[1].final);
}

void TestAttractorRenderer::newerRequestCancelsTheRunningOne()
{
    AttractorRenderer renderer;
    QSignalSpy ready(&renderer, &AttractorRenderer::imageReady);
    // 2^27 images take many seconds: far longer than the whole test may wait below.
    RenderRequest slow = cubicRequest(27);
    renderer.request(slow);
    QVERIFY(ready.wait(awb::test::ms(20000))); // the coarse preview: the full pass is now running
    QCOMPARE(ready.size(), 1);
    QVERIFY(!ready.first().at(1).value<RenderInfo>().final);
    QVERIFY(renderer.isBusy());

    QElapsedTimer t;
    t.start();
    RenderRequest quick = cubicRequest(9);
    quick.world = QRectF(0, 0, 6, 3);
    renderer.request(quick);
    ready.clear();
    const QList<RenderInfo> infos = waitFinal(ready, awb::test::ms(20000));
    QVERIFY(!infos.isEmpty());
    for (const RenderInfo &info : infos) {
        QCOMPARE(info.world, quick.world); // nothing more of the slow request
        QCOMPARE(info.depth, 9);
    }
    QVERIFY(infos.last().final);
    QVERIFY2(t.elapsed() < 8000, qPrintable(QString::number(t.elapsed())));
    QVERIFY(!renderer.isBusy());
    // Nothing of the cancelled request arrives later either.
    QTest::qWait(200);
    QCOMPARE(ready.size(), infos.size());
}

void TestAttractorRenderer::cancelStopsTheRunningRender()
{
    AttractorRenderer renderer;
    QSignalSpy ready(&renderer, &AttractorRenderer::imageReady);
    QSignalSpy progress(&renderer, &AttractorRenderer::progress);
    QSignalSpy busy(&renderer, &AttractorRenderer::busyChanged);
    QSignalSpy failed(&renderer, &AttractorRenderer::failed);
    renderer.request(cubicRequest(27)); // many seconds: only the cancel ends it in time
    QVERIFY(ready.wait(awb::test::ms(20000)));         // the coarse preview: the full pass is now running
    QVERIFY(renderer.isBusy());
    ready.clear();
    progress.clear();
    busy.clear();

    renderer.cancel();
    QVERIFY(!renderer.isBusy());
    QCOMPARE(busy.size(), 1);
    QCOMPARE(busy.first().at(0).toBool(), false);
    // Nothing of the cancelled request arrives later.
    QTest::qWait(500);
    QVERIFY(ready.isEmpty());
    QVERIFY(progress.isEmpty());
    QVERIFY(failed.isEmpty());
    QCOMPARE(busy.size(), 1);

    // Cancelled before any result: nothing at all arrives (not even what the worker had
    // already posted when the cancel came).
    renderer.request(cubicRequest(27));
    renderer.cancel();
    QVERIFY(!renderer.isBusy());
    QCOMPARE(busy.size(), 3); // + on, off
    QTest::qWait(500);
    QVERIFY(ready.isEmpty());
    QVERIFY(progress.isEmpty());
    QCOMPARE(busy.size(), 3);
    busy.clear();
    // Cancelling with nothing running changes nothing.
    renderer.cancel();
    QVERIFY(busy.isEmpty());

    // The worker is free again: the next request is drawn to the end, and soon.
    QElapsedTimer t;
    t.start();
    RenderRequest quick = cubicRequest(9);
    quick.world = QRectF(0, 0, 6, 3);
    renderer.request(quick);
    QVERIFY(renderer.isBusy());
    const QList<RenderInfo> infos = waitFinal(ready, awb::test::ms(20000));
    QVERIFY(!infos.isEmpty());
    for (const RenderInfo &info : infos)
        QCOMPARE(info.world, quick.world);
    QVERIFY(infos.last().final);
    QCOMPARE(infos.last().depth, 9);
    QVERIFY2(t.elapsed() < 8000, qPrintable(QString::number(t.elapsed())));
    QVERIFY(!renderer.isBusy());
}

void TestAttractorRenderer::newerRequestBeforeAnyResult()
{
    AttractorRenderer renderer;
    QSignalSpy ready(&renderer, &AttractorRenderer::imageReady);
    renderer.request(cubicRequest(27));
    renderer.request(cubicRequest(27));
    RenderRequest last = cubicRequest(8);
    renderer.request(last);
    const QList<RenderInfo> infos = waitFinal(ready, awb::test::ms(20000));
    QVERIFY(!infos.isEmpty());
    // The newest request's picture, in one pass (depth 8 needs no coarse pass). A superseded
    // request may still show a coarse pass it had finished before the newer ones came (on a
    // loaded machine, e.g. ThreadSanitizer beside another suite), never its final picture.
    QCOMPARE(infos.last().depth, 8);
    QVERIFY(infos.last().final);
    for (qsizetype i = 0; i + 1 < infos.size(); ++i) {
        QVERIFY(!infos[i].final);
        QVERIFY(infos[i].depth != 8);
    }
}

void TestAttractorRenderer::equalRequestsGiveIdenticalPixels()
{
    for (auto mode : {RenderRequest::Mode::Deterministic, RenderRequest::Mode::Random}) {
        RenderRequest r = cubicRequest(13);
        r.mode = mode;
        r.samples = 60000;
        r.seed = 7;
        r.colouring.mode = AttractorColorMode::ByAddress;
        r.colouring.prefixLength = 3;
        QImage images[2];
        for (QImage &img : images) {
            AttractorRenderer renderer;
            QSignalSpy ready(&renderer, &AttractorRenderer::imageReady);
            renderer.request(r);
            const QList<RenderInfo> infos = waitFinal(ready);
            QVERIFY(!infos.isEmpty() && infos.last().final);
            img = ready.last().at(0).value<QImage>();
        }
        QVERIFY(litPixels(images[0]) > 100);
        QVERIFY(images[0] == images[1]);
        // The synchronous path draws the same pixels.
        QVERIFY(AttractorRenderer::renderNow(r) == images[0]);
    }
}

void TestAttractorRenderer::colourModes()
{
    RenderRequest r = cubicRequest(11);
    r.colouring.mode = AttractorColorMode::ByMap;
    const QImage byMap = AttractorRenderer::renderNow(r);
    QSet<QRgb> colours;
    for (int y = 0; y < byMap.height(); ++y)
        for (int x = 0; x < byMap.width(); ++x)
            if (qAlpha(byMap.pixel(x, y)))
                colours.insert(byMap.pixel(x, y));
    // Two maps, two colours: the default palette's first two.
    QCOMPARE(colours.size(), 2);
    QVERIFY(colours.contains(AttractorRenderer::mapColor(0).rgba()));
    QVERIFY(colours.contains(AttractorRenderer::mapColor(1).rgba()));

    r.colouring.mode = AttractorColorMode::Single;
    r.colouring.palette = {QColor(10, 20, 30)};
    const QImage single = AttractorRenderer::renderNow(r);
    for (int y = 0; y < single.height(); ++y)
        for (int x = 0; x < single.width(); ++x)
            if (qAlpha(single.pixel(x, y)))
                QCOMPARE(single.pixel(x, y), QColor(10, 20, 30).rgba());

    r.colouring.mode = AttractorColorMode::ByAddress;
    r.colouring.prefixLength = 3;
    r.colouring.palette.clear();
    const QImage byAddress = AttractorRenderer::renderNow(r);
    colours.clear();
    for (int y = 0; y < byAddress.height(); ++y)
        for (int x = 0; x < byAddress.width(); ++x)
            if (qAlpha(byAddress.pixel(x, y)))
                colours.insert(byAddress.pixel(x, y));
    QCOMPARE(colours.size(), 8); // 2^3 address prefixes
}

void TestAttractorRenderer::dotRadiusGrowsTheCurve()
{
    RenderRequest r = cubicRequest(12);
    const QImage thin = AttractorRenderer::renderNow(r);
    r.dotRadius = 2;
    RenderInfo info;
    const QImage thick = AttractorRenderer::renderNow(r, &info);
    QVERIFY(litPixels(thick) > 2 * litPixels(thin));
    QCOMPARE(std::uint64_t(litPixels(thin)), info.litPixels);
    // Every pixel of the thin curve is still there with its colour (smallest label wins).
    for (int y = 0; y < thin.height(); ++y)
        for (int x = 0; x < thin.width(); ++x)
            if (qAlpha(thin.pixel(x, y)))
                QVERIFY(qAlpha(thick.pixel(x, y)));
    // And nothing is further than the radius from a thin pixel.
    for (int y = 0; y < thick.height(); ++y)
        for (int x = 0; x < thick.width(); ++x) {
            if (!qAlpha(thick.pixel(x, y)))
                continue;
            bool near = false;
            for (int dy = -2; dy <= 2 && !near; ++dy)
                for (int dx = -2; dx <= 2 && !near; ++dx)
                    near = thin.valid(x + dx, y + dy) && qAlpha(thin.pixel(x + dx, y + dy));
            QVERIFY(near);
        }
}

void TestAttractorRenderer::nonContractiveIfsFails()
{
    auto ifs = std::make_shared<Ifs>();
    ifs->maps.push_back({Mat::Identity(2, 2) * 0.5, RowVec::Zero(2)});
    ifs->maps.push_back({Mat::Identity(2, 2) * 1.5, RowVec::Ones(2)});
    ifs->views.push_back({Mat::Identity(2, 2), RowVec::Zero(2)});
    RenderRequest r;
    r.ifs = ifs;
    r.start = StartSet::points(Mat::Zero(1, 2));
    r.depth = 10;
    r.world = QRectF(-1, -1, 2, 2);
    r.size = QSize(50, 50);
    AttractorRenderer renderer;
    QSignalSpy ready(&renderer, &AttractorRenderer::imageReady);
    QSignalSpy failed(&renderer, &AttractorRenderer::failed);
    renderer.request(r);
    QVERIFY(failed.wait(awb::test::ms(10000)));
    QCOMPARE(failed.size(), 1);
    const QString message = failed.first().at(0).toString();
    QVERIFY2(message.contains(QLatin1String("map 2 is not contractive")), qPrintable(message));
    QVERIFY(ready.isEmpty());
    QVERIFY(!renderer.isBusy());
    QVERIFY_THROWS_EXCEPTION(InputError, AttractorRenderer::renderNow(r));
}

void TestAttractorRenderer::badStartSetFails()
{
    RenderRequest r = cubicRequest(5);
    r.start = StartSet::points(Mat::Zero(1, 3)); // the lifted space has 4 coordinates
    AttractorRenderer renderer;
    QSignalSpy failed(&renderer, &AttractorRenderer::failed);
    renderer.request(r);
    QVERIFY(failed.wait(awb::test::ms(10000)));
    QVERIFY2(failed.first().at(0).toString().contains(QLatin1String("coordinates")),
             qPrintable(failed.first().at(0).toString()));
}

void TestAttractorRenderer::costModelFitsTheLatestPasses()
{
    PassCostModel model;
    const QSize size(800, 600);
    QCOMPARE(model.predict(1000, size), -1.0); // nothing measured
    QCOMPARE(model.workWithin(12, size), -1.0);
    // ms = 2 + 0.001 work, exactly: the fit finds the line.
    for (double work : {1000.0, 4000.0, 10000.0})
        model.add(work, 2 + 0.001 * work, size);
    QVERIFY(std::abs(model.predict(6000, size) - 8.0) < 1e-9);
    QVERIFY(std::abs(model.workWithin(12, size) - 10000.0) < 1e-6);
    QCOMPARE(model.workWithin(1, size), 0.0); // the fixed part alone is over the budget
    // Another picture size: what was measured says nothing about it.
    QCOMPARE(model.predict(6000, QSize(100, 100)), -1.0);
    // One kind of pass only: proportional, through the origin.
    PassCostModel one;
    one.add(5000, 10, size);
    one.add(5000, 10, size);
    QVERIFY(std::abs(one.predict(2500, size) - 5.0) < 1e-9);
    // Garbage is ignored.
    one.add(0, 3, size);
    one.add(100, qQNaN(), size);
    QVERIFY(std::abs(one.predict(2500, size) - 5.0) < 1e-9);
}

void TestAttractorRenderer::interactivePassFitsTheBudget()
{
    AttractorRenderer renderer;
    QSignalSpy ready(&renderer, &AttractorRenderer::imageReady);
    QSignalSpy busy(&renderer, &AttractorRenderer::busyChanged);
    RenderRequest r = cubicRequest(27); // minutes at full depth
    // Nothing measured yet: the coarse pass's size, 30 000 images (2^14 < 30 000 < 2^15).
    QCOMPARE(renderer.interactiveDepth(r), 14);
    renderer.request(r, AttractorRenderer::Quality::Interactive, 7);
    QVERIFY(ready.wait(awb::test::ms(20000)));
    const RenderInfo info = ready.last().at(1).value<RenderInfo>();
    QVERIFY(info.interactive);
    QCOMPARE(info.tag, std::uint64_t(7));
    QCOMPARE(info.depth, 14);
    QVERIFY(!info.final);
    // A frame is not a job: no progress bar, no "busy".
    QVERIFY(busy.isEmpty());
    QVERIFY(!renderer.isBusy());
    // Measured now: a generous budget allows more, a tiny one the minimum (2000 images).
    renderer.setFrameBudget(1e6);
    QVERIFY(renderer.interactiveDepth(r) > 14);
    renderer.setFrameBudget(1e-6);
    QCOMPARE(renderer.interactiveDepth(r), 10); // 2^10 < 2000 < 2^11
    // A request that fits whole is its own final picture.
    renderer.setFrameBudget(1e6);
    renderer.request(cubicRequest(9), AttractorRenderer::Quality::Interactive, 8);
    QVERIFY(ready.wait(awb::test::ms(20000)));
    QVERIFY(ready.last().at(1).value<RenderInfo>().final);
    QCOMPARE(ready.last().at(1).value<RenderInfo>().depth, 9);
    // Random iteration: a sample count, at most the request's.
    RenderRequest random = cubicRequest(9);
    random.mode = RenderRequest::Mode::Random;
    random.samples = 500;
    QCOMPARE(renderer.interactiveSamples(random), std::uint64_t(500));
}

void TestAttractorRenderer::interactivePassIsNotCancelled()
{
    AttractorRenderer renderer;
    QSignalSpy ready(&renderer, &AttractorRenderer::imageReady);
    renderer.setFrameBudget(1e6);
    const auto tagged = [&](std::uint64_t tag) {
        for (const auto &args : ready)
            if (args.at(1).value<RenderInfo>().tag == tag)
                return true;
        return false;
    };
    // The first pass is drawing (or already done) when the second request comes: it ends
    // and shows its picture, then the second one's picture follows.
    renderer.request(cubicRequest(18), AttractorRenderer::Quality::Interactive, 1);
    QTRY_VERIFY_WITH_TIMEOUT(renderer.drawingInteractive() || tagged(1), awb::test::ms(10000));
    renderer.request(cubicRequest(12), AttractorRenderer::Quality::Interactive, 2);
    QTRY_VERIFY_WITH_TIMEOUT(tagged(2), awb::test::ms(30000));
    QVERIFY(tagged(1));
    QCOMPARE(ready.first().at(1).value<RenderInfo>().tag, std::uint64_t(1));
    // A Full request is cancelled by the next one: only the newest picture comes.
    ready.clear();
    renderer.request(cubicRequest(27), AttractorRenderer::Quality::Full, 3);
    QTRY_VERIFY_WITH_TIMEOUT(tagged(3), awb::test::ms(20000)); // its coarse level
    renderer.request(cubicRequest(12), AttractorRenderer::Quality::Interactive, 4);
    QTRY_VERIFY_WITH_TIMEOUT(tagged(4), awb::test::ms(20000));
    QTest::qWait(200);
    for (const auto &args : ready) {
        const RenderInfo info = args.at(1).value<RenderInfo>();
        QVERIFY(info.tag == 4 || (info.tag == 3 && !info.final));
    }
    QCOMPARE(ready.last().at(1).value<RenderInfo>().tag, std::uint64_t(4));
}

void TestAttractorRenderer::refineSkipsTheCoarseLevel()
{
    AttractorRenderer renderer;
    QSignalSpy ready(&renderer, &AttractorRenderer::imageReady);
    renderer.request(cubicRequest(17), AttractorRenderer::Quality::Refine, 5);
    QVERIFY(renderer.isBusy());
    const QList<RenderInfo> infos = waitFinal(ready);
    QCOMPARE(infos.size(), 1); // no coarse picture first: an interactive one is shown
    QCOMPARE(infos.first().depth, 17);
    QCOMPARE(infos.first().tag, std::uint64_t(5));
    QVERIFY(!infos.first().interactive);
    QTRY_VERIFY(!renderer.isBusy());
}

AWB_TEST_MAIN(TestAttractorRenderer)
#include "test_attractor_renderer.moc"
