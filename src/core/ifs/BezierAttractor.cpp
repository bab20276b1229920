#include "core/ifs/BezierAttractor.h"

#include "core/Decompositions.h"
#include "core/Messages.h"
#include "core/schemes/Curves.h"

#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

namespace awb {

namespace {


void requireSplitParameter(double u)
{
    if (!std::isfinite(u))
        throw InputError(
            coreTranslate("awb::ifs", "the split parameter u is not a finite number"));
    if (!(u > 0.0 && u < 1.0))
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "the split parameter u = %1 must lie strictly between 0 "
                                      "and 1 (002 §4: 0 < u < 1)"),
            streamedNumber(u)));
}

// Reciprocal condition of a matrix (sigma_min / sigma_max; 0 for a zero matrix).
double reciprocalCondition(const Mat &M)
{
    Eigen::JacobiSVD<Mat> svd(M);
    const auto &sv = svd.singularValues();
    return sv(0) > 0 ? sv(sv.size() - 1) / sv(0) : 0.0;
}

Mat homogeneousRows(const Mat &P)
{
    Mat H(P.rows(), P.cols() + 1);
    H << P, Mat::Ones(P.rows(), 1);
    return H;
}

std::string spanWord(int d)
{
    return d == 1 ? coreTranslate("awb::ifs", "coincide", "points")
                  : (d == 2 ? coreTranslate("awb::ifs", "are collinear", "points")
                            : coreTranslate("awb::ifs", "are coplanar", "points"));
}


} // namespace

Mat PlaneMap::homogeneous() const
{
    const int d = map.dim();
    Mat H = Mat::Zero(d + 1, d + 1);
    H.topLeftCorner(d, d) = map.A;
    H.bottomLeftCorner(1, d) = map.b;
    H(d, d) = 1.0;
    return H;
}

AffineMap compose(const AffineMap &outer, const AffineMap &inner)
{
    return {inner.A * outer.A, inner.b * outer.A + outer.b};
}

AffineMap inverse(const AffineMap &f)
{
    Eigen::FullPivLU<Mat> lu(f.A);
    if (!lu.isInvertible() || reciprocalCondition(f.A) < 1e-13)
        throw InputError(coreTranslate("awb::ifs", "the affine map is not invertible (its linear "
                                                   "part is singular)"));
    const Mat Ainv = lu.inverse();
    // y = x A + b  <=>  x = y A^-1 - b A^-1
    return {Ainv, -f.b * Ainv};
}

AffineMap conjugate(const AffineMap &w, const AffineMap &omega)
{
    return compose(omega, compose(w, inverse(omega)));
}

AffineMap affineMapThrough(const Mat &from, const Mat &to)
{
    const Eigen::Index d = from.cols();
    if (from.rows() != d + 1 || to.rows() != d + 1 || to.cols() != d)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "an affine map of R^%1 is fixed by %2 point pairs"), d,
            d + 1));
    requireFinite(from, coreTranslate("awb::ifs", "source points"));
    requireFinite(to, coreTranslate("awb::ifs", "target points"));
    const Mat H = homogeneousRows(from);
    if (reciprocalCondition(H) < 1e-12)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "the source points %1: no unique affine map takes them to "
                                      "the targets"),
            spanWord(int(d))));
    // [from | 1] [A; b] = to
    const Mat X = H.fullPivLu().solve(to);
    return {X.topRows(d), X.row(d)};
}

Mat parabolaControlPoints()
{
    Mat P(3, 2);
    P << 0.0, 0.0, 0.5, 0.0, 1.0, 1.0;
    return P;
}

std::array<AffineMap, 2> parabolaMaps(double u)
{
    requireSplitParameter(u);
    const double v = 1.0 - u;
    AffineMap w1{Mat(2, 2), RowVec::Zero(2)};
    w1.A << u, 0.0, 0.0, u * u;  // eq. (11), transposed for row vectors
    AffineMap w2{Mat(2, 2), RowVec(2)};
    w2.A << v, 2.0 * u * v, 0.0, v * v;  // eq. (12), transposed
    w2.b << u, u * u;
    return {w1, w2};
}

