#pragma once
// A patch of a lattice subdivision surface as the attractor of an IFS (000 §3). Role in the
// core: from a LatticeScheme and a patch layout, the control net of the patch and its
// subdivision matrices S_i; classic refinement of a control net (the top rows of 000 Figs.
// 6–8) and points exactly on the limit surface, to compare the two routes.
//
// A layout is a parameter domain D (a polygon in lattice coordinates: a square, a triangle, a
// hexagon) and maps psi_i(x) = (R_i x + t_i) / N that take D into itself and cover it
// (D = U psi_i(D); the pieces may overlap). The net of the patch is the smallest set of lattice
// points that contains the corners of D and whose sub-nets {R_i gamma + t_i : gamma in net}
// (refined coordinates) can all be computed from it: exactly the points whose basis functions
// reach D. S_i (m x m) maps the net to the net of the piece psi_i(D), point k to point k:
//     S_i[k][l] = a[R_i net_k + t_i - N net_l].
// With control points P (m x d) the IFS is f_i(X) = X P^-1 S_i P (000 §2), its attractor the
// surface over D.

#include "core/schemes/LatticeScheme.h"

namespace awb {

struct PatchMap {
    LatticeMatrix R;
    LatticePoint t;  // in refined (level 1) coordinates
    // psi(x) = (R x + t) / N on lattice coordinates.
    Eigen::Vector2d apply(const Eigen::Vector2d &x, int N) const
    {
        return (R.apply(x) + Eigen::Vector2d(t.i, t.j)) / double(N);
    }
};

struct PatchLayout {
    std::string name;                     // "square", "triangle", "hexagon"
    std::vector<Eigen::Vector2d> domain;  // corners of D, lattice coordinates, counter-clockwise
    std::vector<PatchMap> maps;
};

// The layouts a lattice has: square: {"square"}; triangular: {"triangle", "hexagon"}.
std::vector<std::string> layoutNames(Lattice lattice);
// Throws InputError for a name the scheme's lattice has no layout of.
//  * square (square lattice): D = [0,1]^2, N^2 maps t = (a, b), 0 <= a, b < N (bicubic: 4).
//  * triangle (triangular lattice): D = the triangle (0,0), (1,0), (0,1); N(N+1)/2 upright
//    pieces t = (a, b), a + b <= N - 1, and N(N-1)/2 upside-down ones (R = -I), t = (a, b),
//    a, b >= 1, a + b <= N (Loop: 4 maps, √3: 9).
//  * hexagon (triangular lattice): D = the hexagon of the six unit neighbours of 0; one
//    upright piece, a hexagon 1/N the size, around every refined point t with
//    1 <= latticeDistance(t) <= N - 1. For Loop these are the six spoke midpoints (000 §3.2:
//    six maps; the pieces overlap on the inner triangles); for √3 eighteen pieces.
PatchLayout patchLayout(const LatticeScheme &scheme, const std::string &name);

// Whether lattice coordinates x lie in the closed domain of the layout (to tol).
bool insideDomain(const PatchLayout &layout, const Eigen::Vector2d &x, double tol = 1e-12);

struct SurfaceMatrices {
    std::vector<LatticePoint> net;  // m lattice points, ordered by (j, i)
    std::vector<Mat> S;             // one per map of the layout, m x m, rows sum to 1
};
// Throws InputError when the scheme is not symmetric under a map's R or the net does not close.
SurfaceMatrices surfaceMatrices(const LatticeScheme &scheme, const PatchLayout &layout);

// Matches the lattice coordinates a user gave with their control points to `net`, up to one
// common integer translation: order[k] = index in net of the user's point k. Throws InputError
// naming the problem (wrong count, a duplicated coordinate, a point outside the net, a missing
// point).
std::vector<int> matchNet(const std::vector<LatticePoint> &net,
                          const std::vector<LatticePoint> &user, Lattice lattice);
// S with rows and columns in the user's order: out[k][l] = S[order[k]][order[l]].
Mat reorder(const Mat &S, const std::vector<int> &order);

// A control net or a refined one as a mesh: the lattice's faces (unit squares or triangles)
// whose corners are all present.
struct LatticeMesh {
    Lattice lattice = Lattice::Square;
    int level = 0;                      // lattice coordinates are scaled by scale^-level
    int scale = 1;                      // the scheme's dilation (1 for a control net)
    std::vector<LatticePoint> at;       // lattice coordinates of each point at this level
    Mat points;                         // n x d
    std::vector<std::vector<int>> faces;  // counter-clockwise indices, 3 or 4 each
    // Lattice coordinates at level 0 (the control net's).
    Eigen::Vector2d coarseCoords(int k) const;
};
LatticeMesh netMesh(Lattice lattice, const std::vector<LatticePoint> &at, const Mat &P);
// Classic subdivision, `rounds` times: every refined point whose whole stencil is present.
LatticeMesh refineMesh(const LatticeScheme &scheme, const LatticeMesh &mesh, int rounds);
// Points exactly on the limit surface: the limit stencil applied at every vertex of the mesh
// whose stencil is complete. `at` (optional) receives each point's index in mesh.points.
Mat limitPoints(const LatticeScheme &scheme, const LatticeMesh &mesh,
                std::vector<int> *at = nullptr);
// Points on the limit surface over the layout's domain only: the net refined `rounds` times,
// the limit stencil applied at every refined vertex that lies in D. The net's lattice
// coordinates are those of `net` (as returned by surfaceMatrices, rows of P in that order).
Mat limitSurfaceSamples(const LatticeScheme &scheme, const PatchLayout &layout,
                        const std::vector<LatticePoint> &net, const Mat &P, int rounds);

} // namespace awb
