// The raster engine (core/render/Engine.h, Density.h): the fixed-dimension kernels agree with
// the sink-based iteration drawn by the same rasteriser, pictures do not depend on the number
// of threads, the density histogram is the invariant measure (unequal probabilities give the
// pieces their masses), the tone mapping is
// monotone, supersampling anti-aliases, and bad input is refused with a message. How the
// histogram stores its counts: test_engine_storage.cpp.

#include "core/ifs/Random.h"
#include "core/render/Engine.h"
#include "core/schemes/ControlPointFractal.h"
#include "core/schemes/Scheme.h"

#include <QtTest>

#include "EngineTests.h"
#include "TestMain.h"
#include "TestTime.h"

#include <cmath>
#include <cstdlib>
#include <random>
#include <stdexcept>

using namespace awb;

using namespace awb::test;

class TestEngine : public QObject {
    Q_OBJECT
private slots:
    void kernelsAgreeWithTheSinkPath();
    void threadsDoNotChangeThePicture();
    void randomIterationMatchesTheSinkStreams();
    void densityIsTheInvariantMeasure();
    void aliasTableDrawsTheProbabilities();
    void polygonsAndSegmentsAreRasterised();
    void toneMappingIsMonotone();
    void supersamplingAntiAliases();
    void largeDimensionsUseTheSinkPath();
    void badInputIsRefused();
    void smallImagesMatchTheRasteriser();
    void vectorKernelsMatchTheBaseline();
    void dilateMatchesItsDefinition();
};

void TestEngine::kernelsAgreeWithTheSinkPath()
{
    AWB_SKIP_WITHOUT_THREADS();
    // 000 Fig. 2: the cubic B-spline on five points, lifted dimension 4, depth 11.
    const auto s = buildSubdivisionIfs(bsplineScheme(3),
                                       pts({{0, 0}, {1, 2}, {3, 2.5}, {4.5, 1}, {6, 2}}));
    const StartSet start = StartSet::points(s.toIfsSpace(pts({{7, -3}})));
    for (Accumulation mode : {Accumulation::Hits, Accumulation::Density}) {
        EngineJob j = job(s.ifs, start, 300, -0.5, -1.5, 6.5, 3.5);
        j.depth = 11;
        j.accumulation = mode;
        DensityImage fast;
        const IterationStats st = accumulate(j, fast);
        QCOMPARE(st.images, std::uint64_t(1) << 11);
        DensitySink sink(j.frame, s.ifs.views, mode, j.colours, s.ifs.size());
        iterate(s.ifs, start, 11, sink);
        // The fused last step (x A_i V) rounds differently from (x A_i) V: a point exactly on a
        // cell border may change cell, nothing more.
        QVERIFY2(litMismatch(fast, sink.image()) < 0.002,
                 qPrintable(QString::number(litMismatch(fast, sink.image()))));
        std::uint64_t total = 0;
        for (std::size_t i = 0; i < fast.size(); ++i)
            total += fast.count(i);
        QCOMPARE(total + fast.offscreen, std::uint64_t(1) << 11);
    }
}

void TestEngine::threadsDoNotChangeThePicture()
{
    const SubdivisionIfs sier = controlPointFractalIfs(sierpinskiControlPointFractal());
    const StartSet tri = StartSet::polygon(sier.toIfsSpace(pts({{0, 0}, {1, 0}, {0.5, 0.866}})));
    for (bool random : {false, true})
        for (Accumulation mode : {Accumulation::Hits, Accumulation::Density}) {
            EngineJob j = job(sier.ifs, tri, 257, -0.1, -0.1, 1.1, 1.1);
            j.random = random;
            j.depth = 11;         // 3^11 triangles: enough work for several threads
            j.samples = 300001;  // not a multiple of the streams
            j.accumulation = mode;
            DensityImage one, two, three;
            j.threads = 1;
            accumulate(j, one);
            j.threads = 2;
            accumulate(j, two);
            j.threads = 3;
            accumulate(j, three);
            QVERIFY(one.litCells() > 1000);
            QVERIFY(sameBuckets(one, two));
            QVERIFY(sameBuckets(one, three));
        }
}

