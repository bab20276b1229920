#include "core/render/Engine.h"

#include "core/Messages.h"
#include "core/ifs/Random.h"

#include <Eigen/LU>
#include <Eigen/QR>

#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <memory>
#include <thread>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace awb {

namespace {
bool haveAvx2();
std::atomic<bool> g_baselineKernels{false};
} // namespace

const char *engineKernels()
{
    return haveAvx2() ? "avx2" : "baseline";
}

void forceBaselineKernels(bool on)
{
    g_baselineKernels = on;
}

std::uint32_t addressLabel(const std::uint8_t *address, int length, int prefix, int maps)
{
    std::uint32_t label = 0;
    for (int k = 0; k < prefix; ++k)
        label = label * std::uint32_t(maps) + (k < length ? address[k] : 0u);
    return label;
}

namespace {

constexpr int kMaxFixedDim = 12;
constexpr int kInterleave = 4;  // orbits advanced together per thread
// Per-thread histograms beyond this many bytes in all: fewer threads.
constexpr double kHistogramBudget = 192.0 * 1024 * 1024;

// ---- the generic rasteriser (cells, y down) ------------------------------------------------

struct Plotter {
    DensityImage &img;
    int w, h;
    const std::uint8_t *coords;  // colour coordinate of each label (density)

    // Images whose every vertex lies in [0, xMax) x [0, yMax) need no clipping (imageInside).
    double xMax() const { return double(w) - 1e-9; }
    double yMax() const { return double(h) - 1e-9; }

    void cell(int x, int y, std::uint32_t label)
    {
        if (x < 0 || y < 0 || x >= w || y >= h) {
            ++img.offscreen;
            return;
        }
        img.add(std::size_t(y) * w + x, label, coords);
    }

    // The cells of the segment from (sx, sy) to (ex, ey), sampled at least once per cell side,
    // to emit(x, y) (consecutive repeats dropped).
    template <class Emit>
    static void walk(double sx, double sy, double ex, double ey, Emit &&emit)
    {
        const int steps = int(std::ceil(std::max(std::abs(ex - sx), std::abs(ey - sy)))) + 1;
        int lastX = INT_MIN, lastY = INT_MIN;
        for (int s = 0; s <= steps; ++s) {
            const double t = double(s) / steps;
            const int x = int(std::floor(sx + t * (ex - sx)));
            const int y = int(std::floor(sy + t * (ey - sy)));
            if (x != lastX || y != lastY)
                emit(x, y);
            lastX = x;
            lastY = y;
        }
    }

    void line(double ax, double ay, double bx, double by, std::uint32_t label)
    {
        // Clip to the raster (Liang-Barsky) so that a huge segment costs nothing off screen.
        double t0 = 0, t1 = 1;
        const double dx = bx - ax, dy = by - ay;
        const double p[4] = {-dx, dx, -dy, dy};
        const double q[4] = {ax, xMax() - ax, ay, yMax() - ay};
        for (int k = 0; k < 4; ++k) {
            if (p[k] == 0) {
                if (q[k] < 0) {
                    ++img.offscreen;
                    return;
                }
            } else {
                const double r = q[k] / p[k];
                if (p[k] < 0)
                    t0 = std::max(t0, r);
                else
                    t1 = std::min(t1, r);
            }
        }
        if (t0 > t1) {
            ++img.offscreen;
            return;
        }
        walk(ax + t0 * dx, ay + t0 * dy, ax + t1 * dx, ay + t1 * dy,
             [&](int x, int y) { cell(x, y, label); });
    }

    // Even-odd fill: emit(x, y) for the cells of the raster whose centres lie inside the
    // polygon (n xy pairs); xs holds at least n numbers (the crossings of one row).
    template <class Emit>
    void fill(const double *s, int n, double *xs, Emit &&emit) const
    {
        double ymin = 1e300, ymax = -1e300;
        for (int i = 0; i < n; ++i)
            ymin = std::min(ymin, s[2 * i + 1]), ymax = std::max(ymax, s[2 * i + 1]);
        ymin = std::max(0.0, ymin);
        ymax = std::min(double(h), ymax);
        for (int y = int(std::floor(ymin)); y < int(std::ceil(ymax)); ++y) {
            const double yc = y + 0.5;
            int k = 0;
            for (int i = 0; i < n; ++i) {
                const int j = i + 1 < n ? i + 1 : 0;
                const double y0 = s[2 * i + 1], y1 = s[2 * j + 1];
                if ((y0 <= yc && y1 > yc) || (y1 <= yc && y0 > yc))
                    xs[k++] = s[2 * i] + (yc - y0) / (y1 - y0) * (s[2 * j] - s[2 * i]);
            }
            // Few crossings (two for a convex image): insertion sort.
            for (int a = 1; a < k; ++a)
                for (int b = a; b > 0 && xs[b] < xs[b - 1]; --b)
                    std::swap(xs[b], xs[b - 1]);
            for (int c = 0; c + 1 < k; c += 2) {
                const int xa = std::max(0, int(std::ceil(xs[c] - 0.5)));
                const int xb = std::min(w - 1, int(std::floor(xs[c + 1] - 0.5)));
                for (int x = xa; x <= xb; ++x)
                    emit(x, y);
            }
        }
    }

    // One image of the start set, already in cells (n xy pairs). A polygon or polyline whose
    // image lies inside one cell is one hit there.
    void image(const double *s, int n, StartSet::Kind kind, std::uint32_t label,
               std::vector<double> &xs)
    {
        for (int i = 0; i < 2 * n; ++i)
            if (!std::isfinite(s[i])) {
                ++img.nonFinite;
                return;
            }
        if (kind == StartSet::Kind::Points || n == 1) {
            for (int i = 0; i < n; ++i)
                cell(int(std::floor(s[2 * i])), int(std::floor(s[2 * i + 1])), label);
            return;
        }
        double x0 = s[0], x1 = s[0], y0 = s[1], y1 = s[1];
        for (int i = 1; i < n; ++i) {
            x0 = std::min(x0, s[2 * i]), x1 = std::max(x1, s[2 * i]);
            y0 = std::min(y0, s[2 * i + 1]), y1 = std::max(y1, s[2 * i + 1]);
        }
        if (std::floor(x0) == std::floor(x1) && std::floor(y0) == std::floor(y1)) {
            cell(int(std::floor(x0)), int(std::floor(y0)), label);
            return;
        }
        if (xs.size() < std::size_t(n))
            xs.resize(std::size_t(n));
        if (x0 >= 0 && y0 >= 0 && x1 < xMax() && y1 < yMax()) {
            imageInside(s, n, kind, label, xs.data(), x0, y0, x1, y1);
            return;
        }
        auto emit = [&](int x, int y) { cell(x, y, label); };
        if (kind == StartSet::Kind::Polygon && n >= 3)
            fill(s, n, xs.data(), emit);
        const int segments = kind == StartSet::Kind::Polygon ? n : n - 1;
        for (int r = 0; r < segments; ++r) {
            const int q = r + 1 < n ? r + 1 : 0;
            line(s[2 * r], s[2 * r + 1], s[2 * q], s[2 * q + 1], label);
        }
    }

    // The cells of a polyline or polygon whose vertices all lie inside [0, xMax) x [0, yMax),
    // to emit(x, y): the filled cells of a polygon, then its edges' samples. No clipping: it
    // would leave t0 = 0 and t1 = 1 there, rounding included.
    template <class Emit>
    void traceInside(const double *s, int n, StartSet::Kind kind, double *xs, Emit &&emit) const
    {
        if (kind == StartSet::Kind::Polygon && n >= 3)
            fill(s, n, xs, emit);
        const int segments = kind == StartSet::Kind::Polygon ? n : n - 1;
        for (int r = 0; r < segments; ++r) {
            const int q = r + 1 < n ? r + 1 : 0;
            const double dx = s[2 * q] - s[2 * r], dy = s[2 * q + 1] - s[2 * r + 1];
            walk(s[2 * r] + 0.0 * dx, s[2 * r + 1] + 0.0 * dy, s[2 * r] + 1.0 * dx,
                 s[2 * r + 1] + 1.0 * dy, emit);
        }
    }

