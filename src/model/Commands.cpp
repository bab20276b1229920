#include "model/Commands.h"

#include "model/Project.h"

namespace awb {

// ---- items ------------------------------------------------------------------------------------

InsertItemCommand::InsertItemCommand(Project *project, std::unique_ptr<Item> item, Item *parent,
                                     int row)
    : QUndoCommand(tr("Add %1").arg(item->name())), m_project(project), m_item(item.get()),
      m_owned(std::move(item)), m_parent(parent), m_row(row)
{
}

InsertItemCommand::~InsertItemCommand() = default;

void InsertItemCommand::redo()
{
    m_project->attach(std::move(m_owned), m_parent, m_row);
}

void InsertItemCommand::undo()
{
    m_owned = m_project->detach(m_item);
}

RemoveItemCommand::RemoveItemCommand(Project *project, Item *item)
    : QUndoCommand(tr("Remove %1").arg(item->name())), m_project(project), m_item(item),
      m_parent(item->parentItem()), m_row(project->rowOf(item))
{
}

RemoveItemCommand::~RemoveItemCommand() = default;

void RemoveItemCommand::redo()
{
    m_owned = m_project->detach(m_item);
}

void RemoveItemCommand::undo()
{
    m_project->attach(std::move(m_owned), m_parent, m_row);
}

MoveItemCommand::MoveItemCommand(Project *project, Item *item, Item *parent, int row)
    : QUndoCommand(tr("Move %1").arg(item->name())), m_project(project), m_item(item),
      m_oldParent(item->parentItem()), m_newParent(parent), m_oldRow(project->rowOf(item)),
      m_newRow(row)
{
}

void MoveItemCommand::redo()
{
    m_project->relocate(m_item, m_newParent, m_newRow);
}

void MoveItemCommand::undo()
{
    m_project->relocate(m_item, m_oldParent, m_oldRow);
}

// ---- control points ---------------------------------------------------------------------------

MoveControlPointsCommand::MoveControlPointsCommand(AttractorItem *item, int set,
                                                   const std::map<int, Point> &to,
                                                   int gesture)
    // English has no numerus translation file: the singular is its own message.
    : QUndoCommand((to.size() == 1 ? tr("Move a control point of %1")
                                   : tr("Move %n control points of %1", nullptr, int(to.size())))
                       .arg(item->name())),
      m_item(item), m_set(set), m_gesture(gesture)
{
    for (const auto &[index, p] : to)
        m_moves[index] = {item->controlPoints(set)[size_t(index)], p};
}

void MoveControlPointsCommand::redo() { apply(true); }

void MoveControlPointsCommand::undo() { apply(false); }

void MoveControlPointsCommand::apply(bool forward)
{
    for (const auto &[index, move] : m_moves)
        m_item->storePoint(m_set, index, forward ? move.to : move.from);
}

bool MoveControlPointsCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = dynamic_cast<const MoveControlPointsCommand *>(other);
    if (!next || next->m_item != m_item || next->m_set != m_set || next->m_gesture != m_gesture
        || next->m_moves.size() != m_moves.size())
        return false;
    for (const auto &[index, move] : next->m_moves)
        if (!m_moves.count(index))
            return false;
    bool moved = false;
    for (auto &[index, move] : m_moves) {
        move.to = next->m_moves.at(index).to;
        moved = moved || !(move.to == move.from);
    }
    // A drag that ends where it started leaves no undo step.
    setObsolete(!moved);
    return true;
}

InsertControlPointCommand::InsertControlPointCommand(AttractorItem *item, int set, int index,
                                                     const Point &point)
    : QUndoCommand(tr("Add a control point to %1").arg(item->name())), m_item(item), m_set(set),
      m_index(index), m_point(point)
{
}

void InsertControlPointCommand::redo() { m_item->storeInsertedPoint(m_set, m_index, m_point); }

void InsertControlPointCommand::undo() { m_item->storeRemovedPoint(m_set, m_index); }

RemoveControlPointCommand::RemoveControlPointCommand(AttractorItem *item, int set, int index)
    : QUndoCommand(tr("Remove a control point of %1").arg(item->name())), m_item(item),
      m_set(set), m_index(index), m_point(item->controlPoints(set)[size_t(index)])
{
}

void RemoveControlPointCommand::redo() { m_item->storeRemovedPoint(m_set, m_index); }

void RemoveControlPointCommand::undo() { m_item->storeInsertedPoint(m_set, m_index, m_point); }

// ---- compound ---------------------------------------------------------------------------------

CompoundCommand::CompoundCommand(const QString &text) : QUndoCommand(text) {}

CompoundCommand::~CompoundCommand() = default;

void CompoundCommand::addApplied(QUndoCommand *command)
{
    QUndoCommand *last = m_children.empty() ? nullptr : m_children.back().get();
    if (last && last->id() != -1 && last->id() == command->id() && last->mergeWith(command)) {
        delete command;
        if (last->isObsolete())
            m_children.pop_back();
        return;
    }
    m_children.emplace_back(command);
}

void CompoundCommand::redo()
{
    if (m_applied) { // the children ran as they were added
        m_applied = false;
        return;
    }
    for (auto &c : m_children)
        c->redo();
}

void CompoundCommand::undo()
{
    for (auto it = m_children.rbegin(); it != m_children.rend(); ++it)
        (*it)->undo();
}

} // namespace awb
