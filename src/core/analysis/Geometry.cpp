#include "core/analysis/Geometry.h"

#include "core/Messages.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace awb {

double polygonLength(const Mat &pts, bool closed)
{
    double len = 0;
    for (Eigen::Index i = 1; i < pts.rows(); ++i)
        len += (pts.row(i) - pts.row(i - 1)).norm();
    if (closed && pts.rows() > 2)
        len += (pts.row(0) - pts.row(pts.rows() - 1)).norm();
    return len;
}

double polygonArea(const Mat &pts)
{
    double a = 0;
    const Eigen::Index n = pts.rows();
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index j = (i + 1) % n;
        a += pts(i, 0) * pts(j, 1) - pts(j, 0) * pts(i, 1);
    }
    return 0.5 * a;
}

// ---- PointIndex: a k-d tree ----------------------------------------------------------------
// A balanced tree of median splits along the widest side of each node's box, leaves of at most
// kLeaf points, the points copied in leaf order. The uniform grid it replaced sized its cells for
// points spread over the plane: on a curve (the usual attractor) each occupied cell held about
// sqrt(n) points, and the Hausdorff distances of 004 Fig. 3.4 spent 85 % of `attractor-cli
// analyse` in nearest(). A tree's cost does not depend on how the points are spread.

namespace {
constexpr int kLeaf = 8;
}

struct PointIndex::Impl {
    struct Node {
        std::uint32_t begin, end;  // range of points (leaf order)
        std::uint32_t right;       // index of the right child; the left child follows the node
        int axis;                  // -1: leaf
        double split;
    };
    int d = 0;
    std::vector<double> pts;           // d coordinates per point, leaf order
    std::vector<std::uint32_t> id;     // original row of each point
    std::vector<Node> nodes;

    std::uint32_t build(std::uint32_t begin, std::uint32_t end, const Mat &src)
    {
        const auto self = std::uint32_t(nodes.size());
        nodes.push_back({begin, end, 0, -1, 0.0});
        if (end - begin <= std::uint32_t(kLeaf))
            return self;
        double lo[3], hi[3];
        for (int a = 0; a < d; ++a) {
            lo[a] = std::numeric_limits<double>::infinity();
            hi[a] = -lo[a];
        }
        for (std::uint32_t k = begin; k < end; ++k)
            for (int a = 0; a < d; ++a) {
                const double v = src(id[k], a);
                lo[a] = std::min(lo[a], v);
                hi[a] = std::max(hi[a], v);
            }
        int axis = 0;
        for (int a = 1; a < d; ++a)
            if (hi[a] - lo[a] > hi[axis] - lo[axis])
                axis = a;
        if (!(hi[axis] > lo[axis]))
            return self;  // all points of the range coincide: one leaf, however many
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(id.begin() + begin, id.begin() + mid, id.begin() + end,
                         [&](std::uint32_t i, std::uint32_t j) { return src(i, axis) < src(j, axis); });
        nodes[self].axis = axis;
        nodes[self].split = src(id[mid], axis);
        build(begin, mid, src);
        const std::uint32_t right = build(mid, end, src);
        nodes[self].right = right;
        return self;
    }

    // Nearest point to q among those closer than sqrt(best2); best2 and bestIdx updated.
    // Stops at the first point closer than sqrt(stop2) (0: never).
    void search(std::uint32_t n, const double *q, double &best2, std::uint32_t &bestIdx,
                double stop2) const
    {
        for (;;) {
            const Node &node = nodes[n];
            if (node.axis < 0) {
                for (std::uint32_t k = node.begin; k < node.end; ++k) {
                    const double *p = &pts[std::size_t(k) * d];
                    double s = 0;
                    for (int a = 0; a < d; ++a) {
                        const double t = p[a] - q[a];
                        s += t * t;
                    }
                    if (s < best2) {
                        best2 = s;
                        bestIdx = k;
                    }
                }
                return;
            }
            const double diff = q[node.axis] - node.split;
            const std::uint32_t nearChild = diff < 0 ? n + 1 : node.right;
            const std::uint32_t farChild = diff < 0 ? node.right : n + 1;
            search(nearChild, q, best2, bestIdx, stop2);
            if (best2 < stop2 || diff * diff >= best2)
                return;
            n = farChild;  // the far side, as a loop: one recursion per level
        }
    }
};

