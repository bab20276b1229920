#include "core/mesh/MeshPieces.h"

#include "core/Messages.h"

#include <algorithm>
#include <climits>
#include <map>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

namespace awb {

namespace {

constexpr int kMaxValence = 64;
constexpr int kMaxTypes = 4096;
constexpr int kMaxSteps = 3;

// A piece in a topology: a face from one of its corners, or a vertex from one of its edges
// (the edge is ignored on the boundary, where the ring's first edge is the frame).
struct Seed {
    bool vertex = false;
    int id = 0;
    int start = 0;
};

int cornerOf(const std::vector<int> &loop, int v)
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
};

Walk walk(const MeshTopology &t, const Seed &seed)
{
    Walk w;
    std::unordered_map<int, int> local;
    std::unordered_set<int> region;
    const auto add = [&](int x) {
        const auto [it, added] = local.emplace(x, int(w.order.size()));
        if (added)
            w.order.push_back(x);
        return it->second;
    };
    const auto addFace = [&](int g, int corner) {
        region.insert(g);
        const auto &loop = t.face(g);
        const int m = int(loop.size());
        std::vector<int> ids;
        w.key.push_back(m);
        for (int i = 0; i < m; ++i) {
            ids.push_back(add(loop[std::size_t((corner + i) % m)]));
            w.key.push_back(ids.back());
        }
        w.faces.push_back(std::move(ids));
    };
    w.key.push_back(seed.vertex ? 1 : 0);
    if (seed.vertex) {
        const auto &ring = t.ring(seed.id);
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
        const auto &ring = t.ring(u);
        const int F = int(ring.faces.size());
        int s = 0;
        if (!ring.boundary) {
            int best = INT_MAX;
            for (int k = 0; k < int(ring.edges.size()); ++k) {
                const auto it = local.find(t.otherEnd(ring.edges[std::size_t(k)], u));
                if (it != local.end() && it->second < best) {
                    best = it->second;
                    s = k;
                }
            }
        }
        for (int i = 0; i < F; ++i) {
            const int g = ring.faces[std::size_t((s + i) % F)];
            if (!region.count(g))
                addFace(g, cornerOf(t.face(g), u));
        }
    }
    w.key.push_back(-1);
    for (int c = 0; c < w.coreCount; ++c)
        w.key.push_back(t.onBoundary(w.order[std::size_t(c)]) ? 1 : 0);
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

bool irregular(const MeshTopology &t, int v, MeshScheme scheme)
{
    const int n = t.valence(v), inner = regularValence(scheme);
    return n > 0 && n != (t.onBoundary(v) ? inner / 2 + 1 : inner);
}

// No face with two irregular corners, and only quads (Catmull-Clark).
bool isolated(const MeshTopology &t, MeshScheme scheme)
{
    for (int f = 0; f < t.faceCount(); ++f) {
        const auto &loop = t.face(f);
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
        Walk w = walk(t, seed);
        *net = w.order;
        if (const auto it = m_byKey.find(w.key); it != m_byKey.end())
            return it->second;
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
        m_pending.push_back({id, std::move(w.faces)});
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
    };

    // The limit stencils and the maps of a new type, from its neighbourhood refined once.
    void complete(const Pending &p)
    {
        const int m = types[std::size_t(p.type)].netSize;
        const bool vertex = types[std::size_t(p.type)].kind == MeshPieceType::Kind::Vertex;
        const int coreCount = int(types[std::size_t(p.type)].corners.size());
        const Split s0 = splitFans(m, p.faces);
        const MeshTopology t(int(s0.copyOf.size()), s0.faces);
        const std::vector<MeshStencil> limit = limitStencils(t, m_scheme);
        Mat limits = Mat::Zero(coreCount, m);
        for (int c = 0; c < coreCount; ++c)
            for (const auto &[q, w] : limit[std::size_t(c)])
                limits(c, s0.copyOf[std::size_t(q)]) += w;

        const Refinement r = refineTopology(t, m_scheme);
        const Split s1 = splitFans(int(r.stencils.size()), r.faces);
        const MeshTopology t1(int(s1.copyOf.size()), s1.faces);
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
        for (const Seed &seed : seeds) {
            std::vector<int> net;
            MeshPieceType::Child child;
            child.type = typeOf(t1, seed, &net);
            child.S = Mat::Zero(Eigen::Index(net.size()), m);
            for (std::size_t i = 0; i < net.size(); ++i)
                for (const auto &[q, w] : r.stencils[std::size_t(s1.copyOf[std::size_t(net[i])])])
                    child.S(Eigen::Index(i), s0.copyOf[std::size_t(q)]) += w;
            children.push_back(std::move(child));
        }
        MeshPieceType &type = types[std::size_t(p.type)];
        type.limits = std::move(limits);
        type.children = std::move(children);
    }

    MeshScheme m_scheme;
    std::map<std::vector<int>, int> m_byKey;
    std::vector<Pending> m_pending;
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

MeshPieces buildMeshPieces(const Mesh &mesh, MeshScheme scheme)
{
    MeshTopology t = checkMesh(mesh, scheme);
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
    out.isolation.resize(std::size_t(t.vertexCount()));
    out.origin.resize(std::size_t(t.vertexCount()));
    for (int v = 0; v < t.vertexCount(); ++v) {
        out.isolation[std::size_t(v)] = {{v, 1.0}};
        out.origin[std::size_t(v)] = v;
    }
    std::vector<std::vector<int>> faces = mesh.faces;
    while (!isolated(t, scheme)) {
        if (out.steps == kMaxSteps)  // not reached: two steps isolate every vertex
            throw InputError(coreTranslate("awb::mesh", "the irregular vertices do not separate"));
        const Refinement r = refineTopology(t, scheme);
        const int nv = t.vertexCount(), ne = t.edgeCount();
        std::vector<MeshStencil> isolation;
        std::vector<int> origin;
        for (std::size_t p = 0; p < r.stencils.size(); ++p) {
            isolation.push_back(composeStencils(r.stencils[p], out.isolation));
            const int id = int(p);
            origin.push_back(id < nv                                    ? out.origin[p]
                             : out.steps == 0 && id >= nv + ne          ? -1 - (id - nv - ne)
                                                                        : MeshPieces::kNewPoint);
        }
        out.isolation = std::move(isolation);
        out.origin = std::move(origin);
        faces = r.faces;
        t = MeshTopology(int(out.isolation.size()), faces);
        ++out.steps;
    }
    out.isolatedFaces = faces;

    TypeBuilder builder(scheme);
    for (int f = 0; f < t.faceCount(); ++f) {
        bool regular = true;
        for (int v : t.face(f))
            regular = regular && !irregular(t, v, scheme);
        if (!regular)
            continue;
        MeshPieceRoot root;
        root.face = f;
        root.type = builder.typeOf(t, {false, f, 0}, &root.net);
        out.roots.push_back(std::move(root));
    }
    for (int v = 0; v < t.vertexCount(); ++v) {
        if (!irregular(t, v, scheme))
            continue;
        MeshPieceRoot root;
        root.vertex = v;
        root.type = builder.typeOf(t, {true, v, t.ring(v).edges.front()}, &root.net);
        out.roots.push_back(std::move(root));
    }
    builder.run();
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

Mat isolatedPositions(const MeshPieces &pieces, const Mat &inputVertices)
{
    return applyStencils(pieces.isolation, inputVertices);
}

int settledType(const MeshPieces &pieces, int type)
{
    for (int step = 0; step < 8; ++step) {
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