void TestEngine::randomIterationMatchesTheSinkStreams()
{
    AWB_SKIP_WITHOUT_THREADS();
    const Ifs ifs = sierpinski({0.5, 0.3, 0.2});
    RowVec x0(2);
    x0 << 0.3, 0.3;
    EngineJob j = job(ifs, StartSet::points(Mat(x0)), 200, 0, 0, 1, 1);
    j.random = true;
    j.samples = 200000;
    j.accumulation = Accumulation::Hits;
    DensityImage fast;
    QCOMPARE(accumulate(j, fast).images, std::uint64_t(200000));
    DensitySink sink(j.frame, ifs.views, Accumulation::Hits, j.colours, ifs.size());
    ChaosOptions opt;
    opt.samples = 200000;
    opt.seed = j.seed;
    chaosGame(ifs, x0, opt, sink);
    // The same xoshiro streams and alias table: the same orbits (up to rounding, which the
    // contraction damps), so the same cells with the same counts.
    QVERIFY(litMismatch(fast, sink.image()) < 0.001);
    std::size_t sameCount = 0, lit = 0;
    for (std::size_t i = 0; i < fast.size(); ++i)
        if (fast.count(i)) {
            ++lit;
            sameCount += fast.count(i) == sink.image().count(i);
        }
    QVERIFY(double(sameCount) / double(lit) > 0.99);
}

void TestEngine::densityIsTheInvariantMeasure()
{
    // Probabilities (0.6, 0.25, 0.15): the invariant measure gives the piece f_i(A) the mass p_i
    // (the pieces of the gasket meet in single points), and a point lies in f_i(A) exactly when
    // map i was applied last. Cells of side 1/512 with the lines x = 1/2 and y = 1/2 on cell
    // borders sort the hits into the pieces exactly: top y > 1/2, lower left x < 1/2, lower
    // right x > 1/2 (no iterate lies on those lines).
    const Ifs ifs = sierpinski({0.6, 0.25, 0.15});
    RowVec x0(2);
    x0 << 0.3, 0.3;
    const double m = 4.0 / 512;
    EngineJob j = job(ifs, StartSet::points(Mat(x0)), 520, -m, -m, 1 + m, 1 + m);
    j.random = true;
    j.samples = 4'000'000;
    j.accumulation = Accumulation::Density;
    j.threads = 2;
    DensityImage img;
    accumulate(j, img);
    double mass[3] = {0, 0, 0}, total = 0;
    for (int y = 0; y < 520; ++y)
        for (int x = 0; x < 520; ++x) {
            const double n = double(img.count(std::size_t(y) * 520 + x));
            total += n;
            mass[y < 260 ? 2 : (x >= 260 ? 1 : 0)] += n;
        }
    QCOMPARE(total, 4e6);
    QCOMPARE(img.offscreen, std::uint64_t(0));
    // The count of each piece is binomial (the maps are drawn independently): standard error
    // sqrt(p(1-p)/n) < 2.5e-4; 8 standard errors allowed.
    const QString masses = QString("masses %1 %2 %3")
                               .arg(mass[0] / total)
                               .arg(mass[1] / total)
                               .arg(mass[2] / total);
    QVERIFY2(std::abs(mass[0] / total - 0.60) < 0.002, qPrintable(masses));
    QVERIFY2(std::abs(mass[1] / total - 0.25) < 0.002, qPrintable(masses));
    QVERIFY2(std::abs(mass[2] / total - 0.15) < 0.002, qPrintable(masses));
    // The colour coordinate is the hit-weighted mean of the maps' coordinates (0, 128, 255 for
    // three maps): map 0's in its piece, map 2's in the top piece.
    for (int y = 0; y < 520; ++y)
        for (int x = 0; x < 520; ++x) {
            const auto c = img.cell(std::size_t(y) * 520 + x);
            // Rounding may put a point within 1e-16 of a line into the next cell.
            if (c[0] == 0 || y == 259 || y == 260 || x == 259 || x == 260)
                continue;
            if (y < 260)
                QCOMPARE(c[1] / c[0], 255.0);
            else if (x < 260)
                QCOMPARE(c[1] / c[0], 0.0);
            else
                QCOMPARE(c[1] / c[0], 128.0);
        }
}

