#include "core/ifs/Attractor.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>

namespace awb {

std::string toString(StartSet::Kind kind)
{
    switch (kind) {
    case StartSet::Kind::Points: return "points";
    case StartSet::Kind::Polyline: return "polyline";
    case StartSet::Kind::Polygon: return "polygon";
    }
    return "points";
}

double imageCount(const Ifs &ifs, int depth) { return std::pow(double(ifs.size()), depth); }

namespace {

constexpr int kMaxDepth = 64;

void checkInputs(const Ifs &ifs, const StartSet &start, int depth)
{
    ifs.validate();
    if (depth < 0 || depth > kMaxDepth)
        throw InputError("iteration depth must be between 0 and " + std::to_string(kMaxDepth)
                         + ", got " + std::to_string(depth));
    if (start.vertices.rows() == 0)
        throw InputError("the start set is empty");
    if (start.vertices.cols() != ifs.dim())
        throw InputError("start set has " + std::to_string(start.vertices.cols())
                         + " coordinates, the IFS space has " + std::to_string(ifs.dim()));
    requireFinite(start.vertices, "start set");
    if (ifs.size() > 255)
        throw InputError("at most 255 maps are supported, got " + std::to_string(ifs.size()));
}

// Depth-first walk over the words of one subtree. Buffers are allocated once per walker.
class Walker {
public:
    Walker(const Ifs &ifs, const StartSet &start, int depth, AttractorSink &sink,
           const IterationControl &control, std::atomic<std::uint64_t> &done, double total)
        : m_ifs(ifs), m_kind(start.kind), m_depth(depth), m_sink(sink), m_control(control),
          m_done(done), m_total(total), m_buf(depth + 1), m_address(std::max(depth, 1), 0)
    {
        for (auto &b : m_buf)
            b.resize(start.vertices.rows(), start.vertices.cols());
        m_buf[0] = start.vertices;
    }

    // Apply the fixed innermost choices `prefix`, then walk the rest.
    bool run(const std::vector<int> &prefix)
    {
        int level = 0;
        for (int i : prefix) {
            step(level, i);
            ++level;
        }
        return walk(level);
    }

    std::uint64_t emitted() const { return m_emitted; }

private:
    void step(int level, int i)
    {
        // y = x A + b row by row. Plain loops over column-major A: the dynamic-size Eigen
        // product costs more in dispatch than in arithmetic for D <= 8, the common case.
        const AffineMap &f = m_ifs.maps[i];
        const Mat &X = m_buf[level];
        Mat &Y = m_buf[level + 1];
        const Eigen::Index n = X.rows(), D = X.cols();
        const double *a = f.A.data();
        const double *b = f.b.data();
        for (Eigen::Index r = 0; r < n; ++r) {
            for (Eigen::Index j = 0; j < D; ++j) {
                const double *col = a + j * D;
                double s = b[j];
                for (Eigen::Index k = 0; k < D; ++k)
                    s += X(r, k) * col[k];
                Y(r, j) = s;
            }
        }
        m_address[m_depth - level - 1] = std::uint8_t(i);
    }

    bool walk(int level)
    {
        if (level == m_depth) {
            m_sink.consume(m_buf[level], m_kind, m_address.data(), m_depth);
            ++m_emitted;
            if ((m_emitted & 4095) == 0)
                return tick(4096);
            return true;
        }
        for (int i = 0; i < m_ifs.size(); ++i) {
            step(level, i);
            if (!walk(level + 1))
                return false;
        }
        return true;
    }

    bool tick(std::uint64_t n)
    {
        const std::uint64_t done = m_done.fetch_add(n) + n;
        if (m_control.progress)
            m_control.progress(std::min(1.0, double(done) / m_total));
        return !(m_control.cancel && m_control.cancel->load(std::memory_order_relaxed));
    }

