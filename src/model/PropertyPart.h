#pragma once
// A part of an item kind's declared properties (PropertyTable.h): its fields, each a property
// with its texts, its parameter view, its file form and its edit, and the template that reads,
// writes, shows and edits them. Included by PropertyDeclaration.h (the item kinds) and by the
// few places that store a part directly.

#include "model/ProjectIO.h"
#include "model/PropertyTable.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <climits>
#include <cmath>
#include <deque>
#include <functional>
#include <type_traits>

namespace awb {

// The untranslated texts of a declaration: sources marked with QT_TR_NOOP in the kind's class,
// translated in that class's context where they are shown.
struct DeclaredTexts {
    const char *context = "awb::Item";
    const char *label = nullptr;
    const char *group = nullptr;
    const char *tip = nullptr;
    QList<const char *> choices;
    QString translate(const char *source) const;
};

// ---- one field of a part ----------------------------------------------------------------------

// What reading does when the file has no value for a field.
enum class WhenMissing {
    Keep,      // the part's initial value stays
    Required,  // "missing"
    Default,   // the field's file default is read instead
};

template <class T, class Spec>
struct Field {
    ParameterInfo proto;   // key, type, range, slider, read-only (texts: `texts`)
    DeclaredTexts texts;
    QString typeName;      // for structured fields: "points", "matrices", ...
    bool scalar = true;
    // The edits of one gesture (a slider, a plane or a view drag, a script's edit block) are
    // one undo step; a stepwise property keeps each edit apart.
    bool merges = true;
    QString json;          // path in the item's object ("scheme.omega"); empty: not saved
    WhenMissing missing = WhenMissing::Keep;
    const char *missingText = nullptr;  // "missing (the custom form needs its maps)"
    QJsonValue fileDefault;             // WhenMissing::Default
    std::function<void(const T &, Spec &)> onMissing;  // a default that follows the state
    bool omitDefault = false;  // written only when it differs from the part's initial value
    QStringList spellings;     // a choice's file spellings, in index order
    std::function<QStringList(const T &, const Spec &)> dynamicChoices;   // translated texts
    std::function<QStringList(const T &, const Spec &)> dynamicSpellings;

    std::function<bool(const Spec &)> present;  // applies now (shown, saved, read)
    std::function<bool(const Spec &)> saved;    // written now (default: whenever it applies)
    std::function<bool(const T &, const Spec &)> visible;  // a parameter now (default: applies)
    std::function<bool(const T &, const Spec &)> enabled;  // editable now (the dock greys it)
    std::function<void(const T &, const Spec &, ParameterInfo &)> adjust;  // state-dependent texts
    std::function<void(const T &, Spec &)> beforeEdit;  // e.g. a preset becomes custom rules

    std::function<QVariant(const T &, const Spec &)> get;
    // Stores `value` into the copy `next`; a Problem (with the field's key) refuses it.
    std::function<MaybeProblem(const T &, Spec &, const QVariant &)> assign;
    std::function<QJsonValue(const T &, const Spec &)> toJson;
    // Reads the file's value (never undefined) into `s`; throws LoadError at `where`.
    std::function<void(const T &, Spec &, const QJsonValue &, const QString &where)> fromJson;

    // A list shown one element at a time ("alpha.0", "alpha.1", ...).
    struct Elements {
        QString key;            // "alpha.%1"
        const char *label = nullptr;  // "α%1"
        const char *group = nullptr;  // "Rules", or "Curve %1" (then one group per element)
        ParameterInfo::Type type = ParameterInfo::Type::Real;
        std::function<int(const Spec &)> count;
        std::function<QVariant(const Spec &, int)> get;
        std::function<MaybeProblem(Spec &, int, const QVariant &)> assign;
    };
    std::optional<Elements> elements;

