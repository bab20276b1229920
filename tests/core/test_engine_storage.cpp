// How the raster engine's histogram keeps its counts (core/render/Engine.h, Density.h): counts
// stay exact past 2^24 hits in a cell and with the largest coordinates, a picture of one colour
// keeps counts alone and is the same picture, label planes keep the buckets' numbers, and large
// histograms sit on huge-page boundaries.

#include "core/ifs/Random.h"
#include "core/render/Engine.h"
#include "core/schemes/ControlPointFractal.h"
#include "core/schemes/Scheme.h"

#include <QtTest>

#include "EngineTests.h"
#include "TestMain.h"

#include <cmath>
#include <cstdlib>
#include <random>
#include <stdexcept>

using namespace awb;
using namespace awb::test;

class TestEngineStorage : public QObject {
    Q_OBJECT
private slots:
    void countsStayExactPastTheSpillThreshold();
    void uncheckedHitsStayExactWithTheLargestCoordinate();
    void oneColourPicturesKeepCountsOnly();
    void labelPlanesKeepTheBucketsNumbers();
    void largeHistogramsSitOnHugePageBoundaries();
};

void TestEngineStorage::countsStayExactPastTheSpillThreshold()
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

void TestEngineStorage::uncheckedHitsStayExactWithTheLargestCoordinate()
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

void TestEngineStorage::oneColourPicturesKeepCountsOnly()
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

void TestEngineStorage::labelPlanesKeepTheBucketsNumbers()
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

void TestEngineStorage::largeHistogramsSitOnHugePageBoundaries()
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


AWB_TEST_GUILESS_MAIN(TestEngineStorage)
#include "test_engine_storage.moc"
