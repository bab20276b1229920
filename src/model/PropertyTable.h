#pragma once
// Declared properties (layer 2, model). An item kind declares each of its inputs once -- key,
// type, range and validation, label and help, where the file keeps it, when it applies,
// whether an edit merges over a drag -- and gets from that declaration its file form (write,
// read; the loader keeps the fields it does not know), undoable edits with the refusal
// message, the Properties dock's editors, Python's item.parameters, the recorder's lines and
// `attractor-cli set`. FreeCAD's property containers are the model: an item kind is its
// declaration plus its maths (docs/adding-an-item-kind.md walks through one).
//
// The inputs of an item come in parts: values with exact equality that are checked and stored
// as a whole, by one undo command (a curve's scheme, the start set, the style). A property is
// one field of a part. Reading a file builds each part from its fields, checks it and stores
// it; an edit copies the part, changes the field and stores the copy through the part's
// checked setter -- one undo step, or one per drag where the property merges.
//
// Only the item kinds' .cpp files, Item.cpp and the faces (dock, Python, recorder, CLI)
// include this header; Item.h knows the table by name only.

#include "model/Item.h"
#include "model/ProjectIO.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>

#include <climits>
#include <cmath>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <type_traits>
#include <vector>

namespace awb {

// A declared property as `attractor-cli set --list` and the docs show it: its parameter view
// (scalars) or its structured type, its place in the file and its current value there.
struct PropertyDescription {
    ParameterInfo info;   // key, label, group, tip, range, choices (translated)
    QString typeName;     // "real", "integer", "choice", ..., or "points", "matrices", ...
    QStringList spellings;  // a choice's spellings in the file (and on the command line)
    QString json;         // the field's path in the item's JSON object ("" when not saved)
    QJsonValue value;     // the current value in its file form
    bool scalar = true;   // an entry of item.parameters (structured values take JSON)
};

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

// ---- the type-erased part ---------------------------------------------------------------------

class PartBase {
public:
    virtual ~PartBase() = default;
    // Head parts (the name) come first in the dock and the file's reading order, then the
    // kind's own, the inputs every attractor has (start set, algorithm), then the tail
    // (style, animation).
    enum class Place { Head, Kind, Inputs, Tail };
    Place place = Place::Kind;

    virtual void parameters(const Item &item, QList<ParameterInfo> &out) const = 0;
    virtual std::optional<QVariant> value(const Item &item, const QString &key) const = 0;
    // nullopt: the key is none of this part's present parameters.
    virtual std::optional<bool> set(Item &item, const QString &key, const QVariant &value,
                                    int gesture, QString *error) const = 0;
    virtual std::optional<bool> setJson(Item &item, const QString &key, const QJsonValue &value,
                                        QString *error) const = 0;
    virtual void write(const Item &item, QJsonObject &json) const = 0;
    virtual void read(Item &item, const FieldReader &fields) const = 0;
    // Stores `from`'s value of this part into `to` through the checked setter (an update from
    // JSON); false with *error when refused.
    virtual bool transfer(const Item &from, Item &to, QString *error) const = 0;
    virtual void describe(const Item &item, QList<PropertyDescription> &out) const = 0;
    // The top-level JSON keys the part's fields live under.
    virtual QStringList jsonKeys() const = 0;
    virtual bool enabled(const Item &item, const QString &key) const = 0;
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

// ---- the table --------------------------------------------------------------------------------

// The declared properties of one item kind: its parts in order (the base kinds' first, as the
// declaration placed them). Built once per kind (a function-local static), shared by all its
// items.
class PropertyTable {
public:
    PropertyTable() = default;

