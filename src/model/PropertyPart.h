#pragma once
// A part of an item kind's declared properties (PropertyTable.h): its fields, each a property
// with its texts, its parameter view, its file form and its edit; what a part does with them
// (PartCore, compiled once in PropertyPart.cpp) and where a kind's part keeps its value
// (Part<T, Spec>). Included by PropertyDeclaration.h (the item kinds).

#include "model/ProjectIO.h"
#include "model/PropertyTable.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QPointF>

#include <climits>
#include <cmath>
#include <deque>
#include <functional>
#include <memory>
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

// One field of a part, its functions taking the part's value erased (`const void *` is a
// `const Spec *`; PropertyDeclaration.h's builders wrap the kinds' typed functions), so that
// the logic that reads, writes, shows and edits fields is compiled once (PropertyPart.cpp).
struct Field {
    using CSpec = const void *;
    using MSpec = void *;

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
    std::function<void(const Item &, MSpec)> onMissing;  // a default that follows the state
    bool omitDefault = false;  // written only when it differs from the part's initial value
    QStringList spellings;     // a choice's file spellings, in index order
    std::function<QStringList(const Item &, CSpec)> dynamicChoices;   // translated texts
    std::function<QStringList(const Item &, CSpec)> dynamicSpellings;

    std::function<bool(CSpec)> present;  // applies now (shown, saved, read)
    std::function<bool(CSpec)> saved;    // written now (default: whenever it applies)
    std::function<bool(const Item &, CSpec)> visible;  // a parameter now (default: applies)
    std::function<bool(const Item &, CSpec)> enabled;  // editable now (the dock greys it)
    std::function<void(const Item &, CSpec, ParameterInfo &)> adjust;  // state-dependent texts
    std::function<void(const Item &, MSpec)> beforeEdit;  // e.g. a preset becomes own rules

    std::function<QVariant(const Item &, CSpec)> get;
    // Stores `value` into the copy `next`; a Problem (with the field's key) refuses it.
    std::function<MaybeProblem(const Item &, MSpec, const QVariant &)> assign;
    std::function<QJsonValue(const Item &, CSpec)> toJson;
    // Reads the file's value (never undefined) into the value; throws LoadError at `where`.
    std::function<void(const Item &, MSpec, const QJsonValue &, const QString &where)> fromJson;

    // A list shown one element at a time ("alpha.0", "alpha.1", ...).
    struct Elements {
        QString key;            // "alpha.%1"
        const char *label = nullptr;  // "α%1"
        const char *group = nullptr;  // "Rules", or "Curve %1" (then one group per element)
        ParameterInfo::Type type = ParameterInfo::Type::Real;
        std::function<int(CSpec)> count;
        std::function<QVariant(CSpec, int)> get;
        std::function<MaybeProblem(MSpec, int, const QVariant &)> assign;
    };
    std::optional<Elements> elements;

    bool applies(CSpec s) const { return !present || present(s); }
};

// A part's value, owned and erased: a copy to edit, the value reading builds.
class SpecValue {
public:
    virtual ~SpecValue() = default;
    virtual void *get() = 0;
};

template <class Spec>
class SpecValueOf final : public SpecValue {
public:
    explicit SpecValueOf(Spec v) : value(std::move(v)) {}
    void *get() override { return &value; }
    Spec value;
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
// A choice's index from its spelling in the file ("expected one of ..." otherwise), a truth
// value ("expected true or false").
int choiceFromJson(const QStringList &spellings, const QJsonValue &v, const QString &where);
bool boolFromJson(const QJsonValue &v, const QString &where);
// The value as a scalar parameter would give it, from its JSON form (choices by spelling).
QVariant variantFromJson(const ParameterInfo &info, const QStringList &spellings,
                         const QJsonValue &v);
} // namespace property

// ---- a part: the fields of one value of an item -----------------------------------------------

// What every part does with its fields (PropertyPart.cpp); the typed Part<T, Spec> below says
// where its value lives, how it is checked and how it is stored.
class PartCore : public PartBase {
public:
    // A deque: the builders and the codecs keep references to fields declared before.
    std::deque<Field> fields;
    QString checkPath;  // the JSON object the value's own check speaks of ("scheme")

