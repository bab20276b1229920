// Fractals with control points (000 §4): the general recipe and the Koch / Sierpinski presets.
#include "core/schemes/ControlPointFractal.h"

#include "core/Decompositions.h"
#include "core/Messages.h"
#include "core/schemes/Scheme.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace awb {

std::string toString(AffineWeights mode)
{
    switch (mode) {
    case AffineWeights::NearestBarycentric: return "barycentric in the nearest control points";
    case AffineWeights::LeastNorm: return "least-norm affine weights";
    }
    return "";
}

namespace {

// Relative tolerance for "affinely dependent" and "equally near": far above round-off of points
// of size ~1, far below any distance a user would place on purpose.
constexpr double kRelTol = 1e-9;

// Largest extent of the control points: the length scale for the tolerances.
double extent(const Mat &P)
{
    return (P.colwise().maxCoeff() - P.colwise().minCoeff()).maxCoeff();
}

// E = [P^T; 1^T]: (d + 1) x m. w is an affine combination giving y iff E w = [y; 1].
Mat affineSystem(const Mat &P)
{
    Mat E(P.cols() + 1, P.rows());
    E.topRows(P.cols()) = P.transpose();
    E.row(P.cols()).setOnes();
    return E;
}

// Throws InputError unless P (m x d) can carry affine coordinates of the plane (or space).
void requireControlPoints(const Mat &P)
{
    const Eigen::Index d = P.cols();
    if (d != 2 && d != 3)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "control points must have 2 or 3 coordinates, got %1"),
            d));
    requireFinite(P, coreTranslate("awb::schemes", "control points"));
    if (P.rows() < d + 1)
        throw InputError(formatMessage(
            d == 2 ? coreTranslate("awb::schemes", "%1 control points are too few: affine "
                                                   "combinations in %2D need at least %3 that "
                                                   "are not collinear")
                   : coreTranslate("awb::schemes", "%1 control points are too few: affine "
                                                   "combinations in %2D need at least %3 that "
                                                   "are not coplanar"),
            P.rows(), d, d + 1));
    // The points span the space affinely iff the centred points (m x d) have rank d; comparing
    // singular values with each other keeps the test independent of scale and position.
    const Mat centred = P.rowwise() - P.colwise().mean();
    const Vec sv = Eigen::JacobiSVD<Mat>(centred).singularValues();
    if (!(sv(0) > 0) || sv(d - 1) <= kRelTol * sv(0))
        throw InputError(d == 2 ? coreTranslate("awb::schemes", "the control points are all "
                                                "collinear: they must span the plane to write "
                                                "every image point as their affine combination "
                                                "(000 eq. (5))")
                                : coreTranslate("awb::schemes", "the control points are all "
                                                "coplanar: they must span space to write every "
                                                "image point as their affine combination (000 "
                                                "eq. (5))"));
}

void requirePoint(const Mat &P, const RowVec &y)
{
    if (y.size() != P.cols())
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "the point has %1 coordinates, the control points have "
                                          "%2"),
            y.size(), P.cols()));
    requireFinite(Mat(y), coreTranslate("awb::schemes", "point"));
}

bool affinelyIndependent(const Mat &P, const std::vector<int> &idx, double scale)
{
    if (idx.size() <= 1)
        return true;
    Mat D(idx.size() - 1, P.cols());
    for (size_t r = 1; r < idx.size(); ++r)
        D.row(r - 1) = P.row(idx[r]) - P.row(idx[0]);
    Eigen::JacobiSVD<Mat> svd(D);
    return svd.singularValues().minCoeff() > kRelTol * scale;
}

