#include "model/PropertyPart.h"

#include "model/NumberFormat.h"
#include "model/Project.h"

#include <QJsonDocument>
#include <QPointF>

#include <climits>
#include <cmath>

namespace awb {

namespace {

// lupdate reads the context from the macro; the texts belong to the model's item.
struct PropertyTr {
    Q_DECLARE_TR_FUNCTIONS(awb::Item)
};

constexpr double maxExactWhole = 9007199254740992.0;  // 2^53

} // namespace

QString DeclaredTexts::translate(const char *source) const
{
    return source ? QCoreApplication::translate(context, source) : QString();
}

namespace property {

QJsonValue jsonAt(const QJsonObject &json, const QString &path)
{
    const QStringList keys = path.split(QLatin1Char('.'));
    QJsonValue v = json;
    for (const QString &k : keys) {
        if (!v.isObject())
            return QJsonValue(QJsonValue::Undefined);
        v = v.toObject().value(k);
    }
    return v;
}

void setJsonAt(QJsonObject &json, const QString &path, const QJsonValue &value)
{
    const qsizetype dot = path.indexOf(QLatin1Char('.'));
    if (dot < 0) {
        json.insert(path, value);
        return;
    }
    const QString head = path.left(dot);
    QJsonObject inner = json.value(head).toObject();
    setJsonAt(inner, path.mid(dot + 1), value);
    json.insert(head, inner);
}

bool readAt(const FieldReader &fields, const QString &path, WhenMissing missing,
            const QString &missingText,
            const std::function<void(const QJsonValue &, const QString &)> &read)
{
    const qsizetype dot = path.indexOf(QLatin1Char('.'));
    if (dot < 0) {
        const QJsonValue v = fields.value(path);
        if (v.isUndefined()) {
            if (missing == WhenMissing::Required)
                fields.fail(path, missingText.isEmpty()
                                      ? QCoreApplication::translate("awb::FieldReader",
                                                                    "missing")
                                      : missingText);
            return false;
        }
        read(v, fields.path(path));
        return true;
    }
    const std::optional<FieldReader> inner =
        fields.object(path.left(dot), missing == WhenMissing::Required);
    return inner && readAt(*inner, path.mid(dot + 1), missing, missingText, read);
}

std::optional<double> toReal(const QVariant &v)
{
    switch (v.typeId()) {
    case QMetaType::Double:
    case QMetaType::Float:
    case QMetaType::Int:
    case QMetaType::UInt:
    case QMetaType::LongLong:
    case QMetaType::ULongLong:
        // NaN and infinities too: the kind's check names them ("not a finite number").
        return v.toDouble();
    default:
        return std::nullopt;
    }
}

std::optional<qint64> toWhole(const QVariant &v)
{
    const auto x = toReal(v);
    if (!x || !std::isfinite(*x) || *x != std::floor(*x) || std::abs(*x) > maxExactWhole)
        return std::nullopt;
    return qint64(*x);
}

std::optional<std::complex<double>> toComplex(const QVariant &v)
{
    if (v.typeId() != QMetaType::QPointF)
        return std::nullopt;
    const QPointF p = v.toPointF();
    return std::complex<double>(p.x(), p.y());
}

std::optional<bool> toBool(const QVariant &v)
{
    if (v.typeId() != QMetaType::Bool)
        return std::nullopt;
    return v.toBool();
}

bool numeric(ParameterInfo::Type type)
{
    return type == ParameterInfo::Type::Real || type == ParameterInfo::Type::Integer;
}

qint64 wholeFromJson(const QJsonValue &v, const QString &where, double lo, double hi)
{
    // FieldReader's own reading, at `where` (the path without its last key is the reader's).
    const qsizetype dot = where.lastIndexOf(QLatin1Char('.'));
    const QString key = where.mid(dot + 1);
    const FieldReader r(QJsonObject{{key, v}}, where.left(dot + 1));
    return r.integer(key, std::nullopt, qint64(lo), qint64(hi));
}

void failRange(const FieldReader &fields, const QString &path, const ParameterInfo &info,
               double value)
{
    const QString lo = QString::number(info.minimum, 'g', 12);
    const QString hi = QString::number(info.maximum, 'g', 12);
    const QString message =
        info.type == ParameterInfo::Type::Integer
            ? QCoreApplication::translate("awb::FieldReader",
                                          "expected an integer between %1 and %2")
                  .arg(lo, hi)
            : PropertyTr::tr("%1 is outside the range from %2 to %3")
                  .arg(QString::number(value, 'g', 12), lo, hi);
    fields.fail(path, message);
}

QString notValid(const QVariant &value, const QString &key)
{
    return QCoreApplication::translate("awb::Item", "\"%1\" is not a valid value for %2")
        .arg(value.toString(), key);
}

QString noParameter(const Item &item, const QString &key)
{
    return QCoreApplication::translate("awb::Item", "%1 has no parameter \"%2\"")
        .arg(item.typeName(), key);
}

QString outOfRange(const ParameterInfo &info, double value)
{
    if (!std::isfinite(value))
        return PropertyTr::tr("%1 must be a finite number").arg(info.label);
    const bool lo = std::isfinite(info.minimum), hi = std::isfinite(info.maximum);
    const QString v = QString::number(value, 'g', 12);
    if (lo && hi)
        return PropertyTr::tr("%1 must be at least %2 and at most %3, not %4")
            .arg(info.label, QString::number(info.minimum, 'g', 12),
                 QString::number(info.maximum, 'g', 12), v);
    if (lo)
        return PropertyTr::tr("%1 must be at least %2, not %3")
            .arg(info.label, QString::number(info.minimum, 'g', 12), v);
    return PropertyTr::tr("%1 must be at most %2, not %3")
        .arg(info.label, QString::number(info.maximum, 'g', 12), v);
}

ParameterInfo translated(const ParameterInfo &proto, const DeclaredTexts &texts)
{
    ParameterInfo i = proto;
    i.label = texts.label ? texts.translate(texts.label) : proto.key;
    i.group = texts.translate(texts.group);
    i.toolTip = texts.translate(texts.tip);
    i.choices.clear();
    for (const char *c : texts.choices)
        i.choices << texts.translate(c);
    return i;
}

QString typeName(ParameterInfo::Type type)
{
    switch (type) {
    case ParameterInfo::Type::Real: return QStringLiteral("real");
    case ParameterInfo::Type::Integer: return QStringLiteral("integer");
    case ParameterInfo::Type::Choice: return QStringLiteral("choice");
    case ParameterInfo::Type::Complex: return QStringLiteral("complex");
    case ParameterInfo::Type::Bool: return QStringLiteral("bool");
    case ParameterInfo::Type::Text: return QStringLiteral("text");
    }
    return QString();
}

QJsonValue complexToJson(std::complex<double> z)
{
    return QJsonArray{z.real(), z.imag()};
}

std::complex<double> complexFromJson(const QJsonValue &v, const QString &where)
{
    const QJsonArray pair = v.toArray();
    if (v.isArray() && pair.size() == 2)
        return {FieldReader::toNumber(pair[0], where + QStringLiteral("[1]")),
                FieldReader::toNumber(pair[1], where + QStringLiteral("[2]"))};
    if (v.isDouble() || v.isString())  // a real value may be written as a plain number
        return FieldReader::toNumber(v, where);
    throw LoadError{where, PropertyTr::tr("expected [re, im] or a number")};
}

QJsonValue numbersToJson(const std::vector<double> &values)
{
    QJsonArray a;
    for (double v : values)
        a.append(v);
    return a;
}

std::vector<double> numbersFromJson(const QJsonValue &v, const QString &where)
{
    if (!v.isArray())
        throw LoadError{where, QCoreApplication::translate("awb::FieldReader",
                                                           "expected an array of numbers")};
    std::vector<double> out;
    const QJsonArray a = v.toArray();
    for (qsizetype i = 0; i < a.size(); ++i)
        out.push_back(FieldReader::toNumber(a[i], where + QStringLiteral("[%1]").arg(i + 1)));
    return out;
}

QJsonValue matricesToJson(const std::vector<Mat> &matrices)
{
    QJsonArray list;
    for (const Mat &S : matrices) {
        QJsonArray rows;
        for (Eigen::Index r = 0; r < S.rows(); ++r)
            rows.append(ProjectIO::rowToJson(S.row(r)));
        list.append(rows);
    }
    return list;
}

std::vector<Mat> matricesFromJson(const QJsonValue &v, const QString &where)
{
    // FieldReader's reading, at `where` (the path without its last key is the reader's).
    const qsizetype dot = where.lastIndexOf(QLatin1Char('.'));
    const QString key = where.mid(dot + 1);
    const FieldReader r(QJsonObject{{key, v}}, where.left(dot + 1));
    return r.matrices(key);
}

PointList pointsFromJson(const QJsonValue &v, const QString &where, int dim)
{
    const qsizetype dot = where.lastIndexOf(QLatin1Char('.'));
    const QString key = where.mid(dot + 1);
    const FieldReader r(QJsonObject{{key, v}}, where.left(dot + 1));
    return r.points(key, std::nullopt, dim);
}

int choiceFromJson(const QStringList &spellings, const QJsonValue &v, const QString &where)
{
    if (!v.isString())
        throw LoadError{where, QCoreApplication::translate("awb::FieldReader",
                                                           "expected a string")};
    const int i = int(spellings.indexOf(v.toString()));
    if (i < 0) {
        QStringList options;
        for (const QString &n : spellings)
            options << QStringLiteral("\"%1\"").arg(n);
        throw LoadError{where, QCoreApplication::translate("awb::FieldReader",
                                                           "expected one of %1, got %2")
                                   .arg(options.join(QLatin1String(", ")),
                                        QStringLiteral("\"%1\"").arg(v.toString()))};
    }
    return i;
}

bool boolFromJson(const QJsonValue &v, const QString &where)
{
    if (!v.isBool())
        throw LoadError{where, QCoreApplication::translate("awb::FieldReader",
                                                           "expected true or false")};
    return v.toBool();
}

QVariant variantFromJson(const ParameterInfo &info, const QStringList &spellings,
                         const QJsonValue &v)
{
    switch (info.type) {
    case ParameterInfo::Type::Real: return v.toDouble();
    case ParameterInfo::Type::Integer: return v.toInteger();
    case ParameterInfo::Type::Choice: return int(spellings.indexOf(v.toString()));
    case ParameterInfo::Type::Complex: {
        const QJsonArray a = v.toArray();
        return QPointF(a.at(0).toDouble(), a.at(1).toDouble());
    }
    case ParameterInfo::Type::Bool: return v.toBool();
    case ParameterInfo::Type::Text: return v.toString();
    }
    return {};
}

} // namespace property

// ---- PropertyTable ----------------------------------------------------------------------------

QList<ParameterInfo> PropertyTable::parameters(const Item &item) const
{
    QList<ParameterInfo> out;
    for (const auto &p : m_parts)
        p->parameters(item, out);
    return out;
}

QVariant PropertyTable::value(const Item &item, const QString &key) const
{
    for (const auto &p : m_parts)
        if (const auto v = p->value(item, key))
            return *v;
    return {};
}

bool PropertyTable::enabled(const Item &item, const QString &key) const
{
    for (const auto &p : m_parts)
        if (p->value(item, key))
            return p->enabled(item, key);
    return false;
}

bool PropertyTable::set(Item &item, const QString &key, const QVariant &value, int gesture,
                        QString *error) const
{
    for (const auto &p : m_parts)
        if (const auto done = p->set(item, key, value, gesture, error))
            return *done;
    if (error)
        *error = property::noParameter(item, key);
    return false;
}

bool PropertyTable::setJson(Item &item, const QString &key, const QJsonValue &value,
                            QString *error) const
{
    for (const auto &p : m_parts)
        if (const auto done = p->setJson(item, key, value, error))
            return *done;
    // A scalar given in its file form.
    for (const PropertyDescription &d : describe(item))
        if (d.info.key == key && d.scalar)
            return set(item, key, property::variantFromJson(d.info, d.spellings, value), 0,
                       error);
    if (error)
        *error = property::noParameter(item, key);
    return false;
}

bool PropertyTable::setText(Item &item, const QString &key, const QString &text,
                            QString *error) const
{
    const QList<PropertyDescription> all = describe(item);
    const PropertyDescription *d = nullptr;
    for (const PropertyDescription &p : all)
        if (p.info.key == key)
            d = &p;
    if (!d) {
        if (error)
            *error = property::noParameter(item, key);
        return false;
    }
    const QString t = text.trimmed();
    const auto refuse = [&](const QString &expected) {
        if (error)
            *error = PropertyTr::tr("%1: \"%2\" is not %3").arg(key, text, expected);
        return false;
    };
    if (!d->scalar) {
        // JSON; a bare word is a string.
        QJsonParseError pe;
        const QJsonDocument doc = QJsonDocument::fromJson("[" + t.toUtf8() + "]", &pe);
        if (pe.error != QJsonParseError::NoError || doc.array().size() != 1)
            return refuse(PropertyTr::tr("a JSON value (%1)").arg(d->typeName));
        return setJson(item, key, doc.array().at(0), error);
    }
    QVariant v;
    using T = ParameterInfo::Type;
    switch (d->info.type) {
    case T::Real: {
        const auto x = parseNumber(t);
        if (!x)
            return refuse(PropertyTr::tr("a number"));
        v = *x;
        break;
    }
    case T::Integer: {
        const auto x = parseNumber(t);
        if (!x || *x != std::floor(*x) || std::abs(*x) > double(INT_MAX))
            return refuse(PropertyTr::tr("a whole number"));
        v = int(*x);
        break;
    }
    case T::Choice: {
        bool ok = false;
        const int i = t.toInt(&ok);
        int index = ok ? i : int(d->spellings.indexOf(t));
        for (int k = 0; index < 0 && k < d->info.choices.size(); ++k)
            if (d->info.choices[k].compare(t, Qt::CaseInsensitive) == 0)
                index = k;
        if (index < 0) {
            QStringList words = d->spellings.isEmpty() ? d->info.choices : d->spellings;
            return refuse(PropertyTr::tr("one of %1 (or its number from 0)")
                              .arg(words.join(QStringLiteral(", "))));
        }
        v = index;
        break;
    }
    case T::Complex: {
        // "re,im", "re+imi", "re-imi" or a real number.
        QString s = t;
        s.remove(QLatin1Char(' '));
        std::optional<double> re, im;
        if (s.contains(QLatin1Char(','))) {
            re = parseNumber(s.section(QLatin1Char(','), 0, 0));
            im = parseNumber(s.section(QLatin1Char(','), 1));
        } else if (s.endsWith(QLatin1Char('i'))) {
            const QString body = s.chopped(1);
            qsizetype split = -1;
            for (qsizetype k = body.size() - 1; k > 0; --k)
                if ((body[k] == QLatin1Char('+') || body[k] == QLatin1Char('-'))
                    && body[k - 1].toLower() != QLatin1Char('e')) {
                    split = k;
                    break;
                }
            re = split > 0 ? parseNumber(body.left(split)) : std::optional<double>(0.0);
            const QString imText = split > 0 ? body.mid(split) : body;
            im = imText == QLatin1String("+") || imText.isEmpty() ? std::optional<double>(1.0)
                 : imText == QLatin1String("-")                  ? std::optional<double>(-1.0)
                                                                  : parseNumber(imText);
        } else {
            re = parseNumber(s);
            im = 0.0;
        }
        if (!re || !im)
            return refuse(PropertyTr::tr("a complex number (\"0.5,0.3\" or \"0.5+0.3i\")"));
        v = QPointF(*re, *im);
        break;
    }
    case T::Bool: {
        const QString s = t.toLower();
        if (s == QLatin1String("true") || s == QLatin1String("1") || s == QLatin1String("yes")
            || s == QLatin1String("on"))
            v = true;
        else if (s == QLatin1String("false") || s == QLatin1String("0")
                 || s == QLatin1String("no") || s == QLatin1String("off"))
            v = false;
        else
            return refuse(PropertyTr::tr("true or false"));
        break;
    }
    case T::Text: v = text; break;
    }
    return set(item, key, v, 0, error);
}

void PropertyTable::write(const Item &item, QJsonObject &json) const
{
    for (const auto &p : m_parts)
        p->write(item, json);
}

void PropertyTable::read(Item &item, const FieldReader &fields) const
{
    for (const auto &p : m_parts)
        p->read(item, fields);
}

bool PropertyTable::update(Item &item, const QJsonObject &patch, QString *error) const
{
    const auto refuse = [error](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    if (patch.contains("type") && patch.value("type").toString() != item.type())
        return refuse(PropertyTr::tr("an item's type cannot change (%1 to %2): add a new item")
                          .arg(item.type(), patch.value("type").toString()));
    if (patch.contains("children"))
        return refuse(PropertyTr::tr("children are items of their own: add, remove or update "
                                     "them"));
    QJsonObject json = ProjectIO::itemToJson(item);
    json.remove("children");
    for (auto it = patch.begin(); it != patch.end(); ++it)
        json[it.key()] = it.value();
    QString why;
    const std::unique_ptr<Item> merged = ProjectIO::itemFromJson(json, &why);
    if (!merged)
        return refuse(why);
    if (item.project())
        if (const auto p = item.project()->checkName(&item, merged->name()))
            return refuse(p->message);
    CompoundEdit edit(item.project(), PropertyTr::tr("Update %1").arg(item.name()));
    for (const auto &p : m_parts) {
        bool touched = false;
        for (const QString &k : p->jsonKeys())
            touched = touched || patch.contains(k);
        // The merged item was read and checked as a whole: each part is stored as it is
        // there (a part alone may not be valid against the others' old values).
        if (touched && !p->transfer(*merged, item, error))
            return false;
    }
    return true;
}

QList<PropertyDescription> PropertyTable::describe(const Item &item) const
{
    QList<PropertyDescription> out;
    for (const auto &p : m_parts)
        p->describe(item, out);
    return out;
}

} // namespace awb
