#pragma once
// Complex de Casteljau IFS and the Takagi curve (004 §3.7: L. Ptáčková, "Fractals and
// Splines", 2012). Role in the core: the IFS of a Bézier curve whose split parameter t is
// complex, realified so that the ordinary attractor machinery (Attractor.h) draws it; the
// hyperbolicity report for t; the Takagi function and the measurements behind Theorem 3.7.3
// and Conjecture 3.7.1.
//
// Construction (complexBezierIfs). Control points p_0..p_n in C (n >= 1), S_1 = L(t),
// S_2 = R(t) the (n+1) x (n+1) de Casteljau matrices of 004 eq. (2.5) with complex t. As in
// 000 §2 the control points are lifted to an invertible (n+1) x (n+1) complex matrix
//     P^ = [p | identity columns | ones],
// the identity entries sitting in every row except two "free" rows a, b; det P^ = ±(p_a - p_b),
// so any two distinct control points will do (000's choice is the last two; another pair is
// taken when those coincide). Then M_i = P^-1 S_i P^ = [[A_i, 0], [b_i, 1]] (row convention;
// the transpose of 004 eq. (3.28)), A_i: n x n complex, b_i: 1 x n. realify() turns z |-> z A_i
// + b_i on C^n into a real map on R^{2n} (coordinates Re z_1, Im z_1, ...), and the view
// (Re z_1, Im z_1) shows the curve point. The lifted p_0 (row 0 of P^) is the fixed point of f_1.
//
// Why the attractor is the "complex Bézier curve": L(t) P and R(t) P are the Bézier control
// points of the polynomials α |-> c(t α) and α |-> c(t + (1-t) α), identities that hold for
// complex t. So the point of address w is exactly c(φ_w(0)), φ_1(α) = t α, φ_2(α) = (1-t) α + t
// being the degree-1 maps of eq. (3.30): the attractor is c(A_1), A_1 that of eq. (3.30).
// The eigenvalues of A_1 are t, t^2, .., t^n and of A_2 (1-t), .., (1-t)^n, so every degree is
// hyperbolic (eventually contractive) exactly when |t| < 1 and |1 - t| < 1 (004 Fig. 3.3).

#include "core/ifs/Ifs.h"

#include <array>

