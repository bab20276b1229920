#include "cli/Gallery.h"

#include "core/ifs/Attractor.h"

namespace awb {

namespace {
Mat pts(std::initializer_list<std::initializer_list<double>> r) { return matrixFromRows(r); }
} // namespace

std::vector<GalleryExample> builtinGallery()
{
    std::vector<GalleryExample> g;
    // 000 Fig. 2: "we choose a random homogeneous point in five dimensions" — a fixed one here,
    // given in the lifted coordinates (x, y, e1, e2) so that it is off the plane of the curve.
    g.push_back({"000-fig02-cubic-bspline-from-point",
                 "000 Fig. 2: uniform cubic B-spline IFS from a single point",
                 std::make_shared<UniformScheme>(bsplineScheme(3)),
                 pts({{0, 0}, {1.2, 2.6}, {3.2, 3.0}, {4.6, 0.6}, {6.2, 1.8}}),
                 pts({{5.5, 3.4, 0.8, -0.6}}), StartSet::Kind::Points, 16});
    // 000 Fig. 3: knots {0,0,0,1,2,2,2}; a self-intersecting control polygon, a triangle to start.
    g.push_back({"000-fig03-end-interpolating-cubic-from-triangle",
                 "000 Fig. 3: end-interpolating cubic B-spline IFS from a triangle",
                 std::make_shared<EndInterpolatingBSplineScheme>(3),
                 pts({{0, 0}, {5, 4.5}, {5.5, -0.5}, {0.5, 3.5}, {5, 3}}),
                 pts({{1, -1.2}, {3.5, -1.5}, {2, 0.8}}), StartSet::Kind::Polygon, 12});
    // 000 Fig. 5: four-point scheme (omega = 1/16) on seven points, a line segment to start.
    g.push_back({"000-fig05-four-point-from-segment",
                 "000 Fig. 5: four-point scheme IFS from a line segment",
                 std::make_shared<UniformScheme>(fourPointScheme(1.0 / 16)),
                 pts({{0, 0}, {1, 2}, {2.5, 2.4}, {3.5, 0.6}, {5, 0.2}, {6, 2.2}, {7.5, 2.5}}),
                 pts({{1.5, -0.8}, {6, 3.2}}), StartSet::Kind::Polyline, 12});
    return g;
}

} // namespace awb