    // A polyline or polygon of n >= 2 vertices over several cells, inside the raster, with
    // bounding box [x0, x1] x [y0, y1]. An image within a 2 x 2 block of cells (deep levels)
    // adds one hit to each cell it covers, however many of its samples fall there. xs: n
    // numbers.
    void imageInside(const double *s, int n, StartSet::Kind kind, std::uint32_t label,
                     double *xs, double x0, double y0, double x1, double y1)
    {
        // Coordinates are >= 0 here: truncation is the floor.
        const int bx = int(x0), by = int(y0);
        if (int(x1) - bx > 1 || int(y1) - by > 1) {
            traceInside(s, n, kind, xs, [&](int x, int y) { cell(x, y, label); });
            return;
        }
        unsigned mask = 0;
        traceInside(s, n, kind, xs, [&](int x, int y) {
            const unsigned dx = unsigned(x - bx), dy = unsigned(y - by);
            if ((dx | dy) <= 1u)
                mask |= 1u << (2 * dy + dx);
            else
                cell(x, y, label);  // a sample rounded past the block's edge
        });
        for (unsigned k = 0; k < 4; ++k)
            if (mask & (1u << k))
                cell(bx + int(k & 1u), by + int(k >> 1), label);
    }
};

// A view as an affine map from IFS space straight to raster cells: cell = x V + c.
struct CellView {
    Mat V;      // D x 2
    double c[2];
};

std::vector<CellView> cellViews(const std::vector<Projection> &views, const RasterFrame &f, int dim)
{
    const double sx = f.cellsX() / (f.x1 - f.x0), sy = f.cellsY() / (f.y1 - f.y0);
    std::vector<CellView> out;
    for (const Projection &v : views) {
        if (v.V.rows() != dim || v.V.cols() < 2 || v.c.size() != v.V.cols())
            throw InputError(coreTranslate("awb::render", "a view does not fit the IFS space"));
        CellView cv;
        cv.V.resize(dim, 2);
        cv.V.col(0) = v.V.col(0) * sx;
        cv.V.col(1) = -v.V.col(1) * sy;
        cv.c[0] = (v.c(0) - f.x0) * sx;
        cv.c[1] = (f.y1 - v.c(1)) * sy;
        out.push_back(std::move(cv));
    }
    return out;
}

// ---- fixed-dimension kernels ------------------------------------------------------------------

// The maps and views of one job in flat arrays: a[i][k][j] (y_j = b_j + sum_k x_k a_kj),
// view[v][k][0..1].
template <int D>
struct Flat {
    int n = 0, views = 0;
    std::vector<double> a, b, v, c;

    Flat(const Ifs &ifs, const std::vector<CellView> &cv) : n(ifs.size()), views(int(cv.size()))
    {
        a.resize(std::size_t(n) * D * D);
        b.resize(std::size_t(n) * D);
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < D; ++k) {
                b[i * D + k] = ifs.maps[i].b(k);
                for (int j = 0; j < D; ++j)
                    a[(i * D + k) * D + j] = ifs.maps[i].A(k, j);
            }
        v.resize(std::size_t(views) * D * 2);
        c.resize(std::size_t(views) * 2);
        for (int q = 0; q < views; ++q) {
            for (int k = 0; k < D; ++k)
                for (int j = 0; j < 2; ++j)
                    v[(q * D + k) * 2 + j] = cv[q].V(k, j);
            c[q * 2] = cv[q].c[0];
            c[q * 2 + 1] = cv[q].c[1];
        }
    }
};

// Random iteration with one view runs in coordinates whose first two are the view's raster
// cells, x' = x W + t with W = [V | an orthonormal complement of V] and t = (c, 0, ..., 0):
// the maps become x' -> x' W^-1 A W + (b W + t - t W^-1 A W), and a point's cell is read off
// its first two coordinates instead of being projected (2D multiply-adds fewer per point).
// False (the state stays as it was) when the view has not rank 2.
template <int D>
bool toScreenSpace(const Flat<D> &F, Flat<D> &out, double x0[D])
{
    if (D < 2 || F.views != 1)
        return false;
    Mat V(D, 2);
    for (int k = 0; k < D; ++k)
        for (int j = 0; j < 2; ++j)
            V(k, j) = F.v[k * 2 + j];
    Eigen::HouseholderQR<Mat> qr(V);
    const Mat Q = qr.householderQ();
    Mat W(D, D);
    W.leftCols(2) = V;
    if (D > 2)
        W.rightCols(D - 2) = Q.rightCols(D - 2);
    Eigen::FullPivLU<Mat> lu(W);
    // The cells' scale is in W: judge the rank relative to it.
    lu.setThreshold(1e-10);
    if (!lu.isInvertible())
        return false;
    const Mat Wi = lu.inverse();
    RowVec t = RowVec::Zero(D);
    t(0) = F.c[0];
    t(1) = F.c[1];
    out = F;
    for (int i = 0; i < F.n; ++i) {
        Mat A(D, D);
        RowVec b(D);
        for (int k = 0; k < D; ++k) {
            b(k) = F.b[i * D + k];
            for (int j = 0; j < D; ++j)
                A(k, j) = F.a[(i * D + k) * D + j];
        }
        const Mat A2 = Wi * A * W;
        const RowVec b2 = b * W + t - t * A2;
        for (int k = 0; k < D; ++k) {
            out.b[i * D + k] = b2(k);
            for (int j = 0; j < D; ++j)
                out.a[(i * D + k) * D + j] = A2(k, j);
        }
    }
    std::fill(out.v.begin(), out.v.end(), 0.0);
    out.v[0] = 1.0;  // row 0, column 0
    out.v[3] = 1.0;  // row 1, column 1
    out.c[0] = out.c[1] = 0.0;
    RowVec x(D);
    for (int k = 0; k < D; ++k)
        x(k) = x0[k];
    const RowVec y = x * W + t;
    for (int k = 0; k < D; ++k)
        x0[k] = y(k);
    return true;
}

// The cell index of (sx, sy) in a w x h raster, or -1 off it. NaN, infinities and numbers
// beyond the int range count as off: the conversion is SSE2's cvttsd2si (defined for every
// input, 0x80000000 when out of range), and the bounds are tested on the integers. Cell k
// covers [k, k+1): the conversion truncates sx + 1 so that (-1, 0) lands at -1, not 0.
inline std::int32_t cellIndex(double sx, double sy, int w, int h)
{
#if defined(__SSE2__)
    const unsigned ux = unsigned(_mm_cvttsd_si32(_mm_set_sd(sx + 1.0))) - 1u;
    const unsigned uy = unsigned(_mm_cvttsd_si32(_mm_set_sd(sy + 1.0))) - 1u;
    const bool in = (ux < unsigned(w)) & (uy < unsigned(h));
    return in ? std::int32_t(uy * unsigned(w) + ux) : -1;
#else
    const bool in = (sx >= 0.0) & (sy >= 0.0) & (sx < double(w)) & (sy < double(h));
    return in ? int(sy) * w + int(sx) : -1;
#endif
}

// ---- the leaves' vector kernels, baseline and AVX2 ----------------------------------------------
//
// The three loops of a fused leaf node (DfsKernel::leaves) over all N^m words at once: cell
// coordinates of every vertex, the images' bounding boxes, their corners' cell indices. On
// x86-64 each exists twice, for the baseline (SSE2) and for AVX2, chosen once per render by
// the processor (leafKernels). The AVX2 loops add and multiply the same numbers in the same
// order, without fused multiply-adds, so both give the same cells bit for bit.

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define AWB_AVX2_KERNELS 1
#define AWB_AVX2_TARGET __attribute__((target("avx2")))
#define AWB_INLINE_BODY __attribute__((always_inline)) inline
#else
#define AWB_INLINE_BODY inline
#endif

// s[r][k] = C[k] + sum_j X[r][j] L[j][k] for the n vertices X (rows of D) and k < len.
template <int D>
AWB_INLINE_BODY void fusedRowsBody(const double *__restrict C, const double *__restrict L,
                                   const double *__restrict X, int n, int len,
                                   double *__restrict s)
{
    for (int r = 0; r < n; ++r) {
        double *__restrict sr = s + std::size_t(r) * len;
        for (int k = 0; k < len; ++k)
            sr[k] = C[k];
        for (int j = 0; j < D; ++j) {
            const double xj = X[r * D + j];
            const double *__restrict lj = L + std::size_t(j) * len;
            for (int k = 0; k < len; ++k)
                sr[k] += xj * lj[k];
        }
    }
}

// Over the n rows of s: the smallest and largest of each of the len numbers, and their sum
// (NaN when one of them is NaN: min and max alone may pass a NaN over).
AWB_INLINE_BODY void boundsBody(const double *__restrict s, int n, int len,
                                double *__restrict lo, double *__restrict hi,
                                double *__restrict sum)
{
    for (int k = 0; k < len; ++k)
        lo[k] = hi[k] = sum[k] = s[k];
    for (int r = 1; r < n; ++r) {
        const double *__restrict sr = s + std::size_t(r) * len;
        for (int k = 0; k < len; ++k) {
            const double v = sr[k];
            lo[k] = v < lo[k] ? v : lo[k];
            hi[k] = v > hi[k] ? v : hi[k];
            sum[k] += v;
        }
    }
}

