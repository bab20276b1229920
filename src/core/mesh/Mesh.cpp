#include "core/mesh/Mesh.h"

#include "core/Messages.h"
#include "core/mesh/MeshHalfEdges.h"

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

// The problems of one phase of the checks, all of them counted, the first few kept: a mesh
// is refused with every fault of that phase at once, not one per run (issue 44).
class Problems {
public:
    void add(std::string message)
    {
        ++m_count;
        if (m_kept.size() < 5)
            m_kept.push_back(std::move(message));
    }
    // Throws InputError when there is any.
    void raise() const
    {
        if (m_count == 0)
            return;
        if (m_count == 1)
            throw InputError(m_kept.front());
        std::string list;
        for (const std::string &m : m_kept)
            list += (list.empty() ? "" : "; ") + m;
        throw InputError(m_count > (long long)(m_kept.size())
                             ? formatMessage(coreTranslate("awb::mesh",
                                                           "%1 problems, the first %2: %3"),
                                             m_count, m_kept.size(), list)
                             : formatMessage(coreTranslate("awb::mesh", "%1 problems: %2"),
                                             m_count, list));
    }

private:
    std::vector<std::string> m_kept;
    long long m_count = 0;
};

std::string faceList(const std::vector<int> &faces)
{
    std::string s;
    for (std::size_t k = 0; k < faces.size(); ++k)
        s += (k ? ", " : "") + std::to_string(faces[k]);
    return s;
}

} // namespace

std::string toString(MeshScheme scheme)
{
    return scheme == MeshScheme::Loop ? "loop" : "catmull-clark";
}

int regularValence(MeshScheme scheme) { return scheme == MeshScheme::Loop ? 6 : 4; }

MeshScheme suggestedScheme(const Mesh &mesh)
{
    const bool triangles =
        !mesh.faces.empty() && std::all_of(mesh.faces.begin(), mesh.faces.end(),
                                           [](const auto &f) { return f.size() == 3; });
    return triangles ? MeshScheme::Loop : MeshScheme::CatmullClark;
}

