#pragma once
// The pieces of the flame's chaos game (FlameChaos.cpp): the xform choice (weights, xaos), the
// camera to cells, the xforms ready to apply (and their waves, XformWave.h), and the two sinks
// a hit goes to -- the engine's labelled histogram and flam3's colour buckets. Internal to
// src/core/flame.

#include "core/flame/Flame.h"
#include "core/flame/FlameChaos.h"
#include "core/flame/FlameHits.h"
#include "core/flame/FlameStep.h"
#include "core/flame/Variations.h"
#include "core/flame/XformWave.h"
#include "core/ifs/Random.h"
#include "core/render/Density.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace awb::flame::detail {

// The choice of the next xform: row 0 by the weights alone, row i + 1 after xform i by the
// weights times its xaos row (one row when no xaos differs from 1).
struct Choice {
    std::vector<AliasTable> rows;
    bool xaos = false;

    explicit Choice(const Flame &f)
    {
        const std::size_t n = f.xforms.size();
        std::vector<double> w(n);
        for (std::size_t j = 0; j < n; ++j)
            w[j] = f.xforms[j].weight;
        rows.emplace_back(w, int(n));
        for (const FlameXform &x : f.xforms)
            for (std::size_t j = 0; j < n; ++j)
                xaos = xaos || x.xaosTo(j) != 1.0;
        if (!xaos)
            return;
        for (const FlameXform &x : f.xforms) {
            std::vector<double> r(n);
            for (std::size_t j = 0; j < n; ++j)
                r[j] = w[j] * x.xaosTo(j);
            rows.emplace_back(r, int(n));
        }
    }
};

struct Plot {
    // World to cells: col = (x - x0) sx, row = (y_flame + y1) sy (y_flame = -y_world).
    double x0, y1, sx, sy;
    int w, h;
    // Rotation about the centre (flam3 rotates the plotted points, not the orbit).
    bool rotated = false;
    double cx = 0, cy = 0, r00 = 1, r01 = 0, r10 = 0, r11 = 1;

    Plot(const Flame &f, const RasterFrame &frame)
        : x0(frame.x0), y1(frame.y1), sx(frame.cellsX() / (frame.x1 - frame.x0)),
          sy(frame.cellsY() / (frame.y1 - frame.y0)), w(frame.cellsX()), h(frame.cellsY())
    {
        if (f.rotate != 0) {
            rotated = true;
            cx = f.centre[0];
            cy = f.centre[1];
            const double a = f.rotate * 2 * M_PI / 360.0;
            r00 = std::cos(a);
            r01 = -std::sin(a);
            r10 = -r01;
            r11 = r00;
        }
    }
    // The same numbers for the AVX-512 step (FlameStep.h).
    StepCamera numbers() const
    {
        return {x0, y1, sx, sy, w, h, rotated, cx, cy, r00, r01, r10, r11};
    }
    // The cell of a point, or -1 off the frame.
    std::ptrdiff_t cell(double x, double y) const
    {
        if (rotated) {
            const double dx = x - cx, dy = y - cy;
            x = dx * r00 + dy * r01 + cx;
            y = dx * r10 + dy * r11 + cy;
        }
        const double u = (x - x0) * sx, v = (y + y1) * sy;
        if (!(u >= 0 && v >= 0 && u < w && v < h))
            return -1;
        return std::ptrdiff_t(v) * w + std::ptrdiff_t(u);
    }
};

struct Xforms {
    std::vector<XformMap> maps;
    std::vector<double> colour, speed, opacity;
    std::unique_ptr<XformMap> final;
    double finalColour = 0, finalSpeed = 0, finalOpacity = 1;
    // The same maps on waves of orbits (XformWave.h).
    std::vector<XformWave> waves;
    std::unique_ptr<XformWave> finalWave;
    // Whether the game runs on AVX-512 (the waves' eight-lane kernels and the wide step).
    bool wide = false;
    static constexpr std::size_t kWideXforms = 16;

    Xforms(const Xforms &) = delete;  // the waves point at the maps
    Xforms &operator=(const Xforms &) = delete;
    explicit Xforms(const Flame &f)
    {
        maps.reserve(f.xforms.size());
        for (const FlameXform &x : f.xforms) {
            maps.emplace_back(x);
            colour.push_back(x.colour);
            speed.push_back(x.colourSpeed);
            opacity.push_back(x.opacity);
        }
        if (f.finalXform) {
            final = std::make_unique<XformMap>(*f.finalXform);
            finalColour = f.finalXform->colour;
            finalSpeed = f.finalXform->colourSpeed;
            finalOpacity = f.finalXform->opacity;
        }
        // Eight lanes where the stacks fill them: at most 16 xforms, about 16 of a stream's
        // 256 orbits or more each (the bench's three-xform flame 20.1 -> 12.9 ns a sample; a
        // 256-xform flame's stacks hold two orbits, 15.5 s on four lanes, 18.2 s on eight).
        wide = XformWave::wide() && f.xforms.size() <= kWideXforms;
        for (const XformMap &m : maps)
            waves.emplace_back(m, wide);
        if (final)
            finalWave = std::make_unique<XformWave>(*final, wide);
    }
};

