#pragma once
// Declaring an item kind's properties (PropertyTable.h): the fluent builders of fields, parts
// and tables, and setDeclared() for the kinds' typed setters. Only the item kinds' .cpp files
// include it (docs/adding-an-item-kind.md). The builders take the kinds' typed functions and
// store them erased in the part's fields (PropertyPart.h), so that what a part does is
// compiled once.

#include "model/PropertyPart.h"

namespace awb {

namespace declared {
// The erased value of a part, and the item, as the kind's types.
template <class Spec>
const Spec &value(Field::CSpec s) { return *static_cast<const Spec *>(s); }
template <class Spec>
Spec &value(Field::MSpec s) { return *static_cast<Spec *>(s); }
template <class T>
const T &item(const Item &i) { return static_cast<const T &>(i); }
} // namespace declared

// ---- declaring --------------------------------------------------------------------------------

// Fluent declaration of one field: d.part(...).real("scheme.omega", &SchemeSpec::omega)
//     .label(QT_TR_NOOP("Tension ω")).group(QT_TR_NOOP("Scheme")).slider(-0.5, 0.5)
//     .when([](const SchemeSpec &s) { return s.kind == SchemeSpec::Kind::FourPoint; });
// Functions of the state take the value (`const Spec &`), or the item and the value
// (`const T &, const Spec &`).
template <class T, class Spec>
class FieldBuilder {
public:
    explicit FieldBuilder(Field &f) : m_f(f) {}
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
    // "missing" said in the kind's words.
    FieldBuilder &required(const char *why)
    {
        m_f.missing = WhenMissing::Required;
        m_f.missingText = why;
        return *this;
    }
    // A file without the field reads this value (an older default than the part's own).
    FieldBuilder &fileDefault(const QJsonValue &v)
    {
        m_f.missing = WhenMissing::Default;
        m_f.fileDefault = v;
        return *this;
    }
    FieldBuilder &omitWhenDefault() { m_f.omitDefault = true; return *this; }
    FieldBuilder &shownOnly() { m_f.proto.readOnly = true; return *this; }
    FieldBuilder &stepwise() { m_f.merges = false; return *this; }
    FieldBuilder &notAnimated() { m_f.proto.animatable = false; return *this; }

