#include "core/analysis/HausdorffBracket.h"

#include "core/Messages.h"
#include "core/analysis/Geometry.h"
#include "core/schemes/ComplexBezier.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <vector>

namespace awb {

namespace {

using V2 = Eigen::Vector2d;
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kInf = std::numeric_limits<double>::infinity();

double pointSegment(const V2 &p, const V2 &a, const V2 &b)
{
    const V2 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + t * ab)).norm();
}

// de Casteljau on the rows of Q (real or complex), in place: Q becomes the control points of
// [0, u] and the returned rows those of [u, 1] (in order).
template <typename M, typename S>
M splitAt(M &Q, S u)
{
    const Eigen::Index n = Q.rows() - 1;
    M right(Q.rows(), Q.cols());
    M work = Q;
    right.row(n) = work.row(n);
    Q.row(0) = work.row(0);
    for (Eigen::Index r = 1; r <= n; ++r) {
        for (Eigen::Index k = 0; k + r <= n; ++k)
            work.row(k) = (S(1) - u) * work.row(k) + u * work.row(k + 1);
        Q.row(r) = work.row(0);
        right.row(n - r) = work.row(n - r);
    }
    return right;
}

Complex deCasteljau(const CVec &P, Complex z)
{
    CVec w = P;
    for (Eigen::Index r = 1; r < w.size(); ++r)
        for (Eigen::Index k = 0; k + r < w.size(); ++k)
            w(k) = (1.0 - z) * w(k) + z * w(k + 1);
    return w(0);
}

V2 plane(Complex z) { return V2(z.real(), z.imag()); }

} // namespace

// ---- BezierPiecesCurve ---------------------------------------------------------------------

BezierPiecesCurve::BezierPiecesCurve(std::vector<Mat> pieces) : m_pieces(std::move(pieces))
{
    if (m_pieces.empty())
        throw InputError(coreTranslate("awb::analysis", "a curve needs at least one piece"));
    double scale = 0.0;
    Eigen::Index degree = 1;
    for (const Mat &Q : m_pieces) {
        if (Q.cols() != 2 || Q.rows() < 2 || Q.rows() > 31)
            throw InputError(coreTranslate("awb::analysis", "a Bézier piece needs 2 to 31 plane "
                                                            "control points"));
        requireFinite(Q, coreTranslate("awb::analysis", "a Bézier piece"));
        scale = std::max(scale, Q.cwiseAbs().maxCoeff());
        degree = std::max(degree, Q.rows() - 1);
    }
    // Each de Casteljau level is a convex combination: the rounding of two splits and an
    // evaluation stays below a few (n + 1) eps |P|.
    m_allowance = 4.0 * double(degree + 1) * kEps * std::max(scale, 1e-300);
}

std::vector<double> BezierPiecesCurve::breaks() const
{
    std::vector<double> b;
    const double k = double(m_pieces.size());
    for (std::size_t i = 0; i <= m_pieces.size(); ++i)
        b.push_back(double(i) / k);
    return b;
}

int BezierPiecesCurve::pieceOf(double t) const
{
    const int k = int(m_pieces.size());
    return std::clamp(int(std::floor(t * k)), 0, k - 1);
}

Eigen::Vector2d BezierPiecesCurve::point(double t) const
{
    const int i = pieceOf(t);
    const double u = std::clamp(t * double(m_pieces.size()) - i, 0.0, 1.0);
    Mat w = m_pieces[std::size_t(i)];
    for (Eigen::Index r = 1; r < w.rows(); ++r)
        for (Eigen::Index k = 0; k + r < w.rows(); ++k)
            w.row(k) = (1.0 - u) * w.row(k) + u * w.row(k + 1);
    return w.row(0).transpose();
}

CurvePiece BezierPiecesCurve::enclose(double t0, double t1) const
{
    const double k = double(m_pieces.size());
    const int i = pieceOf(0.5 * (t0 + t1));
    const double u0 = std::clamp(t0 * k - i, 0.0, 1.0), u1 = std::clamp(t1 * k - i, 0.0, 1.0);
    Mat Q = m_pieces[std::size_t(i)];
    if (u1 < 1.0)
        splitAt(Q, u1);  // Q: [0, u1]
    if (u0 > 0.0)
        Q = splitAt(Q, u1 > 0.0 ? u0 / u1 : 0.0);  // [u0, u1]
    CurvePiece p;
    p.t0 = t0;
    p.t1 = t1;
    p.a = Q.row(0).transpose();
    p.b = Q.row(Q.rows() - 1).transpose();
    double e = 0.0;
    for (Eigen::Index r = 1; r + 1 < Q.rows(); ++r)
        e = std::max(e, pointSegment(Q.row(r).transpose(), p.a, p.b));
    p.radius = e * (1.0 + 1e-12) + 2.0 * m_allowance;
    return p;
}

