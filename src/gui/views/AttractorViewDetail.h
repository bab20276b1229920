#pragma once
// Internal to AttractorView (its AttractorView*.cpp units only): the view's tuning constants,
// overlay colours and small geometry helpers shared by those translation units.

#include "core/Types.h"
#include "gui/views/AttractorRenderer.h"

#include <QColor>
#include <QPainterPath>
#include <QPointF>
#include <QPolygonF>
#include <QRectF>
#include <QString>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

namespace awb::attractor_view {

inline constexpr double kHandleRadius = 5.0;      // screen pixels
inline constexpr double kHitRadius = 9.0;         // a little larger than drawn: easier to grab
inline constexpr double kClickSlop = 4.0;         // a right press moved less is a click
inline constexpr double kFitMargin = 24.0;
inline constexpr double kMinScale = 1e-9, kMaxScale = 1e12;
// F^k(X0) is drawn as vectors up to this many vertices (it stays interactive).
inline constexpr std::size_t kMaxHutchinsonVertices = 50000;
// A render faster than this shows no progress text (it would only flicker).
inline constexpr int kQuietRenderMs = 250;
// A gesture that pauses this long gets its full picture (the interactive ones fit a frame).
inline constexpr int kRefineDelayMs = 120;
// An export's raster is made at the target's device resolution, at most this many pixels a
// side (a 300 dpi A4 page is 3508 x 2480; a QImage this big takes 256 MB).
inline constexpr int kMaxExportRaster = 8192;
// Curves go to vector devices as paths when the iteration has at most this many images and at
// most this many vertices remain after joining and simplifying (else a raster).
inline constexpr double kMaxExportCurveImages = 2e7;
inline constexpr std::size_t kMaxExportCurveVertices = 1000000;
// An export draws the attractor as vector dots up to this many points.
inline constexpr std::size_t kMaxExportVectorVertices = 20000;
// The export's vector dots come from the renderer's streams, so they are the raster's points.
inline constexpr int kRandomStreams = AttractorRenderer::kRandomStreams;

inline const QColor kControlColour(40, 40, 40);
inline const QColor kStartColour(230, 120, 0);
inline const QColor kExactColour(20, 150, 60);
inline const QColor kSubdivisionColour(120, 120, 160);

inline QString subscript(int n)
{
    static const QChar digits[] = {QChar(0x2080), QChar(0x2081), QChar(0x2082), QChar(0x2083),
                                   QChar(0x2084), QChar(0x2085), QChar(0x2086), QChar(0x2087),
                                   QChar(0x2088), QChar(0x2089)};
    QString s;
    for (QChar c : QString::number(n))
        s += digits[c.digitValue()];
    return s;
}

inline QPolygonF toPolygon(const Mat &pts)
{
    QPolygonF out;
    if (pts.cols() < 2)
        return out;
    out.reserve(int(pts.rows()));
    for (Eigen::Index r = 0; r < pts.rows(); ++r)
        out << QPointF(pts(r, 0), pts(r, 1));
    return out;
}

inline QPainterPath polylinePath(const QPolygonF &poly, bool closed)
{
    QPainterPath path;
    path.addPolygon(poly);
    if (closed)
        path.closeSubpath();
    return path;
}

inline bool finitePoint(const QPointF &p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

// Bounds of the finite points of `poly` (a zero-size rectangle for one point); nullopt if none.
inline std::optional<QRectF> boundsOf(const QPolygonF &poly)
{
    std::optional<QRectF> r;
    for (const QPointF &p : poly) {
        if (!finitePoint(p))
            continue;
        if (!r) {
            r = QRectF(p, QSizeF(0, 0));
            continue;
        }
        // Not QRectF::united: it ignores zero-size rectangles.
        r->setLeft(std::min(r->left(), p.x()));
        r->setRight(std::max(r->right(), p.x()));
        r->setTop(std::min(r->top(), p.y()));
        r->setBottom(std::max(r->bottom(), p.y()));
    }
    return r;
}

// A "nice" grid step (1, 2 or 5 times a power of ten) close to `approx`.
// Grid lines at k * step (k a whole number) within [lo, hi]: the first k and how many, or
// nothing when there would be more than `most` lines or when the coordinates are too large
// for the step (beyond 1e12 steps from 0, neighbouring lines coincide in double precision and
// a loop adding the step to 1e300 would never end).
struct GridLines {
    double first = 0;
    int count = 0;
};
inline std::optional<GridLines> gridLines(double lo, double hi, double step, int most)
{
    if (!(step > 0) || !std::isfinite(step) || !std::isfinite(lo) || !std::isfinite(hi))
        return std::nullopt;
    const double k0 = std::ceil(lo / step), k1 = std::floor(hi / step);
    if (!std::isfinite(k0) || !std::isfinite(k1) || std::max(std::abs(k0), std::abs(k1)) > 1e12)
        return std::nullopt;
    if (k1 - k0 > most)
        return std::nullopt;
    return GridLines{k0, std::max(0, int(k1 - k0) + 1)};
}

inline double niceStep(double approx)
{
    const double e = std::pow(10.0, std::floor(std::log10(approx)));
    const double f = approx / e;
    return (f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0) * e;
}

} // namespace awb::attractor_view
