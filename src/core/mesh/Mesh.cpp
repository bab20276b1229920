#include "core/mesh/Mesh.h"

#include "core/Messages.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

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

std::uint64_t key(int a, int b)
{
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
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

MeshTopology::MeshTopology(int vertexCount, const std::vector<std::vector<int>> &faces)
    : m_faces(faces), m_faceEdges(faces.size()), m_rings(std::size_t(std::max(vertexCount, 0)))
{
    if (vertexCount <= 0)
        throw InputError(coreTranslate("awb::mesh", "the mesh has no vertices"));
    if (faces.empty())
        throw InputError(coreTranslate("awb::mesh", "the mesh has no faces"));
    Problems problems;
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto &loop = faces[f];
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
        std::vector<int> sorted = loop;
        std::sort(sorted.begin(), sorted.end());
        if (auto it = std::adjacent_find(sorted.begin(), sorted.end());
            inRange && it != sorted.end())
            problems.add(
                formatMessage(coreTranslate("awb::mesh", "face %1 lists vertex %2 twice"), f, *it));
    }
    problems.raise();
    // Half-edges a -> b of each face, and the faces on each undirected edge.
    std::unordered_map<std::uint64_t, int> halfEdge;  // (a, b) -> face
    std::map<std::pair<int, int>, std::vector<int>> facesOf;
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto &loop = faces[f];
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const int a = loop[k], b = loop[(k + 1) % loop.size()];
            facesOf[{std::min(a, b), std::max(a, b)}].push_back(int(f));
        }
    }
    for (const auto &[ab, on] : facesOf)
        if (on.size() > 2)
            problems.add(formatMessage(
                coreTranslate("awb::mesh", "edge (%1, %2) is non-manifold: faces %3 meet there"),
                ab.first, ab.second, faceList(on)));
    problems.raise();
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto &loop = faces[f];
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const int a = loop[k], b = loop[(k + 1) % loop.size()];
            const auto [it, added] = halfEdge.emplace(key(a, b), int(f));
            if (!added)
                problems.add(formatMessage(
                    coreTranslate("awb::mesh",
                                  "faces %1 and %2 are oriented inconsistently: both run from "
                                  "vertex %3 to vertex %4 (turn one of them over)"),
                    it->second, f, a, b));
        }
    }
    problems.raise();
    // Edges, numbered in the order the faces first name them.
    std::unordered_map<std::uint64_t, int> edgeOf;
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto &loop = faces[f];
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const int a = loop[k], b = loop[(k + 1) % loop.size()];
            const std::uint64_t id = key(std::min(a, b), std::max(a, b));
            auto it = edgeOf.find(id);
            if (it == edgeOf.end()) {
                Edge e;
                e.v[0] = a;
                e.v[1] = b;
                e.face[0] = int(f);
                it = edgeOf.emplace(id, int(m_edges.size())).first;
                m_edges.push_back(e);
            } else {
                m_edges[std::size_t(it->second)].face[1] = int(f);
            }
            m_faceEdges[f].push_back(it->second);
        }
    }
    // The ring of each vertex, counter-clockwise: in a face ... a -> v -> b ..., the face lies
    // between edge (v, b) and edge (v, a) turning counter-clockwise; the next face is the one
    // with the half-edge v -> a.
    std::vector<std::vector<std::pair<int, int>>> outgoing(m_rings.size());  // (face, corner)
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (std::size_t k = 0; k < faces[f].size(); ++k)
            outgoing[std::size_t(faces[f][k])].emplace_back(int(f), int(k));
    for (std::size_t v = 0; v < m_rings.size(); ++v) {
        const auto &out = outgoing[v];
        if (out.empty())
            continue;
        Ring &ring = m_rings[v];
        // Start at a boundary half-edge v -> b (no b -> v) when there is one.
        std::pair<int, int> start = out.front();
        for (const auto &[f, k] : out) {
            const auto &loop = faces[std::size_t(f)];
            const int b = loop[(std::size_t(k) + 1) % loop.size()];
            if (!halfEdge.count(key(b, int(v)))) {
                start = {f, k};
                ring.boundary = true;
                break;
            }
        }
        std::pair<int, int> at = start;
        for (;;) {
            const auto [f, k] = at;
            const auto &loop = faces[std::size_t(f)];
            const std::size_t n = loop.size();
            ring.edges.push_back(m_faceEdges[std::size_t(f)][std::size_t(k)]);
            ring.faces.push_back(f);
            const int a = loop[(std::size_t(k) + n - 1) % n];
            const auto next = halfEdge.find(key(int(v), a));
            if (next == halfEdge.end()) {  // edge (v, a) is on the boundary: the fan ends
                ring.edges.push_back(m_faceEdges[std::size_t(f)][(std::size_t(k) + n - 1) % n]);
                break;
            }
            const int g = next->second;
            const auto &gl = faces[std::size_t(g)];
            const int corner = int(std::find(gl.begin(), gl.end(), int(v)) - gl.begin());
            at = {g, corner};
            if (at == start)
                break;
        }
        if (ring.faces.size() != out.size())
            problems.add(formatMessage(
                coreTranslate("awb::mesh", "vertex %1 is non-manifold: its %2 faces do not form "
                                           "one fan around it"),
                v,
                out.size()));
    }
    problems.raise();
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
    return MeshTopology(int(mesh.vertices.rows()), mesh.faces);
}

} // namespace awb
