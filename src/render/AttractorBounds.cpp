#include "render/AttractorBounds.h"

#include "core/analysis/Spectrum.h"

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

// Enough levels to see the attractor's extent, few enough to be instant.
constexpr double kImageBudget = 50000;
constexpr std::uint64_t kSampleBudget = 20000;

double imagesAt(const AttractorExtent &a, int depth)
{
    if (a.random)
        return double(a.samples);
    const double perImage = std::max<double>(1, double(a.start.vertices.rows()));
    if (a.ifs && a.ifs->size() > 0)
        return imageCount(*a.ifs, depth) * perImage;
    return 1e18;  // an automaton: count unknown
}

} // namespace

std::optional<QRectF> attractorBounds(const AttractorExtent &a)
{
    if (a.chaos.frame) {
        // Its own frame (a flame's camera): its points are not those of `ifs`.
        const auto &[x0, y0, x1, y1] = *a.chaos.frame;
        return QRectF(x0, y0, x1 - x0, y1 - y0);
    }
    if (!a.ifs || (!a.iterate && a.ifs->size() == 0) || a.start.vertices.rows() == 0)
        return std::nullopt;
    const std::vector<Projection> &views = a.views.empty() ? a.ifs->views : a.views;
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    const auto grow = [&](const Mat &m) {
        for (Eigen::Index r = 0; r < m.rows(); ++r)
            for (int c = 0; c < 2 && c < m.cols(); ++c)
                if (std::isfinite(m(r, c))) {
                    lo[c] = std::min(lo[c], m(r, c));
                    hi[c] = std::max(hi[c], m(r, c));
                }
    };
    int shallow = a.depth;
    while (shallow > 0 && imagesAt(a, shallow) > kImageBudget)
        --shallow;
    BoundsSink bounds(views);
    try {
        const bool maps = a.ifs->size() > 0 && !a.iterate;
        const IfsCheck check = maps ? checkIfs(*a.ifs) : IfsCheck{};
        if (maps && !check.contractive && (a.random || check.contractsOnAverage())) {
            // Contracting on average only (a flame): the box of 99% of the measure.
            if (const auto box = measureBox(*a.ifs, a.start.vertices.row(0), a.seed))
                grow(Mat(box->first).leftCols(std::min<Eigen::Index>(2, box->first.size()))),
                    grow(Mat(box->second).leftCols(std::min<Eigen::Index>(2, box->second.size())));
        } else if (maps && a.random) {
            ChaosOptions opt;
            opt.samples = std::min<std::uint64_t>(a.samples, kSampleBudget);
            opt.seed = a.seed;
            chaosGame(*a.ifs, a.start.vertices.row(0), opt, bounds);
        } else if (a.iterate) {
            a.iterate(a.start, std::min(shallow, 8), {&bounds}, {});
        } else if (check.contractive) {
            iterate(*a.ifs, a.start, shallow, bounds);
        }
    } catch (const std::exception &) {
        // An IFS that cannot be iterated is reported by whoever draws it.
    }
    if (!bounds.empty() && bounds.finite() && bounds.lo().size() >= 2)
        grow(Mat(bounds.lo()).leftCols(2)), grow(Mat(bounds.hi()).leftCols(2));
    if (!a.random)
        for (const Projection &v : views)
            grow(project(v, a.start.vertices).leftCols(2));
    if (lo[0] > hi[0])
        return std::nullopt;
    return QRectF(QPointF(lo[0], lo[1]), QPointF(hi[0], hi[1]));
}

} // namespace awb
