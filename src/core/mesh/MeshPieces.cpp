#include "core/mesh/MeshPieces.h"

#include "core/Messages.h"
#include "core/mesh/MeshSheets.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <functional>
#include <map>
#include <numeric>
#include <unordered_map>

namespace awb {

namespace {

constexpr int kMaxValence = 512;
constexpr int kMaxTypes = 4096;
constexpr int kMaxSteps = 3;

// A piece in a topology: a face from one of its corners, or a vertex from one of its edges
// (the edge is ignored on the boundary, where the ring's first edge is the frame).
struct Seed {
    bool vertex = false;
    int id = 0;
    int start = 0;
};

int cornerOf(std::span<const int> loop, int v)
{
    return int(std::find(loop.begin(), loop.end(), v) - loop.begin());
}

// The canonical walk of a piece: its faces from the seed (a vertex's counter-clockwise from its
// frame edge), then, for each of their corners in the order met (the core), the faces around
// it counter-clockwise from its edge to the earliest vertex met (on the boundary, from its
// boundary edge). The vertices in the order met are the net; the faces in local numbers and
// the core's boundary flags are the key: two pieces with the same key have the same
// neighbourhood, hence the same maps.
struct Walk {
    std::vector<int> order;
    std::vector<std::vector<int>> faces;
    int coreCount = 0;
    std::vector<int> key;
    // The sharp features met, in the walk's numbers (MeshTopology::sharpness's layout).
    MeshSharpness sharpness;
    bool semiSharp = false;  // a feature that is still semi-sharp: the piece is in its prelude
};

// A sharpness in a key: its float's bits (exact, as the rules use it).
int keyOf(float s)
{
    int bits = 0;
    static_assert(sizeof bits == sizeof s);
    std::memcpy(&bits, &s, sizeof bits);
    return bits;
}

// The walk's marks on the vertices and faces, reused from walk to walk (a mesh of a million
// faces has as many pieces; a hash per walk was a quarter of their time): a mark is valid when
// its stamp is the walk's.
struct WalkMarks {
    // A vertex's stamp and its number in the walk side by side: one scattered read, not two.
    struct VertexMark {
        unsigned stamp = 0;
        int local = 0;
    };
    std::vector<VertexMark> vertex;
    std::vector<unsigned> faceStamp;
    unsigned stamp = 0;

