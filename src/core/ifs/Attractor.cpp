#include "core/ifs/Attractor.h"

#include "core/Messages.h"
#include "core/Threads.h"
#include "core/ifs/Random.h"

#include <algorithm>
#include <climits>
#include <cmath>

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
        // Each map's A row by row (A(k, j) at k * D + j), for the product in step().
        const Eigen::Index D = start.vertices.cols();
        m_rows.resize(ifs.maps.size());
        for (std::size_t i = 0; i < ifs.maps.size(); ++i) {
            const Mat &A = ifs.maps[i].A;
            m_rows[i].resize(std::size_t(D * D));
            for (Eigen::Index k = 0; k < D; ++k)
                for (Eigen::Index j = 0; j < D; ++j)
                    m_rows[i][std::size_t(k * D + j)] = A(k, j);
        }
        m_row.resize(std::size_t(D));
        // The last map fused with the sink's projections: per map and projection, A V and b V + c.
        const std::vector<Projection> *projections = sink.projections();
        if (projections && depth >= 1) {
            m_fused = true;
            m_fusedMaps.resize(ifs.maps.size());
            for (std::size_t i = 0; i < ifs.maps.size(); ++i) {
                const AffineMap &f = ifs.maps[i];
                for (const Projection &p : *projections) {
                    Projection q; // 0 columns: the projection does not fit
                    if (p.V.rows() == D && p.c.size() == p.V.cols()) {
                        q.V = f.A * p.V;
                        q.c = f.b * p.V + p.c;
                    }
                    m_fusedMaps[i].push_back(std::move(q));
                }
            }
            m_projected.resize(projections->size());
        }
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
        // y = x A + b row by row, in plain loops: the dynamic-size Eigen product costs more in
        // dispatch than in arithmetic for D <= 8, the common case, and packs its operands for
        // the lifted spaces of surfaces (D = 11 to 36). y = b + x_0 A_0 + x_1 A_1 + ... over
        // the rows A_k of A (contiguous in m_rows): the inner loop runs along y and vectorises,
        // and each y_j sums its terms in the order of the dot product b_j + sum_k x_k A(k, j).
        const AffineMap &f = m_ifs.maps[i];
        const Mat &X = m_buf[level];
        Mat &Y = m_buf[level + 1];
        const Eigen::Index n = X.rows(), D = X.cols();
        const double *rows = m_rows[std::size_t(i)].data();
        const double *b = f.b.data();
        double *y = m_row.data();
        for (Eigen::Index r = 0; r < n; ++r) {
            for (Eigen::Index j = 0; j < D; ++j)
                y[j] = b[j];
            for (Eigen::Index k = 0; k < D; ++k) {
                const double x = X(r, k);
                const double *row = rows + k * D;
                for (Eigen::Index j = 0; j < D; ++j)
                    y[j] += x * row[j];
            }
            for (Eigen::Index j = 0; j < D; ++j)
                Y(r, j) = y[j];
        }
        m_address[m_depth - level - 1] = std::uint8_t(i);
    }

    // The images of the last level through the sink's projections (see projections()).
    bool emitProjected(int level)
    {
        const Mat &X = m_buf[level];
        const Eigen::Index n = X.rows(), D = X.cols();
        for (int i = 0; i < m_ifs.size(); ++i) {
            const std::vector<Projection> &maps = m_fusedMaps[std::size_t(i)];
            for (std::size_t p = 0; p < maps.size(); ++p) {
                const Projection &q = maps[p];
                Mat &Y = m_projected[p];
                const Eigen::Index k = q.V.cols();
                Y.resize(n, k);
                for (Eigen::Index j = 0; j < k; ++j) {
                    const double *col = q.V.data() + j * D;
                    for (Eigen::Index r = 0; r < n; ++r) {
                        double s = 0;
                        for (Eigen::Index e = 0; e < D; ++e)
                            s += X(r, e) * col[e];
                        Y(r, j) = s + q.c(j);
                    }
                }
            }
            m_address[0] = std::uint8_t(i);
            m_sink.consumeProjected(m_projected, m_kind, m_address.data(), m_depth);
            ++m_emitted;
            if ((m_emitted & 4095) == 0 && !tick(4096))
                return false;
        }
        return true;
    }

    bool walk(int level)
    {
        if (m_fused && level == m_depth - 1)
            return emitProjected(level);
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
    std::vector<std::vector<double>> m_rows; // each map's A, row-major
    std::vector<double> m_row;               // the row of y being summed
    std::vector<std::uint8_t> m_address;
    std::uint64_t m_emitted = 0;
    bool m_fused = false;
    // Per map, per projection of the sink: x -> x (A_i V) + (b_i V + c).
    std::vector<std::vector<Projection>> m_fusedMaps;
    std::vector<Mat> m_projected;                 // the image through each projection, reused
};

} // namespace