    // The present scalar properties, elements expanded: the Properties dock's rows, Python's
    // item.parameters, what the recorder compares and animation may key.
    QList<ParameterInfo> parameters(const Item &item) const;
    // Invalid QVariant for an unknown key.
    QVariant value(const Item &item, const QString &key) const;
    bool enabled(const Item &item, const QString &key) const;
    // Undoable, one step; false with *error saying why.
    bool set(Item &item, const QString &key, const QVariant &value, int gesture,
             QString *error) const;
    // A property from its file form (structured values: points, matrices, ...), one undo step.
    bool setJson(Item &item, const QString &key, const QJsonValue &value, QString *error) const;
    // A scalar property from text as typed on a command line: numbers (3/8 and sqrt(3) too),
    // a choice's index, file spelling or text, true/false, a complex "re,im"; structured ones
    // as JSON.
    bool setText(Item &item, const QString &key, const QString &text, QString *error) const;

    void write(const Item &item, QJsonObject &json) const;
    void read(Item &item, const FieldReader &fields) const;
    // Changes the item's fields named in `patch` (its JSON form) as `ProjectIO::itemFromJson`
    // of the merged object would read them, each changed part through its checked setter, in
    // one undo step. False with *error (nothing changed) when the merged item does not read.
    bool update(Item &item, const QJsonObject &patch, QString *error) const;
    // Every present property with its current value.
    QList<PropertyDescription> describe(const Item &item) const;

