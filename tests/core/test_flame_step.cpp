// The flame game's step on AVX-512 registers (src/core/flame/FlameStepAvx512.cpp) against the
// scalar step it stands for (runWave's loop, src/core/flame/FlameChaos.cpp):
//  - one step, orbit by orbit: stacks of 1-61 orbits (partial registers) with bad values,
//    fuse steps and batch ends among them, next-xform tables of 1 (uniform), 3, 12 and 40
//    columns (the table in one register, in two, gathered), a rotated camera: every ordinary
//    orbit lands on the stack that AliasTable::pick gives for its lane's draw, with its point,
//    moved colour and counted counters (a fuse step: its fuse one less, its sample not counted,
//    nothing drawn); every hit is Plot's cell of the point with that colour,
//    in orbit order (with its colour, or its row of whole deltas: the xform's table and the
//    colour's palette index); the rare orbits are left to the scalar step exactly, as they came;
//  - whole flames (a final xform with its opacity, xaos, an xform's opacity; 12 xforms with
//    weights and a rotation; 16 of equal weight, the most that run wide): the histograms of the
//    wide step and of the AVX2 step (engine::forceAvx2Kernels) with the same samples, the same
//    total weight within 1 %, the same lit cells and block sums (correlation >= 0.999); the
//    labelled histogram too.
// Skipped where the processor has no AVX-512 (the wide step does not run there).
#include "core/flame/FlameChaos.h"
#include "core/flame/FlameGame.h"
#include "core/flame/FlameStep.h"
#include "core/flame/Variations.h"
#include "core/flame/XformWave.h"
#include "core/render/Engine.h"

#include <QtTest>

#include "TestMain.h"
#include "cli/BlockCompare.h"

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

using namespace awb;
using namespace awb::flame;
using namespace awb::flame::detail;

namespace {

struct Pushed {
    double x, y, c;
    std::uint64_t n;
    std::size_t stack;
};

std::uint64_t word(OrbitCounters n)
{
    std::uint64_t w;
    std::memcpy(&w, &n, 8);
    return w;
}

Flame flameOf(int xforms, bool weights, double rotate)
{
    Flame f;
    f.width = 160;
    f.height = 120;
    f.scale = 40;
    f.rotate = rotate;
    for (std::size_t i = 0; i < 256; ++i)
        f.palette[i] = {i / 255.0, 0.3, 1 - i / 255.0};
    const char *kinds[] = {"julian", "swirl", "spherical", "sinusoidal", "bubble", "linear"};
    for (int i = 0; i < xforms; ++i) {
        FlameXform x;
        x.variations = {{variationId(kinds[i % 6]), 1.0}};
        const double a = 2 * M_PI * i / xforms;
        x.pre = {0.45 * std::cos(a), -0.45 * std::sin(a), std::cos(a),
                 0.45 * std::sin(a), 0.45 * std::cos(a), std::sin(a)};
        x.parameters[std::size_t(parameterId("julian_power"))] = 3;
        x.colour = double(i) / std::max(1, xforms - 1);
        x.weight = weights ? 1.0 + i % 5 : 1.0;
        f.xforms.push_back(x);
    }
    return f;
}

// Block sums of a histogram's alpha (16 x 16 cells a block) and their correlation.
double blockCorrelation(const FlameHistogram &a, const FlameHistogram &b)
{
    const int bw = (a.width + 15) / 16, bh = (a.height + 15) / 16;
    std::vector<double> sa(std::size_t(bw * bh)), sb(sa.size());
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(a.width) + std::size_t(x);
            const std::size_t k = std::size_t((y / 16) * bw + x / 16);
            sa[k] += a.cells[i][3];
            sb[k] += b.cells[i][3];
        }
    return test::correlation(sa, sb);
}

// The hits of two labelled histograms in 4 x 4 blocks: the mean of (a - b)^2 / (a + b) over
// the blocks either hits -- about 1 for two Poisson draws of one distribution (a little more:
// an orbit's hits are not independent), far more where one picture is shifted or missing parts.
double blockDispersion(const DensityImage &a, const DensityImage &b)
{
    const int bw = (a.cellsX() + 3) / 4, bh = (a.cellsY() + 3) / 4;
    std::vector<double> sa(std::size_t(bw * bh)), sb(sa.size());
    for (int y = 0; y < a.cellsY(); ++y)
        for (int x = 0; x < a.cellsX(); ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(a.cellsX()) + std::size_t(x);
            const std::size_t k = std::size_t((y / 4) * bw + x / 4);
            sa[k] += double(a.count(i));
            sb[k] += double(b.count(i));
        }
    double sum = 0;
    int blocks = 0;
    for (std::size_t k = 0; k < sa.size(); ++k)
        if (sa[k] + sb[k] > 0) {
            sum += (sa[k] - sb[k]) * (sa[k] - sb[k]) / (sa[k] + sb[k]);
            ++blocks;
        }
    return blocks ? sum / blocks : 0.0;
}

} // namespace

