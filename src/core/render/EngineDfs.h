#pragma once
// Deterministic iteration (private to core/render/Engine*.cpp): a depth-first walk of the
// address tree whose last levels are fused into one map per word, drawn into a Store.

#include "core/render/EngineKernels.h"

namespace awb::engine {


// The last `m` levels of a deterministic iteration fused into one table per view: for each
// word w of m maps (the first of them applied first), the composite map from the IFS space
// straight to raster cells, x -> x L_w + c_w (D x 2 and 2 numbers). A node m levels above the
// leaves then draws its N^m leaves with 2D multiply-adds each, in loops over the words that
// the compiler vectorises, and the D x D products of those m levels are never done.
//
// Words are indexed by their address read as a number: address[0] (the outermost map, the
// last applied) is the most significant digit, so the colour label of a prefix p <= m is the
// index divided by N^(m - p).
template <int D>
struct FusedLeaves {
    int m = 0;       // fused levels
    int words = 1;   // N^m
    int views = 0;
    // Cell x and y of every word side by side (one loop over 2 N^m numbers does both):
    // l[((q * D + j) * words + w) * 2 + k] is row j, column k of L_w; c[(q * words + w) * 2 + k].
    std::vector<double> l, c;

    // The most fused levels with N^m <= maxWords (and m <= levels).
    static int levelsFor(int N, int levels, int maxWords = 256)
    {
        int m = 0;
        std::int64_t w = 1;
        while (m < levels && m < 16 && w * N <= maxWords) {
            w *= N;
            ++m;
        }
        return m;
    }

    FusedLeaves(const Flat<D> &F, int levels) : m(levels), views(F.views)
    {
        for (int t = 0; t < m; ++t)
            words *= F.n;
        // Table of t maps (t = 0: the views), grown by prepending the innermost map.
        std::vector<double> L(std::size_t(views) * D * 2), C(std::size_t(views) * 2);
        for (int q = 0; q < views; ++q) {
            for (int j = 0; j < D; ++j)
                for (int k = 0; k < 2; ++k)
                    L[(std::size_t(q) * D + j) * 2 + k] = F.v[(std::size_t(q) * D + j) * 2 + k];
            C[q * 2] = F.c[q * 2];
            C[q * 2 + 1] = F.c[q * 2 + 1];
        }
        int size = 1;
        for (int t = 0; t < m; ++t) {
            std::vector<double> L2(std::size_t(views) * size * F.n * D * 2);
            std::vector<double> C2(std::size_t(views) * size * F.n * 2);
            for (int q = 0; q < views; ++q)
                for (int e = 0; e < size; ++e)
                    for (int i = 0; i < F.n; ++i) {
                        const std::size_t from = std::size_t(q) * size + e;
                        const std::size_t to = std::size_t(q) * size * F.n + std::size_t(e) * F.n + i;
                        const double *A = &F.a[std::size_t(i) * D * D];
                        const double *B = &F.b[std::size_t(i) * D];
                        const double *Le = &L[from * D * 2];
                        double *Lt = &L2[to * D * 2];
                        // L' = A_i L_e, c' = b_i L_e + c_e.
                        for (int r = 0; r < D; ++r)
                            for (int k = 0; k < 2; ++k) {
                                double acc = 0;
                                for (int j = 0; j < D; ++j)
                                    acc += A[r * D + j] * Le[j * 2 + k];
                                Lt[r * 2 + k] = acc;
                            }
                        for (int k = 0; k < 2; ++k) {
                            double acc = C[from * 2 + k];
                            for (int j = 0; j < D; ++j)
                                acc += B[j] * Le[j * 2 + k];
                            C2[to * 2 + k] = acc;
                        }
                    }
            L.swap(L2);
            C.swap(C2);
            size *= F.n;
        }
        l.resize(std::size_t(views) * D * words * 2);
        c = C;
        for (int q = 0; q < views; ++q)
            for (int w = 0; w < words; ++w) {
                const std::size_t e = std::size_t(q) * words + w;
                for (int j = 0; j < D; ++j)
                    for (int k = 0; k < 2; ++k)
                        l[((std::size_t(q) * D + j) * words + w) * 2 + k] = L[(e * D + j) * 2 + k];
            }
    }
};

// Depth-first deterministic iteration of one thread: buf[level] holds the images of the start
// set after `level` maps (the innermost first); the last T.m levels go through the fused
// table T.
template <int D, Store M>
class DfsKernel {
public:
    DfsKernel(const Flat<D> &F, const FusedLeaves<D> &T, const EngineJob &job,
              const std::uint8_t *coords, DensityImage &img, const Progress &progress)
        : m_F(F), m_T(T), m_job(job), m_coords(coords), m_img(img), m_progress(progress),
          m_depth(job.depth), m_n(int(job.start.vertices.rows())), m_kind(job.start.kind),
          m_buf(std::size_t(job.depth + 1) * m_n * D), m_screen(std::size_t(m_n) * 2),
          m_s(std::size_t(m_n) * T.words * 2), m_box(std::size_t(T.words) * 6),
          m_cells(std::size_t(T.words)), m_cells2(std::size_t(T.words)),
          m_labels(std::size_t(T.words)), m_kernels(leafKernels<D>()),
          m_plotter{img, img.cellsX(), img.cellsY(), coords}
    {
        m_xs.resize(std::size_t(std::max(m_n, 1)));
        for (int r = 0; r < m_n; ++r)
            for (int j = 0; j < D; ++j)
                m_buf[std::size_t(r) * D + j] = job.start.vertices(r, j);
        m_points = m_kind == StartSet::Kind::Points || m_n == 1;
        m_maps = std::uint32_t(F.n);
        // Labels of the fused words when the colour prefix lies within them.
        const int prefix = job.colours.prefix;
        std::uint32_t div = 1;
        for (int t = prefix; t < T.m; ++t)
            div *= m_maps;
        m_labelsFixed = prefix <= T.m;
        for (int w = 0; w < T.words; ++w)
            m_labels[std::size_t(w)] = prefix == 0 ? 0u : std::uint32_t(w) / div;
    }