    const std::vector<std::shared_ptr<const PartBase>> &parts() const { return m_parts; }

private:
    template <class T>
    friend class Declaration;
    std::vector<std::shared_ptr<const PartBase>> m_parts;
};

// ---- declaring --------------------------------------------------------------------------------

// Fluent declaration of one field: d.part(...).real("scheme.omega", &SchemeSpec::omega)
//     .label(QT_TR_NOOP("Tension ω")).group(QT_TR_NOOP("Scheme")).slider(-0.5, 0.5)
//     .when([](const SchemeSpec &s) { return s.kind == SchemeSpec::Kind::FourPoint; });
template <class T, class Spec>
class FieldBuilder {
public:
    explicit FieldBuilder(Field<T, Spec> &f) : m_f(f) {}
    FieldBuilder &label(const char *text) { m_f.texts.label = text; return *this; }
    FieldBuilder &group(const char *text) { m_f.texts.group = text; return *this; }
    FieldBuilder &tip(const char *text) { m_f.texts.tip = text; return *this; }
    FieldBuilder &range(double lo, double hi)
    {
        m_f.proto.minimum = lo;
        m_f.proto.maximum = hi;
        return *this;
    }
    FieldBuilder &slider(double lo, double hi)
    {
        m_f.proto.sliderMinimum = lo;
        m_f.proto.sliderMaximum = hi;
        return *this;
    }
    // Where the file keeps it (default: the key); `notSaved()`: derived, never written.
    FieldBuilder &json(const QString &path) { m_f.json = path; return *this; }
    FieldBuilder &notSaved() { m_f.json.clear(); return *this; }
    FieldBuilder &required() { m_f.missing = WhenMissing::Required; return *this; }
    // A file without the field reads this value (an older default than the part's own).
    FieldBuilder &fileDefault(const QJsonValue &v)
    {
        m_f.missing = WhenMissing::Default;
        m_f.fileDefault = v;
        return *this;
    }
    FieldBuilder &omitWhenDefault() { m_f.omitDefault = true; return *this; }
    // A file without the field: a value that follows what was read before (a layout the
    // scheme has).
    FieldBuilder &whenMissing(std::function<void(const T &, Spec &)> f)
    {
        m_f.onMissing = std::move(f);
        return *this;
    }
    FieldBuilder &savedWhen(std::function<bool(const Spec &)> f) { m_f.saved = std::move(f); return *this; }
    // "missing" said in the kind's words.
    FieldBuilder &required(const char *why)
    {
        m_f.missing = WhenMissing::Required;
        m_f.missingText = why;
        return *this;
    }
    FieldBuilder &shownOnly() { m_f.proto.readOnly = true; return *this; }
    FieldBuilder &stepwise() { m_f.merges = false; return *this; }
    FieldBuilder &notAnimated() { m_f.proto.animatable = false; return *this; }
    FieldBuilder &when(std::function<bool(const Spec &)> f) { m_f.present = std::move(f); return *this; }
    // A parameter only in this state of the item (the file still has it where it applies).
    FieldBuilder &shownWhen(std::function<bool(const T &, const Spec &)> f)
    {
        m_f.visible = std::move(f);
        return *this;
    }
    FieldBuilder &enabledWhen(std::function<bool(const T &, const Spec &)> f)
    {
        m_f.enabled = std::move(f);
        return *this;
    }
    FieldBuilder &adjust(std::function<void(const T &, const Spec &, ParameterInfo &)> f)
    {
        m_f.adjust = std::move(f);
        return *this;
    }
    FieldBuilder &beforeEdit(std::function<void(const T &, Spec &)> f)
    {
        m_f.beforeEdit = std::move(f);
        return *this;
    }
    // A step of an edit after the value is stored (a new kind starts from the current curve's
    // mask; a new start-set kind from the control points); may refuse. Not run on reading.
    FieldBuilder &onEdit(std::function<MaybeProblem(const T &, Spec &)> after)
    {
        auto assign = m_f.assign;
        m_f.assign = [assign, after](const T &t, Spec &s, const QVariant &v) -> MaybeProblem {
            if (MaybeProblem p = assign(t, s, v))
                return p;
            return after(t, s);
        };
        return *this;
    }
    // The file value when it differs from the parameter's (e.g. "levels" for a choice).
    FieldBuilder &codec(std::function<QJsonValue(const T &, const Spec &)> toJson,
                        std::function<void(const T &, Spec &, const QJsonValue &,
                                           const QString &)> fromJson)
    {
        m_f.toJson = std::move(toJson);
        m_f.fromJson = std::move(fromJson);
        return *this;
    }
    // Dynamic choices (translated texts and spellings from the state).
    FieldBuilder &choicesFrom(std::function<QStringList(const T &, const Spec &)> texts)
    {
        m_f.dynamicChoices = std::move(texts);
        return *this;
    }
    // Shown one element at a time: keys like "alpha.%1", labels like "α%1", groups like
    // "Curve %1" (numbered from 1).
    FieldBuilder &elements(const QString &key, const char *label, ParameterInfo::Type type,
                           std::function<int(const Spec &)> count,
                           std::function<QVariant(const Spec &, int)> get,
                           std::function<MaybeProblem(Spec &, int, const QVariant &)> assign,
                           const char *group = nullptr)
    {
        typename Field<T, Spec>::Elements e;
        e.key = key;
        e.label = label;
        e.group = group;
        e.type = type;
        e.count = std::move(count);
        e.get = std::move(get);
        e.assign = std::move(assign);
        m_f.elements = std::move(e);
        return *this;
    }
    Field<T, Spec> &field() { return m_f; }

private:
    Field<T, Spec> &m_f;
};

// Accessors: a member pointer (&Spec::omega) or a callable returning a reference to the
// value inside a Spec ([](auto &s) -> double & { return s.refined.j; }).
template <class Spec, class V>
auto accessor(V Spec::*member)
{
    return [member](auto &s) -> auto & { return s.*member; };
}
template <class Spec, class F>
auto accessor(F f)
{
    return f;
}

template <class T, class Spec>
class PartBuilder {
public:
    PartBuilder(std::shared_ptr<Part<T, Spec>> part, const char *context)
        : m_part(std::move(part)), m_context(context)
    {
    }

    // The value's own check while reading; fields of its problems are relative to `path`.
    PartBuilder &checkedOnRead(std::function<MaybeProblem(const T &, const Spec &)> check,
                               const QString &path = {})
    {
        m_part->checkRead = std::move(check);
        m_part->checkPath = path;
        return *this;
    }
    // The canonical form of a value read (after its check): e.g. "all maps" as no subset.
    PartBuilder &normalizedOnRead(std::function<void(const T &, Spec &)> f)
    {
        m_part->normalizeRead = std::move(f);
        return *this;
    }
    // Where reading starts (default Spec{}): e.g. the item's own default points.
    PartBuilder &startsFrom(std::function<Spec(const T &)> initial)
    {
        m_part->initial = std::move(initial);
        return *this;
    }