std::vector<AffineMap> fractalInterpolationMaps(const Mat &data, const std::vector<double> &d)
{
    if (data.cols() != 2 || data.rows() < 3)
        throw InputError(coreTranslate("awb::ifs", "fractal interpolation needs N + 1 >= 3 "
                                                   "data points (x, y)"));
    requireFinite(data, coreTranslate("awb::ifs", "interpolation data"));
    const Eigen::Index N = data.rows() - 1;
    if (Eigen::Index(d.size()) != N)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "fractal interpolation through %1 points needs %2 vertical "
                                      "scalings d_n, got %3"),
            N + 1, N, d.size()));
    for (Eigen::Index n = 1; n <= N; ++n)
        if (!(data(n, 0) > data(n - 1, 0)))
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "interpolation abscissae must increase (x_%1 <= x_%2)"),
                n, n - 1));
    for (Eigen::Index n = 0; n < N; ++n)
        // The paper asks 0 <= d_n < 1; Barnsley's theorem only needs |d_n| < 1.
        if (!std::isfinite(d[n]) || !(std::abs(d[n]) < 1.0))
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "vertical scaling d_%1 = %2 must satisfy |d_n| < 1"),
                n + 1, streamedNumber(d[n])));
    const double x0 = data(0, 0), xN = data(N, 0), y0 = data(0, 1), yN = data(N, 1);
    const double L = xN - x0;
    std::vector<AffineMap> maps;
    for (Eigen::Index n = 1; n <= N; ++n) {
        const double xp = data(n - 1, 0), xn = data(n, 0), yp = data(n - 1, 1), yn = data(n, 1);
        const double dn = d[n - 1];
        const double a = (xn - xp) / L;                                  // eq. (13)
        const double e = (xN * xp - x0 * xn) / L;                        // eq. (14)
        const double c = (yn - yp - dn * (yN - y0)) / L;                 // eq. (15)
        const double f = (xN * yp - x0 * yn - dn * (xN * y0 - x0 * yN)) / L;  // eq. (16)
        AffineMap w{Mat(2, 2), RowVec(2)};
        // (x, y) |-> (a x + e, c x + d y + f), b_n = 0: row form [x y] [[a, c], [0, d]].
        w.A << a, c, 0.0, dn;
        w.b << e, f;
        maps.push_back(w);
    }
    return maps;
}

std::vector<AffineMap> barnsleyParabolaMaps(double u)
{
    requireSplitParameter(u);
    Mat data(3, 2);
    data << 0.0, 0.0, u, u * u, 1.0, 1.0;
    return fractalInterpolationMaps(data, {u * u, (1.0 - u) * (1.0 - u)});
}

std::array<AffineMap, 2> conjugatedQuadraticMaps(const Mat &Q, double u)
{
    if (Q.rows() != 3 || Q.cols() != 2)
        throw InputError(coreTranslate("awb::ifs", "002 §5 needs three control points in the plane "
                                                   "(3 x 2)"));
    requireFinite(Q, coreTranslate("awb::ifs", "control points"));
    if (reciprocalCondition(homogeneousRows(Q)) < 1e-12)
        throw InputError(coreTranslate("awb::ifs", "control points Q0, Q1, Q2 are collinear: the "
                                                   "map omega of 002 §5 "
                         "is not invertible"));
    const AffineMap omega = affineMapThrough(parabolaControlPoints(), Q);
    const auto w = parabolaMaps(u);
    return {conjugate(w[0], omega), conjugate(w[1], omega)};
}

int BezierSplit::levelsFor(double factor) const
{
    if (!(factor > 0.0 && factor < 1.0) || !(slowestRadius > 0.0))
        return 1;
    if (slowestRadius >= 1.0)
        return -1;
    return std::max(1, int(std::ceil(std::log(factor) / std::log(slowestRadius))));
}

