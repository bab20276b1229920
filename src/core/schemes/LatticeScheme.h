#pragma once
// Stationary subdivision on a regular planar lattice (000 §3): the surface schemes. Role in the
// core: the mask a of a scheme, from which everything else is derived — the subdivision
// matrices S_i of a patch (SurfacePatch.h), classic refinement of a control net, and the limit
// position of a vertex. Nothing here is a typed-in table: each scheme is built from its own
// rule (a box spline's directions, Kobbelt's √3 rules), so a new scheme is a few lines.
//
// Conventions. Control points sit on a lattice: integer coordinates (i, j) with the square
// basis (1, 0), (0, 1), or the triangular one (1, 0), (1/2, √3/2). A scheme of dilation N maps
// level-k points p to level-(k+1) points q by the mask a:
//     q_rho = sum_beta a[rho - N beta] p_beta        (rho, beta lattice points),
// so the level-(k+1) lattice is the level-k lattice scaled by 1/N. Every refined point must be
// an affine combination: the mask sums to 1 over each residue class rho mod N.

#include "core/Types.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace awb {

enum class Lattice { Square, Triangular };
std::string toString(Lattice lattice);

struct LatticePoint {
    int i = 0;
    int j = 0;
    auto operator<=>(const LatticePoint &) const = default;
    LatticePoint operator+(LatticePoint o) const { return {i + o.i, j + o.j}; }
    LatticePoint operator-(LatticePoint o) const { return {i - o.i, j - o.j}; }
    LatticePoint operator*(int s) const { return {s * i, s * j}; }
};

// An integer 2 x 2 matrix acting on lattice coordinates as a column vector: R (i, j)^T.
// The lattice symmetries a patch layout uses (identity, point reflection, rotations).
struct LatticeMatrix {
    int a = 1, b = 0, c = 0, d = 1;
    LatticePoint apply(LatticePoint p) const { return {a * p.i + b * p.j, c * p.i + d * p.j}; }
    Eigen::Vector2d apply(const Eigen::Vector2d &x) const
    {
        return {a * x.x() + b * x.y(), c * x.x() + d * x.y()};
    }
    bool operator==(const LatticeMatrix &) const = default;
    static LatticeMatrix identity() { return {}; }
    static LatticeMatrix reflection() { return {-1, 0, 0, -1}; }
};

// Cartesian position of lattice coordinates (x, y may be fractional).
Eigen::Vector2d latticePosition(Lattice lattice, const Eigen::Vector2d &coords);
// Graph distance to the origin: square max(|i|, |j|), triangular max(|i|, |j|, |i + j|).
int latticeDistance(Lattice lattice, LatticePoint p);
// The lattice's unit neighbours of the origin, counter-clockwise (4 or 6).
std::vector<LatticePoint> latticeNeighbours(Lattice lattice);

using Stencil = std::vector<std::pair<LatticePoint, double>>;

class LatticeScheme {
public:
    // Throws InputError when N < 2, the mask is empty or not finite, or a residue class of the
    // mask does not sum to 1 (the message names the class and its sum).
    LatticeScheme(std::string name, Lattice lattice, int dilation,
                  std::map<LatticePoint, double> mask);

    const std::string &name() const { return m_name; }
    Lattice lattice() const { return m_lattice; }
    int dilation() const { return m_dilation; }
    const std::map<LatticePoint, double> &mask() const { return m_mask; }
    // Largest latticeDistance of a mask entry.
    int maskRadius() const { return m_radius; }

    // Refined point rho (level k+1) as a combination of level-k points: (beta, a[rho - N beta]),
    // nonzero weights only, ordered by beta.
    Stencil stencil(LatticePoint rho) const;
    // True when a[R x] = a[x] for every x: the scheme commutes with the lattice map R.
    bool symmetricUnder(const LatticeMatrix &R) const;
    // The limit position of a vertex as weights on the vertex's neighbourhood (offsets from the
    // vertex): the left eigenvector of eigenvalue 1 of the local subdivision matrix around a
    // lattice point, normalised to sum 1 (e.g. Loop: 1/2 the vertex, 1/12 each neighbour).
    const Stencil &limitStencil() const { return m_limit; }

private:
    void computeLimitStencil();

    std::string m_name;
    Lattice m_lattice;
    int m_dilation;
    std::map<LatticePoint, double> m_mask;
    int m_radius = 0;
    Stencil m_limit;
};

// Binary (N = 2) box spline with the given directions, each listed once per multiplicity: the
// mask a(z) = 4 prod_xi (1 + z^xi) / 2 centred on a lattice point. The directions must sum to
// an even vector (otherwise the mask has no vertex centre).
LatticeScheme boxSplineScheme(std::string name, Lattice lattice,
                              const std::vector<LatticePoint> &directions);
// Tensor-product uniform bicubic B-spline = Catmull–Clark on a regular quad grid (000 §3.1):
// the box spline with (1,0) and (0,1) four times each. Mask (1,4,6,4,1)/8 ⊗ (1,4,6,4,1)/8.
LatticeScheme bicubicScheme();
// Three-direction quartic box spline = Loop on a regular triangle mesh (000 §3.2): directions
// (1,0), (0,1), (-1,1) twice each. Vertex rule 5/8, 1/16; edge rule 3/8, 3/8, 1/8, 1/8.
LatticeScheme loopScheme();
// Kobbelt's √3 subdivision (000 §3.3), valence 6 (alpha = 1/3): one round inserts each
// triangle's centroid and relaxes every old vertex to 2/3 p + 1/18 sum of its six neighbours,
// then flips the old edges; the new lattice is turned by 30°. Two rounds are a ternary
// (N = 3) scheme on the original lattice: this is that two-round scheme, derived by running
// the one-round rules twice on a unit impulse.
LatticeScheme sqrt3Scheme();

} // namespace awb
