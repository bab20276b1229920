// flam3's tone pipeline (core/flame/FlameTone.h) against libflam3's own functions (Debian
// libflam3-dev, installed by scripts/setup.sh): the spatial filter of every shape at several
// radii and supersamples, the density estimator's kernels, the alpha of a log density and the
// highlight power's colours, coefficient for coefficient; and the picture's bounds (a filter
// or estimator too large for memory refused by name, a cancelled render without pixels).

#include "core/Messages.h"
#include "core/flame/FlameTone.h"

#include <QtTest>

#include "TestMain.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>

extern "C" {
#include <flam3.h>
// flam3's filters.h (not installed) declares these; libflam3 exports them.
typedef struct {
    int max_filtered_counts;
    int max_filter_index;
    int kernel_size;
    double *filter_widths;
    double *filter_coefs;
} flam3_de_helper;
int flam3_create_spatial_filter(flam3_frame *spec, int field, double **filter);
flam3_de_helper flam3_create_de_filters(double max_rad, double min_rad, double curve, int ss);
double flam3_calc_alpha(double density, double gamma, double linrange);
void flam3_calc_newrgb(double *cbuf, double ls, double highpow, double *newrgb);
}

using namespace awb;
using namespace awb::flame;

namespace {

Flame twoMaps()
{
    Flame f;
    f.width = f.height = 64;
    f.scale = 30;
    FlameXform a, b;
    a.weight = b.weight = 1;
    a.pre = {0.5, 0, -0.5, 0, 0.5, 0};
    b.pre = {0.5, 0, 0.5, 0, 0.5, 0};
    b.colour = 1;
    f.xforms = {a, b};
    for (std::size_t i = 0; i < 256; ++i)
        f.palette[i] = {i / 256.0, 1 - i / 256.0, 0.5};  // exact sums in any order
    return f;
}

bool refused(const std::function<void()> &fn, const char *part)
{
    try {
        fn();
    } catch (const InputError &e) {
        if (QString::fromUtf8(e.what()).contains(QLatin1String(part)))
            return true;
        qWarning("refused with: %s", e.what());
    }
    return false;
}

} // namespace

class TestFlameTone : public QObject {
    Q_OBJECT
private slots:
    void spatialFiltersAreFlam3s();
    void estimatorsAreFlam3s();
    void alphaAndHighlightsAreFlam3s();
    void shapeNames();
    void boundsAndCancel();
    void picture();
};

void TestFlameTone::spatialFiltersAreFlam3s()
{
    int compared = 0, degenerate = 0;
    for (int shape = 0; shape < kFilterShapeCount; ++shape)
        for (double radius : {0.0, 0.25, 0.5, 1.0, 1.7, 3.0})
            for (int ss : {1, 2, 3, 4}) {
                flam3_genome genome;
                std::memset(&genome, 0, sizeof genome);
                genome.spatial_filter_select = shape;
                genome.spatial_oversample = ss;
                genome.spatial_filter_radius = radius;
                flam3_frame frame;
                std::memset(&frame, 0, sizeof frame);
                frame.genomes = &genome;
                frame.ngenomes = 1;
                frame.pixel_aspect_ratio = 1.0;
                double *theirs = nullptr;
                const int width = flam3_create_spatial_filter(&frame, 0, &theirs);
                if (width < 0) {
                    // flam3 refuses a kernel that sums to 0: so must we.
                        QVERIFY(refused([&] { spatialFilter(FilterShape(shape), radius, ss); },
                                    "too small"));
                    std::free(theirs);
                    continue;
                }
                SpatialFilter ours;
                try {
                    ours = spatialFilter(FilterShape(shape), radius, ss);
                } catch (const InputError &) {
                    // A windowed sinc sampled only at its nodes (a quarter pixel at supersample
                    // 2): flam3 normalises the rounding noise of its zeros; we refuse it.
                    QVERIFY(radius == 0.25 && ss == 2);
                    ++degenerate;
                    std::free(theirs);
                    continue;
                }
                QCOMPARE(ours.width, width);
                for (int i = 0; i < width * width; ++i)
                    QVERIFY2(std::abs(ours.coefs[std::size_t(i)] - theirs[i]) <= 1e-14,
                             qPrintable(QStringLiteral("shape %1 radius %2 ss %3 coef %4: %5 vs %6")
                                            .arg(shape)
                                            .arg(radius)
                                            .arg(ss)
                                            .arg(i)
                                            .arg(ours.coefs[std::size_t(i)])
                                            .arg(theirs[i])));
                // The picture filters rows then columns with `row`: its square is the kernel.
                for (int i = 0; i < width; ++i)
                    for (int j = 0; j < width; ++j)
                        QVERIFY(std::abs(ours.row[std::size_t(i)] * ours.row[std::size_t(j)]
                                         - theirs[i + j * width])
                                <= 1e-14);
                std::free(theirs);
                ++compared;
            }
    qInfo("%d spatial filters equal to flam3's; %d refused that vanish at their sample points",
          compared, degenerate);
    QVERIFY(compared > 300);
    QVERIFY(degenerate <= 3);
}