    // ---- what the typed part provides
    virtual const void *valueOf(const Item &item) const = 0;
    virtual std::unique_ptr<SpecValue> copyOf(const Item &item) const = 0;
    virtual std::unique_ptr<SpecValue> start(const Item &item) const = 0;  // reading starts here
    virtual void store(Item &item, SpecValue &value) const = 0;  // reading: no undo, no signal
    virtual MaybeProblem check(const Item &item, const void *value) const = 0;  // for edits
    virtual MaybeProblem checkRead(const Item &item, const void *value) const = 0;
    virtual void normalizeRead(const Item &item, void *value) const = 0;
    // One undo command; edits with the same nonzero gesture merge.
    virtual void apply(Item &item, const void *value, int gesture) const = 0;

    // The checked edit: the kind's check, then one undo step. False with *error when refused.
    bool commit(Item &item, const void *next, int gesture, QString *error,
                bool checked = false) const;

    // ---- PartBase
    void parameters(const Item &item, QList<ParameterInfo> &out) const override;
    std::optional<QVariant> value(const Item &item, const QString &key) const override;
    std::optional<bool> set(Item &item, const QString &key, const QVariant &v, int gesture,
                            QString *error) const override;
    std::optional<bool> setJson(Item &item, const QString &key, const QJsonValue &v,
                                QString *error) const override;
    void write(const Item &item, QJsonObject &json) const override;
    void read(Item &item, const FieldReader &reader) const override;
    bool transfer(const Item &from, Item &to, QString *error) const override;
    void describe(const Item &item, QList<PropertyDescription> &out) const override;
    QStringList jsonKeys() const override;
    bool enabled(const Item &item, const QString &key) const override;

private:
    // The present field `key` names (j: its element, or -1 for the field itself).
    const Field *find(const Item &item, const void *s, const QString &key, int *j) const;
    ParameterInfo info(const Item &item, const void *s, const Field &f) const;
    ParameterInfo elementInfo(const Field &f, int j) const;
};

// A part of item kind T holding a Spec: where the value lives and how it is checked and stored.
template <class T, class Spec>
class Part final : public PartCore {
public:
    std::function<const Spec &(const T &)> get;
    std::function<void(T &, Spec &&)> storeValue;  // reading: no undo, no signal
    // The kind's check with its messages (edits), and the undoable store (one command; edits
    // with the same nonzero gesture merge).
    std::function<MaybeProblem(const T &, const Spec &)> checkValue;
    std::function<void(T &, const Spec &, int gesture)> applyValue;
    // The value's own check while reading (fields relative to `checkPath`), a canonical form
    // after it, and where reading starts (default: Spec{}).
    std::function<MaybeProblem(const T &, const Spec &)> checkReadValue;
    std::function<void(const T &, Spec &)> normalizeValue;
    std::function<Spec(const T &)> initial;

    // The kinds' typed setters (setDeclared).
    bool commitValue(T &t, const Spec &next, int gesture, QString *error) const
    {
        return commit(t, &next, gesture, error);
    }

    const void *valueOf(const Item &item) const override { return &get(self(item)); }
    std::unique_ptr<SpecValue> copyOf(const Item &item) const override
    {
        return std::make_unique<SpecValueOf<Spec>>(get(self(item)));
    }
    std::unique_ptr<SpecValue> start(const Item &item) const override
    {
        return std::make_unique<SpecValueOf<Spec>>(initial ? initial(self(item)) : Spec{});
    }
    void store(Item &item, SpecValue &v) const override
    {
        storeValue(self(item), std::move(*static_cast<Spec *>(v.get())));
    }
    MaybeProblem check(const Item &item, const void *v) const override
    {
        return checkValue ? checkValue(self(item), *static_cast<const Spec *>(v)) : std::nullopt;
    }
    MaybeProblem checkRead(const Item &item, const void *v) const override
    {
        return checkReadValue ? checkReadValue(self(item), *static_cast<const Spec *>(v))
                              : std::nullopt;
    }
    void normalizeRead(const Item &item, void *v) const override
    {
        if (normalizeValue)
            normalizeValue(self(item), *static_cast<Spec *>(v));
    }
    void apply(Item &item, const void *v, int gesture) const override
    {
        applyValue(self(item), *static_cast<const Spec *>(v), gesture);
    }

private:
    static T &self(Item &item) { return static_cast<T &>(item); }
    static const T &self(const Item &item) { return static_cast<const T &>(item); }
};

} // namespace awb