// cells[v] = cellIndex(xy[2v], xy[2v + 1], w, h) for v < words.
AWB_INLINE_BODY void cellsBody(const double *xy, int words, int w, int h, std::int32_t *cells)
{
    for (int v = 0; v < words; ++v)
        cells[v] = cellIndex(xy[2 * v], xy[2 * v + 1], w, h);
}

template <int D>
void fusedRowsBase(const double *C, const double *L, const double *X, int n, int len, double *s)
{
    fusedRowsBody<D>(C, L, X, n, len, s);
}
void boundsBase(const double *s, int n, int len, double *lo, double *hi, double *sum)
{
    boundsBody(s, n, len, lo, hi, sum);
}
void cellsBase(const double *xy, int words, int w, int h, std::int32_t *cells)
{
    cellsBody(xy, words, w, h, cells);
}

#if defined(AWB_AVX2_KERNELS)
template <int D>
AWB_AVX2_TARGET void fusedRowsAvx2(const double *C, const double *L, const double *X, int n,
                                   int len, double *s)
{
    fusedRowsBody<D>(C, L, X, n, len, s);
}
AWB_AVX2_TARGET void boundsAvx2(const double *s, int n, int len, double *lo, double *hi,
                                double *sum)
{
    boundsBody(s, n, len, lo, hi, sum);
}
// Four words at a time: cvttpd2dq is cvttsd2si on four numbers (0x80000000 when out of range
// or NaN), so the indices equal cellIndex's.
AWB_AVX2_TARGET void cellsAvx2(const double *xy, int words, int w, int h, std::int32_t *cells)
{
    const __m256d one = _mm256_set1_pd(1.0);
    const __m128i bias = _mm_set1_epi32(INT_MIN), ones = _mm_set1_epi32(-1);
    const __m128i W = _mm_set1_epi32(w);
    const __m128i wb = _mm_set1_epi32(int(unsigned(w) ^ 0x80000000u));
    const __m128i hb = _mm_set1_epi32(int(unsigned(h) ^ 0x80000000u));
    int v = 0;
    for (; v + 4 <= words; v += 4) {
        const __m256d a = _mm256_loadu_pd(xy + 2 * v);      // x0 y0 x1 y1
        const __m256d b = _mm256_loadu_pd(xy + 2 * v + 4);  // x2 y2 x3 y3
        // x0 x2 x1 x3 and y0 y2 y1 y3: words 0 2 1 3, put back in order after the conversion.
        const __m128i cx = _mm256_cvttpd_epi32(_mm256_add_pd(_mm256_unpacklo_pd(a, b), one));
        const __m128i cy = _mm256_cvttpd_epi32(_mm256_add_pd(_mm256_unpackhi_pd(a, b), one));
        const __m128i ux = _mm_sub_epi32(_mm_shuffle_epi32(cx, _MM_SHUFFLE(3, 1, 2, 0)), _mm_set1_epi32(1));
        const __m128i uy = _mm_sub_epi32(_mm_shuffle_epi32(cy, _MM_SHUFFLE(3, 1, 2, 0)), _mm_set1_epi32(1));
        // Unsigned ux < w and uy < h, as signed comparisons of the biased numbers.
        const __m128i in = _mm_and_si128(_mm_cmplt_epi32(_mm_xor_si128(ux, bias), wb),
                                         _mm_cmplt_epi32(_mm_xor_si128(uy, bias), hb));
        const __m128i index = _mm_add_epi32(_mm_mullo_epi32(uy, W), ux);
        _mm_storeu_si128(reinterpret_cast<__m128i *>(cells + v),
                         _mm_or_si128(_mm_and_si128(in, index), _mm_andnot_si128(in, ones)));
    }
    for (; v < words; ++v)
        cells[v] = cellIndex(xy[2 * v], xy[2 * v + 1], w, h);
}
#endif

template <int D>
struct LeafKernels {
    void (*rows)(const double *C, const double *L, const double *X, int n, int len, double *s);
    void (*bounds)(const double *s, int n, int len, double *lo, double *hi, double *sum);
    void (*cells)(const double *xy, int words, int w, int h, std::int32_t *cells);
    const char *isa;
};

bool haveAvx2()
{
#if defined(AWB_AVX2_KERNELS)
    static const bool avx2 = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") != 0;
    }();
    return avx2 && !g_baselineKernels.load(std::memory_order_relaxed);
#else
    return false;
#endif
}

template <int D>
LeafKernels<D> leafKernels()
{
#if defined(AWB_AVX2_KERNELS)
    if (haveAvx2())
        return {&fusedRowsAvx2<D>, &boundsAvx2, &cellsAvx2, "avx2"};
#endif
    return {&fusedRowsBase<D>, &boundsBase, &cellsBase, "baseline"};
}

// How a kernel stores a hit (DensityImage's layouts): in buckets, the smallest label (hits) or
// the colour coordinate (density); the count alone (a one-label image: a picture of one
// colour, in either mode); the count in the label's plane (label planes).
enum class Store { Hits, Colours, Counts, Planes };

template <Store M>
inline void addUnchecked(DensityImage &img, std::size_t i, std::uint32_t label,
                         const std::uint8_t *coords)
{
    if constexpr (M == Store::Hits)
        img.addHitUnchecked(i, label);
    else if constexpr (M == Store::Colours)
        img.addDensityUnchecked(i, coords[label]);
    else if constexpr (M == Store::Planes)
        img.addCountUnchecked(img.planeIndex(i, label));
    else
        img.addCountUnchecked(i);
}

template <Store M>
inline void plotCell(DensityImage &img, int w, int h, double sx, double sy, std::uint32_t label,
                     const std::uint8_t *coords)
{
    // NaN fails both comparisons and counts as off screen.
    if (sx >= 0.0 && sy >= 0.0 && sx < double(w) && sy < double(h)) {
        const std::size_t i = std::size_t(int(sy)) * std::size_t(w) + std::size_t(int(sx));
        if constexpr (M == Store::Hits)
            img.addHit(i, label);
        else if constexpr (M == Store::Colours)
            img.addDensity(i, coords[label]);
        else if constexpr (M == Store::Planes)
            img.addCount(img.planeIndex(i, label));
        else
            img.addCount(i);
    } else {
        ++img.offscreen;
    }
}

struct Progress {
    const IterationControl &control;
    std::atomic<std::uint64_t> &done;
    double total;
    bool tick(std::uint64_t n) const
    {
        const std::uint64_t d = done.fetch_add(n) + n;
        if (control.progress)
            control.progress(std::min(1.0, double(d) / total));
        return !(control.cancel && control.cancel->load(std::memory_order_relaxed));
    }
};

// K orbits of random iteration advanced together in blocks of kBlock steps, in three passes
// per block so that each runs at its own speed: (1) the map choices of every orbit from its
// own stream (Random.h), (2) the geometry, orbits interleaved so that the latency of one map
// application hides behind the others, ending in a cell index per point, (3) the scatter of
// the points into the histogram.
constexpr int kBlock = 256;

// Equally likely map choices of K orbits for `steps` steps, maps[s][k] for orbit k: two
// per 64-bit draw of the orbit's own stream (multiply-shift of each half by n: a bias below
// 2^-32), the high half first; an odd last step uses the high half of one more draw. The
// baseline runs the streams one after the other; for four orbits, the AVX2 version advances
// them together in the four 64-bit lanes of a register (xoshiro256+ is adds, shifts and xors), with
// the same draws and the same choices, bit for bit.
template <int K>
void uniformChoicesBase(Xoshiro256 *rngs, int steps, std::uint64_t n, std::uint8_t (*maps)[K])
{
    for (int k = 0; k < K; ++k) {
        Xoshiro256 rng = rngs[k];
        int s = 0;
        for (; s + 1 < steps; s += 2) {
            const std::uint64_t r = rng.next();
            maps[s][k] = std::uint8_t(((r >> 32) * n) >> 32);
            maps[s + 1][k] = std::uint8_t(((r & 0xffffffffu) * n) >> 32);
        }
        if (s < steps)
            maps[s][k] = std::uint8_t(((rng.next() >> 32) * n) >> 32);
        rngs[k] = rng;
    }
}

#if defined(AWB_AVX2_KERNELS)
// Xoshiro256::next in each 64-bit lane of the state st[0..3]; the draws into *result.
AWB_AVX2_TARGET AWB_INLINE_BODY void xoshiroNext4(__m256i *st, __m256i *result)
{
    *result = _mm256_add_epi64(st[0], st[3]);
    const __m256i t = _mm256_slli_epi64(st[1], 17);
    st[2] = _mm256_xor_si256(st[2], st[0]);
    st[3] = _mm256_xor_si256(st[3], st[1]);
    st[1] = _mm256_xor_si256(st[1], st[2]);
    st[0] = _mm256_xor_si256(st[0], st[3]);
    st[2] = _mm256_xor_si256(st[2], t);
    st[3] = _mm256_or_si256(_mm256_slli_epi64(st[3], 45), _mm256_srli_epi64(st[3], 19));
}

