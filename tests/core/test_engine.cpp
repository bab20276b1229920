// The raster engine (core/render/Engine.h, Density.h): the fixed-dimension kernels agree with
// the sink-based iteration drawn by the same rasteriser, pictures do not depend on the number
// of threads, the density histogram is the invariant measure (unequal probabilities give the
// pieces their masses), counts stay exact past 2^24 hits in a cell, the tone mapping is
// monotone, supersampling anti-aliases, a picture of one colour keeps counts alone and is the
// same picture, label planes keep the buckets' numbers, and bad input is refused with a message.

#include "core/ifs/Random.h"
#include "core/render/Engine.h"
#include "core/schemes/ControlPointFractal.h"
#include "core/schemes/Scheme.h"

#include <QtTest>

#include "TestMain.h"

#include <cmath>
#include <cstdlib>
#include <random>
#include <stdexcept>

using namespace awb;

namespace {

Mat pts(std::initializer_list<std::pair<double, double>> p)
{
    Mat m(Eigen::Index(p.size()), 2);
    int i = 0;
    for (auto [x, y] : p)
        m.row(i++) << x, y;
    return m;
}

// The Sierpinski gasket in the plane: f_i(z) = z/2 + v_i/2, v = (0,0), (1,0), (0.5,1).
Ifs sierpinski(std::vector<double> probabilities = {})
{
    Ifs ifs;
    const double v[3][2] = {{0, 0}, {1, 0}, {0.5, 1}};
    for (auto &p : v) {
        AffineMap f;
        f.A = Mat::Identity(2, 2) * 0.5;
        f.b = RowVec(2);
        f.b << p[0] / 2, p[1] / 2;
        ifs.maps.push_back(f);
    }
    ifs.views.push_back({Mat::Identity(2, 2), RowVec::Zero(2)});
    ifs.probabilities = std::move(probabilities);
    return ifs;
}

// side^2 maps z -> z R / side + (i, j) / side on the unit square, R a rotation by `angle` (a
// carpet-like IFS; with side 3 and `skipCentre`, Sierpinski's carpet of 8 maps).
Ifs gridIfs(int side, bool skipCentre, double angle)
{
    Ifs ifs;
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j) {
            if (skipCentre && i == side / 2 && j == side / 2)
                continue;
            AffineMap f;
            f.A = Mat(2, 2);
            f.A << std::cos(angle), std::sin(angle), -std::sin(angle), std::cos(angle);
            f.A /= side;
            f.b = RowVec(2);
            f.b << double(i) / side, double(j) / side;
            ifs.maps.push_back(f);
        }
    ifs.views.push_back({Mat::Identity(2, 2), RowVec::Zero(2)});
    return ifs;
}

EngineJob job(const Ifs &ifs, const StartSet &start, int size, double x0, double y0, double x1,
              double y1)
{
    EngineJob j;
    j.ifs = &ifs;
    j.start = start;
    j.frame.width = j.frame.height = size;
    j.frame.x0 = x0, j.frame.y0 = y0, j.frame.x1 = x1, j.frame.y1 = y1;
    j.colours.prefix = 1;
    for (int i = 0; i < ifs.size(); ++i)
        j.colours.labelColours.push_back(Rgb8{std::uint8_t(40 * i), 100, std::uint8_t(200 - 40 * i)});
    return j;
}

bool sameBuckets(const DensityImage &a, const DensityImage &b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a.cell(i) != b.cell(i))
            return false;
    return true;
}

// Fraction of cells lit in exactly one of the two images.
double litMismatch(const DensityImage &a, const DensityImage &b)
{
    std::size_t differ = 0, lit = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const bool la = a.count(i) > 0, lb = b.count(i) > 0;
        differ += la != lb;
        lit += la || lb;
    }
    return lit ? double(differ) / double(lit) : 0.0;
}

} // namespace