// ---- TakagiImageCurve ----------------------------------------------------------------------

TakagiImageCurve::TakagiImageCurve(const CVec &P, double y) : m_P(P), m_y(y)
{
    if (P.size() < 2 || P.size() > 31)
        throw InputError(coreTranslate("awb::analysis", "a Takagi image needs 2 to 31 control "
                                                        "points"));
    requireFinite(CMat(P), coreTranslate("awb::analysis", "the control points"));
    if (!std::isfinite(y) || std::abs(y) > 1.0)
        throw InputError(coreTranslate("awb::analysis", "a Takagi image needs a finite |y| <= 1"));
    const Eigen::Index n = P.size() - 1;
    m_d1 = double(n) * (P.tail(n) - P.head(n));
    if (n >= 2) {
        m_d2 = double(n - 1) * (m_d1.tail(n - 1) - m_d1.head(n - 1));
        // |sum_k B_k(w) q_k| <= max |q_k| sum_k |B_k(w)| = max |q_k| (|w| + |1 - w|)^(n-2), and
        // |w| + |1 - w| <= 1 + 2 |Im w| for 0 <= Re w <= 1.
        const double band = 1.0 + 2.0 * (8.0 / 3.0) * std::abs(y);
        m_secondBound = m_d2.cwiseAbs().maxCoeff() * std::pow(band, double(n - 2));
        m_secondBound *= 1.0 + 1e-12;
    }
    const double band = 1.0 + 2.0 * (8.0 / 3.0) * std::abs(y);
    const double scale = P.cwiseAbs().maxCoeff() * std::pow(band, double(n));
    m_allowance = 8.0 * double(n + 1) * kEps * std::max(scale, 1e-300);
}

Complex TakagiImageCurve::z(double x) const
{
    return Complex(x, 2.0 * m_y * takagi(x, 64));
}

Eigen::Vector2d TakagiImageCurve::point(double t) const { return plane(deCasteljau(m_P, z(t))); }

CurvePiece TakagiImageCurve::enclose(double t0, double t1) const
{
    // On the dyadic I = [t0, t1] of length 2^-m: T = (linear through the ends) + 2^-m T(2^m x - j),
    // 0 <= T <= 2/3, so z(I) lies in {z0 + s (z1 - z0) + i v : s in [0, 1], v between 0 and V}.
    const Complex z0 = z(t0), z1 = z(t1), zm = 0.5 * (z0 + z1);
    const double V = (4.0 / 3.0) * std::abs(m_y) * (t1 - t0);
    const double h = 0.5 * std::abs(z1 - z0);
    double e = std::abs(deCasteljau(m_d1, zm)) * V;
    if (m_d2.size() > 0)
        e += 0.5 * m_secondBound * ((h + V) * (h + V) + h * h);
    CurvePiece p;
    p.t0 = t0;
    p.t1 = t1;
    p.a = plane(deCasteljau(m_P, z0));
    p.b = plane(deCasteljau(m_P, z1));
    p.radius = e * (1.0 + 1e-12) + 2.0 * m_allowance;
    return p;
}

// ---- brackets ------------------------------------------------------------------------------

double DistanceBracket::relativeWidth() const
{
    return upper > 0.0 ? (upper - lower) / upper : 0.0;
}

namespace {

// A bounding-volume tree over pieces kept in parameter order: consecutive pieces of a
// continuous curve are close in the plane, so pairing neighbours gives tight boxes.
class PieceTree {
public:
    explicit PieceTree(const std::vector<CurvePiece> &pieces) : m_pieces(pieces)
    {
        m_leaves = 1;
        while (m_leaves < pieces.size())
            m_leaves *= 2;
        m_lo.assign(2 * m_leaves, V2::Constant(kInf));
        m_hi.assign(2 * m_leaves, V2::Constant(-kInf));
        for (std::size_t i = 0; i < pieces.size(); ++i) {
            const CurvePiece &p = pieces[i];
            m_lo[m_leaves + i] = p.a.cwiseMin(p.b).array() - p.radius;
            m_hi[m_leaves + i] = p.a.cwiseMax(p.b).array() + p.radius;
        }
        for (std::size_t k = m_leaves - 1; k >= 1; --k) {
            m_lo[k] = m_lo[2 * k].cwiseMin(m_lo[2 * k + 1]);
            m_hi[k] = m_hi[2 * k].cwiseMax(m_hi[2 * k + 1]);
        }
    }

