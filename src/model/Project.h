#pragma once
// The document (layer 2, model): an ordered tree of items, the one QUndoStack every edit goes
// through (STYLE.md §5), the file it was loaded from or saved to, and the modified state, which
// follows the stack's clean state. The GUI, the CLI and the tests all work through this class;
// views observe its signals (ProjectTreeModel adapts the tree for Qt's item views).

#include "model/Item.h"

#include <QJsonObject>
#include <QUndoStack>

namespace awb {

struct ProjectData;
class CompoundCommand;

class Project : public QObject {
    Q_OBJECT
public:
    explicit Project(QObject *parent = nullptr);
    ~Project() override;

    // ---- the tree. `parent` nullptr means the top level.
    int childCount(const Item *parent = nullptr) const;
    Item *child(const Item *parent, int row) const;
    Item *child(int row) const { return child(nullptr, row); }
    // Row of `item` under its parent (or the top level); -1 when not in this project.
    int rowOf(const Item *item) const;
    // Every item, depth first in tree order.
    QList<Item *> items() const;
    Item *findItem(const QString &name) const;
    // `base` if no item has that name, else "base 2", "base 3", ...
    QString uniqueName(const QString &base) const;
    // Why `item` cannot be called `name` (empty, or taken by another item).
    MaybeProblem checkName(const Item *item, const QString &name) const;

    // ---- undoable structural edits. Each is one undo step.
    // Takes ownership; renames the item (and its children) if needed to keep names unique.
    // row -1 appends. Returns the item.
    Item *addItem(std::unique_ptr<Item> item, Item *parent = nullptr, int row = -1);
    bool removeItem(Item *item);
    // Removes several items (an item inside another removed one goes with its ancestor).
    bool removeItems(const QList<Item *> &items);
    // `row` is the item's row under `parent` after the move; moving an item into itself or
    // one of its descendants is refused, as is a move that changes nothing.
    bool moveItem(Item *item, Item *parent, int row);
    bool renameItem(Item *item, const QString &name);

    // ---- undo
    QUndoStack *undoStack() { return &m_stack; }
    // Pushes `command` (or adds it to the open compound edit). Takes ownership.
    void push(QUndoCommand *command);
    // Everything pushed between begin and end becomes ONE undo step. Nests; an empty
    // compound leaves no step behind.
    void beginCompound(const QString &text);
    void endCompound();
    // A fresh id for one interactive gesture (a drag, a slider): its edits merge into one
    // undo step. The gesture is open until endGesture(id); while any is open, gestureActive()
    // is true, and views may draw quicker, coarser frames and defer what the pointer does not
    // need (the GUI's FrameBudget). Opening the first and closing the last emit
    // gestureActiveChanged. Ending an unknown or ended id does nothing.
    int beginGesture();
    void endGesture(int id);
    bool gestureActive() const { return !m_openGestures.empty(); }

    // ---- files
    bool isModified() const { return !m_stack.isClean(); }
    QString fileName() const { return m_fileName; }
    // Replaces the project with the file's content, or fails with a message naming the file,
    // the item and the field, leaving the project untouched.
    bool open(const QString &fileName, QString *error = nullptr);
    // Atomic: a failed save leaves the previous file intact. Marks the project clean.
    bool save(QString *error = nullptr);
    bool saveAs(const QString &fileName, QString *error = nullptr);
    // The bytes save() would write.
    QByteArray serialize() const;
    // An empty, clean project with no file.
    void clear();
    // Replaces the content with `data` (loaded elsewhere, e.g. from a recovery file): the undo
    // history is cleared, the file name set, and the project marked modified if asked.
    void adopt(ProjectData &&data, const QString &fileName, bool modified);
    // Fields of the root object this version does not know: written back unchanged.
    const QJsonObject &unknownFields() const { return m_unknownFields; }

    // Every item whose derived data cannot be computed, as "name: reason" (for `validate`).
    QStringList problems() const;

signals:
    void itemAboutToBeInserted(awb::Item *parent, int row);
    void itemInserted(awb::Item *item);
    void itemAboutToBeRemoved(awb::Item *item);
    void itemRemoved(awb::Item *parent, int row);
    // `row` is the row under `parent` after the move.
    void itemAboutToBeMoved(awb::Item *item, awb::Item *parent, int row);
    void itemMoved(awb::Item *item);
    // Forwarded from the items.
    void itemChanged(awb::Item *item);
    void itemDerivedChanged(awb::Item *item);
    // The whole content is replaced (open, clear, adopt).
    void aboutToReset();
    void reset();
    void modifiedChanged(bool modified);
    void fileNameChanged(const QString &fileName);
    void gestureActiveChanged(bool active);

private:
    friend class InsertItemCommand;
    friend class RemoveItemCommand;
    friend class MoveItemCommand;

    // Raw structural edits for the commands (no undo), with the signals above.
    void attach(std::unique_ptr<Item> item, Item *parent, int row);
    std::unique_ptr<Item> detach(Item *item);
    void relocate(Item *item, Item *parent, int row);

    std::vector<std::unique_ptr<Item>> &siblings(Item *parent);
    const std::vector<std::unique_ptr<Item>> &siblings(const Item *parent) const;
    void bind(Item *item, Item *parent);
    void unbind(Item *item);
    void makeNamesUnique(Item *item);
    // Drops the derived data of the items that read `item` (transitively).
    void invalidateReaders(const Item *item);
    void invalidateAllReaders();
    bool writeTo(const QString &fileName, QString *error);
    void replaceContent(std::vector<std::unique_ptr<Item>> items, const QJsonObject &unknown,
                        const QString &fileName);

    std::vector<std::unique_ptr<Item>> m_items;
    QJsonObject m_unknownFields;
    QString m_fileName;
    QUndoStack m_stack;
    std::unique_ptr<CompoundCommand> m_compound;
    int m_compoundDepth = 0;
    int m_lastGesture = 0;
    std::vector<int> m_openGestures;
};

// Runs the edits of its lifetime as one compound undo step (no-op without a project).
class CompoundEdit {
public:
    CompoundEdit(Project *project, const QString &text);
    ~CompoundEdit();
    CompoundEdit(const CompoundEdit &) = delete;
    CompoundEdit &operator=(const CompoundEdit &) = delete;

private:
    Project *m_project;
};

} // namespace awb
