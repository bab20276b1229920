#pragma once
// The engine's generic rasteriser (private to core/render/Engine*.cpp): the cells of points,
// segments and triangles in raster space (y down), into a DensityImage with a label each. The
// fixed-dimension kernels use it for the images they do not fuse; DensitySink for every image.

#include "core/Types.h"
#include "core/render/Density.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace awb::engine {

// ---- the generic rasteriser (cells, y down) ------------------------------------------------

struct Plotter {
    DensityImage &img;
    int w, h;
    const std::uint8_t *coords;  // colour coordinate of each label (density)

    // Images whose every vertex lies in [0, xMax) x [0, yMax) need no clipping (imageInside).
    double xMax() const { return double(w) - 1e-9; }
    double yMax() const { return double(h) - 1e-9; }

    void cell(int x, int y, std::uint32_t label)
    {
        if (x < 0 || y < 0 || x >= w || y >= h) {
            ++img.offscreen;
            return;
        }
        img.add(std::size_t(y) * w + x, label, coords);
    }

    // The cells of the segment from (sx, sy) to (ex, ey), sampled at least once per cell side,
    // to emit(x, y) (consecutive repeats dropped).
    template <class Emit>
    static void walk(double sx, double sy, double ex, double ey, Emit &&emit)
    {
        const int steps = int(std::ceil(std::max(std::abs(ex - sx), std::abs(ey - sy)))) + 1;
        int lastX = INT_MIN, lastY = INT_MIN;
        for (int s = 0; s <= steps; ++s) {
            const double t = double(s) / steps;
            const int x = int(std::floor(sx + t * (ex - sx)));
            const int y = int(std::floor(sy + t * (ey - sy)));
            if (x != lastX || y != lastY)
                emit(x, y);
            lastX = x;
            lastY = y;
        }
    }

    void line(double ax, double ay, double bx, double by, std::uint32_t label)
    {
        // Clip to the raster (Liang-Barsky) so that a huge segment costs nothing off screen.
        double t0 = 0, t1 = 1;
        const double dx = bx - ax, dy = by - ay;
        const double p[4] = {-dx, dx, -dy, dy};
        const double q[4] = {ax, xMax() - ax, ay, yMax() - ay};
        for (int k = 0; k < 4; ++k) {
            if (p[k] == 0) {
                if (q[k] < 0) {
                    ++img.offscreen;
                    return;
                }
            } else {
                const double r = q[k] / p[k];
                if (p[k] < 0)
                    t0 = std::max(t0, r);
                else
                    t1 = std::min(t1, r);
            }
        }
        if (t0 > t1) {
            ++img.offscreen;
            return;
        }
        walk(ax + t0 * dx, ay + t0 * dy, ax + t1 * dx, ay + t1 * dy,
             [&](int x, int y) { cell(x, y, label); });
    }

    // Even-odd fill: emit(x, y) for the cells of the raster whose centres lie inside the
    // polygon (n xy pairs); xs holds at least n numbers (the crossings of one row).
    template <class Emit>
    void fill(const double *s, int n, double *xs, Emit &&emit) const
    {
        double ymin = 1e300, ymax = -1e300;
        for (int i = 0; i < n; ++i)
            ymin = std::min(ymin, s[2 * i + 1]), ymax = std::max(ymax, s[2 * i + 1]);
        ymin = std::max(0.0, ymin);
        ymax = std::min(double(h), ymax);
        for (int y = int(std::floor(ymin)); y < int(std::ceil(ymax)); ++y) {
            const double yc = y + 0.5;
            int k = 0;
            for (int i = 0; i < n; ++i) {
                const int j = i + 1 < n ? i + 1 : 0;
                const double y0 = s[2 * i + 1], y1 = s[2 * j + 1];
                if ((y0 <= yc && y1 > yc) || (y1 <= yc && y0 > yc))
                    xs[k++] = s[2 * i] + (yc - y0) / (y1 - y0) * (s[2 * j] - s[2 * i]);
            }
            // Few crossings (two for a convex image): insertion sort.
            for (int a = 1; a < k; ++a)
                for (int b = a; b > 0 && xs[b] < xs[b - 1]; --b)
                    std::swap(xs[b], xs[b - 1]);
            for (int c = 0; c + 1 < k; c += 2) {
                const int xa = std::max(0, int(std::ceil(xs[c] - 0.5)));
                const int xb = std::min(w - 1, int(std::floor(xs[c + 1] - 0.5)));
                for (int x = xa; x <= xb; ++x)
                    emit(x, y);
            }
        }
    }