    // Calls visit(piece index, chord distance) for every piece whose capsule might lie within
    // `limit()` of q (limit() is read again as the search proceeds and may shrink).
    template <typename Visit, typename Limit>
    void search(const V2 &q, Visit visit, Limit limit) const
    {
        std::vector<std::pair<double, std::size_t>> &stack = m_stack;
        stack.clear();
        stack.emplace_back(boxDistance(q, 1), 1);
        while (!stack.empty()) {
            const auto [d, k] = stack.back();
            stack.pop_back();
            if (d > limit())
                continue;
            if (k >= m_leaves) {
                const std::size_t i = k - m_leaves;
                if (i < m_pieces.size())
                    visit(i, pointSegment(q, m_pieces[i].a, m_pieces[i].b));
                continue;
            }
            const double d0 = boxDistance(q, 2 * k), d1 = boxDistance(q, 2 * k + 1);
            // The nearer child on top of the stack: it is searched first.
            if (d0 <= d1) {
                stack.emplace_back(d1, 2 * k + 1);
                stack.emplace_back(d0, 2 * k);
            } else {
                stack.emplace_back(d0, 2 * k);
                stack.emplace_back(d1, 2 * k + 1);
            }
        }
    }

private:
    double boxDistance(const V2 &q, std::size_t k) const
    {
        if (m_lo[k].x() > m_hi[k].x())
            return kInf;  // empty padding
        const V2 d = (m_lo[k] - q).cwiseMax(q - m_hi[k]).cwiseMax(V2::Zero());
        return d.norm();
    }

