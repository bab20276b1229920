// addHits (FlameHits.h): flam3's bump_no_overflow on each of a hit's four sums; HitDeltas and
// addHitsWhole, the same sums as whole numbers.
#include "core/flame/FlameHits.h"

#include "core/render/EngineShared.h"

#include <algorithm>
#include <cmath>
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

HitDeltas HitDeltas::of(const HitPalette &palette, const std::vector<double> &opacities)
{
    HitDeltas d;
    if (palette.linear)
        return d;
    std::vector<double> distinct;
    for (const double o : opacities) {
        const auto at = std::find(distinct.begin(), distinct.end(), o);
        if (at == distinct.end() && distinct.size() == kMostTables)
            return d;
        d.table.push_back(std::uint32_t(256 * (at - distinct.begin())));
        if (at == distinct.end())
            distinct.push_back(o);
    }
    constexpr double top = double(std::numeric_limits<std::uint32_t>::max());
    constexpr double margin = 1.0 / (1 << 20);
    d.rows.resize(256 * distinct.size());
    for (std::size_t t = 0; t < distinct.size(); ++t)
        for (std::size_t i = 0; i < 256; ++i)
            for (std::size_t c = 0; c < 4; ++c) {
                const double delta = distinct[t] * palette.dmap[4 * i + c];  // as addHits
                std::uint32_t whole = std::numeric_limits<std::uint32_t>::max();
                if (!(delta >= 0))
                    return {};
                if (delta < top) {
                    const double floor = std::floor(delta);
                    if (delta - floor > 1.0 - margin)
                        return {};
                    whole = std::uint32_t(floor);
                }
                d.rows[256 * t + i][c] = whole;
            }
    return d;
}

void addHitsWhole(const FlameHits &hits, std::size_t n, const HitDeltas &deltas,
                  std::array<std::uint32_t, 4> *cells)
{
    const std::array<std::uint32_t, 4> *rows = deltas.rows.data();
    for (std::size_t h = 0; h < n; ++h) {
        std::uint32_t *cell = cells[hits.cell[h]].data();
        const std::uint32_t *d = rows[hits.entry[h]].data();
        for (int c = 0; c < 4; ++c)  // held at 2^32 - 1: min(dest, ~d) + d
            cell[c] = (cell[c] < ~d[c] ? cell[c] : ~d[c]) + d[c];
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

void addHitsWholeAvx2(const FlameHits &, std::size_t, const HitDeltas &,
                      std::array<std::uint32_t, 4> *)
{
    throw std::logic_error("addHitsWholeAvx2: no vector kernels on this platform");
}
#endif

} // namespace awb::flame::detail
