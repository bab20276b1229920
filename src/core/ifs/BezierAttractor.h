#pragma once
// Bézier curves as attractors of two affine maps (002: C. T. John, "All Bézier curves are
// attractors of iterated function systems", NYJM 2007). Role in the core: builds, from control
// points and a split parameter u, the IFS {w1, w2} whose attractor is the curve, the paper's
// cross-check by Barnsley's fractal interpolation, and the IFS of several curves at once
// (002 §6 "dusty" fractal, and the exact union of 000 §2.2).
//
// Conventions of the core (Types.h): points are ROW vectors and a map acts as x |-> x A + b,
// so the paper's column-vector matrices appear here transposed: eq. (11)'s [[u, 0], [0, u^2]]
// is A = [[u, 0], [0, u^2]] and eq. (12)'s [[1-u, 0], [2u(1-u), (1-u)^2]] is
// A = [[1-u, 2u(1-u)], [0, (1-u)^2]] with b = (u, u^2).
//
// Degree n > 2 in the plane. The de Casteljau split maps the control points P (m x 2, m = n+1)
// to L(u) P and R(u) P. An affine map w of the plane with w(P_i) = (S P)_i for all i exists
// only when these m conditions on 6 unknowns are consistent; because the Bézier form of a
// polynomial curve is unique, this is exactly the question whether the curve piece is an affine
// image of the whole curve inside the plane. For a quadratic with non-collinear control points
// it always is (002 Theorem 1). For true degree >= 3 it never is: with c(t) = sum a_k t^k,
// w o c = c(u t) makes every a_k (k >= 1) a left eigenvector of the 2 x 2 linear part with
// eigenvalue u^k, so at most two powers t^i, t^j occur; then c(u + (1-u) t) has a t^k term
// (0 < k < j, k != i) that an affine image of c cannot have unless a_i, a_j are parallel
// (a straight curve). So plane maps exist only for quadratics, possibly degree-elevated;
// bezierSplit() decides it numerically by solving [P | 1] [A; b] = S_i P and checking the
// residual. Otherwise the maps live in the lifted space R^n of 000 §2 (Ifs.h,
// buildSubdivisionIfs): M_i = P^-1 S_i P with P = [P | identity cols | ones], the curve being the
// view onto the first two coordinates. This is the paper's v_i = ω w_i ω^-1 one dimension up
// per degree (002 §7): ω(λ) = λ P takes barycentric coordinates to lifted ones and
// w_i(λ) = λ S_i is the split of the standard simplex. When the last three control points are
// collinear that lifting is singular and buildSubdivisionIfs falls back to barycentric
// coordinates (R^m, drawn as λ P).

#include "core/ifs/Ifs.h"
#include "core/analysis/Spectrum.h"

#include <array>

