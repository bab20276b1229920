#pragma once
// The pieces of the flame's chaos game (FlameChaos.cpp): the xform choice (weights, xaos), the
// camera to cells, the xforms ready to apply (and their waves, XformWave.h), and the two sinks
// a hit goes to -- the engine's labelled histogram and flam3's colour buckets. Internal to
// src/core/flame.

#include "core/flame/Flame.h"
#include "core/flame/FlameChaos.h"
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
        for (const XformMap &m : maps)
            waves.emplace_back(m);
        if (final)
            finalWave = std::make_unique<XformWave>(*final);
    }
};

inline std::uint32_t paletteIndex(double c)
{
    // flam3: (int)(c * 256), the last entry for c = 1.
    const double i = c * 256.0;
    return i >= 255.0 ? 255u : (i > 0 ? std::uint32_t(i) : 0u);
}

// Where the engine's histogram takes a hit: its palette index as the label; an xform's opacity
// as the probability of drawing the hit (the same expected density in whole hits).
struct LabelSink {
    DensityImage &image;
    const std::uint8_t *coordinates;

    bool keep(double opacity, Xoshiro256 &rng) const
    {
        return opacity == 1.0 || (opacity > 0 && uniform01(rng) < opacity);
    }
    void hit(std::size_t k, double c, double) { image.add(k, paletteIndex(c), coordinates); }
    void flush() {}
};

// Where flam3's buckets take a hit (rect.c, iter_thread): the palette's colour at the colour
// coordinate, step or linear, weighted by the xform's opacity. A hit's 32-byte cell is
// scattered over a histogram larger than the caches: the cell is prefetched when the hit
// comes and added kPending hits later, so that the orbit's next steps hide the miss
// (measured on a 1024^2 variation flame: the add's load was 35 % of the render; random
// read-modify-writes of 16 MiB here: 8 ns each at once, 4.6 ns 16 later, 2.5 ns 64 later).
struct ColourSink {
    static constexpr std::size_t kPending = 64;  // a power of 2
    // A hit's four sums (r, g, b, alpha), added at once.
    using Sums = double __attribute__((vector_size(32)));
    using Cell = std::uint32_t __attribute__((vector_size(16)));
    FlameHistogram &histogram;
    const Sums *dmap;  // the palette times 255, alpha 255
    bool linear;
    struct Hit {
        Sums delta;
        std::size_t k;
    };
    std::array<Hit, kPending> pending{};
    std::size_t count = 0;

    bool keep(double opacity, Xoshiro256 &) const { return opacity != 0; }
    void hit(std::size_t k, double c, double opacity)
    {
        // flam3: (int)(c * 256), clamped; NaN cannot occur (finite colours, convex steps).
        const double d = std::clamp(c * 256.0, -1.0, 257.0);
        int i = int(d);
        Sums delta;
        if (linear) {
            double frac;
            if (i < 0) {
                i = 0;
                frac = 0;
            } else if (i >= 255) {
                i = 254;
                frac = 1;
            } else {
                frac = d - i;
            }
            delta = opacity * (dmap[i] * (1.0 - frac) + dmap[i + 1] * frac);
        } else {
            delta = opacity * dmap[std::clamp(i, 0, 255)];
        }
        delta[3] = opacity * 255.0;  // the alpha sum is 255 a hit, not interpolated
        __builtin_prefetch(&histogram.cells[k], 1);
        Hit &slot = pending[count++ & (kPending - 1)];
        if (count > kPending)
            add(slot);
        slot = {delta, k};
    }
    // flam3's bump_no_overflow on each unsigned sum: dest = (unsigned)(dest + delta), held at
    // UINT_MAX -- and at 0 (a negative opacity, which flam3 would convert undefined): the four
    // sums clamped to [0, UINT_MAX] and truncated, without a branch.
    void add(const Hit &h)
    {
        constexpr double top = double(std::numeric_limits<std::uint32_t>::max());
        Cell cell;
        __builtin_memcpy(&cell, histogram.cells[h.k].data(), sizeof cell);
        Sums sum = __builtin_convertvector(cell, Sums) + h.delta;
        sum = sum > top ? top : sum;
        sum = sum > 0.0 ? sum : 0.0;
        cell = __builtin_convertvector(sum, Cell);
        __builtin_memcpy(histogram.cells[h.k].data(), &cell, sizeof cell);
    }
    // The hits still pending, in the order they came (a cell takes its sums in hit order).
    void flush()
    {
        const std::size_t n = std::min(count, kPending);
        for (std::size_t j = count - n; j < count; ++j)
            add(pending[j & (kPending - 1)]);
        count = 0;
    }
};

} // namespace awb::flame::detail
