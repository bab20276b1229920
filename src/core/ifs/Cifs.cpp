#include "core/ifs/Cifs.h"

#include "core/Decompositions.h"
#include "core/Messages.h"
#include "core/analysis/Spectrum.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <random>
#include <sstream>

namespace awb {

namespace {

constexpr int kMaxDepth = 64;


// "T" + std::to_string(i) trips GCC 12's -Wrestrict false positive at -O3; append instead.
std::string indexed(const char *prefix, int i)
{
    std::string s(prefix);
    s += std::to_string(i);
    return s;
}

std::string arcLabel(const Cifs &c, const CifsTransition &t)
{
    return formatMessage(coreTranslate("awb::ifs", "arc '%1' (%2 -> %3)"), t.name,
                         c.states[t.from].name, c.states[t.to].name);
}

} // namespace

int Cifs::addState(std::string name, const Mat &controlPoints)
{
    states.push_back({std::move(name), controlPoints});
    return int(states.size()) - 1;
}

int Cifs::addTransition(std::string name, int from, int to, const Mat &S, double weight)
{
    transitions.push_back({std::move(name), from, to, S, weight});
    return int(transitions.size()) - 1;
}

int Cifs::addColumnTransition(std::string name, int from, int to, const Mat &T, double weight)
{
    return addTransition(std::move(name), from, to, T.transpose(), weight);
}

int Cifs::stateIndex(const std::string &name) const
{
    for (size_t i = 0; i < states.size(); ++i)
        if (states[i].name == name)
            return int(i);
    throw InputError("the automaton has no state '" + name + "'");
}

int Cifs::transitionIndex(const std::string &name) const
{
    for (size_t i = 0; i < transitions.size(); ++i)
        if (transitions[i].name == name)
            return int(i);
    throw InputError("the automaton has no arc '" + name + "'");
}

std::vector<int> Cifs::outgoing(int state) const
{
    std::vector<int> out;
    for (size_t i = 0; i < transitions.size(); ++i)
        if (transitions[i].from == state)
            out.push_back(int(i));
    return out;
}

Projection Cifs::view(int state) const
{
    const Mat &P = states.at(state).controlPoints;
    return {P, RowVec::Zero(P.cols())};
}

void Cifs::validate() const
{
    if (states.empty())
        throw InputError(coreTranslate("awb::ifs", "the automaton has no states"));
    for (const CifsState &s : states) {
        if (s.dim() == 0)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "state '%1' has no control points"), s.name));
        if (s.controlPoints.cols() != 2 && s.controlPoints.cols() != 3)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "state '%1': control points must be 2D or 3D, got %2 "
                                          "coordinates"),
                s.name, s.controlPoints.cols()));
        requireFinite(s.controlPoints,
                      formatMessage(coreTranslate("awb::ifs", "control points of state '%1'"),
                                    s.name));
    }
    if (transitions.size() > 255)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "at most 255 arcs are supported (addresses are bytes), got "
                                      "%1"),
            transitions.size()));
    const int N = int(states.size());
    for (const CifsTransition &t : transitions) {
        if (t.from < 0 || t.from >= N || t.to < 0 || t.to >= N)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "arc '%1' connects states %2 -> %3, but the automaton "
                                          "has %4 states"),
                t.name, t.from, t.to, N));
        const std::string label = arcLabel(*this, t);
        const int nFrom = states[t.from].dim(), nTo = states[t.to].dim();
        if (t.S.rows() != nTo || t.S.cols() != nFrom)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "%1 has a %2 x %3 matrix; it must be %4 x %5 (row "
                                          "convention: rows = dimension of '%6', columns = "
                                          "dimension of '%7')"),
                label, t.S.rows(), t.S.cols(), nTo, nFrom, states[t.to].name,
                states[t.from].name));
        requireFinite(t.S, label);
        for (Eigen::Index r = 0; r < t.S.rows(); ++r) {
            const double sum = t.S.row(r).sum();
            if (std::abs(sum - 1.0) > 1e-9 * std::max(1.0, t.S.row(r).cwiseAbs().sum()))
                throw InputError(formatMessage(
                    coreTranslate("awb::ifs", "row %1 of %2 sums to %3, not 1: the map does not "
                                              "keep barycentric coordinates summing to 1"),
                    r + 1, label, streamedNumber(sum)));
        }
        if (!std::isfinite(t.weight) || t.weight <= 0)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "the weight of %1 must be a finite number > 0, got %2"),
                label, streamedNumber(t.weight)));
    }
    for (int s = 0; s < N; ++s)
        if (outgoing(s).empty())
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "state '%1' has no outgoing arc: its attractor would "
                                          "be empty"),
                states[s].name));
}

