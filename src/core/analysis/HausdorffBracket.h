#pragma once
// Certified Hausdorff distance between a finite point set A (an attractor at some depth) and an
// exact plane curve C = c([0, 1]), as brackets [lower, upper] that contain the true value.
// Sampling the curve at a fixed number of parameters measures the sampling below that
// resolution; here the curve is refined adaptively where the answer depends on it.
//
// Certified curve. A curve is given by enclosures of its pieces: for a parameter interval
// [t0, t1] a "capsule", the chord [c(t0), c(t1)] thickened by a radius e, that holds c([t0, t1])
// (CurvePiece). Since the piece is continuous and joins the chord's ends, its projection onto
// the chord's line covers the chord, so every chord point is also within e of the piece. Hence
// for every point a:   |dist(a, c([t0, t1])) - dist(a, chord)| <= e.
// Implementations:
//  - BezierPiecesCurve: polynomial pieces by their Bézier control points (B-splines, Bézier
//    and end-interpolating B-splines converted exactly, CurveScheme::bezierPieces). The control
//    points of a sub-interval come from de Casteljau splits; the piece lies in their convex
//    hull, and distance to the chord is convex, so e = max_k dist(Q_k, chord).
//  - TakagiImageCurve: c(x + 2 i y T(x)), c a Bézier curve with complex control points, T the
//    Takagi function (004 §3.7, Conj. 3.7.1). On a dyadic interval I of length 2^-m,
//    T(x) = T_m(x) + 2^-m T(2^m x - j) with T_m linear on I and 0 <= T <= 2/3, so z(I) lies in
//    the parallelogram chord_z + 2 i y 2^-m [0, 2/3]; c maps it within
//    |c'(z_mid)| V + (K / 2)((h + V)^2 + h^2) of the chord (Taylor at the chord's midpoint,
//    h = |z1 - z0| / 2, V = (4/3)|y| 2^-m, K >= sup |c''| from the Bernstein form).
// Every radius carries an allowance for the rounding of the evaluation.
//
// The brackets (hausdorffBracket):
//  - oneSided = sup_{a in A} dist(a, C): per point [min_I (d_I - e_I), min_I (d_I + e_I)] over
//    the pieces I; points whose upper bound falls below the best lower bound are dropped, and
//    the pieces near the remaining ones are split until the bracket is narrow enough.
//  - curveToPoints = sup_t dist(c(t), A): branch and bound over pieces; a piece's lower bound
//    is dist(c(t_k), A) at its ends (curve points), its upper bound dist(q, A) + |chord| / 2 + e
//    (q the chord's midpoint; dist(., A) is 1-Lipschitz) or, with a the point of A nearest to
//    an end or to q, max(|c(t0) - a|, |c(t1) - a|) + e (the distance to one point is convex).
//  - value = d_H(A, C) = max(oneSided, curveToPoints), bracketed by the max of the brackets.
// All three satisfy lower <= true <= upper whether or not the requested width was reached.

#include "core/Types.h"

#include <atomic>
#include <memory>

namespace awb {

// An enclosure of c([t0, t1]): every curve point of the interval lies within `radius` of the
// segment [a, b], a = c(t0), b = c(t1).
struct CurvePiece {
    double t0 = 0.0, t1 = 0.0;
    Eigen::Vector2d a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero();
    double radius = 0.0;
};

class CertifiedCurve {
public:
    virtual ~CertifiedCurve() = default;
    // The parameters 0 = b_0 < .. < b_k = 1 at which pieces may start: every interval asked of
    // enclose() lies within one [b_i, b_i+1] and is a bisection of it.
    virtual std::vector<double> breaks() const = 0;
    virtual Eigen::Vector2d point(double t) const = 0;
    virtual CurvePiece enclose(double t0, double t1) const = 0;
    // Bound on the rounding error of point() (also included in every enclosure's radius).
    double allowance() const { return m_allowance; }

protected:
    double m_allowance = 0.0;
};

// Polynomial pieces given by Bézier control points (each (n+1) x 2, n >= 1, n <= 30); piece i
// covers t in [i / k, (i+1) / k]. InputError for no pieces, a wrong shape or non-finite data.
class BezierPiecesCurve : public CertifiedCurve {
public:
    explicit BezierPiecesCurve(std::vector<Mat> pieces);
    std::vector<double> breaks() const override;
    Eigen::Vector2d point(double t) const override;
    CurvePiece enclose(double t0, double t1) const override;

private:
    int pieceOf(double t) const;
    std::vector<Mat> m_pieces;
};

// The Takagi image x |-> c(x + 2 i y T(x)), x in [0, 1], of 004 Conj. 3.7.1: c the Bézier curve
// of the complex control points P (n + 1 >= 2 of them) evaluated at complex parameters, plane
// point (Re, Im). y = 0 gives c([0, 1]). Intervals must be dyadic (bisections of [0, 1]).
// InputError for non-finite data, fewer than 2 or more than 31 control points, |y| > 1.
class TakagiImageCurve : public CertifiedCurve {
public:
    TakagiImageCurve(const CVec &P, double y);
    std::vector<double> breaks() const override { return {0.0, 1.0}; }
    Eigen::Vector2d point(double t) const override;
    CurvePiece enclose(double t0, double t1) const override;

private:
    Complex z(double x) const;  // x + 2 i y T(x), T exact at dyadics
    CVec m_P, m_d1, m_d2;       // control points, and those of c' and c''
    double m_y = 0.0;
    double m_secondBound = 0.0; // sup |c''| on the band 0 <= Re z <= 1, |Im z| <= (8/3)|y|
};

struct DistanceBracket {
    double lower = 0.0, upper = 0.0;
    double mid() const { return 0.5 * (lower + upper); }
    // (upper - lower) / upper, 0 when both are 0.
    double relativeWidth() const;
};

struct HausdorffBracketOptions {
    double relativeWidth = 1e-3;  // requested (upper - lower) / upper for each bracket
    // Stop refining (and report the bracket reached) beyond this many curve enclosures.
    long maxEnclosures = 20'000'000;
    // Polled during the refinement: when it turns true the brackets reached so far are
    // returned (still certified, converged = false).
    const std::atomic<bool> *cancel = nullptr;
};

struct HausdorffBracket {
    DistanceBracket value;          // d_H(A, C) = max(oneSided, curveToPoints)
    DistanceBracket oneSided;       // sup over a in A of dist(a, C)
    DistanceBracket curveToPoints;  // sup over t of dist(c(t), A)
    double width = 0.0;             // the largest relative width of the three brackets
    bool converged = false;         // every bracket reached the requested width
    long enclosures = 0;            // curve enclosures computed
};

// A: n x 2 points (n >= 1). InputError for an empty or non-planar A or non-finite points.
HausdorffBracket hausdorffBracket(const Mat &A, const CertifiedCurve &curve,
                                  const HausdorffBracketOptions &options = {});

} // namespace awb