namespace awb {

// Where t lies relative to the two discs of 004 Fig. 3.3.
struct ParameterReport {
    Complex t;
    double modT = 0.0;          // |t|: contraction factor of f_1(z) = t z
    double modOneMinusT = 0.0;  // |1 - t|: contraction factor of f_2(z) = (1 - t) z + t
    bool insideT = false;       // |t| < 1
    bool insideOneMinusT = false;  // |1 - t| < 1
    bool hyperbolic = false;    // both: the IFS has a unique attractor (Theorem 3.7.2: connected)
    double slowestFactor = 0.0; // max(|t|, |1 - t|)
    std::string message;        // where t lies and, if not hyperbolic, which condition fails
    // Levels of deterministic iteration after which all pieces have shrunk to `factor`
    // (slowestFactor^k <= factor); -1 when not hyperbolic.
    int levelsFor(double factor) const;
};
// Never throws for a finite t (a t on or outside the discs is reported, not an error); a
// non-finite t is an InputError. |t| within 1e-12 of 1 counts as on the circle.
ParameterReport classifyParameter(Complex t);

// The two maps of eq. (3.30), f_1(z) = t z and f_2(z) = (1 - t) z + t, realified on R^2
// (A: 2 x 2, b: 1 x 2), view = identity. Built even when t is not hyperbolic.
Ifs deCasteljauSegmentIfs(Complex t);

// The complex de Casteljau IFS of any degree (see the construction above).
struct ComplexBezierIfs {
    CVec controlPoints;          // n + 1
    Complex t;
    ParameterReport parameter;
    std::array<CMat, 2> S;       // L(t), R(t): (n+1) x (n+1)
    std::array<int, 2> freeRows{0, 0};  // rows a, b of the lifting without identity entries
    CMat lifted;                 // P^: (n+1) x (n+1)
    std::array<CMat, 2> M;       // P^-1 S_i P^: (n+1) x (n+1)
    Ifs ifs;                     // two realified maps on R^{2n}, one view (2n x 2)
    RowVec start;                // lifted p_0, realified: 1 x 2n (fixed point of f_1)
    int degree() const { return int(controlPoints.size()) - 1; }
};
// Throws InputError for fewer than 2 control points (degree < 1), non-finite numbers, or all
// control points equal (the curve is one point, no lifting exists). A non-hyperbolic t is not
// an error: the IFS is built and parameter.message says why it has no attractor.
ComplexBezierIfs complexBezierIfs(const CVec &P, Complex t);

// The 2^depth points f_w(start) for all words w of length depth, in code order: index
// j = sum_k d_k 2^(depth-k) with d_1 the map applied last (so j / 2^depth = r(d), eq. (3.31)).
// They lie on the attractor. Throws InputError (with parameter.message) when t is not
// hyperbolic, or depth outside 0..24.
std::vector<Complex> attractorPoints(const ComplexBezierIfs &ifs, int depth);

// ---- Takagi (004 §3.7.1) -------------------------------------------------------------------

// T(x) = sum_{n=0}^{terms-1} σ(2^n x) / 2^n, σ = distance to the nearest integer. The
// truncation error is at most takagiTruncationBound(terms) = 2^-terms (σ <= 1/2); the sum is
// exact for a dyadic x = j / 2^N once terms >= N. InputError for non-finite x or terms < 0.
double takagi(double x, int terms = 64);
double takagiTruncationBound(int terms);

// g(z, s) = Re z + i s Im z, eq. (3.40). Theorem 3.7.3 scales with s = 1 / (2y).
Complex takagiScaling(Complex z, double s);

// Binary code d = [d_1..d_n] (each 0 or 1, n <= 60): r(d) of eq. (3.31), u(d) of eq. (3.32).
double dyadicValue(const std::vector<int> &d);
int onesCount(const std::vector<int> &d);
// s(d) of Lemma 3.7.2, computed as the paper defines it: the first coordinate of
// M(d_1) M(d_2) .. M(d_n) (0, 1)^T with the 2 x 2 matrices M(0) = [[t, 0], [0, 1]],
// M(1) = [[1-t, t], [0, 1]] of eq. (3.29). Any finite t.
Complex lemmaPoint(const std::vector<int> &d, Complex t);

// Theorem 3.7.3 / eq. (3.42) for t = 1/2 + i y, measured on the 2^depth points s(d) of the
// attractor A*(y) against the Takagi graph at the same dyadics r(d):
struct TakagiComparison {
    double y = 0.0;
    int depth = 0;
    // max_d |g(s(d), 1/(2y)) - (r(d) + i T(r(d)))|. Both sets are the closures of these point
    // families, so as depth grows this bounds d_H(g(A*(y), 1/(2y)), T) from above. It is
    // O(y^2): Re s(d) is even in y and Im s(d) odd (s(d)(-y) = conj s(d)(y)), so Re s = r +
    // O(y^2) and Im s / (2y) = T(r) + O(y^2), uniformly in d.
    double scaledError = 0.0;
    double realError = 0.0;       // max |Re s(d) - r(d)|
    double imagScaledError = 0.0; // max |Im s(d) / (2y) - T(r(d))|
    double unscaledError = 0.0;   // max |s(d) - (r + 2 i y T(r))|: the quantity of eq. (3.42)
    double hausdorffScaled = 0.0; // d_H between the two 2^depth point sets, scaled plane
};
// InputError unless y is finite, nonzero and t = 1/2 + i y hyperbolic (|y| < sqrt(3)/2), and
// depth in 1..24.
TakagiComparison compareWithTakagi(double y, int depth = 16);

// Conjecture 3.7.1, eq. (3.43), for control points P (degree n) and t = 1/2 + i y: A*(y)
// against c(g(T, 2y)) = {c(x + 2 i y T(x))}, c the Bézier curve of P at complex parameters.
struct ConjectureComparison {
    double y = 0.0;
    int depth = 0;
    // max over codes of |point of A*(y) - c(s(d))|, s(d) from the degree-1 IFS: the exact
    // identity A*(y) = c(A_1(y)) explained above (rounding only).
    double identityError = 0.0;
    // max_d |point of A*(y) - c(r(d) + 2 i y T(r(d)))|: an upper bound on d_H of (3.43) as
    // depth grows; at most Lip(c) times TakagiComparison::unscaledError, hence O(y^2).
    double toTakagiImage = 0.0;
    double hausdorffToTakagiImage = 0.0;  // d_H between the two 2^depth point sets
    // d_H(A*(y), c([0, 1])): the plain curve is already O(y) away, so the O(y) of (3.43)
    // alone does not see the Takagi structure; only O(y^2) does.
    double toPlainCurve = 0.0;
};
ConjectureComparison compareConjecture(const CVec &P, double y, int depth = 14);

// The Takagi image of Conjecture 3.7.1 as a polyline: the 2^depth + 1 points
// c(x_j + 2 i y T(x_j)), x_j = j / 2^depth, c the Bézier curve of P at complex parameters (T is
// exact at these dyadics). For P = (0, 1) it is the graph x + 2 i y T(x), which the attractor of
// t = 1/2 + i y approaches as O(y^2) (TakagiComparison). Any finite y (y = 0 gives the plain
// curve c([0, 1])); InputError for fewer than 2 control points, non-finite input, depth outside
// 1..20.
std::vector<Complex> takagiImage(const CVec &P, double y, int depth = 10);

// 004 Example 3.7.3: p_0 = 0, p_1 = 1/2 + 2i, p_2 = 1/2 (the thesis uses y = 10^-2).
CVec example373ControlPoints();

} // namespace awb