Mat barycentricPart(const Mat &S)
{
    if (S.rows() != S.cols() || S.rows() == 0)
        throw InputError(coreTranslate("awb::ifs", "the barycentric part needs a non-empty square "
                                                   "matrix"));
    const Eigen::Index n = S.rows() - 1;
    // Basis e_k - e_{n}: w S has coordinates w_k, so R(k, j) = S(k, j) - S(n, j).
    return S.topLeftCorner(n, n) - S.row(n).head(n).replicate(n, 1);
}

std::string describePath(const Cifs &cifs, int from, const std::vector<int> &transitions)
{
    std::string out = cifs.states.at(from).name;
    for (int t : transitions) {
        const CifsTransition &tr = cifs.transitions.at(t);
        out += " -" + tr.name + "-> " + cifs.states.at(tr.to).name;
    }
    return out;
}

namespace {

// lambda_s = lambda_end * product: S_{t_m} ... S_{t_1} (n_end x n_s).
Mat pathProduct(const Cifs &cifs, int from, const std::vector<int> &path)
{
    Mat M = Mat::Identity(cifs.states[from].dim(), cifs.states[from].dim());
    for (int t : path)
        M = (cifs.transitions[t].S * M).eval();
    return M;
}

// Simple cycles, each once: it starts at its lowest state and visits only higher ones. The
// simple paths of a graph can be exponentially many even where its cycles are few (a layered
// automaton from a file): the walk stops after a bounded number of steps too, then
// `complete` is false.
constexpr long long kMaxCycleSteps = 2'000'000;

void enumerateCycles(const Cifs &cifs, const std::vector<std::vector<int>> &out, int start,
                     int state, std::vector<int> &path, std::vector<bool> &onPath,
                     int maxCycles, CifsCheck &check, long long &steps)
{
    for (int t : out[state]) {
        if (!check.complete)
            return;
        if (++steps > kMaxCycleSteps) {
            check.complete = false;
            return;
        }
        const int q = cifs.transitions[t].to;
        if (q == start) {
            if (int(check.cycles.size()) >= maxCycles) {
                check.complete = false;
                return;
            }
            path.push_back(t);
            check.cycles.push_back({path, 0.0});
            path.pop_back();
        } else if (q > start && !onPath[q]) {
            onPath[q] = true;
            path.push_back(t);
            enumerateCycles(cifs, out, start, q, path, onPath, maxCycles, check, steps);
            path.pop_back();
            onPath[q] = false;
        }
    }
}

std::vector<std::vector<int>> outgoingLists(const Cifs &cifs)
{
    std::vector<std::vector<int>> out(cifs.states.size());
    for (size_t t = 0; t < cifs.transitions.size(); ++t)
        out[cifs.transitions[t].from].push_back(int(t));
    return out;
}

} // namespace

CifsCheck checkCifs(const Cifs &cifs, int maxCycles)
{
    cifs.validate();
    CifsCheck check;
    const auto out = outgoingLists(cifs);
    const int N = int(cifs.states.size());
    std::vector<bool> onPath(N, false);
    std::vector<int> path;
    long long steps = 0;
    for (int s = 0; s < N && check.complete; ++s)
        enumerateCycles(cifs, out, s, s, path, onPath, maxCycles, check, steps);
    for (CycleCheck &c : check.cycles) {
        const int s = cifs.transitions[c.transitions.front()].from;
        const Mat M = pathProduct(cifs, s, c.transitions);
        c.spectralRadius = M.rows() > 1 ? spectrum(barycentricPart(M)).spectralRadius : 0.0;
        if (check.contractive && !(c.spectralRadius < 1.0 - 1e-12)) {
            check.contractive = false;
            check.message = formatMessage(
                coreTranslate("awb::ifs", "cycle %1 has spectral radius %2 >= 1 on the "
                                          "barycentric directions: repeating it does not "
                                          "contract, so the automaton has no attractor"),
                describePath(cifs, s, c.transitions), streamedNumber(c.spectralRadius));
        }
    }
    return check;
}