void checkIterateInputs(const Ifs &ifs, const StartSet &start, int depth)
{
    ifs.validate();
    if (depth < 0 || depth > kMaxDepth)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "iteration depth must be between 0 and %1, got %2"),
            kMaxDepth, depth));
    if (start.vertices.rows() == 0)
        throw InputError(coreTranslate("awb::ifs", "the start set is empty"));
    if (start.vertices.cols() != ifs.dim())
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "start set has %1 coordinates, the IFS space has %2"),
            start.vertices.cols(), ifs.dim()));
    requireFinite(start.vertices, coreTranslate("awb::ifs", "start set"));
    if (ifs.size() > kMaxMaps)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "at most %1 maps are supported, got %2"), kMaxMaps,
            ifs.size()));
}

IterationStats iterate(const Ifs &ifs, const StartSet &start, int depth, AttractorSink &sink,
                       const IterationControl &control)
{
    return iterateParallel(ifs, start, depth, {&sink}, control);
}

IterationStats iterateAlong(const Ifs &ifs, const StartSet &start, int depth, AttractorSink &sink,
                            const IterationControl &control)
{
    checkIterateInputs(ifs, start, depth);
    const int N = ifs.size();
    const Eigen::Index D = ifs.dim();
    // T_w = f_{w1} o ... o f_{wk}, x -> x A_w + b_w; T_{wj} = T_w o f_j: A = A_j A_w,
    // b = b_j A_w + b_w. One composed map per level, allocated once.
    std::vector<Mat> A(size_t(depth) + 1);
    std::vector<RowVec> b(size_t(depth) + 1);
    A[0] = Mat::Identity(D, D);
    b[0] = RowVec::Zero(D);
    for (int l = 1; l <= depth; ++l) {
        A[size_t(l)].resize(D, D);
        b[size_t(l)].resize(D);
    }
    std::vector<std::uint8_t> address(size_t(std::max(depth, 1)), 0);
    std::vector<int> choice(size_t(depth) + 1, 0);
    Mat Y(start.vertices.rows(), D);
    IterationStats stats;
    const double total = std::max(1.0, imageCount(ifs, depth));
    // Iterative depth-first walk: choice[l] is the map tried at level l.
    int level = 0;
    for (;;) {
        if (level == depth) {
            Y.noalias() = start.vertices * A[size_t(depth)];
            Y.rowwise() += b[size_t(depth)];
            sink.consume(Y, start.kind, address.data(), depth);
            ++stats.images;
            if ((stats.images & 4095) == 0) {
                if (control.progress)
                    control.progress(std::min(1.0, double(stats.images) / total));
                if (control.cancel && control.cancel->load(std::memory_order_relaxed)) {
                    stats.cancelled = true;
                    return stats;
                }
            }
            // Back up to the deepest level with a map left to try.
            do {
                --level;
            } while (level >= 0 && choice[size_t(level)] == N - 1);
            if (level < 0)
                return stats;
            ++choice[size_t(level)];
        }
        const int j = choice[size_t(level)];
        const AffineMap &f = ifs.maps[size_t(j)];
        A[size_t(level) + 1].noalias() = f.A * A[size_t(level)];
        b[size_t(level) + 1].noalias() = f.b * A[size_t(level)];
        b[size_t(level) + 1] += b[size_t(level)];
        address[size_t(level)] = std::uint8_t(j);
        ++level;
        if (level < depth)
            choice[size_t(level)] = 0;
    }
}

IterationStats iterateParallel(const Ifs &ifs, const StartSet &start, int depth,
                               const std::vector<AttractorSink *> &sinks,
                               const IterationControl &control)
{
    checkIterateInputs(ifs, start, depth);
    if (sinks.empty())
        throw InputError(coreTranslate("awb::ifs", "no sink to receive the attractor"));
    const int N = ifs.size();
    const int threads = int(sinks.size());
    const std::vector<std::vector<int>> tasks = splitTasks(N, depth, threads, 4);
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
    onThreads(threads, worker);
    IterationStats stats;
    for (auto e : emitted)
        stats.images += e;
    stats.cancelled = stopped.load() || (control.cancel && control.cancel->load());
    if (control.progress && !stats.cancelled)
        control.progress(1.0);
    return stats;
}

