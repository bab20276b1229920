// What every declared part does with its fields (PropertyPart.h): list, show, edit, read,
// write and describe them -- once for every item kind.

#include "model/PropertyPart.h"

#include <cmath>

namespace awb {

namespace {

QString shownNotEdited(const QString &label)
{
    return QCoreApplication::translate("awb::Item", "%1 is shown, not edited").arg(label);
}

// The undo step of one field's edit.
QString editText(const Item &item, const QString &label)
{
    return QCoreApplication::translate("awb::Item", "Change %1 of %2").arg(label, item.name());
}

} // namespace

bool PartCore::commit(Item &item, const void *next, int gesture, QString *error,
                      bool checked) const
{
    if (!checked)
        if (const MaybeProblem p = check(item, next)) {
            if (error)
                *error = p->message;
            return false;
        }
    apply(item, next, gesture);
    return true;
}

void PartCore::parameters(const Item &item, QList<ParameterInfo> &out) const
{
    const void *s = valueOf(item);
    for (const Field &f : fields) {
        if (!f.applies(s) || (f.visible && !f.visible(item, s)))
            continue;
        if (f.elements) {
            for (int j = 0, n = f.elements->count(s); j < n; ++j)
                out << elementInfo(f, j);
            continue;
        }
        if (f.scalar)
            out << info(item, s, f);
    }
}

std::optional<QVariant> PartCore::value(const Item &item, const QString &key) const
{
    const void *s = valueOf(item);
    int j = -1;
    if (const Field *f = find(item, s, key, &j))
        return j >= 0 ? f->elements->get(s, j) : f->get(item, s);
    return std::nullopt;
}

std::optional<bool> PartCore::set(Item &item, const QString &key, const QVariant &v,
                                  int gesture, QString *error) const
{
    const void *now = valueOf(item);
    int j = -1;
    const Field *f = find(item, now, key, &j);
    if (!f)
        return std::nullopt;
    const ParameterInfo i = j >= 0 ? elementInfo(*f, j) : info(item, now, *f);
    const auto refuse = [error](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    // The value it has is no edit (a preset must not turn into own rules for it). A text for a
    // number is parsed and judged, not compared.
    if ((v.typeId() != QMetaType::QString || i.type == ParameterInfo::Type::Text)
        && v == (j >= 0 ? f->elements->get(now, j) : f->get(item, now)))
        return true;
    if (i.readOnly || (j < 0 && !f->assign))
        return refuse(shownNotEdited(i.label));
    const std::unique_ptr<SpecValue> next = copyOf(item);
    if (f->beforeEdit)
        f->beforeEdit(item, next->get());
    const MaybeProblem p =
        j >= 0 ? f->elements->assign(next->get(), j, v) : f->assign(item, next->get(), v);
    if (p)
        return refuse(p->message);
    // The kind's own check speaks first (its words name the paper's bound); the declared range
    // catches the rest.
    if (const MaybeProblem q = check(item, next->get()))
        return refuse(q->message);
    if (const auto x = property::toReal(v);
        x && property::numeric(i.type)
        && (!std::isfinite(*x) || *x < i.minimum || *x > i.maximum))
        return refuse(property::outOfRange(i, *x));
    const Item::EditName naming(item, editText(item, i.label));
    return commit(item, next->get(), f->merges ? gesture : 0, error, true);
}

std::optional<bool> PartCore::setJson(Item &item, const QString &key, const QJsonValue &v,
                                      QString *error) const
{
    const void *now = valueOf(item);
    for (const Field &f : fields) {
        if (f.proto.key != key || !f.applies(now))
            continue;
        if (!f.fromJson || f.proto.readOnly) {
            if (error)
                *error = shownNotEdited(f.proto.key);
            return false;
        }
        const std::unique_ptr<SpecValue> next = copyOf(item);
        if (f.beforeEdit)
            f.beforeEdit(item, next->get());
        try {
            f.fromJson(item, next->get(), v, key);
        } catch (const LoadError &e) {
            if (error)
                *error = e.field.isEmpty() ? e.message
                                           : QStringLiteral("%1: %2").arg(e.field, e.message);
            return false;
        }
        const Item::EditName naming(item, editText(item, info(item, now, f).label));
        return commit(item, next->get(), 0, error);
    }
    return std::nullopt;
}

void PartCore::write(const Item &item, QJsonObject &json) const
{
    const void *s = valueOf(item);
    std::unique_ptr<SpecValue> initial;
    for (const Field &f : fields) {
        if (f.json.isEmpty() || !f.toJson || !f.applies(s) || (f.saved && !f.saved(s)))
            continue;
        const QJsonValue v = f.toJson(item, s);
        if (f.omitDefault) {
            if (!initial)
                initial = start(item);
            if (v == f.toJson(item, initial->get()))
                continue;
        }
        property::setJsonAt(json, f.json, v);
    }
}

void PartCore::read(Item &item, const FieldReader &reader) const
{
    const std::unique_ptr<SpecValue> value = start(item);
    void *s = value->get();
    for (const Field &f : fields) {
        // A field not saved in this state is not read either: the file's value stays one of
        // its unknown fields, written back as it was.
        if (f.json.isEmpty() || !f.fromJson || !f.applies(s) || (f.saved && !f.saved(s)))
            continue;
        const bool found = property::readAt(
            reader, f.json, f.missing, f.texts.translate(f.missingText),
            [&](const QJsonValue &v, const QString &where) { f.fromJson(item, s, v, where); });
        if (!found && f.missing == WhenMissing::Default)
            f.fromJson(item, s, f.fileDefault, reader.path(f.json));
        if (!found && f.onMissing)
            f.onMissing(item, s);
    }
    reader.require(checkRead(item, s), checkPath);
    normalizeRead(item, s);
    // The declared ranges, after the value's own check (whose words name the bound).
    for (const Field &f : fields)
        if (!f.json.isEmpty() && f.scalar && f.applies(s) && property::numeric(f.proto.type)) {
            const double x = f.get(item, s).toDouble();
            if (x < f.proto.minimum || x > f.proto.maximum)
                property::failRange(reader, f.json, f.proto, x);
        }
    store(item, *value);
}

bool PartCore::transfer(const Item &from, Item &to, QString *) const
{
    apply(to, valueOf(from), 0);
    return true;
}

void PartCore::describe(const Item &item, QList<PropertyDescription> &out) const
{
    const void *s = valueOf(item);
    for (const Field &f : fields) {
        if (!f.applies(s))
            continue;
        PropertyDescription d;
        d.info = info(item, s, f);
        d.typeName = f.scalar ? property::typeName(f.proto.type) : f.typeName;
        d.spellings = f.dynamicSpellings ? f.dynamicSpellings(item, s) : f.spellings;
        d.json = f.json;
        d.value = !f.json.isEmpty() && f.toJson ? f.toJson(item, s)
                                                : QJsonValue::fromVariant(f.get(item, s));
        d.scalar = f.scalar;
        out << d;
        if (f.elements)
            for (int j = 0, n = f.elements->count(s); j < n; ++j) {
                PropertyDescription e;
                e.info = elementInfo(f, j);
                e.typeName = property::typeName(e.info.type);
                const QVariant v = f.elements->get(s, j);
                e.value = v.typeId() == QMetaType::Bool ? QJsonValue(v.toBool())
                                                         : QJsonValue(v.toDouble());
                out << e;
            }
    }
}

QStringList PartCore::jsonKeys() const
{
    QStringList keys;
    for (const Field &f : fields)
        if (!f.json.isEmpty() && !keys.contains(f.json.section(QLatin1Char('.'), 0, 0)))
            keys << f.json.section(QLatin1Char('.'), 0, 0);
    return keys;
}

bool PartCore::enabled(const Item &item, const QString &key) const
{
    const void *s = valueOf(item);
    int j = -1;
    const Field *f = find(item, s, key, &j);
    return f && (!f->enabled || f->enabled(item, s));
}

const Field *PartCore::find(const Item &item, const void *s, const QString &key, int *j) const
{
    for (const Field &f : fields) {
        if (!f.applies(s) || (f.visible && !f.visible(item, s)))
            continue;
        if (f.proto.key == key && (f.scalar || !f.elements)) {
            *j = -1;
            return f.scalar ? &f : nullptr;
        }
        if (f.elements) {
            const auto &e = *f.elements;
            const QString head = e.key.section(QStringLiteral("%1"), 0, 0);
            const QString tail = e.key.section(QStringLiteral("%1"), 1);
            if (!key.startsWith(head) || !key.endsWith(tail)
                || key.size() <= head.size() + tail.size())
                continue;
            bool ok = false;
            const int index =
                key.mid(head.size(), key.size() - head.size() - tail.size()).toInt(&ok);
            if (ok && index >= 0 && index < e.count(s) && e.key.arg(index) == key) {
                *j = index;
                return &f;
            }
        }
    }
    return nullptr;
}

ParameterInfo PartCore::info(const Item &item, const void *s, const Field &f) const
{
    ParameterInfo i = property::translated(f.proto, f.texts);
    if (f.dynamicChoices)
        i.choices = f.dynamicChoices(item, s);
    if (f.adjust)
        f.adjust(item, s, i);
    return i;
}

ParameterInfo PartCore::elementInfo(const Field &f, int j) const
{
    const auto &e = *f.elements;
    ParameterInfo i = property::translated(f.proto, f.texts);
    i.key = e.key.arg(j);
    i.type = e.type;
    const QString label = f.texts.translate(e.label);
    i.label = label.contains(QStringLiteral("%1")) ? label.arg(j) : label;
    if (e.group) {
        const QString group = f.texts.translate(e.group);
        i.group = group.contains(QStringLiteral("%1")) ? group.arg(j + 1) : group;
    }
    return i;
}

} // namespace awb
