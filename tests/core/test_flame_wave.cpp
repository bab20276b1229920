// The flame's wave of orbits (src/core/flame/XformWaveKernels.inc: four lanes in AVX2, eight in
// AVX-512 -- each test of the kernels runs on both where the processor has both --, libmvec's
// functions) against XformMap::apply, which tests/core/test_flame_variations.cpp holds to
// libflam3's own apply_xform:
//  - every deterministic variation of the 99 -- those with a vector kernel and those the wave
//    runs lane by lane -- on 400 points of [-2.5, 2.5]^2 through a pre-affine with a
//    translation, alone and after linear, with a post transform: relative error <= 1e-9
//    (relative to max(1, |value|), as the scalar kernels against libflam3) and the same
//    bad-value verdicts;
//  - the random ones (different generators) by their distributions over 20000 draws at fixed
//    points: mean and standard deviation of each coordinate within 6 standard errors;
//  - lane counts that are not multiples of a register, bad values in some lanes only;
//  - a whole flame's histogram drawn by the vector kernels against the scalar kernels'
//    (forceBaselineKernels: the same game, XformMap::apply on each lane): the same total
//    weight and the same lit blocks;
//  - the histogram's adds (FlameHits.h) on AVX2 registers, and two hits a register on AVX-512
//    (hits on one cell side by side among them), against the scalar rule and flam3's
//    bump_no_overflow written out here: the very same sums, step and linear palettes, at 0 and
//    at 2^32 - 1;
//  - the adds of whole deltas (HitDeltas: the step palette's rows for each opacity) against the
//    same rule on the hits' colours and opacities, to the unit, and the deltas refused where
//    they are not whole-safe (linear palette, a negative or NaN opacity, a fraction within
//    2^-20 of 1 -- there the double sum rounds up -- more than 16 opacities);
//  - the game with subnormals as zero, the caller's floating-point state given back.
// Skipped only where the processor has no AVX2 (the wave does not run there).
#include "core/flame/FlameChaos.h"
#include "core/flame/FlameHits.h"
#include "core/flame/Variations.h"
#include "core/flame/XformWave.h"
#include "core/render/Engine.h"

#include <QtTest>

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

#include "TestMain.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <random>
#include <string>
#include <string_view>
#include <vector>

using namespace awb;
using namespace awb::flame;

