#pragma once
// The item tree of a Project as a QAbstractItemModel (layer 2, model), for the GUI's tree view.
// An adapter only: it owns no data, follows the project's signals, and routes edits from the
// view (rename, remove, move) to the project's undoable API, so an edit in the tree is undone
// like any other.

#include <QAbstractItemModel>

namespace awb {

class Item;
class Project;

class ProjectTreeModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum Column { NameColumn, TypeColumn, ColumnCount };
    enum Role {
        ItemTypeRole = Qt::UserRole + 1, // the JSON "type" (QString)
        DerivedErrorRole,                // why the item cannot be computed ("" if it can)
    };

    explicit ProjectTreeModel(Project *project, QObject *parent = nullptr);

    Project *project() const { return m_project; }
    Item *itemAt(const QModelIndex &index) const;
    QModelIndex indexOf(const Item *item, int column = 0) const;

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &index) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    // Renames through Project::renameItem (one undo step); refuses empty or taken names.
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    // Remove and move as one undo step each.
    bool removeRows(int row, int count, const QModelIndex &parent = {}) override;
    bool moveRows(const QModelIndex &sourceParent, int sourceRow, int count,
                  const QModelIndex &destinationParent, int destinationChild) override;

private:
    Project *m_project;
};

} // namespace awb