    const Ifs &m_ifs;
    StartSet::Kind m_kind;
    int m_depth;
    AttractorSink &m_sink;
    const IterationControl &m_control;
    std::atomic<std::uint64_t> &m_done;
    double m_total;
    std::vector<Mat> m_buf;
    std::vector<std::uint8_t> m_address;
    std::uint64_t m_emitted = 0;
};

} // namespace

IterationStats iterate(const Ifs &ifs, const StartSet &start, int depth, AttractorSink &sink,
                       const IterationControl &control)
{
    return iterateParallel(ifs, start, depth, {&sink}, control);
}

IterationStats iterateParallel(const Ifs &ifs, const StartSet &start, int depth,
                               const std::vector<AttractorSink *> &sinks,
                               const IterationControl &control)
{
    checkInputs(ifs, start, depth);
    if (sinks.empty())
        throw InputError("no sink to receive the attractor");
    const int N = ifs.size();
    const int threads = int(sinks.size());
    // Split into tasks: all words of the innermost `split` levels, at least 4 per thread.
    int split = 0;
    while (split < depth && std::pow(double(N), split) < 4.0 * threads && threads > 1)
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
    std::atomic<std::size_t> nextTask{0};
    std::atomic<std::uint64_t> done{0};
    std::atomic<bool> stopped{false};
    std::vector<std::uint64_t> emitted(threads, 0);
    const double total = std::max(1.0, imageCount(ifs, depth));

    auto worker = [&](int t) {
        Walker walker(ifs, start, depth, *sinks[t], control, done, total);
        for (;;) {
            const std::size_t k = nextTask.fetch_add(1);
            if (k >= tasks.size() || stopped.load())
                break;
            if (!walker.run(tasks[k])) {
                stopped = true;
                break;
            }
        }
        emitted[t] = walker.emitted();
    };
    if (threads == 1) {
        worker(0);
    } else {
        std::vector<std::thread> pool;
        for (int t = 0; t < threads; ++t)
            pool.emplace_back(worker, t);
        for (auto &th : pool)
            th.join();
    }
    IterationStats stats;
    for (auto e : emitted)
        stats.images += e;
    stats.cancelled = stopped.load() || (control.cancel && control.cancel->load());
    if (control.progress && !stats.cancelled)
        control.progress(1.0);
    return stats;
}

namespace {

std::vector<double> cumulative(const Ifs &ifs)
{
    std::vector<double> c(ifs.size());
    double sum = 0;
    for (int i = 0; i < ifs.size(); ++i) {
        sum += ifs.probabilities.empty() ? 1.0 : ifs.probabilities[i];
        c[i] = sum;
    }
    for (double &v : c)
        v /= sum;
    c.back() = 1.0;
    return c;
}

IterationStats chaosRun(const Ifs &ifs, const RowVec &x0, std::uint64_t samples, std::uint64_t seed,
                        const ChaosOptions &opt, AttractorSink &sink, const IterationControl &control,
                        std::atomic<std::uint64_t> &done, double total)
{
    const std::vector<double> cum = cumulative(ifs);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    const int L = std::clamp(opt.addressLength, 1, 64);
    std::vector<std::uint8_t> address(L, 0);
    Mat x = x0, y(1, x0.size());
    IterationStats stats;
    int known = 0;
    const std::uint64_t steps = samples + std::uint64_t(std::max(0, opt.skip));
    for (std::uint64_t s = 0; s < steps; ++s) {
        const double u = uni(rng);
        const int i = int(std::lower_bound(cum.begin(), cum.end(), u) - cum.begin());
        const AffineMap &f = ifs.maps[std::min(i, ifs.size() - 1)];
        y.noalias() = x * f.A;
        x = y + f.b;
        std::move_backward(address.begin(), address.end() - 1, address.end());
        address[0] = std::uint8_t(i);
        known = std::min(known + 1, L);
        if (s >= std::uint64_t(std::max(0, opt.skip))) {
            sink.consume(x, StartSet::Kind::Points, address.data(), known);
            ++stats.images;
            if ((stats.images & 16383) == 0) {
                const std::uint64_t d = done.fetch_add(16384) + 16384;
                if (control.progress)
                    control.progress(std::min(1.0, double(d) / total));
                if (control.cancel && control.cancel->load(std::memory_order_relaxed)) {
                    stats.cancelled = true;
                    break;
                }
                if (!x.allFinite())
                    break; // the orbit escaped: the maps are not contractive
            }
        }
    }
    return stats;
}

} // namespace

IterationStats chaosGame(const Ifs &ifs, const RowVec &x0, const ChaosOptions &options,
                         AttractorSink &sink, const IterationControl &control)
{
    return chaosGameParallel(ifs, x0, options, {&sink}, control);
}

IterationStats chaosGameParallel(const Ifs &ifs, const RowVec &x0, const ChaosOptions &options,
                                 const std::vector<AttractorSink *> &sinks,
                                 const IterationControl &control)
{
    ifs.validate();
    if (x0.size() != ifs.dim())
        throw InputError("start point has " + std::to_string(x0.size())
                         + " coordinates, the IFS space has " + std::to_string(ifs.dim()));
    requireFinite(Mat(x0), "start point");
    if (options.samples > 4'000'000'000ULL)
        throw InputError("at most 4e9 random-iteration samples, got "
                         + std::to_string(options.samples));
    if (sinks.empty())
        throw InputError("no sink to receive the attractor");
    const int threads = int(sinks.size());
    std::atomic<std::uint64_t> done{0};
    const double total = std::max(1.0, double(options.samples));
    std::vector<IterationStats> results(threads);
    auto worker = [&](int t) {
        const std::uint64_t share = options.samples / threads
                                    + (std::uint64_t(t) < options.samples % threads ? 1 : 0);
        results[t] = chaosRun(ifs, x0, share, options.seed + 0x9E3779B97F4A7C15ULL * t, options,
                              *sinks[t], control, done, total);
    };
    if (threads == 1) {
        worker(0);
    } else {
        std::vector<std::thread> pool;
        for (int t = 0; t < threads; ++t)
            pool.emplace_back(worker, t);
        for (auto &th : pool)
            th.join();
    }
    IterationStats stats;
    for (const auto &r : results) {
        stats.images += r.images;
        stats.cancelled = stats.cancelled || r.cancelled;
    }
    if (control.progress && !stats.cancelled)
        control.progress(1.0);
    return stats;
}

// ---- sinks ------------------------------------------------------------------------------------

PointCollector::PointCollector(Projection view, std::size_t maxPoints)
    : m_view(std::move(view)), m_max(maxPoints)
{
}

void PointCollector::consume(const Mat &v, StartSet::Kind, const std::uint8_t *a, int n)
{
    if (m_symbols.size() + std::size_t(v.rows()) > m_max) {
        m_truncated = true;
        return;
    }
    const Mat p = project(m_view, v);
    for (Eigen::Index r = 0; r < p.rows(); ++r) {
        for (Eigen::Index c = 0; c < p.cols(); ++c)
            m_data.push_back(p(r, c));
        m_symbols.push_back(n > 0 ? a[0] : 0);
    }
}

Mat PointCollector::points() const
{
    const Eigen::Index k = m_view.outDim();
    const Eigen::Index rows = k ? Eigen::Index(m_data.size()) / k : 0;
    Mat out(rows, k);
    for (Eigen::Index r = 0; r < rows; ++r)
        for (Eigen::Index c = 0; c < k; ++c)
            out(r, c) = m_data[std::size_t(r * k + c)];
    return out;
}

void BoundsSink::consume(const Mat &v, StartSet::Kind, const std::uint8_t *, int)
{
    for (const Projection &view : m_views) {
        const Mat p = project(view, v);
        if (!p.allFinite()) {
            m_finite = false;
            continue;
        }
        const RowVec lo = p.colwise().minCoeff(), hi = p.colwise().maxCoeff();
        if (m_lo.size() == 0) {
            m_lo = lo;
            m_hi = hi;
        } else {
            m_lo = m_lo.cwiseMin(lo);
            m_hi = m_hi.cwiseMax(hi);
        }
    }
}

RasterSink::RasterSink(int width, int height, double x0, double y0, double x1, double y1,
                       std::vector<Projection> views, int prefixLength)
    : m_w(width), m_h(height), m_x0(x0), m_y0(y0), m_x1(x1), m_y1(y1),
      m_views(std::move(views)), m_prefix(std::max(1, prefixLength))
{
    if (width < 1 || height < 1 || width > 32768 || height > 32768)
        throw InputError("raster size must be between 1x1 and 32768x32768");
    if (!(x1 > x0) || !(y1 > y0) || !std::isfinite(x1 - x0) || !std::isfinite(y1 - y0))
        throw InputError("raster world rectangle is empty or not finite");
    m_hits.assign(std::size_t(width) * height, 0);
    m_label.assign(std::size_t(width) * height, 0);
}

void RasterSink::clear()
{
    std::fill(m_hits.begin(), m_hits.end(), 0);
    std::fill(m_label.begin(), m_label.end(), 0);
    m_offscreen = m_nonFinite = 0;
}

Eigen::Vector2d RasterSink::toScreen(double x, double y) const
{
    return {(x - m_x0) / (m_x1 - m_x0) * m_w, (m_y1 - y) / (m_y1 - m_y0) * m_h};
}

void RasterSink::plot(int x, int y, std::uint32_t label)
{
    if (x < 0 || y < 0 || x >= m_w || y >= m_h) {
        ++m_offscreen;
        return;
    }
    const std::size_t i = std::size_t(y) * m_w + x;
    ++m_hits[i];
    // The smallest label wins: the result does not depend on the order of the hits, so a
    // parallel render is pixel-identical to a serial one.
    if (m_label[i] == 0 || label < m_label[i])
        m_label[i] = label;
}

void RasterSink::line(double ax, double ay, double bx, double by, std::uint32_t label)
{
    // Clip to the raster (Liang-Barsky) so that a huge segment costs nothing off screen.
    double t0 = 0, t1 = 1;
    const double dx = bx - ax, dy = by - ay;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {ax, m_w - 1e-9 - ax, ay, m_h - 1e-9 - ay};
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0) {
            if (q[k] < 0) {
                ++m_offscreen;
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
        ++m_offscreen;
        return;
    }
    const double sx = ax + t0 * dx, sy = ay + t0 * dy, ex = ax + t1 * dx, ey = ay + t1 * dy;
    const int steps = int(std::ceil(std::max(std::abs(ex - sx), std::abs(ey - sy)))) + 1;
    int lastX = INT_MIN, lastY = INT_MIN;
    for (int s = 0; s <= steps; ++s) {
        const double t = double(s) / steps;
        const int x = int(std::floor(sx + t * (ex - sx))), y = int(std::floor(sy + t * (ey - sy)));
        if (x != lastX || y != lastY)
            plot(x, y, label);
        lastX = x;
        lastY = y;
    }
}

void RasterSink::fill(const Mat &s, std::uint32_t label)
{
    const double ymin = std::max(0.0, s.col(1).minCoeff()), ymax = std::min(double(m_h), s.col(1).maxCoeff());
    const Eigen::Index n = s.rows();
    std::vector<double> xs;
    for (int y = int(std::floor(ymin)); y < int(std::ceil(ymax)); ++y) {
        const double yc = y + 0.5;
        xs.clear();
        for (Eigen::Index i = 0; i < n; ++i) {
            const Eigen::Index j = (i + 1) % n;
            const double y0 = s(i, 1), y1 = s(j, 1);
            if ((y0 <= yc && y1 > yc) || (y1 <= yc && y0 > yc))
                xs.push_back(s(i, 0) + (yc - y0) / (y1 - y0) * (s(j, 0) - s(i, 0)));
        }
        std::sort(xs.begin(), xs.end());
        for (size_t k = 0; k + 1 < xs.size(); k += 2) {
            const int xa = std::max(0, int(std::ceil(xs[k] - 0.5)));
            const int xb = std::min(m_w - 1, int(std::floor(xs[k + 1] - 0.5)));
            for (int x = xa; x <= xb; ++x)
                plot(x, y, label);
        }
    }
}

void RasterSink::consume(const Mat &v, StartSet::Kind kind, const std::uint8_t *a, int n)
{
    std::uint32_t label = 0;
    for (int k = 0; k < std::min(n, m_prefix); ++k)
        label = label * 256 + a[k];
    label += 1; // 0 means "never hit"
    for (const Projection &view : m_views) {
        const Mat p = project(view, v);
        if (!p.allFinite()) {
            ++m_nonFinite;
            continue;
        }
        Mat s(p.rows(), 2);
        for (Eigen::Index r = 0; r < p.rows(); ++r)
            s.row(r) = toScreen(p(r, 0), p(r, 1)).transpose();
        if (kind == StartSet::Kind::Points || p.rows() == 1) {
            for (Eigen::Index r = 0; r < s.rows(); ++r)
                plot(int(std::floor(s(r, 0))), int(std::floor(s(r, 1))), label);
            continue;
        }
        if (kind == StartSet::Kind::Polygon && p.rows() >= 3)
            fill(s, label);
        const Eigen::Index segments = kind == StartSet::Kind::Polygon ? s.rows() : s.rows() - 1;
        for (Eigen::Index r = 0; r < segments; ++r) {
            const Eigen::Index q = (r + 1) % s.rows();
            line(s(r, 0), s(r, 1), s(q, 0), s(q, 1), label);
        }
    }
}

void RasterSink::merge(const RasterSink &o)
{
    if (o.m_w != m_w || o.m_h != m_h)
        throw InputError("cannot merge rasters of different sizes");
    for (std::size_t i = 0; i < m_hits.size(); ++i) {
        if (o.m_hits[i]) {
            m_hits[i] += o.m_hits[i];
            if (m_label[i] == 0 || o.m_label[i] < m_label[i])
                m_label[i] = o.m_label[i];
        }
    }
    m_offscreen += o.m_offscreen;
    m_nonFinite += o.m_nonFinite;
}

std::uint64_t RasterSink::litPixels() const
{
    return std::uint64_t(std::count_if(m_hits.begin(), m_hits.end(), [](auto h) { return h > 0; }));
}

} // namespace awb