MeshTopology::MeshTopology(int vertexCount, IndexRows faces)
    : m_faces(std::move(faces)), m_ringBoundary(std::size_t(std::max(vertexCount, 0)), 0)
{
    if (vertexCount <= 0)
        throw InputError(coreTranslate("awb::mesh", "the mesh has no vertices"));
    if (m_faces.empty())
        throw InputError(coreTranslate("awb::mesh", "the mesh has no faces"));
    Problems problems;
    std::size_t halfEdges = 0;
    for (std::size_t f = 0; f < m_faces.size(); ++f) {
        const auto loop = m_faces[f];
        halfEdges += loop.size();
        if (loop.size() < 3)
            problems.add(formatMessage(
                coreTranslate("awb::mesh", "face %1 has %2 vertices; a face needs at least 3"), f,
                loop.size()));
        bool inRange = true;
        for (int v : loop)
            if (v < 0 || v >= vertexCount) {
                problems.add(formatMessage(
                    coreTranslate("awb::mesh", "face %1 refers to vertex %2, but the mesh has %3 "
                                               "vertices (0 to %4)"),
                    f, v, vertexCount, vertexCount - 1));
                inRange = false;
            }
        if (!inRange)
            continue;
        int twice = -1;
        if (loop.size() <= 16) {  // no allocation for the usual faces
            for (std::size_t i = 0; i < loop.size(); ++i)
                for (std::size_t j = i + 1; j < loop.size(); ++j)
                    if (loop[i] == loop[j] && (twice < 0 || loop[i] < twice))
                        twice = loop[i];
        } else {
            std::vector<int> sorted(loop.begin(), loop.end());
            std::sort(sorted.begin(), sorted.end());
            if (auto it = std::adjacent_find(sorted.begin(), sorted.end()); it != sorted.end())
                twice = *it;
        }
        if (twice >= 0)
            problems.add(
                formatMessage(coreTranslate("awb::mesh", "face %1 lists vertex %2 twice"), f, twice));
    }
    problems.raise();
    // The half-edges, each vertex's in compressed rows (OpenSubdiv's vertex-edge relation), and
    // how they pair up (MeshHalfEdges.h): every lookup is a scan of one vertex's few
    // half-edges, no hash of edges. For each half-edge a -> b: the first a -> b, the first
    // b -> a (its twin, or -1), and the edges of three or more faces, named once, by their
    // first half-edge.
    const MeshHalfEdges half(int(m_ringBoundary.size()), m_faces);
    const BigVector<int> &halfFace = half.face, &halfFrom = half.from, &halfTo = half.to;
    MeshHalfEdges::Pairing pairing = half.pairing();
    const BigVector<int> &earliest = pairing.same, &twin = pairing.opposite;
    std::vector<std::pair<std::pair<int, int>, std::vector<int>>> nonManifold;
    {
        std::vector<std::pair<int, int>> crowded;  // (the edge's first half-edge, a face on it)
        for (int h = 0; h < int(halfEdges); ++h)
            if (pairing.halves[std::size_t(h)] > 2) {
                const int o = twin[std::size_t(h)];
                crowded.push_back({o >= 0 ? std::min(earliest[std::size_t(h)], o)
                                          : earliest[std::size_t(h)],
                                   halfFace[std::size_t(h)]});
            }
        std::sort(crowded.begin(), crowded.end());
        for (std::size_t lo = 0, hi = 0; lo < crowded.size(); lo = hi) {
            std::vector<int> on;
            while (hi < crowded.size() && crowded[hi].first == crowded[lo].first)
                on.push_back(crowded[hi++].second);
            const int e = crowded[lo].first;
            nonManifold.push_back({{std::min(halfFrom[std::size_t(e)], halfTo[std::size_t(e)]),
                                    std::max(halfFrom[std::size_t(e)], halfTo[std::size_t(e)])},
                                   std::move(on)});
        }
    }
    // Edges of three or more faces, in the order of their vertex pairs.
    std::sort(nonManifold.begin(), nonManifold.end());
    for (const auto &[ab, on] : nonManifold)
        problems.add(formatMessage(
            coreTranslate("awb::mesh", "edge (%1, %2) is non-manifold: faces %3 meet there"),
            ab.first, ab.second, faceList(on)));
    problems.raise();
    for (int h = 0; h < int(halfEdges); ++h)
        if (earliest[std::size_t(h)] != h)
            problems.add(formatMessage(
                coreTranslate("awb::mesh",
                              "faces %1 and %2 are oriented inconsistently: both run from "
                              "vertex %3 to vertex %4 (turn one of them over)"),
                halfFace[std::size_t(earliest[std::size_t(h)])], halfFace[std::size_t(h)],
                halfFrom[std::size_t(h)], halfTo[std::size_t(h)]));
    problems.raise();
    for (const auto &[v, faces] : link(twin))
        problems.add(formatMessage(
            coreTranslate("awb::mesh", "vertex %1 is non-manifold: its %2 faces do not form one "
                                       "fan around it"),
            v, faces));
    problems.raise();
}

