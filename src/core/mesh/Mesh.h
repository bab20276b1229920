#pragma once
// A polygon mesh of any topology (issue 30): vertices in R^3, faces as vertex loops, and the
// connectivity subdivision needs. The mesh room of the core keeps OpenSubdiv's separation:
//   Mesh.h            the topology (OpenSubdiv's Vtr): edges, boundaries, the ordered ring of
//                     every vertex, and the checks that refuse what is not a 2-manifold;
//   MeshSheets.h      a non-manifold mesh as OpenSubdiv draws it: manifold sheets whose cuts
//                     carry its sharpness, so that everything below applies;
//   MeshTags.h        the sharp features and options (Sdc::Crease, Sdc::Options): creases,
//                     corners, holes, boundary interpolation, crease method;
//   MeshRules.h       the scheme rules (Sdc): the weights of Catmull-Clark and Loop;
//   MeshRefine.h      the refinement of data (Far): stencils of one step, limit stencils;
//   VertexSpectrum.h  the local subdivision matrix of a vertex and its eigenvalues.
// Qt-free. Doubles throughout.

#include "core/Types.h"
#include "core/mesh/IndexRows.h"
#include "core/mesh/MeshTags.h"

#include <span>
#include <string>
#include <utility>
#include <vector>

namespace awb {

enum class MeshScheme { CatmullClark, Loop };

std::string toString(MeshScheme scheme);
// The valence of a regular interior vertex: 4 for Catmull-Clark, 6 for Loop.
int regularValence(MeshScheme scheme);

struct Mesh {
    Mat vertices;                         // n x 3, one point per row
    std::vector<std::vector<int>> faces;  // vertex loops, 0-based, counter-clockwise from outside
    MeshTags tags;                        // sharp features and options (none by default)
};

// Sharp features laid on the faces of a topology, so that they survive a renumbering of the
// vertices: one sharpness per face edge (edge k of a face joins its corners k and k + 1), one
// per vertex, a hole flag per face. An empty vector stands for all smooth / no hole.
struct MeshSharpness {
    MeshOptions options;
    std::vector<std::vector<float>> faceEdges;
    std::vector<float> vertices;
    std::vector<char> holes;
    bool sharp() const { return !faceEdges.empty() || !vertices.empty(); }
};

// The scheme made for the mesh: Loop when every face is a triangle (Catmull-Clark would make
// each triangle three quads around a new valence-3 vertex), Catmull-Clark otherwise.
MeshScheme suggestedScheme(const Mesh &mesh);

// The connectivity of a mesh's faces. The constructor refuses, with an InputError naming the
// problem (and the faces or vertices concerned), what subdivision cannot take: no faces, a face
// of fewer than three vertices or one that lists a vertex twice, an index out of range, an edge
// shared by three or more faces (non-manifold), two faces that run along their common edge in
// the same direction (inconsistent orientation), and a vertex whose faces form separate fans.
// A vertex of no face is allowed (it stays where it is). The mesh room's entry points
// (refineMesh, limitPositions, buildMeshPieces) take a non-manifold mesh through its manifold
// sheets (MeshSheets.h) first, as OpenSubdiv draws it.
class MeshTopology {
public:
    MeshTopology(int vertexCount, IndexRows faces);
    MeshTopology(int vertexCount, const std::vector<std::vector<int>> &faces)
        : MeshTopology(vertexCount, IndexRows(faces))
    {
    }
    // The topology one step of `scheme` below `parent`, whose faces `childFaces` are in
    // refineTopology's order (MeshRefine.h), with the parent's vertices, then its edges', then
    // (Catmull-Clark) its faces' points. Its relations are derived from the parent's, as
    // OpenSubdiv's Vtr::Refinement derives the child level's: no search, no check, no walk
    // (MeshChildTopology.cpp). The same edges in the same order, rings and boundary flags as the
    // checked construction finds from the faces alone.
    MeshTopology(const MeshTopology &parent, MeshScheme scheme, IndexRows childFaces);

    struct Edge {
        int v[2] = {-1, -1};
        int face[2] = {-1, -1};  // face[1] == -1: a boundary edge
        bool boundary() const { return face[1] < 0; }
    };
    // The faces and edges around a vertex, counter-clockwise seen from outside: face k lies
    // between edges k and k + 1 (mod the edge count inside). Inside, edges.size() ==
    // faces.size(); on the boundary edges.size() == faces.size() + 1, and edges.front() and
    // edges.back() are the two boundary edges.
    // (A view into the topology, kept in compressed rows.)
    struct Ring {
        std::span<const int> edges;
        std::span<const int> faces;
        bool boundary = false;
    };