    template <class A>
    FieldBuilder<T, Spec> real(const QString &key, A acc)
    {
        auto a = accessor<Spec>(acc);
        auto &f = add(key, ParameterInfo::Type::Real);
        f.get = [a](const T &, const Spec &s) {
            return QVariant(double(a(const_cast<Spec &>(s))));
        };
        f.assign = [a, key](const T &, Spec &s, const QVariant &v) -> MaybeProblem {
            const auto x = property::toReal(v);
            if (!x)
                return Problem{key, property::notValid(v, key)};
            a(s) = *x;
            return std::nullopt;
        };
        f.toJson = [a](const T &, const Spec &s) {
            return QJsonValue(double(a(const_cast<Spec &>(s))));
        };
        f.fromJson = [a](const T &, Spec &s, const QJsonValue &v, const QString &where) {
            a(s) = FieldReader::toNumber(v, where);
        };
        return FieldBuilder<T, Spec>(f);
    }

    template <class A>
    FieldBuilder<T, Spec> integer(const QString &key, A acc)
    {
        auto a = accessor<Spec>(acc);
        auto &f = add(key, ParameterInfo::Type::Integer);
        using V = std::remove_reference_t<decltype(a(std::declval<Spec &>()))>;
        f.get = [a](const T &, const Spec &s) {
            if constexpr (sizeof(V) > sizeof(int))
                return QVariant(qint64(a(const_cast<Spec &>(s))));
            else
                return QVariant(int(a(const_cast<Spec &>(s))));
        };
        f.assign = [a, key](const T &, Spec &s, const QVariant &v) -> MaybeProblem {
            const auto x = property::toWhole(v);
            if (!x || (sizeof(V) <= sizeof(int) && std::abs(*x) > qint64(INT_MAX)))
                return Problem{key, property::notValid(v, key)};
            a(s) = V(*x);
            return std::nullopt;
        };
        f.toJson = [a](const T &, const Spec &s) {
            return QJsonValue(qint64(a(const_cast<Spec &>(s))));
        };
        // As FieldReader::integer: a whole number within the declared range (int's when none).
        const ParameterInfo *proto = &f.proto;  // stable: the fields are a deque
        f.fromJson = [a, proto](const T &, Spec &s, const QJsonValue &v, const QString &where) {
            const bool wide = sizeof(V) > sizeof(int);
            const double lo = std::max(proto->minimum, wide ? -9007199254740992.0 : INT_MIN);
            const double hi = std::min(proto->maximum, wide ? 9007199254740992.0 : INT_MAX);
            a(s) = V(property::wholeFromJson(v, where, lo, hi));
        };
        return FieldBuilder<T, Spec>(f);
    }

    // A choice stored as an enum, int or bool: its index in `spellings` (the file's words);
    // `texts` are the translated labels, one per spelling.
    template <class A>
    FieldBuilder<T, Spec> choice(const QString &key, A acc, const QStringList &spellings,
                                 QList<const char *> texts)
    {
        auto a = accessor<Spec>(acc);
        using V = std::remove_reference_t<decltype(a(std::declval<Spec &>()))>;
        return choiceBy(
            key, spellings, std::move(texts),
            [a](const Spec &s) { return int(a(const_cast<Spec &>(s))); },
            [a](Spec &s, int i) { a(s) = V(i); });
    }