std::vector<std::pair<int, int>> MeshTopology::link(const BigVector<int> &twin)
{
    std::vector<std::pair<int, int>> notOneFan;
    const std::size_t nf = m_faces.size(), nv = m_ringBoundary.size();
    const BigVector<int> &first = m_faces.starts(), &from = m_faces.values();
    const std::size_t halfEdges = from.size();
    // Edges, numbered in the order the faces first name them. The edge of half-edge h is
    // m_faceEdges' value h (its rows are shaped like the faces'); the face of h is h / m when
    // every face has m sides (every level after the first), else stored. A refined level of a
    // million faces touches two arrays of half-edges fewer (fresh pages are a third of it).
    m_edges.reserve(halfEdges / 2 + 1);
    m_faceEdges = IndexRows::shapedLike(m_faces, -1);
    const BigVector<int> &edgeOfHalf = m_faceEdges.values();
    int sides = nf > 0 ? first[1] - first[0] : 0;
    for (std::size_t f = 1; f < nf && sides > 0; ++f)
        if (first[f + 1] - first[f] != sides)
            sides = 0;
    BigVector<int> halfFace(sides > 0 ? 0 : halfEdges);
    const auto faceOf = [&](int h) {
        return sides > 0 ? h / sides : halfFace[std::size_t(h)];
    };
    for (std::size_t f = 0; f < nf; ++f) {
        const auto loop = m_faces[f];
        const auto faceEdges = m_faceEdges.row(f);
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const int h = first[f] + int(k), t = twin[std::size_t(h)];
            if (sides == 0)
                halfFace[std::size_t(h)] = int(f);
            int e;
            if (t >= 0 && t < h) {
                e = edgeOfHalf[std::size_t(t)];
                m_edges[std::size_t(e)].face[1] = int(f);
            } else {
                Edge edge;
                edge.v[0] = loop[k];
                edge.v[1] = loop[(k + 1) % loop.size()];
                edge.face[0] = int(f);
                e = int(m_edges.size());
                m_edges.push_back(edge);
            }
            faceEdges[k] = e;
        }
    }
    // Per vertex: the first half-edge leaving it, the first with no twin (on the boundary), and
    // how many leave it.
    BigVector<int> firstOut(nv, -1), firstOpen(nv, -1), outCount(nv, 0);
    for (std::size_t h = 0; h < halfEdges; ++h) {
        const auto v = std::size_t(from[h]);
        if (firstOut[v] < 0)
            firstOut[v] = int(h);
        if (firstOpen[v] < 0 && twin[h] < 0)
            firstOpen[v] = int(h);
        ++outCount[v];
    }
    const auto previous = [&](int h) {
        const int f = faceOf(h), b = first[std::size_t(f)];
        const int n = first[std::size_t(f) + 1] - b;
        return b + (h - b + n - 1) % n;
    };
    // The ring of each vertex, counter-clockwise: in a face ... a -> v -> b ..., the face lies
    // between edge (v, b) and edge (v, a) turning counter-clockwise; the next face is the one
    // with the half-edge v -> a, the twin of a -> v.
    m_ringEdges.reserve(nv, halfEdges + nv);
    m_ringFaces.reserve(nv, halfEdges);
    std::vector<int> ringEdges, ringFaces;
    for (std::size_t v = 0; v < nv; ++v) {
        ringEdges.clear();
        ringFaces.clear();
        if (firstOut[v] >= 0) {
            // Start at a boundary half-edge v -> b (no b -> v) when there is one.
            int start = firstOut[v];
            if (firstOpen[v] >= 0) {
                start = firstOpen[v];
                m_ringBoundary[v] = 1;
            }
            int at = start;
            for (;;) {
                ringEdges.push_back(edgeOfHalf[std::size_t(at)]);
                ringFaces.push_back(faceOf(at));
                const int back = previous(at);
                const int next = twin[std::size_t(back)];
                if (next < 0) {  // edge (v, a) is on the boundary: the fan ends
                    ringEdges.push_back(edgeOfHalf[std::size_t(back)]);
                    break;
                }
                at = next;
                if (at == start || int(ringFaces.size()) > outCount[v])
                    break;
            }
            if (int(ringFaces.size()) != outCount[v])
                notOneFan.push_back({int(v), outCount[v]});
        }
        m_ringEdges.push_back(ringEdges);
        m_ringFaces.push_back(ringFaces);
    }
    return notOneFan;
}

int MeshTopology::findEdge(int a, int b) const
{
    if (a < 0 || a >= vertexCount())
        return -1;
    for (int e : ring(a).edges)
        if (otherEnd(e, a) == b)
            return e;
    return -1;
}

std::vector<int> MeshTopology::extraordinaryVertices(MeshScheme scheme) const
{
    const int inner = regularValence(scheme), border = inner / 2 + 1;
    std::vector<int> out;
    for (int v = 0; v < vertexCount(); ++v) {
        const int n = valence(v);
        if (n == 0)
            continue;
        if (onBoundary(v) ? (int(ring(v).faces.size()) > 1 && n != border) : n != inner)
            out.push_back(v);
    }
    return out;
}