// A sink takes the hits of one stack's orbits (FlameChaos.cpp's runWave) at once: `room(m)`
// gives space for m hits, the game writes those it draws there (prefetching their cells: cell
// i at prefetchBase() + i sizeof(cell), when that is not null), and `take(n)` hands over the
// first n. `keep` is its rule for an xform's opacity (kOpacityByChance: drawn with that
// probability; else drawn whenever it is not 0, the hit weighed by it).

// Where the engine's histogram takes a hit: its palette index (flam3's step index) as the label;
// an xform's opacity as the probability of drawing the hit (the same expected density in whole
// hits).
struct LabelSink {
    DensityImage &image;
    const std::uint8_t *coordinates;
    HitBuffer hits;

    static constexpr bool kOpacityByChance = true;
    bool keep(double opacity, Xoshiro256 &rng) const
    {
        return opacity == 1.0 || (opacity > 0 && uniform01(rng) < opacity);
    }
    void prefetch(std::size_t) const {}
    const char *prefetchBase() const { return nullptr; }
    std::uint32_t table(std::size_t) const { return 0; }
    FlameHits room(std::size_t m)
    {
        if (hits.size() < m)
            hits.resize(m);
        return hits.hits();
    }
    void take(std::size_t n)
    {
        for (std::size_t h = 0; h < n; ++h)
            image.add(hits.cell[h], std::uint32_t(paletteIndexOf(hits.colour[h], false).i),
                      coordinates);
    }
    void flush() {}
};

// Where flam3's buckets take a hit (rect.c, iter_thread): gathered in runs of about kHitRun
// (FlameHits.h), each cell prefetched when its hit comes and added when the run is full -- by
// addHits, or on AVX2 or AVX-512 registers where the wave's kernels of that width run.
// With whole deltas (HitDeltas: the step palette, as most flames), a hit is its cell and row
// of them, added by addHitsWhole (or its AVX2 form).
struct ColourSink {
    FlameHistogram &histogram;
    HitPalette palette;
    enum class Adds { Scalar, Avx2, Avx512 } adds;  // addHits, addHitsAvx2, addHitsAvx512
    const HitDeltas *deltas;                        // null: the hits' colours and opacities
    HitBuffer hits;
    std::size_t count = 0;

    static constexpr bool kOpacityByChance = false;
    bool keep(double opacity, Xoshiro256 &) const { return opacity != 0; }
    void prefetch(std::size_t k) const { __builtin_prefetch(histogram.cells.data() + k, 1); }
    const char *prefetchBase() const
    {
        return reinterpret_cast<const char *>(histogram.cells.data());
    }
    // Xform k's first row of the whole deltas.
    std::uint32_t table(std::size_t k) const { return deltas ? deltas->table[k] : 0; }
    FlameHits room(std::size_t m)
    {
        if (count + m > hits.size()) {
            flush();
            if (m > hits.size())
                hits.resize(m);
        }
        return hits.hits(deltas != nullptr).from(count);
    }
    void take(std::size_t n)
    {
        count += n;
        if (count >= kHitRun)
            flush();
    }
    // The hits gathered, in the order they came (a cell takes its sums in hit order).
    void flush()
    {
        if (deltas) {
            if (adds == Adds::Scalar)
                addHitsWhole(hits.hits(true), count, *deltas, histogram.cells.data());
            else  // 128-bit integer operations: AVX2's encoding serves both
                addHitsWholeAvx2(hits.hits(true), count, *deltas, histogram.cells.data());
            count = 0;
            return;
        }
        switch (adds) {
        case Adds::Avx512:
            addHitsAvx512(hits.hits(), count, palette, histogram.cells.data());
            break;
        case Adds::Avx2:
            addHitsAvx2(hits.hits(), count, palette, histogram.cells.data());
            break;
        case Adds::Scalar:
            addHits(hits.hits(), count, palette, histogram.cells.data());
            break;
        }
        count = 0;
    }
};

} // namespace awb::flame::detail
