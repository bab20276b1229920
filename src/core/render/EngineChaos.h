#pragma once
// Random iteration (private to core/render/Engine*.cpp): interleaved orbits of the chaos game,
// their map choices drawn in blocks and their points scattered into the histogram of a Store.

#include "core/render/EngineKernels.h"

namespace awb::engine {

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

inline AWB_AVX2_TARGET void uniformChoices4Avx2(Xoshiro256 *rngs, int steps, std::uint64_t n,
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
} // namespace awb::engine