void TestEngine::aliasTableDrawsTheProbabilities()
{
    AWB_SKIP_WITHOUT_THREADS();
    const std::vector<double> p = {0.1, 0.0, 0.45, 0.3, 0.15};
    const AliasTable table(p, 5);
    Xoshiro256 rng(42, 0);
    std::vector<double> n(5, 0);
    const int draws = 2'000'000;
    for (int k = 0; k < draws; ++k)
        n[table.pick(rng.next())] += 1;
    for (int i = 0; i < 5; ++i)
        QVERIFY2(std::abs(n[i] / draws - p[i]) < 0.002, qPrintable(QString::number(i)));
    QCOMPARE(n[1], 0.0);  // probability 0: never
    QVERIFY_THROWS_EXCEPTION(InputError, AliasTable({1, -1}, 2));
    QVERIFY_THROWS_EXCEPTION(InputError, AliasTable({0, 0}, 2));
    QVERIFY_THROWS_EXCEPTION(InputError, AliasTable({1, 2}, 3));
}

void TestEngine::polygonsAndSegmentsAreRasterised()
{
    AWB_SKIP_WITHOUT_THREADS();
    // Depth 0 of a big triangle fills it; a segment draws its cells once each.
    const Ifs ifs = sierpinski();
    EngineJob j = job(ifs, StartSet::polygon(pts({{0, 0}, {1, 0}, {0, 1}})), 100, 0, 0, 1, 1);
    j.depth = 0;
    DensityImage img;
    accumulate(j, img);
    // About half the square (the cells whose centres lie in the triangle, and its outline).
    QVERIFY(img.litCells() > 4900 && img.litCells() < 5300);
    j.start = StartSet::polyline(pts({{0.005, 0.5}, {0.995, 0.5}}));
    accumulate(j, img);
    QCOMPARE(img.litCells(), std::uint64_t(100));
    // Deep levels: each tiny triangle image is one hit; 3^7 of them.
    j.start = StartSet::polygon(pts({{0, 0}, {1, 0}, {0.5, 1}}));
    j.depth = 7;
    accumulate(j, img);
    std::uint64_t total = 0;
    for (std::size_t i = 0; i < img.size(); ++i)
        total += img.count(i);
    QVERIFY(total >= 2187);  // at least one per image; larger images cover several cells
}

void TestEngine::toneMappingIsMonotone()
{
    AWB_SKIP_WITHOUT_THREADS();
    DensityImage img(4, 1, Accumulation::Density);
    for (int k = 0; k < 1; ++k)
        img.addDensity(0, 0);
    for (int k = 0; k < 10; ++k)
        img.addDensity(1, 0);
    for (int k = 0; k < 1000; ++k)
        img.addDensity(2, 0);
    RasterFrame f;
    f.width = 4, f.height = 1;
    ToneSettings tone;
    tone.mode = Accumulation::Density;
    const auto px = toneMap(img, f, tone, {Rgb8{255, 0, 0}});
    const int a0 = int(px[0] >> 24), a1 = int(px[1] >> 24), a2 = int(px[2] >> 24);
    QVERIFY(a0 > 0 && a0 < a1 && a1 < a2);
    QCOMPARE(a2, 255);            // the densest pixel is opaque
    QCOMPARE(px[3], 0u);          // unlit stays transparent
    QCOMPARE(int((px[2] >> 16) & 255), 255);  // red, premultiplied by alpha 1
    QCOMPARE(int(px[2] & 0xFFFF), 0);
    // Hits: every lit pixel opaque whatever its count.
    tone.mode = Accumulation::Hits;
    const auto hits = toneMap(img, f, tone, {Rgb8{255, 0, 0}});
    QCOMPARE(int(hits[0] >> 24), 255);
    QCOMPARE(int(hits[2] >> 24), 255);
}

