#pragma once
// A hit's four sums to add (flam3's palette entry, step or linear, times the hit's opacity) in
// one AVX register: the one definition of it for addHitsAvx2 and addHitsAvx512. Included only
// by those two files, which are compiled for AVX2 and AVX-512 (the function is static and
// always inlined: no copy of it reaches the rest of the program). Internal to src/core/flame.

#include "core/flame/FlameHits.h"

#include <immintrin.h>

namespace awb::flame::detail {

[[gnu::always_inline]] static inline __m256d hitDelta(const FlameHits &hits, std::size_t h,
                                                      const HitPalette &palette)
{
    const PaletteIndex at = paletteIndexOf(hits.colour[h], palette.linear);
    const double *lo = palette.dmap + 4 * at.i;
    __m256d delta = _mm256_loadu_pd(lo);
    if (palette.linear) {
        const __m256d hi = _mm256_loadu_pd(lo + 4);
        // lo (1 - frac) + hi frac, as the scalar rule (no fused multiply-add: the same
        // roundings); the alpha sum keeps 255.
        const __m256d mixed = _mm256_add_pd(_mm256_mul_pd(delta, _mm256_set1_pd(1.0 - at.frac)),
                                            _mm256_mul_pd(hi, _mm256_set1_pd(at.frac)));
        delta = _mm256_blend_pd(mixed, delta, 0x8);
    }
    return _mm256_mul_pd(_mm256_set1_pd(hits.opacity[h]), delta);
}

} // namespace awb::flame::detail
