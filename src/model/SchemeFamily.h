#pragma once
// A family of a subdivision-curve item's scheme (layer 2): the item's scheme with one or two of
// its real parameters moved -- the four-point tension omega, a corner cutting's a and b, or
// names written into a mask ("v, 0, w, 0, 1/2 - w - v, 1, 1/2 - w - v, 0, w, 0, v"). Each
// member is analysed as the item itself would be (SchemeRegularity.h), so regularity-interval,
// the regularity atlas (core RegularityAtlas.h; the Python module's atlas on a Dask cluster)
// and the window's Regularity Atlas compute a member one way. Serialisable (toJson/fromJson)
// so a cluster's workers rebuild it from plain data.

#include "core/analysis/RegularityAtlas.h"
#include "model/SchemeSpec.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QStringList>

namespace awb {

class SubdivisionCurveItem;

class SchemeFamily {
    Q_DECLARE_TR_FUNCTIONS(awb::SchemeFamily)
public:
    // `parameters`: one or two names. Without `mask`: "omega" (four-point), "a" / "b" (corner
    // cutting). With `mask` (a mask item): names that appear in it. Throws InputError naming
    // what does not fit.
    SchemeFamily(const SchemeSpec &base, int controlPoints, QStringList parameters,
                 QString mask = {});
    static SchemeFamily ofItem(const SubdivisionCurveItem &item, QStringList parameters,
                               QString mask = {});

    const QStringList &parameters() const { return m_parameters; }
    const QString &mask() const { return m_mask; }
    const SchemeSpec &base() const { return m_base; }
    int controlPoints() const { return m_controlPoints; }

    // The member at `values` (one per parameter); nullopt with `why` when there is none (a mask
    // whose coefficients do not parse, ...).
    std::optional<SchemeSpec> member(const std::vector<double> &values, QString *why) const;
    // Its certified regularity; applies = false when there is no member.
    Regularity regularity(const std::vector<double> &values, const RegularityOptions &o) const;
    // The core's evaluator over this family.
    AtlasMember atlasMember() const;

    // {"scheme": ..., "control_points": m, "parameters": [...], "mask": "..."}; fromJson throws
    // InputError on anything else.
    QJsonObject toJson() const;
    static SchemeFamily fromJson(const QJsonObject &json);

private:
    SchemeSpec m_base;
    int m_controlPoints = 0;
    QStringList m_parameters;
    QString m_mask;
    std::vector<double SchemeSpec::*> m_fields;   // without a mask: the fields moved
};

// The atlas's rows and runs as JSON: rows {"params": {name: value}, "lower", "upper", "exact",
// "smoothness", "verdict", "sobolev", "applies", "timed_out", "message"}; infinite bounds
// (C^infinity) are written as null with "smoothness": "C^infinity".
QJsonObject atlasRowJson(const AtlasRow &row, const std::vector<AtlasAxis> &axes);
AtlasRow atlasRowFromJson(const QJsonObject &json, const std::vector<AtlasAxis> &axes);

} // namespace awb