    // A choice with its own index mapping (e.g. a name stored as text).
    FieldBuilder<T, Spec> choiceBy(const QString &key, const QStringList &spellings,
                                   QList<const char *> texts,
                                   std::function<int(const Spec &)> index,
                                   std::function<void(Spec &, int)> select)
    {
        auto &f = add(key, ParameterInfo::Type::Choice);
        f.spellings = spellings;
        f.texts.choices = std::move(texts);
        const Field<T, Spec> *field = &f;
        const auto spellingsOf = [field](const T &t, const Spec &s) {
            return field->dynamicSpellings ? field->dynamicSpellings(t, s) : field->spellings;
        };
        f.get = [index](const T &, const Spec &s) { return QVariant(index(s)); };
        f.assign = [select, key, spellingsOf](const T &t, Spec &s,
                                              const QVariant &v) -> MaybeProblem {
            const QStringList names = spellingsOf(t, s);
            std::optional<qint64> i = property::toWhole(v);
            if (!i && v.typeId() == QMetaType::QString && names.contains(v.toString()))
                i = names.indexOf(v.toString());
            if (!i || *i < 0 || *i >= names.size())
                return Problem{key, property::notValid(v, key)};
            select(s, int(*i));
            return std::nullopt;
        };
        f.toJson = [index, spellingsOf](const T &t, const Spec &s) {
            const QStringList names = spellingsOf(t, s);
            const int i = index(s);
            return QJsonValue(i >= 0 && i < names.size() ? names.at(i) : QString());
        };
        f.fromJson = [select, spellingsOf](const T &t, Spec &s, const QJsonValue &v,
                                           const QString &where) {
            const QStringList names = spellingsOf(t, s);
            if (!v.isString())
                throw LoadError{where, QCoreApplication::translate("awb::FieldReader",
                                                                   "expected a string")};
            const int i = int(names.indexOf(v.toString()));
            if (i < 0) {
                QStringList options;
                for (const QString &n : names)
                    options << QStringLiteral("\"%1\"").arg(n);
                throw LoadError{where, QCoreApplication::translate(
                                           "awb::FieldReader", "expected one of %1, got %2")
                                           .arg(options.join(QLatin1String(", ")),
                                                QStringLiteral("\"%1\"").arg(v.toString()))};
            }
            select(s, i);
        };
        return FieldBuilder<T, Spec>(f);
    }

    // Spellings that follow the state (a surface's layouts follow its scheme).
    void spellingsFrom(FieldBuilder<T, Spec> &b,
                       std::function<QStringList(const T &, const Spec &)> names)
    {
        b.field().dynamicSpellings = std::move(names);
    }

    template <class A>
    FieldBuilder<T, Spec> complex(const QString &key, A acc)
    {
        auto a = accessor<Spec>(acc);
        auto &f = add(key, ParameterInfo::Type::Complex);
        f.get = [a](const T &, const Spec &s) {
            const std::complex<double> z = a(const_cast<Spec &>(s));
            return QVariant(QPointF(z.real(), z.imag()));
        };
        f.assign = [a, key](const T &, Spec &s, const QVariant &v) -> MaybeProblem {
            const auto z = property::toComplex(v);
            if (!z)
                return Problem{key, property::notValid(v, key)};
            a(s) = *z;
            return std::nullopt;
        };
        f.toJson = [a](const T &, const Spec &s) {
            return property::complexToJson(a(const_cast<Spec &>(s)));
        };
        f.fromJson = [a](const T &, Spec &s, const QJsonValue &v, const QString &where) {
            a(s) = property::complexFromJson(v, where);
        };
        return FieldBuilder<T, Spec>(f);
    }