    // One image of the start set, already in cells (n xy pairs). A polygon or polyline whose
    // image lies inside one cell is one hit there.
    void image(const double *s, int n, StartSet::Kind kind, std::uint32_t label,
               std::vector<double> &xs)
    {
        for (int i = 0; i < 2 * n; ++i)
            if (!std::isfinite(s[i])) {
                ++img.nonFinite;
                return;
            }
        if (kind == StartSet::Kind::Points || n == 1) {
            for (int i = 0; i < n; ++i)
                cell(int(std::floor(s[2 * i])), int(std::floor(s[2 * i + 1])), label);
            return;
        }
        double x0 = s[0], x1 = s[0], y0 = s[1], y1 = s[1];
        for (int i = 1; i < n; ++i) {
            x0 = std::min(x0, s[2 * i]), x1 = std::max(x1, s[2 * i]);
            y0 = std::min(y0, s[2 * i + 1]), y1 = std::max(y1, s[2 * i + 1]);
        }
        if (std::floor(x0) == std::floor(x1) && std::floor(y0) == std::floor(y1)) {
            cell(int(std::floor(x0)), int(std::floor(y0)), label);
            return;
        }
        if (xs.size() < std::size_t(n))
            xs.resize(std::size_t(n));
        if (x0 >= 0 && y0 >= 0 && x1 < xMax() && y1 < yMax()) {
            imageInside(s, n, kind, label, xs.data(), x0, y0, x1, y1);
            return;
        }
        auto emit = [&](int x, int y) { cell(x, y, label); };
        if (kind == StartSet::Kind::Polygon && n >= 3)
            fill(s, n, xs.data(), emit);
        const int segments = kind == StartSet::Kind::Polygon ? n : n - 1;
        for (int r = 0; r < segments; ++r) {
            const int q = r + 1 < n ? r + 1 : 0;
            line(s[2 * r], s[2 * r + 1], s[2 * q], s[2 * q + 1], label);
        }
    }

    // The cells of a polyline or polygon whose vertices all lie inside [0, xMax) x [0, yMax),
    // to emit(x, y): the filled cells of a polygon, then its edges' samples. No clipping: it
    // would leave t0 = 0 and t1 = 1 there, rounding included.
    template <class Emit>
    void traceInside(const double *s, int n, StartSet::Kind kind, double *xs, Emit &&emit) const
    {
        if (kind == StartSet::Kind::Polygon && n >= 3)
            fill(s, n, xs, emit);
        const int segments = kind == StartSet::Kind::Polygon ? n : n - 1;
        for (int r = 0; r < segments; ++r) {
            const int q = r + 1 < n ? r + 1 : 0;
            const double dx = s[2 * q] - s[2 * r], dy = s[2 * q + 1] - s[2 * r + 1];
            walk(s[2 * r] + 0.0 * dx, s[2 * r + 1] + 0.0 * dy, s[2 * r] + 1.0 * dx,
                 s[2 * r + 1] + 1.0 * dy, emit);
        }
    }

    // A polyline or polygon of n >= 2 vertices over several cells, inside the raster, with
    // bounding box [x0, x1] x [y0, y1]. An image within a 2 x 2 block of cells (deep levels)
    // adds one hit to each cell it covers, however many of its samples fall there. xs: n
    // numbers.
    void imageInside(const double *s, int n, StartSet::Kind kind, std::uint32_t label,
                     double *xs, double x0, double y0, double x1, double y1)
    {
        // Coordinates are >= 0 here: truncation is the floor.
        const int bx = int(x0), by = int(y0);
        if (int(x1) - bx > 1 || int(y1) - by > 1) {
            traceInside(s, n, kind, xs, [&](int x, int y) { cell(x, y, label); });
            return;
        }
        unsigned mask = 0;
        traceInside(s, n, kind, xs, [&](int x, int y) {
            const unsigned dx = unsigned(x - bx), dy = unsigned(y - by);
            if ((dx | dy) <= 1u)
                mask |= 1u << (2 * dy + dx);
            else
                cell(x, y, label);  // a sample rounded past the block's edge
        });
        for (unsigned k = 0; k < 4; ++k)
            if (mask & (1u << k))
                cell(bx + int(k & 1u), by + int(k >> 1), label);
    }
};

} // namespace awb::engine
