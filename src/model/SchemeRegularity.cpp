#include "model/SchemeRegularity.h"

#include "core/schemes/Scheme.h"
#include "model/SubdivisionCurveItem.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <cmath>

namespace awb {

Regularity specRegularity(const SchemeSpec &spec, int controlPoints,
                          const RegularityOptions &options)
{
    Regularity r;
    if (spec.isComplex()) {
        r.message = QCoreApplication::translate("awb::SchemeRegularity",
                                                "does not apply: a complex de Casteljau "
                                                "parameter is not a real subdivision scheme")
                        .toStdString();
        return r;
    }
    try {
        const auto scheme = spec.makeScheme();
        const int m = std::max(controlPoints, scheme->minControlPoints());
        return schemeRegularity(*scheme, std::min(m, scheme->maxControlPoints()), options);
    } catch (const std::exception &e) {
        r.message = QCoreApplication::translate("awb::SchemeRegularity", "does not apply: %1")
                        .arg(QString::fromStdString(e.what()))
                        .toStdString();
        return r;
    }
}

Regularity itemRegularity(const SubdivisionCurveItem &item, const RegularityOptions &options)
{
    return specRegularity(item.scheme(), int(item.controlPoints(0).size()), options);
}

QJsonObject regularityJson(const Regularity &r)
{
    QJsonObject o;
    o["smoothness"] = QString::fromStdString(r.smoothnessLabel());
    o["message"] = QString::fromStdString(r.message);
    if (!r.method.empty())
        o["method"] = QString::fromStdString(r.method);
    if (!r.notes.empty())
        o["notes"] = QString::fromStdString(r.notes);
    if (!r.applies || r.infinite)
        return o;
    o["arity"] = r.arity;
    o["sum_rules"] = r.sumRules;
    o["seconds"] = r.seconds;
    // L2 smoothness (masks): the Sobolev exponent s_2, exact linear algebra (core Sobolev.h)
    o["sobolev"] = r.sobolev ? QJsonValue(*r.sobolev) : QJsonValue(QJsonValue::Null);
    if (r.divergent && r.transition.empty())
        return o;   // no JSR was needed (the mask does not reproduce constants)
    o["lower"] = r.lower;
    o["upper"] = r.upper;
    o["width"] = r.width();
    QJsonArray word;
    for (int i : r.jsr.product)
        word.append(i);
    // Exact (issue 32): an invariant polytope closed; `smp` its spectrum maximizing product
    // (indices of the transition matrices T_0..T_(N-1)), `method` names it.
    o["exact"] = r.exact;
    QJsonArray smp;
    for (int i : r.smp)
        smp.append(i);
    o["smp"] = r.exact ? QJsonValue(smp) : QJsonValue(QJsonValue::Null);
    if (!r.polytopeNote.empty())
        o["polytope"] = QString::fromStdString(r.polytopeNote);
    o["jsr"] = QJsonObject{{"lower", r.jsr.lower},
                           {"upper", r.jsr.upper},
                           {"product", word},
                           {"norm", QString::fromStdString(r.jsr.norm)},
                           {"depth", r.jsr.depth},
                           {"converged", r.jsr.converged}};
    return o;
}

} // namespace awb