RowVec barycentricFixedPoint(const Mat &S)
{
    if (S.rows() != S.cols() || S.rows() == 0)
        throw InputError(coreTranslate("awb::ifs", "a fixed point needs a non-empty square "
                                                   "matrix"));
    const Eigen::Index n = S.rows();
    // lambda (S - I) = 0 and lambda 1 = 1, as one (n+1) x n system on lambda^T.
    Mat A(n + 1, n);
    A.topRows(n) = (S - Mat::Identity(n, n)).transpose();
    A.row(n).setOnes();
    Vec rhs = Vec::Zero(n + 1);
    rhs(n) = 1.0;
    Eigen::FullPivLU<Mat> lu(A);
    lu.setThreshold(1e-10);
    if (lu.rank() < n)
        throw InputError(coreTranslate("awb::ifs", "the fixed point is not unique: 1 is a repeated "
                                                   "eigenvalue"));
    return lu.solve(rhs).transpose();
}

namespace {

// Shortest cycle through s (breadth first), empty when s lies on none.
std::vector<int> shortestCycle(const Cifs &cifs, const std::vector<std::vector<int>> &out, int s)
{
    const int N = int(cifs.states.size());
    std::vector<int> via(N, -1);
    std::vector<bool> seen(N, false);
    std::deque<int> queue{s};
    seen[s] = true;
    while (!queue.empty()) {
        const int q = queue.front();
        queue.pop_front();
        for (int t : out[q]) {
            const int r = cifs.transitions[t].to;
            if (r == s) {
                std::vector<int> path{t};
                for (int x = q; x != s; x = cifs.transitions[via[x]].from)
                    path.insert(path.begin(), via[x]);
                return path;
            }
            if (!seen[r]) {
                seen[r] = true;
                via[r] = t;
                queue.push_back(r);
            }
        }
    }
    return {};
}

} // namespace

std::vector<StartSet> attractorSeeds(const Cifs &cifs)
{
    const CifsCheck check = checkCifs(cifs);
    if (!check.contractive)
        throw InputError(check.message);
    const auto out = outgoingLists(cifs);
    const int N = int(cifs.states.size());
    std::vector<StartSet> seeds(N);
    std::vector<bool> done(N, false);
    for (int s = 0; s < N; ++s) {
        std::vector<RowVec> pts;
        for (int t : out[s])
            if (cifs.transitions[t].to == s)
                pts.push_back(barycentricFixedPoint(cifs.transitions[t].S));
        if (pts.empty()) {
            const std::vector<int> cycle = shortestCycle(cifs, out, s);
            if (!cycle.empty())
                pts.push_back(barycentricFixedPoint(pathProduct(cifs, s, cycle)));
        }
        if (pts.empty())
            continue;
        Mat X(pts.size(), cifs.states[s].dim());
        for (size_t i = 0; i < pts.size(); ++i)
            X.row(i) = pts[i];
        seeds[s] = StartSet::points(X);
        done[s] = true;
    }
    // States on no cycle form a DAG above the cycles: map the first arc's target seeds up.
    for (bool progress = true; progress;) {
        progress = false;
        for (int s = 0; s < N; ++s) {
            if (done[s])
                continue;
            const CifsTransition &t = cifs.transitions[out[s].front()];
            if (!done[t.to])
                continue;
            seeds[s] = StartSet::points(seeds[t.to].vertices * t.S);
            done[s] = progress = true;
        }
    }
    return seeds;
}

std::vector<StartSet> controlPolygonStarts(const Cifs &cifs)
{
    std::vector<StartSet> out;
    for (const CifsState &s : cifs.states)
        out.push_back(StartSet::polyline(Mat::Identity(s.dim(), s.dim())));
    return out;
}

