#pragma once
// Declaring an item kind's properties (PropertyTable.h): the fluent builders of fields, parts
// and tables, and setDeclared() for the kinds' typed setters. Only the item kinds' .cpp files
// include it (docs/adding-an-item-kind.md).

#include "model/PropertyPart.h"

namespace awb {

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
