// stepAvx512 (FlameStep.h): the flame game's step on eight orbits at a time. The file of the
// core compiled for AVX-512 (F, DQ, BW, VL: src/core/CMakeLists.txt), run only where the
// processor has it (XformWave::wide). It calls no inline function of the shared headers.
//
// Per register of eight orbits: the colour moved by the xform, the counters (last xform, one
// sample less), the opacity's and the final xform's draws, the camera's cells, the next xform
// picked from the alias table (held in registers for up to 16 xforms, gathered beyond), then
// the orbits pushed onto their stacks, one compress per field and distinct next xform, and the
// drawn hits written (each cell prefetched; a hit as its colour and opacity, or its row of the
// sink's whole deltas). A fuse step (the first 15 of a batch) counts down its fuse and draws
// nothing. The rare orbits -- a bad value to retry, the last sample of a batch -- are copied
// out for the scalar step (StepOut::deferred).
#include "core/flame/FlameStep.h"

#if defined(__x86_64__) && defined(__AVX512F__) && defined(__AVX512DQ__) \
    && defined(__AVX512BW__) && defined(__AVX512VL__)

#include <immintrin.h>

namespace awb::flame::detail {

namespace {

#define AWB_STEP_INLINE __attribute__((always_inline)) inline
#define AWB_STEP_INLINE_LAMBDA __attribute__((always_inline))

// xoshiro256+ on eight lanes.
struct Rng8 {
    __m512i s0, s1, s2, s3;