CifsStacking stackingOf(const Cifs &cifs)
{
    CifsStacking s;
    for (const CifsState &q : cifs.states) {
        s.offsets.push_back(s.dimension);
        s.dimension += q.dim();
    }
    const Eigen::Index d = cifs.states.empty() ? 2 : cifs.states.front().controlPoints.cols();
    s.points = Mat::Zero(s.dimension, d);
    for (std::size_t q = 0; q < cifs.states.size(); ++q)
        s.points.middleRows(s.offsets[q], cifs.states[q].dim()) = cifs.states[q].controlPoints;
    return s;
}

void StackedSink::consume(const Mat &vertices, StartSet::Kind kind, const std::uint8_t *address,
                          int length)
{
    m_buffer.setZero(vertices.rows(), m_dim);
    m_buffer.middleCols(offset, vertices.cols()) = vertices;
    m_target.consume(m_buffer, kind, address, length);
}

double pathCount(const Cifs &cifs, int state, int depth)
{
    const int N = int(cifs.states.size());
    std::vector<double> count(N, 1.0), next(N);
    for (int k = 0; k < depth; ++k) {
        std::fill(next.begin(), next.end(), 0.0);
        for (const CifsTransition &t : cifs.transitions)
            next[t.from] += count[t.to];
        count.swap(next);
    }
    return count.at(state);
}

namespace {

void checkState(const Cifs &cifs, int state)
{
    if (state < 0 || state >= int(cifs.states.size()))
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "state %1 does not exist: the automaton has %2 states"),
            state, cifs.states.size()));
}

// Depth-first over the paths; composite[k] maps level k's state space into the root's.
class PathWalker {
public:
    PathWalker(const Cifs &cifs, const std::vector<StartSet> &starts, int depth,
               AttractorSink &sink, const IterationControl &control, double total)
        : m_cifs(cifs), m_out(outgoingLists(cifs)), m_starts(starts), m_depth(depth),
          m_sink(sink), m_control(control), m_total(total), m_composite(depth + 1),
          m_address(std::max(depth, 1), 0)
    {
    }

    bool walk(int level, int q)
    {
        if (level == m_depth) {
            m_sink.consume(m_starts[q].vertices * m_composite[level], m_starts[q].kind,
                           m_address.data(), m_depth);
            ++m_emitted;
            return (m_emitted & 4095) != 0 || tick();
        }
        for (int t : m_out[q]) {
            m_composite[level + 1].noalias() = m_cifs.transitions[t].S * m_composite[level];
            m_address[level] = std::uint8_t(t);
            if (!walk(level + 1, m_cifs.transitions[t].to))
                return false;
        }
        return true;
    }

    void setRoot(int state)
    {
        m_composite[0] = Mat::Identity(m_cifs.states[state].dim(), m_cifs.states[state].dim());
    }
    std::uint64_t emitted() const { return m_emitted; }

private:
    bool tick()
    {
        if (m_control.progress)
            m_control.progress(std::min(1.0, double(m_emitted) / m_total));
        return !(m_control.cancel && m_control.cancel->load(std::memory_order_relaxed));
    }

    const Cifs &m_cifs;
    std::vector<std::vector<int>> m_out;
    const std::vector<StartSet> &m_starts;
    int m_depth;
    AttractorSink &m_sink;
    const IterationControl &m_control;
    double m_total;
    std::vector<Mat> m_composite;
    std::vector<std::uint8_t> m_address;
    std::uint64_t m_emitted = 0;
};

} // namespace

