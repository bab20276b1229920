#pragma once
// Iterated function systems of affine maps, and their construction from a subdivision scheme
// plus control points (000 §2: f_i(X) = X P^-1 S_i P).
//
// Row convention throughout: a map acts on row vectors, x |-> x A + b (x: 1 x D, A: D x D).
// This is the papers' convention for M_i = P^-1 S_i P = [[A_i, 0], [b_i, 1]] (004 eq. (3.25)).

#include "core/schemes/Scheme.h"
#include "core/Types.h"

namespace awb {

struct AffineMap {
    Mat A;     // D x D
    RowVec b;  // 1 x D
    int dim() const { return int(A.rows()); }
};

// How a point of the IFS space is drawn: shown point = x V + c (V: D x k, k = 2 or 3).
struct Projection {
    Mat V;
    RowVec c;
    int outDim() const { return int(V.cols()); }
};

struct Ifs {
    std::vector<AffineMap> maps;
    std::vector<Projection> views;      // each IFS point is drawn once per view
    std::vector<double> probabilities;  // for random iteration; empty means uniform
    std::string space;                  // what the coordinates are ("lifted", "barycentric", ...)
    // Coordinate blocks (offset, size) that hold barycentric coordinates: the maps keep their
    // sum at 1, so the eigenvalue 1 in that direction is no obstacle to contraction.
    std::vector<std::pair<int, int>> barycentricBlocks;

    int dim() const { return maps.empty() ? 0 : maps.front().dim(); }
    int size() const { return int(maps.size()); }
    // Throws InputError if the maps disagree in size, hold non-finite numbers, or a view does
    // not fit.
    void validate() const;
    // The linear part of map i restricted to the directions the iteration can move in
    // (barycentric blocks keep their coordinate sum): what decides contraction.
    Mat effectiveLinearPart(int i) const;
};

// The lifted control-point matrix of 000 §2: [P | identity columns | ones], m x m. The d+1
// "free" rows carry no identity entry; the lifted matrix is invertible iff the control points
// of those rows are affinely independent. 000 places the identity columns so that the free rows
// are the last d+1 (NOTES.md); a surface net takes the rows affineBasisRows() picks, since the
// last points of a lattice net often lie in one plane.
struct Lifting {
    Mat lifted;             // m x m
    Mat inverse;            // m x m when invertible
    bool invertible = false;
    double reciprocalCondition = 0.0;  // sigma_min / sigma_max of `lifted`
    std::vector<int> culprits;         // 0-based control points that make it singular
    std::string reason;                // empty when invertible
    // Invertible but ill-conditioned (reciprocal condition below 1e-8): how many digits the
    // lifted maps lose, and which points to move apart. Empty otherwise.
    std::string warning;
    std::vector<int> freeRows;         // the d+1 rows without an identity entry
    // What a user should read about the lifting: the reason when singular, else the warning.
    const std::string &note() const { return invertible ? warning : reason; }
};
// freeRows empty: the last d+1 rows (000 §2).
Lifting liftControlPoints(const Mat &P, const std::vector<int> &freeRows = {});
// d+1 rows of P (m x d) spanning the largest simplex found greedily: the point farthest from
// the centroid, then each next point farthest from the affine hull of those chosen (ties: the
// lowest index). Returns fewer rows when the points span less than d dimensions.
std::vector<int> affineBasisRows(const Mat &P);

// M_i = P^-1 S_i P with its blocks: A_i ((m-1) x (m-1)) and b_i (1 x (m-1)).
struct LiftedMap {
    Mat M;
    Mat A;
    RowVec b;
};
LiftedMap liftMatrix(const Lifting &lifting, const Mat &S);

// The IFS of a curve scheme on control points P (m x d).
struct SubdivisionIfs {
    Mat controlPoints;               // m x d
    SubdivisionMatrices matrices;    // S_1..S_p
    Lifting lifting;
    std::vector<LiftedMap> lifted;   // empty when P is singular
    Ifs ifs;                         // lifted form, or barycentric form when P is singular
    bool barycentric() const { return ifs.space == "barycentric"; }

    // Map points given in the plane (n x d) or in the IFS space (n x D) into the IFS space.
    // Plane points get zero extra lifted coordinates; in barycentric form the least-norm
    // barycentric coordinates are used (any choice gives the same attractor).
    Mat toIfsSpace(const Mat &points) const;
    // A point X of the IFS space is drawn as c P, with c = X V + c0 its coefficients on the
    // control points (1 x m): [X, 1] L^-1 in lifted form, X itself in barycentric form. Empty
    // (no columns) when P is singular and the form is not barycentric. What a control point's
    // move does to a drawn point with these coefficients held: it moves by c_j times the move.
    Projection netCoordinates() const;
};

enum class IfsForm { Automatic, Lifted, Barycentric };
// Throws InputError for non-finite control points or a bad number of them; a singular P is
// not an error (automatic form falls back to barycentric; Lifted form throws with the reason).
SubdivisionIfs buildSubdivisionIfs(const CurveScheme &scheme, const Mat &P,
                                   IfsForm form = IfsForm::Automatic);
SubdivisionIfs buildSubdivisionIfs(const std::vector<Mat> &S, int overlap, const Mat &P,
                                   IfsForm form = IfsForm::Automatic,
                                   const std::vector<int> &freeRows = {});

// Barycentric form: lambda |-> lambda S_i on R^m, drawn as lambda P.
Ifs barycentricIfs(const std::vector<Mat> &S, const Mat &P);

// The block-diagonal union of 000 §2.2: the components must have equally many maps; map i acts
// on each component by its own map i. The attractor is the union of the components' attractors
// (one homogeneous component each). Views of all components are kept.
Ifs blockUnion(const std::vector<Ifs> &components);

// A complex affine map z |-> z A + b on C^D as a real map on R^{2D} with coordinates
// (Re z_1, Im z_1, Re z_2, Im z_2, ...).
AffineMap realify(const CMat &A, const Eigen::RowVectorXcd &b);

// Apply map to rows: X (n x D) -> X A + 1 b.
Mat applyMap(const AffineMap &f, const Mat &X);
// Project IFS-space rows with view v: n x k.
Mat project(const Projection &v, const Mat &X);

} // namespace awb