    template <class A>
    FieldBuilder<T, Spec> boolean(const QString &key, A acc)
    {
        auto a = accessor<Spec>(acc);
        auto &f = add(key, ParameterInfo::Type::Bool);
        f.get = [a](const T &, const Spec &s) { return QVariant(bool(a(const_cast<Spec &>(s)))); };
        f.assign = [a, key](const T &, Spec &s, const QVariant &v) -> MaybeProblem {
            const auto b = property::toBool(v);
            if (!b)
                return Problem{key, property::notValid(v, key)};
            a(s) = *b;
            return std::nullopt;
        };
        f.toJson = [a](const T &, const Spec &s) { return QJsonValue(bool(a(const_cast<Spec &>(s)))); };
        f.fromJson = [a](const T &, Spec &s, const QJsonValue &v, const QString &where) {
            if (!v.isBool())
                throw LoadError{where, QCoreApplication::translate("awb::FieldReader",
                                                                   "expected true or false")};
            a(s) = v.toBool();
        };
        return FieldBuilder<T, Spec>(f);
    }

    // Text the user types (a mask line, lifted points): `get` shows it, `assign` parses it.
    FieldBuilder<T, Spec> text(const QString &key,
                               std::function<QString(const T &, const Spec &)> get,
                               std::function<MaybeProblem(const T &, Spec &, const QString &)>
                                   assign)
    {
        auto &f = add(key, ParameterInfo::Type::Text);
        f.get = [get](const T &t, const Spec &s) { return QVariant(get(t, s)); };
        if (assign)
            f.assign = [assign, key](const T &t, Spec &s, const QVariant &v) -> MaybeProblem {
                if (v.typeId() != QMetaType::QString)
                    return Problem{key, property::notValid(v, key)};
                return assign(t, s, v.toString());
            };
        else
            f.proto.readOnly = true;
        return FieldBuilder<T, Spec>(f);
    }

    // A structured value (points, matrices, faces, ...): edited as its file form (JSON) by
    // Python's update(), `attractor-cli set` and its own editor in the window.
    FieldBuilder<T, Spec> structured(const QString &key, const QString &typeName,
                                     std::function<QJsonValue(const T &, const Spec &)> toJson,
                                     std::function<void(const T &, Spec &, const QJsonValue &,
                                                        const QString &)> fromJson)
    {
        auto &f = add(key, ParameterInfo::Type::Text);
        f.scalar = false;
        f.typeName = typeName;
        f.get = [toJson](const T &t, const Spec &s) {
            return QVariant::fromValue(toJson(t, s));
        };
        f.toJson = std::move(toJson);
        f.fromJson = std::move(fromJson);
        return FieldBuilder<T, Spec>(f);
    }

    template <class A>
    FieldBuilder<T, Spec> points(const QString &key, A acc, std::function<int(const T &)> dim)
    {
        auto a = accessor<Spec>(acc);
        return structured(
            key, QStringLiteral("points"),
            [a, dim](const T &t, const Spec &s) -> QJsonValue {
                return ProjectIO::pointsToJson(a(const_cast<Spec &>(s)), dim(t));
            },
            [a, dim](const T &t, Spec &s, const QJsonValue &v, const QString &where) {
                a(s) = property::pointsFromJson(v, where, dim(t));
            });
    }

    template <class A>
    FieldBuilder<T, Spec> numbers(const QString &key, A acc)
    {
        auto a = accessor<Spec>(acc);
        return structured(
            key, QStringLiteral("numbers"),
            [a](const T &, const Spec &s) {
                return property::numbersToJson(a(const_cast<Spec &>(s)));
            },
            [a](const T &, Spec &s, const QJsonValue &v, const QString &where) {
                a(s) = property::numbersFromJson(v, where);
            });
    }

    template <class A>
    FieldBuilder<T, Spec> matrices(const QString &key, A acc)
    {
        auto a = accessor<Spec>(acc);
        return structured(
            key, QStringLiteral("matrices"),
            [a](const T &, const Spec &s) {
                return property::matricesToJson(a(const_cast<Spec &>(s)));
            },
            [a](const T &, Spec &s, const QJsonValue &v, const QString &where) {
                a(s) = property::matricesFromJson(v, where);
            });
    }

private:
    Field<T, Spec> &add(const QString &key, ParameterInfo::Type type)
    {
        m_part->fields.emplace_back();
        Field<T, Spec> &f = m_part->fields.back();
        f.proto.key = key;
        f.proto.type = type;
        f.texts.context = m_context;
        f.json = key;
        return f;
    }