    // A file without the field: a value that follows what was read before (a layout the
    // scheme has). f(const T &, Spec &)
    template <class F>
    FieldBuilder &whenMissing(F f)
    {
        m_f.onMissing = [f](const Item &i, Field::MSpec s) {
            f(declared::item<T>(i), declared::value<Spec>(s));
        };
        return *this;
    }
    // Applies only in this state: shown, saved and read only then. f(const Spec &)
    template <class F>
    FieldBuilder &when(F f)
    {
        m_f.present = [f](Field::CSpec s) { return f(declared::value<Spec>(s)); };
        return *this;
    }
    // Written (and read) only in this state. f(const Spec &)
    template <class F>
    FieldBuilder &savedWhen(F f)
    {
        m_f.saved = [f](Field::CSpec s) { return f(declared::value<Spec>(s)); };
        return *this;
    }
    // A parameter only in this state of the item (the file still has it where it applies).
    // f(const T &, const Spec &)
    template <class F>
    FieldBuilder &shownWhen(F f)
    {
        m_f.visible = [f](const Item &i, Field::CSpec s) {
            return f(declared::item<T>(i), declared::value<Spec>(s));
        };
        return *this;
    }
    template <class F>
    FieldBuilder &enabledWhen(F f)
    {
        m_f.enabled = [f](const Item &i, Field::CSpec s) {
            return f(declared::item<T>(i), declared::value<Spec>(s));
        };
        return *this;
    }
    // Texts or bounds that follow the state. f(const T &, const Spec &, ParameterInfo &)
    template <class F>
    FieldBuilder &adjust(F f)
    {
        m_f.adjust = [f](const Item &i, Field::CSpec s, ParameterInfo &info) {
            f(declared::item<T>(i), declared::value<Spec>(s), info);
        };
        return *this;
    }
    // Before the edited value is stored (a preset becomes own rules). f(const T &, Spec &)
    template <class F>
    FieldBuilder &beforeEdit(F f)
    {
        m_f.beforeEdit = [f](const Item &i, Field::MSpec s) {
            f(declared::item<T>(i), declared::value<Spec>(s));
        };
        return *this;
    }
    // A step of an edit after the value is stored (a new kind starts from the current curve's
    // mask; a new start-set kind from the control points); may refuse. Not run on reading.
    // f(const T &, Spec &) -> MaybeProblem
    template <class F>
    FieldBuilder &onEdit(F after)
    {
        auto assign = m_f.assign;
        m_f.assign = [assign, after](const Item &i, Field::MSpec s,
                                     const QVariant &v) -> MaybeProblem {
            if (MaybeProblem p = assign(i, s, v))
                return p;
            return after(declared::item<T>(i), declared::value<Spec>(s));
        };
        return *this;
    }
    // The value as the dock and Python see it, and its edit. get(const T &, const Spec &) ->
    // QVariant; assign(const T &, Spec &, const QVariant &) -> MaybeProblem.
    template <class G>
    FieldBuilder &getter(G get)
    {
        m_f.get = [get](const Item &i, Field::CSpec s) {
            return QVariant(get(declared::item<T>(i), declared::value<Spec>(s)));
        };
        return *this;
    }
    template <class A>
    FieldBuilder &assigner(A assign)
    {
        m_f.assign = [assign](const Item &i, Field::MSpec s, const QVariant &v) -> MaybeProblem {
            return assign(declared::item<T>(i), declared::value<Spec>(s), v);
        };
        return *this;
    }
    // The file value when it differs from the parameter's (e.g. "levels" for a choice).
    // toJson(const T &, const Spec &) -> QJsonValue; fromJson(const T &, Spec &,
    // const QJsonValue &, const QString &where), throwing LoadError.
    template <class W, class R>
    FieldBuilder &codec(W toJson, R fromJson)
    {
        m_f.toJson = [toJson](const Item &i, Field::CSpec s) {
            return QJsonValue(toJson(declared::item<T>(i), declared::value<Spec>(s)));
        };
        m_f.fromJson = [fromJson](const Item &i, Field::MSpec s, const QJsonValue &v,
                                  const QString &where) {
            fromJson(declared::item<T>(i), declared::value<Spec>(s), v, where);
        };
        return *this;
    }
    // Choices that follow the state (translated texts), and their spellings in the file.
    // f(const T &, const Spec &) -> QStringList
    template <class F>
    FieldBuilder &choicesFrom(F f)
    {
        m_f.dynamicChoices = [f](const Item &i, Field::CSpec s) {
            return QStringList(f(declared::item<T>(i), declared::value<Spec>(s)));
        };
        return *this;
    }
    template <class F>
    FieldBuilder &spellingsFrom(F f)
    {
        m_f.dynamicSpellings = [f](const Item &i, Field::CSpec s) {
            return QStringList(f(declared::item<T>(i), declared::value<Spec>(s)));
        };
        return *this;
    }
    // Shown one element at a time: keys like "alpha.%1", labels like "α%1", groups like
    // "Curve %1" (numbered from 1). count(const Spec &) -> int; get(const Spec &, int) ->
    // QVariant; assign(Spec &, int, const QVariant &) -> MaybeProblem.
    template <class C, class G, class A>
    FieldBuilder &elements(const QString &key, const char *label, ParameterInfo::Type type,
                           C count, G get, A assign, const char *group = nullptr)
    {
        Field::Elements e;
        e.key = key;
        e.label = label;
        e.group = group;
        e.type = type;
        e.count = [count](Field::CSpec s) { return int(count(declared::value<Spec>(s))); };
        e.get = [get](Field::CSpec s, int j) {
            return QVariant(get(declared::value<Spec>(s), j));
        };
        e.assign = [assign](Field::MSpec s, int j, const QVariant &v) -> MaybeProblem {
            return assign(declared::value<Spec>(s), j, v);
        };
        m_f.elements = std::move(e);
        return *this;
    }
    Field &field() { return m_f; }

private:
    Field &m_f;
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
        m_part->checkReadValue = std::move(check);
        m_part->checkPath = path;
        return *this;
    }
    // The canonical form of a value read (after its check): e.g. "all maps" as no subset.
    PartBuilder &normalizedOnRead(std::function<void(const T &, Spec &)> f)
    {
        m_part->normalizeValue = std::move(f);
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
        Field &f = add(key, ParameterInfo::Type::Real);
        f.get = [a](const Item &, Field::CSpec s) {
            return QVariant(double(a(const_cast<Spec &>(declared::value<Spec>(s)))));
        };
        f.assign = [a, key](const Item &, Field::MSpec s, const QVariant &v) -> MaybeProblem {
            const auto x = property::toReal(v);
            if (!x)
                return Problem{key, property::notValid(v, key)};
            a(declared::value<Spec>(s)) = *x;
            return std::nullopt;
        };
        f.toJson = [a](const Item &, Field::CSpec s) {
            return QJsonValue(double(a(const_cast<Spec &>(declared::value<Spec>(s)))));
        };
        f.fromJson = [a](const Item &, Field::MSpec s, const QJsonValue &v, const QString &where) {
            a(declared::value<Spec>(s)) = FieldReader::toNumber(v, where);
        };
        return FieldBuilder<T, Spec>(f);
    }