    // The fixed innermost choices `prefix`, then every word of the remaining levels.
    bool run(const std::vector<int> &prefix)
    {
        int level = 0;
        for (int i : prefix)
            step(level++, i);
        return walk(level);
    }
    std::uint64_t emitted() const { return m_emitted; }

private:
    double *level(int l) { return &m_buf[std::size_t(l) * m_n * D]; }

    void step(int l, int i)
    {
        const double *A = &m_F.a[std::size_t(i) * D * D];
        const double *B = &m_F.b[std::size_t(i) * D];
        const double *X = level(l);
        double *Y = level(l + 1);
        for (int r = 0; r < m_n; ++r) {
            double y[D];
            for (int j = 0; j < D; ++j)
                y[j] = B[j];
            for (int q = 0; q < D; ++q)
                for (int j = 0; j < D; ++j)
                    y[j] += X[r * D + q] * A[q * D + j];
            for (int j = 0; j < D; ++j)
                Y[r * D + j] = y[j];
        }
        m_address[m_depth - l - 1] = std::uint8_t(i);
    }

    bool walk(int l)
    {
        if (m_depth == 0)
            return leaves0();
        if (l == m_depth - m_T.m)
            return leaves(l);
        for (int i = 0; i < m_F.n; ++i) {
            step(l, i);
            if (!walk(l + 1))
                return false;
        }
        return true;
    }

