#include "core/render/Engine.h"

#include "core/Messages.h"
#include "core/ifs/Random.h"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <memory>
#include <thread>

namespace awb {

std::uint32_t addressLabel(const std::uint8_t *address, int length, int prefix, int maps)
{
    std::uint32_t label = 0;
    for (int k = 0; k < prefix; ++k)
        label = label * std::uint32_t(maps) + (k < length ? address[k] : 0u);
    return label;
}

namespace {

constexpr int kMaxFixedDim = 12;
constexpr int kInterleave = 4;  // orbits advanced together per thread
// Per-thread histograms beyond this many bytes in all: fewer threads.
constexpr double kHistogramBudget = 192.0 * 1024 * 1024;

// ---- the generic rasteriser (cells, y down) ------------------------------------------------

struct Plotter {
    DensityImage &img;
    int w, h;
    const std::uint8_t *coords;  // colour coordinate of each label (density)

    void cell(int x, int y, std::uint32_t label)
    {
        if (x < 0 || y < 0 || x >= w || y >= h) {
            ++img.offscreen;
            return;
        }
        const std::size_t i = std::size_t(y) * w + x;
        if (img.mode() == Accumulation::Hits)
            img.addHit(i, label);
        else
            img.addDensity(i, coords[label]);
    }

    void line(double ax, double ay, double bx, double by, std::uint32_t label)
    {
        // Clip to the raster (Liang-Barsky) so that a huge segment costs nothing off screen.
        double t0 = 0, t1 = 1;
        const double dx = bx - ax, dy = by - ay;
        const double p[4] = {-dx, dx, -dy, dy};
        const double q[4] = {ax, w - 1e-9 - ax, ay, h - 1e-9 - ay};
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
        const double sx = ax + t0 * dx, sy = ay + t0 * dy, ex = ax + t1 * dx, ey = ay + t1 * dy;
        const int steps = int(std::ceil(std::max(std::abs(ex - sx), std::abs(ey - sy)))) + 1;
        int lastX = INT_MIN, lastY = INT_MIN;
        for (int s = 0; s <= steps; ++s) {
            const double t = double(s) / steps;
            const int x = int(std::floor(sx + t * (ex - sx)));
            const int y = int(std::floor(sy + t * (ey - sy)));
            if (x != lastX || y != lastY)
                cell(x, y, label);
            lastX = x;
            lastY = y;
        }
    }

    // Even-odd fill of the cells whose centres lie inside the polygon (xy pairs).
    void fill(const double *s, int n, std::uint32_t label, std::vector<double> &xs)
    {
        double ymin = 1e300, ymax = -1e300;
        for (int i = 0; i < n; ++i)
            ymin = std::min(ymin, s[2 * i + 1]), ymax = std::max(ymax, s[2 * i + 1]);
        ymin = std::max(0.0, ymin);
        ymax = std::min(double(h), ymax);
        for (int y = int(std::floor(ymin)); y < int(std::ceil(ymax)); ++y) {
            const double yc = y + 0.5;
            xs.clear();
            for (int i = 0; i < n; ++i) {
                const int j = (i + 1) % n;
                const double y0 = s[2 * i + 1], y1 = s[2 * j + 1];
                if ((y0 <= yc && y1 > yc) || (y1 <= yc && y0 > yc))
                    xs.push_back(s[2 * i] + (yc - y0) / (y1 - y0) * (s[2 * j] - s[2 * i]));
            }
            std::sort(xs.begin(), xs.end());
            for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
                const int xa = std::max(0, int(std::ceil(xs[k] - 0.5)));
                const int xb = std::min(w - 1, int(std::floor(xs[k + 1] - 0.5)));
                for (int x = xa; x <= xb; ++x)
                    cell(x, y, label);
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
        if (kind == StartSet::Kind::Polygon && n >= 3)
            fill(s, n, label, xs);
        const int segments = kind == StartSet::Kind::Polygon ? n : n - 1;
        for (int r = 0; r < segments; ++r) {
            const int q = (r + 1) % n;
            line(s[2 * r], s[2 * r + 1], s[2 * q], s[2 * q + 1], label);
        }
    }
};

// A view as an affine map from IFS space straight to raster cells: cell = x V + c.
struct CellView {
    Mat V;      // D x 2
    double c[2];
};

std::vector<CellView> cellViews(const std::vector<Projection> &views, const RasterFrame &f, int dim)
{
    const double sx = f.cellsX() / (f.x1 - f.x0), sy = f.cellsY() / (f.y1 - f.y0);
    std::vector<CellView> out;
    for (const Projection &v : views) {
        if (v.V.rows() != dim || v.V.cols() < 2 || v.c.size() != v.V.cols())
            throw InputError(coreTranslate("awb::render", "a view does not fit the IFS space"));
        CellView cv;
        cv.V.resize(dim, 2);
        cv.V.col(0) = v.V.col(0) * sx;
        cv.V.col(1) = -v.V.col(1) * sy;
        cv.c[0] = (v.c(0) - f.x0) * sx;
        cv.c[1] = (f.y1 - v.c(1)) * sy;
        out.push_back(std::move(cv));
    }
    return out;
}

// ---- fixed-dimension kernels ------------------------------------------------------------------

// The maps and views of one job in flat arrays: a[i][k][j] (y_j = b_j + sum_k x_k a_kj),
// view[v][k][0..1], and the fused last step leaf[i][v]: x (A_i V) + (b_i V + c), D x 2 + 2.
template <int D>
struct Flat {
    int n = 0, views = 0;
    std::vector<double> a, b, v, c, leaf;

