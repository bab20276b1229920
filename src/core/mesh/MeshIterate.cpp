#include "core/mesh/MeshIterate.h"

#include "core/Messages.h"
#include "core/Threads.h"
#include "core/schemes/ControlPointFractal.h"

#include <atomic>
#include <cmath>
#include <map>

namespace awb {

namespace {

constexpr int kMaxDepth = 64;
constexpr double kMaxPoints = 2147483648.0;  // 2^31

// Images of each type at each depth: 1 at depth 0, the children's sum below.
class ImageCounts {
public:
    explicit ImageCounts(const MeshPieces &pieces) : m_pieces(pieces) {}
    double operator()(int type, int depth)
    {
        if (depth == 0)
            return 1.0;
        const auto [it, added] = m_memo.emplace(std::make_pair(type, depth), 0.0);
        if (!added)
            return it->second;
        double sum = 0.0;
        for (const auto &child : m_pieces.types[std::size_t(type)].children)
            sum += (*this)(child.type, depth - 1);
        m_memo[{type, depth}] = sum;
        return sum;
    }

private:
    const MeshPieces &m_pieces;
    std::map<std::pair<int, int>, double> m_memo;
};

// One thread's walk down the pieces: the nets of the current path, one per level, allocated
// once.
class PieceWalker {
public:
    PieceWalker(const MeshPieces &pieces, const MeshStart &start, AttractorSink &sink,
                const IterationControl &control)
        : m_pieces(pieces), m_start(start), m_sink(sink), m_control(control)
    {
    }

    void root(int type, Mat net, int depth)
    {
        m_nets.resize(std::size_t(depth) + 1);
        m_address.assign(std::size_t(depth) + 1, 0);
        m_nets[0] = std::move(net);
        if (m_start.kind == MeshStart::Kind::Points)
            liftStart(type);
        descend(type, 0, depth);
    }

    bool cancelled() const { return m_cancelled; }
    std::uint64_t images() const { return m_images; }

private:
    // The start set in the lifted space of every type the root reaches: its least-norm weights
    // over the net of the type's first piece met breadth first (the root's own net for the
    // root's type, so that depth 0 gives the start set itself). Each type keeps its weights at
    // every depth below: f_w(X0) then stays within |w| diam(net) of the shrinking piece.
    void liftStart(int rootType)
    {
        m_weights.assign(m_pieces.types.size(), Mat());
        std::vector<std::pair<int, Mat>> queue;
        queue.emplace_back(rootType, m_nets[0]);
        m_weights[std::size_t(rootType)] =
            leastNormWeightsOfRows(m_nets[0], m_start.points.vertices);
        for (std::size_t q = 0; q < queue.size(); ++q) {
            const MeshPieceType &t = m_pieces.types[std::size_t(queue[q].first)];
            for (const MeshPieceType::Child &child : t.children) {
                if (m_weights[std::size_t(child.type)].size() > 0)
                    continue;
                const Mat net = child.S * queue[q].second;
                m_weights[std::size_t(child.type)] =
                    leastNormWeightsOfRows(net, m_start.points.vertices);
                queue.emplace_back(child.type, net);
            }
        }
    }

    void descend(int type, int level, int depth)
    {
        const MeshPieceType &t = m_pieces.types[std::size_t(type)];
        const Mat &net = m_nets[std::size_t(level)];
        if (depth == 0) {
            emit(t, net, level);
            return;
        }
        for (std::size_t c = 0; c < t.children.size(); ++c) {
            if ((++m_steps & 255) == 0 && m_control.cancel && m_control.cancel->load()) {
                m_cancelled = true;
                return;
            }
            const MeshPieceType::Child &child = t.children[c];
            Mat &next = m_nets[std::size_t(level) + 1];
            next.setZero(m_pieces.types[std::size_t(child.type)].netSize, 3);
            for (const MeshPieceType::Entry &e : child.entries)
                next.row(e.row) += e.weight * net.row(e.col);
            m_address[std::size_t(level)] = std::uint8_t(c);
            descend(child.type, level + 1, depth - 1);
            if (m_cancelled)
                return;
        }
    }

    void emit(const MeshPieceType &t, const Mat &net, int level)
    {
        StartSet::Kind kind = StartSet::Kind::Points;
        switch (m_start.kind) {
        case MeshStart::Kind::VertexLimits:
            m_out.noalias() = t.limits * net;
            break;
        case MeshStart::Kind::ControlPoints:
            m_out.resize(Eigen::Index(t.corners.size()), 3);
            for (std::size_t i = 0; i < t.corners.size(); ++i)
                m_out.row(Eigen::Index(i)) = net.row(t.corners[i]);
            break;
        case MeshStart::Kind::Points:
            m_out.noalias() = m_weights[std::size_t(&t - m_pieces.types.data())] * net;
            kind = m_start.points.kind;
            break;
        }
        m_sink.consume(m_out, kind, m_address.data(), level);
        ++m_images;
    }

