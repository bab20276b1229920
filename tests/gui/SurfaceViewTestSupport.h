#pragma once
// The Loop surface item of the 3D view's tests (test_surface_view, test_surface_view_gl), and
// a view fed with it as ItemController feeds one.
#include "gui/views/SurfaceView.h"
#include "core/ifs/SurfaceIfs.h"
#include "model/SubdivisionSurfaceItem.h"

#include <QtTest>

#include <memory>

namespace awb::test {

inline std::unique_ptr<SubdivisionSurfaceItem> loopItem(int depth = 6)
{
    auto item = std::make_unique<SubdivisionSurfaceItem>();
    item->setName(QStringLiteral("Loop"));
    item->setScheme({SurfaceSchemeSpec::Kind::Loop, QStringLiteral("hexagon")});
    AlgorithmSpec a = item->algorithm();
    a.depth = depth;
    item->setAlgorithm(a);
    // As Add > Subdivision surface does: the polygon of the domain's corner limit points,
    // whose images lie on the surface (the default triangle of net points only converges).
    const Mat c = item->derivedIfs()->surface->cornerLimitPoints;
    StartSetSpec start;
    start.kind = StartSetSpec::Kind::Polygon;
    start.points.clear();
    for (Eigen::Index r = 0; r < c.rows(); ++r)
        start.points.push_back({c(r, 0), c(r, 1), c(r, 2)});
    item->setStartSet(start);
    return item;
}

// Feeds a view the item's data as ItemController does (for the view on its own).
inline void feed(SurfaceView &view, SubdivisionSurfaceItem &item)
{
    const auto d = item.derivedIfs();
    QVERIFY2(d, qPrintable(item.derivedError()));
    SurfaceView::RenderSettings rs;
    rs.depth = item.algorithm().depth;
    view.setRenderSettings(rs);
    view.setControlNet(toMatrix(item.controlPoints(0), 3), item.refinedMesh(0).faces);
    view.setIfs(std::make_shared<const Ifs>(d->ifs), item.coreStartSet(*d), d->mapIndex);
}

} // namespace awb::test
