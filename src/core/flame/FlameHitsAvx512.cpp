// addHitsAvx512 (FlameHits.h): flam3's bump_no_overflow on two hits at once, their eight sums in
// one register. Compiled for AVX-512 as FlameStepAvx512.cpp (src/core/CMakeLists.txt), and run
// only where the processor has it (XformWave::wide). The rule is addHitsAvx2's, whose sums it
// gives to the unit: the unsigned conversions of AVX-512 in place of its biased signed ones
// (both exact on 0 .. 2^32 - 1), the same products and sums without fused multiply-adds. Two
// hits on one cell are added one after the other.
#include "core/flame/FlameHits.h"

#if defined(__x86_64__) && defined(__AVX512F__) && defined(__AVX512DQ__) \
    && defined(__AVX512BW__) && defined(__AVX512VL__)

#include "core/flame/FlameHitsVector.h"

namespace awb::flame::detail {

namespace {

#define AWB_HITS_INLINE __attribute__((always_inline)) inline

AWB_HITS_INLINE std::uint32_t *cellOf(std::array<std::uint32_t, 4> *cells, std::uint64_t k)
{
    return reinterpret_cast<std::uint32_t *>(cells + k);  // no inline call
}

// One hit: its cell's four sums in the low half of a register.
AWB_HITS_INLINE void addOne(const FlameHits &hits, std::size_t h, const HitPalette &palette,
                            std::array<std::uint32_t, 4> *cells)
{
    std::uint32_t *cell = cellOf(cells, hits.cell[h]);
    const __m128i u = _mm_loadu_si128(reinterpret_cast<const __m128i *>(cell));
    __m256d sum = _mm256_add_pd(_mm256_cvtepu32_pd(u), hitDelta(hits, h, palette));
    sum = _mm256_max_pd(_mm256_min_pd(sum, _mm256_set1_pd(4294967295.0)), _mm256_setzero_pd());
    _mm_storeu_si128(reinterpret_cast<__m128i *>(cell), _mm256_cvttpd_epu32(sum));
}

} // namespace

void addHitsAvx512(const FlameHits &hitsIn, std::size_t n, const HitPalette &paletteIn,
                   std::array<std::uint32_t, 4> *cells)
{
    // Copies the loop keeps in registers (the cells' stores could otherwise be any of them).
    const FlameHits hits = hitsIn;
    const HitPalette palette = paletteIn;
    const __m512d top = _mm512_set1_pd(4294967295.0);
    const __m512d zero = _mm512_setzero_pd();
    std::size_t h = 0;
    for (; h + 1 < n; h += 2) {
        if (hits.cell[h] == hits.cell[h + 1]) {  // one after the other
            addOne(hits, h, palette, cells);
            addOne(hits, h + 1, palette, cells);
            continue;
        }
        std::uint32_t *c0 = cellOf(cells, hits.cell[h]), *c1 = cellOf(cells, hits.cell[h + 1]);
        const __m512d delta = _mm512_insertf64x4(_mm512_castpd256_pd512(hitDelta(hits, h, palette)),
                                                 hitDelta(hits, h + 1, palette), 1);
        const __m256i u = _mm256_inserti128_si256(
            _mm256_castsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i *>(c0))),
            _mm_loadu_si128(reinterpret_cast<const __m128i *>(c1)), 1);
        __m512d sum = _mm512_add_pd(_mm512_cvtepu32_pd(u), delta);
        sum = _mm512_max_pd(_mm512_min_pd(sum, top), zero);
        // Truncated to whole numbers by the unsigned conversion itself.
        const __m256i back = _mm512_cvttpd_epu32(sum);
        _mm_storeu_si128(reinterpret_cast<__m128i *>(c0), _mm256_castsi256_si128(back));
        _mm_storeu_si128(reinterpret_cast<__m128i *>(c1), _mm256_extracti128_si256(back, 1));
    }
    if (h < n)
        addOne(hits, h, palette, cells);
}

} // namespace awb::flame::detail

#endif
