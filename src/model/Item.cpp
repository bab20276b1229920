#include "model/Item.h"

#include "model/Commands.h"
#include "model/Project.h"
#include "model/ProjectIO.h"

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
    if (checkStyle(style))
        return false;
    applyProperty(&Item::m_style, style, &Item::styleChanged,
                  tr("Change style of %1").arg(m_name), gesture);
    return true;
}

bool Item::setAnimation(const AnimationSpec &animation, QString *error)
{
    AnimationSpec spec = animation;
    if (spec.isEmpty())
        spec = AnimationSpec{0.0, 25.0, {}};
    else if (const MaybeProblem p = animationProblem(*this, spec, &m_animation)) {
        if (error)
            *error = p->field.isEmpty() ? p->message
                                        : QStringLiteral("%1: %2").arg(p->field, p->message);
        return false;
    }
    applyProperty(&Item::m_animation, spec, &Item::animationChanged,
                  tr("Edit animation of %1").arg(m_name));
    return true;
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

void Item::inputsChanged()
{
    ++m_generation;
    dropDerived();
    emit derivedChanged();
}

void Item::renameReference(const QString &, const QString &) {}

void Item::write(QJsonObject &json) const
{
    for (auto it = m_unknownFields.begin(); it != m_unknownFields.end(); ++it)
        json.insert(it.key(), it.value());
    json["name"] = m_name;
    json["style"] = ProjectIO::styleToJson(m_style);
    if (!m_animation.isEmpty())
        json["animation"] = animationToJson(m_animation);
}

void Item::read(const FieldReader &fields)
{
    m_name = fields.string("name");
    if (m_name.trimmed().isEmpty())
        fields.fail("name", tr("the name cannot be empty"));
    if (auto style = fields.object("style"))
        m_style = ProjectIO::readStyle(*style);
    if (auto animation = fields.object("animation")) {
        m_animation = readAnimation(*animation);
        if (m_animation.isEmpty())
            m_animation = AnimationSpec{0.0, 25.0, {}};
    }
}

void Item::checkLoaded(const FieldReader &) const {}

QVariant Item::parameter(const QString &) const { return {}; }

bool Item::setParameter(const QString &key, const QVariant &, int, QString *error)
{
    if (error)
        *error = tr("%1 has no parameter \"%2\"").arg(typeName(), key);
    return false;
}

bool Item::commitParameter(const QString &key, const QVariant &value, bool parsed,
                           const MaybeProblem &problem, const std::function<bool()> &apply,
                           QString *error)
{
    if (!parsed) {
        if (error)
            *error = tr("\"%1\" is not a valid value for %2").arg(value.toString(), key);
        return false;
    }
    if (problem) {
        if (error)
            *error = problem->message;
        return false;
    }
    return apply();
}

} // namespace awb