namespace {

// A few parameters away from their defaults, so that the kernels read them.
FlameXform xformOf(int id, bool withLinear, bool withPost)
{
    FlameXform x;
    x.variations = {{id, 0.7}};
    if (withLinear && id != 0)
        x.variations.insert(x.variations.begin(), VariationTerm{0, 0.3});
    x.pre = {0.8, -0.3, 0.15, 0.25, 0.9, -0.2};
    if (withPost)
        x.post = {0.9, 0.2, 0.05, -0.1, 1.1, 0.1};
    auto set = [&](const char *name, double v) {
        const int p = parameterId(name);
        if (p < 0)
            qFatal("no parameter %s", name);
        x.parameters[std::size_t(p)] = v;
    };
    set("julian_power", 3);
    set("juliascope_power", -4);
    set("julian_dist", 0.7);
    set("blob_low", 0.3);
    set("blob_waves", 3);
    set("pdj_a", 1.1);
    set("pdj_b", -2.0);
    set("pdj_c", 0.7);
    set("pdj_d", 1.6);
    set("perspective_angle", 0.4);
    set("perspective_dist", 2.5);
    set("curl_c1", 0.6);
    set("curl_c2", 0.2);
    set("bent2_x", 0.4);
    set("bent2_y", 1.7);
    set("splits_x", 0.3);
    set("splits_y", -0.2);
    set("waves2_freqx", 2.0);
    set("waves2_scalex", 0.3);
    set("waves2_freqy", 1.5);
    set("waves2_scaley", 0.2);
    set("radial_blur_angle", 0.6);
    set("rectangles_x", 0.7);
    set("fan2_x", 0.4);
    set("rings2_val", 0.6);
    set("fan2_y", 0.3);
    set("pie_slices", 5);
    set("pie_rotation", 0.7);
    set("pie_thickness", 0.4);
    set("disc2_rot", 0.8);
    set("disc2_twist", 0.3);
    set("wedge_angle", 0.5);
    set("wedge_count", 3);
    set("wedge_swirl", 0.2);
    set("wedge_hole", 0.1);
    set("wedge_sph_angle", 0.4);
    set("wedge_sph_count", 4);
    set("wedge_sph_swirl", 0.3);
    set("wedge_sph_hole", 0.05);
    set("wedge_julia_angle", 0.6);
    set("wedge_julia_count", 2);
    set("wedge_julia_power", 3);
    set("wedge_julia_dist", 0.8);
    set("whorl_inside", 0.7);
    set("whorl_outside", 0.3);
    x.weight = 1;
    return x;
}

double scaleOf(double v) { return std::max(1.0, std::fabs(v)); }

struct Lanes {
    std::vector<double> x, y, qx, qy;
    std::vector<std::uint8_t> bad;
    explicit Lanes(int n)
        : x(std::size_t(n + 8)), y(std::size_t(n + 8)), qx(std::size_t(n + 8)),
          qy(std::size_t(n + 8)), bad(std::size_t(n + 8))
    {
    }
};

// The 10, 30, 45, 60 and 90 % quantiles: robust where a variation's tails are heavy (arch's
// 1 / cos, rays' tan), and away from the steps of the discrete ones (julia's 2 roots, julian's
// 3, juliascope's 4, pie's 6 slices: at 1/2, 1/3, 1/4 and 1/6 a quantile would fall on either side).
std::vector<double> quantiles(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    std::vector<double> q;
    for (double f : {0.1, 0.3, 0.45, 0.6, 0.9})
        q.push_back(v[std::size_t(f * double(v.size() - 1))]);
    return q;
}

// The kernels of a test row: the eight-lane AVX-512 ones or the four-lane AVX2 ones (the latter
// forced where the processor has both), for the waves made while it lives.
struct Kernels {
    explicit Kernels(bool wide) { forceAvx2Kernels(!wide); }
    ~Kernels() { forceAvx2Kernels(false); }
    Kernels(const Kernels &) = delete;
    Kernels &operator=(const Kernels &) = delete;
};

void kernelRows()
{
    QTest::addColumn<bool>("wide");
    QTest::newRow("AVX2, four lanes") << false;
    QTest::newRow("AVX-512, eight lanes") << true;
}

} // namespace

#define AWB_KERNELS_OF_ROW()                                                                  \
    QFETCH(bool, wide);                                                                       \
    if (wide && !XformWave::wide())                                                           \
        QSKIP("this processor has no AVX-512: the eight-lane kernels do not run here");       \
    const Kernels kernels(wide)