void TestFlameTone::estimatorsAreFlam3s()
{
    struct Case {
        double radius, minimum, curve;
        int ss;
    };
    // flam3's defaults (9, 0, 0.4), a minimum, a steep and a flat curve, supersamples.
    const Case cases[] = {{9, 0, 0.4, 1}, {9, 0, 0.4, 2}, {9, 0, 0.4, 3}, {5, 1, 0.6, 1},
                          {3, 0, 0.2, 2}, {12, 2, 1.0, 1}, {1, 0, 0.4, 4}, {2.5, 0.5, 0.3, 1}};
    int onRim = 0;
    for (const Case &c : cases) {
        const flam3_de_helper theirs = flam3_create_de_filters(c.radius, c.minimum, c.curve, c.ss);
        QVERIFY(theirs.kernel_size > 0);
        const DensityEstimator ours = densityEstimator(c.radius, c.minimum, c.curve, c.ss);
        QCOMPARE(ours.kernelSize, theirs.kernel_size);
        QCOMPARE(ours.maxFilterIndex, theirs.max_filter_index);
        QCOMPARE(ours.maxFilteredCounts, theirs.max_filtered_counts);
        // flam3 fills kernels up to the one that reaches the minimum radius.
        for (int k = 0; k <= ours.maxFilterIndex; ++k) {
            const double h = ours.filterWidths[std::size_t(k)];
            QCOMPARE(h, theirs.filter_widths[k]);
            double kernelWorst = 0;
            for (int i = 0; i < ours.kernelSize; ++i) {
                const std::size_t j = std::size_t(k) * std::size_t(ours.kernelSize) + std::size_t(i);
                kernelWorst = std::max(kernelWorst, std::abs(ours.coefs[j] - theirs.filter_coefs[j]));
            }
            if (kernelWorst <= 1e-14)
                continue;
            // A lattice point on the kernel's rim (|d| / h = 1 up to rounding: h = 28 / 32^0.4
            // = 7): flam3's library, built with other contractions, counts it on the other side.
            bool rim = false;
            for (int a = 0; a <= int(h) + 1; ++a)
                for (int b = 0; b <= a; ++b)
                    rim = rim || std::abs(std::sqrt(double(a * a + b * b)) / h - 1.0) < 1e-12;
            QVERIFY2(rim, qPrintable(QStringLiteral("kernel %1 of (%2, %3, %4, %5) differs by %6")
                                         .arg(k).arg(c.radius).arg(c.minimum).arg(c.curve)
                                         .arg(c.ss).arg(kernelWorst)));
            ++onRim;
        }
        std::free(theirs.filter_coefs);
        std::free(theirs.filter_widths);
    }
    qInfo("estimator kernels equal to flam3's to 1e-14 but %d with a lattice point on the rim",
          onRim);
    QVERIFY(onRim <= 2);
    QVERIFY(refused([] { densityEstimator(9, 0, 0, 1); }, "curve must be > 0"));
    QVERIFY(refused([] { densityEstimator(1, 2, 0.4, 1); }, "at least its minimum"));
    QVERIFY(refused([] { densityEstimator(5000, 2500, 1, 1); }, "coefficients"));
    QVERIFY(refused([] { densityEstimator(1000, 0, 0.01, 1); }, "too many kernels"));
}

void TestFlameTone::alphaAndHighlightsAreFlam3s()
{
    for (double gamma : {0.25, 1 / 2.2, 1.0})
        for (double lin : {0.0, 0.01, 0.2})
            for (double d : {0.0, 1e-4, 0.005, 0.01, 0.3, 1.0, 7.5})
                QCOMPARE(flam3Alpha(d, gamma, lin), flam3_calc_alpha(d, gamma, lin));
    double sums[][4] = {{0, 0, 0, 255},        {100, 50, 20, 255},   {3e4, 1e4, 5e3, 4e4},
                        {2e5, 2e5, 1e3, 3e5},  {5e3, 9e4, 9e4, 1e5}, {1e6, 10, 10, 1e6}};
    for (auto &s : sums)
        for (double ls : {0.0, 0.5, 3.0, 40.0})
            for (double hp : {-1.0, -0.5, 0.0, 0.5, 1.0, 3.0}) {
                double ours[3], theirs[3];
                flam3NewRgb(s, ls, hp, ours);
                flam3_calc_newrgb(s, ls, hp, theirs);
                for (int c = 0; c < 3; ++c)
                    QVERIFY2(std::abs(ours[c] - theirs[c]) <= 1e-9 * (1 + std::abs(theirs[c])),
                             qPrintable(QStringLiteral("ls %1 hp %2: %3 vs %4")
                                            .arg(ls)
                                            .arg(hp)
                                            .arg(ours[c])
                                            .arg(theirs[c])));
            }
}

