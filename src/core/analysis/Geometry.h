#pragma once
// Measuring attractors: polygon length and area, Hausdorff distances between point sets and to
// curves (004 §3.2, eq. (3.11)), and the box-counting dimension (004 eq. (3.15)).
// Point sets are n x d matrices, one point per row, d = 2 or 3.

#include "core/Types.h"

#include <memory>

namespace awb {

double polygonLength(const Mat &pts, bool closed = false);
// Signed shoelace area of a closed planar polygon (counter-clockwise positive).
double polygonArea(const Mat &pts);

// Nearest-neighbour queries on a fixed point set of 1 to 3 coordinates (a k-d tree: the cost of a
// query does not depend on how the points are spread, on a curve, a surface or a cloud).
class PointIndex {
public:
    explicit PointIndex(const Mat &pts);
    ~PointIndex();
    PointIndex(const PointIndex &) = delete;
    PointIndex &operator=(const PointIndex &) = delete;
    // Distance from q (size d) to the nearest indexed point; index of that point in `index`.
    double nearest(const double *q, Eigen::Index *index = nullptr) const;
    // Whether an indexed point lies closer than `radius` to q (stops at the first found).
    bool within(const double *q, double radius) const;

private:
    struct Impl;
    std::unique_ptr<Impl> d;
};

// max over a in A of the distance from a to the set B.
double directedDistance(const Mat &A, const Mat &B);
// d_H(A, B) = max(d(A, B), d(B, A)), 004 eq. (3.11).
double hausdorffDistance(const Mat &A, const Mat &B);
// Distance from each point of A to the polyline through the rows of `curve` (segments between
// consecutive rows), maximised over A.
double distanceToPolyline(const Mat &A, const Mat &curve);
// Hausdorff distance between the point set A and the curve given densely as a polyline:
// max(distanceToPolyline(A, curve), directedDistance(curve vertices, A)).
double hausdorffToCurve(const Mat &A, const Mat &curve);

struct BoxDimension {
    double dimension = 0.0;   // slope of log N(eps) against log(1/eps)
    double intercept = 0.0;
    double r2 = 0.0;          // quality of the straight-line fit
    int levelFrom = 0, levelTo = 0;  // eps = size / 2^level over this range was fitted
    std::vector<double> logInverseEps, logCount;  // every level computed (for plotting)
    bool valid = false;
    std::string note;         // why not valid, or what limited the range
};
// Box counting on the bounding box of the points (its largest side = eps at level 0).
// Levels from `minLevel` up to where boxes hold on average fewer than `minPointsPerBox` points.
BoxDimension boxCountingDimension(const Mat &pts, int minLevel = 2, int maxLevel = 24,
                                  double minPointsPerBox = 8.0);

} // namespace awb