    // Stamps only grow, so the marks of earlier walks, on any topology, are never valid.
    void begin(const MeshTopology &t)
    {
        if (stamp == UINT_MAX) {
            std::fill(vertex.begin(), vertex.end(), VertexMark{});
            std::fill(faceStamp.begin(), faceStamp.end(), 0u);
            stamp = 0;
        }
        if (vertex.size() < std::size_t(t.vertexCount()))
            vertex.resize(std::size_t(t.vertexCount()));
        if (faceStamp.size() < std::size_t(t.faceCount()))
            faceStamp.resize(std::size_t(t.faceCount()), 0u);
        ++stamp;
    }
    // The walk's number of vertex x, or -1.
    int find(int x) const
    {
        const VertexMark &m = vertex[std::size_t(x)];
        return m.stamp == stamp ? m.local : -1;
    }
};

// Without `faces`, only the net and the key (enough to find a known type; a mesh of a million
// faces has as many pieces and a few types): no list per face.
// Into w (its vectors reused: a million walks, a few allocations).
void walk(const MeshTopology &t, const Seed &seed, bool faces, Walk &w)
{
    w.order.clear();
    w.faces.clear();
    w.coreCount = 0;
    w.key.clear();
    w.sharpness = {};
    w.semiSharp = false;
    thread_local WalkMarks marks;
    marks.begin(t);
    const auto add = [&](int x) {
        WalkMarks::VertexMark &m = marks.vertex[std::size_t(x)];
        if (m.stamp != marks.stamp) {
            m = {marks.stamp, int(w.order.size())};
            w.order.push_back(x);
        }
        return m.local;
    };
    const bool sharp = t.hasSharpness(), holes = t.hasHoles();
    const auto addFace = [&](int g, int corner) {
        marks.faceStamp[std::size_t(g)] = marks.stamp;
        const auto loop = t.face(g);
        const int m = int(loop.size());
        w.key.push_back(m);
        for (int i = 0; i < m; ++i)
            w.key.push_back(add(loop[std::size_t((corner + i) % m)]));
        if (faces)
            w.faces.emplace_back(w.key.end() - m, w.key.end());
        if (sharp) {
            std::vector<float> edges;
            for (int i = 0; i < m; ++i) {
                const int e = t.faceEdges(g)[std::size_t((corner + i) % m)];
                edges.push_back(t.edge(e).boundary() ? kSharpnessSmooth : t.edgeSharpness(e));
                w.key.push_back(keyOf(edges.back()));
                w.semiSharp = w.semiSharp || crease::isSemiSharp(edges.back());
            }
            w.sharpness.faceEdges.push_back(std::move(edges));
        }
        if (holes) {
            w.sharpness.holes.push_back(t.hole(g) ? 1 : 0);
            w.key.push_back(t.hole(g) ? 1 : 0);
        }
    };
    w.key.push_back(seed.vertex ? 1 : 0);
    if (seed.vertex) {
        const auto ring = t.ring(seed.id);
        const int F = int(ring.faces.size());
        int s = 0;
        if (!ring.boundary)
            s = std::max(0, int(std::find(ring.edges.begin(), ring.edges.end(), seed.start)
                                - ring.edges.begin()) % std::max(F, 1));
        w.key.push_back(F);
        for (int i = 0; i < F; ++i) {
            const int g = ring.faces[std::size_t((s + i) % F)];
            addFace(g, cornerOf(t.face(g), seed.id));
        }
    } else {
        w.key.push_back(1);
        addFace(seed.id, seed.start);
    }
    w.coreCount = int(w.order.size());
    for (int c = 0; c < w.coreCount; ++c) {
        const int u = w.order[std::size_t(c)];
        const auto ring = t.ring(u);
        const int F = int(ring.faces.size());
        int s = 0;
        if (!ring.boundary) {
            // Edge k's other end is u's successor in face k (... -> u -> b ...: the face lies
            // between edges (u, b) and (u, a)): read from the face loops the walk reads anyway,
            // not from the edges (a scattered read per edge, a fifth of the walks).
            int best = INT_MAX;
            for (int k = 0; k < F; ++k) {
                const auto loop = t.face(ring.faces[std::size_t(k)]);
                const int next = cornerOf(loop, u) + 1;
                const int at = marks.find(loop[std::size_t(next == int(loop.size()) ? 0 : next)]);
                if (at >= 0 && at < best) {
                    best = at;
                    s = k;
                }
            }
        }
        for (int i = 0; i < F; ++i) {
            const int g = ring.faces[std::size_t((s + i) % F)];
            if (marks.faceStamp[std::size_t(g)] != marks.stamp)
                addFace(g, cornerOf(t.face(g), u));
        }
    }
    w.key.push_back(-1);
    for (int c = 0; c < w.coreCount; ++c)
        w.key.push_back(t.onBoundary(w.order[std::size_t(c)]) ? 1 : 0);
    w.sharpness.options = t.options();
    if (sharp) {
        w.key.push_back(-2);
        for (int x : w.order) {
            w.sharpness.vertices.push_back(t.vertexSharpness(x));
            w.key.push_back(keyOf(w.sharpness.vertices.back()));
            w.semiSharp = w.semiSharp || crease::isSemiSharp(w.sharpness.vertices.back());
        }
    }
}

Walk walk(const MeshTopology &t, const Seed &seed)
{
    Walk w;
    walk(t, seed, true, w);
    return w;
}

// A neighbourhood cut out of a mesh may have a vertex on its rim whose faces there form
// separate fans (the rest of the mesh joined them). Each further fan gets a copy of the vertex
// so that the cut-out is a manifold; copyOf[copy] names the original. The rim's rules are never
// used: only the core's, whose rings are whole.
struct Split {
    std::vector<std::vector<int>> faces;
    std::vector<int> copyOf;
};

std::uint64_t halfKey(int a, int b)
{
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

Split splitFans(int n, std::vector<std::vector<int>> faces)
{
    Split s;
    s.copyOf.resize(std::size_t(n));
    std::iota(s.copyOf.begin(), s.copyOf.end(), 0);
    std::vector<std::vector<int>> facesAt(static_cast<std::size_t>(n));
    std::unordered_map<std::uint64_t, int> half;  // a -> b : face
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto &loop = faces[f];
        for (std::size_t k = 0; k < loop.size(); ++k) {
            facesAt[std::size_t(loop[k])].push_back(int(f));
            half[halfKey(loop[k], loop[(k + 1) % loop.size()])] = int(f);
        }
    }
    for (int v = 0; v < n; ++v) {
        const auto &at = facesAt[std::size_t(v)];
        if (at.size() < 2)
            continue;
        std::unordered_map<int, int> parent;
        for (int f : at)
            parent[f] = f;
        const auto find = [&](int f) {
            while (parent[f] != f)
                f = parent[f] = parent[parent[f]];
            return f;
        };
        for (int f : at) {
            const auto &loop = faces[std::size_t(f)];
            const int b = loop[std::size_t(cornerOf(loop, v) + 1) % loop.size()];
            if (const auto it = half.find(halfKey(b, v)); it != half.end())
                parent[find(f)] = find(it->second);
        }
        std::unordered_map<int, int> idOf;  // component root -> vertex id
        idOf[find(at.front())] = v;
        for (int f : at) {
            const int root = find(f);
            auto it = idOf.find(root);
            if (it == idOf.end()) {
                it = idOf.emplace(root, int(s.copyOf.size())).first;
                s.copyOf.push_back(v);
            }
            if (it->second != v) {
                auto &loop = faces[std::size_t(f)];
                loop[std::size_t(cornerOf(loop, v))] = it->second;
            }
        }
    }
    s.faces = std::move(faces);
    return s;
}

// A vertex whose neighbourhood is not that of a regular face piece: an interior vertex of
// valence != 4 (Catmull-Clark) or 6 (Loop), a boundary vertex of valence != 3 or 4 (a corner of
// one face included, unless it is infinitely sharp: OpenSubdiv's regular corner patch), and
// every vertex on a sharp feature other than a regular crease (OpenSubdiv's: two sharp edges
// opposite each other at a regular vertex).
bool irregular(const MeshTopology &t, int v, MeshScheme scheme)
{
    const int n = t.valence(v), inner = regularValence(scheme);
    if (n == 0)
        return false;
    const auto ring = t.ring(v);
    if (!t.hasSharpness())
        return n != (ring.boundary ? inner / 2 + 1 : inner);
    if (ring.boundary && ring.faces.size() == 1)  // regular only as an infinitely sharp corner
        return !crease::isInfinite(t.vertexSharpness(v)) || t.sharpEdgeCount(v) != 2;
    const VertexRule rule = t.rule(v);
    if (ring.boundary)
        return rule != VertexRule::Crease || n != inner / 2 + 1;
    if (n != inner)
        return true;
    if (rule == VertexRule::Smooth)
        return false;
    if (rule != VertexRule::Crease)
        return true;
    const auto sharp = [&](int k) { return crease::isSharp(t.edgeSharpness(ring.edges[std::size_t(k)])); };
    const int half = inner / 2;
    for (int k = 0; k < half; ++k)
        if (sharp(k) != sharp(k + half))
            return true;
    return false;
}

// No face with two irregular corners, and only quads (Catmull-Clark).
bool isolated(const MeshTopology &t, MeshScheme scheme)
{
    for (int f = 0; f < t.faceCount(); ++f) {
        const auto loop = t.face(f);
        if (scheme == MeshScheme::CatmullClark && loop.size() != 4)
            return false;
        int count = 0;
        for (int v : loop)
            count += irregular(t, v, scheme) ? 1 : 0;
        if (count > 1)
            return false;
    }
    return true;
}

class TypeBuilder {
public:
    explicit TypeBuilder(MeshScheme scheme) : m_scheme(scheme) {}

