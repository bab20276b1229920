#include "core/flame/FlameTone.h"

#include "core/Messages.h"
#include "core/Threads.h"
#include "core/Types.h"
#include "core/ifs/Random.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstring>

namespace awb::flame {

namespace {

std::string tr(const char *text) { return coreTranslate("awb::flame", text); }

// flam3's parser: the names by FilterShape's numbers.
constexpr std::array<std::string_view, kFilterShapeCount> kShapeNames = {
    "gaussian", "hermite",  "box",      "triangle", "bell",    "bspline", "lanczos3",
    "lanczos2", "mitchell", "blackman", "catrom",   "hamming", "hanning", "quadratic"};

// filters.c: each number's support and function, in filters.c's own order (gaussian, hermite,
// box, triangle, bell, b-spline, mitchell, blackman, catrom, hanning, hamming, lanczos3,
// lanczos2, quadratic) -- which is not the parser's from 6 on: flam3 draws a shape named
// "lanczos3" (6) with Mitchell's filter, and we draw what flam3 draws.
constexpr std::array<double, kFilterShapeCount> kSupport = {1.5, 1.0, 0.5, 1.0, 1.5, 2.0, 2.0,
                                                            1.0, 2.0, 1.0, 1.0, 3.0, 2.0, 1.5};

double sinc(double x)
{
    x *= M_PI;
    return x != 0 ? std::sin(x) / x : 1.0;
}

double gaussian(double x) { return std::exp(-2.0 * x * x) * std::sqrt(2.0 / M_PI); }

double shapeValue(FilterShape shape, double t)
{
    switch (int(shape)) {
    case 0: return gaussian(t);
    case 1:
        t = std::abs(t);
        return t < 1.0 ? (2.0 * t - 3.0) * t * t + 1.0 : 0.0;
    case 2: return t > -0.5 && t <= 0.5 ? 1.0 : 0.0;
    case 3:
        t = std::abs(t);
        return t < 1.0 ? 1.0 - t : 0.0;
    case 4:
        t = std::abs(t);
        if (t < 0.5)
            return 0.75 - t * t;
        if (t < 1.5) {
            t -= 1.5;
            return 0.5 * t * t;
        }
        return 0.0;
    case 5:
        t = std::abs(t);
        if (t < 1) {
            const double tt = t * t;
            return 0.5 * tt * t - tt + 2.0 / 3.0;
        }
        if (t < 2) {
            t = 2 - t;
            return (1.0 / 6.0) * (t * t * t);
        }
        return 0.0;
    case 6: {
        constexpr double B = 1.0 / 3.0, C = 1.0 / 3.0;
        const double tt = t * t;
        t = std::abs(t);
        if (t < 1.0)
            return ((12.0 - 9.0 * B - 6.0 * C) * (t * tt) + (-18.0 + 12.0 * B + 6.0 * C) * tt
                    + (6.0 - 2 * B))
                   / 6.0;
        if (t < 2.0)
            return ((-1.0 * B - 6.0 * C) * (t * tt) + (6.0 * B + 30.0 * C) * tt
                    + (-12.0 * B - 48.0 * C) * t + (8.0 * B + 24 * C))
                   / 6.0;
        return 0.0;
    }
    case 7:
        return sinc(t) * (0.42 + 0.5 * std::cos(M_PI * t) + 0.08 * std::cos(2 * M_PI * t));
    case 8:
        if (t < -2.0)
            return 0.0;
        if (t < -1.0)
            return 0.5 * (4.0 + t * (8.0 + t * (5.0 + t)));
        if (t < 0.0)
            return 0.5 * (2.0 + t * t * (-5.0 - 3.0 * t));
        if (t < 1.0)
            return 0.5 * (2.0 + t * t * (-5.0 + 3.0 * t));
        if (t < 2.0)
            return 0.5 * (4.0 + t * (-8.0 + t * (5.0 - t)));
        return 0.0;
    case 9: return sinc(t) * (0.5 + 0.5 * std::cos(M_PI * t));
    case 10: return sinc(t) * (0.54 + 0.46 * std::cos(M_PI * t));
    case 11: {
        const double a = std::abs(t);
        return (a < 3.0 ? sinc(a) * sinc(a / 3.0) : 0.0) * sinc(t / 3.0);
    }
    case 12: {
        const double a = std::abs(t);
        return (a < 2.0 ? sinc(a) * sinc(a / 2.0) : 0.0) * sinc(t / 2.0);
    }
    case 13:
        if (t < -1.5)
            return 0.0;
        if (t < -0.5)
            return 0.5 * (t + 1.5) * (t + 1.5);
        if (t < 0.5)
            return 0.75 - t * t;
        if (t < 1.5)
            return 0.5 * (t - 1.5) * (t - 1.5);
        return 0.0;
    }
    return 0.0;
}

constexpr int kDeThreshold = 100;  // filters.h: DE_THRESH


// The accumulator of the log-scaled, density-estimated cells is float, as flam3-render's
// (its default bits=33: an unsigned histogram, a float accumulator; flam3.c), each sum taken
// in double and stored as float (its abump_no_overflow); the spatial filter's sums are double.
using Accum = std::array<float, 4>;
// The log-scaled cells: as large as the histogram, so on huge pages as it (BigAllocator.h).
using Accums = BigVector<Accum>;
using Cell = std::array<double, 4>;
using Bucket = std::array<std::uint32_t, 4>;

// The log scaling without the estimator (rect.c): every lit cell by k1 log(1 + k2 a) / a.
void logScale(const FlameHistogram &h, Accums &acc, double k1, double k2,
              int threads)
{
    const std::size_t n = h.cells.size();
    onThreads(threads, [&](int t) {
        const std::size_t first = n * std::size_t(t) / std::size_t(threads);
        const std::size_t last = n * std::size_t(t + 1) / std::size_t(threads);
        for (std::size_t i = first; i < last; ++i) {
            const Bucket &c = h.cells[i];
            if (c[3] == 0)
                continue;
            const double a = c[3];
            const double ls = k1 * std::log(1.0 + a * k2) / a;
            Accum &out = acc[i];  // summed over flam3's passes
            out[0] += c[0] * ls;
            out[1] += c[1] * ls;
            out[2] += c[2] * ls;
            out[3] += a * ls;
        }
    });
}

// The same in the histogram's own memory, for one pass without the estimator: each cell's four
// sums replaced by its four floats (16 bytes both, written and read by memcpy), the unlit ones
// by zeros -- no second array of the histogram's size to fault in (16 MB at 1024^2; a fresh
// page is dear on a virtual machine whose host takes freed memory back).
void logScaleInPlace(FlameHistogram &h, double k1, double k2, int threads)
{
    static_assert(sizeof(Accum) == sizeof(Bucket));
    const std::size_t n = h.cells.size();
    onThreads(threads, [&](int t) {
        const std::size_t first = n * std::size_t(t) / std::size_t(threads);
        const std::size_t last = n * std::size_t(t + 1) / std::size_t(threads);
        for (std::size_t i = first; i < last; ++i) {
            const Bucket c = h.cells[i];
            Accum out{0, 0, 0, 0};
            if (c[3] != 0) {  // as logScale into a cleared accumulator
                const double a = c[3];
                const double ls = k1 * std::log(1.0 + a * k2) / a;
                out = {float(c[0] * ls), float(c[1] * ls), float(c[2] * ls), float(a * ls)};
            }
            std::memcpy(&h.cells[i], &out, sizeof out);
        }
    });
}

// The density estimator (rect.c, de_thread) on the rows [first, last) of the histogram, in
// row order. Writes reach `reach` rows above and below.
void estimateRows(const FlameHistogram &h, Accums &acc, const DensityEstimator &de,
                  double curve, int ss, double k1, double k2, int first, int last)
{
    const int w = h.width, hgt = h.height;
    const int half = ss / 2;
    const bool scf = (ss & 1) == 0;
    const double scfact = std::pow(ss / (ss + 1.0), 2.0);
    auto add = [&](int x, int y, const double c[4]) {
        if (y >= 0 && y < hgt && x >= 0 && x < w) {
            Accum &a = acc[std::size_t(x) + std::size_t(y) * std::size_t(w)];
            a[0] += c[0];
            a[1] += c[1];
            a[2] += c[2];
            a[3] += c[3];
        }
    };
    for (int j = first; j < last; ++j) {
        for (int i = ss - 1; i < w - (ss - 1); ++i) {
            const Bucket &bucket = h.cells[std::size_t(i) + std::size_t(j) * std::size_t(w)];
            if (bucket[3] == 0)
                continue;
            const double b[4] = {double(bucket[0]), double(bucket[1]), double(bucket[2]),
                                 double(bucket[3])};
            double fSelect = 0.0;
            for (int ii = -half; ii <= half; ++ii)
                for (int jj = -half; jj <= half; ++jj)
                    fSelect += h.cells[std::size_t(i + ii) + std::size_t(j + jj) * std::size_t(w)][3]
                               / 255.0;
            if (scf)
                fSelect *= scfact;
            int k;
            if (fSelect > de.maxFilteredCounts)
                k = de.maxFilterIndex;
            else if (fSelect <= kDeThreshold)
                k = int(std::ceil(fSelect)) - 1;
            else
                k = kDeThreshold + int(std::floor(std::pow(fSelect - kDeThreshold, curve)));
            k = std::clamp(k, 0, de.maxFilterIndex);
            std::size_t idx = std::size_t(k) * std::size_t(de.kernelSize);
            const int width = int(std::ceil(de.filterWidths[std::size_t(k)])) - 1;
            const double scale = k1 * std::log(1.0 + b[3] * k2) / b[3];
            for (int jj = 0; jj <= width; ++jj) {
                for (int ii = 0; ii <= jj; ++ii, ++idx) {
                    const double coef = de.coefs[idx];
                    if (coef == 0.0)
                        continue;
                    const double ls = coef * scale;
                    const double c[4] = {b[0] * ls, b[1] * ls, b[2] * ls, b[3] * ls};
                    if (jj == 0 && ii == 0) {
                        add(i, j, c);
                    } else if (ii == 0) {
                        add(i + jj, j, c);
                        add(i - jj, j, c);
                        add(i, j + jj, c);
                        add(i, j - jj, c);
                    } else if (jj == ii) {
                        add(i + ii, j + jj, c);
                        add(i - ii, j + jj, c);
                        add(i + ii, j - jj, c);
                        add(i - ii, j - jj, c);
                    } else {
                        add(i + ii, j + jj, c);
                        add(i - ii, j + jj, c);
                        add(i + ii, j - jj, c);
                        add(i - ii, j - jj, c);
                        add(i + jj, j + ii, c);
                        add(i - jj, j + ii, c);
                        add(i + jj, j - ii, c);
                        add(i - jj, j - ii, c);
                    }
                }
            }
        }
    }
}

// The estimator over the histogram's rows in bands at least 2 reach + 1 rows high: the even
// bands side by side, then the odd ones. No two bands of a phase write the same cell, and each
// cell takes its sums in the same order on any number of threads.
void estimate(const FlameHistogram &h, Accums &acc, const DensityEstimator &de,
              double curve, int ss, double k1, double k2, int threads)
{
    const int first = ss - 1, last = h.height - (ss - 1);
    if (last <= first)
        return;
    const int reach = (de.kernelSize > 0 ? int(std::ceil(de.filterWidths[0])) : 1);
    const int band = std::max(2 * reach + 1, 16);
    const int bands = (last - first + band - 1) / band;
    for (int phase = 0; phase < 2; ++phase) {
        std::atomic<int> next{phase};
        onThreads(threads, [&](int) {
            for (int b = next.fetch_add(2); b < bands; b = next.fetch_add(2))
                estimateRows(h, acc, de, curve, ss, k1, k2, first + b * band,
                             std::min(last, first + (b + 1) * band));
        });
    }
}

} // namespace

// palettes.c's rgb2hsv / hsv2rgb (h 0..6).
void rgbToHsv(const double rgb[3], double hsv[3])
{
    const double r = rgb[0], g = rgb[1], b = rgb[2];
    const double max = std::max({r, g, b}), min = std::min({r, g, b});
    const double del = max - min;
    const double s = max != 0.0 ? del / max : 0.0;
    double h = 0;
    if (s != 0.0) {
        const double rc = (max - r) / del, gc = (max - g) / del, bc = (max - b) / del;
        if (r == max)
            h = bc - gc;
        else if (g == max)
            h = 2 + rc - bc;
        else
            h = 4 + gc - rc;
        if (h < 0)
            h += 6;
    }
    hsv[0] = h;
    hsv[1] = s;
    hsv[2] = max;
}

void hsvToRgb(const double hsv[3], double rgb[3])
{
    double h = hsv[0];
    const double s = hsv[1], v = hsv[2];
    h = std::fmod(h, 6.0);
    if (h < 0)
        h += 6.0;
    const int j = int(std::floor(h));
    const double f = h - j, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    switch (j) {
    case 1: rgb[0] = q, rgb[1] = v, rgb[2] = p; break;
    case 2: rgb[0] = p, rgb[1] = v, rgb[2] = t; break;
    case 3: rgb[0] = p, rgb[1] = q, rgb[2] = v; break;
    case 4: rgb[0] = t, rgb[1] = p, rgb[2] = v; break;
    case 5: rgb[0] = v, rgb[1] = p, rgb[2] = q; break;
    default: rgb[0] = v, rgb[1] = t, rgb[2] = p; break;
    }
}

std::string_view filterShapeName(FilterShape shape)
{
    return kShapeNames[std::size_t(shape)];
}

int filterShapeId(std::string_view name)
{
    for (std::size_t i = 0; i < kShapeNames.size(); ++i)
        if (kShapeNames[i] == name)
            return int(i);
    return -1;
}

SpatialFilter spatialFilter(FilterShape shape, double radius, int supersample)
{
    const double support = kSupport[std::size_t(shape)];
    const double fw = 2.0 * support * supersample * radius;
    if (!(fw >= 0) || !(fw < kMaxFilterWidth))
        throw InputError(formatMessage(tr("the spatial filter of radius %1 at supersample %2 "
                                          "would be %3 cells wide; at most %4"),
                                       streamedNumber(radius), supersample,
                                       streamedNumber(std::ceil(fw)), kMaxFilterWidth));
    int width = int(fw) + 1;
    if ((width ^ supersample) & 1)
        ++width;
    const double adjust = fw > 0.0 ? support * width / fw : 1.0;
    // The shape at the cells' centres; flam3's kernel is its product with itself.
    std::vector<double> f(static_cast<std::size_t>(width));
    for (int i = 0; i < width; ++i)
        f[std::size_t(i)] = shapeValue(shape, ((2.0 * i + 1.0) / double(width) - 1.0) * adjust);
    SpatialFilter out;
    out.width = width;
    out.coefs.resize(std::size_t(width) * std::size_t(width));
    for (int i = 0; i < width; ++i)
        for (int j = 0; j < width; ++j)
            out.coefs[std::size_t(i) + std::size_t(j) * std::size_t(width)] =
                f[std::size_t(i)] * f[std::size_t(j)];
    double sum = 0;
    for (double c : out.coefs)
        sum += c;
    // flam3 refuses a sum of exactly 0: the shape vanishes at every sample point (a box or
    // hermite filter of a quarter pixel at supersample 2). Its zeros in floating point (the
    // windowed sincs at their nodes) leave a sum of about 1e-66 here, and its normalised
    // kernel would be noise: refused the same.
    if (!(std::abs(sum) > 1e-12) || !std::isfinite(sum))
        throw InputError(formatMessage(tr("the spatial filter of radius %1 is too small"),
                                       streamedNumber(radius)));
    for (double &c : out.coefs)
        c /= sum;
    double rowSum = 0;
    for (double v : f)
        rowSum += v;
    out.row = std::move(f);
    for (double &v : out.row)
        v /= rowSum;
    return out;
}

DensityEstimator densityEstimator(double maxRadius, double minRadius, double curve,
                                  int supersample)
{
    if (!(curve > 0.0))
        throw InputError(tr("the estimator curve must be > 0"));
    if (!(maxRadius >= minRadius) || !(minRadius >= 0) || !std::isfinite(maxRadius))
        throw InputError(formatMessage(tr("the estimator radius %1 must be at least its "
                                          "minimum %2 (and not negative)"),
                                       streamedNumber(maxRadius), streamedNumber(minRadius)));
    const double compMax = maxRadius * supersample + 1;
    const double compMin = minRadius * supersample + 1;
    const double countD = std::pow(compMax / compMin, 1.0 / curve);
    if (!(countD <= 1e7))
        throw InputError(formatMessage(tr("the estimator (radius %1, minimum %2, curve %3) "
                                          "needs too many kernels (%4)"),
                                       streamedNumber(maxRadius), streamedNumber(minRadius),
                                       streamedNumber(curve), streamedNumber(countD)));
    const int count = int(std::ceil(countD));
    constexpr int keep = 100;
    DensityEstimator de;
    int maxIndex;
    if (count > keep) {
        maxIndex = int(std::ceil(kDeThreshold + std::pow(count - kDeThreshold, curve))) + 1;
        de.maxFilteredCounts =
            int(std::pow(double(maxIndex - kDeThreshold), 1.0 / curve)) + kDeThreshold;
    } else {
        maxIndex = count;
        de.maxFilteredCounts = maxIndex;
    }
    const int rowSize = int(2 * std::ceil(compMax) - 1);
    const int half = (rowSize - 1) / 2;
    const double kernelSize = (half + 1.0) * (2.0 + half) / 2.0;
    if (kernelSize * maxIndex > kMaxEstimatorCoefs)
        throw InputError(formatMessage(tr("the estimator of radius %1 at supersample %2 needs "
                                          "%3 coefficients; at most %4"),
                                       streamedNumber(maxRadius), supersample,
                                       streamedNumber(kernelSize * maxIndex),
                                       streamedNumber(kMaxEstimatorCoefs)));
    de.kernelSize = int(kernelSize);
    de.coefs.assign(std::size_t(maxIndex) * std::size_t(de.kernelSize), 0.0);
    de.filterWidths.assign(std::size_t(maxIndex), 0.0);
    de.maxFilterIndex = 0;
    for (int loop = 0; loop < maxIndex; ++loop) {
        double h;
        if (loop < keep)
            h = compMax / std::pow(loop + 1, curve);
        else
            h = compMax / std::pow(std::pow(loop - keep, 1.0 / curve) + keep + 1, curve);
        if (h <= compMin) {
            h = compMin;
            de.maxFilterIndex = loop;
        }
        de.filterWidths[std::size_t(loop)] = h;
        double sum = 0.0;
        for (int dej = -half; dej <= half; ++dej)
            for (int dek = -half; dek <= half; ++dek) {
                const double d = std::sqrt(double(dej * dej + dek * dek)) / h;
                if (d <= 1.0)
                    sum += gaussian(kSupport[0] * d);
            }
        std::size_t idx = std::size_t(loop) * std::size_t(de.kernelSize);
        for (int dej = 0; dej <= half; ++dej)
            for (int dek = 0; dek <= dej; ++dek, ++idx) {
                const double d = std::sqrt(double(dej * dej + dek * dek)) / h;
                de.coefs[idx] = d > 1.0 ? 0.0 : gaussian(kSupport[0] * d) / sum;
            }
        if (de.maxFilterIndex > 0)
            break;
    }
    if (de.maxFilterIndex == 0)
        de.maxFilterIndex = maxIndex - 1;
    return de;
}

double flam3Alpha(double density, double gamma, double linearRange)
{
    if (!(density > 0))
        return 0;
    if (density < linearRange) {
        const double frac = density / linearRange;
        return (1.0 - frac) * density * (std::pow(linearRange, gamma) / linearRange)
               + frac * std::pow(density, gamma);
    }
    return std::pow(density, gamma);
}

void flam3NewRgb(const double c[4], double ls, double highpow, double rgb[3])
{
    if (ls == 0.0 || (c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0)) {
        rgb[0] = rgb[1] = rgb[2] = 0.0;
        return;
    }
    double maxa = -1.0, maxc = 0;
    for (int i = 0; i < 3; ++i) {
        const double a = ls * (c[i] / 255.0);
        if (a > maxa) {
            maxa = a;
            maxc = c[i] / 255.0;
        }
    }
    if (maxa > 255 && highpow >= 0.0) {
        // A saturated channel: keep the hue, lower the saturation by the highlight power.
        const double newls = 255.0 / maxc;
        const double ratio = std::pow(newls / ls, highpow);
        for (int i = 0; i < 3; ++i)
            rgb[i] = newls * (c[i] / 255.0) / 255.0;
        double hsv[3];
        rgbToHsv(rgb, hsv);
        hsv[1] *= ratio;
        hsvToRgb(hsv, rgb);
        for (int i = 0; i < 3; ++i)
            rgb[i] *= 255.0;
    } else {
        const double newls = 255.0 / maxc;
        double adjust = std::min(-highpow, 1.0);
        if (maxa <= 255)
            adjust = 1.0;
        for (int i = 0; i < 3; ++i)
            rgb[i] = ((1.0 - adjust) * newls + adjust * ls) * (c[i] / 255.0);
    }
}

FlameImage renderFlameImage(const FlameImageJob &job, const IterationControl &control)
{
    if (!job.flame)
        throw InputError(tr("there is no flame to draw"));
    const Flame &f = *job.flame;
    checkFlame(f);
    if (f.passes < 1 || f.passes > kMaxFlamePasses)
        throw InputError(formatMessage(tr("the flame's passes is %1; it takes 1 to %2"), f.passes,
                                       kMaxFlamePasses));
    RasterFrame frame = job.frame;
    frame.supersample = 1;
    frame.validate();
    const int W = frame.width, H = frame.height;
    const int ss = std::max(1, f.supersample);
    const SpatialFilter filter = spatialFilter(f.filterShape, f.filter, ss);
    // rect.c: the gutter the spatial filter needs, widened to the estimator's reach.
    int gutter = (filter.width - ss) / 2;
    int deWidth = f.estimatorRadius > 0 ? int(std::ceil(f.estimatorRadius)) * ss : 0;
    if (deWidth > 0)
        deWidth += ss - 1;
    int deOffset = 0;
    if (deWidth > gutter) {
        deOffset = deWidth - gutter;
        gutter = deWidth;
    }
    const bool estimator = f.estimatorRadius > 0;
    DensityEstimator de;
    if (estimator)
        de = densityEstimator(f.estimatorRadius, f.estimatorMinimum, f.estimatorCurve, ss);
    const double cellsX = double(ss) * W + 2.0 * gutter, cellsY = double(ss) * H + 2.0 * gutter;
    if (cellsX > 32768 || cellsY > 32768 || cellsX < 1 || cellsY < 1)
        throw InputError(formatMessage(tr("a %1 x %2 picture of the flame at supersample %3 needs "
                                          "%4 x %5 histogram cells; at most 32768 a side"),
                                       W, H, ss, streamedNumber(cellsX), streamedNumber(cellsY)));
    // Memory: a histogram of buckets per thread, then the log-scaled cells (floats); the
    // spatial filter's rows are held for a band of 16 pixel rows per thread (small beside them).
    int threads = std::clamp(job.threads, 1, kChaosStreams);
    const double cells = cellsX * cellsY;
    // One pass without the estimator log-scales the histogram in place (logScaleInPlace).
    const bool inPlace = !estimator && f.passes == 1;
    auto bytes = [&](int t) {
        return cells * (double(sizeof(Bucket)) * t + (inPlace ? 0.0 : double(sizeof(Accum))));
    };
    while (threads > 1 && bytes(threads) > kMaxFlameHistogramBytes)
        --threads;
    if (bytes(1) > kMaxFlameHistogramBytes)
        throw InputError(formatMessage(tr("a %1 x %2 picture of the flame at supersample %3 needs "
                                          "%4 MB of histograms; at most %5 MB"),
                                       W, H, ss, std::lround(bytes(1) / (1 << 20)),
                                       std::lround(kMaxFlameHistogramBytes / (1 << 20))));

    // The histogram's frame: the picture's, widened by the gutter's cells.
    const double cx = (frame.x1 - frame.x0) / (double(ss) * W);
    const double cy = (frame.y1 - frame.y0) / (double(ss) * H);
    FlameRaster raster;
    raster.flame = &f;
    raster.frame.width = int(cellsX);
    raster.frame.height = int(cellsY);
    raster.frame.supersample = 1;
    raster.frame.x0 = frame.x0 - gutter * cx;
    raster.frame.x1 = frame.x1 + gutter * cx;
    raster.frame.y0 = frame.y0 - gutter * cy;
    raster.frame.y1 = frame.y1 + gutter * cy;
    raster.accumulation = Accumulation::Density;
    raster.samples = job.samples;
    raster.seed = job.seed;
    raster.threads = threads;
    // The buffers of the last picture on this thread, reused when they are not huge (a window
    // renders many pictures of one size; an export's gigabytes are given back).
    struct Workspace {
        FlameHistogram histogram;
        std::vector<FlameHistogram> parts;
        Accums acc;
        std::vector<Cell> across;
    };
    static thread_local Workspace kept;
    Workspace fresh;
    const bool keep = bytes(threads) <= kKeptFlameBytes;
    Workspace &w = keep ? kept : fresh;
    if (!keep)
        kept = Workspace{};
    FlameHistogram &histogram = w.histogram;
    FlameImage out;
    // rect.c: k1 from the brightness, k2 from the sample density per unit area; each of flam3's
    // passes (its batches) draws its share of the samples in a histogram of its own, log-scaled
    // with k1 / passes and k2 * passes into the sum.
    const int passes = f.passes;
    const double ppux = W / (frame.x1 - frame.x0), ppuy = H / (frame.y1 - frame.y0);
    const double area = W * double(H) / (ppux * ppuy);
    const double sampleDensity = std::max<double>(1.0, double(job.samples)) / (double(W) * H);
    const double k1 = f.brightness * 255.0 * 268.0 / 256.0 / passes;
    const double k2 = double(ss) * ss * passes / (area * 255.0 * sampleDensity);
    Accums &acc = w.acc;
    // The log-scaled cells as the filter reads them: acc's, or the histogram's own.
    const std::byte *scaled = nullptr;
    for (int pass = 0; pass < passes; ++pass) {
        raster.samples = job.samples / std::uint64_t(passes)
                         + (std::uint64_t(pass) < job.samples % std::uint64_t(passes) ? 1 : 0);
        raster.seed = job.seed + std::uint64_t(pass) * 0x9E3779B97F4A7C15ull;
        const FlameStats stats = accumulateFlameColours(raster, histogram, control, &w.parts);
        out.stats.samples += stats.samples;
        out.stats.badValues += stats.badValues;
        out.stats.offscreen += stats.offscreen;
        out.stats.cancelled = stats.cancelled;
        if (out.stats.cancelled)
            return out;
        if (inPlace) {
            logScaleInPlace(histogram, k1, k2, threads);
            scaled = reinterpret_cast<const std::byte *>(histogram.cells.data());
        } else {
            if (pass == 0)
                acc.assign(histogram.cells.size(), Accum{0, 0, 0, 0});
            if (estimator)
                estimate(histogram, acc, de, f.estimatorCurve, ss, k1, k2, threads);
            else
                logScale(histogram, acc, k1, k2, threads);
            scaled = reinterpret_cast<const std::byte *>(acc.data());
        }
        if (control.cancel && control.cancel->load()) {
            out.stats.cancelled = true;
            return out;
        }
    }

    // The spatial filter (separable: flam3's kernel is the product of one row by itself,
    // normalised) at the pixels' cells, then the tone of each pixel (earlyclip off). Each
    // thread takes bands of kBand pixel rows: the cells' rows the band reads filtered across
    // (into its own buffer), then down, so that the rows filtered across are held for one band
    // at a time, not for the whole picture (32 MB at 1024^2). The same sums in the same order.
    constexpr int kBand = 16;
    const int fw = filter.width;
    const std::vector<double> &k1d = filter.row;
    const std::size_t stride = std::size_t(cellsX);
    const std::size_t bandRows = std::size_t((kBand - 1) * ss + fw);
    std::vector<Cell> &across = w.across;
    across.assign(std::size_t(threads) * bandRows * std::size_t(W), Cell{0, 0, 0, 0});
    const double g = 1.0 / f.gamma;
    const double vibrancy = f.vibrancy;
    // At vibrancy 1 the dull part of a channel is 0 times a finite power for sums >= 0 and
    // g <= 1 (a power of at most the sum); otherwise it is computed.
    const bool vibrant = vibrancy == 1.0 && g <= 1.0;
    const double background[3] = {f.background.r * 256.0, f.background.g * 256.0,
                                  f.background.b * 256.0};
    out.width = W;
    out.height = H;
    out.argb.assign(std::size_t(W) * std::size_t(H), 0);
    onThreads(threads, [&](int t) {
        Cell *band = across.data() + std::size_t(t) * bandRows * std::size_t(W);
        for (int j0 = t * kBand; j0 < H; j0 += threads * kBand) {
            const int j1 = std::min(H, j0 + kBand);
            const int y0 = deOffset + j0 * ss;          // the first cells' row the band reads
            const int readRows = (j1 - 1 - j0) * ss + fw;
            for (int r = 0; r < readRows; ++r)
                for (int i = 0; i < W; ++i) {
                    Cell s{0, 0, 0, 0};
                    const std::byte *row =
                        scaled
                        + (std::size_t(y0 + r) * stride + std::size_t(deOffset + i * ss))
                              * sizeof(Accum);
                    for (int ii = 0; ii < fw; ++ii) {
                        const double k = k1d[std::size_t(ii)];
                        Accum a;
                        std::memcpy(&a, row + std::size_t(ii) * sizeof(Accum), sizeof a);
                        for (int c = 0; c < 4; ++c)
                            s[std::size_t(c)] += k * a[std::size_t(c)];
                    }
                    band[std::size_t(r) * std::size_t(W) + std::size_t(i)] = s;
                }
            for (int j = j0; j < j1; ++j)
                for (int i = 0; i < W; ++i) {
                    double s[4] = {0, 0, 0, 0};
                    for (int jj = 0; jj < fw; ++jj) {
                        const double k = k1d[std::size_t(jj)];
                        const Cell &a = band[std::size_t((j - j0) * ss + jj) * std::size_t(W)
                                             + std::size_t(i)];
                        for (int c = 0; c < 4; ++c)
                            s[c] += k * a[std::size_t(c)];
                    }
                    double alpha = 0, ls = 0;
                    if (s[3] > 0) {
                        const double tmp = s[3] / 255.0;
                        alpha = flam3Alpha(tmp, g, f.gammaThreshold);
                        ls = vibrancy * 256.0 * alpha / tmp;
                        alpha = std::clamp(alpha, 0.0, 1.0);
                    }
                    double rgb[3];
                    flam3NewRgb(s, ls, f.highlightPower, rgb);
                    std::uint32_t px = 0xff000000u;
                    for (int c = 0; c < 3; ++c) {
                        // (1 - vibrancy) 256 (s / 255)^g: +0 at vibrancy 1 (flam3's default),
                        // where the power is taken only when it could be NaN or infinite.
                        double dull = 0.0;
                        if (!vibrant || !(s[c] >= 0))
                            dull = (1.0 - vibrancy) * 256.0 * std::pow(s[c] / 255.0, g);
                        double a = rgb[c] + dull + (1.0 - alpha) * background[c];
                        // NaN (a negative lobe's sum under the gamma) as flam3's clamp would not.
                        if (!(a >= 0))
                            a = 0;
                        if (a > 255)
                            a = 255;
                        px |= std::uint32_t(a) << (16 - 8 * c);
                    }
                    out.argb[std::size_t(j) * std::size_t(W) + std::size_t(i)] = px;
                }
        }
    });
    return out;
}

} // namespace awb::flame