    template <class A>
    FieldBuilder<T, Spec> integer(const QString &key, A acc)
    {
        auto a = accessor<Spec>(acc);
        Field &f = add(key, ParameterInfo::Type::Integer);
        using V = std::remove_reference_t<decltype(a(std::declval<Spec &>()))>;
        f.get = [a](const Item &, Field::CSpec s) {
            const auto v = a(const_cast<Spec &>(declared::value<Spec>(s)));
            if constexpr (sizeof(V) > sizeof(int))
                return QVariant(qint64(v));
            else
                return QVariant(int(v));
        };
        f.assign = [a, key](const Item &, Field::MSpec s, const QVariant &v) -> MaybeProblem {
            const auto x = property::toWhole(v);
            if (!x || (sizeof(V) <= sizeof(int) && std::abs(*x) > qint64(INT_MAX)))
                return Problem{key, property::notValid(v, key)};
            a(declared::value<Spec>(s)) = V(*x);
            return std::nullopt;
        };
        f.toJson = [a](const Item &, Field::CSpec s) {
            return QJsonValue(qint64(a(const_cast<Spec &>(declared::value<Spec>(s)))));
        };
        // As FieldReader::integer: a whole number within the declared range (int's when none).
        const ParameterInfo *proto = &f.proto;  // stable: the fields are a deque
        f.fromJson = [a, proto](const Item &, Field::MSpec s, const QJsonValue &v,
                                const QString &where) {
            const bool wide = sizeof(V) > sizeof(int);
            const double lo = std::max(proto->minimum, wide ? -9007199254740992.0 : INT_MIN);
            const double hi = std::min(proto->maximum, wide ? 9007199254740992.0 : INT_MAX);
            a(declared::value<Spec>(s)) = V(property::wholeFromJson(v, where, lo, hi));
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

    // A choice with its own index mapping (e.g. a name stored as text). index(const Spec &)
    // -> int; select(Spec &, int).
    template <class I, class S>
    FieldBuilder<T, Spec> choiceBy(const QString &key, const QStringList &spellings,
                                   QList<const char *> texts, I index, S select)
    {
        Field &f = add(key, ParameterInfo::Type::Choice);
        f.spellings = spellings;
        f.texts.choices = std::move(texts);
        const Field *field = &f;  // stable: the fields are a deque
        const auto spellingsOf = [field](const Item &i, Field::CSpec s) {
            return field->dynamicSpellings ? field->dynamicSpellings(i, s) : field->spellings;
        };
        f.get = [index](const Item &, Field::CSpec s) {
            return QVariant(int(index(declared::value<Spec>(s))));
        };
        f.assign = [select, key, spellingsOf](const Item &i, Field::MSpec s,
                                              const QVariant &v) -> MaybeProblem {
            const QStringList names = spellingsOf(i, s);
            std::optional<qint64> k = property::toWhole(v);
            if (!k && v.typeId() == QMetaType::QString && names.contains(v.toString()))
                k = names.indexOf(v.toString());
            if (!k || *k < 0 || *k >= names.size())
                return Problem{key, property::notValid(v, key)};
            select(declared::value<Spec>(s), int(*k));
            return std::nullopt;
        };
        f.toJson = [index, spellingsOf](const Item &i, Field::CSpec s) {
            const QStringList names = spellingsOf(i, s);
            const int k = index(declared::value<Spec>(s));
            return QJsonValue(k >= 0 && k < names.size() ? names.at(k) : QString());
        };
        f.fromJson = [select, spellingsOf](const Item &i, Field::MSpec s, const QJsonValue &v,
                                           const QString &where) {
            select(declared::value<Spec>(s),
                   property::choiceFromJson(spellingsOf(i, s), v, where));
        };
        return FieldBuilder<T, Spec>(f);
    }

    template <class A>
    FieldBuilder<T, Spec> complex(const QString &key, A acc)
    {
        auto a = accessor<Spec>(acc);
        Field &f = add(key, ParameterInfo::Type::Complex);
        f.get = [a](const Item &, Field::CSpec s) {
            const std::complex<double> z = a(const_cast<Spec &>(declared::value<Spec>(s)));
            return QVariant(QPointF(z.real(), z.imag()));
        };
        f.assign = [a, key](const Item &, Field::MSpec s, const QVariant &v) -> MaybeProblem {
            const auto z = property::toComplex(v);
            if (!z)
                return Problem{key, property::notValid(v, key)};
            a(declared::value<Spec>(s)) = *z;
            return std::nullopt;
        };
        f.toJson = [a](const Item &, Field::CSpec s) {
            return property::complexToJson(a(const_cast<Spec &>(declared::value<Spec>(s))));
        };
        f.fromJson = [a](const Item &, Field::MSpec s, const QJsonValue &v, const QString &where) {
            a(declared::value<Spec>(s)) = property::complexFromJson(v, where);
        };
        return FieldBuilder<T, Spec>(f);
    }

    template <class A>
    FieldBuilder<T, Spec> boolean(const QString &key, A acc)
    {
        auto a = accessor<Spec>(acc);
        Field &f = add(key, ParameterInfo::Type::Bool);
        f.get = [a](const Item &, Field::CSpec s) {
            return QVariant(bool(a(const_cast<Spec &>(declared::value<Spec>(s)))));
        };
        f.assign = [a, key](const Item &, Field::MSpec s, const QVariant &v) -> MaybeProblem {
            const auto b = property::toBool(v);
            if (!b)
                return Problem{key, property::notValid(v, key)};
            a(declared::value<Spec>(s)) = *b;
            return std::nullopt;
        };
        f.toJson = [a](const Item &, Field::CSpec s) {
            return QJsonValue(bool(a(const_cast<Spec &>(declared::value<Spec>(s)))));
        };
        f.fromJson = [a](const Item &, Field::MSpec s, const QJsonValue &v, const QString &where) {
            a(declared::value<Spec>(s)) = property::boolFromJson(v, where);
        };
        return FieldBuilder<T, Spec>(f);
    }

    // Text the user types (a mask line, lifted points): `get` shows it, `assign` parses it
    // (none: shown, not edited). get(const T &, const Spec &) -> QString; assign(const T &,
    // Spec &, const QString &) -> MaybeProblem.
    template <class G, class A = std::nullptr_t>
    FieldBuilder<T, Spec> text(const QString &key, G get, A assign = nullptr)
    {
        Field &f = add(key, ParameterInfo::Type::Text);
        f.get = [get](const Item &i, Field::CSpec s) {
            return QVariant(QString(get(declared::item<T>(i), declared::value<Spec>(s))));
        };
        if constexpr (std::is_same_v<A, std::nullptr_t>) {
            f.proto.readOnly = true;
        } else {
            f.assign = [assign, key](const Item &i, Field::MSpec s,
                                     const QVariant &v) -> MaybeProblem {
                if (v.typeId() != QMetaType::QString)
                    return Problem{key, property::notValid(v, key)};
                return assign(declared::item<T>(i), declared::value<Spec>(s), v.toString());
            };
        }
        return FieldBuilder<T, Spec>(f);
    }

    // A structured value (points, matrices, faces, ...): edited as its file form (JSON) by
    // Python's update(), `attractor-cli set` and its own editor in the window.
    // toJson(const T &, const Spec &) -> QJsonValue; fromJson(const T &, Spec &,
    // const QJsonValue &, const QString &where), throwing LoadError.
    template <class W, class R>
    FieldBuilder<T, Spec> structured(const QString &key, const QString &typeName, W toJson,
                                     R fromJson)
    {
        Field &f = add(key, ParameterInfo::Type::Text);
        f.scalar = false;
        f.typeName = typeName;
        FieldBuilder<T, Spec> b(f);
        b.codec(std::move(toJson), std::move(fromJson));
        const Field *field = &f;
        f.get = [field](const Item &i, Field::CSpec s) {
            return QVariant::fromValue(field->toJson(i, s));
        };
        return b;
    }

    // Points of `dim(item)` coordinates each.
    template <class A, class D>
    FieldBuilder<T, Spec> points(const QString &key, A acc, D dim)
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
    Field &add(const QString &key, ParameterInfo::Type type)
    {
        m_part->fields.emplace_back();
        Field &f = m_part->fields.back();
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
//         Declaration<SubdivisionMeshItem> d(&AttractorItem::attractorProperties());
//         d.part(&SubdivisionMeshItem::m_inputs, &SubdivisionMeshItem::checkInputs,
//                &SubdivisionMeshItem::meshChanged, QT_TR_NOOP("Change mesh of %1"))
//             .choice(...)...;
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
        p->storeValue = [member](T &t, Spec &&s) { t.*member = std::move(s); };
        if (check)
            p->checkValue = [check](const T &t, const Spec &s) { return (t.*check)(s); };
        p->applyValue = [member, signal, undoText, context](T &t, const Spec &s, int gesture) {
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
        p->storeValue = std::move(store);
        p->checkValue = std::move(check);
        p->applyValue = std::move(apply);
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
            return part->commitValue(item, value, gesture, error);
    return false;
}

} // namespace awb