    // The type of the piece `seed` of `t` (new types are completed by run()); *net its net.
    int typeOf(const MeshTopology &t, const Seed &seed, std::vector<int> *net)
    {
        thread_local Walk known;
        walk(t, seed, false, known);
        if (const auto it = m_byKey.find(known.key); it != m_byKey.end()) {
            net->assign(known.order.begin(), known.order.end());
            return it->second;
        }
        Walk w = walk(t, seed);
        *net = w.order;
        if (int(types.size()) >= kMaxTypes)
            throw InputError(formatMessage(
                coreTranslate("awb::mesh", "the mesh has more than %1 kinds of neighbourhood"),
                kMaxTypes));
        MeshPieceType type;
        type.kind = seed.vertex ? MeshPieceType::Kind::Vertex : MeshPieceType::Kind::Face;
        type.netSize = int(w.order.size());
        if (seed.vertex) {
            type.valence = t.valence(seed.id);
            type.boundary = t.onBoundary(seed.id);
            type.rule = t.rule(seed.id);
            type.ringSharpness = t.ringSharpness(seed.id);
            type.vertexSharpness = t.vertexSharpness(seed.id);
        } else {
            for (int c = 0; c < w.coreCount; ++c)
                type.boundary = type.boundary || t.onBoundary(w.order[std::size_t(c)]);
        }
        type.faces.assign(w.faces.begin(),
                          w.faces.begin() + (seed.vertex ? t.ring(seed.id).faces.size() : 1));
        type.corners.resize(std::size_t(w.coreCount));
        std::iota(type.corners.begin(), type.corners.end(), 0);
        const int id = int(types.size());
        types.push_back(std::move(type));
        m_byKey.emplace(std::move(w.key), id);
        if (w.semiSharp)
            m_prelude.push_back(id);
        m_pending.push_back({id, std::move(w.faces), std::move(w.sharpness)});
        return id;
    }

