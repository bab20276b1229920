#include "core/mesh/MeshRefine.h"

#include "core/Messages.h"
#include "core/mesh/MeshRules.h"

#include <algorithm>
#include <optional>

namespace awb {

namespace {

using namespace meshrules;

// Sums weights of the same point (sorted by point).
MeshStencil merged(MeshStencil s)
{
    std::sort(s.begin(), s.end());
    MeshStencil out;
    for (const auto &[p, w] : s) {
        if (!out.empty() && out.back().first == p)
            out.back().second += w;
        else
            out.emplace_back(p, w);
    }
    return out;
}

void addFaceCentroid(MeshStencil &s, const std::vector<int> &face, double weight)
{
    for (int v : face)
        s.emplace_back(v, weight / double(face.size()));
}

// The two boundary neighbours of a boundary vertex.
std::pair<int, int> boundaryNeighbours(const MeshTopology &t, int v)
{
    const auto &ring = t.ring(v);
    return {t.otherEnd(ring.edges.front(), v), t.otherEnd(ring.edges.back(), v)};
}

// The vertex point of a vertex of no face (itself) or on the boundary (the crease rule), the
// same in both schemes; nullopt inside.
std::optional<MeshStencil> creaseVertex(const MeshTopology &t, int v)
{
    const auto &ring = t.ring(v);
    if (ring.edges.empty())
        return MeshStencil{{v, 1.0}};
    if (!ring.boundary)
        return std::nullopt;
    const auto [a, b] = boundaryNeighbours(t, v);
    return merged({{v, kCreaseSelf}, {a, kCreaseNeighbour}, {b, kCreaseNeighbour}});
}

MeshStencil catmarkVertex(const MeshTopology &t, int v)
{
    if (auto s = creaseVertex(t, v))
        return *s;
    const auto &ring = t.ring(v);
    const int n = int(ring.edges.size());
    MeshStencil s{{v, catmarkVertexSelf(n)}};
    for (int e : ring.edges)
        s.emplace_back(t.otherEnd(e, v), catmarkVertexRing(n));
    for (int f : ring.faces)
        addFaceCentroid(s, t.face(f), catmarkVertexRing(n));
    return merged(std::move(s));
}

MeshStencil loopVertex(const MeshTopology &t, int v)
{
    if (auto s = creaseVertex(t, v))
        return *s;
    const auto &ring = t.ring(v);
    const int n = int(ring.edges.size());
    const double beta = loopBeta(n);
    MeshStencil s{{v, 1.0 - n * beta}};
    for (int e : ring.edges)
        s.emplace_back(t.otherEnd(e, v), beta);
    return merged(std::move(s));
}

// The corner of triangle f opposite edge e.
int opposite(const MeshTopology &t, int f, int e)
{
    const auto &edge = t.edge(e);
    for (int c : t.face(f))
        if (c != edge.v[0] && c != edge.v[1])
            return c;
    return edge.v[0];
}

MeshStencil edgePoint(const MeshTopology &t, int e, MeshScheme scheme)
{
    const auto &edge = t.edge(e);
    if (edge.boundary())
        return merged({{edge.v[0], 0.5}, {edge.v[1], 0.5}});
    if (scheme == MeshScheme::Loop)
        return merged({{edge.v[0], 0.375},
                       {edge.v[1], 0.375},
                       {opposite(t, edge.face[0], e), 0.125},
                       {opposite(t, edge.face[1], e), 0.125}});
    MeshStencil s{{edge.v[0], 0.25}, {edge.v[1], 0.25}};
    addFaceCentroid(s, t.face(edge.face[0]), 0.25);
    addFaceCentroid(s, t.face(edge.face[1]), 0.25);
    return merged(std::move(s));
}

// The limit stencil of v, when every face at v is a quad (Catmull-Clark) or v is on the
// boundary, of no face, or in a Loop mesh; nullopt otherwise.
std::optional<MeshStencil> directLimit(const MeshTopology &t, int v, MeshScheme scheme)
{
    const auto &ring = t.ring(v);
    if (ring.edges.empty())
        return MeshStencil{{v, 1.0}};
    if (ring.boundary) {
        const auto [a, b] = boundaryNeighbours(t, v);
        return merged(
            {{v, kCreaseLimitSelf}, {a, kCreaseLimitNeighbour}, {b, kCreaseLimitNeighbour}});
    }
    const int n = int(ring.edges.size());
    if (scheme == MeshScheme::Loop) {
        const double chi = loopLimitNeighbour(n);
        MeshStencil s{{v, 1.0 - n * chi}};
        for (int e : ring.edges)
            s.emplace_back(t.otherEnd(e, v), chi);
        return merged(std::move(s));
    }
    MeshStencil s{{v, catmarkLimitSelf(n)}};
    for (int e : ring.edges)
        s.emplace_back(t.otherEnd(e, v), catmarkLimitEdge(n));
    for (int f : ring.faces) {
        const auto &face = t.face(f);
        if (face.size() != 4)
            return std::nullopt;
        const int corner = int(std::find(face.begin(), face.end(), v) - face.begin());
        s.emplace_back(face[std::size_t(corner + 2) % 4], catmarkLimitDiagonal(n));
    }
    return merged(std::move(s));
}

} // namespace

MeshStencil composeStencils(const MeshStencil &outer, const std::vector<MeshStencil> &inner)
{
    MeshStencil s;
    for (const auto &[p, w] : outer)
        for (const auto &[q, u] : inner[std::size_t(p)])
            s.emplace_back(q, w * u);
    return merged(std::move(s));
}

Refinement refineTopology(const MeshTopology &t, MeshScheme scheme)
{
    Refinement r;
    const int nv = t.vertexCount(), ne = t.edgeCount(), nf = t.faceCount();
    if (scheme == MeshScheme::Loop)
        for (int f = 0; f < nf; ++f)
            if (t.face(f).size() != 3)
                throw InputError(formatMessage(
                    coreTranslate("awb::mesh",
                                  "face %1 has %2 vertices; Loop subdivision takes triangles only"),
                    f, t.face(f).size()));
    r.stencils.reserve(std::size_t(nv + ne + (scheme == MeshScheme::CatmullClark ? nf : 0)));
    for (int v = 0; v < nv; ++v)
        r.stencils.push_back(scheme == MeshScheme::Loop ? loopVertex(t, v) : catmarkVertex(t, v));
    for (int e = 0; e < ne; ++e)
        r.stencils.push_back(edgePoint(t, e, scheme));
    const auto edgeChild = [nv](int e) { return nv + e; };
    if (scheme == MeshScheme::CatmullClark) {
        for (int f = 0; f < nf; ++f) {
            MeshStencil s;
            addFaceCentroid(s, t.face(f), 1.0);
            r.stencils.push_back(merged(std::move(s)));
        }
        for (int f = 0; f < nf; ++f) {
            const auto &face = t.face(f);
            const auto &edges = t.faceEdges(f);
            const std::size_t k = face.size();
            for (std::size_t i = 0; i < k; ++i)
                r.faces.push_back({face[i], edgeChild(edges[i]), nv + ne + f,
                                   edgeChild(edges[(i + k - 1) % k])});
        }
    } else {
        for (int f = 0; f < nf; ++f) {
            const auto &c = t.face(f);
            const auto &e = t.faceEdges(f);
            const int e0 = edgeChild(e[0]), e1 = edgeChild(e[1]), e2 = edgeChild(e[2]);
            r.faces.push_back({c[0], e0, e2});
            r.faces.push_back({c[1], e1, e0});
            r.faces.push_back({c[2], e2, e1});
            r.faces.push_back({e0, e1, e2});
        }
    }
    return r;
}

Mat applyStencils(const std::vector<MeshStencil> &stencils, const Mat &data)
{
    Mat out = Mat::Zero(Eigen::Index(stencils.size()), data.cols());
    for (std::size_t i = 0; i < stencils.size(); ++i)
        for (const auto &[p, w] : stencils[i])
            out.row(Eigen::Index(i)) += w * data.row(p);
    return out;
}

Mesh refineMesh(const Mesh &mesh, MeshScheme scheme, int steps)
{
    MeshTopology t = checkMesh(mesh, scheme);
    Mesh m = mesh;
    for (int k = 0; k < steps; ++k) {
        if (k > 0)
            t = MeshTopology(int(m.vertices.rows()), m.faces);
        Refinement r = refineTopology(t, scheme);
        m.vertices = applyStencils(r.stencils, m.vertices);
        m.faces = std::move(r.faces);
    }
    return m;
}

std::vector<MeshStencil> limitStencils(const MeshTopology &t, MeshScheme scheme)
{
    std::vector<MeshStencil> out(std::size_t(t.vertexCount()));
    std::vector<int> later;
    for (int v = 0; v < t.vertexCount(); ++v) {
        if (auto s = directLimit(t, v, scheme))
            out[std::size_t(v)] = std::move(*s);
        else
            later.push_back(v);
    }
    if (later.empty())
        return out;
    // After one step every face at a vertex point is a quad; the vertex keeps its number.
    const Refinement r = refineTopology(t, scheme);
    const MeshTopology child(int(r.stencils.size()), r.faces);
    for (int v : later)
        out[std::size_t(v)] = composeStencils(*directLimit(child, v, scheme), r.stencils);
    return out;
}

Mat limitPositions(const Mesh &mesh, MeshScheme scheme)
{
    const MeshTopology t = checkMesh(mesh, scheme);
    return applyStencils(limitStencils(t, scheme), mesh.vertices);
}

} // namespace awb