// Barycentric coordinates of y in the d + 1 points idx (affinely independent): 1 x m.
RowVec barycentric(const Mat &P, const std::vector<int> &idx, const RowVec &y)
{
    const Eigen::Index d = P.cols();
    Mat E(d + 1, d + 1);
    Vec rhs(d + 1);
    for (Eigen::Index c = 0; c <= d; ++c) {
        E.col(c).head(d) = P.row(idx[c]).transpose();
        E(d, c) = 1.0;
    }
    rhs.head(d) = y.transpose();
    rhs(d) = 1.0;
    const Vec w = E.fullPivLu().solve(rhs);
    RowVec out = RowVec::Zero(P.rows());
    for (Eigen::Index c = 0; c <= d; ++c)
        out(idx[c]) = w(c);
    return out;
}

// Calls fn on every k-subset of items (in lexicographic order).
template<class Fn>
void forEachSubset(const std::vector<int> &items, int k, Fn fn)
{
    std::vector<int> pick(k);
    std::iota(pick.begin(), pick.end(), 0);
    const int n = int(items.size());
    while (true) {
        std::vector<int> subset(k);
        for (int t = 0; t < k; ++t)
            subset[t] = items[pick[t]];
        fn(subset);
        int t = k - 1;
        while (t >= 0 && pick[t] == n - k + t)
            --t;
        if (t < 0)
            return;
        ++pick[t];
        for (int u = t + 1; u < k; ++u)
            pick[u] = pick[u - 1] + 1;
    }
}

RowVec nearestBarycentricUnchecked(const Mat &P, const RowVec &y)
{
    const int m = int(P.rows()), d = int(P.cols());
    const double scale = extent(P); // > 0: requireControlPoints refused coincident points
    const double tol = kRelTol * scale;
    std::vector<double> dist(m);
    for (int k = 0; k < m; ++k)
        dist[k] = (P.row(k) - y).norm();
    std::vector<int> order(m);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return dist[a] < dist[b]; });

    // Affine independence is a matroid, so the greedy pick is the nearest basis: its k-th
    // distance is no larger than the k-th distance of any other affinely independent set.
    std::vector<int> basis;
    for (int k : order) {
        basis.push_back(k);
        if (!affinelyIndependent(P, basis, scale))
            basis.pop_back();
        else if (int(basis.size()) == d + 1)
            break;
    }
    std::vector<double> profile;
    for (int k : basis)
        profile.push_back(dist[k]);

    // Other bases with the same distance profile are equally "nearest" (Koch's f_3(P_3) is as
    // far from P_2 as from P_5); prefer the one with the smallest sum |w|.
    std::vector<int> candidates;
    for (int k : order)
        if (dist[k] <= profile.back() + tol)
            candidates.push_back(k);
    RowVec best = barycentric(P, basis, y);
    constexpr int kMaxTied = 16; // C(16, 4) = 1820 subsets at most; beyond that keep greedy
    if (int(candidates.size()) == d + 1 || int(candidates.size()) > kMaxTied)
        return best;
    std::sort(candidates.begin(), candidates.end());
    double bestCost = std::numeric_limits<double>::infinity();
    forEachSubset(candidates, d + 1, [&](const std::vector<int> &subset) {
        std::vector<double> prof;
        for (int k : subset)
            prof.push_back(dist[k]);
        std::sort(prof.begin(), prof.end());
        for (size_t t = 0; t < prof.size(); ++t)
            if (std::abs(prof[t] - profile[t]) > tol)
                return;
        if (!affinelyIndependent(P, subset, scale))
            return;
        const RowVec w = barycentric(P, subset, y);
        const double cost = w.cwiseAbs().sum();
        if (cost < bestCost - 1e-12) {
            bestCost = cost;
            best = w;
        }
    });
    return best;
}

RowVec leastNormUnchecked(const Eigen::CompleteOrthogonalDecomposition<Mat> &cod,
                          const RowVec &y)
{
    Vec rhs(y.size() + 1);
    rhs.head(y.size()) = y.transpose();
    rhs(y.size()) = 1.0;
    return cod.solve(rhs).transpose();
}

Mat rotationScale(double angle, double ratio)
{
    // Row convention: (x, y) A rotates counter-clockwise by `angle` for A = [[c, s], [-s, c]].
    const double c = std::cos(angle), s = std::sin(angle);
    Mat A(2, 2);
    A << c, s, -s, c;
    return ratio * A;
}