IterationStats iterate(const Cifs &cifs, int state, const std::vector<StartSet> &starts,
                       int depth, AttractorSink &sink, const IterationControl &control)
{
    cifs.validate();
    checkState(cifs, state);
    if (depth < 0 || depth > kMaxDepth)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "iteration depth must be between 0 and %1, got %2"),
            kMaxDepth, depth));
    if (starts.size() != cifs.states.size())
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "one start set per state is needed: the automaton has %1 "
                                      "states, got %2 start sets"),
            cifs.states.size(), starts.size()));
    for (size_t q = 0; q < starts.size(); ++q) {
        const std::string label = formatMessage(
            coreTranslate("awb::ifs", "start set of state '%1'"), cifs.states[q].name);
        if (starts[q].vertices.rows() == 0)
            throw InputError(formatMessage(coreTranslate("awb::ifs", "%1 is empty"), label));
        if (starts[q].vertices.cols() != cifs.states[q].dim())
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "%1 has %2 coordinates, the state's space has %3"),
                label, starts[q].vertices.cols(), cifs.states[q].dim()));
        requireFinite(starts[q].vertices, label);
    }
    PathWalker walker(cifs, starts, depth, sink, control,
                      std::max(1.0, pathCount(cifs, state, depth)));
    walker.setRoot(state);
    IterationStats stats;
    stats.cancelled = !walker.walk(0, state);
    stats.images = walker.emitted();
    if (control.progress && !stats.cancelled)
        control.progress(1.0);
    return stats;
}

IterationStats chaosGame(const Cifs &cifs, int state, const ChaosOptions &options,
                         AttractorSink &sink, const IterationControl &control)
{
    cifs.validate();
    checkState(cifs, state);
    if (options.samples > 4'000'000'000ULL)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "at most 4e9 random-iteration samples, got %1"),
            options.samples));
    const auto out = outgoingLists(cifs);
    const int N = int(cifs.states.size());
    // Only the states reachable from `state` feed its point.
    std::vector<int> live;
    std::vector<bool> seen(N, false);
    std::deque<int> queue{state};
    seen[state] = true;
    while (!queue.empty()) {
        const int q = queue.front();
        queue.pop_front();
        live.push_back(q);
        for (int t : out[q])
            if (!seen[cifs.transitions[t].to]) {
                seen[cifs.transitions[t].to] = true;
                queue.push_back(cifs.transitions[t].to);
            }
    }
    std::vector<std::vector<double>> cumulative(N);
    for (int q : live) {
        double sum = 0;
        for (int t : out[q])
            cumulative[q].push_back(sum += cifs.transitions[t].weight);
        for (double &c : cumulative[q])
            c /= sum;
        cumulative[q].back() = 1.0;
    }
    const int L = std::clamp(options.addressLength, 1, 64);
    std::vector<RowVec> x(N), nx(N);
    std::vector<std::vector<std::uint8_t>> addr(N, std::vector<std::uint8_t>(L, 0)), naddr = addr;
    std::vector<int> known(N, 0), nknown(N, 0);
    for (int q : live)
        x[q] = RowVec::Constant(cifs.states[q].dim(), 1.0 / cifs.states[q].dim());
    nx = x;

    std::mt19937_64 rng(options.seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    IterationStats stats;
    const std::uint64_t skip = std::uint64_t(std::max(0, options.skip));
    for (std::uint64_t round = 0; round < skip + options.samples; ++round) {
        for (int q : live) {
            const auto &cum = cumulative[q];
            const size_t k = std::min(
                size_t(std::lower_bound(cum.begin(), cum.end(), uni(rng)) - cum.begin()),
                cum.size() - 1);
            const int t = out[q][k];
            const int to = cifs.transitions[t].to;
            nx[q].noalias() = x[to] * cifs.transitions[t].S;
            naddr[q][0] = std::uint8_t(t);
            std::copy(addr[to].begin(), addr[to].end() - 1, naddr[q].begin() + 1);
            nknown[q] = std::min(known[to] + 1, L);
        }
        x.swap(nx);
        addr.swap(naddr);
        known.swap(nknown);
        if (round < skip)
            continue;
        sink.consume(x[state], StartSet::Kind::Points, addr[state].data(), known[state]);
        ++stats.images;
        if ((stats.images & 16383) == 0) {
            if (control.progress)
                control.progress(double(stats.images) / double(std::max<std::uint64_t>(
                                                            1, options.samples)));
            if (control.cancel && control.cancel->load(std::memory_order_relaxed)) {
                stats.cancelled = true;
                break;
            }
            if (!x[state].allFinite())
                break; // the orbit escaped: some cycle does not contract
        }
    }
    if (control.progress && !stats.cancelled)
        control.progress(1.0);
    return stats;
}

