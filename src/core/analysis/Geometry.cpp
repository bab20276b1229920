#include "core/analysis/Geometry.h"

#include "core/Messages.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

// ---- PointIndex: a uniform grid in CSR layout --------------------------------------------------

struct PointIndex::Impl {
    Mat pts;
    int d = 0;
    double lo[3] = {0, 0, 0};
    double cell = 1.0;
    int dims[3] = {1, 1, 1};
    std::vector<std::uint32_t> start;   // cell -> first entry in `order`
    std::vector<std::uint32_t> order;   // point indices sorted by cell

    int cellCoord(double v, int axis) const
    {
        const int c = int(std::floor((v - lo[axis]) / cell));
        return std::clamp(c, 0, dims[axis] - 1);
    }
    std::size_t cellIndex(const int *c) const
    {
        std::size_t idx = 0;
        for (int a = d - 1; a >= 0; --a)
            idx = idx * dims[a] + c[a];
        return idx;
    }
};

PointIndex::PointIndex(const Mat &pts) : d(std::make_unique<Impl>())
{
    if (pts.rows() == 0)
        throw InputError(coreTranslate("awb::analysis", "cannot index an empty point set"));
    if (pts.cols() < 1 || pts.cols() > 3)
        throw InputError(coreTranslate("awb::analysis", "point sets must have 1 to 3 coordinates"));
    requireFinite(pts, coreTranslate("awb::analysis", "point set"));
    d->pts = pts;
    d->d = int(pts.cols());
    const RowVec lo = pts.colwise().minCoeff(), hi = pts.colwise().maxCoeff();
    double extent = 0;
    for (int a = 0; a < d->d; ++a) {
        d->lo[a] = lo(a);
        extent = std::max(extent, hi(a) - lo(a));
    }
    // About one point per cell on a d-dimensional grid, at most 2^22 cells.
    const double n = double(pts.rows());
    const double perAxis = std::clamp(std::pow(n, 1.0 / d->d), 1.0, std::pow(4194304.0, 1.0 / d->d));
    d->cell = extent > 0 ? extent / perAxis : 1.0;
    std::size_t cells = 1;
    for (int a = 0; a < d->d; ++a) {
        d->dims[a] = std::max(1, int(std::ceil((hi(a) - lo(a)) / d->cell)) + 1);
        cells *= std::size_t(d->dims[a]);
    }
    std::vector<std::uint32_t> count(cells + 1, 0);
    std::vector<std::uint32_t> cellOf(pts.rows());
    for (Eigen::Index i = 0; i < pts.rows(); ++i) {
        int c[3] = {0, 0, 0};
        for (int a = 0; a < d->d; ++a)
            c[a] = d->cellCoord(pts(i, a), a);
        cellOf[i] = std::uint32_t(d->cellIndex(c));
        ++count[cellOf[i] + 1];
    }
    for (std::size_t k = 1; k <= cells; ++k)
        count[k] += count[k - 1];
    d->start = count;
    d->order.resize(pts.rows());
    std::vector<std::uint32_t> fillPos(count.begin(), count.end() - 1);
    for (Eigen::Index i = 0; i < pts.rows(); ++i)
        d->order[fillPos[cellOf[i]]++] = std::uint32_t(i);
}

PointIndex::~PointIndex() = default;

double PointIndex::nearest(const double *q, Eigen::Index *index) const
{
    const Impl &g = *d;
    int c0[3] = {0, 0, 0};
    for (int a = 0; a < g.d; ++a)
        c0[a] = g.cellCoord(q[a], a);
    double best = std::numeric_limits<double>::infinity();
    Eigen::Index bestIdx = -1;
    const int maxRing = std::max({g.dims[0], g.dims[1], g.dims[2]});
    auto visit = [&](int x, int y, int z) {
        const int c[3] = {x, y, z};
        const std::size_t cell = g.cellIndex(c);
        for (std::uint32_t k = g.start[cell]; k < g.start[cell + 1]; ++k) {
            const std::uint32_t i = g.order[k];
            double s = 0;
            for (int a = 0; a < g.d; ++a) {
                const double t = g.pts(i, a) - q[a];
                s += t * t;
            }
            if (s < best * best || bestIdx < 0) {
                const double dist = std::sqrt(s);
                if (dist < best) {
                    best = dist;
                    bestIdx = i;
                }
            }
        }
    };
    for (int r = 0; r <= maxRing; ++r) {
        // Points in ring r are at least (r - 1) cells away from q (clamping only helps).
        if (bestIdx >= 0 && (r - 1) * g.cell > best)
            break;
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = a < g.d ? std::max(0, c0[a] - r) : 0;
            hi[a] = a < g.d ? std::min(g.dims[a] - 1, c0[a] + r) : 0;
        }
        // The cells at Chebyshev distance exactly r from c0: whole layers where z or y is at
        // distance r, and only the two end columns x = c0 +- r in the rows between (a ring
        // costs its perimeter, not its area: far queries no longer scan r^2 cells per ring).
        for (int z = lo[2]; z <= hi[2]; ++z) {
            const bool zEdge = g.d > 2 && std::abs(z - c0[2]) == r;
            for (int y = lo[1]; y <= hi[1]; ++y) {
                const bool yEdge = g.d > 1 && std::abs(y - c0[1]) == r;
                if (zEdge || yEdge || r == 0) {
                    for (int x = lo[0]; x <= hi[0]; ++x)
                        visit(x, y, z);
                } else {
                    if (c0[0] - r >= 0)
                        visit(c0[0] - r, y, z);
                    if (c0[0] + r <= g.dims[0] - 1)
                        visit(c0[0] + r, y, z);
                }
            }
        }
    }
    if (index)
        *index = bestIdx;
    return best;
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