class TestFlameStep : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        if (!XformWave::wide())
            QSKIP("this processor has no AVX-512: the wide step does not run here");
    }

    void stepAsTheScalarStep_data()
    {
        QTest::addColumn<int>("columns");
        QTest::addColumn<bool>("weights");
        QTest::addColumn<double>("rotate");
        QTest::addColumn<int>("orbits");
        QTest::addColumn<bool>("whole");  // hits as rows of whole deltas (FlameHits::entry)
        QTest::newRow("one xform (uniform), 61 orbits") << 1 << false << 0.0 << 61 << false;
        QTest::newRow("3 xforms in a register, 7 orbits") << 3 << true << 0.0 << 7 << false;
        QTest::newRow("3 xforms, 40 orbits") << 3 << true << 0.0 << 40 << false;
        QTest::newRow("3 xforms, 40 orbits, hits as rows") << 3 << true << 0.0 << 40 << true;
        QTest::newRow("12 xforms in two registers, rotated") << 12 << true << 30.0 << 53 << false;
        QTest::newRow("12 xforms, rotated, hits as rows") << 12 << true << 30.0 << 53 << true;
        QTest::newRow("40 xforms gathered") << 40 << true << 0.0 << 48 << false;
        QTest::newRow("40 xforms of equal weight") << 40 << false << -15.0 << 33 << false;
    }

    void stepAsTheScalarStep()
    {
        QFETCH(int, columns);
        QFETCH(bool, weights);
        QFETCH(double, rotate);
        QFETCH(int, orbits);
        QFETCH(bool, whole);
        const Flame f = flameOf(columns, weights, rotate);
        const RasterFrame frame = flameFrame(f);
        const Plot plot(f, frame);
        const Choice choice(f);
        const AliasTable &row = choice.rows[0];
        QCOMPARE(row.uniform(), !weights);

        // One stack after its xform: points on and off the frame, some bad, some fusing, some
        // at their batch's last sample; all from xform 2 (k = 1), which is stack 1 itself.
        const std::size_t m = std::size_t(orbits), k = std::min<std::size_t>(1, columns - 1);
        const std::size_t cap = m + kStackPadding;
        std::mt19937_64 gen(1234 + std::uint64_t(orbits));
        std::uniform_real_distribution<double> coordinate(-2.5, 2.5), unit(0, 1);
        std::vector<double> qx(cap), qy(cap), colour(cap);
        std::vector<std::uint8_t> bad(cap);
        std::vector<OrbitCounters> counters(cap);
        for (std::size_t j = 0; j < m; ++j) {
            qx[j] = coordinate(gen);
            qy[j] = coordinate(gen);
            colour[j] = unit(gen);
            bad[j] = j % 11 == 5;
            counters[j] = OrbitCounters{std::uint16_t(j % 13 == 7 ? 1 : 2 + j * 37 % 9000),
                                        std::uint8_t(j % 17 == 3 ? 4 : 0),
                                        std::uint8_t(bad[j] ? 1 + j % 4 : j % 3),  // retries
                                        std::uint16_t(j % columns),
                                        std::uint16_t(j)};
        }
        std::vector<double> sx(std::size_t(columns) * cap), sy(sx.size()), sc(sx.size());
        std::vector<OrbitCounters> sn(sx.size());
        std::vector<std::uint32_t> top(std::size_t(columns), 0);
        // Stack k as the game leaves it: its orbits read, its top back to 0.
        for (std::size_t j = 0; j < m; ++j) {
            sc[k * cap + j] = colour[j];
            sn[k * cap + j] = counters[j];
        }
        const Stacks stacks{sx.data(), sy.data(), sc.data(), sn.data(), top.data(), cap};
        const double towards = 0.5 * 0.25, keep = 0.5;
        std::vector<std::array<std::uint32_t, 4>> cells(std::size_t(frame.cellsX())
                                                        * std::size_t(frame.cellsY()));
        const StepRule rule{.towards = towards,
                            .keep = keep,
                            .opacity = 1.0,
                            .opacityByChance = false,
                            .table = whole ? 768u : 0u,
                            .last = std::uint16_t(k + 1),
                            .final = false,
                            .finalTowards = 0,
                            .finalKeep = 1,
                            .finalOpacity = 1,
                            .next = {row.size(), row.uniform(), row.thresholds(), row.aliases()},
                            .camera = plot.numbers(),
                            .prefetch = reinterpret_cast<const char *>(cells.data()),
                            .stride = 16};
        const StepOrbits in{qx.data(), qy.data(), bad.data(), nullptr, nullptr,
                            sc.data() + k * cap, sn.data() + k * cap, m};
        HitBuffer hits;
        hits.resize(m);
        std::vector<std::uint32_t> deferred(cap);
        std::vector<double> deferredColour(cap);
        std::vector<OrbitCounters> deferredCounters(cap);
        StepOut out{hits.hits(whole), deferred.data(), deferredColour.data(),
                    deferredCounters.data()};
        std::uint64_t state[4][8];
        for (int w = 0; w < 4; ++w)
            for (int j = 0; j < 8; ++j)
                state[w][j] = gen() | 1;
        std::uint64_t lanes[4][8];
        std::memcpy(lanes, state, sizeof lanes);
        stepAvx512(in, rule, stacks, state, out);

        // What the scalar step gives for the ordinary orbits, lane j's draws from its own
        // xoshiro256+ (one draw a register: the pick; no opacity or final xform to draw).
        std::vector<Pushed> expected;
        struct Hit {
            double colour;
            std::size_t cell;
        };
        std::vector<Hit> expectedHits;
        std::vector<std::uint32_t> expectedDeferred;
        std::size_t offscreen = 0;
        for (std::size_t g = 0; g < m; g += 8) {
            bool anyOrdinary = false;
            for (std::size_t j = g; j < std::min(m, g + 8); ++j)
                anyOrdinary = anyOrdinary || !(bad[j] || counters[j].togo == 1);
            std::uint64_t draw[8] = {};
            if (anyOrdinary)
                for (int l = 0; l < 8; ++l) {
                    Xoshiro256 lane;
                    for (int w = 0; w < 4; ++w)
                        lane.s[w] = lanes[w][l];
                    draw[l] = lane.next();
                    for (int w = 0; w < 4; ++w)
                        lanes[w][l] = lane.s[w];
                }
            for (std::size_t j = g; j < std::min(m, g + 8); ++j) {
                const OrbitCounters n = counters[j];
                if (bad[j] || n.togo == 1) {
                    expectedDeferred.push_back(std::uint32_t(j));
                    continue;
                }
                const double c = towards + keep * colour[j];
                OrbitCounters counted = n;
                counted.bad = 0;  // its retries over
                counted.last = std::uint16_t(k + 1);
                if (n.fuse > 0) {  // a fuse step: nothing drawn, no sample counted
                    --counted.fuse;
                } else {
                    const std::ptrdiff_t cell = plot.cell(qx[j], qy[j]);
                    if (cell < 0)
                        ++offscreen;
                    else
                        expectedHits.push_back(Hit{c, std::size_t(cell)});
                    --counted.togo;
                }
                expected.push_back(Pushed{qx[j], qy[j], c, word(counted),
                                          std::size_t(row.pick(draw[j - g]))});
            }
        }
        QCOMPARE(out.deferredCount, expectedDeferred.size());
        for (std::size_t i = 0; i < expectedDeferred.size(); ++i) {
            const std::uint32_t j = expectedDeferred[i];
            QCOMPARE(deferred[i], j);
            QCOMPARE(deferredColour[i], colour[j]);
            QCOMPARE(word(deferredCounters[i]), word(counters[j]));
        }
        QCOMPARE(out.offscreen, offscreen);
        QCOMPARE(out.drawn, expectedHits.size());
        QVERIFY(!expectedHits.empty());
        for (std::size_t i = 0; i < expectedHits.size(); ++i) {
            QCOMPARE(std::size_t(hits.cell[i]), expectedHits[i].cell);
            if (whole) {  // the xform's table + the colour's palette index (step palette)
                const double c = expectedHits[i].colour;
                const std::uint32_t row = 768u + std::uint32_t(paletteIndexOf(c, false).i);
                // (the step's colour is a fused multiply-add: one ulp from c at most)
                QVERIFY(hits.entry[i] == row
                        || std::fabs(c * 256 - std::round(c * 256)) <= 1e-12);
                continue;
            }
            QCOMPARE(hits.opacity[i], 1.0);
            QVERIFY(std::fabs(hits.colour[i] - expectedHits[i].colour) <= 1e-15);
        }
        // Each stack holds its orbits in orbit order.
        std::vector<std::uint32_t> seen(std::size_t(columns), 0);
        for (const Pushed &p : expected) {
            QVERIFY(seen[p.stack] < top[p.stack]);
            const std::size_t at = p.stack * cap + seen[p.stack]++;
            QCOMPARE(sx[at], p.x);
            QCOMPARE(sy[at], p.y);
            QVERIFY(std::fabs(sc[at] - p.c) <= 1e-15);
            QCOMPARE(word(sn[at]), p.n);
        }
        QCOMPARE(seen, top);
    }

    void flamesAsTheAvx2Step_data()
    {
        QTest::addColumn<int>("xforms");
        QTest::addColumn<bool>("weights");
        QTest::addColumn<double>("rotate");
        QTest::addColumn<bool>("extras");
        QTest::newRow("final xform, xaos, opacity") << 3 << true << 0.0 << true;
        QTest::newRow("12 xforms, rotated") << 12 << true << 20.0 << false;
        QTest::newRow("16 xforms of equal weight") << 16 << false << 0.0 << false;
    }

    void flamesAsTheAvx2Step()
    {
        QFETCH(int, xforms);
        QFETCH(bool, weights);
        QFETCH(double, rotate);
        QFETCH(bool, extras);
        Flame f = flameOf(xforms, weights, rotate);
        if (extras) {
            f.xforms[1].opacity = 0.6;
            f.xforms[1].xaos = {2.0, 0.5};
            FlameXform fin;
            fin.variations = {{variationId("bubble"), 1.0}};
            fin.opacity = 0.7;
            fin.colour = 0.9;
            f.finalXform = fin;
        }
        FlameRaster job;
        job.flame = &f;
        job.frame = flameFrame(f);
        job.samples = 3000000;
        job.threads = 2;
        FlameHistogram wide, narrow;
        const FlameStats ws = accumulateFlameColours(job, wide);
        DensityImage wideLabels, narrowLabels;
        const FlameStats wl = accumulateFlame(job, wideLabels);
        forceAvx2Kernels(true);
        const FlameStats ns = accumulateFlameColours(job, narrow);
        const FlameStats nl = accumulateFlame(job, narrowLabels);
        forceAvx2Kernels(false);
        QCOMPARE(ws.samples, job.samples);
        QCOMPARE(ns.samples, job.samples);
        QCOMPARE(wl.samples, job.samples);
        QCOMPARE(nl.samples, job.samples);
        double tw = 0, tn = 0, litW = 0, litN = 0;
        for (std::size_t i = 0; i < wide.cells.size(); ++i) {
            tw += wide.cells[i][3];
            tn += narrow.cells[i][3];
            litW += wide.cells[i][3] > 0;
            litN += narrow.cells[i][3] > 0;
        }
        const double r = blockCorrelation(wide, narrow);
        const double chi = blockDispersion(wideLabels, narrowLabels);
        qInfo("total alpha: wide %.0f, AVX2 %.0f; lit cells %.0f / %.0f; blocks: correlation "
              "%.5f, (a - b)^2 / (a + b) %.3f; offscreen %llu / %llu",
              tw, tn, litW, litN, r, chi, static_cast<unsigned long long>(ws.offscreen),
              static_cast<unsigned long long>(ns.offscreen));
        QVERIFY(std::fabs(tw - tn) <= 0.01 * tn);
        QVERIFY(std::fabs(litW - litN) <= 0.02 * litN);
        QVERIFY(r >= 0.999);
        QVERIFY(chi <= 3.0);
        QVERIFY(std::llabs(std::int64_t(ws.offscreen) - std::int64_t(ns.offscreen))
                <= 6 * std::sqrt(double(ns.offscreen)) + 10);
        QVERIFY(std::llabs(std::int64_t(ws.badValues) - std::int64_t(ns.badValues))
                <= 6 * std::sqrt(double(ns.badValues)) + 10);
        // The labelled histogram (an opacity drawn by chance there).
        double hw = 0, hn = 0;
        for (std::size_t i = 0; i < wideLabels.size(); ++i) {
            hw += double(wideLabels.count(i));
            hn += double(narrowLabels.count(i));
        }
        qInfo("labelled hits: wide %.0f, AVX2 %.0f", hw, hn);
        QVERIFY(std::fabs(hw - hn) <= 6 * std::sqrt(hn) + 10);
    }
};

AWB_TEST_APPLESS_MAIN(TestFlameStep)
#include "test_flame_step.moc"
