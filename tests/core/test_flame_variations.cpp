// XformMap::apply (src/core/flame/VariationKernels.cpp) against libflam3 3.1.1's own
// apply_xform, which is the reference:
//  - every deterministic variation point by point, on ~2000 points (near 0, ordinary, ~1e3,
//    on the axes, negative) for several settings each (default and non-default parameters,
//    non-identity pre-affines with translations -- waves, rings, fan and popcorn read them --,
//    post transforms, sums with linear): relative error <= 1e-9 (relative to max(1, |value|))
//    and the same bad-value verdicts, and no random number drawn;
//  - the random ones by their distributions over 20000 draws at fixed points: the same
//    branches with the same frequencies for the discrete ones (julia, julian, juliascope,
//    cpow, wedge_julia, boarders), the same quantiles (and means, where they exist) otherwise.
// libflam3 is built with -O3 -ffast-math, which reorders its arithmetic: the kernels, which
// follow variations.c's order, are bit-identical to that source built without it, and within
// ~1e-12 relative of the library (more only where a post transform cancels large terms).
// libflam3 (Debian libflam3-dev, installed by scripts/setup.sh with the tests' packages) is
// linked by this layer's test executable only (tests/CMakeLists.txt).
#include "core/flame/Variations.h"
#include "core/flame/VariationIds.h"

#include <QtTest>

#include "TestMain.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

extern "C" {
#include <flam3.h>
// flam3's variations.h (not installed) declares these; libflam3 exports them.
int apply_xform(flam3_genome *cp, int fn, double *p, double *q, randctx *rc);
void xform_precalc(flam3_genome *cp, int xi);
int prepare_precalc_flags(flam3_genome *cp);
void initialize_xforms(flam3_genome *thiscp, int start_here);
}

using namespace awb;
using namespace awb::flame;
using namespace awb::flame::detail;