BezierSplit bezierSplit(const Mat &P, double u)
{
    requireSplitParameter(u);
    if (P.rows() < 2)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "a Bézier curve needs at least 2 control points (degree >= "
                                      "1), got %1"),
            P.rows()));
    if (P.cols() < 1 || P.cols() > 3)
        throw InputError(
            coreTranslate("awb::ifs", "control points must have 1 to 3 coordinates"));
    requireFinite(P, coreTranslate("awb::ifs", "control points"));
    const int m = int(P.rows()), d = int(P.cols()), n = m - 1;

    BezierSplit s;
    s.controlPoints = P;
    s.degree = n;
    s.u = u;
    s.S = {deCasteljauL(n, u), deCasteljauR(n, u)};
    s.lifted = buildSubdivisionIfs({s.S[0], s.S[1]}, 1, P);

    // w_i with [P | 1] [A; b] = S_i P: m equations for the (d+1) x d unknowns.
    const Mat H = homogeneousRows(P);
    const double scale = 1.0 + (P.colwise().maxCoeff() - P.colwise().minCoeff()).norm();
    if (m < d + 1 || reciprocalCondition(H) < 1e-10) {
        s.planarReason = formatMessage(
            coreTranslate("awb::ifs", "the %1 control points %2, so the affine maps of eqs. "
                                      "(9)-(10) are not unique"),
            m, spanWord(d));
    } else {
        const auto solver = H.colPivHouseholderQr();
        double residual = 0.0;
        std::vector<PlaneMap> maps;
        for (const Mat &Si : s.S) {
            const Mat target = Si * P;
            const Mat X = solver.solve(target);
            residual = std::max(residual, (H * X - target).cwiseAbs().maxCoeff());
            PlaneMap pm;
            pm.map = {X.topRows(d), X.row(d)};
            pm.contractivity = contractivity(pm.map.A);
            maps.push_back(pm);
        }
        if (residual <= 1e-9 * scale) {
            s.planar = true;
            s.planeMaps = maps;
        } else {
            s.planarReason = formatMessage(
                coreTranslate("awb::ifs", "no affine map of R^%1 takes the control polygon of "
                                          "this degree-%2 curve to its de Casteljau pieces "
                                          "(mismatch %3): the pieces are not affine images of "
                                          "the curve in its own space"),
                d, n, streamedNumber(residual));
        }
    }

    if (s.planar) {
        s.ifs.space = "plane";
        for (const PlaneMap &pm : s.planeMaps)
            s.ifs.maps.push_back(pm.map);
        s.ifs.views.push_back({Mat::Identity(d, d), RowVec::Zero(d)});
        s.start = P.row(0);
    } else {
        s.ifs = s.lifted.ifs;
        if (s.lifted.barycentric()) {
            s.planarReason += formatMessage(
                coreTranslate("awb::ifs", "; the maps act on barycentric coordinates R^%1 (%2)"),
                m, s.lifted.lifting.reason);
            s.start = RowVec::Zero(m);
            s.start(0) = 1.0;
        } else {
            s.planarReason += formatMessage(
                coreTranslate("awb::ifs", "; the maps act on the lifted space R^%1 of 000 §2, "
                                          "drawn through its first %2 coordinates"),
                m - 1, d);
            // Row 0 of the lifted control-point matrix, without its homogeneous 1: e_0 P.
            s.start = s.lifted.lifting.lifted.row(0).head(m - 1);
        }
    }

    s.check = checkIfs(s.ifs);
    std::string note;
    int slowest = 0;
    for (size_t i = 0; i < s.check.maps.size(); ++i) {
        if (s.check.maps[i].spectralRadius > s.slowestRadius) {
            s.slowestRadius = s.check.maps[i].spectralRadius;
            slowest = int(i);
        }
    }
    s.nearlyNonContractive = s.slowestRadius >= 0.9;
    note = formatMessage(coreTranslate("awb::ifs", "map 1 has spectral radius %1, map 2 %2; %3 "
                                                   "levels shrink every piece to 1/1000 of the "
                                                   "curve"),
                         streamedNumber(s.check.maps[0].spectralRadius, 4),
                         streamedNumber(s.check.maps[1].spectralRadius, 4), s.levelsFor(1e-3));
    if (s.nearlyNonContractive)
        note += formatMessage(
            coreTranslate("awb::ifs", ". u = %1 is close to %2: map %3 is nearly non-contractive "
                                      "and the pieces are very unequal (random iteration, or u "
                                      "nearer 1/2, converges faster)"),
            streamedNumber(u, 4), u < 0.5 ? "0" : "1", slowest + 1);
    for (size_t i = 0; i < s.check.maps.size(); ++i)
        if (s.check.maps[i].normFactor >= 1.0)
            note += formatMessage(
                coreTranslate("awb::ifs", ". Map %1 is not a Euclidean contraction (||A||_2 = "
                                          "%2) but is eventually contractive, as 002 §5 allows"),
                i + 1, streamedNumber(s.check.maps[i].normFactor, 4));
    s.contractionNote = note;
    return s;
}