PointIndex::PointIndex(const Mat &pts) : d(std::make_unique<Impl>())
{
    if (pts.rows() == 0)
        throw InputError(coreTranslate("awb::analysis", "cannot index an empty point set"));
    if (pts.cols() < 1 || pts.cols() > 3)
        throw InputError(coreTranslate("awb::analysis", "point sets must have 1 to 3 coordinates"));
    if (pts.rows() >= Eigen::Index(std::numeric_limits<std::uint32_t>::max()))
        throw InputError(coreTranslate("awb::analysis", "too many points to index"));
    requireFinite(pts, coreTranslate("awb::analysis", "point set"));
    Impl &g = *d;
    g.d = int(pts.cols());
    const auto n = std::uint32_t(pts.rows());
    g.id.resize(n);
    for (std::uint32_t i = 0; i < n; ++i)
        g.id[i] = i;
    g.nodes.reserve(std::size_t(n) / 2 + 1);
    g.build(0, n, pts);
    g.pts.resize(std::size_t(n) * g.d);
    for (std::uint32_t k = 0; k < n; ++k)
        for (int a = 0; a < g.d; ++a)
            g.pts[std::size_t(k) * g.d + a] = pts(g.id[k], a);
}

PointIndex::~PointIndex() = default;

double PointIndex::nearest(const double *q, Eigen::Index *index) const
{
    double best2 = std::numeric_limits<double>::infinity();
    std::uint32_t k = 0;
    d->search(0, q, best2, k, 0.0);
    if (index)
        *index = d->id[k];
    return std::sqrt(best2);
}

bool PointIndex::within(const double *q, double radius) const
{
    double best2 = std::numeric_limits<double>::infinity();
    std::uint32_t k = 0;
    const double r2 = radius * radius;
    d->search(0, q, best2, k, r2);
    return best2 < r2;
}

double directedDistance(const Mat &A, const Mat &B)
{
    if (A.cols() != B.cols())
        throw InputError(coreTranslate("awb::analysis", "point sets of different dimensions"));
    const PointIndex index(B);
    double worst = 0;
    double q[3] = {0, 0, 0};
    for (Eigen::Index i = 0; i < A.rows(); ++i) {
        for (Eigen::Index a = 0; a < A.cols(); ++a)
            q[a] = A(i, a);
        // A point of B within the distance found so far means that a cannot raise the maximum
        // (the early break of Taha & Hanbury 2015): most queries stop at their first leaf.
        if (i > 0 && index.within(q, worst))
            continue;
        worst = std::max(worst, index.nearest(q));
    }
    return worst;
}

double hausdorffDistance(const Mat &A, const Mat &B)
{
    return std::max(directedDistance(A, B), directedDistance(B, A));
}

namespace {
double pointSegment(const RowVec &p, const RowVec &a, const RowVec &b)
{
    const RowVec ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + t * ab)).norm();
}
} // namespace

double distanceToPolyline(const Mat &A, const Mat &curve)
{
    if (A.cols() != curve.cols())
        throw InputError(coreTranslate("awb::analysis", "point sets of different dimensions"));
    if (curve.rows() < 2)
        return directedDistance(A, curve);
    const PointIndex index(curve);
    double worst = 0;
    double q[3] = {0, 0, 0};
    for (Eigen::Index i = 0; i < A.rows(); ++i) {
        for (Eigen::Index a = 0; a < A.cols(); ++a)
            q[a] = A(i, a);
        Eigen::Index v = 0;
        index.nearest(q, &v);
        const RowVec p = A.row(i);
        double best = std::numeric_limits<double>::infinity();
        // Check segments around the nearest vertex; a dense polyline makes this exact up to
        // the chord error of the sampling.
        for (Eigen::Index s = std::max<Eigen::Index>(0, v - 2);
             s < std::min<Eigen::Index>(curve.rows() - 1, v + 2); ++s)
            best = std::min(best, pointSegment(p, curve.row(s), curve.row(s + 1)));
        worst = std::max(worst, best);
    }
    return worst;
}

