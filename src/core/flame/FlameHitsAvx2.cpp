// addHitsAvx2 (FlameHits.h): flam3's bump_no_overflow on a hit's four sums in one register;
// addHitsWholeAvx2, a hit's row of whole deltas (HitDeltas) in a quarter of one.
// Compiled with -mavx2 -mfma as XformWaveAvx2.cpp (src/core/CMakeLists.txt says why), and run
// only where the processor has AVX2.
#include "core/flame/FlameHits.h"

#if defined(__x86_64__) && defined(__AVX2__)

#include "core/flame/FlameHitsVector.h"

namespace awb::flame::detail {

void addHitsAvx2(const FlameHits &hits, std::size_t n, const HitPalette &palette,
                 std::array<std::uint32_t, 4> *cells)
{
    // An unsigned sum u as a double: the signed conversion of u - 2^31, plus 2^31; back: the
    // truncated double minus 2^31, converted signed, plus 2^31 (both exact on 0 .. 2^32 - 1).
    const __m128i bias = _mm_set1_epi32(int(0x80000000u));
    const __m256d half = _mm256_set1_pd(2147483648.0);
    const __m256d top = _mm256_set1_pd(4294967295.0);
    const __m256d zero = _mm256_setzero_pd();
    for (std::size_t h = 0; h < n; ++h) {
        const __m256d delta = hitDelta(hits, h, palette);
        auto *cell = reinterpret_cast<std::uint32_t *>(cells + hits.cell[h]);  // no inline call
        const __m128i u = _mm_loadu_si128(reinterpret_cast<const __m128i *>(cell));
        __m256d sum = _mm256_add_pd(_mm256_cvtepi32_pd(_mm_xor_si128(u, bias)), half);
        sum = _mm256_add_pd(sum, delta);
        sum = _mm256_max_pd(_mm256_min_pd(sum, top), zero);
        sum = _mm256_round_pd(sum, _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
        const __m128i back = _mm_xor_si128(_mm256_cvttpd_epi32(_mm256_sub_pd(sum, half)), bias);
        _mm_storeu_si128(reinterpret_cast<__m128i *>(cell), back);
    }
}

void addHitsWholeAvx2(const FlameHits &hitsIn, std::size_t n, const HitDeltas &deltas,
                      std::array<std::uint32_t, 4> *cells)
{
    const FlameHits hits = hitsIn;  // kept in registers (the cells' stores could be any of it)
    const std::array<std::uint32_t, 4> *rows = deltas.rows.data();
    const __m128i ones = _mm_set1_epi32(-1);
    for (std::size_t h = 0; h < n; ++h) {
        auto *cell = reinterpret_cast<__m128i *>(cells + hits.cell[h]);  // no inline call
        const __m128i d = _mm_loadu_si128(reinterpret_cast<const __m128i *>(rows + hits.entry[h]));
        // min(dest, ~d) + d: each sum held at 2^32 - 1 (as addHitsWhole).
        _mm_storeu_si128(cell, _mm_add_epi32(_mm_min_epu32(_mm_loadu_si128(cell),
                                                           _mm_xor_si128(d, ones)),
                                             d));
    }
}

} // namespace awb::flame::detail

#endif