void TestFlameTone::shapeNames()
{
    for (int s = 0; s < kFilterShapeCount; ++s)
        QCOMPARE(filterShapeId(filterShapeName(FilterShape(s))), s);
    QCOMPARE(filterShapeId("lanczos3"), int(FilterShape::Lanczos3));
    QCOMPARE(filterShapeId("sinc"), -1);
}

void TestFlameTone::boundsAndCancel()
{
    Flame f = twoMaps();
    FlameImageJob job;
    job.flame = &f;
    job.frame = flameFrame(f);
    job.samples = 1000;
    f.filter = 400;
    f.supersample = 2;
    QVERIFY(refused([&] { renderFlameImage(job); }, "spatial filter of radius 400"));
    f = twoMaps();
    f.estimatorRadius = 5000;
    f.estimatorMinimum = 2500;
    f.estimatorCurve = 1;
    QVERIFY(refused([&] { renderFlameImage(job); }, "coefficients"));
    f = twoMaps();
    f.width = f.height = 9000;
    f.supersample = 4;
    job.frame = flameFrame(f);
    QVERIFY(refused([&] { renderFlameImage(job); }, "at most 32768 a side"));
    f.width = f.height = 6000;
    f.supersample = 2;
    f.estimatorRadius = 0;
    job.frame = flameFrame(f);
    QVERIFY(refused([&] { renderFlameImage(job); }, "MB of histograms"));
    f = twoMaps();
    job.frame = flameFrame(f);
    std::atomic<bool> cancel{true};
    IterationControl control;
    control.cancel = &cancel;
    const FlameImage cancelled = renderFlameImage(job, control);
    QVERIFY(cancelled.stats.cancelled);
    QVERIFY(cancelled.argb.empty());
}

void TestFlameTone::picture()
{
    // A Sierpinski-like pair of maps on a red background: the lit pixels' hue follows the
    // palette from left (colour 0) to right (colour 1); the unlit ones are the background.
    Flame f = twoMaps();
    f.background = {1, 0, 0};
    FlameImageJob job;
    job.flame = &f;
    job.frame = flameFrame(f);
    job.samples = std::uint64_t(flameSamples(f) * 50);
    job.threads = 2;
    const FlameImage one = renderFlameImage(job);
    QCOMPARE(one.width, 64);
    QCOMPARE(one.argb.size(), std::size_t(64 * 64));
    // Every pixel opaque; the corner far from the attractor is the background.
    for (std::uint32_t px : one.argb)
        QCOMPARE(px >> 24, 0xffu);
    QCOMPARE(one.argb[0], 0xffff0000u);
    // The same picture on one thread (the estimator's bands sum in a fixed order).
    job.threads = 1;
    const FlameImage again = renderFlameImage(job);
    QVERIFY(again.argb == one.argb);
    // Without the estimator the histogram is log-scaled in its own memory: the same picture on
    // one thread and two, lit where the estimator's is.
    f.estimatorRadius = 0;
    const FlameImage plain = renderFlameImage(job);
    job.threads = 2;
    QVERIFY(renderFlameImage(job).argb == plain.argb);
    job.threads = 1;
    f.estimatorRadius = 9;
    QCOMPARE(plain.argb[0], 0xffff0000u);
    QVERIFY(std::count(plain.argb.begin(), plain.argb.end(), 0xffff0000u)
            < std::ptrdiff_t(plain.argb.size()));
    // A negative opacity (finite, so accepted) subtracts its hits down to an empty cell, never
    // below (the instrumented build checks the conversion); the picture is still drawn.
    f.xforms[1].opacity = -1;
    const FlameImage negative = renderFlameImage(job);
    QCOMPARE(negative.argb.size(), one.argb.size());
    const auto background = [](const FlameImage &im) {
        return std::count(im.argb.begin(), im.argb.end(), 0xffff0000u);
    };
    QVERIFY(background(negative) > background(one));  // xform 2's cells are empty now
    QVERIFY(background(negative) < std::ptrdiff_t(negative.argb.size()));  // xform 1's are not
}

AWB_TEST_MAIN(TestFlameTone)
#include "test_flame_tone.moc"