    bool applies(const Spec &s) const { return !present || present(s); }
};

// Helpers of the templates below (PropertyTable.cpp).
namespace property {
// The value of `path` ("scheme.omega") in `json`, undefined when absent.
QJsonValue jsonAt(const QJsonObject &json, const QString &path);
void setJsonAt(QJsonObject &json, const QString &path, const QJsonValue &value);
// Reads the field at `path` below `fields`: calls `read(value, where)` when present, fails
// "missing" when required; marks the top-level key read.
// False when the field is absent (and not required).
bool readAt(const FieldReader &fields, const QString &path, WhenMissing missing,
            const QString &missingText,
            const std::function<void(const QJsonValue &, const QString &)> &read);
// QVariant to a finite double / whole number / index / complex / bool; nullopt when it is not
// one (the caller says "not a valid value").
std::optional<double> toReal(const QVariant &v);
std::optional<qint64> toWhole(const QVariant &v);
std::optional<std::complex<double>> toComplex(const QVariant &v);
std::optional<bool> toBool(const QVariant &v);
bool numeric(ParameterInfo::Type type);  // Real or Integer
// A whole number of the file from lo to hi ("expected an integer", "expected an integer
// between lo and hi" otherwise), as FieldReader::integer reads one.
qint64 wholeFromJson(const QJsonValue &v, const QString &where, double lo, double hi);
// "expected a number between 0 and 1" at `path`, for a value outside the declared range.
[[noreturn]] void failRange(const FieldReader &fields, const QString &path,
                            const ParameterInfo &info, double value);
// The refusals every face shows.
QString notValid(const QVariant &value, const QString &key);
QString noParameter(const Item &item, const QString &key);
QString outOfRange(const ParameterInfo &info, double value);
// The parameter view of a field's texts and prototype.
ParameterInfo translated(const ParameterInfo &proto, const DeclaredTexts &texts);
QString typeName(ParameterInfo::Type type);
// JSON codecs of the common values.
QJsonValue complexToJson(std::complex<double> z);
std::complex<double> complexFromJson(const QJsonValue &v, const QString &where);
QJsonValue numbersToJson(const std::vector<double> &values);
std::vector<double> numbersFromJson(const QJsonValue &v, const QString &where);
QJsonValue matricesToJson(const std::vector<Mat> &matrices);
std::vector<Mat> matricesFromJson(const QJsonValue &v, const QString &where);
PointList pointsFromJson(const QJsonValue &v, const QString &where, int dim);
// The value as a scalar parameter would give it, from its JSON form (choices by spelling).
QVariant variantFromJson(const ParameterInfo &info, const QStringList &spellings,
                         const QJsonValue &v);
} // namespace property

// ---- a part of item kind T holding a Spec ------------------------------------------------------

template <class T, class Spec>
class Part : public PartBase {
public:
    std::function<const Spec &(const T &)> get;
    std::function<void(T &, Spec &&)> store;  // reading: no undo, no signal
    // The kind's check with its messages (edits), and the undoable store (one command; edits
    // with the same nonzero gesture merge).
    std::function<MaybeProblem(const T &, const Spec &)> check;
    std::function<void(T &, const Spec &, int gesture)> apply;
    // The value's own check while reading (fields relative to `checkPath`), and where reading
    // starts (default: Spec{}).
    std::function<MaybeProblem(const T &, const Spec &)> checkRead;
    QString checkPath;
    std::function<void(const T &, Spec &)> normalizeRead;  // after the check (canonical form)
    std::function<Spec(const T &)> initial;
    // A deque: the builders and the codecs keep references to fields declared before.
    std::deque<Field<T, Spec>> fields;

    // The checked edit: the kind's check, then one undo step. False with *error when refused.
    bool commit(T &t, const Spec &next, int gesture, QString *error, bool checked = false) const
    {
        if (check && !checked)
            if (const MaybeProblem p = check(t, next)) {
                if (error)
                    *error = p->message;
                return false;
            }
        apply(t, next, gesture);
        return true;
    }

    // ---- PartBase
    void parameters(const Item &item, QList<ParameterInfo> &out) const override
    {
        const T &t = self(item);
        const Spec &s = get(t);
        for (const Field<T, Spec> &f : fields) {
            if (!f.applies(s) || (f.visible && !f.visible(t, s)))
                continue;
            if (f.elements) {
                const auto &e = *f.elements;
                for (int j = 0, n = e.count(s); j < n; ++j)
                    out << elementInfo(f, j);
                continue;
            }
            if (f.scalar)
                out << info(t, s, f);
        }
    }