AWB_AVX2_TARGET void uniformChoices4Avx2(Xoshiro256 *rngs, int steps, std::uint64_t n,
                                         std::uint8_t (*maps)[4])
{
    __m256i st[4];
    for (int j = 0; j < 4; ++j)
        st[j] = _mm256_setr_epi64x(std::int64_t(rngs[0].s[j]), std::int64_t(rngs[1].s[j]),
                                   std::int64_t(rngs[2].s[j]), std::int64_t(rngs[3].s[j]));
    const __m256i nv = _mm256_set1_epi64x(std::int64_t(n));
    // Dwords hi0 lo0 hi1 lo1 hi2 lo2 hi3 lo3 -> hi0 hi1 hi2 hi3 | lo0 lo1 lo2 lo3, then the
    // low byte of each dword to bytes 0..3 of its 128-bit half.
    const __m256i order = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);
    const __m256i bytes = _mm256_setr_epi8(0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
                                           -1, -1, 0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1,
                                           -1, -1, -1, -1);
    // The choices of one draw per orbit: the high halves' (step s) and the low halves' (s + 1),
    // four bytes each.
    auto choices = [&](std::int32_t *h4, std::int32_t *l4) AWB_AVX2_TARGET {
        __m256i r;
        xoshiroNext4(st, &r);
        // ((r >> 32) n) >> 32 and ((r mod 2^32) n) >> 32: mul_epu32 takes each lane's low dword.
        const __m256i hi = _mm256_srli_epi64(_mm256_mul_epu32(_mm256_srli_epi64(r, 32), nv), 32);
        const __m256i lo = _mm256_srli_epi64(_mm256_mul_epu32(r, nv), 32);
        const __m256i d = _mm256_or_si256(hi, _mm256_slli_epi64(lo, 32));
        const __m256i b = _mm256_shuffle_epi8(_mm256_permutevar8x32_epi32(d, order), bytes);
        *h4 = _mm_cvtsi128_si32(_mm256_castsi256_si128(b));
        *l4 = _mm_cvtsi128_si32(_mm256_extracti128_si256(b, 1));
    };
    int s = 0;
    std::int32_t h4, l4;
    for (; s + 1 < steps; s += 2) {
        choices(&h4, &l4);
        std::memcpy(maps[s], &h4, 4);
        std::memcpy(maps[s + 1], &l4, 4);
    }
    if (s < steps) {  // an odd last step: the high halves of one more draw
        choices(&h4, &l4);
        std::memcpy(maps[s], &h4, 4);
    }
    alignas(32) std::uint64_t lanes[4][4];
    for (int j = 0; j < 4; ++j)
        _mm256_store_si256(reinterpret_cast<__m256i *>(lanes[j]), st[j]);
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            rngs[k].s[j] = lanes[j][k];
}
#endif

template <int K>
void uniformChoices(Xoshiro256 *rngs, int steps, std::uint64_t n, std::uint8_t (*maps)[K])
{
#if defined(AWB_AVX2_KERNELS)
    if constexpr (K == 4)
        if (haveAvx2())
            return uniformChoices4Avx2(rngs, steps, n, maps);
#endif
    uniformChoicesBase<K>(rngs, steps, n, maps);
}

// The geometry of four orbits in screen space (toScreenSpace), one step of all four at a time
// in the four 64-bit lanes of AVX2 registers (orbit k in lane k), ending in the cells of
// cellIndex. The chosen maps' coefficients come from tables of the maps' values (`lanes`: for
// coefficient c (A's D x D row by row, then b), maps 0..7 at lanes[8c + i]) by a permute
// each, not by a load per orbit: one permute with at most four maps, two and a blend with up
// to eight. The products and sums are the scalar loop's, in its order and without fused
// multiply-adds: the same numbers bit for bit.
template <int D>
using ChaosGeometry = void (*)(const double *lanes, double (*x)[D], const std::uint8_t (*maps)[4],
                               int steps, int w, int h, std::int32_t (*cells)[4]);

// The coefficient tables of the geometry kernel for up to 8 maps (zeros beyond n).
template <int D>
std::vector<double> chaosLanes(const Flat<D> &F)
{
    std::vector<double> lanes(std::size_t(D * D + D) * 8, 0.0);
    for (int i = 0; i < std::min(F.n, 8); ++i) {
        for (int c = 0; c < D * D; ++c)
            lanes[std::size_t(c) * 8 + i] = F.a[std::size_t(i) * D * D + c];
        for (int j = 0; j < D; ++j)
            lanes[std::size_t(D * D + j) * 8 + i] = F.b[std::size_t(i) * D + j];
    }
    return lanes;
}

#if defined(AWB_AVX2_KERNELS)
template <int D, bool Wide>
AWB_AVX2_TARGET void chaosGeometry4Avx2(const double *lanes, double (*x)[D],
                                        const std::uint8_t (*maps)[4], int steps, int w, int h,
                                        std::int32_t (*cells)[4])
{
    __m256d X[D];
    for (int j = 0; j < D; ++j)
        X[j] = _mm256_setr_pd(x[0][j], x[1][j], x[2][j], x[3][j]);
    const __m256i high = _mm256_set1_epi64x(std::int64_t(1) << 32), three = _mm256_set1_epi64x(3);
    const __m256d one = _mm256_set1_pd(1.0);
    const __m128i bias = _mm_set1_epi32(INT_MIN), ones = _mm_set1_epi32(-1), W = _mm_set1_epi32(w);
    const __m128i wb = _mm_set1_epi32(int(unsigned(w) ^ 0x80000000u));
    const __m128i hb = _mm_set1_epi32(int(unsigned(h) ^ 0x80000000u));
    for (int s = 0; s < steps; ++s) {
        std::int32_t m4;
        std::memcpy(&m4, maps[s], 4);
        const __m256i m = _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(m4));
        // Map i's double is dwords 2i and 2i + 1 of a table (the permute reads i mod 4).
        const __m256i idx = _mm256_add_epi64(
            _mm256_add_epi64(_mm256_slli_epi64(m, 1), _mm256_slli_epi64(m, 33)), high);
        __m256d upper = _mm256_setzero_pd();
        if constexpr (Wide)
            upper = _mm256_castsi256_pd(_mm256_cmpgt_epi64(m, three));
        auto coef = [&](int c) AWB_AVX2_TARGET {
            const __m256i *t = reinterpret_cast<const __m256i *>(lanes + std::size_t(c) * 8);
            __m256d v = _mm256_castsi256_pd(_mm256_permutevar8x32_epi32(_mm256_loadu_si256(t), idx));
            if constexpr (Wide)
                v = _mm256_blendv_pd(v,
                                     _mm256_castsi256_pd(_mm256_permutevar8x32_epi32(
                                         _mm256_loadu_si256(t + 1), idx)),
                                     upper);
            return v;
        };
        __m256d y[D];
        for (int j = 0; j < D; ++j)
            y[j] = coef(D * D + j);
        for (int q = 0; q < D; ++q)
            for (int j = 0; j < D; ++j)
                y[j] = _mm256_add_pd(y[j], _mm256_mul_pd(X[q], coef(q * D + j)));
        for (int j = 0; j < D; ++j)
            X[j] = y[j];
        // cellIndex of (y0, y1) in each lane (as cellsAvx2).
        const __m128i ux = _mm_sub_epi32(_mm256_cvttpd_epi32(_mm256_add_pd(y[0], one)), _mm_set1_epi32(1));
        const __m128i uy = _mm_sub_epi32(_mm256_cvttpd_epi32(_mm256_add_pd(y[1], one)), _mm_set1_epi32(1));
        const __m128i in = _mm_and_si128(_mm_cmplt_epi32(_mm_xor_si128(ux, bias), wb),
                                         _mm_cmplt_epi32(_mm_xor_si128(uy, bias), hb));
        const __m128i index = _mm_add_epi32(_mm_mullo_epi32(uy, W), ux);
        _mm_storeu_si128(reinterpret_cast<__m128i *>(cells[s]),
                         _mm_or_si128(_mm_and_si128(in, index), _mm_andnot_si128(in, ones)));
    }
    alignas(32) double out[4];
    for (int j = 0; j < D; ++j) {
        _mm256_store_pd(out, X[j]);
        for (int k = 0; k < 4; ++k)
            x[k][j] = out[k];
    }
}
#endif