double hausdorffToCurve(const Mat &A, const Mat &curve)
{
    return std::max(distanceToPolyline(A, curve), directedDistance(curve, A));
}

BoxDimension boxCountingDimension(const Mat &pts, int minLevel, int maxLevel,
                                  double minPointsPerBox)
{
    BoxDimension out;
    if (pts.rows() < 16) {
        out.note = coreTranslate("awb::analysis", "too few points for box counting");
        return out;
    }
    requireFinite(pts, coreTranslate("awb::analysis", "point set"));
    const RowVec lo = pts.colwise().minCoeff(), hi = pts.colwise().maxCoeff();
    const double size = (hi - lo).maxCoeff();
    if (!(size > 0)) {
        out.note = coreTranslate("awb::analysis", "all points coincide");
        return out;
    }
    const int d = int(pts.cols());
    std::vector<std::uint64_t> keys(pts.rows());
    std::vector<double> counts;
    int last = minLevel - 1;
    for (int level = 0; level <= std::min(maxLevel, 60 / d); ++level) {
        const double eps = size / std::ldexp(1.0, level);
        // The bounding box is closed: a point on its upper face belongs to the last box of
        // that axis, not to a box outside it.
        double lastBox[3] = {0, 0, 0};
        for (int a = 0; a < d; ++a)
            lastBox[a] = std::max(0.0, std::ceil((hi(a) - lo(a)) / eps) - 1);
        for (Eigen::Index i = 0; i < pts.rows(); ++i) {
            std::uint64_t key = 0;
            for (int a = 0; a < d; ++a) {
                const auto c = std::uint64_t(std::min(lastBox[a],
                                                      std::floor((pts(i, a) - lo(a)) / eps)));
                key = (key << (60 / d)) | c;
            }
            keys[i] = key;
        }
        std::sort(keys.begin(), keys.end());
        const double n = double(std::unique(keys.begin(), keys.end()) - keys.begin());
        out.logInverseEps.push_back(std::log(std::ldexp(1.0, level) / size));
        out.logCount.push_back(std::log(n));
        counts.push_back(n);
        if (level >= minLevel && double(pts.rows()) / n >= minPointsPerBox)
            last = level;
        if (double(pts.rows()) / n < minPointsPerBox)
            break;
    }
    if (last - minLevel < 2) {
        out.note = formatMessage(coreTranslate("awb::analysis", "not enough points for three "
                                                                "box sizes with at least %1 "
                                                                "points per box"),
                                 int(minPointsPerBox));
        return out;
    }
    out.levelFrom = minLevel;
    out.levelTo = last;
    const int k = last - minLevel + 1;
    double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
    for (int l = minLevel; l <= last; ++l) {
        const double x = out.logInverseEps[l], y = out.logCount[l];
        sx += x; sy += y; sxx += x * x; sxy += x * y; syy += y * y;
    }
    const double den = k * sxx - sx * sx;
    out.dimension = (k * sxy - sx * sy) / den;
    out.intercept = (sy - out.dimension * sx) / k;
    const double ssTot = syy - sy * sy / k;
    double ssRes = 0;
    for (int l = minLevel; l <= last; ++l) {
        const double e = out.logCount[l] - (out.intercept + out.dimension * out.logInverseEps[l]);
        ssRes += e * e;
    }
    out.r2 = ssTot > 0 ? 1.0 - ssRes / ssTot : 1.0;
    out.valid = true;
    return out;
}

} // namespace awb
