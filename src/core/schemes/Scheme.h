#pragma once
// Stationary curve subdivision schemes and their IFS matrices (000 §2, 004 §2 and §3.6).
//
// For m control points a scheme yields the square matrices S_1..S_p (p = arity), each m x m and
// row-stochastic, such that S_j P are the control points of the j-th of the p self-similar
// pieces of the limit curve. Consecutive pieces share `overlap` rows (the last rows of S_j equal
// the first rows of S_{j+1}); this is the overlapping-rows split of 000 §2.

#include "core/Messages.h"
#include "core/schemes/Curves.h"
#include "core/Types.h"

#include <climits>
#include <memory>
#include <optional>

namespace awb {

struct SubdivisionMatrices {
    std::vector<Mat> S;  // S_1..S_p, each m x m
    int overlap = 0;     // rows shared by consecutive pieces
    // One step of classic subdivision: the pieces S_1 P, .., S_p P joined (shared rows once).
    Mat refinement() const;
};

class CurveScheme {
public:
    virtual ~CurveScheme() = default;
    virtual std::string name() const = 0;
    virtual int arity() const = 0;
    virtual int minControlPoints() const = 0;
    virtual int maxControlPoints() const { return INT_MAX; }
    // Throws InputError when m is not an acceptable number of control points.
    virtual SubdivisionMatrices matrices(int m) const = 0;
    // Points on the exact limit curve (samples x d) when the scheme has a closed form
    // (B-splines, Bézier); std::nullopt otherwise (four-point, user masks, ...).
    virtual std::optional<Mat> exactCurve(const Mat &P, int samples) const;
    // The same curve exactly, as the Bézier control points of its polynomial pieces (each
    // (n+1) x d, in order along the curve); std::nullopt where exactCurve() has no closed form.
    virtual std::optional<std::vector<Mat>> bezierPieces(const Mat &P) const;

    void requireControlPointCount(int m) const;
};

// One rule of a uniform p-ary scheme: new point (p*i + r) = sum_j weights[j] * old point
// (i + offset + j). A scheme has one rule for each residue r = 0..p-1.
struct SchemeRule {
    int offset = 0;
    std::vector<double> weights;
};

// A uniform stationary scheme of any arity given by its rules (equivalently its mask a[k]:
// q_n = sum_l a[n - p l] p_l). Open curves: only refined points whose whole stencil lies
// inside the control polygon are kept.
class UniformScheme : public CurveScheme {
public:
    // Validates that every rule's weights sum to 1 (InputError names the rule otherwise).
    UniformScheme(std::string name, int arity, std::vector<SchemeRule> rules);

    std::string name() const override { return m_name; }
    int arity() const override { return m_arity; }
    int minControlPoints() const override;
    SubdivisionMatrices matrices(int m) const override;
    std::optional<Mat> exactCurve(const Mat &P, int samples) const override;
    std::optional<std::vector<Mat>> bezierPieces(const Mat &P) const override;

    const std::vector<SchemeRule> &rules() const { return m_rules; }
    // The mask a[k0 .. k1] (padded with zeros so that (p-1) divides k1 - k0).
    const std::vector<double> &mask() const { return m_mask; }
    int maskStart() const { return m_k0; }
    // The refinement matrix of one classic subdivision step on m points (all valid rows).
    Mat refinementMatrix(int m) const;

    // Set by bsplineScheme(): the limit curve is the uniform B-spline of this degree.
    void setBSplineDegree(int degree) { m_bsplineDegree = degree; }
    int bsplineDegree() const { return m_bsplineDegree; }

private:
    int firstRow() const;   // refined index of the first row of S_1
    int pieceShift(int m) const;

    std::string m_name;
    int m_arity;
    std::vector<SchemeRule> m_rules;
    std::vector<double> m_mask;
    int m_k0 = 0;
    int m_bsplineDegree = -1;
};

// Uniform B-spline of degree 1..15 by Lane-Riesenfeld, 004 eq. (2.7).
UniformScheme bsplineScheme(int degree);
// Corner cutting: on each edge (p_i, p_{i+1}) new points at parameters a and b, 0 < a < b < 1.
// Chaikin is a = 1/4, b = 3/4 (= quadratic B-spline, 004 eq. (3.27)).
UniformScheme cornerCuttingScheme(double a, double b);
UniformScheme chaikinScheme();
// Dyn-Levin-Gregory four-point scheme with tension omega, 004 eq. (2.10); 1/16 is the classic.
UniformScheme fourPointScheme(double omega);
// The uniform scheme of arity N >= 2 with the mask a_k, k = offset .. offset + size - 1:
// q_n = sum_l a_{n - N l} p_l (symbol a(z) = sum_k a_k z^k). Each of the N cosets
// {a_k : k = r mod N} must sum to 1 (the scheme reproduces constants); an InputError names
// the first coset that does not, and its sum. The cubic B-spline is (1 4 6 4 1)/8 from -2.
UniformScheme maskScheme(int arity, const std::vector<double> &mask, int offset);

// The de Casteljau split of a Bézier curve of degree n at a real t in (0, 1):
// S_1 = L(t), S_2 = R(t), m = n + 1 (004 eq. (2.5), 000 §2.2).
class BezierScheme : public CurveScheme {
public:
    BezierScheme(int degree, double t = 0.5);
    std::string name() const override;
    int arity() const override { return 2; }
    int minControlPoints() const override { return m_degree + 1; }
    int maxControlPoints() const override { return m_degree + 1; }
    SubdivisionMatrices matrices(int m) const override;
    std::optional<Mat> exactCurve(const Mat &P, int samples) const override;
    std::optional<std::vector<Mat>> bezierPieces(const Mat &P) const override;
    int degree() const { return m_degree; }
    double t() const { return m_t; }

private:
    int m_degree;
    double m_t;
};

// B-spline of degree n whose end knots have multiplicity n (it interpolates its end points):
// knots {0^n, 1, .., N-1, N^n}, N = m - n. Each half is again such a curve: S_1, S_2 come from
// knot insertion (blossoming) with the middle knot made n-fold, as in 000 §2.1.
class EndInterpolatingBSplineScheme : public CurveScheme {
public:
    explicit EndInterpolatingBSplineScheme(int degree = 3);
    std::string name() const override;
    int arity() const override { return 2; }
    int minControlPoints() const override { return m_degree + 1; }
    SubdivisionMatrices matrices(int m) const override;
    std::optional<Mat> exactCurve(const Mat &P, int samples) const override;
    std::optional<std::vector<Mat>> bezierPieces(const Mat &P) const override;
    int degree() const { return m_degree; }

private:
    int m_degree;
};

// The user's own S_1..S_p (all m x m, rows summing to 1): any arity.
class MatrixScheme : public CurveScheme {
public:
    explicit MatrixScheme(std::vector<Mat> S,
                          std::string name = coreTranslate("awb::schemes", "user matrices"));
    std::string name() const override { return m_name; }
    int arity() const override { return int(m_S.size()); }
    int minControlPoints() const override { return int(m_S.front().rows()); }
    int maxControlPoints() const override { return int(m_S.front().rows()); }
    SubdivisionMatrices matrices(int m) const override;

private:
    std::vector<Mat> m_S;
    std::string m_name;
    int m_overlap = 0;
};

// Classic subdivision: k steps applied to the control polygon P (m x d). Level k is the join of
// the pieces S_w P over all words w of length k, in curve order.
Mat subdivide(const CurveScheme &scheme, const Mat &P, int steps);

// Largest number of leading rows of `next` that equal trailing rows of `prev` (to 1e-12).
int sharedRows(const Mat &prev, const Mat &next);

} // namespace awb