    const std::vector<CurvePiece> &m_pieces;
    std::size_t m_leaves = 1;
    std::vector<V2> m_lo, m_hi;
    mutable std::vector<std::pair<double, std::size_t>> m_stack;
};

std::vector<CurvePiece> initialPieces(const CertifiedCurve &curve, std::size_t atLeast,
                                      long &count)
{
    const std::vector<double> b = curve.breaks();
    std::vector<CurvePiece> pieces;
    for (std::size_t i = 0; i + 1 < b.size(); ++i)
        pieces.push_back(curve.enclose(b[i], b[i + 1]));
    count += long(pieces.size());
    while (pieces.size() < atLeast) {
        std::vector<CurvePiece> finer;
        for (const CurvePiece &p : pieces) {
            const double tm = 0.5 * (p.t0 + p.t1);
            finer.push_back(curve.enclose(p.t0, tm));
            finer.push_back(curve.enclose(tm, p.t1));
        }
        count += long(finer.size());
        pieces.swap(finer);
    }
    return pieces;
}

void splitInto(const CertifiedCurve &curve, const CurvePiece &p, double target, int levels,
               std::vector<CurvePiece> &out, long &count)
{
    if (levels == 0 || p.radius <= target || !(p.t1 - p.t0 > 4.0 * kEps * std::abs(p.t1))) {
        out.push_back(p);
        return;
    }
    const double tm = 0.5 * (p.t0 + p.t1);
    const CurvePiece l = curve.enclose(p.t0, tm), r = curve.enclose(tm, p.t1);
    count += 2;
    splitInto(curve, l, target, levels - 1, out, count);
    splitInto(curve, r, target, levels - 1, out, count);
}

bool narrowEnough(double lower, double upper, double rel, double floor)
{
    return upper - lower <= rel * upper || upper <= floor;
}

// sup_{a in A} dist(a, C).
DistanceBracket pointsToCurve(const Mat &A, const CertifiedCurve &curve,
                              const HausdorffBracketOptions &o, double floor, long &count,
                              bool &converged)
{
    std::vector<CurvePiece> pieces = initialPieces(curve, 256, count);
    // The points that may still hold the supremum, with their brackets.
    struct Candidate {
        Eigen::Index row;
        double lo, hi;
    };
    std::vector<Candidate> cand;
    cand.reserve(std::size_t(A.rows()));
    for (Eigen::Index i = 0; i < A.rows(); ++i)
        cand.push_back({i, 0.0, kInf});
    double L = 0.0, U = kInf;
    converged = false;
    const long budget = count + o.maxEnclosures;
    for (;;) {
        const PieceTree tree(pieces);
        U = 0.0;
        for (Candidate &c : cand) {
            const V2 q = A.row(c.row).transpose();
            double best = c.hi, low = kInf;
            tree.search(
                q,
                [&](std::size_t i, double d) {
                    best = std::min(best, d + pieces[i].radius);
                    low = std::min(low, d - pieces[i].radius);
                },
                [&] { return best; });
            // Pieces not visited have a capsule farther than the final `best`.
            c.hi = best;
            c.lo = std::max(c.lo, std::max(0.0, std::min(low, best)));
            L = std::max(L, c.lo);
            U = std::max(U, c.hi);
        }
        if (narrowEnough(L, U, o.relativeWidth, floor)) {
            converged = true;
            break;
        }
        if (count >= budget || (o.cancel && *o.cancel))
            break;
        // Only points that may still hold the supremum.
        cand.erase(std::remove_if(cand.begin(), cand.end(),
                                  [L](const Candidate &c) { return c.hi < L; }),
                   cand.end());
        // Split the pieces that can hold a candidate's nearest curve point and are too thick.
        const double target = std::max(0.25 * o.relativeWidth * L, (U - L) / 16.0);
        std::vector<char> mark(pieces.size(), 0);
        std::size_t marked = 0;
        for (const Candidate &c : cand) {
            const V2 q = A.row(c.row).transpose();
            const double limit = c.hi;
            tree.search(
                q,
                [&](std::size_t i, double d) {
                    if (d - pieces[i].radius <= limit && pieces[i].radius > target && !mark[i]) {
                        mark[i] = 1;
                        ++marked;
                    }
                },
                [&] { return limit; });
        }
        if (marked == 0)
            break;  // cannot happen unless rounding keeps the bracket from narrowing
        const long before = count;
        std::vector<CurvePiece> next;
        next.reserve(pieces.size() + 8 * marked);
        for (std::size_t i = 0; i < pieces.size(); ++i) {
            if (mark[i])
                splitInto(curve, pieces[i], target, 3, next, count);
            else
                next.push_back(pieces[i]);
        }
        pieces.swap(next);
        if (count == before)
            break;  // the marked pieces are at the parameter's resolution
    }
    return {L, std::max(L, U)};
}

// sup_t dist(c(t), A), branch and bound over the parameter.
DistanceBracket curveToPointSet(const Mat &A, const CertifiedCurve &curve,
                                const HausdorffBracketOptions &o, double floor, long &count,
                                bool &converged)
{
    const PointIndex index(A);
    const double err = curve.allowance();
    double L = 0.0;
    struct Node {
        CurvePiece p;
        double upper;
        bool operator<(const Node &n) const { return upper < n.upper; }
    };
    auto bound = [&](const CurvePiece &p) {
        Eigen::Index ia = 0, ib = 0, iq = 0;
        const V2 q = 0.5 * (p.a + p.b);
        const double fa = index.nearest(p.a.data(), &ia), fb = index.nearest(p.b.data(), &ib);
        const double fq = index.nearest(q.data(), &iq);
        L = std::max(L, std::max(fa, fb) - err);
        double upper = fq + 0.5 * (p.b - p.a).norm() + p.radius;
        for (Eigen::Index k : {ia, ib, iq}) {
            const V2 x = A.row(k).transpose();
            upper = std::min(upper, std::max((p.a - x).norm(), (p.b - x).norm()) + p.radius);
        }
        return upper * (1.0 + 4.0 * kEps);
    };
    std::priority_queue<Node> queue;
    for (const CurvePiece &p : initialPieces(curve, 256, count))
        queue.push({p, bound(p)});
    const long budget = count + o.maxEnclosures;
    converged = false;
    double U = 0.0;
    long pops = 0;
    while (!queue.empty()) {
        const Node top = queue.top();
        U = top.upper;
        if (narrowEnough(L, U, o.relativeWidth, floor)) {
            converged = true;
            break;
        }
        if (count >= budget || !(top.p.t1 - top.p.t0 > 4.0 * kEps * std::abs(top.p.t1)))
            break;
        if ((++pops & 1023) == 0 && o.cancel && *o.cancel)
            break;
        queue.pop();
        const double tm = 0.5 * (top.p.t0 + top.p.t1);
        for (const CurvePiece &child : {curve.enclose(top.p.t0, tm), curve.enclose(tm, top.p.t1)}) {
            ++count;
            const double upper = bound(child);
            if (upper > L)
                queue.push({child, upper});
        }
    }
    if (queue.empty()) {
        U = L;
        converged = true;
    }
    return {std::min(L, U), std::max(L, U)};
}

} // namespace

HausdorffBracket hausdorffBracket(const Mat &A, const CertifiedCurve &curve,
                                  const HausdorffBracketOptions &options)
{
    if (A.rows() < 1 || A.cols() != 2)
        throw InputError(coreTranslate("awb::analysis", "the Hausdorff bracket needs a nonempty "
                                                        "set of plane points"));
    requireFinite(A, coreTranslate("awb::analysis", "the point set"));
    // Below this, a bracket is at the level of rounding.
    const double floor =
        64.0 * kEps * std::max(A.cwiseAbs().maxCoeff(), 1.0) + 8.0 * curve.allowance();
    HausdorffBracket h;
    bool c1 = false, c2 = false;
    h.oneSided = pointsToCurve(A, curve, options, floor, h.enclosures, c1);
    h.curveToPoints = curveToPointSet(A, curve, options, floor, h.enclosures, c2);
    h.value = {std::max(h.oneSided.lower, h.curveToPoints.lower),
               std::max(h.oneSided.upper, h.curveToPoints.upper)};
    h.width = std::max({h.value.relativeWidth(), h.oneSided.relativeWidth(),
                        h.curveToPoints.relativeWidth()});
    h.converged = c1 && c2;
    return h;
}

} // namespace awb