    void run()
    {
        while (!m_pending.empty()) {
            Pending p = std::move(m_pending.back());
            m_pending.pop_back();
            complete(p);
        }
    }

    std::vector<MeshPieceType> types;

private:
    struct Pending {
        int type;
        std::vector<std::vector<int>> faces;  // the neighbourhood in the type's local numbers
        MeshSharpness sharpness;              // its sharp features, in the same numbers
    };

    // A topology of split faces with the sharp features `s` (vertices in the unsplit numbers).
    static MeshTopology splitTopology(const Split &split, MeshSharpness s)
    {
        MeshTopology t(int(split.copyOf.size()), split.faces);
        if (!s.vertices.empty()) {
            std::vector<float> vertices(split.copyOf.size());
            for (std::size_t i = 0; i < vertices.size(); ++i) {
                const auto from = std::size_t(split.copyOf[i]);  // beyond: new points, smooth
                vertices[i] = from < s.vertices.size() ? s.vertices[from] : kSharpnessSmooth;
            }
            s.vertices = std::move(vertices);
        }
        t.applySharpness(s);
        return t;
    }

    // The limit stencils and the maps of a new type, from its neighbourhood refined once.
    void complete(const Pending &p)
    {
        const int m = types[std::size_t(p.type)].netSize;
        const bool vertex = types[std::size_t(p.type)].kind == MeshPieceType::Kind::Vertex;
        const int coreCount = int(types[std::size_t(p.type)].corners.size());
        const Split s0 = splitFans(m, p.faces);
        const MeshTopology t = splitTopology(s0, p.sharpness);
        const StencilTable limit = limitStencils(t, m_scheme);
        Mat limits = Mat::Zero(coreCount, m);
        for (int c = 0; c < coreCount; ++c)
            for (const auto &[q, w] : limit[std::size_t(c)])
                limits(c, s0.copyOf[std::size_t(q)]) += w;

        const Refinement r = refineTopology(t, m_scheme);
        const Split s1 = splitFans(int(r.stencils.size()), r.faces.toVectors());
        const MeshTopology t1 = splitTopology(s1, r.sharpness);
        const int nv = t.vertexCount();
        // The first child face of face f in r.faces (refineTopology's order).
        std::vector<int> firstChild(std::size_t(t.faceCount()));
        for (int f = 0, at = 0; f < t.faceCount(); ++f) {
            firstChild[std::size_t(f)] = at;
            at += m_scheme == MeshScheme::Loop ? 4 : int(t.face(f).size());
        }
        std::vector<Seed> seeds;
        const auto faceChildren = [&](int f, int fromCorner) {
            const int k = int(t.face(f).size());
            for (int j = fromCorner; j < k; ++j)
                seeds.push_back({false, firstChild[std::size_t(f)] + j, 0});
            if (m_scheme == MeshScheme::Loop)
                seeds.push_back({false, firstChild[std::size_t(f)] + 3, 0});
        };
        if (vertex) {
            // Local vertex 0 is the vertex; its frame runs to local vertex 1.
            const int frame = t.findEdge(0, 1);
            seeds.push_back({true, 0, t1.findEdge(0, nv + frame)});
            for (int f = 0; f < int(t.ring(0).faces.size()); ++f)
                faceChildren(f, 1);
        } else {
            faceChildren(0, 0);
        }
        std::vector<MeshPieceType::Child> children;
        // Where each corner goes: (child, its corner) with the corner's vertex point.
        std::vector<std::pair<int, int>> cornerChild(std::size_t(coreCount), {-1, -1});
        for (const Seed &seed : seeds) {
            std::vector<int> net;
            MeshPieceType::Child child;
            child.type = typeOf(t1, seed, &net);
            for (std::size_t j = 0; j < net.size(); ++j) {
                const int c = s1.copyOf[std::size_t(net[j])];
                if (c < coreCount && cornerChild[std::size_t(c)].first < 0
                    && j < types[std::size_t(child.type)].corners.size())
                    cornerChild[std::size_t(c)] = {int(children.size()), int(j)};
            }
            child.S = Mat::Zero(Eigen::Index(net.size()), m);
            for (std::size_t i = 0; i < net.size(); ++i)
                for (const auto &[q, w] : r.stencils[std::size_t(s1.copyOf[std::size_t(net[i])])])
                    child.S(Eigen::Index(i), s0.copyOf[std::size_t(q)]) += w;
            children.push_back(std::move(child));
        }
        MeshPieceType &type = types[std::size_t(p.type)];
        type.limits = std::move(limits);
        type.children = std::move(children);
        // A hole draws nothing (its children, holes too, stay for the limits of its corners).
        if (type.kind == MeshPieceType::Kind::Face && t.hole(0)) {
            type.faces.clear();
            type.hole = true;
        } else if (type.kind == MeshPieceType::Kind::Vertex && t.hasHoles()) {
            std::vector<std::vector<int>> kept;
            for (std::size_t f = 0; f < type.faces.size(); ++f)
                if (!t.hole(int(f)))
                    kept.push_back(type.faces[f]);
            type.faces = std::move(kept);
        }
        m_cornerChild[p.type] = std::move(cornerChild);
    }

public:
    // The limit stencils of the types in their prelude (a semi-sharp feature in their net): a
    // corner's limit is its vertex point's limit in the child that holds it, down to the
    // stationary types, whose limits the rules give.
    void preludeLimits()
    {
        std::vector<char> done(types.size(), 1);
        for (int id : m_prelude)
            done[std::size_t(id)] = 0;
        std::function<void(int, int)> settle = [&](int id, int depth) {
            if (done[std::size_t(id)])
                return;
            if (depth > 64)
                throw std::logic_error("mesh pieces: a prelude that does not end");
            MeshPieceType &type = types[std::size_t(id)];
            const auto &where = m_cornerChild.at(id);
            for (std::size_t c = 0; c < where.size(); ++c) {
                const auto [k, j] = where[c];
                if (k < 0)
                    continue;  // not reached: every corner is a child's corner
                const MeshPieceType::Child &child = type.children[std::size_t(k)];
                settle(child.type, depth + 1);
                const MeshPieceType &below = types[std::size_t(child.type)];
                // The child's corner j is its net's place j when j is among its corners.
                if (j < below.limits.rows())
                    type.limits.row(Eigen::Index(c)) = below.limits.row(j) * child.S;
                else
                    type.limits.row(Eigen::Index(c)) = child.S.row(j);  // not reached
            }
            done[std::size_t(id)] = 1;
        };
        for (int id : m_prelude)
            settle(id, 0);
    }

private:

