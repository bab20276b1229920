#pragma once
// The engine's kernel primitives (private to core/render/Engine*.cpp): the maps and views of a
// job in flat arrays of a fixed dimension D <= kMaxFixedDim, the leaf kernels (baseline and
// AVX2), and the plotting of a hit in each of the four Stores of DensityImage. Random iteration
// is in EngineChaos.h, deterministic iteration in EngineDfs.h, the choice between them in
// EngineRun.h; Engine.cpp sees only EngineShared.h.

#include "core/Decompositions.h"
#include "core/render/EngineShared.h"
#include "core/render/Plotter.h"
#include "core/Messages.h"
#include "core/ifs/Random.h"

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

namespace awb::engine {

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

// (AWB_AVX2_KERNELS, AWB_AVX2_TARGET and AWB_INLINE_BODY: EngineShared.h.)

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
inline void boundsBase(const double *s, int n, int len, double *lo, double *hi, double *sum)
{
    boundsBody(s, n, len, lo, hi, sum);
}
inline void cellsBase(const double *xy, int words, int w, int h, std::int32_t *cells)
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
inline AWB_AVX2_TARGET void boundsAvx2(const double *s, int n, int len, double *lo, double *hi,
                                double *sum)
{
    boundsBody(s, n, len, lo, hi, sum);
}
// Four words at a time: cvttpd2dq is cvttsd2si on four numbers (0x80000000 when out of range
// or NaN), so the indices equal cellIndex's.
inline AWB_AVX2_TARGET void cellsAvx2(const double *xy, int words, int w, int h, std::int32_t *cells)
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

template <int D>
LeafKernels<D> leafKernels()
{
#if defined(AWB_AVX2_KERNELS)
    if (haveAvx2())
        return {&fusedRowsAvx2<D>, &boundsAvx2, &cellsAvx2, "avx2"};
#endif
    return {&fusedRowsBase<D>, &boundsBase, &cellsBase, "baseline"};
}

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

} // namespace awb::engine
