#pragma once
// The hits of flam3's buckets (rect.c, iter_thread): each drawn point's cell, colour coordinate
// and opacity, gathered while the orbits run and added to the histogram (FlameChaos.h's
// FlameHistogram) a run at a time. A hit's cell is scattered over a histogram larger than the
// caches: it is prefetched when the hit is gathered and added up to kHitRun hits later, so that
// the orbits' next steps hide the miss. flam3's rule for one hit is written once in scalar code
// (addHits), on AVX2 registers (addHitsAvx2, FlameHitsAvx2.cpp) and two hits a register on
// AVX-512 (addHitsAvx512, FlameHitsAvx512.cpp), which give the very same sums
// (tests/core/test_flame_wave.cpp); where the sums allow whole numbers (HitDeltas, below), a hit
// is its cell and a row of them, added by addHitsWhole. Internal to src/core/flame.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace awb::flame::detail {

// Hits side by side: hit h's colour coordinate (0..1), opacity (the xform's: flam3's logvis
// times its opacity) and cell at index h of each array -- so that the AVX-512 step writes a
// register of them at once. Where the sink adds whole deltas (HitDeltas), `entry` is not null
// and a hit is its cell and its row of the deltas (its xform's table + its palette index) in
// place of its colour and opacity.
struct FlameHits {
    double *colour;
    double *opacity;
    std::uint64_t *cell;
    std::uint32_t *entry = nullptr;

    // `table`: the first row of the hit's xform's deltas (used only where `entry` is set).
    [[gnu::always_inline]] inline void put(std::size_t h, double c, double o, std::size_t k,
                                           std::uint32_t table) const;
    FlameHits from(std::size_t h) const
    {
        return {colour + h, opacity + h, cell + h, entry ? entry + h : nullptr};
    }
};

// The arrays of FlameHits, with a register's padding after them (the AVX-512 step writes whole
// registers; the lanes beyond its hits are overwritten by the next ones or ignored).
struct HitBuffer {
    static constexpr std::size_t kPadding = 8;  // one AVX-512 register of hits
    std::vector<double> colour, opacity;
    std::vector<std::uint64_t> cell;
    std::vector<std::uint32_t> entry;

    std::size_t size() const { return colour.empty() ? 0 : colour.size() - kPadding; }
    void resize(std::size_t n)
    {
        colour.resize(n + kPadding);
        opacity.resize(n + kPadding);
        cell.resize(n + kPadding);
        entry.resize(n + kPadding);
    }
    // `whole`: the hits as rows of whole deltas (FlameHits::entry).
    FlameHits hits(bool whole = false)
    {
        return {colour.data(), opacity.data(), cell.data(), whole ? entry.data() : nullptr};
    }
};

inline constexpr std::size_t kHitRun = 256;

// The palette as flam3's dmap: entry i is (r, g, b, 255) x 255 at dmap[4 i .. 4 i + 3].
struct HitPalette {
    const double *dmap;  // 256 x 4
    bool linear;         // flam3's palette_mode linear (else step)
};

// Adds the hits to the cells in order, as flam3's bump_no_overflow: a cell's four sums (r, g,
// b: the palette at the colour, step or linear; alpha: 255), each times the opacity, added,
// held at 2^32 - 1 (and 0), truncated to whole numbers after every hit.
void addHits(const FlameHits &hits, std::size_t n, const HitPalette &palette,
             std::array<std::uint32_t, 4> *cells);
// The same on AVX2 registers; call only where XformWave::available().
void addHitsAvx2(const FlameHits &hits, std::size_t n, const HitPalette &palette,
                 std::array<std::uint32_t, 4> *cells);
// The same two hits a register on AVX-512 (FlameHitsAvx512.cpp); call only where
// XformWave::wide().
void addHitsAvx512(const FlameHits &hits, std::size_t n, const HitPalette &palette,
                   std::array<std::uint32_t, 4> *cells);

// flam3's colour index of a hit: (int)(c 256) clamped to the palette, and for the linear mode
// the fraction towards the next entry (the last pair for c >= 255/256, the first below 0).
// NaN cannot occur (finite colours, convex steps); out-of-range colours are clamped first so
// that the conversion is defined. Internal to each file and always inlined: FlameHitsAvx2.cpp
// is compiled for AVX2, and no AVX2 copy of a shared function may reach the rest of the program.
struct PaletteIndex {
    int i;
    double frac;
};
[[gnu::always_inline]] static inline PaletteIndex paletteIndexOf(double colour, bool linear)
{
    double d = colour * 256.0;
    d = d < -1.0 ? -1.0 : (d > 257.0 ? 257.0 : d);
    const int i = int(d);
    if (!linear)
        return {i < 0 ? 0 : (i > 255 ? 255 : i), 0.0};
    if (i < 0)
        return {0, 0.0};
    if (i >= 255)
        return {254, 1.0};
    return {i, d - i};
}

[[gnu::always_inline]] inline void FlameHits::put(std::size_t h, double c, double o,
                                                  std::size_t k, std::uint32_t table) const
{
    if (entry) {
        entry[h] = table + std::uint32_t(paletteIndexOf(c, false).i);
    } else {
        colour[h] = c;
        opacity[h] = o;
    }
    cell[h] = k;
}

// flam3's sums of a hit as whole numbers, where they can be: a cell's sums are whole, so
// (unsigned)(dest + delta) is dest + floor(delta) as long as delta >= 0 and the double sum does
// not round up to the next whole number -- which it cannot when delta's fraction is below
// 1 - 2^-20 (a sum below 2^32 is exact to 2^-21). With the step palette and such deltas for
// every entry and opacity, a hit's four sums are a row of whole numbers looked up once (its
// xform's opacity's table, its palette index) and added held at 2^32 - 1: the very sums of
// addHits, in fewer instructions (addHitsWhole).
struct HitDeltas {
    static constexpr std::size_t kMostTables = 16;  // distinct opacities (64 KB of rows)
    std::vector<std::array<std::uint32_t, 4>> rows;  // table t, palette index i: row 256 t + i
    std::vector<std::uint32_t> table;                // xform k's first row (256 t)

    // The rows for these xforms' opacities, or empty when some delta is not whole-safe (the
    // linear palette, a negative or NaN delta, a fraction within 2^-20 of 1) or there are more
    // than kMostTables distinct opacities: then the hits keep their colour and opacity.
    static HitDeltas of(const HitPalette &palette, const std::vector<double> &opacities);
    bool empty() const { return rows.empty(); }
};

// The hits (rows of `deltas`) added to their cells in order, held at 2^32 - 1: addHits' sums.
void addHitsWhole(const FlameHits &hits, std::size_t n, const HitDeltas &deltas,
                  std::array<std::uint32_t, 4> *cells);
// The same on a quarter of an AVX2 register (FlameHitsAvx2.cpp), for the AVX2 and AVX-512
// games alike (the bench's flame: 12.9 ns a sample with addHitsWhole, 10.3 with this on
// AVX-512; 21.7 -> 19.5 on the AVX2 path); call only where XformWave::available().
void addHitsWholeAvx2(const FlameHits &hits, std::size_t n, const HitDeltas &deltas,
                      std::array<std::uint32_t, 4> *cells);

} // namespace awb::flame::detail