    MeshScheme m_scheme;
    std::map<std::vector<int>, int> m_byKey;
    std::vector<Pending> m_pending;
    std::vector<int> m_prelude;
    std::map<int, std::vector<std::pair<int, int>>> m_cornerChild;
};

} // namespace

SparseRows SparseRows::of(const Mat &m)
{
    SparseRows r;
    r.begin.reserve(std::size_t(m.rows()) + 1);
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
        for (Eigen::Index j = 0; j < m.cols(); ++j)
            if (m(i, j) != 0.0)
                r.entries.emplace_back(int(j), m(i, j));
        r.begin.push_back(int(r.entries.size()));
    }
    return r;
}

namespace {

MeshPieces buildManifoldPieces(const Mesh &mesh, MeshScheme scheme, MeshTopology t)
{
    MeshPieces out;
    out.scheme = scheme;
    out.inputVertexCount = t.vertexCount();
    out.inputFaceCount = t.faceCount();
    out.inputFaces = mesh.faces;
    for (int v = 0; v < t.vertexCount(); ++v) {
        if (t.valence(v) > kMaxValence)
            throw InputError(formatMessage(
                coreTranslate("awb::mesh",
                              "vertex %1 has %2 edges; valences above %3 are not supported"),
                v, t.valence(v), kMaxValence));
        if (t.valence(v) == 0)
            out.loneVertices.push_back(v);
    }
    for (int f = 0; f < t.faceCount(); ++f)
        if (int(t.face(f).size()) > kMaxValence)
            throw InputError(formatMessage(
                coreTranslate("awb::mesh",
                              "face %1 has %2 sides; faces of more than %3 sides are not "
                              "supported"),
                f, t.face(f).size(), kMaxValence));
    out.origin.resize(std::size_t(t.vertexCount()));
    for (int v = 0; v < t.vertexCount(); ++v)
        out.origin[std::size_t(v)] = v;
    out.inputTags = mesh.tags;
    // Chaikin's rule takes a semi-sharp edge's neighbours beyond a piece's net: the semi-sharp
    // features are refined away on the whole mesh first (uniform creasing keeps them in the
    // pieces, whose types then have a prelude).
    const auto chaikinPrelude = [&] {
        return t.options().creaseMethod == CreaseMethod::Chaikin && preludeLevels(t) > 0;
    };
    while (!isolated(t, scheme) || chaikinPrelude()) {
        if (out.steps >= kMaxSteps && !chaikinPrelude())  // not reached: two steps isolate
            throw InputError(coreTranslate("awb::mesh", "the irregular vertices do not separate"));
        if ((long long)t.faceCount() * 4 > kMaxPreludeFaces)
            throw InputError(formatMessage(
                coreTranslate("awb::mesh",
                              "Chaikin's creases last %1 more levels here; the mesh would have "
                              "more than %2 faces (use the uniform crease method)"),
                preludeLevels(t), kMaxPreludeFaces));
        Refinement r = refineTopology(t, scheme);
        const int nv = t.vertexCount(), ne = t.edgeCount();
        std::vector<int> origin;
        origin.reserve(r.stencils.size());
        for (std::size_t p = 0; p < r.stencils.size(); ++p) {
            const int id = int(p);
            origin.push_back(id < nv                                    ? out.origin[p]
                             : out.steps == 0 && id >= nv + ne          ? -1 - (id - nv - ne)
                                                                        : MeshPieces::kNewPoint);
        }
        out.origin = std::move(origin);
        out.isolation.push_back(std::move(r.stencils));
        t = refinedTopology(t, std::move(r));
        ++out.steps;
    }

    // The roots' nets, sized before they are walked (a regular face's 16 or 12 points, an
    // interior vertex's 6n + 1 or 3n + 1): one allocation, where a growing array held its old
    // and its doubled copy at once -- the top of a large mesh's peak.
    const auto regularFace = [&](int f) {
        for (int v : t.face(f))
            if (irregular(t, v, scheme))
                return false;
        return !t.hole(f);
    };
    std::size_t rootCount = 0, netValues = 0;
    for (int f = 0; f < t.faceCount(); ++f)
        if (regularFace(f)) {
            ++rootCount;
            netValues += scheme == MeshScheme::CatmullClark ? 16 : 12;
        }
    for (int v = 0; v < t.vertexCount(); ++v)
        if (irregular(t, v, scheme)) {
            ++rootCount;
            netValues += std::size_t(scheme == MeshScheme::CatmullClark ? 6 : 3) * t.valence(v) + 1;
        }
    out.roots.reserve(rootCount);
    out.rootNets.reserve(rootCount, netValues);

    TypeBuilder builder(scheme);
    std::vector<int> net;
    for (int f = 0; f < t.faceCount(); ++f) {
        if (!regularFace(f))
            continue;
        MeshPieceRoot root;
        root.face = f;
        root.number = int(out.roots.size());
        root.type = builder.typeOf(t, {false, f, 0}, &net);
        out.roots.push_back(root);
        out.rootNets.push_back(net);
    }
    for (int v = 0; v < t.vertexCount(); ++v) {
        if (!irregular(t, v, scheme))
            continue;
        MeshPieceRoot root;
        root.vertex = v;
        root.number = int(out.roots.size());
        root.type = builder.typeOf(t, {true, v, t.ring(v).edges.front()}, &net);
        out.roots.push_back(root);
        out.rootNets.push_back(net);
    }
    out.isolatedFaces = std::move(t).takeFaces();  // t is not used again
    builder.run();
    builder.preludeLimits();
    out.types = std::move(builder.types);
    for (MeshPieceType &type : out.types) {
        type.limitRows = SparseRows::of(type.limits);
        for (MeshPieceType::Child &c : type.children) {
            c.rows = SparseRows::of(c.S);
            c.leaf = SparseRows::of(out.types[std::size_t(c.type)].limits * c.S);
        }
    }
    for (const MeshPieceRoot &root : out.roots)
        ++out.types[std::size_t(root.type)].roots;
    return out;
}

} // namespace

