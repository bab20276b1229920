#include "model/Item.h"

#include "model/Commands.h"
#include "model/Project.h"
#include "model/ProjectIO.h"
#include "model/PropertyDeclaration.h"

namespace awb {

Item::Item(const QString &defaultName) : m_name(defaultName) {}

Item::~Item() = default;

Item *Item::child(int row) const
{
    return row >= 0 && row < childCount() ? m_children[size_t(row)].get() : nullptr;
}

int Item::indexOfChild(const Item *child) const
{
    for (size_t i = 0; i < m_children.size(); ++i)
        if (m_children[i].get() == child)
            return int(i);
    return -1;
}

bool Item::isAncestorOf(const Item *other) const
{
    for (const Item *p = other ? other->m_parent : nullptr; p; p = p->m_parent)
        if (p == this)
            return true;
    return false;
}

bool Item::setName(const QString &name)
{
    if (m_project)
        return m_project->renameItem(this, name);
    if (name.trimmed().isEmpty())
        return false;
    applyProperty(&Item::m_name, name, &Item::nameChanged, tr("Rename"));
    return true;
}

bool Item::setStyle(const StyleSpec &style, int gesture)
{
    return setDeclared(*this, style, gesture);
}

MaybeProblem Item::checkAnimation(const AnimationSpec &spec) const
{
    if (spec.isEmpty())
        return std::nullopt;
    if (const MaybeProblem p = animationProblem(*this, spec, &m_animation))
        return Problem{p->field, p->field.isEmpty()
                                     ? p->message
                                     : QStringLiteral("%1: %2").arg(p->field, p->message)};
    return std::nullopt;
}

bool Item::setAnimation(const AnimationSpec &animation, QString *error)
{
    AnimationSpec spec = animation;
    if (spec.isEmpty())
        spec = AnimationSpec{0.0, 25.0, {}};
    return setDeclared(*this, spec, 0, error);
}

void Item::execute(QUndoCommand *command)
{
    if (m_project) {
        m_project->push(command);
    } else {
        command->redo();
        delete command;
    }
}

void Item::executeProperty(QUndoCommand *command, int gesture)
{
    if (!m_editName.isEmpty())
        command->setText(m_editName);
    if (gesture != 0 || !hasDependents()) {
        execute(command);
        return;
    }
    const CompoundEdit edit(m_project, command->text());
    execute(command);
    refitDependents();
}

void Item::inputsChanged()
{
    ++m_generation;
    dropDerived();
    emit derivedChanged();
}

void Item::renameReference(const QString &, const QString &) {}

// ---- declared properties ----------------------------------------------------------------------

const PropertyTable &Item::itemProperties()
{
    static const PropertyTable table = [] {
        Declaration<Item> head(nullptr, PartBase::Place::Head);
        // The name: renamed through the project, which keeps names unique and updates the
        // items that refer to this one in the same undo step.
        head.part<QString>(
                [](const Item &i) -> const QString & { return i.m_name; },
                [](Item &i, QString &&name) { i.m_name = std::move(name); },
                [](const Item &i, const QString &name) -> MaybeProblem {
                    if (i.project())
                        return i.project()->checkName(&i, name);
                    if (name.trimmed().isEmpty())
                        return Problem{"name", tr("the name cannot be empty")};
                    return std::nullopt;
                },
                [](Item &i, const QString &name, int) { i.setName(name); })
            .text("name", [](const Item &i, const QString &) { return i.name(); },
                  [](const Item &, QString &name, const QString &text) -> MaybeProblem {
                      name = text;
                      return std::nullopt;
                  })
            .label(QT_TR_NOOP("Name"))
            .adjust([](const Item &i, const QString &, ParameterInfo &info) {
                info.group = i.typeName();
            })
            .codec([](const Item &, const QString &name) { return QJsonValue(name); },
                   [](const Item &, QString &name, const QJsonValue &v, const QString &where) {
                       if (!v.isString())
                           throw LoadError{where, QCoreApplication::translate(
                                                      "awb::FieldReader", "expected a string")};
                       name = v.toString();
                       if (name.trimmed().isEmpty())
                           throw LoadError{where, tr("the name cannot be empty")};
                   })
            .required();

        const PropertyTable named = head.table();
        Declaration<Item> tail(&named, PartBase::Place::Tail);
        auto style = tail.part(&Item::m_style, &Item::checkStyle, &Item::styleChanged,
                               QT_TR_NOOP("Change style of %1"));
        // Every item keeps a style in its file; it colours only what is drawn as an attractor.
        const auto drawn = [](const Item &i, const StyleSpec &) {
            return i.inherits("awb::AttractorItem");
        };
        // A flame colours and tones itself (its palette, flam3's gamma under "Tone").
        const auto mapColoured = [](const Item &i, const StyleSpec &) {
            return i.inherits("awb::AttractorItem") && !i.inherits("awb::FlameItem");
        };
        style.checkedOnRead([](const Item &, const StyleSpec &s) { return s.check(); },
                            QStringLiteral("style"));
        style.choice("style.color_by", &StyleSpec::colorBy, StyleSpec::colorByNames(),
                     {QT_TR_NOOP("By map"), QT_TR_NOOP("By address prefix"),
                      QT_TR_NOOP("Single colour")})
            .label(QT_TR_NOOP("Colour"))
            .group(QT_TR_NOOP("Style"))
            .shownWhen(mapColoured)
            .tip(QT_TR_NOOP("The attractor's colours: by the map that made each point, by the "
                            "first symbols of its address, or one colour"));
        style.integer("style.prefix_length", &StyleSpec::prefixLength)
            .label(QT_TR_NOOP("Prefix length"))
            .group(QT_TR_NOOP("Style"))
            .shownWhen(mapColoured)
            .range(1, StyleSpec::maxPrefixLength)
            .tip(QT_TR_NOOP("Colour by address: how many of its first symbols pick the colour"))
            .notAnimated()
            .enabledWhen([](const Item &, const StyleSpec &s) {
                return s.colorBy == StyleSpec::ColorBy::Address;
            });
        style.real("style.point_size", &StyleSpec::pointSize)
            .label(QT_TR_NOOP("Point size"))
            .group(QT_TR_NOOP("Style"))
            .shownWhen(drawn)
            .range(0, StyleSpec::maxPointSize)
            .tip(QT_TR_NOOP("Points of the attractor, in pixels"));
        style.structured(
                 "style.colors", QStringLiteral("colours"),
                 [](const Item &, const StyleSpec &s) {
                     return QJsonValue(QJsonArray::fromStringList(s.colors));
                 },
                 [](const Item &, StyleSpec &s, const QJsonValue &v, const QString &where) {
                     if (!v.isArray())
                         throw LoadError{where, tr("expected an array of \"#rrggbb\" strings")};
                     s.colors.clear();
                     const QJsonArray list = v.toArray();
                     for (qsizetype i = 0; i < list.size(); ++i) {
                         if (!list[i].isString())
                             throw LoadError{where + QStringLiteral("[%1]").arg(i + 1),
                                             tr("expected a string \"#rrggbb\"")};
                         s.colors << list[i].toString().toLower();
                     }
                 })
            .label(QT_TR_NOOP("Palette"))
            .group(QT_TR_NOOP("Style"))
            .tip(QT_TR_NOOP("Own colours, one per map or address prefix (\"#rrggbb\"); none: "
                            "the views' palette"));
        style.choice("style.tone", &StyleSpec::tone, StyleSpec::toneNames(),
                     {QT_TR_NOOP("Automatic"), QT_TR_NOOP("Hits"), QT_TR_NOOP("Density")})
            .label(QT_TR_NOOP("Tone"))
            .group(QT_TR_NOOP("Style"))
            .shownWhen(drawn)
            .tip(QT_TR_NOOP("Hits: every pixel the attractor reaches (the papers' look); "
                            "density: the invariant measure by log density; automatic: hits "
                            "for deterministic, density for random iteration"))
            .omitWhenDefault();
        style.real("style.gamma", &StyleSpec::gamma)
            .label(QT_TR_NOOP("Gamma"))
            .group(QT_TR_NOOP("Style"))
            .shownWhen(mapColoured)
            .range(0.2, 10)
            .tip(QT_TR_NOOP("Gamma of the density tone"))
            .enabledWhen([](const Item &, const StyleSpec &s) {
                return s.tone != StyleSpec::Tone::Hits;
            })
            .omitWhenDefault();

        auto animation = tail.part(&Item::m_animation, &Item::checkAnimation,
                                   &Item::animationChanged,
                                   QT_TR_NOOP("Edit animation of %1"));
        animation.startsFrom([](const Item &) { return AnimationSpec{0.0, 25.0, {}}; });
        animation
            .structured(
                "animation", QStringLiteral("animation"),
                [](const Item &, const AnimationSpec &a) {
                    return QJsonValue(animationToJson(a));
                },
                [](const Item &, AnimationSpec &a, const QJsonValue &v, const QString &where) {
                    if (!v.isObject())
                        throw LoadError{where, QCoreApplication::translate(
                                                   "awb::FieldReader", "expected an object")};
                    a = readAnimation(FieldReader(v.toObject(), where + QLatin1Char('.')));
                    if (a.isEmpty())
                        a = AnimationSpec{0.0, 25.0, {}};
                })
            .label(QT_TR_NOOP("Animation"))
            .omitWhenDefault();  // an empty animation is always the initial one
        return tail.table();
    }();
    return table;
}

const PropertyTable &Item::properties() const { return itemProperties(); }

QList<ParameterInfo> Item::parameters() const { return properties().parameters(*this); }

QVariant Item::parameter(const QString &key) const { return properties().value(*this, key); }

bool Item::setParameter(const QString &key, const QVariant &value, int gesture, QString *error)
{
    return properties().set(*this, key, value, gesture, error);
}

void Item::write(QJsonObject &json) const
{
    for (auto it = m_unknownFields.begin(); it != m_unknownFields.end(); ++it)
        json.insert(it.key(), it.value());
    properties().write(*this, json);
}

void Item::read(const FieldReader &fields) { properties().read(*this, fields); }

void Item::checkLoaded(const FieldReader &) const {}

} // namespace awb
