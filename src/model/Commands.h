#pragma once
// The undo commands of the document (layer 2, model). Every user-visible edit is one of these,
// pushed on the Project's QUndoStack (STYLE.md §5-8):
//  * PropertyCommand: the one template for property edits (swap old/new, emit the signal);
//  * structural commands for items (insert, remove, move) and control points (insert, remove);
//  * MoveControlPointsCommand: moving one or several points; the moves of one drag share a
//    gesture id and merge into ONE undo step;
//  * CompoundCommand: several edits as one undo step.

#include "model/AttractorItem.h"
#include "model/Item.h"

#include <QUndoCommand>

#include <map>

namespace awb {

class Project;

// Every mergeable command's id(), in one place. Commands that never merge return -1.
enum CommandId : int {
    PropertyEditId = 1,   // PropertyCommand with a gesture
    MoveControlPointsId,  // MoveControlPointsCommand with a gesture
};

// Sets one stored field of an item. The owner keeps the field private and hands the command a
// pointer to it; redo and undo both swap the command's value with the field's, so the command
// always holds the value the other direction needs. Edits with the same nonzero gesture on the
// same field merge (a slider drag is one step); a merge that returns to the start is obsolete.
template <class Owner, class Value>
class PropertyCommand : public QUndoCommand {
public:
    using Field = Value Owner::*;
    using Signal = void (Owner::*)();

    PropertyCommand(Owner *owner, Field field, Value value, Signal signal, const QString &text,
                    int gesture = 0)
        : QUndoCommand(text), m_owner(owner), m_field(field), m_value(std::move(value)),
          m_signal(signal), m_gesture(gesture)
    {
    }

    void redo() override { swap(); }
    void undo() override { swap(); }
    int id() const override { return m_gesture != 0 ? PropertyEditId : -1; }

    bool mergeWith(const QUndoCommand *other) override
    {
        const auto *next = dynamic_cast<const PropertyCommand *>(other);
        if (!next || next->m_owner != m_owner || next->m_field != m_field
            || next->m_gesture != m_gesture)
            return false;
        // This command keeps the value from before the gesture; the field already holds the
        // newest one.
        setObsolete(m_owner->*m_field == m_value);
        return true;
    }

private:
    void swap()
    {
        std::swap(m_owner->*m_field, m_value);
        m_owner->inputsChanged();
        emit(m_owner->*m_signal)();
        emit m_owner->changed();
    }

    Owner *m_owner;
    Field m_field;
    Value m_value;
    Signal m_signal;
    int m_gesture;
};

template <class Owner, class Value>
void Item::applyProperty(Value Owner::*field, const Value &value, void (Owner::*signal)(),
                         const QString &text, int gesture)
{
    auto *owner = static_cast<Owner *>(this);
    if (owner->*field == value)
        return;
    executeProperty(new PropertyCommand<Owner, Value>(owner, field, value, signal, text, gesture),
                    gesture);
}

// Adds an item to the tree. Ownership: the command owns the item before its first redo and
// while undone; the project owns it after redo.
class InsertItemCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(awb::InsertItemCommand)
public:
    InsertItemCommand(Project *project, std::unique_ptr<Item> item, Item *parent, int row);
    ~InsertItemCommand() override;
    void redo() override;
    void undo() override;
    Item *item() const { return m_item; }

private:
    Project *m_project;
    Item *m_item;
    std::unique_ptr<Item> m_owned;
    Item *m_parent;
    int m_row;
};

// Removes an item (with its children) from the tree. Ownership: the project owns the item
// while the command is undone; the command owns it after redo, so that undo puts the very
// same object back and the commands above this one on the stack still point to it.
class RemoveItemCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(awb::RemoveItemCommand)
public:
    RemoveItemCommand(Project *project, Item *item);
    ~RemoveItemCommand() override;
    void redo() override;
    void undo() override;

private:
    Project *m_project;
    Item *m_item;
    std::unique_ptr<Item> m_owned;
    Item *m_parent;
    int m_row;
};

// Moves an item to another row and/or parent. The project owns the item throughout.
class MoveItemCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(awb::MoveItemCommand)
public:
    // `row` is the item's row under `parent` after the move.
    MoveItemCommand(Project *project, Item *item, Item *parent, int row);
    void redo() override;
    void undo() override;

private:
    Project *m_project;
    Item *m_item;
    Item *m_oldParent, *m_newParent;
    int m_oldRow, m_newRow;
};

// Moves control points of one point set of an item: index -> new position.
class MoveControlPointsCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(awb::MoveControlPointsCommand)
public:
    MoveControlPointsCommand(AttractorItem *item, int set, const std::map<int, Point> &to,
                             int gesture);
    void redo() override;
    void undo() override;
    int id() const override { return m_gesture != 0 ? MoveControlPointsId : -1; }
    // Same item, point set, points and gesture: keep the start, take the newest end.
    bool mergeWith(const QUndoCommand *other) override;

private:
    struct Move {
        Point from, to;
    };
    void apply(bool forward);

    AttractorItem *m_item;
    int m_set;
    std::map<int, Move> m_moves;
    int m_gesture;
};

// Inserts one control point. The point is a value: nothing to own.
class InsertControlPointCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(awb::InsertControlPointCommand)
public:
    InsertControlPointCommand(AttractorItem *item, int set, int index, const Point &point);
    void redo() override;
    void undo() override;

private:
    AttractorItem *m_item;
    int m_set, m_index;
    Point m_point;
};

class RemoveControlPointCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(awb::RemoveControlPointCommand)
public:
    RemoveControlPointCommand(AttractorItem *item, int set, int index);
    void redo() override;
    void undo() override;

private:
    AttractorItem *m_item;
    int m_set, m_index;
    Point m_point;
};

// Several edits as one undo step (a multi-point or multi-item edit). The project collects the
// edits made between beginCompound() and endCompound(): each is applied as it comes, so the
// first redo() when the compound is pushed has nothing left to do.
class CompoundCommand : public QUndoCommand {
public:
    explicit CompoundCommand(const QString &text);
    ~CompoundCommand() override;
    // Takes a command that has already been applied; merges it into the previous child when
    // they are steps of the same gesture.
    void addApplied(QUndoCommand *command);
    int size() const { return int(m_children.size()); }
    void redo() override;
    void undo() override;

private:
    std::vector<std::unique_ptr<QUndoCommand>> m_children;
    bool m_applied = true;
};

} // namespace awb