MeshPieces buildMeshPieces(const Mesh &mesh, MeshScheme scheme)
{
    DrawnMesh drawn = drawnMesh(mesh, scheme);
    if (!drawn.sheets)
        return buildManifoldPieces(mesh, scheme, std::move(drawn.topology));
    // The pieces of the sheets, on the input's vertices: a copy is its vertex.
    const std::optional<ManifoldSheets> &sheets = drawn.sheets;
    MeshPieces out = buildManifoldPieces(sheets->mesh, scheme, std::move(drawn.topology));
    const int n = int(mesh.vertices.rows());
    const auto inputVertex = [&](int v) { return v < n ? v : sheets->original[std::size_t(v)]; };
    StencilTable copies;  // each vertex of the sheets from the input's
    const int sheetVertices = int(sheets->mesh.vertices.rows());
    copies.reserve(std::size_t(sheetVertices), std::size_t(sheetVertices));
    for (int v = 0; v < sheetVertices; ++v)
        copies.push_back({{inputVertex(v), 1.0}});
    out.isolation.insert(out.isolation.begin(), std::move(copies));
    for (int &o : out.origin)
        if (o >= n)
            o = inputVertex(o);
    std::erase_if(out.loneVertices, [&](int v) { return v >= n; });
    out.inputVertexCount = n;
    out.inputFaces = mesh.faces;
    out.inputTags = mesh.tags;
    return out;
}

Mat isolatedPositions(const MeshPieces &pieces, const Mat &inputVertices)
{
    Mat level = inputVertices;
    for (const StencilTable &stencils : pieces.isolation)
        level = applyStencils(stencils, level);
    return level;
}

int settledType(const MeshPieces &pieces, int type)
{
    for (int step = 0; step < 16; ++step) {
        const MeshPieceType &t = pieces.types[std::size_t(type)];
        if (t.kind != MeshPieceType::Kind::Vertex || t.children.empty())
            return -1;
        if (t.children.front().type == type)
            return type;
        type = t.children.front().type;
    }
    return -1;
}

} // namespace awb
