// The topology one refinement step below a parent, its relations derived from the parent's as
// OpenSubdiv's Vtr::Refinement derives the child level's (Mesh.h). The child's faces come in
// refineTopology's order (MeshRefine.cpp):
//   Catmull-Clark: child face start(f) + i = {v_i, E(e_i), F(f), E(e_(i-1))} for corner i of
//                  parent face f, whose edge e_i joins its corners i and i + 1;
//   Loop:          child faces 4f + i = {v_i, E(e_i), E(e_(i-1))} (i < 3), 4f + 3 = {E(e_0),
//                  E(e_1), E(e_2)};
// with the parent's vertices first, then a point E(e) = nv + e per edge, then (Catmull-Clark)
// F(f) = nv + ne + f per face. The checked construction (Mesh.cpp) links a child of a million
// faces from its twins, a chain of scattered reads per vertex; here every relation is read off
// the parent's, and the test compares the two (core_test_mesh, refinedTopologyFromTheParent).

#include "core/mesh/Mesh.h"

#include <algorithm>
#include <stdexcept>

namespace awb {

namespace {

int positionIn(std::span<const int> row, int x)
{
    return int(std::find(row.begin(), row.end(), x) - row.begin());
}

} // namespace

MeshTopology::MeshTopology(const MeshTopology &parent, MeshScheme scheme, IndexRows childFaces)
    : m_faces(std::move(childFaces)),
      m_ringBoundary(std::size_t(parent.vertexCount()) + std::size_t(parent.edgeCount())
                         + (scheme == MeshScheme::CatmullClark ? std::size_t(parent.faceCount())
                                                               : 0),
                     0)
{
    const std::size_t corners = std::size_t(parent.faces().start(parent.faces().size()));
    const std::size_t expected =
        scheme == MeshScheme::CatmullClark ? corners : 4 * std::size_t(parent.faceCount());
    if (m_faces.size() != expected)
        throw std::logic_error("MeshTopology: the child's faces are not its parent's refinement");
    deriveEdges(parent, scheme);
    deriveRings(parent, scheme);
}

// The child's edges, numbered in the order its faces first name them (as link() numbers them):
// the two halves of each parent edge, made by the first child face that names each, and the
// edges inside each parent face. A child face's edges are known when it is reached (what it
// shares with an earlier face was made there), so its row of edges is written whole, in order.
void MeshTopology::deriveEdges(const MeshTopology &parent, MeshScheme scheme)
{
    const int nv = parent.vertexCount(), ne = parent.edgeCount(), nf = parent.faceCount();
    const IndexRows &pf = parent.faces();
    const std::size_t corners = std::size_t(pf.start(pf.size()));
    m_edges.reserve(2 * std::size_t(ne)
                    + (scheme == MeshScheme::CatmullClark ? corners : 3 * std::size_t(nf)));
    m_faceEdges.reserve(m_faces.size(), m_faces.values().size());
    // The child edge on each half of parent edge e: [2e] at its end v[0], [2e + 1] at v[1].
    BigVector<int> halfChild(2 * std::size_t(ne), -1);
    const auto made = [&](int from, int to, int face) {
        m_edges.push_back(Edge{{from, to}, {face, -1}});
        return int(m_edges.size()) - 1;
    };
    const auto joined = [&](int e, int face) {
        m_edges[std::size_t(e)].face[1] = face;
        return e;
    };
    // The half of parent edge e at vertex v, run from -> to in child face `face`.
    const auto half = [&](int e, int v, int from, int to, int face) {
        int &slot = halfChild[2 * std::size_t(e) + (parent.edge(e).v[0] == v ? 0 : 1)];
        if (slot < 0)
            slot = made(from, to, face);
        else
            joined(slot, face);
        return slot;
    };
    for (int f = 0; f < nf; ++f) {
        const auto loop = parent.face(f);
        const auto edges = parent.faceEdges(f);
        const int k = int(loop.size());
        if (scheme == MeshScheme::CatmullClark) {
            const int s = pf.start(std::size_t(f)), centre = nv + ne + f;
            int firstToCentre = -1, previousIn = -1;  // c_0's edge F -> E(e_(k-1)); c_(i-1)'s E -> F
            for (int i = 0; i < k; ++i) {
                const int c = s + i, v = loop[std::size_t(i)];
                const int e = edges[std::size_t(i)], ep = edges[std::size_t((i + k - 1) % k)];
                const int h0 = half(e, v, v, nv + e, c);
                const int h1 = i < k - 1 ? made(nv + e, centre, c) : joined(firstToCentre, c);
                const int h2 = i == 0 ? (firstToCentre = made(centre, nv + ep, c))
                                      : joined(previousIn, c);
                const int h3 = half(ep, v, nv + ep, v, c);
                previousIn = h1;
                m_faceEdges.push_back({h0, h1, h2, h3});
            }
        } else {
            int inner[3];  // face 4f + i's edge E(e_i) -> E(e_(i-1))
            for (int i = 0; i < 3; ++i) {
                const int c = 4 * f + i, v = loop[std::size_t(i)];
                const int e = edges[std::size_t(i)], ep = edges[std::size_t((i + 2) % 3)];
                const int h0 = half(e, v, v, nv + e, c);
                inner[i] = made(nv + e, nv + ep, c);
                const int h2 = half(ep, v, nv + ep, v, c);
                m_faceEdges.push_back({h0, inner[i], h2});
            }
            const int c = 4 * f + 3;  // its half j, E(e_j) -> E(e_(j+1)), is face j + 1's inner
            m_faceEdges.push_back({joined(inner[1], c), joined(inner[2], c), joined(inner[0], c)});
        }
    }
}

// Each child vertex's ring, counter-clockwise as link() makes it: the child faces around it,
// each with the vertex's corner there, from the parent's ring (a vertex point), the faces on an
// edge (an edge point) or a face's children (a face point); the ring's edges are the child
// faces' edges leaving the vertex. An inner ring starts at its first child face (link() starts
// at the vertex's first half-edge), a boundary ring at its boundary edge.
void MeshTopology::deriveRings(const MeshTopology &parent, MeshScheme scheme)
{
    const int nv = parent.vertexCount(), ne = parent.edgeCount(), nf = parent.faceCount();
    const IndexRows &pf = parent.faces();
    const bool cc = scheme == MeshScheme::CatmullClark;
    const int sides = cc ? 4 : 3;  // every child face's
    m_ringEdges.reserve(m_ringBoundary.size(), 2 * m_edges.size());
    m_ringFaces.reserve(m_ringBoundary.size(), m_faces.values().size());
    // The child face at corner j of parent face f.
    const auto childFace = [&](int f, int j) { return cc ? pf.start(std::size_t(f)) + j : 4 * f + j; };
    std::vector<int> faces, at, edges;  // a ring's child faces, the vertex's corner in each
    const auto emit = [&](int v, bool boundary) {
        if (!boundary && !faces.empty()) {
            const auto first = std::min_element(faces.begin(), faces.end()) - faces.begin();
            std::rotate(faces.begin(), faces.begin() + first, faces.end());
            std::rotate(at.begin(), at.begin() + first, at.end());
        }
        edges.clear();
        for (std::size_t k = 0; k < faces.size(); ++k)
            edges.push_back(m_faceEdges[std::size_t(faces[k])][std::size_t(at[k])]);
        if (boundary)  // the edge arriving at the vertex in the last face
            edges.push_back(
                m_faceEdges[std::size_t(faces.back())][std::size_t((at.back() + sides - 1) % sides)]);
        m_ringEdges.push_back(edges);
        m_ringFaces.push_back(faces);
        m_ringBoundary[std::size_t(v)] = boundary ? 1 : 0;
        faces.clear();
        at.clear();
    };
    const auto add = [&](int face, int corner) {
        faces.push_back(face);
        at.push_back(corner);
    };
    for (int v = 0; v < nv; ++v) {
        const Ring ring = parent.ring(v);
        for (int g : ring.faces)
            add(childFace(g, positionIn(parent.face(g), v)), 0);
        emit(v, ring.boundary);
    }
    for (int e = 0; e < ne; ++e) {
        const Edge &edge = parent.edge(e);
        const int f0 = edge.face[0], f1 = edge.face[1];
        const int i0 = positionIn(parent.faceEdges(f0), e);
        const int i1 = f1 >= 0 ? positionIn(parent.faceEdges(f1), e) : 0;
        if (cc) {
            const int k0 = int(parent.face(f0).size());
            if (f1 >= 0) {
                const int k1 = int(parent.face(f1).size());
                add(childFace(f0, i0), 1);
                add(childFace(f1, (i1 + 1) % k1), 3);
                add(childFace(f1, i1), 1);
            }
            add(childFace(f0, (i0 + 1) % k0), 3);
            if (f1 < 0)
                add(childFace(f0, i0), 1);
        } else {
            if (f1 >= 0) {
                add(4 * f0 + i0, 1);
                add(4 * f1 + (i1 + 1) % 3, 2);
                add(4 * f1 + 3, i1);
                add(4 * f1 + i1, 1);
            }
            add(4 * f0 + (i0 + 1) % 3, 2);
            add(4 * f0 + 3, i0);
            if (f1 < 0)
                add(4 * f0 + i0, 1);
        }
        emit(nv + e, f1 < 0);
    }
    if (cc)
        for (int f = 0; f < nf; ++f) {
            const int k = int(parent.face(f).size());
            for (int i = 0; i < k; ++i)
                add(childFace(f, i), 2);
            emit(nv + ne + f, false);
        }
}

} // namespace awb
