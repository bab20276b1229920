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

// Points a piece of each type sends at each depth: its outputs at depth 0, its children's
// sum below.
class PointCounts {
public:
    PointCounts(const MeshPieces &pieces, const MeshStart &start)
        : m_pieces(pieces), m_start(start)
    {
    }
    double operator()(int type, int depth);

private:
    const MeshPieces &m_pieces;
    const MeshStart &m_start;
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
        m_rootIsVertex = m_pieces.types[std::size_t(type)].kind == MeshPieceType::Kind::Vertex;
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
        if (m_start.kind == MeshStart::Kind::Points) {
            m_out.noalias() = m_weights[std::size_t(&t - m_pieces.types.data())] * net;
            consume(m_out, m_start.points.kind, level);
            return;
        }
        // The piece's faces as polygons of their corners' limits (or the corners): drawn as
        // shaded faces, and as points the vertices of the refined mesh.
        const bool limits = m_start.kind == MeshStart::Kind::VertexLimits;
        if (limits)
            m_out.noalias() = t.limits * net;
        const Mat &corners = limits ? m_out : net;
        for (const std::vector<int> &face : t.faces) {
            m_face.resize(Eigen::Index(face.size()), 3);
            for (std::size_t i = 0; i < face.size(); ++i)
                m_face.row(Eigen::Index(i)) = corners.row(face[i]);
            consume(m_face, StartSet::Kind::Polygon, level);
        }
    }

    void consume(const Mat &points, StartSet::Kind kind, int level)
    {
        if (m_start.levelAddresses && m_rootIsVertex && level > 0) {
            m_levelAddress.assign(m_address.begin(), m_address.end());
            int k = 0;
            while (k < level && m_address[std::size_t(k)] == 0)
                ++k;
            m_levelAddress[0] = std::uint8_t(std::min(k, 255));
            m_sink.consume(points, kind, m_levelAddress.data(), level);
        } else {
            m_sink.consume(points, kind, m_address.data(), level);
        }
        ++m_images;
    }

    const MeshPieces &m_pieces;
    const MeshStart &m_start;
    AttractorSink &m_sink;
    const IterationControl &m_control;
    std::vector<Mat> m_nets;
    std::vector<Mat> m_weights;  // per type (Points)
    std::vector<std::uint8_t> m_address, m_levelAddress;
    bool m_rootIsVertex = false;
    Mat m_out, m_face;
    std::uint64_t m_steps = 0, m_images = 0;
    bool m_cancelled = false;
};

// Points per image set of one piece: the start set, or the corners of each of its faces.
int outputsOf(const MeshPieceType &t, const MeshStart &start)
{
    if (start.kind == MeshStart::Kind::Points)
        return int(start.points.vertices.rows());
    int n = 0;
    for (const auto &face : t.faces)
        n += int(face.size());
    return n;
}

double PointCounts::operator()(int type, int depth)
{
    const MeshPieceType &t = m_pieces.types[std::size_t(type)];
    if (depth == 0)
        return outputsOf(t, m_start);
    const auto it = m_memo.find({type, depth});
    if (it != m_memo.end())
        return it->second;
    double sum = 0.0;
    for (const auto &child : t.children)
        sum += (*this)(child.type, depth - 1);
    m_memo[{type, depth}] = sum;
    return sum;
}

} // namespace

double meshPointCount(const MeshPieces &pieces, const MeshStart &start, int depth)
{
    if (depth < pieces.steps && start.kind != MeshStart::Kind::Points) {
        MeshTopology t(pieces.inputVertexCount, pieces.inputFaces);
        int count = t.vertexCount();
        for (int k = 0; k < depth; ++k) {
            Refinement r = refineTopology(t, pieces.scheme);
            count = int(r.stencils.size());
            t = MeshTopology(count, r.faces);
        }
        return count;
    }
    const int pieceDepth = std::max(depth - pieces.steps, 0);
    PointCounts counts(pieces, start);
    double points = double(pieces.loneVertices.size());
    for (const MeshPieceRoot &root : pieces.roots)
        points += counts(root.type, pieceDepth);
    return points;
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
    const double points = meshPointCount(pieces, start, depth);
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