std::vector<float> MeshTopology::ringSharpness(int v) const
{
    const auto edges = ring(v).edges;
    std::vector<float> out(edges.size());
    for (std::size_t k = 0; k < edges.size(); ++k)
        out[k] = edgeSharpness(edges[k]);
    return out;
}

int MeshTopology::sharpEdgeCount(int v) const
{
    int count = 0;
    for (int e : ring(v).edges)
        count += crease::isSharp(edgeSharpness(e)) ? 1 : 0;
    return count;
}

VertexRule MeshTopology::rule(int v) const
{
    return crease::vertexRule(vertexSharpness(v), sharpEdgeCount(v));
}

void MeshTopology::applySharpness(const MeshSharpness &s)
{
    m_options = s.options;
    m_edgeSharpness.clear();
    m_vertexSharpness.clear();
    m_holes.clear();
    bool anyEdge = false;
    for (std::size_t f = 0; f < s.faceEdges.size() && f < m_faces.size(); ++f)
        for (std::size_t k = 0; k < s.faceEdges[f].size() && k < m_faceEdges[f].size(); ++k) {
            const float value = s.faceEdges[f][k];
            const int e = m_faceEdges[f][k];
            if (!crease::isSharp(value) || m_edges[std::size_t(e)].boundary())
                continue;
            if (!anyEdge)
                m_edgeSharpness.assign(m_edges.size(), kSharpnessSmooth);
            anyEdge = true;
            m_edgeSharpness[std::size_t(e)] = std::max(m_edgeSharpness[std::size_t(e)], value);
        }
    for (std::size_t v = 0; v < s.vertices.size() && v < m_ringBoundary.size(); ++v)
        if (crease::isSharp(s.vertices[v])) {
            m_vertexSharpness.resize(m_ringBoundary.size(), kSharpnessSmooth);
            m_vertexSharpness[v] = s.vertices[v];
        }
    for (std::size_t f = 0; f < s.holes.size() && f < m_faces.size(); ++f)
        if (s.holes[f]) {
            m_holes.resize(m_faces.size(), 0);
            m_holes[f] = 1;
        }
}