namespace {

// flam3_xform's parameter fields, in the order of VariationIds.h's Param.
#define FIELDS(F)                                                                                  \
    F(blob_low) F(blob_high) F(blob_waves) F(pdj_a) F(pdj_b) F(pdj_c) F(pdj_d) F(fan2_x)          \
    F(fan2_y) F(rings2_val) F(perspective_angle) F(perspective_dist) F(julian_power)              \
    F(julian_dist) F(juliascope_power) F(juliascope_dist) F(radial_blur_angle) F(pie_slices)      \
    F(pie_rotation) F(pie_thickness) F(ngon_sides) F(ngon_power) F(ngon_circle) F(ngon_corners)   \
    F(curl_c1) F(curl_c2) F(rectangles_x) F(rectangles_y) F(disc2_rot) F(disc2_twist)             \
    F(super_shape_rnd) F(super_shape_m) F(super_shape_n1) F(super_shape_n2) F(super_shape_n3)     \
    F(super_shape_holes) F(flower_petals) F(flower_holes) F(conic_eccentricity) F(conic_holes)    \
    F(parabola_height) F(parabola_width) F(bent2_x) F(bent2_y) F(bipolar_shift) F(cell_size)      \
    F(cpow_r) F(cpow_i) F(cpow_power) F(curve_xamp) F(curve_yamp) F(curve_xlength)                \
    F(curve_ylength) F(escher_beta) F(lazysusan_spin) F(lazysusan_space) F(lazysusan_twist)       \
    F(lazysusan_x) F(lazysusan_y) F(modulus_x) F(modulus_y) F(oscope_separation)                  \
    F(oscope_frequency) F(oscope_amplitude) F(oscope_damping) F(popcorn2_x) F(popcorn2_y)         \
    F(popcorn2_c) F(separation_x) F(separation_xinside) F(separation_y) F(separation_yinside)     \
    F(split_xsize) F(split_ysize) F(splits_x) F(splits_y) F(stripes_space) F(stripes_warp)        \
    F(wedge_angle) F(wedge_hole) F(wedge_count) F(wedge_swirl) F(wedge_julia_angle)               \
    F(wedge_julia_count) F(wedge_julia_power) F(wedge_julia_dist) F(wedge_sph_angle)              \
    F(wedge_sph_count) F(wedge_sph_hole) F(wedge_sph_swirl) F(whorl_inside) F(whorl_outside)      \
    F(waves2_freqx) F(waves2_scalex) F(waves2_freqy) F(waves2_scaley) F(auger_sym)                \
    F(auger_weight) F(auger_freq) F(auger_scale) F(flux_spread) F(mobius_re_a) F(mobius_im_a)     \
    F(mobius_re_b) F(mobius_im_b) F(mobius_re_c) F(mobius_im_c) F(mobius_re_d) F(mobius_im_d)

#define MEMBER(name) &flam3_xform::name,
#define NAME(name) #name,
double flam3_xform::*const kFields[] = {FIELDS(MEMBER)};
const char *const kFieldNames[] = {FIELDS(NAME)};
static_assert(sizeof(kFields) / sizeof(kFields[0]) == kParamCount);

struct Term {
    int id;
    double weight;
};

using Params = std::vector<std::pair<int, double>>;  // (Param id, value)

struct Case {
    std::vector<Term> terms;
    Params params;  // non-default parameters
    Affine2 pre, post;
};

FlameXform ourXform(const Case &c)
{
    FlameXform x;
    x.pre = c.pre;
    x.post = c.post;
    x.variations.clear();
    for (const Term &t : c.terms)
        x.variations.push_back({t.id, t.weight});
    std::sort(x.variations.begin(), x.variations.end(),
              [](const VariationTerm &a, const VariationTerm &b) { return a.id < b.id; });
    for (auto [p, v] : c.params)
        x.parameters[std::size_t(p)] = v;
    x.weight = 1;
    return x;
}

void setAffine(double m[3][2], const Affine2 &a)
{
    m[0][0] = a.a, m[0][1] = a.d, m[1][0] = a.b, m[1][1] = a.e, m[2][0] = a.c, m[2][1] = a.f;
}

// The genome's only xform set to the case, as flam3's parser and prepare_xform_fn_ptrs do.
void setFlam3(flam3_genome &g, const Case &c)
{
    initialize_xforms(&g, 0);
    flam3_xform &x = g.xform[0];
    x.density = 1.0;
    x.var[0] = 0.0;
    for (const Term &t : c.terms)
        x.var[t.id] += t.weight;
    for (auto [p, v] : c.params)
        x.*kFields[p] = v;
    setAffine(x.c, c.pre);
    setAffine(x.post, c.post);
    if (prepare_precalc_flags(&g) != 0)
        std::fprintf(stderr, "prepare_precalc_flags failed\n");
    xform_precalc(&g, 0);
}

// Deterministic numbers for the test's own choices (not the ones under test).
struct TestRng {
    Xoshiro256 r{12345, 7};
    double u() { return uniform01(r); }
    double in(double lo, double hi) { return lo + (hi - lo) * u(); }
};

std::vector<std::pair<double, double>> testPoints(TestRng &t, int n)
{
    std::vector<std::pair<double, double>> pts = {
        {0, 0}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1e-9, -1e-9}, {-1e3, 1e3}, {0.5, 0.5},
        {-0.5, 0.5}, {1e3, -2e3}, {3.0, -3.0}, {-2.5, -0.5}};
    while (int(pts.size()) < n) {
        const int kind = int(t.u() * 10);
        double x, y;
        if (kind < 4) {
            x = t.in(-2, 2), y = t.in(-2, 2);
        } else if (kind < 5) {  // near 0
            const double s = std::pow(10.0, t.in(-8, -2));
            x = t.in(-s, s), y = t.in(-s, s);
        } else if (kind < 6) {  // ~1e3
            x = t.in(-2000, 2000), y = t.in(-2000, 2000);
        } else if (kind < 7) {  // on an axis
            const double v = t.in(-5, 5);
            if (t.u() < 0.5)
                x = v, y = 0;
            else
                x = 0, y = v;
        } else {
            x = t.in(-10, 10), y = t.in(-10, 10);
        }
        pts.push_back({x, y});
    }
    return pts;
}

