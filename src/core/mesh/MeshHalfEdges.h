#pragma once
// The half-edges of a face list and how they pair up (OpenSubdiv's Vtr relations, flat): shared
// by the topology's checks (Mesh.cpp) and the manifold sheets (MeshSheets.cpp), so that an edge's
// faces are found one way. Internal to the mesh room. Qt-free.

#include "core/mesh/IndexRows.h"

#include <vector>

namespace awb {

struct MeshHalfEdges {
    // Half-edge h = first[f] + k runs from corner k of face f to corner k + 1.
    BigVector<int> first;  // per face, its first half-edge; first.back() = the count
    BigVector<int> from, to, face;
    // The half-edges leaving each vertex, in half-edge order (compressed rows).
    BigVector<int> outStart, out;

    // `faces` must name vertices 0 .. vertexCount - 1 (checked by the caller).
    MeshHalfEdges(int vertexCount, const IndexRows &faces);
    MeshHalfEdges(int vertexCount, const std::vector<std::vector<int>> &faces)
        : MeshHalfEdges(vertexCount, IndexRows(faces))
    {
    }
    int count() const { return int(from.size()); }
    int corner(int h) const { return h - first[std::size_t(face[std::size_t(h)])]; }
    int next(int h) const;
    int previous(int h) const;

    // Per half-edge a -> b (a != b): the first half-edge a -> b (itself or an earlier one), the
    // first b -> a (-1: none) and how many half-edges, both ways, its edge has. A degenerate
    // half-edge a -> a: itself first, no opposite, and the count of a -> a. Found by scanning
    // each end's half-edges where every vertex has at most 64 (linear, what real meshes have),
    // otherwise by sorting the half-edges by vertex pair: a vertex of a million faces (a hostile
    // file) costs a sort, not 10^12 steps.
    struct Pairing {
        BigVector<int> same, opposite, halves;
    };
    Pairing pairing() const;
};

} // namespace awb