// The geometry kernel for n maps here, or none (the scalar loop: no AVX2, or more than 8 maps).
template <int D>
ChaosGeometry<D> chaosGeometry(int n)
{
#if defined(AWB_AVX2_KERNELS)
    if constexpr (D >= 2) {
        if (haveAvx2() && n <= 4)
            return &chaosGeometry4Avx2<D, false>;
        if (haveAvx2() && n <= 8)
            return &chaosGeometry4Avx2<D, true>;
    }
#endif
    (void)n;
    return nullptr;
}

template <int D, int K>
struct Orbits {
    double x[K][D];
    std::uint32_t label[K];
    Xoshiro256 rng[K];
};

template <int D, int K, Store M, bool oneView>
void chaosBlock(const Flat<D> &F, const AliasTable &pick, Orbits<D, K> &o, int steps,
                bool plot, int prefix, std::uint32_t labelMod, DensityImage &img,
                const std::uint8_t *coords, ChaosGeometry<D> geometry = nullptr,
                const double *lanes = nullptr)
{
    std::uint8_t maps[kBlock][K];
    if (pick.uniform()) {
        uniformChoices<K>(o.rng, steps, std::uint64_t(pick.size()), maps);
    } else {
        for (int k = 0; k < K; ++k) {
            Xoshiro256 rng = o.rng[k];
            for (int s = 0; s < steps; ++s)
                maps[s][k] = std::uint8_t(pick.pick(rng.next()));
            o.rng[k] = rng;
        }
    }

    const int w = img.cellsX(), h = img.cellsY();
    double x[K][D];
    std::uint32_t label[K];
    for (int k = 0; k < K; ++k) {
        label[k] = prefix > 1 ? o.label[k] : 0u;
        for (int j = 0; j < D; ++j)
            x[k][j] = o.x[k][j];
    }
    std::int32_t cells[kBlock][K];
    std::uint32_t labels[kBlock][K];
    const double *const allA = F.a.data();
    const double *const allB = F.b.data();
    int s0 = 0;  // the steps the vector kernel did
    if constexpr (K == 4 && oneView && D >= 2) {
        if (geometry) {
            geometry(lanes, x, maps, steps, w, h, cells);
            if (prefix > 1)
                for (int s = 0; s < steps; ++s)
                    for (int k = 0; k < K; ++k) {
                        label[k] = (label[k] * std::uint32_t(F.n) + maps[s][k]) % labelMod;
                        labels[s][k] = label[k];
                    }
            s0 = steps;
        }
    }
    for (int s = s0; s < steps; ++s) {
        for (int k = 0; k < K; ++k) {
            const int i = maps[s][k];
            const double *A = allA + std::size_t(i) * D * D;
            const double *B = allB + std::size_t(i) * D;
            double y[D];
            for (int j = 0; j < D; ++j)
                y[j] = B[j];
            for (int q = 0; q < D; ++q)
                for (int j = 0; j < D; ++j)
                    y[j] += x[k][q] * A[q * D + j];
            for (int j = 0; j < D; ++j)
                x[k][j] = y[j];
            if (prefix > 1) {
                label[k] = (label[k] * std::uint32_t(F.n) + std::uint32_t(i)) % labelMod;
                labels[s][k] = label[k];
            }
            if constexpr (oneView && D >= 2) {
                // Screen space (toScreenSpace): the first two coordinates are the cell.
                cells[s][k] = cellIndex(y[0], y[1], w, h);
            }
        }
        if (!oneView && plot)
            for (int k = 0; k < K; ++k)
                for (int q = 0; q < F.views; ++q) {
                    const double *V = &F.v[std::size_t(q) * D * 2];
                    double sx = F.c[2 * q], sy = F.c[2 * q + 1];
                    for (int j = 0; j < D; ++j) {
                        sx += x[k][j] * V[2 * j];
                        sy += x[k][j] * V[2 * j + 1];
                    }
                    const std::uint32_t l = prefix == 1 ? maps[s][k] : prefix == 0 ? 0u : label[k];
                    plotCell<M>(img, w, h, sx, sy, l, coords);
                }
    }
    for (int k = 0; k < K; ++k) {
        o.label[k] = label[k];
        for (int j = 0; j < D; ++j)
            o.x[k][j] = x[k][j];
    }
    // The cells were found in screen space only with one view in 2D or more.
    if constexpr (oneView && D >= 2) {
        if (!plot)
            return;
        img.reserve(std::size_t(steps) * K);
        for (int s = 0; s < steps; ++s)
            for (int k = 0; k < K; ++k) {
                const std::int32_t c = cells[s][k];
                if (c < 0) {
                    ++img.offscreen;
                    continue;
                }
                const std::uint32_t l = prefix == 1 ? maps[s][k] : prefix == 0 ? 0u : labels[s][k];
                addUnchecked<M>(img, std::size_t(c), l, coords);
            }
    }
}

// Random iteration of streams [first, last) (Random.h), kInterleave orbits at a time.
template <int D, Store M, bool OneView>
IterationStats chaosKernel(const Flat<D> &F, const AliasTable &pick, const RowVec &x0,
                           const EngineJob &job, const std::uint8_t *colours, int first, int last,
                           DensityImage &img, const Progress &progress)
{
    const int prefix = job.colours.prefix;
    std::uint32_t labelMod = 1;
    for (int k = 0; k < prefix; ++k)
        labelMod *= std::uint32_t(F.n);
    IterationStats stats;
    constexpr int K = kInterleave;
    static_assert(K == 4, "the vector geometry advances four orbits");
    // The vector geometry runs in screen space (one view), where the cells are coordinates.
    const ChaosGeometry<D> geometry = OneView ? chaosGeometry<D>(F.n) : nullptr;
    const std::vector<double> lanes = geometry ? chaosLanes(F) : std::vector<double>();
    for (int g = first; g < last; g += K) {
        // A group of K streams (fewer at the end: those run one by one below).
        const int members = std::min(K, last - g);
        Orbits<D, K> o;
        std::uint64_t left[K];
        for (int k = 0; k < K; ++k) {
            o.rng[k] = Xoshiro256(job.seed, std::uint64_t(g + std::min(k, members - 1)));
            o.label[k] = 0;
            for (int j = 0; j < D; ++j)
                o.x[k][j] = x0(j);
            left[k] = streamShare(job.samples, g + std::min(k, members - 1));
        }
        if (members < K) {
            // Run the short group's streams singly.
            for (int m = 0; m < members; ++m) {
                Orbits<D, 1> one;
                one.rng[0] = Xoshiro256(job.seed, std::uint64_t(g + m));
                one.label[0] = 0;
                for (int j = 0; j < D; ++j)
                    one.x[0][j] = x0(j);
                for (int sk = job.skip; sk > 0; sk -= kBlock)
                    chaosBlock<D, 1, M, OneView>(F, pick, one, std::min(sk, kBlock), false, prefix,
                                        labelMod, img, colours);
                for (std::uint64_t n = streamShare(job.samples, g + m); n > 0;) {
                    const int steps = int(std::min<std::uint64_t>(n, kBlock));
                    chaosBlock<D, 1, M, OneView>(F, pick, one, steps, true, prefix, labelMod, img, colours);
                    n -= std::uint64_t(steps);
                    stats.images += std::uint64_t(steps);
                }
            }
            continue;
        }
        for (int sk = job.skip; sk > 0; sk -= kBlock)
            chaosBlock<D, K, M, OneView>(F, pick, o, std::min(sk, kBlock), false, prefix, labelMod, img,
                                         colours, geometry, lanes.data());
        std::uint64_t common = left[0];
        for (int k = 1; k < K; ++k)
            common = std::min(common, left[k]);
        bool stop = false;
        std::uint64_t sinceCheck = 0;
        while (common > 0) {
            const int steps = int(std::min<std::uint64_t>(common, kBlock));
            chaosBlock<D, K, M, OneView>(F, pick, o, steps, true, prefix, labelMod, img, colours,
                                         geometry, lanes.data());
            common -= std::uint64_t(steps);
            for (int k = 0; k < K; ++k)
                left[k] -= std::uint64_t(steps);
            stats.images += std::uint64_t(steps) * K;
            sinceCheck += std::uint64_t(steps) * K;
            if (sinceCheck >= (1u << 18) || common == 0) {
                if (!progress.tick(sinceCheck)) {
                    stats.cancelled = true;
                    stop = true;
                    break;
                }
                sinceCheck = 0;
                bool finite = true;
                for (int k = 0; k < K; ++k)
                    for (int j = 0; j < D; ++j)
                        finite = finite && std::isfinite(o.x[k][j]);
                if (!finite) {  // an orbit escaped: the maps are not contractive
                    ++img.nonFinite;
                    stop = true;
                    break;
                }
            }
        }
        if (stop)
            break;
        // The streams' last samples (shares differ by one at most), one orbit at a time.
        for (int k = 0; k < K; ++k) {
            if (left[k] == 0)
                continue;
            Orbits<D, 1> one;
            one.rng[0] = o.rng[k];
            one.label[0] = o.label[k];
            for (int j = 0; j < D; ++j)
                one.x[0][j] = o.x[k][j];
            chaosBlock<D, 1, M, OneView>(F, pick, one, int(left[k]), true, prefix, labelMod, img, colours);
            stats.images += left[k];
        }
    }
    return stats;
}

