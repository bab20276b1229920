#pragma once
// A mesh of any topology as an IFS with condensation (issue 30; the construction and its proof:
// docs/mathematics.md, "Extraordinary vertices: an IFS with a condensation set").
//
// After the steps that isolate the irregular vertices (no face with two irregular corners: at
// most two steps), the limit surface is a union of pieces, each a control net and the maps of
// its refinement:
// - a *face piece*: a face whose corners are all regular (the bicubic patch's 16 points, the
//   Loop box-spline triangle's 12, or fewer on the boundary). Its maps take its net to the
//   nets of its 4 sub-faces: f_i(X) = X P^-1 S_i P as for lattice patches (000 §3);
// - a *vertex piece*: the faces around an irregular vertex v (interior of valence != 4 or 6,
//   or on the boundary of valence != 3 or 4, a corner of one face included) over its ring
//   (every point within two faces of v). Its first map f_0 = the local subdivision matrix S of
//   the ring takes it to the same neighbourhood one level finer; its other maps take it to the
//   3n faces of the annulus between the two levels, which are face pieces: the condensation
//   set. So the neighbourhood is C u f(C) u f^2(C) u ... u {the limit of v}.
//
// Pieces of the same local topology share their matrices: a piece *type* is that topology,
// read off a canonical walk of the net (its key), and its maps are computed once, on a copy of
// the neighbourhood refined once. The types and their maps form a graph-directed IFS (the
// child of a piece may be of another type: a face piece along the boundary has sub-faces away
// from it); after at most one step every vertex piece maps to its own type.
//
// Qt-free; doubles throughout. The maps are exact: started from the limit stencils of the
// pieces' corners, depth K gives exactly the limit positions of the vertices of the mesh
// refined L + K times (tested against limitPositions and OpenSubdiv).

#include "core/mesh/MeshRefine.h"

#include <cstdint>
#include <vector>

namespace awb {

// A sparse matrix by rows, for the iteration's inner loop: row i is entries[begin[i] ..
// begin[i + 1]) as (column, weight).
struct SparseRows {
    std::vector<int> begin{0};
    std::vector<std::pair<int, double>> entries;
    static SparseRows of(const Mat &m);
    int rows() const { return int(begin.size()) - 1; }
    // out (rows x 3) = this * in (columns x 3), both row-major x, y, z triples.
    void apply(const double *in, double *out) const
    {
        const std::pair<int, double> *e = entries.data();
        for (int i = 0, n = rows(); i < n; ++i) {
            double x = 0, y = 0, z = 0;
            for (int k = begin[std::size_t(i)], end = begin[std::size_t(i) + 1]; k < end; ++k) {
                const double *p = in + 3 * e[k].first;
                const double w = e[k].second;
                x += w * p[0];
                y += w * p[1];
                z += w * p[2];
            }
            out[3 * i] = x;
            out[3 * i + 1] = y;
            out[3 * i + 2] = z;
        }
    }
};

struct MeshPieceType {
    enum class Kind { Face, Vertex };
    Kind kind = Kind::Face;
    int netSize = 0;
    // Vertex pieces: the vertex's valence (edges) and whether it is on the boundary. Face
    // pieces: 0, and whether a corner is on the boundary.
    int valence = 0;
    bool boundary = false;
    VertexRule rule = VertexRule::Smooth;  // vertex pieces: the vertex's rule at this level
    // Vertex pieces: the sharpness of its edges in the order of its ring (MeshTopology::Ring;
    // boundary edges infinite) and its own, at this level.
    std::vector<float> ringSharpness;
    float vertexSharpness = 0.0f;
    // The piece's output vertices: for a face, its corners; for a vertex piece, every corner of
    // its faces (v first). `corners` holds their places in the net, `limits` (corners x net)
    // their limit stencils.
    std::vector<int> corners;
    Mat limits;
    SparseRows limitRows;  // `limits`, sparse
    // The piece's own faces (one for a face piece, the n faces around the vertex for a vertex
    // piece) as loops of places in the net (all among `corners`).
    std::vector<std::vector<int>> faces;
    // One per map: the child piece's type and S_i (child net x this net; rows sum to 1), also
    // sparse for the iteration, and the child's corner limits over this net (its limits times
    // S_i: the last step and the limits in one product). Vertex pieces: child 0 is the
    // neighbourhood one level finer, the others the annulus faces.
    struct Child {
        int type = 0;
        Mat S;
        SparseRows rows;
        SparseRows leaf;
    };
    std::vector<Child> children;
    int roots = 0;      // pieces of the isolated mesh of this type
    bool hole = false;  // a face that is a hole: nothing drawn, at any depth
};

struct MeshPieceRoot {
    int type = 0;
    int number = 0;   // its place in MeshPieces::roots: its net is MeshPieces::net(root)
    int vertex = -1;  // vertex pieces: the vertex of the isolated mesh
    int face = -1;    // face pieces: the face of the isolated mesh
};

struct MeshPieces {
    MeshScheme scheme = MeshScheme::CatmullClark;
    int inputVertexCount = 0;
    int inputFaceCount = 0;
    std::vector<std::vector<int>> inputFaces;
    MeshTags inputTags;
    int steps = 0;  // isolation steps L (and, with Chaikin creases, the levels they last)
    // The isolated mesh's vertices from the input's, level by level as OpenSubdiv's
    // PrimvarRefiner goes (vertex v < inputVertexCount is the input's vertex v at every level):
    // level k's stencils are over level k - 1's points, level 0 the input's vertices (for a
    // non-manifold input, the first table gives each vertex's copies in the sheets,
    // MeshSheets.h); none when the input is isolated already. Each level's stencils are kept
    // as refineTopology made them: composing them over the input would hold two tables of
    // the finest level at once (a quarter of a large mesh's peak) for no gain in applying them.
    std::vector<StencilTable> isolation;
    IndexRows isolatedFaces;
    // Where an isolated vertex comes from: >= 0 an input vertex; -1 - f the centre of input
    // face f (a Catmull-Clark face that is not a quad); otherwise kNewPoint.
    std::vector<int> origin;
    static constexpr int kNewPoint = -1000000000;
    std::vector<MeshPieceType> types;
    std::vector<MeshPieceRoot> roots;
    IndexRows rootNets;  // per root, the vertices of the isolated mesh, in its type's order
    std::span<const int> net(const MeshPieceRoot &root) const
    {
        return rootNets[std::size_t(root.number)];
    }
    std::vector<int> loneVertices;  // input vertices of no face: they stay where they are
};

// Refuses what checkMesh refuses, a vertex of valence above 64, and (an internal limit that
// real meshes do not reach) more than 4096 piece types, with an InputError.
MeshPieces buildMeshPieces(const Mesh &mesh, MeshScheme scheme);

// The isolated mesh's vertices for the input's (n x 3).
Mat isolatedPositions(const MeshPieces &pieces, const Mat &inputVertices);

// The type reached from vertex type t by following child 0 until a type maps to itself (after
// at most one step, or past a semi-sharp prelude of at most 10); its S_0 is the local subdivision matrix of the vertex's ring. -1 when the
// chain does not settle, or for a face type.
int settledType(const MeshPieces &pieces, int type);

} // namespace awb
