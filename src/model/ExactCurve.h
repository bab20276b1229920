#pragma once
// The exact curve an item's attractor converges to, where one is known in closed form: the
// B-spline / Bézier / end-interpolating curve of a real subdivision scheme (evaluated by the
// core's CurveScheme::exactCurve), and for a complex Bézier curve (004 §3.7) the Bézier curve
// c([0, 1]) when t is real or the Takagi image c(x + 2iy T(x)) of Conjecture 3.7.1 when
// t = 1/2 + iy (which the attractor approaches as O(y^2); the label says so). Shared by the
// attractor view and the CLI's render so both draw the same overlay.

#include "core/Types.h"

#include <QString>

#include <memory>
#include <optional>

namespace awb {

class CertifiedCurve;
class Item;

struct ExactCurve {
    Mat points;       // n x 2, plane coordinates, n >= 2
    QString label;    // for a legend: what the curve is
};

// nullopt when the item has no known exact curve or its data cannot be computed (the item's
// own derived error says why). `samples` is a hint for the number of points.
std::optional<ExactCurve> exactCurveOf(const Item *item, int samples = 600);

// The same curve as exact data for measuring (core/analysis/HausdorffBracket): the Bézier
// pieces of the B-spline / Bézier / end-interpolating curve, or the control points and y of the
// Takagi image, with enclosures of every parameter interval; the label is exactCurveOf's.
struct CertifiedExactCurve {
    std::shared_ptr<const CertifiedCurve> curve;
    QString label;
};
std::optional<CertifiedExactCurve> certifiedExactCurveOf(const Item *item);

} // namespace awb
