// addHits (FlameHits.h): flam3's bump_no_overflow on each of a hit's four sums.
#include "core/flame/FlameHits.h"

#include "core/render/EngineShared.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace awb::flame::detail {

void addHits(const FlameHits &hits, std::size_t n, const HitPalette &palette,
             std::array<std::uint32_t, 4> *cells)
{
    constexpr double top = double(std::numeric_limits<std::uint32_t>::max());
    for (std::size_t h = 0; h < n; ++h) {
        const PaletteIndex at = paletteIndexOf(hits.colour[h], palette.linear);
        const double *lo = palette.dmap + 4 * at.i;
        const double opacity = hits.opacity[h];
        std::array<std::uint32_t, 4> &cell = cells[hits.cell[h]];
        for (int c = 0; c < 4; ++c) {
            // The alpha sum is 255 a hit, not interpolated.
            double delta = lo[c];
            if (palette.linear && c < 3)
                delta = lo[c] * (1.0 - at.frac) + lo[4 + c] * at.frac;
            // dest = (unsigned)(dest + delta), held at UINT_MAX -- and at 0 (a negative
            // opacity, which flam3 would convert undefined).
            const double sum = std::clamp(double(cell[std::size_t(c)]) + opacity * delta, 0.0, top);
            cell[std::size_t(c)] = std::uint32_t(sum);
        }
    }
}

#if !defined(AWB_AVX2_KERNELS)
void addHitsAvx2(const FlameHits &, std::size_t, const HitPalette &, std::array<std::uint32_t, 4> *)
{
    throw std::logic_error("addHitsAvx2: no vector kernels on this platform");
}

void addHitsAvx512(const FlameHits &, std::size_t, const HitPalette &,
                   std::array<std::uint32_t, 4> *)
{
    throw std::logic_error("addHitsAvx512: no vector kernels on this platform");
}
#endif

} // namespace awb::flame::detail
