#include "core/ifs/SurfaceIfs.h"

#include "core/Messages.h"

#include <algorithm>
#include <map>

namespace awb {

SurfaceIfs buildSurfaceIfs(const LatticeScheme &scheme, const PatchLayout &layout,
                           const std::vector<LatticePoint> &lattice, const Mat &P,
                           std::vector<int> mapsUsed)
{
    return buildSurfaceIfs(scheme, layout, surfaceMatrices(scheme, layout), lattice, P,
                           std::move(mapsUsed));
}

SurfaceIfs buildSurfaceIfs(const LatticeScheme &scheme, const PatchLayout &layout,
                           const SurfaceMatrices &canonical,
                           const std::vector<LatticePoint> &lattice, const Mat &P,
                           std::vector<int> mapsUsed)
{
    requireFinite(P, coreTranslate("awb::ifs", "control points"));
    if (Eigen::Index(lattice.size()) != P.rows())
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "the lattice lists %1 coordinates for %2 control points"),
            lattice.size(), P.rows()));
    const std::vector<int> order = matchNet(canonical.net, lattice, scheme.lattice());
    SurfaceIfs out;
    out.layout = layout;
    out.lattice = lattice;
    for (const Mat &S : canonical.S)
        out.S.push_back(reorder(S, order));
    const int n = int(out.S.size());
    if (mapsUsed.empty())
        for (int i = 0; i < n; ++i)
            mapsUsed.push_back(i);
    std::sort(mapsUsed.begin(), mapsUsed.end());
    if (std::adjacent_find(mapsUsed.begin(), mapsUsed.end()) != mapsUsed.end())
        throw InputError(coreTranslate("awb::ifs", "a map is listed twice among the maps used"));
    if (mapsUsed.front() < 0 || mapsUsed.back() >= n)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "map index %1 is out of range: the %2 layout has maps 0 "
                                      "to %3"),
            mapsUsed.front() < 0 ? mapsUsed.front() : mapsUsed.back(), layout.name, n - 1));
    out.mapsUsed = mapsUsed;
    std::vector<Mat> used;
    for (int i : mapsUsed)
        used.push_back(out.S[size_t(i)]);
    std::vector<int> freeRows = affineBasisRows(P);
    if (int(freeRows.size()) != P.cols() + 1)
        freeRows.clear();  // a flat net: the default rows, whose lifting reports the problem
    out.ifs = buildSubdivisionIfs(used, 0, P, IfsForm::Automatic, freeRows);

    // Corner limit points: the limit stencil at each domain corner, in the user's order.
    std::map<LatticePoint, int> index;
    for (size_t k = 0; k < canonical.net.size(); ++k)
        index[canonical.net[k]] = int(k);
    std::vector<int> userRow(order.size());
    for (size_t k = 0; k < order.size(); ++k)
        userRow[size_t(order[k])] = int(k);
    const Eigen::Index corners = Eigen::Index(layout.domain.size());
    Mat lambda = Mat::Zero(corners, P.rows());
    for (Eigen::Index c = 0; c < corners; ++c) {
        const LatticePoint corner{int(std::lround(layout.domain[size_t(c)].x())),
                                  int(std::lround(layout.domain[size_t(c)].y()))};
        for (const auto &[delta, w] : scheme.limitStencil())
            lambda(c, userRow[size_t(index.at(corner + delta))]) += w;
    }
    out.cornerLimitPoints = lambda * P;
    out.cornerLimitStart = out.ifs.barycentric()
                               ? lambda
                               : Mat((lambda * out.ifs.lifting.lifted).leftCols(P.rows() - 1));
    return out;
}

} // namespace awb
