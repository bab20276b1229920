#include "core/mesh/MeshIterate.h"

#include "core/Messages.h"
#include "core/Threads.h"
#include "core/mesh/MeshSheets.h"
#include "core/schemes/ControlPointFractal.h"

#include <atomic>
#include <cmath>
#include <map>
#include <optional>

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

// One thread's walk down the pieces. The nets of the current path, one per level, are arrays
// of x, y, z allocated once; a child's net is its sparse S_i times the parent's, each row summed
// in registers and stored once; one step above the leaves the children's corner limits come
// straight from the parent's net (their limits times S_i, precomputed), so that the leaves'
// nets are never built.
class PieceWalker {
public:
    PieceWalker(const MeshPieces &pieces, const MeshStart &start, AttractorSink &sink,
                const IterationControl &control)
        : m_pieces(pieces), m_start(start), m_sink(sink), m_control(control)
    {
        int corners = 0;
        for (const MeshPieceType &t : pieces.types) {
            m_maxNet = std::max(m_maxNet, t.netSize);
            corners = std::max(corners, int(t.corners.size()));
        }
        m_out.assign(std::size_t(3 * std::max(corners, m_maxNet)), 0.0);
    }

    void root(const MeshPieceRoot &root, const Mat &level, int depth)
    {
        m_rootIsVertex =
            m_pieces.types[std::size_t(root.type)].kind == MeshPieceType::Kind::Vertex;
        if (int(m_nets.size()) < depth + 1)
            m_nets.resize(std::size_t(depth) + 1,
                          std::vector<double>(std::size_t(3 * m_maxNet), 0.0));
        m_address.assign(std::size_t(depth) + 1, 0);
        double *net = m_nets[0].data();
        const auto rootNet = m_pieces.net(root);
        for (std::size_t i = 0; i < rootNet.size(); ++i)
            for (int k = 0; k < 3; ++k)
                net[3 * i + std::size_t(k)] = level(rootNet[i], k);
        if (m_start.kind == MeshStart::Kind::Points)
            liftStart(root.type, level, rootNet);
        descend(root.type, 0, depth);
    }

    bool cancelled() const { return m_cancelled; }
    std::uint64_t images() const { return m_images; }

private:
    // The start set in the lifted space of every type the root reaches: its least-norm weights
    // over the net of the type's first piece met breadth first (the root's own net for the
    // root's type, so that depth 0 gives the start set itself). Each type keeps its weights at
    // every depth below: f_w(X0) then stays within |w| diam(net) of the shrinking piece.
    void liftStart(int rootType, const Mat &level, std::span<const int> rootNet)
    {
        m_weights.assign(m_pieces.types.size(), Mat());
        Mat net(Eigen::Index(rootNet.size()), 3);
        for (std::size_t i = 0; i < rootNet.size(); ++i)
            net.row(Eigen::Index(i)) = level.row(rootNet[i]);
        std::vector<std::pair<int, Mat>> queue;
        m_weights[std::size_t(rootType)] = leastNormWeightsOfRows(net, m_start.points.vertices);
        queue.emplace_back(rootType, std::move(net));
        for (std::size_t q = 0; q < queue.size(); ++q) {
            const MeshPieceType &t = m_pieces.types[std::size_t(queue[q].first)];
            for (const MeshPieceType::Child &child : t.children) {
                if (m_weights[std::size_t(child.type)].size() > 0)
                    continue;
                Mat next = child.S * queue[q].second;
                m_weights[std::size_t(child.type)] =
                    leastNormWeightsOfRows(next, m_start.points.vertices);
                queue.emplace_back(child.type, std::move(next));
            }
        }
    }

    void descend(int type, int level, int depth)
    {
        const MeshPieceType &t = m_pieces.types[std::size_t(type)];
        if (t.hole)
            return;
        const double *net = m_nets[std::size_t(level)].data();
        if (depth == 0) {
            emit(t, type, net, level);
            return;
        }
        const bool limitsNext = depth == 1 && m_start.kind == MeshStart::Kind::VertexLimits;
        for (std::size_t c = 0; c < t.children.size(); ++c) {
            if ((++m_steps & 255) == 0 && m_control.cancel && m_control.cancel->load()) {
                m_cancelled = true;
                return;
            }
            const MeshPieceType::Child &child = t.children[c];
            m_address[std::size_t(level)] = std::uint8_t(c);
            if (limitsNext) {
                child.leaf.apply(net, m_out.data());
                emitFaces(m_pieces.types[std::size_t(child.type)], level + 1);
            } else {
                child.rows.apply(net, m_nets[std::size_t(level) + 1].data());
                descend(child.type, level + 1, depth - 1);
            }
            if (m_cancelled)
                return;
        }
    }

    void emit(const MeshPieceType &t, int type, const double *net, int level)
    {
        switch (m_start.kind) {
        case MeshStart::Kind::Points: {
            const Mat &w = m_weights[std::size_t(type)];
            m_points.resize(w.rows(), 3);
            for (Eigen::Index r = 0; r < w.rows(); ++r)
                for (int k = 0; k < 3; ++k) {
                    double x = 0;
                    for (Eigen::Index j = 0; j < w.cols(); ++j)
                        x += w(r, j) * net[3 * j + k];
                    m_points(r, k) = x;
                }
            consume(m_points, m_start.points.kind, level);
            return;
        }
        case MeshStart::Kind::VertexLimits:
            t.limitRows.apply(net, m_out.data());
            break;
        case MeshStart::Kind::ControlPoints:
            for (std::size_t i = 0; i < t.corners.size(); ++i)
                for (int k = 0; k < 3; ++k)
                    m_out[3 * i + std::size_t(k)] = net[3 * t.corners[i] + k];
            break;
        }
        emitFaces(t, level);
    }

    // The piece's faces as polygons of their corners in m_out (limits, or the corners): drawn
    // as shaded faces, and as points the vertices of the refined mesh.
    void emitFaces(const MeshPieceType &t, int level)
    {
        for (const std::vector<int> &face : t.faces) {
            if (m_face.rows() != Eigen::Index(face.size()))
                m_face.resize(Eigen::Index(face.size()), 3);
            for (std::size_t i = 0; i < face.size(); ++i)
                for (int k = 0; k < 3; ++k)
                    m_face(Eigen::Index(i), k) = m_out[3 * std::size_t(face[i]) + std::size_t(k)];
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
    int m_maxNet = 0;
    std::vector<std::vector<double>> m_nets;
    std::vector<double> m_out;
    std::vector<Mat> m_weights;  // per type (Points)
    std::vector<std::uint8_t> m_address, m_levelAddress;
    Mat m_face, m_points;
    std::uint64_t m_steps = 0, m_images = 0;
    bool m_rootIsVertex = false;
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
    if (t.hole)
        return 0.0;
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
        // The input's topology, or its sheets' when it is non-manifold (MeshSheets.h).
        const Mesh input{Mat::Zero(pieces.inputVertexCount, 3), pieces.inputFaces,
                         pieces.inputTags};
        const std::optional<ManifoldSheets> sheets = manifoldSheets(input);
        const Mesh &drawn = sheets ? sheets->mesh : input;
        MeshTopology t(int(drawn.vertices.rows()), drawn.faces);
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
    Mesh input{inputVertices, pieces.inputFaces, pieces.inputTags};
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
            walker.root(pieces.roots[std::size_t(r)], level, pieceDepth);
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