// ---- the example of 003 §2.2 -------------------------------------------------------------

std::vector<AffineMap> barnsleyFernMaps()
{
    // The classic table gives (x, y) |-> (a x + b y + e, c x + d y + f); in the row
    // convention the linear part is its transpose [[a, c], [b, d]].
    auto map = [](double a, double b, double c, double d, double e, double f) {
        Mat A(2, 2);
        A << a, c, b, d;
        RowVec t(2);
        t << e, f;
        return AffineMap{A, t};
    };
    return {map(0.0, 0.0, 0.0, 0.16, 0.0, 0.0),        // stem
            map(0.85, 0.04, -0.04, 0.85, 0.0, 1.6),    // main frond
            map(0.2, -0.26, 0.23, 0.22, 0.0, 1.6),     // left leaflet
            map(-0.15, 0.28, 0.26, 0.24, 0.0, 0.44)};  // right leaflet
}

std::vector<double> barnsleyFernProbabilities() { return {0.01, 0.85, 0.07, 0.07}; }

Mat barycentricMatrix(const AffineMap &f, const Mat &domain, const Mat &image)
{
    const int d = f.dim();
    if (f.b.size() != d)
        throw InputError(coreTranslate("awb::ifs", "the affine map's translation does not "
                                                   "match its linear part"));
    for (const Mat *frame : {&domain, &image})
        if (frame->rows() != d + 1 || frame->cols() != d)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "a barycentric frame in %1D needs %2 points, got a %3 "
                                          "x %4 matrix"),
                d, d + 1, frame->rows(), frame->cols()));
    requireFinite(domain, coreTranslate("awb::ifs", "domain frame"));
    requireFinite(image, coreTranslate("awb::ifs", "image frame"));
    requireFinite(f.A, coreTranslate("awb::ifs", "affine map"));
    // [x 1] = lambda [P | 1], and f acts on [x 1] by H = [[A, 0], [b, 1]].
    auto homogeneous = [d](const Mat &P) {
        Mat H(d + 1, d + 1);
        H << P, Vec::Ones(d + 1);
        return H;
    };
    Mat H = Mat::Zero(d + 1, d + 1);
    H.topLeftCorner(d, d) = f.A;
    H.bottomLeftCorner(1, d) = f.b;
    H(d, d) = 1.0;
    const Mat Ih = homogeneous(image);
    Eigen::FullPivLU<Mat> lu(Ih);
    lu.setThreshold(1e-12);
    if (!lu.isInvertible())
        throw InputError(coreTranslate("awb::ifs", "the image frame's points are affinely "
                                                   "dependent (collinear in 2D)"));
    return homogeneous(domain) * H * lu.inverse();
}

Mat fernFrame()
{
    Mat P(3, 2);
    P << -3, 0, 3, 0, 0, 10;
    return P;
}

Cifs barnsleyFernCifs(const Mat &frame)
{
    Cifs c;
    const int fern = c.addState("Fern", frame);
    const auto maps = barnsleyFernMaps();
    const auto prob = barnsleyFernProbabilities();
    for (int i = 0; i < 4; ++i)
        c.addTransition(indexed("T", i), fern, fern,
                        barycentricMatrix(maps[i], frame, frame), prob[i]);
    return c;
}

Cifs fernSierpinskiCifs(int redirected, const Mat &frame)
{
    if (redirected < 0 || redirected > 3)
        throw InputError("the redirected fern arc must be T0..T3, got "
                         + std::to_string(redirected));
    Cifs c = barnsleyFernCifs(frame);
    const int sierpinski = c.addState("Sierpinski", frame);
    // The arc keeps its map; only its target changes (003 §2.2), so S = frame -> frame again.
    c.transitions[redirected].to = sierpinski;
    for (int k = 0; k < 3; ++k) {
        // lambda |-> (lambda + e_k) / 2: row i of S is (e_i + e_k) / 2.
        Mat S = 0.5 * Mat::Identity(3, 3);
        S.col(k).array() += 0.5;
        c.addTransition(indexed("S", k), sierpinski, sierpinski, S);
    }
    return c;
}

} // namespace awb