Affine2 randomAffine(TestRng &t, double translation)
{
    Affine2 a;
    a.a = t.in(-1.5, 1.5), a.b = t.in(-1.5, 1.5), a.c = t.in(-translation, translation);
    a.d = t.in(-1.5, 1.5), a.e = t.in(-1.5, 1.5), a.f = t.in(-translation, translation);
    return a;
}

// A parameter setting of variation v away from the defaults; super_shape_rnd stays 0 (that
// makes super_shape deterministic) and the root powers at +-1 when `unitPowers`.
Params randomParams(TestRng &t, int v, bool unitPowers)
{
    Params out;
    for (int p : variationParameters(v)) {
        double value = parameterDefault(p) + t.in(-2, 2);
        if (p == kSuperShapeRnd)
            value = 0;
        if (unitPowers && (p == kJulianPower || p == kJuliascopePower || p == kWedgeJuliaPower ||
                           p == kCpowPower))
            value = t.u() < 0.5 ? 1.0 : -1.0;
        out.push_back({p, value});
    }
    return out;
}

struct ErrorStats {
    int cases = 0;
    long points = 0, badBoth = 0, badMismatch = 0, drew = 0;
    double maxAbs = 0, maxRel = 0;
};

const Affine2 kIdentity;

// ---- the deterministic variations, point by point ----
int testDeterministic(flam3_genome &g, randctx &rc)
{
    TestRng t;
    const auto points = testPoints(t, 2000);
    // Pointwise also: super_shape with rnd 0, and the roots at power +-1 (one branch).
    std::vector<int> ids;
    for (int v = 0; v < kVariationCount; ++v)
        if (!variationIsRandom(v) || v == kSuperShape || v == kJulian || v == kJuliascope ||
            v == kCpow || v == kWedgeJulia)
            ids.push_back(v);

    std::printf("Deterministic variations vs libflam3 apply_xform (%zu points per case)\n",
                points.size());
    std::printf("%-14s %5s %8s %7s %8s %12s %12s  %s\n", "variation", "cases", "points",
                "badboth", "badmis", "max abs", "max rel", "status");
    int failures = 0;
    for (int v : ids) {
        const bool unit = variationIsRandom(v);
        std::vector<Case> cases;
        const Affine2 mild{0.9, -0.3, 0.25, 0.2, 1.1, -0.4};
        cases.push_back({{{v, 0.7}}, unit ? randomParams(t, v, true) : Params{}, mild, kIdentity});
        for (int k = 0; k < 4; ++k) {
            Case c;
            c.terms = {{v, t.in(0.2, 1.6) * (k == 3 ? -1 : 1)}};
            if (k >= 2)
                c.terms.push_back({k == 2 ? kLinear : kSpherical, t.in(0.1, 0.6)});
            c.params = randomParams(t, v, true);
            c.pre = randomAffine(t, 1.5);
            if (k % 2 == 1)
                c.post = randomAffine(t, 0.8);
            cases.push_back(c);
        }
        ErrorStats st;
        for (const Case &c : cases) {
            ++st.cases;
            setFlam3(g, c);
            const XformMap map(ourXform(c));
            Xoshiro256 rng(99, 1);
            for (auto [x, y] : points) {
                double p4[4] = {x, y, 0.5, 0}, q4[4];
                const int flamBad = apply_xform(&g, 0, p4, q4, &rc);
                const double p[2] = {x, y};
                double q[2];
                const Xoshiro256 before = rng;
                const bool ok = map.apply(p, q, rng);
                ++st.points;
                if (ok && !unit && std::memcmp(before.s, rng.s, sizeof rng.s) != 0)
                    ++st.drew;
                if (ok != (flamBad == 0)) {
                    if (st.badMismatch < 3)
                        std::printf("  %s: bad-value mismatch at (%g, %g): ours %s (%.17g, %.17g), "
                                    "flam3 %s (%.17g, %.17g)\n",
                                    std::string(variationName(v)).c_str(), x, y, ok ? "ok" : "bad",
                                    q[0], q[1], flamBad ? "bad" : "ok", q4[0], q4[1]);
                    ++st.badMismatch;
                    continue;
                }
                if (!ok) {
                    ++st.badBoth;
                    continue;
                }
                for (int k = 0; k < 2; ++k) {
                    const double abs = std::fabs(q[k] - q4[k]);
                    const double rel = abs / std::max(1.0, std::fabs(q4[k]));
                    if (rel > 1e-9 && rel > st.maxRel)
                        std::printf("  %s: (%.17g, %.17g) -> ours %.17g, flam3 %.17g\n",
                                    std::string(variationName(v)).c_str(), x, y, q[k], q4[k]);
                    st.maxAbs = std::max(st.maxAbs, abs);
                    st.maxRel = std::max(st.maxRel, rel);
                }
            }
        }
        const bool pass = st.maxRel <= 1e-9 && st.badMismatch == 0 && st.drew == 0;
        failures += pass ? 0 : 1;
        std::printf("%-14s %5d %8ld %7ld %8ld %12.3g %12.3g  %s%s\n",
                    std::string(variationName(v)).c_str(), st.cases, st.points, st.badBoth,
                    st.badMismatch, st.maxAbs, st.maxRel, pass ? "ok" : "FAIL",
                    st.drew ? " (drew random numbers)" : "");
    }
    return failures;
}