    AWB_STEP_INLINE __m512i next()
    {
        const __m512i result = _mm512_add_epi64(s0, s3);
        const __m512i t = _mm512_slli_epi64(s1, 17);
        s2 = _mm512_xor_si512(s2, s0);
        s3 = _mm512_xor_si512(s3, s1);
        s1 = _mm512_xor_si512(s1, s2);
        s0 = _mm512_xor_si512(s0, s3);
        s2 = _mm512_xor_si512(s2, t);
        s3 = _mm512_rol_epi64(s3, 45);
        return result;
    }
    // [1, 2) - 1 from the top 52 bits, as uniform01.
    AWB_STEP_INLINE __m512d uniform()
    {
        const __m512i bits = _mm512_or_si512(_mm512_srli_epi64(next(), 12),
                                             _mm512_set1_epi64(0x3FF0000000000000LL));
        return _mm512_sub_pd(_mm512_castsi512_pd(bits), _mm512_set1_pd(1.0));
    }
};

} // namespace

void stepAvx512(const StepOrbits &o, const StepRule &r, const Stacks &st,
                std::uint64_t (&state)[4][8], StepOut &out)
{
    Rng8 rng{_mm512_loadu_si512(state[0]), _mm512_loadu_si512(state[1]),
             _mm512_loadu_si512(state[2]), _mm512_loadu_si512(state[3])};
    const __m512d towards = _mm512_set1_pd(r.towards), keep = _mm512_set1_pd(r.keep);
    const __m512d opacity = _mm512_set1_pd(r.opacity);
    const __m512d finalTowards = _mm512_set1_pd(r.finalTowards);
    const __m512d finalKeep = _mm512_set1_pd(r.finalKeep);
    const __m512d finalOpacity = _mm512_set1_pd(r.finalOpacity);
    const __m512d x0 = _mm512_set1_pd(r.camera.x0), y1 = _mm512_set1_pd(r.camera.y1);
    const __m512d sx = _mm512_set1_pd(r.camera.sx), sy = _mm512_set1_pd(r.camera.sy);
    const __m512d wd = _mm512_set1_pd(r.camera.w), hd = _mm512_set1_pd(r.camera.h);
    const __m512d zero = _mm512_setzero_pd();
    const __m512i wi = _mm512_set1_epi64(r.camera.w);
    const __m512i clearedFields =
        _mm512_set1_epi64((std::int64_t(0xffff) << 32) | (std::int64_t(0xff) << 24));
    const __m512i lastBits = _mm512_set1_epi64(std::int64_t(r.last) << 32);
    const __m512i one = _mm512_set1_epi64(1);
    const __m512i togoField = _mm512_set1_epi64(0xffff);
    const __m512i fuseField = _mm512_set1_epi64(std::int64_t(0xff) << 16);
    const __m512i fuseOne = _mm512_set1_epi64(std::int64_t(1) << 16);
    const __m512i columns = _mm512_set1_epi64(r.next.n);
    const __m512i low32 = _mm512_set1_epi64(0xffffffffLL);
    // The alias table in registers for up to 16 columns (8 a register).
    __m512i thr0 = _mm512_setzero_si512(), thr1 = thr0, ali0 = thr0, ali1 = thr0;
    if (!r.next.uniform && r.next.n <= 16) {
        alignas(64) std::int64_t t[16] = {}, a[16] = {};
        for (int i = 0; i < r.next.n; ++i) {
            t[i] = std::int64_t(r.next.threshold[i]);
            a[i] = r.next.alias[i];
        }
        thr0 = _mm512_load_si512(t);
        thr1 = _mm512_load_si512(t + 8);
        ali0 = _mm512_load_si512(a);
        ali1 = _mm512_load_si512(a + 8);
    }
    // Whether a hit is drawn at all (the sink's rule for the xform's opacity).
    const bool never = r.opacity == 0 || (r.opacityByChance && !(r.opacity > 0));
    const bool chance = r.opacityByChance && r.opacity != 1.0 && !never;
    const bool byChanceFinal = r.final && r.finalOpacity != 1.0;
    const bool few = r.next.n <= 4;
    const __m512i base =
        _mm512_set1_epi64(std::int64_t(reinterpret_cast<std::uintptr_t>(r.prefetch)));
    // A cell's bytes (a power of two) as a shift.
    const __m512i shift = _mm512_set1_epi64(r.stride ? __builtin_ctzll(r.stride) : 0);

    double *sx_ = st.x, *sy_ = st.y, *sc_ = st.c;
    std::uint64_t *sn_ = reinterpret_cast<std::uint64_t *>(st.n);
    std::uint32_t *top = st.top;
    const std::size_t cap = st.cap;
    const FlameHits hits = out.hits;
    // paletteIndexOf (FlameHits.h, step palette): colour 256 held to [-1, 257], truncated, held
    // to the palette; plus the xform's table.
    const bool whole = hits.entry != nullptr;
    const __m512d by256 = _mm512_set1_pd(256.0), lastIndex = _mm512_set1_pd(255.5);
    const __m256i table = _mm256_set1_epi32(int(r.table));
    std::size_t drawn = 0, offscreen = 0, deferred = 0;
    const auto *counters = reinterpret_cast<const std::uint64_t *>(o.counters);

    for (std::size_t j = 0; j < o.m; j += 8) {
        const __mmask8 in = o.m - j >= 8 ? __mmask8(0xff) : __mmask8((1u << (o.m - j)) - 1);
        const __m512i n = _mm512_maskz_loadu_epi64(in, counters + j);
        const __m512d c = _mm512_maskz_loadu_pd(in, o.colour + j);
        const __m512i b = _mm512_cvtepu8_epi64(_mm_maskz_loadu_epi8(in, o.bad + j));
        const __mmask8 special =
            (_mm512_test_epi64_mask(b, b)
             | _mm512_cmpeq_epi64_mask(_mm512_and_si512(n, togoField), one))
            & in;
        if (special) {  // rare: for the scalar step, as they came
            _mm512_mask_compressstoreu_pd(out.deferredColour + deferred, special, c);
            _mm512_mask_compressstoreu_epi64(out.deferredCounters + deferred, special, n);
            const __m512i index = _mm512_add_epi64(_mm512_set1_epi64(std::int64_t(j)),
                                                   _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0));
            _mm256_mask_compressstoreu_epi32(out.deferred + deferred, special,
                                             _mm512_cvtepi64_epi32(index));
            deferred += std::size_t(__builtin_popcount(special));
        }
        const __mmask8 go = __mmask8(in & ~special);
        if (!go)
            continue;
        // A fuse step: one fuse step less, nothing drawn, no sample counted.
        const __mmask8 fusing = _mm512_mask_test_epi64_mask(go, n, fuseField);
        const __m512d x = _mm512_maskz_loadu_pd(go, o.qx + j);
        const __m512d y = _mm512_maskz_loadu_pd(go, o.qy + j);
        const __m512d colour = _mm512_fmadd_pd(keep, c, towards);
        // Drawn: one sample less of the batch (or a fuse step less), its retries over, xform
        // k its last.
        const __m512i counted =
            _mm512_sub_epi64(_mm512_or_si512(_mm512_andnot_si512(clearedFields, n), lastBits),
                             _mm512_mask_mov_epi64(one, fusing, fuseOne));

        // The hit: kept by the opacity, through the final xform (by its opacity), the camera.
        __mmask8 kept = never ? __mmask8(0) : __mmask8(go & ~fusing);
        if (chance)
            kept &= _mm512_cmp_pd_mask(rng.uniform(), opacity, _CMP_LT_OQ);
        if (kept) {
            __m512d hx = x, hy = y, hc = colour;
            if (r.final) {
                __mmask8 fin = kept;
                if (byChanceFinal)
                    fin &= _mm512_cmp_pd_mask(rng.uniform(), finalOpacity, _CMP_LT_OQ);
                hx = _mm512_mask_loadu_pd(hx, fin, o.fx + j);
                hy = _mm512_mask_loadu_pd(hy, fin, o.fy + j);
                hc = _mm512_mask_mov_pd(hc, fin, _mm512_fmadd_pd(finalKeep, colour, finalTowards));
            }
            if (r.camera.rotated) {
                const __m512d dx = _mm512_sub_pd(hx, _mm512_set1_pd(r.camera.cx));
                const __m512d dy = _mm512_sub_pd(hy, _mm512_set1_pd(r.camera.cy));
                hx = _mm512_add_pd(_mm512_fmadd_pd(dx, _mm512_set1_pd(r.camera.r00),
                                                   _mm512_mul_pd(dy, _mm512_set1_pd(r.camera.r01))),
                                   _mm512_set1_pd(r.camera.cx));
                hy = _mm512_add_pd(_mm512_fmadd_pd(dx, _mm512_set1_pd(r.camera.r10),
                                                   _mm512_mul_pd(dy, _mm512_set1_pd(r.camera.r11))),
                                   _mm512_set1_pd(r.camera.cy));
            }
            const __m512d u = _mm512_mul_pd(_mm512_sub_pd(hx, x0), sx);
            const __m512d v = _mm512_mul_pd(_mm512_add_pd(hy, y1), sy);
            const __mmask8 inside = _mm512_mask_cmp_pd_mask(kept, u, zero, _CMP_GE_OQ)
                                    & _mm512_cmp_pd_mask(v, zero, _CMP_GE_OQ)
                                    & _mm512_cmp_pd_mask(u, wd, _CMP_LT_OQ)
                                    & _mm512_cmp_pd_mask(v, hd, _CMP_LT_OQ);
            offscreen += std::size_t(__builtin_popcount(kept & ~inside));
            // Written a register at a time (no branch on how many): the next register's
            // overwrite the lanes beyond these; each cell prefetched (those beyond, cell 0).
            // row w + column: both below 2^31 on the frame, so the 32-bit product is exact.
            const __m512i cell = _mm512_add_epi64(
                _mm512_mul_epu32(_mm512_cvttpd_epi64(v), wi), _mm512_cvttpd_epi64(u));
            const __m512i packed = _mm512_maskz_compress_epi64(inside, cell);
            _mm512_storeu_si512(hits.cell + drawn, packed);
            if (whole) {  // the row: the table's + paletteIndexOf (step) of the colour
                // colour 256 held to [0, 255.5] and truncated: paletteIndexOf's [-1, 257],
                // truncated and held to [0, 255], for every colour (NaN: max gives 0, as -1).
                const __m512d d = _mm512_min_pd(_mm512_max_pd(_mm512_mul_pd(hc, by256), zero),
                                                lastIndex);
                const __m256i i = _mm256_add_epi32(_mm512_cvttpd_epi32(d), table);
                _mm256_storeu_si256(reinterpret_cast<__m256i *>(hits.entry + drawn),
                                    _mm256_maskz_compress_epi32(inside, i));
            } else {
                _mm512_storeu_pd(hits.colour + drawn, _mm512_maskz_compress_pd(inside, hc));
                _mm512_storeu_pd(hits.opacity + drawn, opacity);
            }
            if (r.prefetch) {
                // The addresses from an aligned copy: a load from the unaligned store just
                // made may not be forwarded from it, and would wait for it to reach the cache.
                alignas(64) std::uint64_t at[8];
                _mm512_store_si512(at, _mm512_add_epi64(base, _mm512_sllv_epi64(packed, shift)));
                for (std::size_t i = 0; i < 8; ++i)
                    __builtin_prefetch(reinterpret_cast<const char *>(at[i]), 1);
            }
            drawn += std::size_t(__builtin_popcount(inside));
        }

        // The next xform: flam3's choice by the row (AliasTable::pick on eight draws).
        const __m512i draw = rng.next();
        __m512i to = _mm512_srli_epi64(_mm512_mul_epu32(_mm512_srli_epi64(draw, 32), columns), 32);
        if (!r.next.uniform) {
            __m512i thr, ali;
            if (r.next.n <= 8) {
                thr = _mm512_permutexvar_epi64(to, thr0);
                ali = _mm512_permutexvar_epi64(to, ali0);
            } else if (r.next.n <= 16) {
                thr = _mm512_permutex2var_epi64(thr0, to, thr1);
                ali = _mm512_permutex2var_epi64(ali0, to, ali1);
            } else {
                const auto *threshold = reinterpret_cast<const long long *>(r.next.threshold);
                thr = _mm512_i64gather_epi64(to, threshold, 8);
                ali = _mm512_cvtepi32_epi64(_mm512_i64gather_epi32(to, r.next.alias, 4));
            }
            const __mmask8 column =
                _mm512_cmplt_epu64_mask(_mm512_and_si512(draw, low32), thr);
            to = _mm512_mask_mov_epi64(ali, column, to);
        }

        // Onto the stacks: the lanes bound for one xform at a time, compressed to its top
        // (every xform in turn when there are few: no branch to mispredict; else those the
        // lanes name).
        auto push = [&](std::uint64_t k, __mmask8 same) AWB_STEP_INLINE_LAMBDA {
            const std::size_t at = k * cap + top[k];
            _mm512_storeu_pd(sx_ + at, _mm512_maskz_compress_pd(same, x));
            _mm512_storeu_pd(sy_ + at, _mm512_maskz_compress_pd(same, y));
            _mm512_storeu_pd(sc_ + at, _mm512_maskz_compress_pd(same, colour));
            _mm512_storeu_si512(sn_ + at, _mm512_maskz_compress_epi64(same, counted));
            top[k] += std::uint32_t(__builtin_popcount(same));
        };
        if (few) {
            for (int k = 0; k < r.next.n; ++k)
                push(std::uint64_t(k), _mm512_mask_cmpeq_epi64_mask(go, to, _mm512_set1_epi64(k)));
        } else {
            alignas(64) std::uint64_t target[8];
            _mm512_store_si512(target, to);
            __mmask8 left = go;
            while (left) {
                const std::uint64_t k = target[__builtin_ctz(left)];
                const __mmask8 same = _mm512_mask_cmpeq_epi64_mask(
                    left, to, _mm512_set1_epi64(std::int64_t(k)));
                push(k, same);
                left = __mmask8(left & ~same);
            }
        }
    }
    _mm512_storeu_si512(state[0], rng.s0);
    _mm512_storeu_si512(state[1], rng.s1);
    _mm512_storeu_si512(state[2], rng.s2);
    _mm512_storeu_si512(state[3], rng.s3);
    out.drawn = drawn;
    out.offscreen = offscreen;
    out.deferredCount = deferred;
}

} // namespace awb::flame::detail

#else

#include <stdexcept>

namespace awb::flame::detail {

void stepAvx512(const StepOrbits &, const StepRule &, const Stacks &, std::uint64_t (&)[4][8],
                StepOut &)
{
    throw std::logic_error("stepAvx512: no AVX-512 kernels on this platform");
}

} // namespace awb::flame::detail

#endif