    Flat(const Ifs &ifs, const std::vector<CellView> &cv) : n(ifs.size()), views(int(cv.size()))
    {
        a.resize(std::size_t(n) * D * D);
        b.resize(std::size_t(n) * D);
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < D; ++k) {
                b[i * D + k] = ifs.maps[i].b(k);
                for (int j = 0; j < D; ++j)
                    a[(i * D + k) * D + j] = ifs.maps[i].A(k, j);
            }
        v.resize(std::size_t(views) * D * 2);
        c.resize(std::size_t(views) * 2);
        for (int q = 0; q < views; ++q) {
            for (int k = 0; k < D; ++k)
                for (int j = 0; j < 2; ++j)
                    v[(q * D + k) * 2 + j] = cv[q].V(k, j);
            c[q * 2] = cv[q].c[0];
            c[q * 2 + 1] = cv[q].c[1];
        }
        leaf.resize(std::size_t(n) * views * (2 * D + 2));
        for (int i = 0; i < n; ++i)
            for (int q = 0; q < views; ++q) {
                double *L = &leaf[(std::size_t(i) * views + q) * (2 * D + 2)];
                const Mat W = ifs.maps[i].A * cv[q].V;
                const RowVec bw = ifs.maps[i].b * cv[q].V;
                for (int k = 0; k < D; ++k)
                    L[2 * k] = W(k, 0), L[2 * k + 1] = W(k, 1);
                L[2 * D] = bw(0) + cv[q].c[0];
                L[2 * D + 1] = bw(1) + cv[q].c[1];
            }
    }
};

template <Accumulation M>
inline void plotCell(DensityImage &img, int w, int h, double sx, double sy, std::uint32_t label,
                     const std::uint8_t *coords)
{
    // NaN fails both comparisons and counts as off screen.
    if (sx >= 0.0 && sy >= 0.0 && sx < double(w) && sy < double(h)) {
        const std::size_t i = std::size_t(int(sy)) * std::size_t(w) + std::size_t(int(sx));
        if constexpr (M == Accumulation::Hits)
            img.addHit(i, label);
        else
            img.addDensity(i, coords[label]);
    } else {
        ++img.offscreen;
    }
}

struct Progress {
    const IterationControl &control;
    std::atomic<std::uint64_t> &done;
    double total;
    bool tick(std::uint64_t n) const
    {
        const std::uint64_t d = done.fetch_add(n) + n;
        if (control.progress)
            control.progress(std::min(1.0, double(d) / total));
        return !(control.cancel && control.cancel->load(std::memory_order_relaxed));
    }
};

// K orbits of random iteration advanced together in blocks of kBlock steps, in three passes
// per block so that each runs at its own speed: (1) the map choices of every orbit from its
// own stream (Random.h), (2) the geometry, orbits interleaved so that the latency of one map
// application hides behind the others, ending in a cell index per point, (3) the scatter of
// the points into the histogram.
constexpr int kBlock = 256;

template <int D, int K>
struct Orbits {
    double x[K][D];
    std::uint32_t label[K];
    Xoshiro256 rng[K];
};

template <int D, int K, Accumulation M, bool oneView>
void chaosBlock(const Flat<D> &F, const AliasTable &pick, Orbits<D, K> &o, int steps,
                bool plot, int prefix, std::uint32_t labelMod, DensityImage &img,
                const std::uint8_t *coords)
{
    std::uint8_t maps[kBlock][K];
    if (pick.uniform()) {
        const std::uint64_t n = std::uint64_t(pick.size());
        for (int k = 0; k < K; ++k) {
            Xoshiro256 rng = o.rng[k];
            for (int s = 0; s < steps; ++s)
                maps[s][k] = std::uint8_t(((rng.next() >> 32) * n) >> 32);
            o.rng[k] = rng;
        }
    } else {
        for (int k = 0; k < K; ++k) {
            Xoshiro256 rng = o.rng[k];
            for (int s = 0; s < steps; ++s)
                maps[s][k] = std::uint8_t(pick.pick(rng.next()));
            o.rng[k] = rng;
        }
    }

    const int w = img.cellsX(), h = img.cellsY();
    const double fw = double(w), fh = double(h);
    double x[K][D];
    std::uint32_t label[K];
    for (int k = 0; k < K; ++k) {
        label[k] = prefix > 1 ? o.label[k] : 0u;
        for (int j = 0; j < D; ++j)
            x[k][j] = o.x[k][j];
    }
    const double *v = F.v.data();
    const double c0 = F.c[0], c1 = F.c[1];
    std::int32_t cells[kBlock][K];
    std::uint32_t labels[kBlock][K];
    for (int s = 0; s < steps; ++s) {
        for (int k = 0; k < K; ++k) {
            const int i = maps[s][k];
            const double *A = &F.a[std::size_t(i) * D * D];
            const double *B = &F.b[std::size_t(i) * D];
            double y[D];
            for (int j = 0; j < D; ++j)
                y[j] = B[j];
            for (int q = 0; q < D; ++q)
                for (int j = 0; j < D; ++j)
                    y[j] += x[k][q] * A[q * D + j];
            for (int j = 0; j < D; ++j)
                x[k][j] = y[j];
            if (prefix > 1) {
                label[k] = (label[k] * std::uint32_t(F.n) + std::uint32_t(i)) % labelMod;
                labels[s][k] = label[k];
            }
            if constexpr (oneView) {
                double sx = c0, sy = c1;
                for (int j = 0; j < D; ++j) {
                    sx += y[j] * v[2 * j];
                    sy += y[j] * v[2 * j + 1];
                }
                // NaN fails the comparisons and counts as off screen. Bitwise: no branches.
                const bool in = (sx >= 0.0) & (sy >= 0.0) & (sx < fw) & (sy < fh);
                const int cell = int(in ? sy : 0.0) * w + int(in ? sx : 0.0);
                cells[s][k] = in ? cell : -1;
            }
        }
        if (!oneView && plot)
            for (int k = 0; k < K; ++k)
                for (int q = 0; q < F.views; ++q) {
                    const double *V = &F.v[std::size_t(q) * D * 2];
                    double sx = F.c[2 * q], sy = F.c[2 * q + 1];
                    for (int j = 0; j < D; ++j) {
                        sx += x[k][j] * V[2 * j];
                        sy += x[k][j] * V[2 * j + 1];
                    }
                    const std::uint32_t l = prefix == 1 ? maps[s][k] : prefix == 0 ? 0u : label[k];
                    plotCell<M>(img, w, h, sx, sy, l, coords);
                }
    }
    for (int k = 0; k < K; ++k) {
        o.label[k] = label[k];
        for (int j = 0; j < D; ++j)
            o.x[k][j] = x[k][j];
    }
    if (!plot || !oneView)
        return;
    for (int s = 0; s < steps; ++s)
        for (int k = 0; k < K; ++k) {
            const std::int32_t c = cells[s][k];
            if (c < 0) {
                ++img.offscreen;
                continue;
            }
            const std::uint32_t l = prefix == 1 ? maps[s][k] : prefix == 0 ? 0u : labels[s][k];
            if constexpr (M == Accumulation::Hits)
                img.addHit(std::size_t(c), l);
            else
                img.addDensity(std::size_t(c), coords[l]);
        }
}

// Random iteration of streams [first, last) (Random.h), kInterleave orbits at a time.
template <int D, Accumulation M, bool OneView>
IterationStats chaosKernel(const Flat<D> &F, const AliasTable &pick, const RowVec &x0,
                           const EngineJob &job, const std::uint8_t *colours, int first, int last,
                           DensityImage &img, const Progress &progress)
{
    const int prefix = job.colours.prefix;
    std::uint32_t labelMod = 1;
    for (int k = 0; k < prefix; ++k)
        labelMod *= std::uint32_t(F.n);
    IterationStats stats;
    constexpr int K = kInterleave;
    for (int g = first; g < last; g += K) {
        // A group of K streams (fewer at the end: those run one by one below).
        const int members = std::min(K, last - g);
        Orbits<D, K> o;
        std::uint64_t left[K];
        for (int k = 0; k < K; ++k) {
            o.rng[k] = Xoshiro256(job.seed, std::uint64_t(g + std::min(k, members - 1)));
            o.label[k] = 0;
            for (int j = 0; j < D; ++j)
                o.x[k][j] = x0(j);
            left[k] = streamShare(job.samples, g + std::min(k, members - 1));
        }
        if (members < K) {
            // Run the short group's streams singly.
            for (int m = 0; m < members; ++m) {
                Orbits<D, 1> one;
                one.rng[0] = Xoshiro256(job.seed, std::uint64_t(g + m));
                one.label[0] = 0;
                for (int j = 0; j < D; ++j)
                    one.x[0][j] = x0(j);
                for (int sk = job.skip; sk > 0; sk -= kBlock)
                    chaosBlock<D, 1, M, OneView>(F, pick, one, std::min(sk, kBlock), false, prefix,
                                        labelMod, img, colours);
                for (std::uint64_t n = streamShare(job.samples, g + m); n > 0;) {
                    const int steps = int(std::min<std::uint64_t>(n, kBlock));
                    chaosBlock<D, 1, M, OneView>(F, pick, one, steps, true, prefix, labelMod, img, colours);
                    n -= std::uint64_t(steps);
                    stats.images += std::uint64_t(steps);
                }
            }
            continue;
        }
        for (int sk = job.skip; sk > 0; sk -= kBlock)
            chaosBlock<D, K, M, OneView>(F, pick, o, std::min(sk, kBlock), false, prefix, labelMod, img,
                                colours);
        std::uint64_t common = left[0];
        for (int k = 1; k < K; ++k)
            common = std::min(common, left[k]);
        bool stop = false;
        std::uint64_t sinceCheck = 0;
        while (common > 0) {
            const int steps = int(std::min<std::uint64_t>(common, kBlock));
            chaosBlock<D, K, M, OneView>(F, pick, o, steps, true, prefix, labelMod, img, colours);
            common -= std::uint64_t(steps);
            for (int k = 0; k < K; ++k)
                left[k] -= std::uint64_t(steps);
            stats.images += std::uint64_t(steps) * K;
            sinceCheck += std::uint64_t(steps) * K;
            if (sinceCheck >= (1u << 18) || common == 0) {
                if (!progress.tick(sinceCheck)) {
                    stats.cancelled = true;
                    stop = true;
                    break;
                }
                sinceCheck = 0;
                bool finite = true;
                for (int k = 0; k < K; ++k)
                    for (int j = 0; j < D; ++j)
                        finite = finite && std::isfinite(o.x[k][j]);
                if (!finite) {  // an orbit escaped: the maps are not contractive
                    ++img.nonFinite;
                    stop = true;
                    break;
                }
            }
        }
        if (stop)
            break;
        // The streams' last samples (shares differ by one at most), one orbit at a time.
        for (int k = 0; k < K; ++k) {
            if (left[k] == 0)
                continue;
            Orbits<D, 1> one;
            one.rng[0] = o.rng[k];
            one.label[0] = o.label[k];
            for (int j = 0; j < D; ++j)
                one.x[0][j] = o.x[k][j];
            chaosBlock<D, 1, M, OneView>(F, pick, one, int(left[k]), true, prefix, labelMod, img, colours);
            stats.images += left[k];
        }
    }
    return stats;
}

// Depth-first deterministic iteration of one thread: buf[level] holds the images of the start
// set after `level` maps (the innermost first); the last map is fused with the view.
template <int D, Accumulation M>
class DfsKernel {
public:
    DfsKernel(const Flat<D> &F, const EngineJob &job, const std::uint8_t *coords, DensityImage &img,
              const Progress &progress)
        : m_F(F), m_job(job), m_coords(coords), m_img(img), m_progress(progress), m_depth(job.depth),
          m_n(int(job.start.vertices.rows())), m_kind(job.start.kind),
          m_buf(std::size_t(job.depth + 1) * m_n * D), m_screen(std::size_t(m_n) * 2),
          m_plotter{img, img.cellsX(), img.cellsY(), coords}
    {
        for (int r = 0; r < m_n; ++r)
            for (int j = 0; j < D; ++j)
                m_buf[std::size_t(r) * D + j] = job.start.vertices(r, j);
        m_points = m_kind == StartSet::Kind::Points || m_n == 1;
        m_maps = std::uint32_t(F.n);
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

    std::uint32_t label() const
    {
        const int prefix = m_job.colours.prefix;
        if (prefix == 1)
            return m_address[0];
        return addressLabel(m_address, m_depth, prefix, int(m_maps));
    }

    bool walk(int l)
    {
        if (m_depth == 0)
            return leaves0();
        if (l == m_depth - 1)
            return leaves(l);
        for (int i = 0; i < m_F.n; ++i) {
            step(l, i);
            if (!walk(l + 1))
                return false;
        }
        return true;
    }

    // The last level: every map's image of buf[l], fused with the views, into the raster.
    bool leaves(int l)
    {
        const double *X = level(l);
        const std::uint8_t *colours = m_coords;
        const int w = m_img.cellsX(), h = m_img.cellsY();
        const std::size_t stride = 2 * D + 2;
        for (int i = 0; i < m_F.n; ++i) {
            m_address[0] = std::uint8_t(i);
            const std::uint32_t lab = label();
            for (int q = 0; q < m_F.views; ++q) {
                const double *L = &m_F.leaf[(std::size_t(i) * m_F.views + q) * stride];
                if (m_points) {
                    for (int r = 0; r < m_n; ++r) {
                        double sx = L[2 * D], sy = L[2 * D + 1];
                        for (int j = 0; j < D; ++j) {
                            sx += X[r * D + j] * L[2 * j];
                            sy += X[r * D + j] * L[2 * j + 1];
                        }
                        plotCell<M>(m_img, w, h, sx, sy, lab, colours);
                    }
                } else {
                    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
                    bool nan = false;
                    for (int r = 0; r < m_n; ++r) {
                        double sx = L[2 * D], sy = L[2 * D + 1];
                        for (int j = 0; j < D; ++j) {
                            sx += X[r * D + j] * L[2 * j];
                            sy += X[r * D + j] * L[2 * j + 1];
                        }
                        m_screen[2 * r] = sx;
                        m_screen[2 * r + 1] = sy;
                        x0 = std::min(x0, sx), x1 = std::max(x1, sx);
                        y0 = std::min(y0, sy), y1 = std::max(y1, sy);
                        nan = nan || sx != sx || sy != sy;
                    }
                    // Deep levels: the image inside one cell is one hit there (NaN fails the
                    // test and goes to the rasteriser, which counts it).
                    if (!nan && std::floor(x0) == std::floor(x1)
                        && std::floor(y0) == std::floor(y1) && x0 >= 0.0 && y0 >= 0.0)
                        plotCell<M>(m_img, w, h, x0, y0, lab, colours);
                    else
                        m_plotter.image(m_screen.data(), m_n, m_kind, lab, m_xs);
                }
            }
        }
        m_emitted += std::uint64_t(m_F.n);
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
    const EngineJob &m_job;
    const std::uint8_t *m_coords;
    DensityImage &m_img;
    const Progress &m_progress;
    int m_depth, m_n;
    StartSet::Kind m_kind;
    bool m_points = true;
    std::uint32_t m_maps = 1;
    std::vector<double> m_buf, m_screen, m_xs;
    Plotter m_plotter;
    std::uint8_t m_address[65] = {};
    std::uint64_t m_emitted = 0, m_ticked = 0;
};

// Runs fn(t) on `threads` threads (t = 0 on the caller's).
template <typename Fn>
void onThreads(int threads, Fn fn)
{
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back(fn, t);
    fn(0);
    for (auto &th : pool)
        th.join();
}

// Words of the innermost `split` levels, at least 4 per thread, as tasks.
std::vector<std::vector<int>> splitTasks(int N, int depth, int threads)
{
    int split = 0;
    while (split < depth && std::pow(double(N), split) < 8.0 * threads && threads > 1)
        ++split;
    std::vector<std::vector<int>> tasks(1);
    for (int s = 0; s < split; ++s) {
        std::vector<std::vector<int>> next;
        for (const auto &t : tasks)
            for (int i = 0; i < N; ++i) {
                auto u = t;
                u.push_back(i);
                next.push_back(u);
            }
        tasks.swap(next);
    }
    return tasks;
}

template <int D, Accumulation M>
IterationStats runFixed(const EngineJob &job, const std::vector<CellView> &cv,
                        std::vector<DensityImage *> &images, const IterationControl &control)
{
    const Flat<D> F(*job.ifs, cv);
    const std::vector<std::uint8_t> coords = labelCoordinates(job.colours.labelColours.size());
    const int threads = int(images.size());
    std::atomic<std::uint64_t> done{0};
    std::vector<IterationStats> results(threads);
    if (job.random) {
        const AliasTable pick(job.ifs->probabilities, job.ifs->size());
        const Progress progress{control, done, std::max(1.0, double(job.samples))};
        const RowVec x0 = job.start.vertices.row(0);
        // Thread t runs a contiguous block of streams.
        onThreads(threads, [&](int t) {
            const int first = kChaosStreams * t / threads, last = kChaosStreams * (t + 1) / threads;
            results[t] = F.views == 1
                             ? chaosKernel<D, M, true>(F, pick, x0, job, coords.data(), first,
                                                       last, *images[t], progress)
                             : chaosKernel<D, M, false>(F, pick, x0, job, coords.data(), first,
                                                        last, *images[t], progress);
        });
    } else {
        const auto tasks = splitTasks(F.n, job.depth, threads);
        const Progress progress{control, done, std::max(1.0, imageCount(*job.ifs, job.depth))};
        std::atomic<std::size_t> next{0};
        std::atomic<bool> stopped{false};
        onThreads(threads, [&](int t) {
            DfsKernel<D, M> walker(F, job, coords.data(), *images[t], progress);
            for (;;) {
                const std::size_t k = next.fetch_add(1);
                if (k >= tasks.size() || stopped.load())
                    break;
                if (!walker.run(tasks[k])) {
                    stopped = true;
                    break;
                }
            }
            results[t].images = walker.emitted();
            results[t].cancelled = stopped.load();
        });
    }
    IterationStats stats;
    for (const auto &r : results) {
        stats.images += r.images;
        stats.cancelled = stats.cancelled || r.cancelled;
    }
    return stats;
}

template <Accumulation M, int D = 1>
IterationStats dispatch(int dim, const EngineJob &job, const std::vector<CellView> &cv,
                        std::vector<DensityImage *> &images, const IterationControl &control)
{
    if constexpr (D > kMaxFixedDim) {
        return {};
    } else {
        if (dim == D)
            return runFixed<D, M>(job, cv, images, control);
        return dispatch<M, D + 1>(dim, job, cv, images, control);
    }
}

} // namespace

IterationStats accumulate(const EngineJob &job, DensityImage &out, const IterationControl &control)
{
    if (!job.ifs)
        throw InputError(coreTranslate("awb::render", "there is no IFS to draw"));
    job.frame.validate();
    const Ifs &ifs = *job.ifs;
    const std::vector<Projection> &views = job.views.empty() ? ifs.views : job.views;
    if (views.empty())
        throw InputError(coreTranslate("awb::render", "the IFS has no view to draw it with"));
    std::uint64_t labels = 1;
    for (int k = 0; k < job.colours.prefix; ++k)
        labels *= std::uint64_t(std::max(1, ifs.size()));
    if (job.colours.prefix < 0 || job.colours.prefix > 3
        || job.colours.labelColours.size() < labels)
        throw InputError(coreTranslate("awb::render", "the colour table does not cover the address "
                                                      "labels"));
    if (job.random) {
        checkChaosInputs(ifs, job.start.vertices.row(0), job.samples);
    } else {
        checkIterateInputs(ifs, job.start, job.depth);
    }
    const std::vector<CellView> cv = cellViews(views, job.frame, ifs.dim());

    // One histogram per thread, within the memory budget; thread 0 fills `out` itself.
    const double bytes = 16.0 * job.frame.cellsX() * job.frame.cellsY();
    int threads = std::clamp(job.threads, 1, kChaosStreams);
    // A small picture's work is less than starting threads and merging their histograms.
    const double work = job.random ? double(job.samples)
                                   : imageCount(ifs, job.depth) * double(job.start.vertices.rows());
    if (work < 2e5)
        threads = 1;
    threads = std::max(1, std::min(threads, int(kHistogramBudget / std::max(1.0, bytes))));
    out.reset(job.frame.cellsX(), job.frame.cellsY(), job.accumulation);
    // The other threads' histograms are kept per calling thread and reused by the next
    // picture of the same size (live drags render one picture after another).
    static thread_local std::vector<std::unique_ptr<DensityImage>> spare;
    if (spare.size() < std::size_t(threads))
        spare.resize(std::size_t(threads));
    std::vector<DensityImage *> images{&out};
    for (int t = 1; t < threads; ++t) {
        if (!spare[t])
            spare[t] = std::make_unique<DensityImage>();
        spare[t]->reset(job.frame.cellsX(), job.frame.cellsY(), job.accumulation);
        images.push_back(spare[t].get());
    }
    // A much larger earlier picture's memory is not kept.
    auto release = [&] {
        for (auto &img : spare)
            if (img && img->size() > 4 * std::size_t(job.frame.cellsX()) * job.frame.cellsY())
                img.reset();
    };

    IterationStats stats;
    if (ifs.dim() <= kMaxFixedDim && ifs.size() > 0) {
        stats = job.accumulation == Accumulation::Hits
                    ? dispatch<Accumulation::Hits>(ifs.dim(), job, cv, images, control)
                    : dispatch<Accumulation::Density>(ifs.dim(), job, cv, images, control);
    } else {
        // Large dimensions: the sink-based iteration into the same rasteriser.
        std::vector<std::unique_ptr<DensitySink>> sinks;
        std::vector<AttractorSink *> raw;
        for (int t = 0; t < threads; ++t) {
            sinks.push_back(std::make_unique<DensitySink>(job.frame, views, job.accumulation,
                                                          job.colours, ifs.size()));
            raw.push_back(sinks.back().get());
        }
        if (job.random) {
            ChaosOptions opt;
            opt.samples = job.samples;
            opt.seed = job.seed;
            opt.skip = job.skip;
            opt.addressLength = std::max(1, job.colours.prefix);
            stats = chaosGameParallel(ifs, job.start.vertices.row(0), opt, raw, control);
        } else {
            stats = iterateParallel(ifs, job.start, job.depth, raw, control);
        }
        for (int t = 0; t < threads; ++t)
            images[t]->merge(sinks[t]->image());
    }
    if (stats.cancelled)
        return stats;
    for (std::size_t t = 1; t < images.size(); ++t)
        out.merge(*images[t]);
    release();
    if (control.progress)
        control.progress(1.0);
    return stats;
}

DensitySink::DensitySink(const RasterFrame &frame, std::vector<Projection> views,
                         Accumulation mode, const EngineColours &colours, int maps)
    : m_frame(frame), m_views(std::move(views)), m_colours(colours), m_maps(std::max(1, maps)),
      m_image(frame.cellsX(), frame.cellsY(), mode),
      m_coords(labelCoordinates(colours.labelColours.size()))
{
    frame.validate();
}

void DensitySink::consume(const Mat &v, StartSet::Kind kind, const std::uint8_t *a, int n)
{
    const std::uint32_t label = addressLabel(a, n, m_colours.prefix, m_maps);
    const double sx = m_frame.cellsX() / (m_frame.x1 - m_frame.x0);
    const double sy = m_frame.cellsY() / (m_frame.y1 - m_frame.y0);
    Plotter plotter{m_image, m_image.cellsX(), m_image.cellsY(), m_coords.data()};
    std::vector<double> xs;
    m_screen.resize(std::size_t(v.rows()) * 2);
    for (const Projection &view : m_views) {
        const Mat p = project(view, v);
        for (Eigen::Index r = 0; r < p.rows(); ++r) {
            m_screen[2 * r] = (p(r, 0) - m_frame.x0) * sx;
            m_screen[2 * r + 1] = (m_frame.y1 - p(r, 1)) * sy;
        }
        plotter.image(m_screen.data(), int(p.rows()), kind, label, xs);
    }
}

} // namespace awb