// ---- the random variations, by their distributions ----
struct Sample {
    std::vector<double> x, y;
    long bad = 0;
    std::map<std::pair<long long, long long>, long> branches;
};

double quantile(std::vector<double> v, double q)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    return v[std::size_t(q * double(v.size() - 1))];
}

double mean(const std::vector<double> &v)
{
    double s = 0;
    for (double a : v)
        s += a;
    return v.empty() ? 0 : s / double(v.size());
}

double stddev(const std::vector<double> &v)
{
    const double m = mean(v);
    double s = 0;
    for (double a : v)
        s += (a - m) * (a - m);
    return v.empty() ? 0 : std::sqrt(s / double(v.size()));
}

void record(Sample &s, const double q[2], bool ok)
{
    if (!ok) {
        ++s.bad;
        return;
    }
    s.x.push_back(q[0]);
    s.y.push_back(q[1]);
    s.branches[{std::llround(q[0] * 1e6), std::llround(q[1] * 1e6)}]++;
}

struct RandomCase {
    const char *label;
    Case c;
    bool discrete;   // a few branches: compare them and their frequencies
    bool heavyTail;  // no mean (tan, 1/cos): compare quantiles only
};

int testRandom(flam3_genome &g, randctx &rc)
{
    const int N = 20000;
    const Affine2 mild{0.9, -0.3, 0.1, 0.2, 1.1, -0.2};
    auto one = [&](int v, double w, Params params = {},
                   Affine2 pre = Affine2{}) {
        Case c;
        c.terms = {{v, w}};
        c.params = std::move(params);
        c.pre = pre;
        return c;
    };
    std::vector<RandomCase> cases = {
        {"blur", one(kBlur, 1.0), false, false},
        {"gaussian_blur", one(kGaussianBlur, 0.8, {}, mild), false, false},
        {"noise", one(kNoise, 1.2), false, false},
        {"julia", one(kJulia, 1.0, {}, mild), true, false},
        {"julian p5 d1", one(kJulian, 1.0, {{kJulianPower, 5}, {kJulianDist, 1}}), true, false},
        {"julian p-3 d.5", one(kJulian, 0.9, {{kJulianPower, -3}, {kJulianDist, 0.5}}, mild), true,
         false},
        {"juliascope p4", one(kJuliascope, 1.0, {{kJuliascopePower, 4}, {kJuliascopeDist, 1.5}}),
         true, false},
        {"radial_blur", one(kRadialBlur, 0.7, {{kRadialBlurAngle, 0.6}}), false, false},
        {"pie", one(kPie, 1.0, {{kPieSlices, 7}, {kPieRotation, 0.3}, {kPieThickness, 0.6}}), false,
         false},
        {"arch", one(kArch, 0.8), false, true},
        {"square", one(kSquare, 1.5), false, false},
        {"rays", one(kRays, 0.7), false, true},
        {"blade", one(kBlade, 0.9, {}, mild), false, false},
        {"twintrian", one(kTwintrian, 0.8), false, false},
        {"flower", one(kFlower, 1.0, {{kFlowerPetals, 3}, {kFlowerHoles, 0.2}}), false, false},
        {"conic", one(kConic, 1.0, {{kConicEccentricity, 0.7}, {kConicHoles, 0.1}}), false, false},
        {"parabola", one(kParabola, 1.0, {{kParabolaHeight, 0.8}, {kParabolaWidth, 1.3}}), false,
         false},
        {"boarders", one(kBoarders, 1.0, {}, mild), true, false},
        {"cpow p3", one(kCpow, 1.0, {{kCpowR, 1.2}, {kCpowI, 0.3}, {kCpowPower, 3}}), true, false},
        {"super_shape", one(kSuperShape, 1.0, {{kSuperShapeRnd, 0.5}, {kSuperShapeM, 5},
                                               {kSuperShapeN1, 2}, {kSuperShapeN2, 1.5},
                                               {kSuperShapeN3, 1.2}, {kSuperShapeHoles, 0.1}}),
         false, false},
        {"wedge_julia", one(kWedgeJulia, 1.0, {{kWedgeJuliaPower, 3}, {kWedgeJuliaDist, 1},
                                               {kWedgeJuliaCount, 2}, {kWedgeJuliaAngle, 0.4}}),
         true, false},
        {"pre_blur", [&] {
             Case c = one(kPreBlur, 0.5, {}, mild);
             c.terms.push_back({kSpherical, 0.8});
             return c;
         }(), false, false},
    };
    const double pts[3][2] = {{0.3, -0.7}, {-1.2, 0.4}, {2.5, 1.5}};

    std::printf("\nRandom variations vs libflam3, %d draws per point, 3 points\n", N);
    std::printf("%-16s %10s %10s %10s %8s %8s  %s\n", "variation", "max dmean", "max dquant",
                "(scale)", "branches", "max dfreq", "status");
    int failures = 0;
    for (const RandomCase &rcase : cases) {
        setFlam3(g, rcase.c);
        const XformMap map(ourXform(rcase.c));
        Xoshiro256 rng(2024, 3);
        double maxDMean = 0, maxDQuant = 0, maxScale = 0, maxDFreq = 0;
        bool pass = true;
        std::string branchNote;
        for (const auto &pt : pts) {
            Sample ours, theirs;
            for (int i = 0; i < N; ++i) {
                double p4[4] = {pt[0], pt[1], 0.5, 0}, q4[4];
                record(theirs, q4, apply_xform(&g, 0, p4, q4, &rc) == 0);
                double q[2];
                const bool ok = map.apply(pt, q, rng);
                record(ours, q, ok);
            }
            if (std::abs(double(ours.bad - theirs.bad)) > 0.01 * N + 10)
                pass = false;
            for (int k = 0; k < 2; ++k) {
                const auto &a = k ? ours.y : ours.x;
                const auto &b = k ? theirs.y : theirs.x;
                const double scale = std::max(1.0, quantile(b, 0.9) - quantile(b, 0.1));
                maxScale = std::max(maxScale, scale);
                if (!rcase.discrete)
                    for (double qq : {0.1, 0.5, 0.9}) {
                        const double d = std::fabs(quantile(a, qq) - quantile(b, qq));
                        maxDQuant = std::max(maxDQuant, d / scale);
                        if (d > 0.05 * scale)
                            pass = false;
                    }
                const double dm = std::fabs(mean(a) - mean(b));
                if (!rcase.heavyTail) {
                    maxDMean = std::max(maxDMean, dm);
                    if (dm > 0.05 * std::max(1.0, stddev(b)))
                        pass = false;
                }
            }
            if (rcase.discrete) {
                // the same branches (those drawn more than 0.5% of the time), at the same rates
                auto frequent = [&](const Sample &s) {
                    std::map<std::pair<long long, long long>, double> f;
                    for (const auto &[key, n] : s.branches)
                        if (n > N / 200)
                            f[key] = double(n) / N;
                    return f;
                };
                const auto fa = frequent(ours), fb = frequent(theirs);
                if (fa.size() != fb.size())
                    pass = false;
                for (const auto &[key, f] : fb) {
                    const auto it = fa.find(key);
                    const double d = it == fa.end() ? f : std::fabs(it->second - f);
                    maxDFreq = std::max(maxDFreq, d);
                    if (d > 0.02)
                        pass = false;
                }
                if (!branchNote.empty())
                    branchNote += '/';
                branchNote += std::to_string(fb.size());
            }
        }
        failures += pass ? 0 : 1;
        std::printf("%-16s %10.4f %10.4f %10.3g %8s %8.4f  %s\n", rcase.label, maxDMean,
                    maxDQuant, maxScale, branchNote.empty() ? "-" : branchNote.c_str(), maxDFreq,
                    pass ? "ok" : "FAIL");
    }
    return failures;
}

} // namespace

