#include "model/FigureMetadata.h"
#include "model/Project.h"

#include "model/AttractorItem.h"

#include "model/Commands.h"
#include "model/ProjectIO.h"

#include <QRegularExpression>
#include <QSet>

#include <algorithm>

namespace awb {

namespace {

QString uniqueIn(const QSet<QString> &taken, QString base)
{
    base = base.trimmed();
    if (base.isEmpty())
        base = QCoreApplication::translate("awb::Project", "Item");
    if (!taken.contains(base))
        return base;
    // "Curve 3" continues as "Curve 4", not "Curve 3 2".
    static const QRegularExpression numbered("^(.*\\S)\\s+\\d+$");
    const auto m = numbered.match(base);
    const QString stem = m.hasMatch() ? m.captured(1) : base;
    for (int n = 2;; ++n) {
        const QString candidate = QStringLiteral("%1 %2").arg(stem).arg(n);
        if (!taken.contains(candidate))
            return candidate;
    }
}

void collect(const Item *item, QList<Item *> &out)
{
    for (int i = 0; i < item->childCount(); ++i) {
        out << item->child(i);
        collect(item->child(i), out);
    }
}

} // namespace

Project::Project(QObject *parent) : QObject(parent)
{
    connect(&m_stack, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
}

Project::~Project()
{
    // ~QUndoStack clears the stack and emits signals: not into a half-destroyed project.
    m_stack.disconnect();
    m_stack.clear();
}

// ---- the tree ---------------------------------------------------------------------------------

std::vector<std::unique_ptr<Item>> &Project::siblings(Item *parent)
{
    return parent ? parent->m_children : m_items;
}

const std::vector<std::unique_ptr<Item>> &Project::siblings(const Item *parent) const
{
    return parent ? parent->m_children : m_items;
}

int Project::childCount(const Item *parent) const
{
    return int(siblings(parent).size());
}

Item *Project::child(const Item *parent, int row) const
{
    const auto &list = siblings(parent);
    return row >= 0 && row < int(list.size()) ? list[size_t(row)].get() : nullptr;
}

int Project::rowOf(const Item *item) const
{
    if (!item || item->m_project != this)
        return -1;
    const auto &list = siblings(item->m_parent);
    for (size_t i = 0; i < list.size(); ++i)
        if (list[i].get() == item)
            return int(i);
    return -1;
}

QList<Item *> Project::items() const
{
    QList<Item *> out;
    for (const auto &item : m_items) {
        out << item.get();
        collect(item.get(), out);
    }
    return out;
}

Item *Project::findItem(const QString &name) const
{
    for (Item *item : items())
        if (item->name() == name)
            return item;
    return nullptr;
}

QString Project::uniqueName(const QString &base) const
{
    QSet<QString> taken;
    for (const Item *item : items())
        taken.insert(item->name());
    return uniqueIn(taken, base);
}

MaybeProblem Project::checkName(const Item *item, const QString &name) const
{
    if (name.trimmed().isEmpty())
        return Problem{"name", tr("the name cannot be empty")};
    const Item *other = findItem(name);
    if (other && other != item)
        return Problem{"name", tr("another item is already called \"%1\"").arg(name)};
    return std::nullopt;
}

// ---- undoable edits ---------------------------------------------------------------------------

Item *Project::addItem(std::unique_ptr<Item> item, Item *parent, int row)
{
    if (!item || item->m_project || (parent && parent->m_project != this))
        return nullptr;
    const int count = childCount(parent);
    if (row < 0 || row > count)
        row = count;
    makeNamesUnique(item.get());
    Item *raw = item.get();
    push(new InsertItemCommand(this, std::move(item), parent, row));
    return raw;
}

void Project::makeNamesUnique(Item *item)
{
    QSet<QString> taken;
    for (const Item *other : items())
        taken.insert(other->name());
    QList<Item *> subtree{item};
    collect(item, subtree);
    for (Item *i : subtree) {
        i->m_name = uniqueIn(taken, i->m_name); // not in a project yet: no undo needed
        taken.insert(i->m_name);
    }
}

bool Project::removeItem(Item *item)
{
    return removeItems({item});
}

bool Project::removeItems(const QList<Item *> &items)
{
    QList<Item *> roots;
    for (Item *item : items) {
        if (!item || item->m_project != this || roots.contains(item))
            continue;
        bool insideAnother = false;
        for (Item *other : items)
            insideAnother = insideAnother || (other && other->isAncestorOf(item));
        if (!insideAnother)
            roots << item;
    }
    if (roots.isEmpty())
        return false;
    CompoundEdit edit(roots.size() > 1 ? this : nullptr,
                      tr("Remove %n items", nullptr, int(roots.size())));
    for (Item *item : roots)
        push(new RemoveItemCommand(this, item));
    return true;
}

bool Project::moveItem(Item *item, Item *parent, int row)
{
    if (!item || item->m_project != this || (parent && parent->m_project != this)
        || parent == item || item->isAncestorOf(parent))
        return false;
    const bool sameParent = item->m_parent == parent;
    const int count = childCount(parent) - (sameParent ? 1 : 0);
    if (row < 0 || row > count || (sameParent && row == rowOf(item)))
        return false;
    push(new MoveItemCommand(this, item, parent, row));
    return true;
}

bool Project::renameItem(Item *item, const QString &name)
{
    if (!item || item->m_project != this || checkName(item, name))
        return false;
    const QString old = item->m_name;
    if (old == name)
        return true;
    // Items that refer to the old name follow it, in the same undo step.
    CompoundEdit edit(this, tr("Rename %1 to %2").arg(old, name));
    push(new PropertyCommand<Item, QString>(item, &Item::m_name, name, &Item::nameChanged,
                                            tr("Rename %1 to %2").arg(old, name)));
    for (Item *other : items())
        if (other != item && other->references().contains(old))
            other->renameReference(old, name);
    return true;
}

void Project::push(QUndoCommand *command)
{
    if (m_compound) {
        command->redo();
        m_compound->addApplied(command);
    } else {
        m_stack.push(command);
    }
}

void Project::beginCompound(const QString &text)
{
    if (m_compoundDepth++ == 0)
        m_compound = std::make_unique<CompoundCommand>(text);
}

void Project::endCompound()
{
    if (m_compoundDepth == 0 || --m_compoundDepth > 0)
        return;
    std::unique_ptr<CompoundCommand> compound = std::move(m_compound);
    if (compound->size() > 0)
        m_stack.push(compound.release()); // its first redo() is a no-op
}

// ---- raw structural edits (for the commands) --------------------------------------------------

void Project::bind(Item *item, Item *parent)
{
    item->m_project = this;
    item->m_parent = parent;
    connect(item, &Item::changed, this, [this, item] { emit itemChanged(item); });
    connect(item, &Item::nameChanged, this, [this] { invalidateAllReaders(); });
    connect(item, &Item::derivedChanged, this, [this, item] {
        emit itemDerivedChanged(item);
        invalidateReaders(item);
    });
    for (const auto &child : item->m_children)
        bind(child.get(), item);
}

void Project::unbind(Item *item)
{
    disconnect(item, nullptr, this, nullptr);
    item->m_project = nullptr;
    for (const auto &child : item->m_children)
        unbind(child.get());
}

void Project::attach(std::unique_ptr<Item> item, Item *parent, int row)
{
    auto &list = siblings(parent);
    Item *raw = item.get();
    emit itemAboutToBeInserted(parent, row);
    list.insert(list.begin() + row, std::move(item));
    bind(raw, parent);
    emit itemInserted(raw);
    invalidateAllReaders(); // a name may resolve now
}

std::unique_ptr<Item> Project::detach(Item *item)
{
    Item *parent = item->m_parent;
    const int row = rowOf(item);
    auto &list = siblings(parent);
    emit itemAboutToBeRemoved(item);
    std::unique_ptr<Item> owned = std::move(list[size_t(row)]);
    list.erase(list.begin() + row);
    unbind(owned.get());
    owned->m_parent = nullptr;
    emit itemRemoved(parent, row);
    invalidateAllReaders(); // a name no longer resolves
    return owned;
}

void Project::relocate(Item *item, Item *parent, int row)
{
    emit itemAboutToBeMoved(item, parent, row);
    auto &from = siblings(item->m_parent);
    const int oldRow = rowOf(item);
    std::unique_ptr<Item> owned = std::move(from[size_t(oldRow)]);
    from.erase(from.begin() + oldRow);
    auto &to = siblings(parent);
    to.insert(to.begin() + row, std::move(owned));
    item->m_parent = parent;
    emit itemMoved(item);
}

void Project::invalidateReaders(const Item *item)
{
    const QString name = item->name();
    for (Item *other : items())
        if (other != item && other->references().contains(name) && other->dropDerived())
            emit other->derivedChanged(); // reaches the readers of `other` in turn
}

void Project::invalidateAllReaders()
{
    for (Item *item : items())
        if (!item->references().isEmpty() && item->dropDerived())
            emit item->derivedChanged();
}

// ---- files ------------------------------------------------------------------------------------

bool Project::open(const QString &fileName, QString *error)
{
    ProjectData data;
    if (figureFileFormat(fileName) != FigureFormat::None) {
        // A figure exported with its parameters (model/FigureMetadata.h): its project goes
        // through the same loader, and opens untitled and unsaved, so that saving never
        // writes over the picture.
        const QByteArray bytes = embeddedProject(fileName, error);
        if (bytes.isEmpty() || !ProjectIO::parse(bytes, fileName, &data, error))
            return false;
        adopt(std::move(data), QString(), true);
        return true;
    }
    if (!ProjectIO::readFile(fileName, &data, error))
        return false;
    adopt(std::move(data), fileName, false);
    return true;
}

bool Project::save(QString *error)
{
    if (m_fileName.isEmpty()) {
        if (error)
            *error = tr("the project has no file name yet: use \"Save As\"");
        return false;
    }
    return writeTo(m_fileName, error);
}

bool Project::saveAs(const QString &fileName, QString *error)
{
    if (!writeTo(fileName, error))
        return false;
    if (m_fileName != fileName) {
        m_fileName = fileName;
        emit fileNameChanged(m_fileName);
    }
    return true;
}

bool Project::writeTo(const QString &fileName, QString *error)
{
    if (!ProjectIO::writeFile(fileName, serialize(), error))
        return false;
    m_stack.setClean();
    return true;
}

QByteArray Project::serialize() const
{
    return ProjectIO::toBytes(ProjectIO::toJson(*this));
}

int Project::beginGesture()
{
    m_openGestures.push_back(++m_lastGesture);
    if (m_openGestures.size() == 1)
        emit gestureActiveChanged(true);
    return m_lastGesture;
}

void Project::endGesture(int id)
{
    const auto it = std::find(m_openGestures.begin(), m_openGestures.end(), id);
    if (it == m_openGestures.end())
        return;
    m_openGestures.erase(it);
    if (m_openGestures.empty())
        emit gestureActiveChanged(false);
}

void Project::clear()
{
    replaceContent({}, {}, {});
}

void Project::adopt(ProjectData &&data, const QString &fileName, bool modified)
{
    replaceContent(std::move(data.items), data.unknownFields, fileName);
    if (modified)
        m_stack.resetClean();
}

void Project::replaceContent(std::vector<std::unique_ptr<Item>> items,
                             const QJsonObject &unknown, const QString &fileName)
{
    emit aboutToReset();
    // Gestures edit items that are about to go.
    if (!m_openGestures.empty()) {
        m_openGestures.clear();
        emit gestureActiveChanged(false);
    }
    m_compound.reset();
    m_compoundDepth = 0;
    m_stack.clear(); // its commands point into the old items: drop them first
    for (const auto &item : m_items)
        unbind(item.get());
    m_items = std::move(items);
    for (const auto &item : m_items)
        bind(item.get(), nullptr);
    m_unknownFields = unknown;
    if (m_fileName != fileName) {
        m_fileName = fileName;
        emit fileNameChanged(m_fileName);
    }
    emit reset();
}

QStringList Project::problems() const
{
    QStringList out;
    for (const Item *item : items()) {
        const QString error = item->derivedError();
        if (!error.isEmpty()) {
            out << tr("%1: %2").arg(item->name(), error);
            continue;
        }
        // The start set too: it is drawn in the IFS's own space.
        if (const auto *a = qobject_cast<const AttractorItem *>(item))
            if (const auto d = a->derivedIfs(); d && !d->iterate)
                try {
                    a->coreStartSet(*d);
                } catch (const std::exception &e) {
                    out << tr("%1: %2").arg(item->name(), QString::fromStdString(e.what()));
                }
    }
    return out;
}

// ---- CompoundEdit -----------------------------------------------------------------------------

CompoundEdit::CompoundEdit(Project *project, const QString &text) : m_project(project)
{
    if (m_project)
        m_project->beginCompound(text);
}

CompoundEdit::~CompoundEdit()
{
    if (m_project)
        m_project->endCompound();
}

} // namespace awb
