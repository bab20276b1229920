#include "model/NormalVectorItem.h"

#include "core/schemes/NormalVectorScheme.h"
#include "model/Commands.h"
#include "model/PointSetProperty.h"
#include "model/ProjectIO.h"
#include "model/PropertyDeclaration.h"

#include <cmath>

namespace awb {

namespace {

const std::vector<NormalVectorPreset> &presets()
{
    static const std::vector<NormalVectorPreset> list = normalVectorPresets();
    return list;
}

const NormalVectorPreset *findPreset(const QString &key)
{
    for (const NormalVectorPreset &p : presets())
        if (QString::fromStdString(p.key) == key)
            return &p;
    return nullptr;
}

// The preset's rules as custom values (so that an edit starts from what is shown).
void copyPresetRules(NormalVectorSpec &spec)
{
    if (spec.isCustom())
        return;
    const NormalVectorScheme s = spec.makeScheme();
    spec.alpha = s.alpha();
    spec.beta = s.beta();
    spec.normal = s.normal() == NormalDirection::Negative ? NormalVectorSpec::Normal::Negative
                                                          : NormalVectorSpec::Normal::Positive;
    spec.signs.clear();
    for (BetaSign sign : s.signs())
        spec.signs.push_back(NormalVectorSpec::Sign(int(sign)));
    spec.preset = QStringLiteral("custom");
}

} // namespace

// ---- NormalVectorSpec -------------------------------------------------------------------------

const QStringList &NormalVectorSpec::presetNames()
{
    static const QStringList names = [] {
        QStringList out;
        for (const NormalVectorPreset &p : presets())
            out << QString::fromStdString(p.key);
        return out << QStringLiteral("custom");
    }();
    return names;
}

const QStringList &NormalVectorSpec::normalNames()
{
    static const QStringList names{"positive", "negative"};
    return names;
}

const QStringList &NormalVectorSpec::signNames()
{
    // In the order of the core's BetaSign.
    static const QStringList names{"constant", "edge-alternating", "level-edge-alternating",
                                   "level-alternating"};
    return names;
}

NormalVectorScheme NormalVectorSpec::makeScheme() const
{
    if (!isCustom()) {
        if (const NormalVectorPreset *p = findPreset(preset))
            return p->scheme;
        throw InputError(tr("unknown preset \"%1\"").arg(preset).toStdString());
    }
    std::vector<BetaSign> core;
    for (Sign s : signs)
        core.push_back(BetaSign(int(s)));
    return NormalVectorScheme(alpha, beta,
                              normal == Normal::Negative ? NormalDirection::Negative
                                                         : NormalDirection::Positive,
                              core);
}

int NormalVectorSpec::arity() const
{
    if (isCustom())
        return int(alpha.size());
    const NormalVectorPreset *p = findPreset(preset);
    return p ? p->scheme.arity() : -1;
}

MaybeProblem NormalVectorSpec::check() const
{
    if (!presetNames().contains(preset))
        return Problem{"preset", tr("unknown preset \"%1\"").arg(preset)};
    if (steps < 0 || steps > maxSteps)
        return Problem{"steps", tr("%1 steps: at least 0 and at most %2 are allowed")
                                    .arg(steps).arg(maxSteps)};
    if (!isCustom())
        return std::nullopt;
    if (alpha.size() < 2)
        return Problem{"alpha", tr("need at least 2 rules (p >= 2), got %1").arg(alpha.size())};
    if (beta.size() != alpha.size())
        return Problem{"beta", tr("%1 values of beta for %2 of alpha: need one per rule")
                                   .arg(beta.size()).arg(alpha.size())};
    if (!signs.empty() && signs.size() != 1 && signs.size() != alpha.size())
        return Problem{"signs", tr("%1 signs for %2 rules: give none, one, or one per rule")
                                    .arg(signs.size()).arg(alpha.size())};
    for (const auto &[key, values] : {std::pair{"alpha", &alpha}, std::pair{"beta", &beta}})
        for (size_t j = 0; j < values->size(); ++j)
            if (!std::isfinite((*values)[j]))
                return Problem{QStringLiteral("%1[%2]").arg(key).arg(j + 1),
                               tr("%1_%2 is not a finite number").arg(key).arg(j)};
    try {
        (void)makeScheme();
    } catch (const InputError &e) {
        return Problem{"alpha", QString::fromStdString(e.what())};
    }
    return std::nullopt;
}

// ---- NormalVectorItem -------------------------------------------------------------------------

NormalVectorItem::NormalVectorItem()
    : AttractorItem(tr("Normal-vector curve")), m_points{{0, 0}, {1, 0}}
{
}

MaybeProblem NormalVectorItem::checkSpec(const NormalVectorSpec &spec) const
{
    return checkWithMaps(spec.check(), spec.arity());
}

bool NormalVectorItem::setSpec(const NormalVectorSpec &spec, int gesture)
{
    return setDeclared(*this, spec, gesture);
}

DerivedIfs NormalVectorItem::computeIfs() const
{
    const NormalVectorScheme scheme = m_spec.makeScheme();
    const ControlPolygon poly{toMatrix(m_points), m_spec.closed};
    scheme.validate(poly);
    DerivedIfs out;
    out.polygon = scheme.subdivide(poly, m_spec.steps).points;
    out.polygonClosed = m_spec.closed;
    out.toIfsSpace = [](const Mat &X) { return X; };
    out.S.unavailable = tr("the normal-vector scheme is not linear: it has no subdivision "
                           "matrices (001 eq. (1))");
    QStringList note{QString::fromStdString(analyse(scheme).verdict)};
    if (const auto why = whyNoEquivalentIfs(scheme)) {
        // No IFS: the polygon is the figure; ifs.maps stays empty and nothing is iterated.
        note << tr("No equivalent IFS: %1").arg(QString::fromStdString(*why));
        out.A.unavailable = note.last();
    } else {
        try {
            out.ifs = equivalentIfs(scheme, poly);
            for (const AffineMap &f : out.ifs.maps)
                out.A.real.push_back(f.A);
            applyAlgorithm(out.ifs);
        } catch (const InputError &e) {
            // A map that does not contract: the polygon is still well defined.
            note << tr("No equivalent IFS: %1").arg(QString::fromUtf8(e.what()));
            out.ifs = Ifs();
            out.A.real.clear();
            out.A.unavailable = note.last();
        }
    }
    out.note = note.join(QLatin1Char(' '));
    return out;
}

// ---- declared properties ----------------------------------------------------------------------

const PropertyTable &NormalVectorItem::declaration()
{
    static const PropertyTable table = [] {
        using S = NormalVectorSpec;
        const auto custom = [](const S &s) { return s.isCustom(); };
        Declaration<NormalVectorItem> d(&AttractorItem::attractorProperties());
        auto spec = d.part(&NormalVectorItem::m_spec, &NormalVectorItem::checkSpec,
                           &NormalVectorItem::specChanged,
                           QT_TR_NOOP("Change normal-vector scheme of %1"));
        spec.checkedOnRead([](const NormalVectorItem &, const S &s) { return s.check(); });
        spec.choiceBy(
                "preset", S::presetNames(), {},
                [](const S &s) { return int(S::presetNames().indexOf(s.preset)); },
                [](S &s, int i) { s.preset = S::presetNames().at(i); })
            .label(QT_TR_NOOP("Scheme"))
            .group(QT_TR_NOOP("Scheme"))
            .required()
            .choicesFrom([](const NormalVectorItem &, const S &) {
                QStringList texts;
                for (const NormalVectorPreset &p : presets())
                    texts << QString::fromStdString(p.name);
                return texts << tr("Own rules");
            })
            .adjust([](const NormalVectorItem &, const S &, ParameterInfo &i) {
                i.toolTip = QString::fromStdString(normalVectorConventions());
            })
            // Own rules start from the preset's.
            .onEdit([](const NormalVectorItem &item, S &next) -> MaybeProblem {
                if (next.isCustom() && !item.m_spec.isCustom()) {
                    next.preset = item.m_spec.preset;
                    copyPresetRules(next);
                }
                return std::nullopt;
            });
        spec.integer("steps", &S::steps)
            .label(QT_TR_NOOP("Steps"))
            .group(QT_TR_NOOP("Scheme"))
            .range(0, S::maxSteps)
            .slider(0, 10)
            .tip(QT_TR_NOOP("Subdivision steps of the polygon shown"));
        // The normal, α and β show the preset's rules; editing one makes them own rules.
        spec.choice("normal", &S::normal, S::normalNames(),
                    {QT_TR_NOOP("Counter-clockwise (positive)"),
                     QT_TR_NOOP("Clockwise (negative)")})
            .label(QT_TR_NOOP("Normal direction"))
            .group(QT_TR_NOOP("Scheme"))
            .savedWhen(custom)
            .beforeEdit([](const NormalVectorItem &, S &s) { copyPresetRules(s); })
            .getter([](const NormalVectorItem &, const S &s) {
                return s.makeScheme().normal() == NormalDirection::Negative ? 1 : 0;
            });
        spec.boolean("closed", &S::closed)
            .label(QT_TR_NOOP("Closed polygon"))
            .group(QT_TR_NOOP("Scheme"));
        // One rule per new point: α_j along the edge, β_j along its normal.
        const auto rules = [&spec](const char *key, std::vector<double> S::*list,
                                   const char *label, double lo, double hi) {
            spec.numbers(key, list)
                .savedWhen([](const S &s) { return s.isCustom(); })
                .required()
                .beforeEdit([](const NormalVectorItem &, S &s) { copyPresetRules(s); })
                .elements(
                    QStringLiteral("%1.%2").arg(key, QStringLiteral("%1")), label,
                    ParameterInfo::Type::Real, [](const S &s) { return s.arity(); },
                    [list](const S &s, int j) {
                        const NormalVectorScheme scheme = s.makeScheme();
                        const std::vector<double> &v =
                            list == &S::alpha ? scheme.alpha() : scheme.beta();
                        return QVariant(v[size_t(j)]);
                    },
                    [list, key](S &s, int j, const QVariant &v) -> MaybeProblem {
                        const auto x = property::toReal(v);
                        if (!x)
                            return Problem{QString::fromLatin1(key),
                                           property::notValid(v, QString::fromLatin1(key))};
                        (s.*list)[size_t(j)] = *x;
                        return std::nullopt;
                    },
                    QT_TR_NOOP("Rules"))
                .slider(lo, hi);
        };
        rules("alpha", &S::alpha, QT_TR_NOOP("α%1"), 0, 1);
        rules("beta", &S::beta, QT_TR_NOOP("β%1"), -1, 1);
        spec.structured(
                "signs", QStringLiteral("sign rules"),
                [](const NormalVectorItem &, const S &s) {
                    QJsonArray signs;
                    for (S::Sign sign : s.signs)
                        signs.append(S::signNames().at(int(sign)));
                    return QJsonValue(signs);
                },
                [](const NormalVectorItem &, S &s, const QJsonValue &v, const QString &where) {
                    if (!v.isArray())
                        throw LoadError{where, tr("expected an array of sign rules")};
                    const QJsonArray list = v.toArray();
                    s.signs.clear();
                    for (qsizetype i = 0; i < list.size(); ++i) {
                        const int k = int(S::signNames().indexOf(list[i].toString()));
                        if (!list[i].isString() || k < 0)
                            throw LoadError{where + QStringLiteral("[%1]").arg(i + 1),
                                            tr("expected one of \"%1\"")
                                                .arg(S::signNames().join("\", \""))};
                        s.signs.push_back(S::Sign(k));
                    }
                })
            .label(QT_TR_NOOP("Signs of β"))
            .tip(QT_TR_NOOP("How the sign of β alternates: \"constant\", \"edge-alternating\", "
                            "\"level-edge-alternating\" or \"level-alternating\"; none, one, or "
                            "one per rule"))
            .savedWhen(custom);
        declarePointSet(d, 0, QStringLiteral("control_points"), QT_TR_NOOP("Control points"));
        return d.table();
    }();
    return table;
}

} // namespace awb