namespace {

// One stream of random iteration (see Random.h): the same draws as the engine's kernels.
IterationStats chaosRun(const Ifs &ifs, const AliasTable &pick, const RowVec &x0, int stream,
                        std::uint64_t samples, const ChaosOptions &opt, AttractorSink &sink,
                        const IterationControl &control, std::atomic<std::uint64_t> &done,
                        double total)
{
    Xoshiro256 rng(opt.seed, std::uint64_t(stream));
    const int L = std::clamp(opt.addressLength, 1, 64);
    std::vector<std::uint8_t> address(L, 0);
    Mat x = x0, y(1, x0.size());
    IterationStats stats;
    int known = 0;
    const std::uint64_t skip = std::uint64_t(std::max(0, opt.skip));
    const std::uint64_t steps = samples + skip;
    for (std::uint64_t s = 0; s < steps; ++s) {
        const int i = pick.pick(rng.next());
        const AffineMap &f = ifs.maps[i];
        y.noalias() = x * f.A;
        x = y + f.b;
        std::move_backward(address.begin(), address.end() - 1, address.end());
        address[0] = std::uint8_t(i);
        known = std::min(known + 1, L);
        if (s >= skip) {
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

void checkChaosInputs(const Ifs &ifs, const RowVec &x0, std::uint64_t samples)
{
    ifs.validate();
    if (x0.size() != ifs.dim())
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "start point has %1 coordinates, the IFS space has %2"),
            x0.size(), ifs.dim()));
    requireFinite(Mat(x0), coreTranslate("awb::ifs", "start point"));
    if (samples > kMaxChaosSamples)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "at most %1 random-iteration samples, got %2"),
            kMaxChaosSamples, samples));
    if (ifs.size() > kMaxMaps)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "at most %1 maps are supported, got %2"), kMaxMaps,
            ifs.size()));
}

IterationStats chaosGame(const Ifs &ifs, const RowVec &x0, const ChaosOptions &options,
                         AttractorSink &sink, const IterationControl &control)
{
    return chaosGameParallel(ifs, x0, options, {&sink}, control);
}

IterationStats chaosGameParallel(const Ifs &ifs, const RowVec &x0, const ChaosOptions &options,
                                 const std::vector<AttractorSink *> &sinks,
                                 const IterationControl &control)
{
    checkChaosInputs(ifs, x0, options.samples);
    if (sinks.empty())
        throw InputError(coreTranslate("awb::ifs", "no sink to receive the attractor"));
    const AliasTable pick(ifs.probabilities, ifs.size());
    const int threads = std::min(int(sinks.size()), kChaosStreams);
    std::atomic<std::uint64_t> done{0};
    const double total = std::max(1.0, double(options.samples));
    std::vector<IterationStats> results(kChaosStreams);
    // Thread t runs streams t, t + threads, ...: the same streams whatever the thread count.
    auto worker = [&](int t) {
        for (int s = t; s < kChaosStreams; s += threads)
            results[s] = chaosRun(ifs, pick, x0, s, streamShare(options.samples, s), options,
                                  *sinks[t], control, done, total);
    };
    onThreads(threads, worker);
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

void QuantileBoundsSink::consume(const Mat &v, StartSet::Kind, const std::uint8_t *, int)
{
    for (const Projection &view : m_views) {
        const Mat p = project(view, v);
        if (m_coords.size() < std::size_t(p.cols()))
            m_coords.resize(std::size_t(p.cols()));
        for (Eigen::Index r = 0; r < p.rows(); ++r)
            if (p.row(r).allFinite())
                for (Eigen::Index c = 0; c < p.cols(); ++c)
                    m_coords[std::size_t(c)].push_back(p(r, c));
    }
}

std::optional<std::pair<RowVec, RowVec>> measureBox(const Ifs &ifs, const RowVec &x0,
                                                    std::uint64_t seed, double share,
                                                    std::uint64_t samples)
{
    ChaosOptions opt;
    opt.samples = samples;
    opt.seed = seed;
    QuantileBoundsSink mass(ifs.views, share);
    chaosGame(ifs, x0, opt, mass);
    if (mass.empty())
        return std::nullopt;
    return std::pair{mass.lo(), mass.hi()};
}

RowVec QuantileBoundsSink::columnQuantile(std::vector<std::vector<double>> columns, double q)
{
    RowVec out(Eigen::Index(columns.size()));
    for (std::size_t c = 0; c < columns.size(); ++c) {
        std::vector<double> &v = columns[c];
        if (v.empty()) {
            out(Eigen::Index(c)) = 0;
            continue;
        }
        const auto k = std::size_t(std::clamp(q, 0.0, 1.0) * double(v.size() - 1) + 0.5);
        std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
        out(Eigen::Index(c)) = v[k];
    }
    return out;
}

} // namespace awb