    int vertexCount() const { return int(m_ringBoundary.size()); }
    int faceCount() const { return int(m_faces.size()); }
    int edgeCount() const { return int(m_edges.size()); }
    std::span<const int> face(int f) const { return m_faces[std::size_t(f)]; }
    const IndexRows &faces() const { return m_faces; }
    // The faces taken from a topology that is not used again (its relations stay).
    IndexRows takeFaces() && { return std::move(m_faces); }
    // Edge k of face f joins its corners k and k + 1.
    std::span<const int> faceEdges(int f) const { return m_faceEdges[std::size_t(f)]; }
    const Edge &edge(int e) const { return m_edges[std::size_t(e)]; }
    Ring ring(int v) const
    {
        return {m_ringEdges[std::size_t(v)], m_ringFaces[std::size_t(v)],
                m_ringBoundary[std::size_t(v)] != 0};
    }
    // The number of edges at v (0 for a vertex of no face).
    int valence(int v) const { return int(m_ringEdges[std::size_t(v)].size()); }
    bool onBoundary(int v) const { return m_ringBoundary[std::size_t(v)] != 0; }
    int otherEnd(int e, int v) const { return edge(e).v[0] == v ? edge(e).v[1] : edge(e).v[0]; }
    // The edge joining a and b, or -1.
    int findEdge(int a, int b) const;
    // Interior vertices of valence != regularValence(scheme), and boundary vertices of two or
    // more faces whose valence is not the regular boundary valence (3 for Catmull-Clark, 4 for
    // Loop; a corner of one face takes the crease rule and is not listed), in vertex order.
    std::vector<int> extraordinaryVertices(MeshScheme scheme) const;

    // Sharp features, as OpenSubdiv's Vtr level keeps them: a boundary edge is infinitely sharp;
    // the rest is what applySharpness() set (all smooth, no hole, default options otherwise).
    const MeshOptions &options() const { return m_options; }
    float edgeSharpness(int e) const
    {
        return edge(e).boundary() ? kSharpnessInfinite
               : m_edgeSharpness.empty() ? kSharpnessSmooth
                                         : m_edgeSharpness[std::size_t(e)];
    }
    float vertexSharpness(int v) const
    {
        return m_vertexSharpness.empty() ? kSharpnessSmooth : m_vertexSharpness[std::size_t(v)];
    }
    bool hole(int f) const { return !m_holes.empty() && m_holes[std::size_t(f)]; }
    // Any semi-sharp or interior sharp edge, or sharp vertex.
    bool hasSharpness() const { return !m_edgeSharpness.empty() || !m_vertexSharpness.empty(); }
    bool hasHoles() const { return !m_holes.empty(); }
    // The sharpness of the edges at v, in the ring's order.
    std::vector<float> ringSharpness(int v) const;
    int sharpEdgeCount(int v) const;
    VertexRule rule(int v) const;
    // Lays `s` on the faces (their count must be the topology's); an edge named by both of its
    // faces takes the larger value.
    void applySharpness(const MeshSharpness &s);

private:
    // Edges (numbered in the order the faces first name them) and rings from the twins; the
    // vertices whose faces do not form one fan, with their face counts.
    std::vector<std::pair<int, int>> link(const BigVector<int> &twin);
    // The child's edges and faces' edges, then its rings (MeshChildTopology.cpp).
    void deriveEdges(const MeshTopology &parent, MeshScheme scheme);
    void deriveRings(const MeshTopology &parent, MeshScheme scheme);

    IndexRows m_faces;
    IndexRows m_faceEdges;  // shaped like m_faces
    BigVector<Edge> m_edges;
    IndexRows m_ringEdges, m_ringFaces;  // per vertex
    std::vector<char> m_ringBoundary;
    MeshOptions m_options;
    std::vector<float> m_edgeSharpness;    // empty: all smooth
    std::vector<float> m_vertexSharpness;  // empty: all smooth
    std::vector<char> m_holes;             // empty: none
};

// The checks of a mesh for a scheme, beyond MeshTopology's: vertices with three finite
// coordinates, triangles only for Loop, and tags that name edges, vertices and faces of the mesh
// with sharpness values that are numbers >= 0. Throws InputError naming the problems; returns
// the mesh's topology with its tags applied as OpenSubdiv's TopologyRefinerFactory applies them
// (boundary "edge-and-corner": a boundary vertex of one face is infinitely sharp; "none": the
// faces at a boundary vertex are holes unless its boundary edges are tagged infinitely sharp).
MeshTopology checkMesh(const Mesh &mesh, MeshScheme scheme);

} // namespace awb