class TestFlameWave : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        if (!XformWave::available())
            QSKIP("this processor has no AVX2: the wave of orbits does not run here");
    }

    void deterministicVariationsAsTheScalarKernels_data() { kernelRows(); }
    void deterministicVariationsAsTheScalarKernels()
    {
        AWB_KERNELS_OF_ROW();
        const int n = 400;
        Lanes l(n);
        Xoshiro256 points(7, 0);
        for (int i = 0; i < n; ++i) {
            l.x[std::size_t(i)] = 5 * uniform01(points) - 2.5;
            l.y[std::size_t(i)] = 5 * uniform01(points) - 2.5;
        }
        int vectorised = 0, laneByLane = 0;
        for (int id = 0; id < kVariationCount; ++id) {
            if (variationIsRandom(id))
                continue;
            (XformWave::vectorKernel(id) ? vectorised : laneByLane) += 1;
            for (int setting = 0; setting < 3; ++setting) {
                const XformMap map(xformOf(id, setting >= 1, setting == 2));
                const XformWave wave(map);
                WaveRandom random(1, 0);
                wave.apply(l.x.data(), l.y.data(), l.qx.data(), l.qy.data(), l.bad.data(), n,
                           random);
                Xoshiro256 rng(1, 0);
                for (int i = 0; i < n; ++i) {
                    const double p[2] = {l.x[std::size_t(i)], l.y[std::size_t(i)]};
                    double q[2];
                    const bool ok = map.apply(p, q, rng);
                    const auto where = QStringLiteral("%1 (setting %2) at (%3, %4)")
                                           .arg(QString::fromUtf8(variationName(id).data(),
                                                                  qsizetype(variationName(id).size())))
                                           .arg(setting)
                                           .arg(p[0], 0, 'g', 17)
                                           .arg(p[1], 0, 'g', 17);
                    QVERIFY2(ok == !l.bad[std::size_t(i)], qPrintable(where));
                    if (!ok)
                        continue;
                    const double ex = std::fabs(l.qx[std::size_t(i)] - q[0]) / scaleOf(q[0]);
                    const double ey = std::fabs(l.qy[std::size_t(i)] - q[1]) / scaleOf(q[1]);
                    QVERIFY2(ex <= 1e-9 && ey <= 1e-9,
                             qPrintable(where + QStringLiteral(": wave (%1, %2), scalar (%3, %4)")
                                                   .arg(l.qx[std::size_t(i)], 0, 'g', 17)
                                                   .arg(l.qy[std::size_t(i)], 0, 'g', 17)
                                                   .arg(q[0], 0, 'g', 17)
                                                   .arg(q[1], 0, 'g', 17)));
                }
            }
        }
        qInfo("%d deterministic variations with a vector kernel, %d lane by lane", vectorised,
              laneByLane);
        QVERIFY(vectorised >= 40);
    }

    // julian's and juliascope's roots, whichever the draw takes: the radius |z|^(dist / power)
    // -- by square and cube roots where dist is 1 and |power| is 1 to 4, else exp(c log) --
    // against std::pow (the scalar kernels', flam3's) on points from 1e-150 to 1e150 and 0, for
    // powers -4 to 5 and dists 1 and 0.7: relative error <= 1e-13 (a few ulp: libmvec's cube
    // root and the rotation by the root's angle), and the same bad values (0 to a negative
    // power); the direction one of flam3's |power| roots' (atan2(y, x) + 2 pi k) / power, odd k
    // mirrored for juliascope (the kernels multiply by 1 / power): within 1e-12.
    void juliansRootsAsFlam3s_data() { kernelRows(); }
    void juliansRootsAsFlam3s()
    {
        AWB_KERNELS_OF_ROW();
        std::vector<double> xs, ys;
        Xoshiro256 points(11, 0);
        for (int i = 0; i < 200; ++i) {
            xs.push_back(5 * uniform01(points) - 2.5);
            ys.push_back(5 * uniform01(points) - 2.5);
        }
        for (double m : {1e-150, 1e-20, 1e-3, 30.0, 1e6, 1e40, 1e150}) {
            xs.push_back(m * 0.6);
            ys.push_back(-m * 0.8);
        }
        xs.push_back(0);
        ys.push_back(0);
        const int n = int(xs.size());
        Lanes l(n);
        std::copy(xs.begin(), xs.end(), l.x.begin());
        std::copy(ys.begin(), ys.end(), l.y.begin());
        const double w = 0.9;
        int checked = 0;
        for (const char *kind : {"julian", "juliascope"})
            for (double dist : {1.0, 0.7})
                for (double power : {1.0, -1.0, 2.0, -2.0, 3.0, -3.0, 4.0, -4.0, 5.0}) {
                    FlameXform x;
                    x.variations = {{variationId(kind), w}};
                    x.parameters[std::size_t(parameterId(std::string(kind) + "_power"))] = power;
                    x.parameters[std::size_t(parameterId(std::string(kind) + "_dist"))] = dist;
                    const XformMap map(x);
                    const XformWave wave(map);
                    WaveRandom random(3, 0);
                    wave.apply(l.x.data(), l.y.data(), l.qx.data(), l.qy.data(), l.bad.data(), n,
                               random);
                    for (int i = 0; i < n; ++i) {
                        const std::size_t j = std::size_t(i);
                        const double sumsq = xs[j] * xs[j] + ys[j] * ys[j];
                        const double r = w * std::pow(sumsq, dist / power / 2.0);
                        const bool bad = !(std::fabs(r) <= 1e10);
                        const auto where = QStringLiteral("%1 power %2 dist %3 at (%4, %5)")
                                               .arg(QLatin1String(kind))
                                               .arg(power)
                                               .arg(dist)
                                               .arg(xs[j], 0, 'g', 17)
                                               .arg(ys[j], 0, 'g', 17);
                        QVERIFY2(bool(l.bad[j]) == bad, qPrintable(where));
                        if (bad)
                            continue;
                        const double got = std::hypot(l.qx[j], l.qy[j]);
                        QVERIFY2(std::fabs(got - r) <= 1e-13 * r + 1e-300,
                                 qPrintable(where + QStringLiteral(": radius %1, pow's %2")
                                                       .arg(got, 0, 'g', 17)
                                                       .arg(r, 0, 'g', 17)));
                        if (!(got > 1e-250))  // no direction to compare
                            continue;
                        const bool scope = std::string_view(kind) == "juliascope";
                        const double theta = std::atan2(ys[j], xs[j]);
                        double nearest = 2;
                        for (int k = 0; k < int(std::fabs(power)); ++k) {
                            const double a =
                                ((scope && k % 2 ? -theta : theta) + 2 * M_PI * k) / power;
                            nearest = std::min(nearest, std::hypot(l.qx[j] / got - std::cos(a),
                                                                   l.qy[j] / got - std::sin(a)));
                        }
                        QVERIFY2(nearest <= 1e-12,
                                 qPrintable(where + QStringLiteral(": direction %1 from a root's")
                                                       .arg(nearest, 0, 'g', 3)));
                        ++checked;
                    }
                }
        QVERIFY(checked > 2 * 2 * 9 * 200);
    }

    // The kernels' own sine and cosine (the argument reduced by pi/2 in three parts up to
    // 2^20, libmvec's beyond): sinusoidal on arguments from 1e-3 to 1e8 and swirl on |z|^2 up
    // to 2^35, the large ones among small ones in a register, against the scalar kernels
    // (std::sin, cos). Swirl's points are multiples of 2^-8 below 2^17, so that |z|^2 is exact
    // whether or not a compiler fuses its multiply-add (an ulp of 1e6 is 1e-10, a difference of
    // the argument, not of the sine).
    void sinesOfAnyArgumentAsTheScalarKernels_data() { kernelRows(); }
    void sinesOfAnyArgumentAsTheScalarKernels()
    {
        AWB_KERNELS_OF_ROW();
        const int n = 4000;
        for (const char *name : {"sinusoidal", "swirl"}) {
            const bool swirl = std::string_view(name) == "swirl";
            Lanes l(n);
            Xoshiro256 points(9, 0);
            for (int i = 0; i < n; ++i) {
                // now and then beyond 2^20
                const double most = i % 16 == 5 ? (swirl ? 5.1 : 8.0) : 3.2;
                for (std::vector<double> *c : {&l.x, &l.y}) {
                    double v = std::pow(10.0, -3 + (most + 3) * uniform01(points));
                    if (swirl)
                        v = std::round(v * 256) / 256;
                    (*c)[std::size_t(i)] = uniform01(points) < 0.5 ? -v : v;
                }
            }
            FlameXform x = xformOf(variationId(name), false, false);
            x.pre = {1, 0, 0, 0, 1, 0};
            const XformMap map(x);
            const XformWave wave(map);
            WaveRandom random(1, 0);
            wave.apply(l.x.data(), l.y.data(), l.qx.data(), l.qy.data(), l.bad.data(), n, random);
            Xoshiro256 rng(1, 0);
            double worst = 0;
            for (int i = 0; i < n; ++i) {
                const double p[2] = {l.x[std::size_t(i)], l.y[std::size_t(i)]};
                double q[2];
                const bool ok = map.apply(p, q, rng);
                QCOMPARE(!l.bad[std::size_t(i)], ok);
                if (!ok)
                    continue;
                worst = std::max({worst, std::fabs(l.qx[std::size_t(i)] - q[0]) / scaleOf(q[0]),
                                  std::fabs(l.qy[std::size_t(i)] - q[1]) / scaleOf(q[1])});
                QVERIFY2(worst <= 1e-9, qPrintable(QStringLiteral("%1 at (%2, %3)")
                                                       .arg(QLatin1String(name))
                                                       .arg(p[0], 0, 'g', 17)
                                                       .arg(p[1], 0, 'g', 17)));
            }
            qInfo("%s: largest difference %.3g", name, worst);
        }
    }

    void randomVariationsByTheirDistributions_data() { kernelRows(); }
    void randomVariationsByTheirDistributions()
    {
        AWB_KERNELS_OF_ROW();
        const int draws = 20000;
        const double points[3][2] = {{0.3, -0.4}, {1.2, 0.7}, {-0.8, 1.5}};
        int tested = 0;
        for (int id = 0; id < kVariationCount; ++id) {
            if (!variationIsRandom(id))
                continue;
            ++tested;
            // With linear beside it: pre_blur moves the point the terms see.
            const XformMap map(xformOf(id, true, false));
            const XformWave wave(map);
            const auto name = QString::fromUtf8(variationName(id).data(),
                                                qsizetype(variationName(id).size()));
            for (const auto &p : points) {
                Lanes l(draws);
                std::fill(l.x.begin(), l.x.end(), p[0]);
                std::fill(l.y.begin(), l.y.end(), p[1]);
                WaveRandom random(3, 1);
                wave.apply(l.x.data(), l.y.data(), l.qx.data(), l.qy.data(), l.bad.data(),
                           draws, random);
                std::vector<double> wx, wy, sx, sy;
                Xoshiro256 rng(5, 2);
                for (int i = 0; i < draws; ++i) {
                    double q[2];
                    if (map.apply(p, q, rng)) {
                        sx.push_back(q[0]);
                        sy.push_back(q[1]);
                    }
                    if (!l.bad[std::size_t(i)]) {
                        wx.push_back(l.qx[std::size_t(i)]);
                        wy.push_back(l.qy[std::size_t(i)]);
                    }
                }
                const double badW = double(draws) - double(wx.size());
                const double badS = double(draws) - double(sx.size());
                QVERIFY2(std::fabs(badW - badS) <= 6 * std::sqrt(std::max(badW, badS)) + 2,
                         qPrintable(name + QStringLiteral(": bad values %1 against %2")
                                               .arg(badW)
                                               .arg(badS)));
                for (const auto &[w, s] : {std::pair{&wx, &sx}, std::pair{&wy, &sy}}) {
                    const std::vector<double> qw = quantiles(*w), qs = quantiles(*s);
                    const double spread = qs[4] - qs[0];
                    for (std::size_t k = 0; k < qw.size(); ++k)
                        QVERIFY2(std::fabs(qw[k] - qs[k]) <= 0.05 * spread + 1e-9,
                                 qPrintable(name + QStringLiteral(": quantile %1 wave %2, "
                                                                  "scalar %3 (10-90 %% spread %4)")
                                                       .arg(k)
                                                       .arg(qw[k])
                                                       .arg(qs[k])
                                                       .arg(spread)));
                }
            }
        }
        QVERIFY(tested >= 15);
    }

    void partialLanesAndOneBadLane_data() { kernelRows(); }
    void partialLanesAndOneBadLane()
    {
        AWB_KERNELS_OF_ROW();
        // Nine lanes (two registers of four and one lane, or one of eight and one lane): a
        // pre-affine that sends five of them beyond flam3's 1e10 (bad: a random replacement
        // in [-1, 1]^2), four not; the padding lanes hold NaN and are ignored.
        FlameXform x;
        x.variations = {{0, 1.0}};
        x.pre = {1e12, 0, 0, 0, 1, 0};
        const XformMap map(x);
        const XformWave wave(map);
        Lanes l(9);
        const double xs[9] = {0.5, 2e-11, 0.25, -0.3, 1e-12, 4e-12, 0.125, 3.0, 2e-13};
        for (std::size_t i = 0; i < 9; ++i) {
            l.x[i] = xs[i];
            l.y[i] = 0.25 * double(i);
        }
        for (std::size_t i = 9; i < 16; ++i)
            l.x[i] = std::nan("");
        WaveRandom random(1, 0);
        wave.apply(l.x.data(), l.y.data(), l.qx.data(), l.qy.data(), l.bad.data(), 9, random);
        const bool bad[9] = {true, false, true, true, false, false, true, true, false};
        Xoshiro256 rng(1, 0);
        for (std::size_t i = 0; i < 9; ++i) {
            QCOMPARE(bool(l.bad[i]), bad[i]);
            if (bad[i]) {
                QVERIFY(std::fabs(l.qx[i]) <= 1 && std::fabs(l.qy[i]) <= 1);
                continue;
            }
            const double p[2] = {l.x[i], l.y[i]};
            double q[2];
            QVERIFY(map.apply(p, q, rng));
            QCOMPARE(l.qx[i], q[0]);
            QCOMPARE(l.qy[i], q[1]);
        }
    }

    void flameAsTheScalarGame()
    {
        // tests/cli/test_flame_chaos.cpp holds the wave's pictures to flam3-render's; here the
        // vector kernels against the scalar ones on one flame with a final xform, xaos and
        // opacity.
        Flame f;
        f.width = f.height = 128;
        f.scale = 32;
        for (std::size_t i = 0; i < 256; ++i)
            f.palette[i] = {i / 255.0, 0.3, 1 - i / 255.0};
        FlameXform a = xformOf(variationId("julian"), true, false);
        a.colour = 0;
        FlameXform b = xformOf(variationId("swirl"), false, true);
        b.colour = 1;
        b.opacity = 0.6;
        b.xaos = {2.0, 0.5};
        FlameXform c = xformOf(variationId("spherical"), true, false);
        c.pre = {0.5, 0, 0.3, 0, 0.5, -0.2};
        c.colour = 0.5;
        f.xforms = {a, b, c};
        FlameXform fin = xformOf(variationId("bubble"), false, false);
        fin.pre = {1, 0, 0, 0, 1, 0};
        f.finalXform = fin;
        FlameRaster job;
        job.flame = &f;
        job.frame = flameFrame(f);
        job.samples = 2000000;
        FlameHistogram wave, scalar;
        const FlameStats ws = accumulateFlameColours(job, wave);
        forceBaselineKernels(true);
        const FlameStats ss = accumulateFlameColours(job, scalar);
        forceBaselineKernels(false);
        QCOMPARE(ws.samples, job.samples);
        QCOMPARE(ss.samples, job.samples);
        double tw = 0, ts = 0;
        int litBoth = 0, litOne = 0;
        for (std::size_t i = 0; i < wave.cells.size(); ++i) {
            tw += wave.cells[i][3];
            ts += scalar.cells[i][3];
            const bool lw = wave.cells[i][3] > 0, ls = scalar.cells[i][3] > 0;
            litBoth += lw && ls;
            litOne += lw != ls;
        }
        qInfo("total alpha: wave %.0f, scalar %.0f; cells lit in both %d, in one %d", tw, ts,
              litBoth, litOne);
        QVERIFY(std::fabs(tw - ts) <= 0.01 * ts);  // opacity 0.6: ~1e6 hits a side
        QVERIFY(litOne <= litBoth / 20);
        QVERIFY(std::llabs(std::int64_t(ws.offscreen) - std::int64_t(ss.offscreen))
                <= 6 * std::sqrt(double(ss.offscreen)) + 10);
    }

    void hitsAsFlam3Bumps()
    {
        using namespace awb::flame::detail;
        std::mt19937_64 gen(7);
        auto uniform = [&](double a, double b) {
            return std::uniform_real_distribution<double>(a, b)(gen);
        };
        std::vector<double> dmap(4 * 256);
        for (int i = 0; i < 256; ++i) {
            dmap[std::size_t(4 * i)] = 255.0 * uniform(0, 1);
            dmap[std::size_t(4 * i + 1)] = 255.0 * uniform(0, 1);
            dmap[std::size_t(4 * i + 2)] = 255.0 * (i == 7 ? 1.0 : uniform(0, 1));
            dmap[std::size_t(4 * i + 3)] = 255.0;
        }
        // Colours at the palette's ends and steps, and beyond; opacities of flam3's range and a
        // negative one (held at 0 here; flam3's conversion would be undefined).
        const double colours[] = {0.0, 1.0, 255.0 / 256, 254.5 / 256, 7.0 / 256, -0.2, 1.3};
        const double opacities[] = {1.0, 0.6, 0.25, 3.0};
        const std::size_t n = 4000;
        HitBuffer buffer;
        buffer.resize(n);
        const FlameHits hits = buffer.hits();
        for (std::size_t h = 0; h < n; ++h) {
            const double c = h % 3 == 0 ? colours[h / 3 % 7] : uniform(0, 1);
            const double o = h % 5 == 4 ? -0.5 : opacities[h / 5 % 4];
            hits.put(h, c, o, std::size_t(gen() % 37), 0);  // cells hit many times
        }
        for (const bool linear : {false, true}) {
            std::vector<std::array<std::uint32_t, 4>> start(37);
            for (std::size_t i = 0; i < start.size(); ++i)
                for (std::uint32_t &v : start[i])
                    v = i % 3 == 0 ? UINT_MAX - std::uint32_t(gen() % 40000)
                                   : std::uint32_t(gen() % 100000);
            const HitPalette palette{dmap.data(), linear};
            auto scalar = start, vector = start, flam3 = start;
            auto wide = start;
            addHits(hits, n, palette, scalar.data());
            addHitsAvx2(hits, n, palette, vector.data());
            if (XformWave::wide())
                addHitsAvx512(hits, n, palette, wide.data());
            else
                wide = scalar;
            // flam3 3.1.1 (rect.c): the colour index, then bump_no_overflow on each sum.
            for (std::size_t h = 0; h < n; ++h) {
                const double colour = hits.colour[h], opacity = hits.opacity[h];
                double delta[4];
                const double d = colour * 256;
                int i = int(std::clamp(d, -1.0, 257.0));
                if (!linear) {
                    i = std::clamp(i, 0, 255);
                    for (int c = 0; c < 4; ++c)
                        delta[c] = opacity * dmap[std::size_t(4 * i + c)];
                } else {
                    double frac = d - i;
                    if (i < 0) {
                        i = 0;
                        frac = 0;
                    } else if (i >= 255) {
                        i = 254;
                        frac = 1;
                    }
                    for (int c = 0; c < 3; ++c)
                        delta[c] = opacity * (dmap[std::size_t(4 * i + c)] * (1.0 - frac)
                                              + dmap[std::size_t(4 * i + 4 + c)] * frac);
                    delta[3] = opacity * 255.0;
                }
                for (int c = 0; c < 4; ++c) {
                    std::uint32_t &dest = flam3[hits.cell[h]][std::size_t(c)];
                    if (delta[c] < 0 && -delta[c] > dest)
                        dest = 0;
                    else if (UINT_MAX - dest > delta[c])
                        dest = std::uint32_t(dest + delta[c]);
                    else
                        dest = UINT_MAX;
                }
            }
            int held = 0;
            for (std::size_t i = 0; i < start.size(); ++i) {
                QCOMPARE(vector[i], scalar[i]);
                QCOMPARE(wide[i], scalar[i]);
                QCOMPARE(scalar[i], flam3[i]);
                held += scalar[i][3] == UINT_MAX;
            }
            QVERIFY(held > 0);  // some sums reached 2^32 - 1
        }
    }

    // The game (and the Lyapunov exponent's orbit) runs with subnormals as zero (an orbit drawn
    // to an axis reaches them; each operation on one would cost a microcode assist) and gives
    // the caller's floating-point state back: a flame drawn to the origin, x -> x / 2, on every
    // kernel set.
    void subnormalsAsZeroOnlyWhileTheGameRuns()
    {
#if defined(__SSE__) || defined(__x86_64__)
        Flame f;
        f.width = f.height = 64;
        f.scale = 16;
        for (std::size_t i = 0; i < 256; ++i)
            f.palette[i] = {i / 255.0, 0.3, 1 - i / 255.0};
        FlameXform half;
        half.variations = {{variationId("linear"), 1.0}};
        half.pre = {0.5, 0, 0, 0, 0.5, 0};
        half.weight = 1;
        f.xforms = {half, half};
        FlameRaster job;
        job.flame = &f;
        job.frame = flameFrame(f);
        job.samples = 300000;  // batches of thousands of steps: 2^-1074 within the first
        const unsigned before = _mm_getcsr();
        QCOMPARE(before & 0x8040u, 0u);  // the program's own state: subnormals kept
        for (const int kernels : {0, 1, 2}) {  // wide, AVX2, scalar
            forceAvx2Kernels(kernels == 1);
            forceBaselineKernels(kernels == 2);
            FlameHistogram h;
            const FlameStats st = accumulateFlameColours(job, h);
            QCOMPARE(_mm_getcsr(), before);
            QCOMPARE(st.samples, job.samples);
            QCOMPARE(st.badValues, std::uint64_t(0));
            // Every hit but those of the fuse's first steps at the origin's cell.
            double total = 0, origin = 0;
            const std::size_t centre = std::size_t(32 * 64 + 32);
            for (std::size_t i = 0; i < h.cells.size(); ++i) {
                total += h.cells[i][3];
                if (i == centre || i == centre - 1 || i == centre - 64 || i == centre - 65)
                    origin += h.cells[i][3];
            }
            QVERIFY(origin >= 0.999 * total);
        }
        forceAvx2Kernels(false);
        forceBaselineKernels(false);
        // The exponent along the orbit too (each xform halves: ln 1/2).
        const FlameLyapunov l = flameLyapunov(f);
        QCOMPARE(_mm_getcsr(), before);
        QVERIFY(std::fabs(l.exponent - std::log(0.5)) <= 1e-6);
#else
        QSKIP("no MXCSR here: subnormals are the processor's own");
#endif
    }

    void wholeAddsAsTheRule()
    {
        using namespace awb::flame::detail;
        std::mt19937_64 gen(11);
        auto uniform = [&](double a, double b) {
            return std::uniform_real_distribution<double>(a, b)(gen);
        };
        std::vector<double> dmap(4 * 256);
        for (int i = 0; i < 256; ++i) {
            for (int c = 0; c < 3; ++c)
                dmap[std::size_t(4 * i + c)] = 255.0 * (i == 9 ? 0.0 : uniform(0, 1));
            dmap[std::size_t(4 * i + 3)] = 255.0;
        }
        const HitPalette palette{dmap.data(), false};
        // Xforms' opacities: two share a table; 3.0 and 1e9 make sums held at 2^32 - 1.
        const std::vector<double> opacities{1.0, 0.6, 1.0, 0.25, 3.0, 1e9};
        const HitDeltas deltas = HitDeltas::of(palette, opacities);
        QVERIFY(!deltas.empty());
        QCOMPARE(deltas.rows.size(), std::size_t(5 * 256));
        QCOMPARE(deltas.table[2], deltas.table[0]);
        const double colours[] = {0.0, 1.0, 255.0 / 256, 9.0 / 256, -0.2, 1.3, 9.5 / 256};
        const std::size_t n = 6000, cellCount = 41;
        HitBuffer plain, whole;
        plain.resize(n);
        whole.resize(n);
        const FlameHits a = plain.hits(), b = whole.hits(true);
        QVERIFY(a.entry == nullptr && b.entry != nullptr);
        for (std::size_t h = 0; h < n; ++h) {
            const double c = h % 3 == 0 ? colours[h / 3 % 7] : uniform(0, 1);
            const std::size_t k = h % 97 == 0 ? 5 : std::size_t(gen() % 5);
            const std::size_t cell = std::size_t(gen() % cellCount);
            a.put(h, c, opacities[k], cell, deltas.table[k]);
            b.put(h, c, opacities[k], cell, deltas.table[k]);
        }
        std::vector<std::array<std::uint32_t, 4>> start(cellCount);
        for (std::size_t i = 0; i < start.size(); ++i)
            for (std::uint32_t &v : start[i])
                v = i % 4 == 0 ? UINT_MAX - std::uint32_t(gen() % 40000)
                               : std::uint32_t(gen() % 100000);
        auto rule = start, scalar = start, vector = start;
        addHits(a, n, palette, rule.data());
        addHitsWhole(b, n, deltas, scalar.data());
        addHitsWholeAvx2(b, n, deltas, vector.data());  // initTestCase: the processor has AVX2
        int held = 0;
        for (std::size_t i = 0; i < cellCount; ++i) {
            QCOMPARE(scalar[i], rule[i]);
            QCOMPARE(vector[i], rule[i]);
            held += rule[i][0] == UINT_MAX;
        }
        QVERIFY(held > 0);

        // Where a whole delta would not give the rule's sums: refused.
        QVERIFY(HitDeltas::of({dmap.data(), true}, opacities).empty());  // linear palette
        QVERIFY(HitDeltas::of(palette, {1.0, -0.5}).empty());
        QVERIFY(HitDeltas::of(palette, {1.0, std::nan("")}).empty());
        std::vector<double> many;
        for (int i = 0; i < 17; ++i)
            many.push_back(1.0 - i / 64.0);
        QVERIFY(HitDeltas::of(palette, many).empty());
        many.pop_back();
        QVERIFY(!HitDeltas::of(palette, many).empty());
        // A delta of 2 - 2^-23: 3e9 + it rounds to 3e9 + 2 in doubles, so the rule gives one
        // more than 3e9 + floor(delta).
        auto nearWhole = dmap;
        nearWhole[4 * 200 + 1] = 2.0 - 1.0 / (1 << 23);
        QCOMPARE(std::uint32_t(3e9 + nearWhole[4 * 200 + 1]), std::uint32_t(3000000002u));
        QVERIFY(HitDeltas::of({nearWhole.data(), false}, {1.0}).empty());
        nearWhole[4 * 200 + 1] = 2.0 - 1.0 / (1 << 19);  // far enough from 2
        QVERIFY(!HitDeltas::of({nearWhole.data(), false}, {1.0}).empty());
    }
};

AWB_TEST_APPLESS_MAIN(TestFlameWave)
#include "test_flame_wave.moc"