void TestEngine::supersamplingAntiAliases()
{
    AWB_SKIP_WITHOUT_THREADS();
    // A horizontal segment through the middle of a pixel row, 3x3 cells per pixel: the lit
    // pixels are partly covered (alpha 1/3), not opaque.
    const Ifs ifs = sierpinski();
    EngineJob j = job(ifs, StartSet::polyline(pts({{0.01, 0.55}, {0.99, 0.55}})), 10, 0, 0, 1, 1);
    j.frame.supersample = 3;
    j.depth = 0;
    DensityImage img;
    accumulate(j, img);
    ToneSettings tone;
    const auto px = toneMap(img, j.frame, tone, j.colours.labelColours);
    int partial = 0;
    for (std::uint32_t p : px)
        partial += (p >> 24) > 0 && (p >> 24) < 255;
    QCOMPARE(partial, 10);
    QCOMPARE(int(px[4 * 10 + 5] >> 24), 85);  // one row of three cells: 255 / 3
}

void TestEngine::largeDimensionsUseTheSinkPath()
{
    AWB_SKIP_WITHOUT_THREADS();
    // 16 control points of a cubic B-spline: lifted dimension 15 > 12, the sink path.
    Mat P(16, 2);
    for (int i = 0; i < 16; ++i)
        P.row(i) << i, std::sin(i);
    const auto s = buildSubdivisionIfs(bsplineScheme(3), P);
    QCOMPARE(s.ifs.dim(), 15);
    const StartSet start = StartSet::points(s.toIfsSpace(pts({{3, 0}})));
    EngineJob j = job(s.ifs, start, 200, -1, -2, 16, 2);
    j.depth = 9;
    j.threads = 2;
    DensityImage img;
    QCOMPARE(accumulate(j, img).images, std::uint64_t(512));
    QVERIFY(img.litCells() > 100);
}

void TestEngine::badInputIsRefused()
{
    AWB_SKIP_WITHOUT_THREADS();
    const Ifs ifs = sierpinski();
    RowVec x0(2);
    x0 << 0.3, 0.3;
    EngineJob j = job(ifs, StartSet::points(Mat(x0)), 100, 0, 0, 1, 1);
    DensityImage img;
    j.frame.supersample = 5;
    QVERIFY_THROWS_EXCEPTION(InputError, accumulate(j, img));
    j.frame.supersample = 1;
    j.frame.x1 = std::nan("");
    QVERIFY_THROWS_EXCEPTION(InputError, accumulate(j, img));
    j.frame.x1 = 1;
    j.depth = 65;
    QVERIFY_THROWS_EXCEPTION(InputError, accumulate(j, img));
    j.depth = 3;
    j.colours.labelColours.resize(2);  // three maps need three colours
    QVERIFY_THROWS_EXCEPTION(InputError, accumulate(j, img));
    j.colours.labelColours.resize(3);
    j.random = true;
    j.samples = kMaxChaosSamples + 1;
    QVERIFY_THROWS_EXCEPTION(InputError, accumulate(j, img));
    j.samples = 1000;
    j.start = StartSet::points(Mat::Constant(1, 2, std::nan("")));
    QVERIFY_THROWS_EXCEPTION(InputError, accumulate(j, img));
    // A cancelled job reports it and stops early.
    j.start = StartSet::points(Mat(x0));
    j.samples = 500'000'000;
    std::atomic<bool> cancel{true};
    IterationControl control;
    control.cancel = &cancel;
    QVERIFY(accumulate(j, img, control).cancelled);
}

void TestEngine::smallImagesMatchTheRasteriser()
{
    AWB_SKIP_WITHOUT_THREADS();
    // The plane Sierpinski gasket with dyadic numbers everywhere (maps, start triangle, frame)
    // computes every vertex exactly on both paths, so the fused kernel's shortcuts for images
    // inside one cell and for small images inside the raster must give exactly the cells of
    // the generic rasteriser fed by the sink iteration. Depth 9: images of half a cell, most
    // over two cells or more; the frame cuts the gasket, so images are clipped too.
    const Ifs ifs = sierpinski();
    for (const auto &start : {StartSet::polygon(pts({{0, 0}, {1, 0}, {0.5, 1}})),
                              StartSet::polyline(pts({{0, 0}, {0.5, 1}, {1, 0}}))})
        for (Accumulation mode : {Accumulation::Hits, Accumulation::Density}) {
            EngineJob j = job(ifs, start, 256, 0.25, -0.125, 0.75, 0.375);
            j.depth = 9;
            j.accumulation = mode;
            DensityImage fast;
            accumulate(j, fast);
            DensitySink sink(j.frame, ifs.views, mode, j.colours, ifs.size());
            iterate(ifs, start, 9, sink);
            QVERIFY(fast.litCells() > 5000);
            QVERIFY(sameBuckets(fast, sink.image()));
            QCOMPARE(fast.offscreen, sink.image().offscreen);
        }
}

