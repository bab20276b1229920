#pragma once
// Exact curves the attractors are measured against: Bernstein/Bézier (de Casteljau, real or
// complex parameter) and B-splines of any degree and knot vector (blossoms, de Boor).
// Also the de Casteljau subdivision matrices L(t), R(t) of 004 eq. (2.5).

#include "core/Types.h"

namespace awb {

// B_i^n(t), 004 eq. (1.1).
double bernstein(int n, int i, double t);
Complex bernstein(int n, int i, Complex t);

// de Casteljau split matrices of degree n ((n+1) x (n+1)), 004 eq. (2.5):
// L(t) P = control points of the piece [0, t], R(t) P = those of [t, 1].
Mat deCasteljauL(int n, double t);
Mat deCasteljauR(int n, double t);
CMat deCasteljauL(int n, Complex t);
CMat deCasteljauR(int n, Complex t);

// Points of the Bézier curve with control points P ((n+1) x d) at the given parameters.
// Returns params.size() x d.
Mat bezierPoints(const Mat &P, const std::vector<double> &params);
// n+1 complex control points (column), complex parameters: the complex Bézier curve of 004 §3.7.
CVec bezierPoints(const CVec &P, const std::vector<Complex> &params);

// A B-spline in Ramshaw's (blossom) labelling: knots t_0..t_{m+n-2} (m + n - 1 of them,
// nondecreasing), control point P_i = f(t_i, ..., t_{i+n-1}). The curve is defined on
// [t_{n-1}, t_{m-1}]. The uniform cubic B-spline on 5 points has knots 0..6 and lives on [2, 4];
// the end-interpolating cubic of 000 §2.1 has knots {0,0,0,1,2,2,2}.
class BSplineBasis {
public:
    BSplineBasis(int degree, std::vector<double> knots); // throws InputError
    static BSplineBasis uniform(int degree, int m);
    static BSplineBasis endInterpolating(int degree, int m); // knots {0^n, 1, ..., N-1, N^n}

    int degree() const { return m_degree; }
    int controlPointCount() const { return int(m_knots.size()) - m_degree + 1; }
    const std::vector<double> &knots() const { return m_knots; }
    double domainStart() const { return m_knots[m_degree - 1]; }
    double domainEnd() const { return m_knots[controlPointCount() - 1]; }

    // Weights w (1 x m, summing to 1) with f(u_1..u_n) = w P, the blossom of the polynomial
    // piece on the nondegenerate span [t_J, t_{J+1}] (J in [n-1, m-2]).
    RowVec blossomWeights(const std::vector<double> &u, int span) const;
    // Span index J containing parameter x of the domain (last span for x = domainEnd()).
    int spanOf(double x) const;
    // Weights of the curve point at x: c(x) = weights(x) P.
    RowVec pointWeights(double x) const;
    // Matrix K (m' x m) with Q = K P the control points of the same curve over the finer
    // knot vector `finer` (which must contain these knots, each with at least its multiplicity).
    Mat insertionMatrix(const std::vector<double> &finer) const;

    // samples points of the curve, evenly spaced in the parameter: samples x d.
    Mat curve(const Mat &P, int samples) const;
    // The exact Bézier control points ((n+1) x d each) of the polynomial pieces on the
    // nondegenerate spans of the domain, in order: row k is the blossom f(a^(n-k), b^k) of the
    // span [a, b] (Ramshaw). Together they are the whole curve.
    std::vector<Mat> bezierPieces(const Mat &P) const;

private:
    int m_degree;
    std::vector<double> m_knots;
};

} // namespace awb