int sharedOverlap(const std::vector<Mat> &S)
{
    int overlap = S.empty() ? 0 : int(S.front().rows());
    for (size_t i = 1; i < S.size(); ++i)
        overlap = std::min(overlap, sharedRows(S[i - 1], S[i]));
    return S.size() < 2 ? 0 : overlap;
}

} // namespace

RowVec nearestBarycentricWeights(const Mat &P, const RowVec &y)
{
    requireControlPoints(P);
    requirePoint(P, y);
    return nearestBarycentricUnchecked(P, y);
}

RowVec leastNormWeights(const Mat &P, const RowVec &y)
{
    requireControlPoints(P);
    requirePoint(P, y);
    return leastNormUnchecked(Eigen::CompleteOrthogonalDecomposition<Mat>(affineSystem(P)), y);
}

Mat leastNormWeightsOfRows(const Mat &P, const Mat &X)
{
    const Eigen::CompleteOrthogonalDecomposition<Mat> cod(affineSystem(P));
    Mat rhs(P.cols() + 1, X.rows());
    rhs.topRows(P.cols()) = X.transpose();
    rhs.row(P.cols()).setOnes();
    return cod.solve(rhs).transpose();
}

ControlPointMatrices controlPointMatrices(const std::vector<AffineMap> &maps, const Mat &P,
                                          AffineWeights mode)
{
    if (maps.empty())
        throw InputError(coreTranslate("awb::schemes", "the IFS has no maps"));
    requireControlPoints(P);
    const Eigen::Index d = P.cols();
    for (size_t i = 0; i < maps.size(); ++i) {
        if (maps[i].A.rows() != d || maps[i].A.cols() != d || maps[i].b.size() != d)
            throw InputError(formatMessage(
                coreTranslate("awb::schemes", "map f_%1 is not a map of %2D points like the "
                                              "control points"),
                i + 1, d));
        requireFinite(maps[i].A,
                      formatMessage(coreTranslate("awb::schemes", "map f_%1 (linear part)"),
                                    i + 1));
        requireFinite(Mat(maps[i].b),
                      formatMessage(coreTranslate("awb::schemes", "map f_%1 (translation)"),
                                    i + 1));
    }
    ControlPointMatrices out;
    out.mode = mode;
    const Eigen::CompleteOrthogonalDecomposition<Mat> cod(affineSystem(P));
    for (const AffineMap &f : maps) {
        const Mat image = applyMap(f, P); // f_i(P): m x d
        Mat S(P.rows(), P.rows());
        for (Eigen::Index j = 0; j < P.rows(); ++j)
            S.row(j) = mode == AffineWeights::LeastNorm
                           ? leastNormUnchecked(cod, image.row(j))
                           : nearestBarycentricUnchecked(P, image.row(j));
        out.residuals.push_back((S * P - image).rowwise().norm().maxCoeff());
        out.maxResidual = std::max(out.maxResidual, out.residuals.back());
        out.S.push_back(std::move(S));
    }
    out.overlap = sharedOverlap(out.S);
    return out;
}

