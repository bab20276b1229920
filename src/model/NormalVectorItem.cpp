#include "model/NormalVectorItem.h"

#include "core/schemes/NormalVectorScheme.h"
#include "model/Commands.h"
#include "model/ProjectIO.h"

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

// "alpha.2" -> (true, 2) within p rules.
bool parseRuleKey(const QString &key, const QString &name, int p, int *j)
{
    if (!key.startsWith(name + QLatin1Char('.')))
        return false;
    bool ok = false;
    *j = key.mid(name.size() + 1).toInt(&ok);
    return ok && *j >= 0 && *j < p;
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
    if (auto p = spec.check())
        return p;
    if (auto p = algorithm().check(spec.arity()))
        return Problem{"algorithm." + p->field, p->message};
    return std::nullopt;
}

bool NormalVectorItem::setSpec(const NormalVectorSpec &spec, int gesture)
{
    if (checkSpec(spec))
        return false;
    applyProperty(&NormalVectorItem::m_spec, spec, &NormalVectorItem::specChanged,
                  tr("Change normal-vector scheme of %1").arg(name()), gesture);
    return true;
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

void NormalVectorItem::write(QJsonObject &json) const
{
    AttractorItem::write(json);
    json["preset"] = m_spec.preset;
    json["steps"] = m_spec.steps;
    json["closed"] = m_spec.closed;
    json["control_points"] = ProjectIO::pointsToJson(m_points);
    if (!m_spec.isCustom())
        return;
    QJsonArray alpha, beta, signs;
    for (double a : m_spec.alpha)
        alpha.append(a);
    for (double b : m_spec.beta)
        beta.append(b);
    for (NormalVectorSpec::Sign s : m_spec.signs)
        signs.append(NormalVectorSpec::signNames().at(int(s)));
    json["alpha"] = alpha;
    json["beta"] = beta;
    json["normal"] = NormalVectorSpec::normalNames().at(int(m_spec.normal));
    json["signs"] = signs;
}

void NormalVectorItem::read(const FieldReader &fields)
{
    AttractorItem::read(fields);
    NormalVectorSpec spec;
    spec.preset = NormalVectorSpec::presetNames().at(
        fields.choice("preset", NormalVectorSpec::presetNames()));
    spec.steps = int(fields.integer("steps", spec.steps, 0, NormalVectorSpec::maxSteps));
    const QJsonValue closed = fields.value("closed");
    if (!closed.isUndefined() && !closed.isBool())
        fields.fail("closed", tr("expected true or false"));
    spec.closed = closed.toBool(false);
    if (spec.isCustom()) {
        spec.alpha = fields.numbers("alpha");
        spec.beta = fields.numbers("beta");
        spec.normal = NormalVectorSpec::Normal(
            fields.choice("normal", NormalVectorSpec::normalNames(), int(spec.normal)));
        const QJsonValue signs = fields.value("signs");
        if (!signs.isUndefined() && !signs.isArray())
            fields.fail("signs", tr("expected an array of sign rules"));
        const QJsonArray list = signs.toArray();
        for (qsizetype i = 0; i < list.size(); ++i) {
            const int s = int(NormalVectorSpec::signNames().indexOf(list[i].toString()));
            if (!list[i].isString() || s < 0)
                throw LoadError{fields.path("signs") + QStringLiteral("[%1]").arg(i + 1),
                                tr("expected one of \"%1\"")
                                    .arg(NormalVectorSpec::signNames().join("\", \""))};
            spec.signs.push_back(NormalVectorSpec::Sign(s));
        }
    }
    fields.require(spec.check());
    m_spec = spec;
    m_points = fields.points("control_points");
}

// ---- generic parameters ---------------------------------------------------------------------

QList<ParameterInfo> NormalVectorItem::parameters() const
{
    using P = ParameterInfo;
    const QString group = tr("Scheme");
    QStringList presetTexts;
    for (const NormalVectorPreset &p : presets())
        presetTexts << QString::fromStdString(p.name);
    presetTexts << tr("Own rules");
    QList<ParameterInfo> list;
    list << P::make("preset", tr("Scheme"), P::Type::Choice)
                .options(presetTexts)
                .in(group)
                .tip(QString::fromStdString(normalVectorConventions()));
    list << P::make("steps", tr("Steps"), P::Type::Integer)
                .range(0, NormalVectorSpec::maxSteps)
                .slider(0, 10)
                .in(group)
                .tip(tr("Subdivision steps of the polygon shown"));
    list << P::make("normal", tr("Normal direction"), P::Type::Choice)
                .options({tr("Counter-clockwise (positive)"), tr("Clockwise (negative)")})
                .in(group);
    list << P::make("closed", tr("Closed polygon"), P::Type::Bool).in(group);
    const NormalVectorScheme s = m_spec.makeScheme();
    for (int j = 0; j < s.arity(); ++j) {
        list << P::make(QStringLiteral("alpha.%1").arg(j), tr("α%1").arg(j), P::Type::Real)
                    .slider(0, 1)
                    .in(tr("Rules"))
                    .tip(tr("Position of new point %1 along the edge (001 eq. (1))").arg(j));
        list << P::make(QStringLiteral("beta.%1").arg(j), tr("β%1").arg(j), P::Type::Real)
                    .slider(-1, 1)
                    .in(tr("Rules"))
                    .tip(tr("Displacement of new point %1 along the normal").arg(j));
    }
    return list;
}

QVariant NormalVectorItem::parameter(const QString &key) const
{
    if (key == "preset")
        return int(NormalVectorSpec::presetNames().indexOf(m_spec.preset));
    if (key == "steps")
        return m_spec.steps;
    if (key == "closed")
        return m_spec.closed;
    const NormalVectorScheme s = m_spec.makeScheme();
    if (key == "normal")
        return s.normal() == NormalDirection::Negative ? 1 : 0;
    int j = 0;
    if (parseRuleKey(key, "alpha", s.arity(), &j))
        return s.alpha()[size_t(j)];
    if (parseRuleKey(key, "beta", s.arity(), &j))
        return s.beta()[size_t(j)];
    return {};
}

bool NormalVectorItem::setParameter(const QString &key, const QVariant &value, int gesture,
                                    QString *error)
{
    NormalVectorSpec next = m_spec;
    bool ok = true;
    int j = 0;
    const int p = m_spec.arity();
    // A rule set to the value it has is no edit: a preset must not turn into "custom" for it.
    const bool rule = key == "normal" || parseRuleKey(key, "alpha", p, &j)
                      || parseRuleKey(key, "beta", p, &j);
    if (rule && value.typeId() != QMetaType::QString && value == parameter(key))
        return true;
    if (key == "preset") {
        const int index = value.toInt(&ok);
        const int custom = int(NormalVectorSpec::presetNames().size()) - 1;
        ok = ok && index >= 0 && index <= custom;
        if (ok && index == custom)
            copyPresetRules(next);
        else if (ok)
            next.preset = NormalVectorSpec::presetNames().at(index);
    } else if (key == "steps") {
        next.steps = value.toInt(&ok);
    } else if (key == "closed") {
        ok = value.typeId() == QMetaType::Bool;
        next.closed = value.toBool();
    } else if (key == "normal") {
        const int index = value.toInt(&ok);
        ok = ok && (index == 0 || index == 1);
        copyPresetRules(next);
        next.normal = NormalVectorSpec::Normal(index);
    } else if (parseRuleKey(key, "alpha", p, &j)) {
        copyPresetRules(next);
        next.alpha[size_t(j)] = value.toDouble(&ok);
    } else if (parseRuleKey(key, "beta", p, &j)) {
        copyPresetRules(next);
        next.beta[size_t(j)] = value.toDouble(&ok);
    } else {
        return Item::setParameter(key, value, gesture, error);
    }
    return commitParameter(key, value, ok, checkSpec(next),
                           [&] { return setSpec(next, gesture); }, error);
}

} // namespace awb
