#pragma once
// Boundary controlled IFS for curves (003 §2.3-§5): cells with barycentric spaces, subdivision
// operators, boundary operators ∂, and the incidence and adjacency equations that make the
// attractor a curve; the junction curve between a cubic and a quadratic B-spline (§3, §4.1),
// the refined junction with an interpolated vertex (§5), and the spectral verdict at the
// junction point (§4). toCifs() turns a BCIFS into the automaton of Cifs.h that draws it.
//
// Convention: as in 003 (and unlike the rest of the core), every operator here acts on
// COLUMN barycentric vectors. An operator from cell A to cell B is a matrix T (n_A x n_B) that
// maps B's space into A's: lambda_A = T lambda_B, and its columns sum to 1. A path
// o_1 o_2 .. o_k (o_1 leaves the first cell) composes to T_{o_1} T_{o_2} .. T_{o_k}, so the
// paper's equations read as written (T^l ∂^l_1 = T^i ∂^i_0). The core's row-convention
// matrix is S = T^T; toCifs() converts.

#include "core/ifs/Cifs.h"
#include "core/analysis/Spectrum.h"

namespace awb {

enum class CellKind { Model, Edge, Vertex };
enum class OperatorKind {
    Subdivision,  // edge -> edge or vertex -> vertex: T (n_from x n_to), columns sum to 1
    Boundary,     // edge -> vertex: ∂ (n_edge x n_vertex), the vertex's space in the edge's
    Placement     // model -> cell: P (d x n), its columns are the cell's control points
};
enum class ConstraintKind {
    Incidence,  // a vertex stays at the end of its edge when both are subdivided (§2.4)
    Adjacency,  // two consecutive pieces share their common vertex (§2.4)
    Junction    // two cells share control points in the modelling space (§3, eqs. (1), (4))
};
std::string toString(ConstraintKind kind);

struct BcifsCell {
    std::string name;
    CellKind kind = CellKind::Edge;
    int dim = 0;  // barycentric dimension (number of control points); d for the model cell
};

struct BcifsOperator {
    std::string name;
    OperatorKind kind = OperatorKind::Subdivision;
    int from = 0;
    int to = 0;
    Mat T;  // n_from x n_to (column convention)
};

// lhs and rhs are paths (operator indices) from the same cell to the same cell; the
// constraint is T_lhs = T_rhs.
struct BcifsConstraint {
    std::string name;  // the paper's label, e.g. "(8)"
    ConstraintKind kind = ConstraintKind::Incidence;
    std::vector<int> lhs, rhs;
};

struct Bcifs {
    std::vector<BcifsCell> cells;
    std::vector<BcifsOperator> operators;
    std::vector<BcifsConstraint> constraints;

    int addCell(std::string name, CellKind kind, int dim);
    int addOperator(std::string name, OperatorKind kind, const std::string &from,
                    const std::string &to, const Mat &T);
    // Paths by operator names; InputError for an unknown name.
    void addConstraint(std::string name, ConstraintKind kind,
                       const std::vector<std::string> &lhs, const std::vector<std::string> &rhs);

    int cellIndex(const std::string &name) const;      // InputError when unknown
    int operatorIndex(const std::string &name) const;  // InputError when unknown
    const Mat &matrix(const std::string &op) const;
    // Replace an operator's matrix (a user editing T^i); validate() judges it.
    void setMatrix(const std::string &op, const Mat &T);
    // "T^l ∂^l_1 = T^i ∂^i_0"
    std::string equation(const BcifsConstraint &c) const;