ControlPointFractal kochControlPointFractal()
{
    const double r3 = std::sqrt(3.0);
    ControlPointFractal f;
    f.name = coreTranslate("awb::schemes", "Koch curve with control points");
    f.source = "000 §4.1, Fig. 10";
    f.controlPoints.resize(5, 2);
    f.controlPoints << 0, 0, 1.0 / 3, 0, 0.5, r3 / 6, 2.0 / 3, 0, 1, 0;
    const double a = 1.0 / 3, b = 2.0 / 3;
    Mat S1(5, 5), S2(5, 5), S3(5, 5), S4(5, 5);
    S1 << 1, 0, 0, 0, 0,
          b, a, 0, 0, 0,
          b, 0, a, 0, 0,
          a, b, 0, 0, 0,
          0, 1, 0, 0, 0;
    S2 << 0, 1, 0, 0, 0,
          0, b, a, 0, 0,
          a, 0, b, 0, 0,
          0, a, b, 0, 0,
          0, 0, 1, 0, 0;
    S3 << 0, 0, 1, 0, 0,
          0, 0, b, a, 0,
          0, 0, b, 0, a,
          0, 0, a, b, 0,
          0, 0, 0, 1, 0;
    S4 << 0, 0, 0, 1, 0,
          0, 0, 0, b, a,
          0, 0, a, 0, b,
          0, 0, 0, a, b,
          0, 0, 0, 0, 1;
    f.S = {S1, S2, S3, S4};
    f.overlap = sharedOverlap(f.S);
    const double pi = std::acos(-1.0);
    auto at = [](double x, double y) { RowVec v(2); v << x, y; return v; };
    f.classicMaps = {
        {rotationScale(0, a), at(0, 0)},
        {rotationScale(pi / 3, a), at(a, 0)},
        {rotationScale(-pi / 3, a), at(0.5, r3 / 6)},
        {rotationScale(0, a), at(b, 0)},
    };
    return f;
}

ControlPointFractal sierpinskiControlPointFractal()
{
    const double r3 = std::sqrt(3.0);
    ControlPointFractal f;
    f.name = coreTranslate("awb::schemes", "Sierpinski gasket with control points");
    f.source = "000 §4.2, Fig. 11";
    // Corner, edge midpoint, corner, ... counter-clockwise (NOTES.md).
    f.controlPoints.resize(6, 2);
    f.controlPoints << 0, 0, 0.5, 0, 1, 0, 0.75, r3 / 4, 0.5, r3 / 2, 0.25, r3 / 4;
    const double e = 1.0 / 8, t = 3.0 / 8, q = 3.0 / 4, h = 0.5;
    Mat S1(6, 6), S2(6, 6), S3(6, 6);
    S1 << 1, 0, 0, 0, 0, 0,
          t, q, -e, 0, 0, 0,
          0, 1, 0, 0, 0, 0,
          0, h, 0, 0, 0, h,
          0, 0, 0, 0, 0, 1,
          t, 0, 0, 0, -e, q;
    S2 << 0, 1, 0, 0, 0, 0,
          -e, q, t, 0, 0, 0,
          0, 0, 1, 0, 0, 0,
          0, 0, t, q, -e, 0,
          0, 0, 0, 1, 0, 0,
          0, h, 0, h, 0, 0;
    S3 << 0, 0, 0, 0, 0, 1,
          0, 0, 0, h, 0, h,
          0, 0, 0, 1, 0, 0,
          0, 0, -e, q, t, 0,
          0, 0, 0, 0, 1, 0,
          -e, 0, 0, 0, t, q;
    f.S = {S1, S2, S3};
    f.overlap = sharedOverlap(f.S);
    const Mat half = 0.5 * Mat::Identity(2, 2);
    for (int c : {0, 2, 4})
        f.classicMaps.push_back({half, 0.5 * f.controlPoints.row(c)});
    return f;
}

Ifs classicIfs(const ControlPointFractal &fractal)
{
    Ifs ifs;
    ifs.space = "plane";
    ifs.maps = fractal.classicMaps;
    ifs.views.push_back({Mat::Identity(2, 2), RowVec::Zero(2)});
    ifs.validate();
    return ifs;
}

SubdivisionIfs controlPointFractalIfs(const ControlPointFractal &fractal, const Mat &P,
                                      IfsForm form)
{
    const Eigen::Index m = fractal.controlPoints.rows();
    if (P.rows() != m || P.cols() != 2)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "%1 needs %2 control points in the plane, got %3 with "
                                          "%4 coordinates"),
            fractal.name, m, P.rows(), P.cols()));
    return buildSubdivisionIfs(fractal.S, fractal.overlap, P, form);
}

SubdivisionIfs controlPointFractalIfs(const ControlPointFractal &fractal)
{
    return controlPointFractalIfs(fractal, fractal.controlPoints);
}

} // namespace awb