    std::shared_ptr<Part<T, Spec>> m_part;
    const char *m_context;
};

// Builds the table of item kind T:
//     static const PropertyTable table = [] {
//         Declaration<SubdivisionMeshItem> d(AttractorItem::declaredProperties());
//         d.part(&SubdivisionMeshItem::m_inputs, &SubdivisionMeshItem::setInputs,
//                &SubdivisionMeshItem::checkInputs).choice(...)...;
//         return d.table();
//     }();
// Parts declared here go after the base's head parts and before its tail parts (or into the
// head or tail, for the base kinds themselves).
template <class T>
class Declaration {
public:
    explicit Declaration(const PropertyTable *base = nullptr,
                         PartBase::Place place = PartBase::Place::Kind)
        : m_place(place)
    {
        if (base)
            m_table.m_parts = base->m_parts;
    }

    // A part kept in member `member`, checked by the kind's `check` (which names what is
    // wrong; nullptr: the value's own check while reading is all) and stored by one undo
    // command that emits `signal`, with `undoText` ("Change scheme of %1", the item's name).
    template <class Spec>
    PartBuilder<T, Spec> part(Spec T::*member, MaybeProblem (T::*check)(const Spec &) const,
                              void (T::*signal)(), const char *undoText)
    {
        auto p = std::make_shared<Part<T, Spec>>();
        const char *context = T::staticMetaObject.className();
        p->place = m_place;
        p->get = [member](const T &t) -> const Spec & { return t.*member; };
        p->store = [member](T &t, Spec &&s) { t.*member = std::move(s); };
        if (check)
            p->check = [check](const T &t, const Spec &s) { return (t.*check)(s); };
        p->apply = [member, signal, undoText, context](T &t, const Spec &s, int gesture) {
            t.applyProperty(member, s, signal,
                            QCoreApplication::translate(context, undoText).arg(t.name()),
                            gesture);
        };
        insert(p);
        return PartBuilder<T, Spec>(p, context);
    }

    // A part with its own get, store and undoable edit (a value kept inside a larger member,
    // or one the project must see change: the name).
    template <class Spec>
    PartBuilder<T, Spec> part(std::function<const Spec &(const T &)> get,
                              std::function<void(T &, Spec &&)> store,
                              std::function<MaybeProblem(const T &, const Spec &)> check,
                              std::function<void(T &, const Spec &, int)> apply)
    {
        auto p = std::make_shared<Part<T, Spec>>();
        p->place = m_place;
        p->get = std::move(get);
        p->store = std::move(store);
        p->check = std::move(check);
        p->apply = std::move(apply);
        insert(p);
        return PartBuilder<T, Spec>(p, T::staticMetaObject.className());
    }

    // A part of another shape (the point sets of attractor items: model/PointSetProperty.h).
    void add(std::shared_ptr<PartBase> part)
    {
        part->place = m_place;
        insert(std::move(part));
    }

    PropertyTable table() const { return m_table; }

private:
    void insert(std::shared_ptr<PartBase> p)
    {
        auto &parts = m_table.m_parts;
        const auto at = std::find_if(parts.begin(), parts.end(), [&](const auto &q) {
            return int(q->place) > int(m_place);
        });
        parts.insert(at, std::move(p));
    }

    PropertyTable m_table;
    PartBase::Place m_place;
};

// The kinds' typed setters (setScheme, setSpec, ...): the declared part of kind T holding a
// Spec, checked and stored as one undo step.
template <class T, class Spec>
bool setDeclared(T &item, const Spec &value, int gesture = 0, QString *error = nullptr)
{
    for (const auto &p : item.properties().parts())
        if (const auto *part = dynamic_cast<const Part<T, Spec> *>(p.get()))
            return part->commit(item, value, gesture, error);
    return false;
}

} // namespace awb