void TestEngine::vectorKernelsMatchTheBaseline()
{
    // The AVX2 kernels (where the processor has them) and the baseline ones give the same
    // histogram, bit for bit: points and triangles, lifted dimensions 4 to 6, partly off the
    // raster.
    const auto bspline = buildSubdivisionIfs(bsplineScheme(3),
                                             pts({{0, 0}, {1, 2}, {3, 2.5}, {4.5, 1}, {6, 2}}));
    const SubdivisionIfs sier = controlPointFractalIfs(sierpinskiControlPointFractal());
    struct Case {
        const SubdivisionIfs *s;
        StartSet start;
        double x0, y0, x1, y1;
        int depth;
    };
    const Case cases[] = {
        {&bspline, StartSet::points(bspline.toIfsSpace(pts({{7, -3}}))), -0.5, -1.5, 6.5, 3.5, 12},
        {&bspline, StartSet::points(bspline.toIfsSpace(pts({{7, -3}}))), 2.0, 1.0, 5.0, 3.0, 12},
        {&sier, StartSet::polygon(sier.toIfsSpace(pts({{0, 0}, {1, 0}, {0.5, 0.866}}))), -0.1,
         -0.1, 1.1, 1.1, 9},
        {&sier, StartSet::polygon(sier.toIfsSpace(pts({{0, 0}, {1, 0}, {0.5, 0.866}}))), 0.3,
         0.2, 0.9, 0.7, 10},
    };
    const QByteArray isa = engineKernels();
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    // On a processor with AVX2 the vector kernels run: when the engine was split (6694385),
    // haveAvx2() lost the macro that enables them, and the comparisons below compared the
    // baseline with itself for a week.
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2"))
        QCOMPARE(isa, QByteArray("avx2"));
#endif
    for (const Case &c : cases)
        for (Accumulation mode : {Accumulation::Hits, Accumulation::Density}) {
            EngineJob j = job(c.s->ifs, c.start, 301, c.x0, c.y0, c.x1, c.y1);
            j.depth = c.depth;
            j.accumulation = mode;
            DensityImage native, baseline;
            accumulate(j, native);
            forceBaselineKernels(true);
            QCOMPARE(QByteArray(engineKernels()), QByteArray("baseline"));
            accumulate(j, baseline);
            forceBaselineKernels(false);
            QCOMPARE(QByteArray(engineKernels()), isa);
            QVERIFY2(native.litCells() > 200, qPrintable(QString::number(native.litCells())));
            QVERIFY(sameBuckets(native, baseline));
            QCOMPARE(native.offscreen, baseline.offscreen);
        }
    // Random iteration: the four orbits' map choices drawn in AVX2 lanes, and their geometry
    // advanced in AVX2 lanes (coefficients permuted from tables of up to four maps, or eight
    // with a blend), are the baseline's, whatever the block's parity (samples per stream odd
    // and even, a skip of odd length), on one and two threads, colour by map and by address,
    // and in one colour (counts only): the gasket (3 maps, lifted dimension 2, also with
    // unequal probabilities), a carpet of 8 rotated maps, a grid of 9 (the scalar loop),
    // and the cubic B-spline's IFS (2 maps, dimension 4: full matrices in screen space).
    const Ifs gasket = sierpinski();
    const Ifs unequal = sierpinski({0.5, 0.3, 0.2});
    const Ifs carpet = gridIfs(3, true, 0.1);
    const Ifs nine = gridIfs(3, false, 0.0);
    RowVec z0(2);
    z0 << 0.3, 0.3;
    struct Orbit {
        const Ifs *ifs;
        RowVec x0;
        double x0w, y0w, x1w, y1w;
    };
    const Orbit orbits[] = {
        {&gasket, z0, -0.1, -0.1, 1.1, 1.1},
        {&unequal, z0, -0.1, -0.1, 1.1, 1.1},
        {&carpet, z0, -0.1, -0.1, 1.1, 1.1},
        {&nine, z0, -0.1, -0.1, 1.1, 1.1},
        {&bspline.ifs, bspline.toIfsSpace(pts({{7, -3}})).row(0), -0.5, -1.5, 6.5, 3.5},
    };
    for (const Orbit &orbit : orbits)
        for (std::uint64_t samples : {std::uint64_t(1000003), std::uint64_t(999 * 8 + 5)})
            for (int threads : {1, 2})
                for (int prefix : {1, 2, -1}) {  // -1: prefix 1 in one colour
                    EngineJob j = job(*orbit.ifs, StartSet::points(Mat(orbit.x0)), 128, orbit.x0w,
                                      orbit.y0w, orbit.x1w, orbit.y1w);
                    j.random = true;
                    j.samples = samples;
                    j.skip = 21;
                    j.threads = threads;
                    j.colours.prefix = std::abs(prefix);
                    j.colours.labelColours.clear();
                    for (int l = 0; l < 81; ++l)
                        j.colours.labelColours.push_back(
                            prefix < 0 ? Rgb8{10, 20, 30}
                                       : Rgb8{std::uint8_t(l), std::uint8_t(3 * l), 7});
                    j.accumulation = Accumulation::Density;
                    DensityImage native, baseline;
                    accumulate(j, native);
                    forceBaselineKernels(true);
                    accumulate(j, baseline);
                    forceBaselineKernels(false);
                    QCOMPARE(native.oneLabel(), prefix < 0);
                    const QString what = QStringLiteral("%1 maps, dim %2, samples %3, threads %4, prefix %5")
                                             .arg(orbit.ifs->size()).arg(orbit.ifs->dim())
                                             .arg(samples).arg(threads).arg(prefix);
                    QVERIFY2(native.litCells() > 60, qPrintable(what));  // the B-spline: 95
                    QVERIFY2(sameBuckets(native, baseline), qPrintable(what));
                    QVERIFY2(native.offscreen == baseline.offscreen, qPrintable(what));
                }
    qInfo("vector kernels here: %s", isa.constData());
}