    std::optional<QVariant> value(const Item &item, const QString &key) const override
    {
        const T &t = self(item);
        const Spec &s = get(t);
        int j = -1;
        if (const Field<T, Spec> *f = find(t, s, key, &j))
            return j >= 0 ? f->elements->get(s, j) : f->get(t, s);
        return std::nullopt;
    }

    std::optional<bool> set(Item &item, const QString &key, const QVariant &v, int gesture,
                            QString *error) const override
    {
        T &t = self(item);
        const Spec &now = get(t);
        int j = -1;
        const Field<T, Spec> *f = find(t, now, key, &j);
        if (!f)
            return std::nullopt;
        const ParameterInfo i = j >= 0 ? elementInfo(*f, j) : info(t, now, *f);
        const auto refuse = [error](const QString &message) {
            if (error)
                *error = message;
            return false;
        };
        // The value it has is no edit (a preset must not turn into own rules for it). A text
        // for a number is parsed and judged, not compared.
        if ((v.typeId() != QMetaType::QString || i.type == ParameterInfo::Type::Text)
            && v == (j >= 0 ? f->elements->get(now, j) : f->get(t, now)))
            return true;
        if (i.readOnly || (j < 0 && !f->assign))
            return refuse(QCoreApplication::translate("awb::Item",
                                                      "%1 is shown, not edited").arg(i.label));
        Spec next = now;
        if (f->beforeEdit)
            f->beforeEdit(t, next);
        const MaybeProblem p = j >= 0 ? f->elements->assign(next, j, v) : f->assign(t, next, v);
        if (p)
            return refuse(p->message);
        // The kind's own check speaks first (its words name the paper's bound); the declared
        // range catches the rest.
        if (check)
            if (const MaybeProblem q = check(t, next))
                return refuse(q->message);
        if (const auto x = property::toReal(v);
            x && property::numeric(i.type)
            && (!std::isfinite(*x) || *x < i.minimum || *x > i.maximum))
            return refuse(property::outOfRange(i, *x));
        return commit(t, next, f->merges ? gesture : 0, error, true);
    }

    std::optional<bool> setJson(Item &item, const QString &key, const QJsonValue &v,
                                QString *error) const override
    {
        T &t = self(item);
        const Spec &now = get(t);
        for (const Field<T, Spec> &f : fields) {
            if (f.proto.key != key || !f.applies(now))
                continue;
            if (!f.fromJson || f.proto.readOnly) {
                if (error)
                    *error = QCoreApplication::translate("awb::Item", "%1 is shown, not edited")
                                 .arg(f.proto.key);
                return false;
            }
            Spec next = now;
            if (f.beforeEdit)
                f.beforeEdit(t, next);
            try {
                f.fromJson(t, next, v, key);
            } catch (const LoadError &e) {
                if (error)
                    *error = e.field.isEmpty() ? e.message
                                               : QStringLiteral("%1: %2").arg(e.field, e.message);
                return false;
            }
            return commit(t, next, 0, error);
        }
        return std::nullopt;
    }

    void write(const Item &item, QJsonObject &json) const override
    {
        const T &t = self(item);
        const Spec &s = get(t);
        std::optional<Spec> initialValue;
        for (const Field<T, Spec> &f : fields) {
            if (f.json.isEmpty() || !f.toJson || !f.applies(s) || (f.saved && !f.saved(s)))
                continue;
            const QJsonValue v = f.toJson(t, s);
            if (f.omitDefault) {
                if (!initialValue)
                    initialValue = start(t);
                if (v == f.toJson(t, *initialValue))
                    continue;
            }
            property::setJsonAt(json, f.json, v);
        }
    }

