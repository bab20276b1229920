#include "model/ProjectTreeModel.h"

#include "model/Project.h"

namespace awb {

ProjectTreeModel::ProjectTreeModel(Project *project, QObject *parent)
    : QAbstractItemModel(parent), m_project(project)
{
    connect(project, &Project::itemAboutToBeInserted, this, [this](Item *parent, int row) {
        beginInsertRows(indexOf(parent), row, row);
    });
    connect(project, &Project::itemInserted, this, [this] { endInsertRows(); });
    connect(project, &Project::itemAboutToBeRemoved, this, [this](Item *item) {
        const int row = m_project->rowOf(item);
        beginRemoveRows(indexOf(item->parentItem()), row, row);
    });
    connect(project, &Project::itemRemoved, this, [this] { endRemoveRows(); });
    connect(project, &Project::itemAboutToBeMoved, this, [this](Item *item, Item *to, int row) {
        const int from = m_project->rowOf(item);
        // Qt wants the destination row as it is before the move.
        const int destination = item->parentItem() == to && row > from ? row + 1 : row;
        beginMoveRows(indexOf(item->parentItem()), from, from, indexOf(to), destination);
    });
    connect(project, &Project::itemMoved, this, [this] { endMoveRows(); });
    auto changed = [this](Item *item) {
        emit dataChanged(indexOf(item, NameColumn), indexOf(item, TypeColumn));
    };
    connect(project, &Project::itemChanged, this, changed);
    connect(project, &Project::itemDerivedChanged, this, changed);
    connect(project, &Project::aboutToReset, this, [this] { beginResetModel(); });
    connect(project, &Project::reset, this, [this] { endResetModel(); });
}

Item *ProjectTreeModel::itemAt(const QModelIndex &index) const
{
    return index.isValid() ? static_cast<Item *>(index.internalPointer()) : nullptr;
}

QModelIndex ProjectTreeModel::indexOf(const Item *item, int column) const
{
    const int row = m_project->rowOf(item);
    return row < 0 ? QModelIndex() : createIndex(row, column, const_cast<Item *>(item));
}

QModelIndex ProjectTreeModel::index(int row, int column, const QModelIndex &parent) const
{
    if (column < 0 || column >= ColumnCount || (parent.isValid() && parent.column() != 0))
        return {};
    Item *item = m_project->child(itemAt(parent), row);
    return item ? createIndex(row, column, item) : QModelIndex();
}

QModelIndex ProjectTreeModel::parent(const QModelIndex &index) const
{
    const Item *item = itemAt(index);
    return item ? indexOf(item->parentItem()) : QModelIndex();
}

int ProjectTreeModel::rowCount(const QModelIndex &parent) const
{
    if (parent.isValid() && parent.column() != 0)
        return 0;
    return m_project->childCount(itemAt(parent));
}

int ProjectTreeModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

QVariant ProjectTreeModel::data(const QModelIndex &index, int role) const
{
    const Item *item = itemAt(index);
    if (!item)
        return {};
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        return index.column() == NameColumn ? item->name() : item->typeName();
    case Qt::ToolTipRole: {
        // The whole name (the column elides it), its kind, and what keeps it from being drawn.
        const QString error = item->derivedError();
        const QString what = QStringLiteral("%1\n%2").arg(item->name(), item->typeName());
        return error.isEmpty() ? what : what + QLatin1Char('\n') + error;
    }
    case ItemTypeRole: return item->type();
    case DerivedErrorRole: return item->derivedError();
    default: return {};
    }
}

QVariant ProjectTreeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    return section == NameColumn ? tr("Name") : section == TypeColumn ? tr("Kind") : QVariant();
}

Qt::ItemFlags ProjectTreeModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsSelectable | Qt::ItemIsEnabled;
    if (index.column() == NameColumn)
        f |= Qt::ItemIsEditable;
    return f;
}

bool ProjectTreeModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    Item *item = itemAt(index);
    if (!item || role != Qt::EditRole || index.column() != NameColumn)
        return false;
    return m_project->renameItem(item, value.toString());
}

bool ProjectTreeModel::removeRows(int row, int count, const QModelIndex &parent)
{
    const Item *parentItem = itemAt(parent);
    if (count < 1 || row < 0 || row + count > m_project->childCount(parentItem))
        return false;
    QList<Item *> items;
    for (int i = row; i < row + count; ++i)
        items << m_project->child(parentItem, i);
    return m_project->removeItems(items);
}

bool ProjectTreeModel::moveRows(const QModelIndex &sourceParent, int sourceRow, int count,
                                const QModelIndex &destinationParent, int destinationChild)
{
    Item *from = itemAt(sourceParent);
    Item *to = itemAt(destinationParent);
    if (count < 1 || sourceRow < 0 || sourceRow + count > m_project->childCount(from)
        || destinationChild < 0 || destinationChild > m_project->childCount(to))
        return false;
    QList<Item *> items;
    for (int i = sourceRow; i < sourceRow + count; ++i)
        items << m_project->child(from, i);
    for (Item *item : items)
        if (item == to || item->isAncestorOf(to))
            return false;
    // Qt's destination counts the moved rows when they sit before it under the same parent;
    // `row` is where the first moved item ends up.
    if (from == to && destinationChild >= sourceRow && destinationChild <= sourceRow + count)
        return false; // onto itself
    int row = destinationChild;
    if (from == to && destinationChild > sourceRow)
        row -= count;
    CompoundEdit edit(m_project, items.size() == 1
                                     ? tr("Move %1").arg(items.front()->name())
                                     : tr("Move %n items", nullptr, int(items.size())));
    // Moving down a list, place the last item first so the others do not shift its target.
    if (from == to && row > sourceRow) {
        for (int k = count - 1; k >= 0; --k)
            m_project->moveItem(items[k], to, row + k);
    } else {
        for (int k = 0; k < count; ++k)
            m_project->moveItem(items[k], to, row + k);
    }
    return true;
}

} // namespace awb
