#include "model/SchemeFamily.h"

#include "core/Types.h"
#include "model/ProjectIO.h"
#include "model/SchemeRegularity.h"
#include "model/SubdivisionCurveItem.h"

#include <QJsonArray>
#include <QRegularExpression>

#include <cmath>
#include <limits>

namespace awb {

namespace {

QRegularExpression wordOf(const QString &name)
{
    return QRegularExpression(QStringLiteral("\\b%1\\b").arg(QRegularExpression::escape(name)));
}

[[noreturn]] void refuse(const QString &message)
{
    throw InputError(message.toStdString());
}

} // namespace

SchemeFamily::SchemeFamily(const SchemeSpec &base, int controlPoints, QStringList parameters,
                           QString mask)
    : m_base(base), m_controlPoints(controlPoints), m_parameters(std::move(parameters)),
      m_mask(std::move(mask))
{
    if (m_parameters.isEmpty() || m_parameters.size() > 2)
        refuse(tr("a family has one or two parameters, got %1").arg(m_parameters.size()));
    if (m_parameters.size() == 2 && m_parameters[0] == m_parameters[1])
        refuse(tr("the two parameters have the same name '%1'").arg(m_parameters[0]));
    const QString kind = SchemeSpec::kindNames().at(int(m_base.kind));
    if (!m_mask.isEmpty()) {
        if (m_base.kind != SchemeSpec::Kind::Mask)
            refuse(tr("a mask with parameters needs a mask item; this one is %1").arg(kind));
        static const QRegularExpression identifier(QStringLiteral("^[A-Za-z_]\\w*$"));
        static const QStringList reserved{"pi", "e", "sqrt", "cbrt", "sin", "cos",
                                          "tan", "exp", "ln"};
        for (const QString &p : m_parameters) {
            if (!identifier.match(p).hasMatch() || reserved.contains(p))
                refuse(tr("the parameter of a mask must be a name that is not a function or "
                          "constant (pi, e, sqrt, ...), got '%1'")
                           .arg(p));
            if (!m_mask.contains(wordOf(p)))
                refuse(tr("the mask '%1' does not contain the parameter '%2'").arg(m_mask, p));
        }
        return;
    }
    for (const QString &p : m_parameters) {
        const QString name = p.toLower();
        if (name == "omega" && m_base.kind == SchemeSpec::Kind::FourPoint)
            m_fields.push_back(&SchemeSpec::omega);
        else if (name == "a" && m_base.kind == SchemeSpec::Kind::CornerCutting)
            m_fields.push_back(&SchemeSpec::a);
        else if (name == "b" && m_base.kind == SchemeSpec::Kind::CornerCutting)
            m_fields.push_back(&SchemeSpec::b);
        else
            refuse(tr("the scheme (%1) has no parameter '%2': omega belongs to the four-point "
                      "scheme, a and b to corner cutting; a mask item takes a mask with the "
                      "parameter in its coefficients")
                       .arg(kind, p));
    }
}

SchemeFamily SchemeFamily::ofItem(const SubdivisionCurveItem &item, QStringList parameters,
                                  QString mask)
{
    return SchemeFamily(item.scheme(), int(item.controlPoints(0).size()), std::move(parameters),
                        std::move(mask));
}

std::optional<SchemeSpec> SchemeFamily::member(const std::vector<double> &values,
                                               QString *why) const
{
    if (values.size() != size_t(m_parameters.size())) {
        if (why)
            *why = tr("expected %1 parameter values, got %2")
                       .arg(m_parameters.size())
                       .arg(values.size());
        return std::nullopt;
    }
    SchemeSpec s = m_base;
    if (m_mask.isEmpty()) {
        for (size_t i = 0; i < values.size(); ++i)
            s.*m_fields[i] = values[i];
        return s;
    }
    QString line = m_mask;
    for (int i = 0; i < m_parameters.size(); ++i)
        line.replace(wordOf(m_parameters[i]),
                     QStringLiteral("(%1)").arg(values[size_t(i)], 0, 'g', 17));
    QString error;
    if (!s.setMaskLine(line, &error)) {
        if (why)
            *why = error;
        return std::nullopt;
    }
    return s;
}

Regularity SchemeFamily::regularity(const std::vector<double> &values,
                                    const RegularityOptions &o) const
{
    QString why;
    const std::optional<SchemeSpec> s = member(values, &why);
    if (!s) {
        Regularity none;
        none.message = why.toStdString();
        return none;  // not a member: not C^k
    }
    return specRegularity(*s, m_controlPoints, o);
}

AtlasMember SchemeFamily::atlasMember() const
{
    return [family = *this](const std::vector<double> &values, const RegularityOptions &o) {
        return family.regularity(values, o);
    };
}

QJsonObject SchemeFamily::toJson() const
{
    QJsonObject o{{"scheme", m_base.toJson()},
                  {"control_points", m_controlPoints},
                  {"parameters", QJsonArray::fromStringList(m_parameters)}};
    if (!m_mask.isEmpty())
        o["mask"] = m_mask;
    return o;
}

SchemeFamily SchemeFamily::fromJson(const QJsonObject &json)
{
    try {
        const FieldReader r(json);
        const std::optional<FieldReader> scheme = r.object("scheme", true);
        const SchemeSpec spec = SchemeSpec::fromJson(*scheme);
        const int m = int(r.integer("control_points", std::nullopt, 1, 100000));
        QStringList names;
        const QJsonValue p = r.value("parameters");
        for (const QJsonValue &v : p.toArray())
            names << v.toString();
        if (!p.isArray() || names.contains(QString()))
            r.fail("parameters", tr("expected a list of names"));
        return SchemeFamily(spec, m, names, r.string("mask", QString()));
    } catch (const LoadError &e) {
        refuse(tr("family: %1: %2").arg(e.field, e.message));
    }
}

QJsonObject atlasRowJson(const AtlasRow &row, const std::vector<AtlasAxis> &axes)
{
    QJsonObject params;
    for (size_t a = 0; a < axes.size() && a < row.params.size(); ++a)
        params[QString::fromStdString(axes[a].name)] = row.params[a];
    const auto finite = [](double v) { return std::isfinite(v) ? QJsonValue(v) : QJsonValue(); };
    const bool infinite = row.applies && std::isinf(row.lower);
    QJsonObject o{{"params", params},
                  {"applies", row.applies},
                  {"lower", row.applies ? finite(row.lower) : QJsonValue()},
                  {"upper", row.applies ? finite(row.upper) : QJsonValue()},
                  {"exact", row.exact},
                  {"verdict", row.verdict},
                  {"smoothness", !row.applies ? QJsonValue()
                                 : infinite   ? QJsonValue("C^infinity")
                                 : row.smoothness < 0
                                     ? QJsonValue()
                                     : QJsonValue(QStringLiteral("C^%1").arg(row.smoothness))},
                  {"sobolev", row.sobolev >= 0 ? QJsonValue(row.sobolev) : QJsonValue()},
                  {"timed_out", row.timedOut},
                  {"message", QString::fromStdString(row.message)}};
    return o;
}

AtlasRow atlasRowFromJson(const QJsonObject &json, const std::vector<AtlasAxis> &axes)
{
    AtlasRow row;
    const QJsonObject params = json.value("params").toObject();
    for (const AtlasAxis &a : axes) {
        const QJsonValue v = params.value(QString::fromStdString(a.name));
        if (!v.isDouble())
            refuse(SchemeFamily::tr("an atlas row has no value of '%1'")
                       .arg(QString::fromStdString(a.name)));
        row.params.push_back(v.toDouble());
    }
    constexpr double inf = std::numeric_limits<double>::infinity();
    row.applies = json.value("applies").toBool();
    const QString smoothness = json.value("smoothness").toString();
    const bool infinite = smoothness == "C^infinity";
    row.lower = infinite ? inf : json.value("lower").toDouble();
    row.upper = infinite ? inf : json.value("upper").toDouble();
    row.exact = json.value("exact").toBool();
    row.smoothness = infinite ? std::numeric_limits<int>::max()
                     : smoothness.startsWith("C^") ? smoothness.mid(2).toInt()
                                                   : -1;
    row.sobolev = json.value("sobolev").isDouble() ? json.value("sobolev").toDouble() : -1.0;
    row.verdict = json.value("verdict").toInt();
    row.timedOut = json.value("timed_out").toBool();
    row.message = json.value("message").toString().toStdString();
    return row;
}

} // namespace awb