namespace {

// The tags of `mesh` on its topology, checked, with OpenSubdiv's boundary options applied.
void applyTags(MeshTopology &t, const Mesh &mesh)
{
    const MeshTags &tags = mesh.tags;
    Problems problems;
    const auto badSharpness = [](float s) { return !(s >= 0.0f); };  // NaN or negative
    MeshSharpness s;
    s.options = tags.options;
    if (!tags.edges.empty())
        s.faceEdges.resize(std::size_t(t.faceCount()));
    // Each edge's sharpness (the last tag of an edge wins, as OpenSubdiv applies them), then
    // each face's edges read from it: one pass over the faces, whatever their size.
    std::vector<float> edgeSharpness(tags.edges.empty() ? 0 : std::size_t(t.edgeCount()),
                                     kSharpnessSmooth);
    for (const SharpEdge &tag : tags.edges) {
        const int e = t.findEdge(tag.a, tag.b);
        if (badSharpness(tag.sharpness))
            problems.add(formatMessage(
                coreTranslate("awb::mesh", "the crease on vertices %1 and %2 has sharpness %3; "
                                           "a sharpness is a number of 0 or more"),
                tag.a, tag.b, streamedNumber(double(tag.sharpness))));
        else if (e < 0)
            problems.add(formatMessage(
                coreTranslate("awb::mesh",
                              "a crease names vertices %1 and %2, but no edge joins them"),
                tag.a, tag.b));
        else
            edgeSharpness[std::size_t(e)] = tag.sharpness;
    }
    for (int f = 0; f < t.faceCount() && !tags.edges.empty(); ++f) {
        const auto edges = t.faceEdges(f);
        auto &sharpness = s.faceEdges[std::size_t(f)];
        sharpness.resize(edges.size());
        for (std::size_t k = 0; k < edges.size(); ++k)
            sharpness[k] = edgeSharpness[std::size_t(edges[k])];
    }
    for (const SharpVertex &tag : tags.vertices) {
        if (tag.vertex < 0 || tag.vertex >= t.vertexCount())
            problems.add(formatMessage(
                coreTranslate("awb::mesh", "a corner names vertex %1, but the mesh has %2 "
                                           "vertices (0 to %3)"),
                tag.vertex, t.vertexCount(), t.vertexCount() - 1));
        else if (badSharpness(tag.sharpness))
            problems.add(formatMessage(
                coreTranslate("awb::mesh", "the corner at vertex %1 has sharpness %2; a "
                                           "sharpness is a number of 0 or more"),
                tag.vertex, streamedNumber(double(tag.sharpness))));
        else {
            s.vertices.resize(std::size_t(t.vertexCount()), kSharpnessSmooth);
            s.vertices[std::size_t(tag.vertex)] = tag.sharpness;
        }
    }
    for (int f : tags.holes) {
        if (f < 0 || f >= t.faceCount())
            problems.add(formatMessage(
                coreTranslate("awb::mesh",
                              "a hole names face %1, but the mesh has %2 faces (0 to %3)"),
                f, t.faceCount(), t.faceCount() - 1));
        else {
            s.holes.resize(std::size_t(t.faceCount()), 0);
            s.holes[std::size_t(f)] = 1;
        }
    }
    problems.raise();
    t.applySharpness(s);
    // OpenSubdiv's boundary options (Far::TopologyRefinerFactory): "none" makes the faces at a
    // boundary vertex holes unless its boundary edges are tagged infinitely sharp;
    // "edge-and-corner" makes a boundary vertex of one face infinitely sharp.
    const auto tagged = [&](int e) {
        const auto &edge = t.edge(e);
        const int f = edge.face[0];
        const auto edges = t.faceEdges(f);
        const auto k = std::size_t(std::find(edges.begin(), edges.end(), e) - edges.begin());
        return s.faceEdges.empty() ? kSharpnessSmooth : s.faceEdges[std::size_t(f)][k];
    };
    bool changed = false;
    for (int v = 0; v < t.vertexCount(); ++v) {
        const auto ring = t.ring(v);
        if (!ring.boundary)
            continue;
        if (tags.options.boundary == BoundaryInterpolation::EdgeAndCorner
            && ring.faces.size() == 1) {
            s.vertices.resize(std::size_t(t.vertexCount()), kSharpnessSmooth);
            s.vertices[std::size_t(v)] = kSharpnessInfinite;
            changed = true;
        }
        if (tags.options.boundary == BoundaryInterpolation::None) {
            bool exclude = false;
            for (int e : ring.edges)
                exclude = exclude || (t.edge(e).boundary() && !crease::isInfinite(tagged(e)));
            if (exclude) {
                s.holes.resize(std::size_t(t.faceCount()), 0);
                for (int f : ring.faces)
                    s.holes[std::size_t(f)] = 1;
                changed = true;
            }
        }
    }
    if (changed)
        t.applySharpness(s);
}

} // namespace

MeshTopology checkMesh(const Mesh &mesh, MeshScheme scheme)
{
    if (mesh.vertices.rows() == 0)
        throw InputError(coreTranslate("awb::mesh", "the mesh has no vertices"));
    if (mesh.vertices.cols() != 3)
        throw InputError(formatMessage(
            coreTranslate("awb::mesh", "mesh vertices need 3 coordinates, got %1"),
                                       mesh.vertices.cols()));
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
        if (!mesh.vertices.row(v).allFinite())
            throw InputError(formatMessage(
                coreTranslate("awb::mesh",
                              "vertex %1 has a coordinate that is not a finite number"),
                v));
    if (scheme == MeshScheme::Loop)
        for (std::size_t f = 0; f < mesh.faces.size(); ++f)
            if (mesh.faces[f].size() != 3)
                throw InputError(formatMessage(
                    coreTranslate("awb::mesh",
                                  "face %1 has %2 vertices; Loop subdivision takes triangles only"),
                    f,
                    mesh.faces[f].size()));
    MeshTopology topology(int(mesh.vertices.rows()), mesh.faces);
    if (!mesh.tags.empty())
        applyTags(topology, mesh);
    return topology;
}

} // namespace awb