    // Throws InputError naming the problem: operator kinds joining the wrong cells, a matrix of
    // the wrong size (n_from x n_to), non-finite entries, a column of a subdivision or boundary
    // operator not summing to 1, an edge cell with no subdivision operator, a constraint whose
    // paths do not chain or do not join the same cells.
    void validate() const;
};

struct ConstraintResidual {
    std::string name;
    ConstraintKind kind = ConstraintKind::Incidence;
    std::string equation;
    double residual = 0.0;  // max |T_lhs - T_rhs| over the entries
    int row = 0, column = 0;  // 0-based entry where it is reached
};
struct ConstraintReport {
    std::vector<ConstraintResidual> residuals;  // one per constraint, in order
    bool satisfied = true;
    // Names the worst violated constraint with its size; empty when all hold.
    std::string message;
};
// Validates first. A constraint holds when its residual is <= tol.
ConstraintReport checkConstraints(const Bcifs &bcifs, double tol = 1e-12);

// The automaton that draws the edges: one state per edge cell (control points = the
// transposed placement P^T, n x d), one arc per subdivision operator between edges, with
// S = T^T. Boundary operators and vertex cells only constrain; they are not arcs. Throws
// InputError for an edge cell without a placement.
Cifs toCifs(const Bcifs &bcifs);

// ---- spectral analysis (003 §4) ----------------------------------------------------------

// How one side of a junction behaves at the fixed point of T (n x n, column convention). The
// copies of an initial curve are placed in T's space by C (n x m, its columns are the copy's
// control points). The points of the k-th copy are v_1 + sum_j c_j lambda_j^k v_j, so the
// eigenvalue that governs the side is the largest one (after 1) whose eigenvector has a
// non-zero component c_j in the copy; when the copy has none along the subdominant
// eigenvector the next one takes over (003 §4).
struct HalfTangent {
    SubdominantKind kind = SubdominantKind::None;
    std::vector<Complex> values;  // the governing eigenvalue(s): T v = lambda v
    std::vector<CVec> vectors;    // their eigenvectors (n, summing to 0)
    bool skippedSubdominant = false;  // the copy has no component along T's subdominant one
    bool eigenbasisComplete = true;   // false: T is (nearly) defective, components not used
    // Real positive, simple eigenvalue only: the unit direction from the junction point towards
    // this side's copies, sign(c) v^T P (1 x d); without P, sign(c) v^T in T's space (1 x n).
    // Empty otherwise (no half-tangent).
    RowVec direction;
    std::string verdict;
};
// P: n x d control points (row convention) of T's space, or empty. InputError for sizes that
// do not match, non-finite entries, or columns of T or C not summing to 1.
HalfTangent halfTangent(const Mat &T, const Mat &C, const Mat &P = Mat());

// Half-tangents that are opposite within angleTol radians make the curve G1 at the point.
bool isG1(const HalfTangent &left, const HalfTangent &right, double angleTol = 1e-9);

// ---- the junction of 003 §3-§4.1 ---------------------------------------------------------

// The left curve's right vertex subdivision V^l (n_l x n_l), the right curve's left vertex
// subdivision V^r (n_r x n_r) and the free columns X (n x (m_l - n_l)), Y (n x (m_r - n_r)),
// n = n_l + n_r, fix (eqs. (2), (5), (7), (8)):
//   T^l = [ [V^l; 0] | X ]  (n x m_l),   T^r = [ Y | [0; V^r] ]  (n x m_r),
//   T^i = [ last n_l columns of T^l | first n_r columns of T^r ]  (n x n).
struct JunctionMatrices {
    Mat Tl, Tr, Ti;
};
JunctionMatrices junctionMatrices(const Mat &Vl, const Mat &Vr, const Mat &X, const Mat &Y);

// One initial curve of a junction: its two subdivision operators (003's column convention,
// m x m), the dimension of its vertex space, and its control points (m x d, rows).
struct JunctionCurve {
    Mat T0, T1;
    int vertexDim = 0;
    Mat P;
};
// The BCIFS of 003 Fig. 14: cells model, l, r, vl, vr, i; operators L0, L1, R0, R1, V^l, V^r,
// ∂^l_0, ∂^l_1, ∂^r_0, ∂^r_1, ∂^i_0, ∂^i_1, T^l, T^r, T^i, P^l, P^r, P^i (P^i from eqs. (1),
// (4): the last n_l rows of left.P, then the first n_r of right.P); constraints (1)-(8) and
// each curve's own incidence and adjacency equations (§2.4). The vertex subdivisions are read
// from the curves: V^l = last n_l x n_l block of L1, V^r = first n_r x n_r block of R0.
// X: n x (m_l - n_l), Y: n x (m_r - n_r) as for junctionMatrices().
Bcifs junctionBcifs(const JunctionCurve &left, const JunctionCurve &right, const Mat &X,
                    const Mat &Y);

// The free parameters of 003 §4.1: X = (a, b, c, d, e)^T is T^l's last column and
// Y = (k, l, m, n, p)^T is T^r's first column; e and p follow from the column sums = 1.
// The defaults are Fig. 16 (top).
struct JunctionParameters {
    double a = 0.131, b = 0.2, c = 0.38, d = 0.289;
    double k = 0.11, l = 0.12, m = 0.1, n = 0.12;
    double e() const { return 1.0 - a - b - c - d; }
    double p() const { return 1.0 - k - l - m - n; }
};
// The cubic (4 control points) and quadratic (3) uniform B-spline curves of §4.1, from the
// core's schemes (T = S^T): T^l 5 x 4, T^r 5 x 3, T^i 5 x 5. InputError for non-finite
// parameters.
JunctionCurve cubicCurve(const Mat &P);      // P: 4 x d
JunctionCurve quadraticCurve(const Mat &P);  // P: 3 x d
JunctionMatrices cubicQuadraticMatrices(const JunctionParameters &p);
Bcifs cubicQuadraticJunction(const JunctionParameters &p, const Mat &Pl, const Mat &Pr);

struct JunctionAnalysis {
    Spectrum spectrum;        // of T^i, column convention: T^i v = lambda v
    Subdominant subdominant;  // the paper's lambda_2 and its eigenvector(s)
    HalfTangent left, right;  // the copies T^l C_l and T^r C_r
    bool g1 = false;
    std::string verdict;
};
// Pi: n x d control points of the junction (row convention) or empty.
JunctionAnalysis analyseJunction(const JunctionMatrices &m, const Mat &Pi = Mat());
// For a GUI dragging the free parameters: the spectrum for these a..d, k..n. With control
// points (Pl: 4 x d, Pr: 3 x d) the half-tangents also get plane directions.
JunctionAnalysis analyseCubicQuadratic(const JunctionParameters &p, const Mat &Pl = Mat(),
                                       const Mat &Pr = Mat());

// ---- the refined junction of 003 §5 ------------------------------------------------------

// j controls T^il's tangent eigenvalue, r that of T^ir. Admissible: j in (0.5, 1),
// r in (0.25, 1); the bounds are computed, see refinedRangeJ() and refinedRangeR().
struct RefinedParameters {
    double j = 0.75;
    double r = 0.5;
};
struct ParameterRange {
    double lo = 0.0, hi = 1.0;  // open interval
    std::string why;
};
// j (or r) is subdominant iff it exceeds every other eigenvalue of T^il (T^ir), which belong
// to its fixed block (the vertex subdivision part), and the map contracts iff it is < 1.
ParameterRange refinedRangeJ();
ParameterRange refinedRangeR();
// InputError naming the parameter, its value and its range when j or r is not admissible.
void checkRefinedParameters(const RefinedParameters &p);

// 003 §5 with a, b, c, e, f, g, h = 0, d = 1 (T^l's free column = e_4, T^r's = e_2):
//   T^l 5 x 4, T^il 5 x 5 = [[1/8,0,0,0,0],[3/4,1/2,0,0,0],[1/8,1/2,0,0,0],[0,0,1,j,0],
//   [0,0,0,1-j,1]], T^r 4 x 3, T^ir 4 x 4 = [[1,1-r,0,0],[0,r,1,0],[0,0,0,3/4],[0,0,0,1/4]].
struct RefinedMatrices {
    Mat Tl, Til, Tr, Tir;
};
RefinedMatrices refinedMatrices(const RefinedParameters &p);
// Cells model, l, r, il, ir, vl, vr, vi (Fig. 17). Pl: 4 x d cubic, Pr: 3 x d quadratic,
// handles: 3 x d rows = left tangent handle, interpolated vertex, right tangent handle.
// il's control points (5 x d) are the cubic's last three, the left handle and the vertex;
// ir's (4 x d) the vertex, the right handle and the quadratic's first two.
Bcifs refinedJunction(const RefinedParameters &p, const Mat &Pl, const Mat &Pr,
                      const Mat &handles);

struct RefinedAnalysis {
    Spectrum left, right;     // of T^il and T^ir
    HalfTangent leftTangent;  // governed by T^il on the copy T^l (expected: j, e_4 - e_5)
    HalfTangent rightTangent; // governed by T^ir on the copy T^r (expected: r, e_1 - e_2)
    bool g1 = false;          // the two half-tangents are opposite (three handles aligned)
    std::string verdict;
};
// The control points are optional (all empty: directions in each barycentric space, no G1).
RefinedAnalysis analyseRefined(const RefinedParameters &p, const Mat &Pl = Mat(),
                               const Mat &Pr = Mat(), const Mat &handles = Mat());

} // namespace awb