    void read(Item &item, const FieldReader &reader) const override
    {
        T &t = self(item);
        Spec s = start(t);
        for (const Field<T, Spec> &f : fields) {
            // A field not saved in this state is not read either: the file's value stays
            // one of its unknown fields, written back as it was.
            if (f.json.isEmpty() || !f.fromJson || !f.applies(s) || (f.saved && !f.saved(s)))
                continue;
            const bool found = property::readAt(
                reader, f.json, f.missing, f.texts.translate(f.missingText),
                [&](const QJsonValue &v, const QString &where) { f.fromJson(t, s, v, where); });
            if (!found && f.missing == WhenMissing::Default)
                f.fromJson(t, s, f.fileDefault, reader.path(f.json));
            if (!found && f.onMissing)
                f.onMissing(t, s);
        }
        if (checkRead)
            reader.require(checkRead(t, s), checkPath);
        if (normalizeRead)
            normalizeRead(t, s);
        // The declared ranges, after the value's own check (whose words name the bound).
        for (const Field<T, Spec> &f : fields)
            if (!f.json.isEmpty() && f.scalar && f.applies(s)
                && property::numeric(f.proto.type)) {
                const double x = f.get(t, s).toDouble();
                if (x < f.proto.minimum || x > f.proto.maximum)
                    property::failRange(reader, f.json, f.proto, x);
            }
        store(t, std::move(s));
    }

    bool transfer(const Item &from, Item &to, QString *) const override
    {
        apply(self(to), get(self(from)), 0);
        return true;
    }

    void describe(const Item &item, QList<PropertyDescription> &out) const override
    {
        const T &t = self(item);
        const Spec &s = get(t);
        for (const Field<T, Spec> &f : fields) {
            if (!f.applies(s))
                continue;
            PropertyDescription d;
            d.info = info(t, s, f);
            d.typeName = f.scalar ? property::typeName(f.proto.type) : f.typeName;
            d.spellings = f.dynamicSpellings ? f.dynamicSpellings(t, s) : f.spellings;
            d.json = f.json;
            d.value = !f.json.isEmpty() && f.toJson ? f.toJson(t, s)
                                                    : QJsonValue::fromVariant(f.get(t, s));
            d.scalar = f.scalar;
            out << d;
            if (f.elements)
                for (int j = 0, n = f.elements->count(s); j < n; ++j) {
                    PropertyDescription e;
                    e.info = elementInfo(f, j);
                    e.typeName = property::typeName(e.info.type);
                    e.json = QString();
                    const QVariant v = f.elements->get(s, j);
                    e.value = v.typeId() == QMetaType::Bool ? QJsonValue(v.toBool())
                                                             : QJsonValue(v.toDouble());
                    out << e;
                }
        }
    }

    QStringList jsonKeys() const override
    {
        QStringList keys;
        for (const Field<T, Spec> &f : fields)
            if (!f.json.isEmpty() && !keys.contains(f.json.section(QLatin1Char('.'), 0, 0)))
                keys << f.json.section(QLatin1Char('.'), 0, 0);
        return keys;
    }

    bool enabled(const Item &item, const QString &key) const override
    {
        const T &t = self(item);
        const Spec &s = get(t);
        int j = -1;
        const Field<T, Spec> *f = find(t, s, key, &j);
        return f && (!f->enabled || f->enabled(t, s));
    }

private:
    static T &self(Item &item) { return static_cast<T &>(item); }
    static const T &self(const Item &item) { return static_cast<const T &>(item); }
    Spec start(const T &t) const { return initial ? initial(t) : Spec{}; }

    // The present field `key` names (j: its element, or -1 for the field itself).
    const Field<T, Spec> *find(const T &t, const Spec &s, const QString &key, int *j) const
    {
        for (const Field<T, Spec> &f : fields) {
            if (!f.applies(s) || (f.visible && !f.visible(t, s)))
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
                const int index = key.mid(head.size(), key.size() - head.size() - tail.size())
                                      .toInt(&ok);
                if (ok && index >= 0 && index < e.count(s)
                    && e.key.arg(index) == key) {
                    *j = index;
                    return &f;
                }
            }
        }
        return nullptr;
    }

    ParameterInfo info(const T &t, const Spec &s, const Field<T, Spec> &f) const
    {
        ParameterInfo i = property::translated(f.proto, f.texts);
        if (f.dynamicChoices)
            i.choices = f.dynamicChoices(t, s);
        if (f.adjust)
            f.adjust(t, s, i);
        return i;
    }

    ParameterInfo elementInfo(const Field<T, Spec> &f, int j) const
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
};

} // namespace awb