namespace awb {

// One map of a split in the form the paper prints it, with its contractivity.
struct PlaneMap {
    AffineMap map;               // A: d x d, b: 1 x d (row convention)
    Contractivity contractivity; // of A: spectral radius, ||A||_2, exponent (004 Thm 3.5.1)
    // The (d+1) x (d+1) homogeneous form [[A, 0], [b, 1]], so that [x 1] H = [x A + b, 1].
    Mat homogeneous() const;
};

// ---- small affine-map algebra (row convention; maps of R^d) ----------------------------------

// outer o inner: x |-> (x A_in + b_in) A_out + b_out. Both d x d.
AffineMap compose(const AffineMap &outer, const AffineMap &inner);
// f^-1 (A d x d invertible, else InputError).
AffineMap inverse(const AffineMap &f);
// omega o w o omega^-1, eqs. (17)-(18); both d x d, omega invertible.
AffineMap conjugate(const AffineMap &w, const AffineMap &omega);
// The unique affine map of R^d with from_i |-> to_i. from, to: (d+1) x d, the rows of `from`
// affinely independent (InputError names them otherwise).
AffineMap affineMapThrough(const Mat &from, const Mat &to);

// ---- 002 §4: the parabola y = x^2, P = (0,0), (1/2,0), (1,1) --------------------------------

// The standard control points of 002 §4 (3 x 2).
Mat parabolaControlPoints();
// w1, w2 of eqs. (11)-(12) in closed form, u in (0, 1). A: 2 x 2, b: 1 x 2.
std::array<AffineMap, 2> parabolaMaps(double u);

// Barnsley's fractal interpolation IFS, eqs. (13)-(16): data (N+1) x 2 with x_0 < ... < x_N,
// vertical scalings d (N of them, 0 <= d_n < 1). Returns N maps, w_n(x, y) =
// (a_n x + e_n, c_n x + d_n y + f_n), i.e. A = [[a_n, c_n], [0, d_n]], b = (e_n, f_n).
std::vector<AffineMap> fractalInterpolationMaps(const Mat &data, const std::vector<double> &d);
// The paper's instance: data (0,0), (u,u^2), (1,1) with d_1 = u^2, d_2 = (1-u)^2. It must
// coincide with parabolaMaps(u).
std::vector<AffineMap> barnsleyParabolaMaps(double u);

// ---- 002 §5: any quadratic, v_i = omega w_i omega^-1 ----------------------------------------

// Q: 3 x 2, not collinear. omega maps parabolaControlPoints() to Q; v_i = omega w_i omega^-1.
std::array<AffineMap, 2> conjugatedQuadraticMaps(const Mat &Q, double u);

// ---- any degree -------------------------------------------------------------------------------

// The split IFS of a Bézier curve of degree n = m - 1 at u (004 eq. (2.5), 002 eqs. (9)-(10)).
struct BezierSplit {
    Mat controlPoints;            // m x d (d = 1..3)
    int degree = 0;               // n = m - 1 >= 1
    double u = 0.5;
    std::array<Mat, 2> S;         // L(u), R(u): m x m
    // True when w1, w2 exist as affine maps of the curve's own space R^d (the plane for d = 2):
    // the control points span R^d affinely and w_i(P_j) = (S_i P)_j for every j is consistent.
    bool planar = false;
    std::string planarReason;     // why not, when planar is false
    std::vector<PlaneMap> planeMaps;  // w1, w2 (d x d) when planar
    SubdivisionIfs lifted;        // 000 §2 lifted form (barycentric if P is singular), always
    Ifs ifs;                      // the plane maps when planar, else lifted.ifs
    RowVec start;                 // p_0 in the space of `ifs`: fixed point of w1, on the curve
    IfsCheck check;               // contractivity of each map of `ifs`
    // Largest spectral radius of the maps' linear parts: max(u, 1 - u) for every degree (the
    // subdominant eigenvalues of L(u), R(u) are u and 1 - u). Near 1 the IFS barely contracts.
    double slowestRadius = 0.0;
    bool nearlyNonContractive = false;  // slowestRadius >= 0.9 (u <= 0.1 or u >= 0.9)
    std::string contractionNote;        // plain words for the user

    // Deterministic levels k after which every piece has shrunk to `factor` of its size
    // (slowestRadius^k <= factor), e.g. levelsFor(1e-3).
    int levelsFor(double factor) const;
};
// Throws InputError for u outside (0, 1), non-finite numbers, fewer than 2 control points
// (degree < 1) or d outside 1..3. Collinear or otherwise special control points are no error:
// the reason lands in planarReason and the lifted / barycentric form is used.
BezierSplit bezierSplit(const Mat &P, double u);

// ---- 002 §6 and 000 §2.2: several curves -------------------------------------------------------

struct BezierCurveSpec {
    Mat controlPoints;  // m x 2
    double u = 0.5;     // the curve's own split parameter
};

// An upper bound on the joint spectral radius of an IFS's linear parts A_i (D x D):
// min over L <= maxLength of max over words w of length L of ||A_w||_2^(1/L).
struct JointContraction {
    int length = 0;        // the L that gave the bound
    double factor = 0.0;
    // factor < 1: every composition of `length` maps is a Euclidean contraction, so the IFS
    // F^length is hyperbolic and F has a unique attractor (an eventually contractive IFS, 004
    // §3.5). Eventually contractive single maps alone do not guarantee this for a mixed IFS.
    bool contractive = false;
};
// Words up to maxWords per length are examined (N^L <= maxWords). Uses effectiveLinearPart.
JointContraction jointContraction(const Ifs &ifs, int maxLength = 12, double maxWords = 2e5);

// 002 §6: all maps of all curves acting on the plane together, {w_1, ..., w_2k}. Its attractor
// is a "dusty" fractal, not the union of the curves. Every curve must have plane maps (a
// quadratic with non-collinear control points, or a degree-elevated one); otherwise
// InputError names the curve and the reason.
struct CombinedBezierIfs {
    std::vector<BezierSplit> curves;
    Ifs ifs;                 // 2k maps on R^2, curve i gives maps 2i, 2i+1 (0-based)
    IfsCheck check;          // per map
    JointContraction joint;  // for the whole IFS
};
CombinedBezierIfs combinedBezierIfs(const std::vector<BezierCurveSpec> &curves);

// The exact union (000 §2.2): blockUnion of the curves' IFSs (plane or lifted), map i acting on
// each block by that curve's map i. One view per curve; the attractor seen through the views is
// the union of the curves. `start` (1 x D) is the concatenation of each curve's p_0.
struct BezierUnion {
    std::vector<BezierSplit> curves;
    Ifs ifs;
    RowVec start;
};
BezierUnion bezierUnion(const std::vector<BezierCurveSpec> &curves);

} // namespace awb