// The last `m` levels of a deterministic iteration fused into one table per view: for each
// word w of m maps (the first of them applied first), the composite map from the IFS space
// straight to raster cells, x -> x L_w + c_w (D x 2 and 2 numbers). A node m levels above the
// leaves then draws its N^m leaves with 2D multiply-adds each, in loops over the words that
// the compiler vectorises, and the D x D products of those m levels are never done.
//
// Words are indexed by their address read as a number: address[0] (the outermost map, the
// last applied) is the most significant digit, so the colour label of a prefix p <= m is the
// index divided by N^(m - p).
template <int D>
struct FusedLeaves {
    int m = 0;       // fused levels
    int words = 1;   // N^m
    int views = 0;
    // Cell x and y of every word side by side (one loop over 2 N^m numbers does both):
    // l[((q * D + j) * words + w) * 2 + k] is row j, column k of L_w; c[(q * words + w) * 2 + k].
    std::vector<double> l, c;

    // The most fused levels with N^m <= maxWords (and m <= levels).
    static int levelsFor(int N, int levels, int maxWords = 256)
    {
        int m = 0;
        std::int64_t w = 1;
        while (m < levels && m < 16 && w * N <= maxWords) {
            w *= N;
            ++m;
        }
        return m;
    }

    FusedLeaves(const Flat<D> &F, int levels) : m(levels), views(F.views)
    {
        for (int t = 0; t < m; ++t)
            words *= F.n;
        // Table of t maps (t = 0: the views), grown by prepending the innermost map.
        std::vector<double> L(std::size_t(views) * D * 2), C(std::size_t(views) * 2);
        for (int q = 0; q < views; ++q) {
            for (int j = 0; j < D; ++j)
                for (int k = 0; k < 2; ++k)
                    L[(std::size_t(q) * D + j) * 2 + k] = F.v[(std::size_t(q) * D + j) * 2 + k];
            C[q * 2] = F.c[q * 2];
            C[q * 2 + 1] = F.c[q * 2 + 1];
        }
        int size = 1;
        for (int t = 0; t < m; ++t) {
            std::vector<double> L2(std::size_t(views) * size * F.n * D * 2);
            std::vector<double> C2(std::size_t(views) * size * F.n * 2);
            for (int q = 0; q < views; ++q)
                for (int e = 0; e < size; ++e)
                    for (int i = 0; i < F.n; ++i) {
                        const std::size_t from = std::size_t(q) * size + e;
                        const std::size_t to = std::size_t(q) * size * F.n + std::size_t(e) * F.n + i;
                        const double *A = &F.a[std::size_t(i) * D * D];
                        const double *B = &F.b[std::size_t(i) * D];
                        const double *Le = &L[from * D * 2];
                        double *Lt = &L2[to * D * 2];
                        // L' = A_i L_e, c' = b_i L_e + c_e.
                        for (int r = 0; r < D; ++r)
                            for (int k = 0; k < 2; ++k) {
                                double acc = 0;
                                for (int j = 0; j < D; ++j)
                                    acc += A[r * D + j] * Le[j * 2 + k];
                                Lt[r * 2 + k] = acc;
                            }
                        for (int k = 0; k < 2; ++k) {
                            double acc = C[from * 2 + k];
                            for (int j = 0; j < D; ++j)
                                acc += B[j] * Le[j * 2 + k];
                            C2[to * 2 + k] = acc;
                        }
                    }
            L.swap(L2);
            C.swap(C2);
            size *= F.n;
        }
        l.resize(std::size_t(views) * D * words * 2);
        c = C;
        for (int q = 0; q < views; ++q)
            for (int w = 0; w < words; ++w) {
                const std::size_t e = std::size_t(q) * words + w;
                for (int j = 0; j < D; ++j)
                    for (int k = 0; k < 2; ++k)
                        l[((std::size_t(q) * D + j) * words + w) * 2 + k] = L[(e * D + j) * 2 + k];
            }
    }
};

// Depth-first deterministic iteration of one thread: buf[level] holds the images of the start
// set after `level` maps (the innermost first); the last T.m levels go through the fused
// table T.
template <int D, Store M>
class DfsKernel {
public:
    DfsKernel(const Flat<D> &F, const FusedLeaves<D> &T, const EngineJob &job,
              const std::uint8_t *coords, DensityImage &img, const Progress &progress)
        : m_F(F), m_T(T), m_job(job), m_coords(coords), m_img(img), m_progress(progress),
          m_depth(job.depth), m_n(int(job.start.vertices.rows())), m_kind(job.start.kind),
          m_buf(std::size_t(job.depth + 1) * m_n * D), m_screen(std::size_t(m_n) * 2),
          m_s(std::size_t(m_n) * T.words * 2), m_box(std::size_t(T.words) * 6),
          m_cells(std::size_t(T.words)), m_cells2(std::size_t(T.words)),
          m_labels(std::size_t(T.words)), m_kernels(leafKernels<D>()),
          m_plotter{img, img.cellsX(), img.cellsY(), coords}
    {
        m_xs.resize(std::size_t(std::max(m_n, 1)));
        for (int r = 0; r < m_n; ++r)
            for (int j = 0; j < D; ++j)
                m_buf[std::size_t(r) * D + j] = job.start.vertices(r, j);
        m_points = m_kind == StartSet::Kind::Points || m_n == 1;
        m_maps = std::uint32_t(F.n);
        // Labels of the fused words when the colour prefix lies within them.
        const int prefix = job.colours.prefix;
        std::uint32_t div = 1;
        for (int t = prefix; t < T.m; ++t)
            div *= m_maps;
        m_labelsFixed = prefix <= T.m;
        for (int w = 0; w < T.words; ++w)
            m_labels[std::size_t(w)] = prefix == 0 ? 0u : std::uint32_t(w) / div;
    }

    // The fixed innermost choices `prefix`, then every word of the remaining levels.
    bool run(const std::vector<int> &prefix)
    {
        int level = 0;
        for (int i : prefix)
            step(level++, i);
        return walk(level);
    }
    std::uint64_t emitted() const { return m_emitted; }

private:
    double *level(int l) { return &m_buf[std::size_t(l) * m_n * D]; }

    void step(int l, int i)
    {
        const double *A = &m_F.a[std::size_t(i) * D * D];
        const double *B = &m_F.b[std::size_t(i) * D];
        const double *X = level(l);
        double *Y = level(l + 1);
        for (int r = 0; r < m_n; ++r) {
            double y[D];
            for (int j = 0; j < D; ++j)
                y[j] = B[j];
            for (int q = 0; q < D; ++q)
                for (int j = 0; j < D; ++j)
                    y[j] += X[r * D + q] * A[q * D + j];
            for (int j = 0; j < D; ++j)
                Y[r * D + j] = y[j];
        }
        m_address[m_depth - l - 1] = std::uint8_t(i);
    }

    bool walk(int l)
    {
        if (m_depth == 0)
            return leaves0();
        if (l == m_depth - m_T.m)
            return leaves(l);
        for (int i = 0; i < m_F.n; ++i) {
            step(l, i);
            if (!walk(l + 1))
                return false;
        }
        return true;
    }