// The dots' growth (dilate): each unlit pixel takes the most opaque pixel of its (2r+1)^2
// window, the first in row-major order on a tie; lit pixels keep their colour. The fast
// version (lit pixels spread, empty rows skipped) must give exactly this.
void TestEngine::dilateMatchesItsDefinition()
{
    AWB_SKIP_WITHOUT_THREADS();
    std::mt19937 random(7);
    for (int r = 1; r <= 4; ++r) {
        for (const double fill : {0.0, 0.002, 0.05, 0.5}) {
            const int w = 67, h = 41;
            std::vector<std::uint32_t> image(std::size_t(w) * h, 0);
            std::uniform_real_distribution<double> u(0, 1);
            for (std::uint32_t &p : image)
                if (u(random) < fill)
                    p = (std::uint32_t(1 + random() % 255) << 24) | (random() & 0xffffffu);
            // A lit pixel in the bottom-left corner.
            image[std::size_t(w) * (h - 1)] = 0xff102030u;
            std::vector<std::uint32_t> expected(image.size());
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const std::uint32_t own = image[std::size_t(y) * w + x];
                    if (own >> 24) {
                        expected[std::size_t(y) * w + x] = own;
                        continue;
                    }
                    // Per row the leftmost most opaque pixel, then the topmost of those.
                    std::uint32_t best = 0;
                    for (int yy = std::max(0, y - r); yy <= std::min(h - 1, y + r); ++yy) {
                        std::uint32_t rowBest = 0;
                        for (int xx = std::max(0, x - r); xx <= std::min(w - 1, x + r); ++xx) {
                            const std::uint32_t c = image[std::size_t(yy) * w + xx];
                            if ((c >> 24) > (rowBest >> 24))
                                rowBest = c;
                        }
                        if ((rowBest >> 24) > (best >> 24))
                            best = rowBest;
                    }
                    expected[std::size_t(y) * w + x] = best;
                }
            dilate(image.data(), w, h, r);
            QVERIFY2(image == expected,
                     qPrintable(QStringLiteral("r = %1, fill %2").arg(r).arg(fill)));
        }
    }
}

AWB_TEST_GUILESS_MAIN(TestEngine)
#include "test_engine.moc"