    const MeshPieces &m_pieces;
    const MeshStart &m_start;
    AttractorSink &m_sink;
    const IterationControl &m_control;
    std::vector<Mat> m_nets;
    std::vector<Mat> m_weights;  // per type (Points)
    std::vector<std::uint8_t> m_address;
    Mat m_out;
    std::uint64_t m_steps = 0, m_images = 0;
    bool m_cancelled = false;
};

int outputsOf(const MeshPieceType &t, const MeshStart &start)
{
    return start.kind == MeshStart::Kind::Points ? int(start.points.vertices.rows())
                                                 : int(t.corners.size());
}

} // namespace

double meshImageCount(const MeshPieces &pieces, int depth)
{
    if (depth < pieces.steps)
        return 1.0;
    ImageCounts counts(pieces);
    double sum = double(pieces.loneVertices.size());
    for (const MeshPieceRoot &root : pieces.roots)
        sum += counts(root.type, depth - pieces.steps);
    return sum;
}

IterationStats iterateMesh(const MeshPieces &pieces, const Mat &inputVertices,
                           const MeshStart &start, int depth,
                           const std::vector<AttractorSink *> &sinks,
                           const IterationControl &control)
{
    if (depth < 0 || depth > kMaxDepth)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "iteration depth must be between 0 and %1, got %2"),
            kMaxDepth, depth));
    if (inputVertices.rows() != pieces.inputVertexCount || inputVertices.cols() != 3)
        throw InputError(formatMessage(
            coreTranslate("awb::mesh", "the mesh has %1 vertices, but %2 positions were given"),
            pieces.inputVertexCount, inputVertices.rows()));
    requireFinite(inputVertices, coreTranslate("awb::mesh", "mesh vertices"));
    if (start.kind == MeshStart::Kind::Points) {
        if (start.points.vertices.rows() == 0)
            throw InputError(coreTranslate("awb::ifs", "the start set is empty"));
        if (start.points.vertices.cols() != 3)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "start set has %1 coordinates, the IFS space has %2"),
                start.points.vertices.cols(), 3));
        requireFinite(start.points.vertices, coreTranslate("awb::ifs", "start set"));
    }
    if (sinks.empty())
        return {};
    IterationStats stats;
    Mesh input{inputVertices, pieces.inputFaces};
    if (depth < pieces.steps && start.kind != MeshStart::Kind::Points) {
        // Below the isolation steps the pieces do not exist yet: the refined mesh itself.
        const Mesh refined = refineMesh(input, pieces.scheme, depth);
        const Mat out = start.kind == MeshStart::Kind::VertexLimits
                            ? limitPositions(refined, pieces.scheme)
                            : refined.vertices;
        sinks.front()->consume(out, StartSet::Kind::Points, nullptr, 0);
        stats.images = 1;
        return stats;
    }
    const int pieceDepth = std::max(depth - pieces.steps, 0);
    ImageCounts counts(pieces);
    double points = double(pieces.loneVertices.size());
    for (const MeshPieceRoot &root : pieces.roots)
        points += counts(root.type, pieceDepth)
                  * outputsOf(pieces.types[std::size_t(root.type)], start);
    if (points > kMaxPoints)
        throw InputError(formatMessage(
            coreTranslate("awb::mesh", "depth %1 makes about %2 points; at most 2^31 are drawn"),
            depth, std::to_string(std::llround(points))));
    const Mat level = isolatedPositions(pieces, inputVertices);
    if (!pieces.loneVertices.empty()) {
        Mat lone(Eigen::Index(pieces.loneVertices.size()), 3);
        for (std::size_t i = 0; i < pieces.loneVertices.size(); ++i)
            lone.row(Eigen::Index(i)) = inputVertices.row(pieces.loneVertices[i]);
        sinks.front()->consume(lone, StartSet::Kind::Points, nullptr, 0);
        ++stats.images;
    }
    const int threads = int(sinks.size());
    const int rootCount = int(pieces.roots.size());
    std::atomic<int> next{0}, done{0};
    std::atomic<std::uint64_t> images{0};
    std::atomic<bool> cancelled{false};
    onThreads(threads, [&](int thread) {
        PieceWalker walker(pieces, start, *sinks[std::size_t(thread)], control);
        for (int r = next++; r < rootCount && !cancelled.load(); r = next++) {
            const MeshPieceRoot &root = pieces.roots[std::size_t(r)];
            Mat net(Eigen::Index(root.net.size()), 3);
            for (std::size_t i = 0; i < root.net.size(); ++i)
                net.row(Eigen::Index(i)) = level.row(root.net[i]);
            walker.root(root.type, std::move(net), pieceDepth);
            if (walker.cancelled())
                cancelled = true;
            const int finished = ++done;
            if (control.progress)
                control.progress(double(finished) / rootCount);
        }
        images += walker.images();
    });
    stats.images += images.load();
    stats.cancelled = cancelled.load();
    return stats;
}

} // namespace awb