    // The N^m leaves below buf[l] through the fused table, into the raster.
    bool leaves(int l)
    {
        const double *X = level(l);
        const int W = m_T.words;
        const int w = m_img.cellsX(), h = m_img.cellsY();
        const double xMax = m_plotter.xMax(), yMax = m_plotter.yMax();
        if (!m_labelsFixed) {
            // A colour prefix longer than the fused levels: the parent's part of the address
            // (address[m..prefix-1]) is the low digits of every word's label.
            const int prefix = m_job.colours.prefix;
            std::uint32_t low = 0, scale = 1;
            for (int k = m_T.m; k < prefix; ++k) {
                low = low * m_maps + (k < m_depth ? m_address[k] : 0u);
                scale *= m_maps;
            }
            for (int v = 0; v < W; ++v)
                m_labels[std::size_t(v)] = std::uint32_t(v) * scale + low;
        }
        for (int q = 0; q < m_T.views; ++q) {
            const double *L = &m_T.l[std::size_t(q) * D * W * 2];
            const double *C = &m_T.c[std::size_t(q) * W * 2];
            // Every vertex's cell coordinates for every word: s = x L + c, as 2W-long
            // multiply-adds (vectorised).
            m_kernels.rows(C, L, X, m_n, 2 * W, m_s.data());
            if (m_points) {
                for (int r = 0; r < m_n; ++r) {
                    // Cells first (NaN: off screen), then the hits.
                    m_kernels.cells(&m_s[std::size_t(r) * W * 2], W, w, h, m_cells.data());
                    m_img.reserve(std::size_t(W));
                    for (int v = 0; v < W; ++v) {
                        const std::int32_t cell = m_cells[std::size_t(v)];
                        if (cell < 0) {
                            ++m_img.offscreen;
                            continue;
                        }
                        addUnchecked<M>(m_img, std::size_t(cell), m_labels[std::size_t(v)],
                                        m_coords);
                    }
                }
                continue;
            }
            // Each image's bounding box (and a NaN check), and the cells of its corners.
            double *lo = m_box.data(), *hi = lo + 2 * W, *sum = hi + 2 * W;
            m_kernels.bounds(m_s.data(), m_n, 2 * W, lo, hi, sum);
            m_kernels.cells(lo, W, w, h, m_cells.data());
            m_kernels.cells(hi, W, w, h, m_cells2.data());
            m_img.reserve(std::size_t(W));
            for (int v = 0; v < W; ++v) {
                // Deep levels: an image whose bounding box has both corners in one cell on the
                // raster is one hit there. NaN, and images off the raster or over several
                // cells, go to the rasteriser.
                const std::int32_t c0 = m_cells[std::size_t(v)];
                const bool nan = sum[2 * v] != sum[2 * v] || sum[2 * v + 1] != sum[2 * v + 1];
                if (c0 >= 0 && c0 == m_cells2[std::size_t(v)] && !nan) {
                    addUnchecked<M>(m_img, std::size_t(c0), m_labels[std::size_t(v)], m_coords);
                    continue;
                }
                for (int r = 0; r < m_n; ++r) {
                    m_screen[2 * r] = m_s[(std::size_t(r) * W + v) * 2];
                    m_screen[2 * r + 1] = m_s[(std::size_t(r) * W + v) * 2 + 1];
                }
                // Small images straddling cells inside the raster (most of the rest at deep
                // levels) skip the rasteriser's checks and clipping.
                if (!nan && lo[2 * v] >= 0 && lo[2 * v + 1] >= 0 && hi[2 * v] < xMax
                    && hi[2 * v + 1] < yMax)
                    m_plotter.imageInside(m_screen.data(), m_n, m_kind, m_labels[std::size_t(v)],
                                          m_xs.data(), lo[2 * v], lo[2 * v + 1], hi[2 * v],
                                          hi[2 * v + 1]);
                else
                    m_plotter.image(m_screen.data(), m_n, m_kind, m_labels[std::size_t(v)], m_xs);
            }
        }
        m_emitted += std::uint64_t(W);
        if (m_emitted - m_ticked >= 16384) {
            const std::uint64_t n = m_emitted - m_ticked;
            m_ticked = m_emitted;
            return m_progress.tick(n);
        }
        return true;
    }

    // Depth 0: the start set itself.
    bool leaves0()
    {
        const double *X = level(0);
        for (int q = 0; q < m_F.views; ++q) {
            const double *V = &m_F.v[std::size_t(q) * D * 2];
            for (int r = 0; r < m_n; ++r) {
                double sx = m_F.c[2 * q], sy = m_F.c[2 * q + 1];
                for (int j = 0; j < D; ++j) {
                    sx += X[r * D + j] * V[2 * j];
                    sy += X[r * D + j] * V[2 * j + 1];
                }
                m_screen[2 * r] = sx;
                m_screen[2 * r + 1] = sy;
            }
            m_plotter.image(m_screen.data(), m_n, m_kind, 0, m_xs);
        }
        m_emitted += 1;
        return true;
    }

    const Flat<D> &m_F;
    const FusedLeaves<D> &m_T;
    const EngineJob &m_job;
    const std::uint8_t *m_coords;
    DensityImage &m_img;
    const Progress &m_progress;
    int m_depth, m_n;
    StartSet::Kind m_kind;
    bool m_points = true;
    bool m_labelsFixed = true;
    std::uint32_t m_maps = 1;
    std::vector<double> m_buf, m_screen, m_xs, m_s, m_box;
    std::vector<std::int32_t> m_cells, m_cells2;
    std::vector<std::uint32_t> m_labels;
    LeafKernels<D> m_kernels;
    Plotter m_plotter;
    std::uint8_t m_address[65] = {};
    std::uint64_t m_emitted = 0, m_ticked = 0;
};

// Runs fn(t) on `threads` threads (t = 0 on the caller's).
template <typename Fn>
void onThreads(int threads, Fn fn)
{
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back(fn, t);
    fn(0);
    for (auto &th : pool)
        th.join();
}

// Words of the innermost `split` levels, at least 4 per thread, as tasks.
std::vector<std::vector<int>> splitTasks(int N, int depth, int threads)
{
    int split = 0;
    while (split < depth && std::pow(double(N), split) < 8.0 * threads && threads > 1)
        ++split;
    std::vector<std::vector<int>> tasks(1);
    for (int s = 0; s < split; ++s) {
        std::vector<std::vector<int>> next;
        for (const auto &t : tasks)
            for (int i = 0; i < N; ++i) {
                auto u = t;
                u.push_back(i);
                next.push_back(u);
            }
        tasks.swap(next);
    }
    return tasks;
}

// The histograms of one render: images[0] is the caller's picture, the others the threads'
// own, reused from one render to the next; clean[t]: images[t] is known to be empty (taken
// whole by the last merge) and of this size and mode, so it needs no reset.
struct Histograms {
    std::vector<DensityImage *> images;
    std::vector<char> clean;
    CellLayout layout;  // buckets, one label's counts (one colour), or label planes

    // Called by thread t before it draws.
    void prepare(int t, const EngineJob &job) const
    {
        DensityImage &img = *images[std::size_t(t)];
        if (!clean[std::size_t(t)] || img.cellsX() != job.frame.cellsX()
            || img.cellsY() != job.frame.cellsY() || img.mode() != job.accumulation
            || !(img.layout() == layout))
            img.reset(job.frame.cellsX(), job.frame.cellsY(), job.accumulation, layout);
    }
};

template <int D, Store M>
IterationStats runFixed(const EngineJob &job, const std::vector<CellView> &cv,
                        const Histograms &hist, const IterationControl &control)
{
    const Flat<D> F(*job.ifs, cv);
    const std::vector<std::uint8_t> coords = labelCoordinates(job.colours.labelColours.size());
    const std::vector<DensityImage *> &images = hist.images;
    const int threads = int(images.size());
    std::atomic<std::uint64_t> done{0};
    std::vector<IterationStats> results(threads);
    if (job.random) {
        const AliasTable pick(job.ifs->probabilities, job.ifs->size());
        const Progress progress{control, done, std::max(1.0, double(job.samples))};
        RowVec x0 = job.start.vertices.row(0);
        // One view: the orbit runs in screen space (toScreenSpace).
        Flat<D> screen = F;
        double start[D];
        for (int k = 0; k < D; ++k)
            start[k] = x0(k);
        const bool inScreen = toScreenSpace(F, screen, start);
        RowVec x0Screen = x0;
        for (int k = 0; k < D; ++k)
            x0Screen(k) = start[k];
        // Thread t runs a contiguous block of streams.
        onThreads(threads, [&](int t) {
            hist.prepare(t, job);
            const int first = kChaosStreams * t / threads, last = kChaosStreams * (t + 1) / threads;
            results[t] = inScreen
                             ? chaosKernel<D, M, true>(screen, pick, x0Screen, job, coords.data(),
                                                       first, last, *images[t], progress)
                             : chaosKernel<D, M, false>(F, pick, x0, job, coords.data(), first,
                                                        last, *images[t], progress);
        });
    } else {
        const auto tasks = splitTasks(F.n, job.depth, threads);
        const int split = tasks.empty() ? 0 : int(tasks.front().size());
        const FusedLeaves<D> fused(F, FusedLeaves<D>::levelsFor(F.n, job.depth - split));
        const Progress progress{control, done, std::max(1.0, imageCount(*job.ifs, job.depth))};
        std::atomic<std::size_t> next{0};
        std::atomic<bool> stopped{false};
        onThreads(threads, [&](int t) {
            hist.prepare(t, job);
            DfsKernel<D, M> walker(F, fused, job, coords.data(), *images[t], progress);
            for (;;) {
                const std::size_t k = next.fetch_add(1);
                if (k >= tasks.size() || stopped.load())
                    break;
                if (!walker.run(tasks[k])) {
                    stopped = true;
                    break;
                }
            }
            results[t].images = walker.emitted();
            results[t].cancelled = stopped.load();
        });
    }
    IterationStats stats;
    for (const auto &r : results) {
        stats.images += r.images;
        stats.cancelled = stats.cancelled || r.cancelled;
    }
    return stats;
}

