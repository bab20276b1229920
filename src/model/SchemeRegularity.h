#pragma once
// The certified regularity of a subdivision-curve item's scheme (layer 2): the core's
// Regularity.h applied to the item's scheme and number of control points, and its JSON form
// used by `attractor-cli analyse --json`.

#include "core/analysis/Regularity.h"

#include <QJsonObject>

namespace awb {

class SubdivisionCurveItem;
struct SchemeSpec;

// Throws nothing: a scheme the analysis does not cover (complex Bézier parameter, a scheme the
// core refuses) comes back with applies == false and the reason in `message`.
Regularity itemRegularity(const SubdivisionCurveItem &item, const RegularityOptions &options = {});
// The same for a scheme and a number of control points (a member of a family: the item's
// scheme with a parameter moved, `regularity-interval` and the regularity chart).
Regularity specRegularity(const SchemeSpec &spec, int controlPoints,
                          const RegularityOptions &options = {});

// {"lower", "upper", "width", "smoothness": "C^n", "method", "message", "notes", "sum_rules",
// "arity", "seconds", "jsr": {"lower", "upper", "product", "norm", "depth"}}; lower/upper/width
// only when finite (C^infinity and "does not apply" carry "smoothness" and "message").
QJsonObject regularityJson(const Regularity &r);

} // namespace awb