class TestFlameVariations : public QObject {
    Q_OBJECT
private slots:
    void parameterNamesAreFlam3s();
    void everyVariationAsLibflam3DrawsIt();
};

void TestFlameVariations::parameterNamesAreFlam3s()
{
    // The parameter table agrees with flam3's fields (oscilloscope_* are flam3's oscope_*).
    for (int p = 0; p < kParamCount; ++p)
        QVERIFY2(parameterId(kFieldNames[p]) == p, kFieldNames[p]);
    QCOMPARE(kVariationCount, 99);
    QCOMPARE(variationId("gaussian_blur"), 35);
    QCOMPARE(std::string(variationName(98)), std::string("mobius"));
    QCOMPARE(variationId("no_such"), -1);
}

void TestFlameVariations::everyVariationAsLibflam3DrawsIt()
{
    flam3_genome g;
    std::memset(&g, 0, sizeof g);
    g.final_xform_index = -1;
    clear_cp(&g, flam3_defaults_on);
    flam3_add_xforms(&g, 1, 0, 0);

    randctx rc;
    std::memset(&rc, 0, sizeof rc);
    for (int i = 0; i < RANDSIZ; ++i)
        rc.randrsl[i] = 0x5eed0000u + unsigned(i);
    irandinit(&rc, 1);

    // Deterministic variations point by point (relative error 1e-9), random ones by their
    // distributions; each function prints its table and counts the failing variations.
    const int deterministic = testDeterministic(g, rc);
    const int random = testRandom(g, rc);
    // What flam3_add_xforms allocated (clear_cp frees nothing): the xforms and the xaos rows.
    for (int i = 0; i < g.num_xforms - (g.final_xform_index >= 0); ++i)
        std::free(g.chaos[i]);
    std::free(g.chaos);
    std::free(g.xform);
    QCOMPARE(deterministic, 0);
    QCOMPARE(random, 0);
}

AWB_TEST_APPLESS_MAIN(TestFlameVariations)
#include "test_flame_variations.moc"