template <Store M, int D = 1>
IterationStats dispatch(int dim, const EngineJob &job, const std::vector<CellView> &cv,
                        const Histograms &hist, const IterationControl &control)
{
    if constexpr (D > kMaxFixedDim) {
        return {};
    } else {
        if (dim == D)
            return runFixed<D, M>(job, cv, hist, control);
        return dispatch<M, D + 1>(dim, job, cv, hist, control);
    }
}

} // namespace

IterationStats accumulate(const EngineJob &job, DensityImage &out, const IterationControl &control)
{
    if (!job.ifs)
        throw InputError(coreTranslate("awb::render", "there is no IFS to draw"));
    job.frame.validate();
    const Ifs &ifs = *job.ifs;
    const std::vector<Projection> &views = job.views.empty() ? ifs.views : job.views;
    if (views.empty())
        throw InputError(coreTranslate("awb::render", "the IFS has no view to draw it with"));
    std::uint64_t labels = 1;
    for (int k = 0; k < job.colours.prefix; ++k)
        labels *= std::uint64_t(std::max(1, ifs.size()));
    if (job.colours.prefix < 0 || job.colours.prefix > 3
        || job.colours.labelColours.size() < labels)
        throw InputError(coreTranslate("awb::render", "the colour table does not cover the address "
                                                      "labels"));
    if (job.random) {
        checkChaosInputs(ifs, job.start.vertices.row(0), job.samples);
    } else {
        checkIterateInputs(ifs, job.start, job.depth);
    }
    const std::vector<CellView> cv = cellViews(views, job.frame, ifs.dim());

    // One histogram per thread, within the memory budget; thread 0 fills `out` itself.
    const double bytes = 16.0 * job.frame.cellsX() * job.frame.cellsY();
    int threads = std::clamp(job.threads, 1, kChaosStreams);
    // A small picture's work is less than starting threads and merging their histograms.
    const double work = job.random ? double(job.samples)
                                   : imageCount(ifs, job.depth) * double(job.start.vertices.rows());
    if (work < 2e5)
        threads = 1;
    threads = std::max(1, std::min(threads, int(kHistogramBudget / std::max(1.0, bytes))));
    // The other threads' histograms are kept per calling thread and reused by the next
    // picture of the same size (live drags render one picture after another). The merge
    // below empties them, so the next picture of that size skips their reset; each thread
    // resets its own otherwise (the kernels; here for the sink path).
    struct Spare {
        std::unique_ptr<DensityImage> image;
        bool clean = false;
    };
    static thread_local std::vector<Spare> spare;
    if (spare.size() < std::size_t(threads))
        spare.resize(std::size_t(threads));
    Histograms hist;
    hist.images.push_back(&out);
    hist.clean.push_back(0);
    for (int t = 1; t < threads; ++t) {
        if (!spare[t].image)
            spare[t].image = std::make_unique<DensityImage>();
        hist.images.push_back(spare[t].image.get());
        hist.clean.push_back(spare[t].clean ? 1 : 0);
        spare[t].clean = false;  // until the merge empties it again
    }
    const std::vector<DensityImage *> &images = hist.images;
    // A much larger earlier picture's memory is not kept.
    auto release = [&] {
        for (auto &s : spare)
            if (s.image && s.image->size() > 4 * std::size_t(job.frame.cellsX()) * job.frame.cellsY())
                s.image.reset(), s.clean = false;
    };
    const bool fixed = ifs.dim() <= kMaxFixedDim && ifs.size() > 0;
    if (!fixed)
        for (int t = 0; t < threads; ++t)
            hist.prepare(t, job);

    IterationStats stats;
    if (fixed) {
        // A picture whose labels all have one colour is the same picture with one label: its
        // histograms keep the counts alone (half the memory the hits touch), and the kernels
        // skip the labels' arithmetic.
        bool oneColour = true;
        for (std::uint64_t l = 1; l < labels; ++l) {
            const Rgb8 &a = job.colours.labelColours[l], &b = job.colours.labelColours[0];
            oneColour = oneColour && a.r == b.r && a.g == b.g && a.b == b.b;
        }
        // The random iteration's hits scatter over the whole picture: with few labels, one
        // plane of counts per label touches the memory of one colour where the labels' parts
        // do not overlap (Density.h). Deterministic iteration hits its cells in the order of
        // the addresses, where 8-byte buckets cost less to clear, merge and tone map.
        const bool planes =
            job.labelPlanes && job.random && labels >= 2 && labels <= CellLayout::kMaxPlanes;
        if (oneColour) {
            hist.layout = CellLayout::oneLabel();
            EngineJob one = job;
            one.colours.prefix = 0;
            one.colours.labelColours.resize(1);
            stats = dispatch<Store::Counts>(ifs.dim(), one, cv, hist, control);
        } else if (planes) {
            hist.layout = CellLayout::labelPlanes(
                int(labels), labelCoordinates(job.colours.labelColours.size()));
            stats = dispatch<Store::Planes>(ifs.dim(), job, cv, hist, control);
        } else {
            stats = job.accumulation == Accumulation::Hits
                        ? dispatch<Store::Hits>(ifs.dim(), job, cv, hist, control)
                        : dispatch<Store::Colours>(ifs.dim(), job, cv, hist, control);
        }
    } else {
        // Large dimensions: the sink-based iteration into the same rasteriser.
        std::vector<std::unique_ptr<DensitySink>> sinks;
        std::vector<AttractorSink *> raw;
        for (int t = 0; t < threads; ++t) {
            sinks.push_back(std::make_unique<DensitySink>(job.frame, views, job.accumulation,
                                                          job.colours, ifs.size()));
            raw.push_back(sinks.back().get());
        }
        if (job.random) {
            ChaosOptions opt;
            opt.samples = job.samples;
            opt.seed = job.seed;
            opt.skip = job.skip;
            opt.addressLength = std::max(1, job.colours.prefix);
            stats = chaosGameParallel(ifs, job.start.vertices.row(0), opt, raw, control);
        } else {
            stats = iterateParallel(ifs, job.start, job.depth, raw, control);
        }
        for (int t = 0; t < threads; ++t)
            images[t]->merge(sinks[t]->image());
    }
    if (stats.cancelled)
        return stats;
    if (images.size() > 1) {
        // Thread t moves every other histogram's band t of cells into `out`, leaving them
        // empty for the next picture.
        const std::size_t cells = out.size();
        onThreads(threads, [&](int t) {
            const std::size_t first = cells * std::size_t(t) / std::size_t(threads);
            const std::size_t last = cells * std::size_t(t + 1) / std::size_t(threads);
            for (std::size_t k = 1; k < images.size(); ++k)
                out.takeCells(*images[k], first, last);
        });
        for (std::size_t k = 1; k < images.size(); ++k) {
            out.takeRest(*images[k]);
            spare[k].clean = true;
        }
    }
    release();
    if (control.progress)
        control.progress(1.0);
    return stats;
}

DensitySink::DensitySink(const RasterFrame &frame, std::vector<Projection> views,
                         Accumulation mode, const EngineColours &colours, int maps)
    : m_frame(frame), m_views(std::move(views)), m_colours(colours), m_maps(std::max(1, maps)),
      m_image(frame.cellsX(), frame.cellsY(), mode),
      m_coords(labelCoordinates(colours.labelColours.size()))
{
    frame.validate();
}

void DensitySink::consume(const Mat &v, StartSet::Kind kind, const std::uint8_t *a, int n)
{
    const std::uint32_t label = addressLabel(a, n, m_colours.prefix, m_maps);
    const double sx = m_frame.cellsX() / (m_frame.x1 - m_frame.x0);
    const double sy = m_frame.cellsY() / (m_frame.y1 - m_frame.y0);
    Plotter plotter{m_image, m_image.cellsX(), m_image.cellsY(), m_coords.data()};
    std::vector<double> xs;
    m_screen.resize(std::size_t(v.rows()) * 2);
    for (const Projection &view : m_views) {
        const Mat p = project(view, v);
        for (Eigen::Index r = 0; r < p.rows(); ++r) {
            m_screen[2 * r] = (p(r, 0) - m_frame.x0) * sx;
            m_screen[2 * r + 1] = (m_frame.y1 - p(r, 1)) * sy;
        }
        plotter.image(m_screen.data(), int(p.rows()), kind, label, xs);
    }
}

} // namespace awb