    // The N^m leaves below buf[l] through the fused table, into the raster.
    bool leaves(int l)
    {
        const double *X = level(l);
        const int W = m_T.words;
        const int w = m_img.cellsX(), h = m_img.cellsY();
        const double xMax = m_plotter.xMax(), yMax = m_plotter.yMax();
        if (!m_labelsFixed) {
            // A colour prefix longer than the fused levels: the parent's part of the address
            // (address[m..prefix-1]) is the low digits of every word's label.
            const int prefix = m_job.colours.prefix;
            std::uint32_t low = 0, scale = 1;
            for (int k = m_T.m; k < prefix; ++k) {
                low = low * m_maps + (k < m_depth ? m_address[k] : 0u);
                scale *= m_maps;
            }
            for (int v = 0; v < W; ++v)
                m_labels[std::size_t(v)] = std::uint32_t(v) * scale + low;
        }
        for (int q = 0; q < m_T.views; ++q) {
            const double *L = &m_T.l[std::size_t(q) * D * W * 2];
            const double *C = &m_T.c[std::size_t(q) * W * 2];
            // Every vertex's cell coordinates for every word: s = x L + c, as 2W-long
            // multiply-adds (vectorised).
            m_kernels.rows(C, L, X, m_n, 2 * W, m_s.data());
            if (m_points) {
                for (int r = 0; r < m_n; ++r) {
                    // Cells first (NaN: off screen), then the hits.
                    m_kernels.cells(&m_s[std::size_t(r) * W * 2], W, w, h, m_cells.data());
                    m_img.reserve(std::size_t(W));
                    for (int v = 0; v < W; ++v) {
                        const std::int32_t cell = m_cells[std::size_t(v)];
                        if (cell < 0) {
                            ++m_img.offscreen;
                            continue;
                        }
                        addUnchecked<M>(m_img, std::size_t(cell), m_labels[std::size_t(v)],
                                        m_coords);
                    }
                }
                continue;
            }
            // Each image's bounding box (and a NaN check), and the cells of its corners.
            double *lo = m_box.data(), *hi = lo + 2 * W, *sum = hi + 2 * W;
            m_kernels.bounds(m_s.data(), m_n, 2 * W, lo, hi, sum);
            m_kernels.cells(lo, W, w, h, m_cells.data());
            m_kernels.cells(hi, W, w, h, m_cells2.data());
            m_img.reserve(std::size_t(W));
            for (int v = 0; v < W; ++v) {
                // Deep levels: an image whose bounding box has both corners in one cell on the
                // raster is one hit there. NaN, and images off the raster or over several
                // cells, go to the rasteriser.
                const std::int32_t c0 = m_cells[std::size_t(v)];
                const bool nan = sum[2 * v] != sum[2 * v] || sum[2 * v + 1] != sum[2 * v + 1];
                if (c0 >= 0 && c0 == m_cells2[std::size_t(v)] && !nan) {
                    addUnchecked<M>(m_img, std::size_t(c0), m_labels[std::size_t(v)], m_coords);
                    continue;
                }
                for (int r = 0; r < m_n; ++r) {
                    m_screen[2 * r] = m_s[(std::size_t(r) * W + v) * 2];
                    m_screen[2 * r + 1] = m_s[(std::size_t(r) * W + v) * 2 + 1];
                }
                // Small images straddling cells inside the raster (most of the rest at deep
                // levels) skip the rasteriser's checks and clipping.
                if (!nan && lo[2 * v] >= 0 && lo[2 * v + 1] >= 0 && hi[2 * v] < xMax
                    && hi[2 * v + 1] < yMax)
                    m_plotter.imageInside(m_screen.data(), m_n, m_kind, m_labels[std::size_t(v)],
                                          m_xs.data(), lo[2 * v], lo[2 * v + 1], hi[2 * v],
                                          hi[2 * v + 1]);
                else
                    m_plotter.image(m_screen.data(), m_n, m_kind, m_labels[std::size_t(v)], m_xs);
            }
        }
        m_emitted += std::uint64_t(W);
        if (m_emitted - m_ticked >= 16384) {
            const std::uint64_t n = m_emitted - m_ticked;
            m_ticked = m_emitted;
            return m_progress.tick(n);
        }
        return true;
    }

    // Depth 0: the start set itself.
    bool leaves0()
    {
        const double *X = level(0);
        for (int q = 0; q < m_F.views; ++q) {
            const double *V = &m_F.v[std::size_t(q) * D * 2];
            for (int r = 0; r < m_n; ++r) {
                double sx = m_F.c[2 * q], sy = m_F.c[2 * q + 1];
                for (int j = 0; j < D; ++j) {
                    sx += X[r * D + j] * V[2 * j];
                    sy += X[r * D + j] * V[2 * j + 1];
                }
                m_screen[2 * r] = sx;
                m_screen[2 * r + 1] = sy;
            }
            m_plotter.image(m_screen.data(), m_n, m_kind, 0, m_xs);
        }
        m_emitted += 1;
        return true;
    }

    const Flat<D> &m_F;
    const FusedLeaves<D> &m_T;
    const EngineJob &m_job;
    const std::uint8_t *m_coords;
    DensityImage &m_img;
    const Progress &m_progress;
    int m_depth, m_n;
    StartSet::Kind m_kind;
    bool m_points = true;
    bool m_labelsFixed = true;
    std::uint32_t m_maps = 1;
    std::vector<double> m_buf, m_screen, m_xs, m_s, m_box;
    std::vector<std::int32_t> m_cells, m_cells2;
    std::vector<std::uint32_t> m_labels;
    LeafKernels<D> m_kernels;
    Plotter m_plotter;
    std::uint8_t m_address[65] = {};
    std::uint64_t m_emitted = 0, m_ticked = 0;
};

} // namespace awb::engine