class TestEngine : public QObject {
    Q_OBJECT
private slots:
    void kernelsAgreeWithTheSinkPath();
    void threadsDoNotChangeThePicture();
    void randomIterationMatchesTheSinkStreams();
    void densityIsTheInvariantMeasure();
    void aliasTableDrawsTheProbabilities();
    void countsStayExactPastTheSpillThreshold();
    void uncheckedHitsStayExactWithTheLargestCoordinate();
    void oneColourPicturesKeepCountsOnly();
    void labelPlanesKeepTheBucketsNumbers();
    void largeHistogramsSitOnHugePageBoundaries();
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

void TestEngine::countsStayExactPastTheSpillThreshold()
{
    // The whole gasket inside one cell: 2^24 + 12345 hits there, counted exactly.
    Ifs ifs = sierpinski();
    RowVec x0(2);
    x0 << 0.3, 0.3;
    EngineJob j = job(ifs, StartSet::points(Mat(x0)), 4, -1, -1, 7, 7);
    j.colours.prefix = 0;
    j.colours.labelColours = {Rgb8{255, 255, 1}};
    j.random = true;
    j.samples = (std::uint64_t(1) << 24) + 12345;
    j.accumulation = Accumulation::Density;
    // One thread spills while accumulating; two threads (8.4M hits each) spill on merging.
    for (int threads : {1, 2}) {
        j.threads = threads;
        DensityImage img;
        accumulate(j, img);
        QCOMPARE(img.litCells(), std::uint64_t(1));
        const std::size_t where = 3 * 4 + 0;  // x in [-1, 1): column 0; y in [1, 3): row 3
        QCOMPARE(img.count(where), j.samples);
        const auto c = img.cell(where);
        QCOMPARE(c[0], double(j.samples));
        QCOMPARE(c[1], 0.0);  // one label: coordinate 0
    }
}

void TestEngine::uncheckedHitsStayExactWithTheLargestCoordinate()
{
    // 33 555 000 hits (over 2^25) of colour coordinate 255 in one cell, in reserved batches of
    // unchecked hits (and a few checked ones), then merged into an image with hits of its own: the
    // coordinate sums (8.6e9 and more) would wrap in the 32-bit buckets without the sweeps.
    constexpr std::uint64_t batches = 33555, batch = 1000;
    constexpr std::size_t cell = 4;
    DensityImage a(3, 2, Accumulation::Density);
    for (std::uint64_t k = 0; k < batches; ++k) {
        a.reserve(batch);
        for (std::uint64_t i = 0; i < batch; ++i)
            a.addDensityUnchecked(cell, 255);
        if (k < 10)
            a.addDensity(cell, 255);
    }
    const std::uint64_t total = batches * batch + 10;
    QCOMPARE(a.count(cell), total);
    QCOMPARE(a.cell(cell)[1], 255.0 * double(total));
    QCOMPARE(a.litCells(), std::uint64_t(1));

    DensityImage b(3, 2, Accumulation::Density);
    const std::uint64_t own = DensityImage::kSpillAt;  // one whole batch, no sweep yet
    b.reserve(own);
    for (std::uint64_t i = 0; i < own; ++i)
        b.addDensityUnchecked(cell, 255);
    b.merge(a);
    b.reserve(batch);  // sweeps: the room is used up
    for (std::uint64_t i = 0; i < batch; ++i)
        b.addDensityUnchecked(cell, 200);
    QCOMPARE(b.count(cell), total + own + batch);
    QCOMPARE(b.cell(cell)[1], 255.0 * double(total + own) + 200.0 * batch);

    // Hits: the count is exact and the smallest label stays.
    DensityImage h(3, 2, Accumulation::Hits);
    for (std::uint64_t k = 0; k < batches; ++k) {
        h.reserve(batch);
        for (std::uint64_t i = 0; i < batch; ++i)
            h.addHitUnchecked(cell, i == 500 && k == 7 ? 3u : 9u);
    }
    QCOMPARE(h.count(cell), batches * batch);
    QCOMPARE(h.cell(cell)[1], 4.0);  // 1 + the smallest label
    DensityImage h2(3, 2, Accumulation::Hits);
    h2.addHit(cell, 5);
    h2.merge(h);
    QCOMPARE(h2.count(cell), batches * batch + 1);
    QCOMPARE(h2.cell(cell)[1], 4.0);
    // A batch larger than one sweep covers is a caller's bug, refused.
    QVERIFY_THROWS_EXCEPTION(std::length_error, h2.reserve(DensityImage::kSpillAt + 1));
}

void TestEngine::oneColourPicturesKeepCountsOnly()
{
    // A picture whose labels all have one colour is accumulated as one label (4-byte counts):
    // the same counts as the coloured picture, cell for cell, and the same pixels as the
    // coloured histogram toned with that one colour. Random and deterministic iteration,
    // points and triangles, hits and density, one and two threads, one and 2x2 cells a pixel.
    const SubdivisionIfs sier = controlPointFractalIfs(sierpinskiControlPointFractal());
    const StartSet point = StartSet::points(sier.toIfsSpace(pts({{0.37, 0.37}})));
    const StartSet tri = StartSet::polygon(sier.toIfsSpace(pts({{0, 0}, {1, 0}, {0.5, 0.866}})));
    const std::vector<Rgb8> one(9, Rgb8{200, 60, 30});
    for (bool random : {false, true})
        for (const StartSet *start : {&point, &tri}) {
            if (random && start == &tri)
                continue;
            for (Accumulation mode : {Accumulation::Hits, Accumulation::Density})
                for (int threads : {1, 2})
                    for (int ss : {1, 2}) {
                        EngineJob j = job(sier.ifs, *start, 150, -0.1, -0.1, 1.1, 1.1);
                        j.random = random;
                        j.depth = 10;
                        j.samples = 400001;
                        j.accumulation = mode;
                        j.threads = threads;
                        j.frame.supersample = ss;
                        j.colours.prefix = 2;
                        j.colours.labelColours.clear();
                        for (int l = 0; l < 9; ++l)
                            j.colours.labelColours.push_back(Rgb8{std::uint8_t(25 * l), 90, 20});
                        DensityImage coloured, counts;
                        const IterationStats a = accumulate(j, coloured);
                        j.colours.labelColours = one;
                        const IterationStats b = accumulate(j, counts);
                        QVERIFY(!coloured.oneLabel());
                        QVERIFY(counts.oneLabel());
                        QCOMPARE(a.images, b.images);
                        QCOMPARE(counts.offscreen, coloured.offscreen);
                        QVERIFY(counts.litCells() > 1000);
                        QCOMPARE(counts.litCells(), coloured.litCells());
                        for (std::size_t i = 0; i < counts.size(); ++i)
                            QCOMPARE(counts.count(i), coloured.count(i));
                        ToneSettings tone;
                        tone.mode = mode;
                        QVERIFY(toneMap(counts, j.frame, tone, one)
                                == toneMap(coloured, j.frame, tone, one));
                    }
        }

    // Past the spill threshold: 3.4e7 unchecked counts (and a few checked) in one cell, merged
    // into an image holding a whole batch of its own, stay exact.
    constexpr std::uint64_t batches = 33555, batch = 1000;
    constexpr std::size_t cell = 4;
    DensityImage a(3, 2, Accumulation::Density, CellLayout::oneLabel());
    for (std::uint64_t k = 0; k < batches; ++k) {
        a.reserve(batch);
        for (std::uint64_t i = 0; i < batch; ++i)
            a.addCountUnchecked(cell);
        if (k < 10)
            a.addCount(cell);
    }
    const std::uint64_t total = batches * batch + 10;
    QCOMPARE(a.count(cell), total);
    QCOMPARE(a.cell(cell)[1], 0.0);
    QCOMPARE(a.litCells(), std::uint64_t(1));
    DensityImage b(3, 2, Accumulation::Density, CellLayout::oneLabel());
    b.reserve(DensityImage::kSpillAt);
    for (std::uint64_t i = 0; i < DensityImage::kSpillAt; ++i)
        b.addCountUnchecked(cell);
    b.merge(a);
    b.reserve(batch);
    for (std::uint64_t i = 0; i < batch; ++i)
        b.addCountUnchecked(cell);
    QCOMPARE(b.count(cell), total + DensityImage::kSpillAt + batch);
    // A hits image of one label reads as label 0 wherever it was hit.
    DensityImage h(3, 2, Accumulation::Hits, CellLayout::oneLabel());
    h.addCount(1);
    QCOMPARE(h.cell(1), (std::array<double, 2>{1.0, 1.0}));
    QCOMPARE(h.cell(2), (std::array<double, 2>{0.0, 0.0}));
    // Images of one label and coloured ones do not merge.
    DensityImage coloured(3, 2, Accumulation::Density);
    QVERIFY_THROWS_EXCEPTION(InputError, coloured.merge(a));
}

void TestEngine::labelPlanesKeepTheBucketsNumbers()
{
    // Random iteration with 2 to 4 labels keeps a plane of counts per label: the cells' counts,
    // coordinate sums (density) and smallest labels (hits) are the buckets', and so are the
    // pixels. The gasket (3 maps, also with unequal probabilities), 4 rotated maps, the cubic
    // B-spline's IFS by address (2 maps, prefix 2: 4 labels, lifted dimension 4); hits and
    // density, one and two threads, one and 2x2 cells a pixel.
    const Ifs gasket = sierpinski();
    const Ifs unequal = sierpinski({0.5, 0.3, 0.2});
    const Ifs four = gridIfs(2, false, 0.2);
    const auto bspline = buildSubdivisionIfs(bsplineScheme(3),
                                             pts({{0, 0}, {1, 2}, {3, 2.5}, {4.5, 1}, {6, 2}}));
    RowVec z0(2);
    z0 << 0.3, 0.3;
    struct Orbit {
        const Ifs *ifs;
        RowVec x0;
        int prefix;
        double x0w, y0w, x1w, y1w;
    };
    const Orbit orbits[] = {
        {&gasket, z0, 1, -0.1, -0.1, 1.1, 1.1},
        {&unequal, z0, 1, 0.2, 0.1, 0.9, 0.8},
        {&four, z0, 1, -0.6, -0.1, 1.1, 1.1},
        {&bspline.ifs, bspline.toIfsSpace(pts({{7, -3}})).row(0), 2, -0.5, -1.5, 6.5, 3.5},
    };
    for (const Orbit &orbit : orbits)
        for (Accumulation mode : {Accumulation::Hits, Accumulation::Density})
            for (int threads : {1, 2})
                for (int ss : {1, 2}) {
                    EngineJob j = job(*orbit.ifs, StartSet::points(Mat(orbit.x0)), 160,
                                      orbit.x0w, orbit.y0w, orbit.x1w, orbit.y1w);
                    j.random = true;
                    j.samples = 600001;
                    j.accumulation = mode;
                    j.threads = threads;
                    j.frame.supersample = ss;
                    j.colours.prefix = orbit.prefix;
                    j.colours.labelColours.clear();
                    for (int l = 0; l < 5; ++l)  // one more colour than labels: coordinates 0..255
                        j.colours.labelColours.push_back(
                            Rgb8{std::uint8_t(50 * l), std::uint8_t(200 - 30 * l), 90});
                    const int labels = orbit.prefix == 1 ? orbit.ifs->size() : 4;
                    const QString what = QStringLiteral("%1 maps, prefix %2, %3, threads %4, ss %5")
                                             .arg(orbit.ifs->size()).arg(orbit.prefix)
                                             .arg(mode == Accumulation::Hits ? "hits" : "density")
                                             .arg(threads).arg(ss);
                    DensityImage planes, buckets;
                    const IterationStats a = accumulate(j, planes);
                    j.labelPlanes = false;
                    const IterationStats b = accumulate(j, buckets);
                    QCOMPARE(planes.planes(), labels);
                    QCOMPARE(buckets.planes(), 0);
                    QCOMPARE(a.images, b.images);
                    QVERIFY2(planes.litCells() > 100, qPrintable(what + QStringLiteral(", lit %1").arg(planes.litCells())));
                    QCOMPARE(planes.litCells(), buckets.litCells());
                    QCOMPARE(planes.offscreen, buckets.offscreen);
                    QVERIFY2(sameBuckets(planes, buckets), qPrintable(what));
                    // Cells hit by several labels (their coordinate sums mix the labels'):
                    // where the rotated squares overlap, at least.
                    std::size_t mixed = 0;
                    for (std::size_t i = 0; i < planes.size(); ++i) {
                        int hit = 0;
                        for (int l = 0; l < labels; ++l)
                            hit += planes.counts()[planes.planeIndex(i, std::uint32_t(l))] != 0;
                        mixed += hit > 1;
                    }
                    if (orbit.ifs == &four)
                        QVERIFY2(mixed > 100, qPrintable(QString::number(mixed)));
                    ToneSettings tone;
                    tone.mode = mode;
                    QVERIFY2(toneMap(planes, j.frame, tone, j.colours.labelColours)
                                 == toneMap(buckets, j.frame, tone, j.colours.labelColours),
                             qPrintable(what));
                }

    // Past the spill threshold: the same 2.6e7 hits of three labels in two cells, checked and
    // unchecked, into planes and into buckets, then merged into images holding a whole batch
    // of their own: the same exact counts, coordinate sums and smallest labels.
    const std::vector<std::uint8_t> coords = labelCoordinates(3);
    for (Accumulation mode : {Accumulation::Density, Accumulation::Hits}) {
        DensityImage p(3, 2, mode, CellLayout::labelPlanes(3, coords)), q(3, 2, mode);
        Xoshiro256 rng(5, 0);
        constexpr std::uint64_t batches = 26000, batch = 1000;
        for (std::uint64_t k = 0; k < batches; ++k) {
            p.reserve(batch);
            q.reserve(batch);
            for (std::uint64_t n = 0; n < batch; ++n) {
                const std::uint64_t r = rng.next();
                const std::size_t cell = (r >> 63) ? 4 : 1;
                const std::uint32_t label = cell == 4 ? 2u : std::uint32_t((r >> 40) % 3);
                p.addCountUnchecked(p.planeIndex(cell, label));
                if (mode == Accumulation::Density)
                    q.addDensityUnchecked(cell, coords[label]);
                else
                    q.addHitUnchecked(cell, label);
            }
            if (k % 1000 == 0) {
                p.add(0, 1, coords.data());
                q.add(0, 1, coords.data());
            }
        }
        QCOMPARE(p.count(4) + p.count(1), batches * batch);
        QVERIFY(p.count(4) > DensityImage::kSpillAt);
        QVERIFY(sameBuckets(p, q));
        DensityImage p2(3, 2, mode, CellLayout::labelPlanes(3, coords)), q2(3, 2, mode);
        p2.reserve(DensityImage::kSpillAt);
        q2.reserve(DensityImage::kSpillAt);
        for (std::uint64_t n = 0; n < DensityImage::kSpillAt; ++n) {
            p2.addCountUnchecked(p2.planeIndex(4, 0));
            if (mode == Accumulation::Density)
                q2.addDensityUnchecked(4, coords[0]);
            else
                q2.addHitUnchecked(4, 0);
        }
        p2.merge(p);
        q2.merge(q);
        QVERIFY(sameBuckets(p2, q2));
        QCOMPARE(p2.count(4), p.count(4) + DensityImage::kSpillAt);
        if (mode == Accumulation::Density)
            QCOMPARE(p2.cell(4)[1], double(p.count(4)) * 255.0);
        else
            QCOMPARE(p2.cell(4)[1], 1.0);  // label 0 came with the merge
        QCOMPARE(p2.litCells(), std::uint64_t(3));
        // Other layouts, or other coordinates, do not merge.
        DensityImage other(3, 2, mode, CellLayout::labelPlanes(3, labelCoordinates(4)));
        QVERIFY_THROWS_EXCEPTION(InputError, other.merge(p));
        QVERIFY_THROWS_EXCEPTION(InputError, q.merge(p));
    }
    // A plane's count carries no coordinate sum: 2^24 + 1000 unchecked hits in one cell need no
    // sweep (a bucket's sum could overflow there, and is swept every kSpillAt hits).
    for (CellLayout layout : {CellLayout::oneLabel(), CellLayout::labelPlanes(3, coords),
                              CellLayout::buckets()}) {
        DensityImage img(3, 2, Accumulation::Density, layout);
        const std::uint64_t hits = 2 * std::uint64_t(DensityImage::kSpillAt) + 1000;
        for (std::uint64_t done = 0; done < hits;) {
            const std::uint64_t batch = std::min<std::uint64_t>(hits - done, 1u << 20);
            img.reserve(batch);
            for (std::uint64_t n = 0; n < batch; ++n) {
                if (layout.planes > 0)
                    img.addCountUnchecked(img.planeIndex(5, std::uint32_t(layout.planes - 1)));
                else
                    img.addDensityUnchecked(5, 255);
            }
            done += batch;
        }
        QCOMPARE(img.count(5), hits);
        QCOMPARE(img.hasSpills(), layout.planes == 0);
        QCOMPARE(img.cell(5)[1], double(hits) * (layout.planes == 1 ? 0 : 255));
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CellLayout::labelPlanes(5, labelCoordinates(5)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CellLayout::labelPlanes(3, labelCoordinates(2)));
}

void TestEngine::largeHistogramsSitOnHugePageBoundaries()
{
    // A histogram of 2 MiB or more starts on a 2 MiB boundary (the transparent huge pages
    // that keep the chaos game's random hits out of the page table); a small one is an
    // ordinary block. Its cells start at zero and keep their hits through a reset to another
    // size and back.
    const auto aligned = [](const void *p) {
        return reinterpret_cast<std::uintptr_t>(p) % (std::uintptr_t(2) << 20) == 0;
    };
    DensityImage img(1024, 1024, Accumulation::Density);
    QVERIFY(aligned(img.buckets()));
    for (std::size_t i = 0; i < img.size(); i += 4099)
        QCOMPARE(img.count(i), std::uint64_t(0));
    img.addDensity(img.size() - 1, 200);
    QCOMPARE(img.cell(img.size() - 1)[1], 200.0);
    img.reset(1024, 1024, Accumulation::Density, CellLayout::oneLabel());
    QVERIFY(aligned(img.counts()));
    img.addCount(img.size() - 1);
    QCOMPARE(img.count(img.size() - 1), std::uint64_t(1));
    img.reset(30, 20, Accumulation::Hits);
    QCOMPARE(img.count(599), std::uint64_t(0));
    img.addHit(599, 3);
    QCOMPARE(img.cell(599)[1], 4.0);
    img.reset(1024, 1024, Accumulation::Density);
    QCOMPARE(img.count(img.size() - 1), std::uint64_t(0));
    QCOMPARE(img.litCells(), std::uint64_t(0));
}

void TestEngine::polygonsAndSegmentsAreRasterised()
{
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