JointContraction jointContraction(const Ifs &ifs, int maxLength, double maxWords)
{
    ifs.validate();
    const int N = ifs.size();
    std::vector<Mat> A;
    for (int i = 0; i < N; ++i)
        A.push_back(ifs.effectiveLinearPart(i));
    JointContraction best;
    best.factor = std::numeric_limits<double>::infinity();
    // Maps of the plane (every combined Bézier IFS): fixed-size products and the closed form
    // of the largest singular value, sigma^2 = (|P|_F^2 + sqrt(|P|_F^4 - 4 det(P)^2)) / 2,
    // with no allocation per word (about 10^5 words).
    const bool plane = A[0].rows() == 2 && A[0].cols() == 2;
    std::vector<Eigen::Matrix2d> A2;
    if (plane)
        for (const Mat &a : A)
            A2.push_back(a);
    const auto sigmaMax2 = [](const Eigen::Matrix2d &P) {
        const double f = P.squaredNorm(), det = P.determinant();
        return std::sqrt(std::max(0.0, 0.5 * (f + std::sqrt(std::max(0.0, f * f - 4 * det * det)))));
    };
    const auto sigmaMax = [](const Mat &P) { return Eigen::JacobiSVD<Mat>(P).singularValues()(0); };
    // The largest sigma over all words of length L, depth-first (one walker for both kinds).
    const auto worstOver = [](const auto &maps, const auto &identity, const auto &sigma, int L) {
        double worst = 0.0;
        const auto walk = [&](const auto &self, int level, const auto &prod) -> void {
            if (level == L) {
                worst = std::max(worst, sigma(prod));
                return;
            }
            for (const auto &m : maps)
                self(self, level + 1, (prod * m).eval());
        };
        walk(walk, 0, identity);
        return worst;
    };
    for (int L = 1; L <= maxLength && std::pow(double(N), L) <= maxWords; ++L) {
        const double worst =
            plane ? worstOver(A2, Eigen::Matrix2d::Identity().eval(), sigmaMax2, L)
                  : worstOver(A, Mat::Identity(A[0].rows(), A[0].cols()).eval(), sigmaMax, L);
        const double f = std::pow(worst, 1.0 / L);
        if (f < best.factor) {
            best.factor = f;
            best.length = L;
        }
    }
    best.contractive = best.factor < 1.0;
    return best;
}

CombinedBezierIfs combinedBezierIfs(const std::vector<BezierCurveSpec> &curves)
{
    if (curves.empty())
        throw InputError(coreTranslate("awb::ifs", "a combined IFS needs at least one curve"));
    CombinedBezierIfs out;
    out.ifs.space = "plane";
    for (size_t k = 0; k < curves.size(); ++k) {
        const std::string label = formatMessage(coreTranslate("awb::ifs", "curve %1"), k + 1);
        if (curves[k].controlPoints.cols() != 2)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "%1: the combined IFS of 002 §6 acts on the plane, "
                                          "control points need 2 coordinates"),
                label));
        BezierSplit s;
        try {
            s = bezierSplit(curves[k].controlPoints, curves[k].u);
        } catch (const InputError &e) {
            throw InputError(label + ": " + e.what());
        }
        if (!s.planar)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "%1: its maps do not act on the plane (%2), so they "
                                          "cannot be combined with the other curves' maps"),
                label, s.planarReason));
        for (const PlaneMap &pm : s.planeMaps)
            out.ifs.maps.push_back(pm.map);
        out.curves.push_back(std::move(s));
    }
    out.ifs.views.push_back({Mat::Identity(2, 2), RowVec::Zero(2)});
    out.check = checkIfs(out.ifs);
    out.joint = jointContraction(out.ifs);
    return out;
}

BezierUnion bezierUnion(const std::vector<BezierCurveSpec> &curves)
{
    if (curves.empty())
        throw InputError(coreTranslate("awb::ifs", "a union needs at least one curve"));
    BezierUnion out;
    std::vector<Ifs> parts;
    std::vector<double> start;
    for (size_t k = 0; k < curves.size(); ++k) {
        try {
            out.curves.push_back(bezierSplit(curves[k].controlPoints, curves[k].u));
        } catch (const InputError &e) {
            throw InputError(formatMessage(coreTranslate("awb::ifs", "curve %1"), k + 1) + ": "
                             + e.what());
        }
        parts.push_back(out.curves.back().ifs);
        const RowVec &s = out.curves.back().start;
        start.insert(start.end(), s.data(), s.data() + s.size());
    }
    out.ifs = blockUnion(parts);
    out.start = Eigen::Map<const RowVec>(start.data(), Eigen::Index(start.size()));
    return out;
}

} // namespace awb
