// The recording of a project's edits as Python lines (ScriptRecorder.h).

#include "model/ScriptRecorder.h"

#include "model/AttractorItem.h"
#include "model/Project.h"
#include "model/ProjectIO.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLocale>
#include <QPointF>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <set>

namespace awb {

namespace {

QVariantList pointRow(const Point &p, int dim)
{
    return dim == 3 ? QVariantList{p.x, p.y, p.z} : QVariantList{p.x, p.y};
}

// A JSON value with every string equal to a renamed item's old name replaced by its new one
// (what the project does to references when an item is renamed).
QJsonValue followRenames(const QJsonValue &v, const std::map<QString, QString> &renamed)
{
    if (v.isString()) {
        const auto it = renamed.find(v.toString());
        return it == renamed.end() ? v : QJsonValue(it->second);
    }
    if (v.isArray()) {
        QJsonArray a;
        for (const QJsonValue &e : v.toArray())
            a.append(followRenames(e, renamed));
        return a;
    }
    if (v.isObject()) {
        QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it)
            it.value() = followRenames(it.value(), renamed);
        return o;
    }
    return v;
}

QJsonObject withoutChildren(QJsonObject json)
{
    json.remove(QStringLiteral("children"));
    return json;
}

QString pointsLiteral(const QVariantList &points, int dim)
{
    QStringList rows;
    for (int i = 0; i + dim <= points.size(); i += dim) {
        QStringList c;
        for (int k = 0; k < dim; ++k)
            c << ScriptRecorder::pyNumber(points[i + k].toDouble());
        rows << "[" + c.join(", ") + "]";
    }
    return "[" + rows.join(", ") + "]";
}

} // namespace

ScriptRecorder::ScriptRecorder(Project *project, QObject *parent)
    : QObject(parent), m_project(project)
{
    QUndoStack *stack = project->undoStack();
    connect(stack, &QUndoStack::indexChanged, this, &ScriptRecorder::onIndexChanged);
    connect(project, &Project::itemChanged, this, &ScriptRecorder::onItemChanged);
    auto structural = [this] { m_dirty = true; };
    connect(project, &Project::itemInserted, this, structural);
    connect(project, &Project::itemRemoved, this, structural);
    connect(project, &Project::itemMoved, this, structural);
    connect(project, &Project::reset, this, [this] {
        m_origin.clear();
        restart();
    });
    connect(project, &Project::gestureActiveChanged, this, [this](bool active) {
        if (!active && m_dirty)
            process();
    });
    restart();
}

ScriptRecorder::~ScriptRecorder() = default;

void ScriptRecorder::restart()
{
    m_steps.clear();
    m_snapshot.clear();
    m_snapshot = take();
    m_changed.clear();
    m_stepBase.clear();
    m_commands = commands();
    m_index = m_project->undoStack()->index();
    m_floor = m_index;
    m_dirty = false;
    m_lastIsPush = false;
    m_aligned = true;
    m_baseFile = m_project->fileName().isEmpty() ? m_origin : m_project->fileName();
    emit restarted(m_baseFile);
}

void ScriptRecorder::setOrigin(const QString &file)
{
    m_origin = file;
    restart();
}

std::vector<const QUndoCommand *> ScriptRecorder::commands() const
{
    const QUndoStack *s = m_project->undoStack();
    std::vector<const QUndoCommand *> out;
    for (int i = 0; i < s->count(); ++i)
        out.push_back(s->command(i));
    return out;
}

ScriptRecorder::Snapshot ScriptRecorder::take() const
{
    Snapshot s;
    for (Item *item : m_project->items()) {
        // An item that did not change since the last snapshot keeps its entry (a large mesh
        // is not written to JSON again on every edit of another item).
        if (const auto old = m_snapshot.find(item);
            old != m_snapshot.end() && !m_changed.count(item) && old->second.item == item) {
            Entry e = old->second;
            e.name = item->name();
            e.parent = item->parentItem();
            e.row = m_project->rowOf(item);
            s[item] = std::move(e);
            continue;
        }
        Entry e;
        e.item = item;
        e.name = item->name();
        e.parent = item->parentItem();
        e.row = m_project->rowOf(item);
        e.json = withoutChildren(ProjectIO::itemToJson(*item));
        if (const auto *a = qobject_cast<const AttractorItem *>(item))
            for (int set = 0; set < a->controlPointSetCount(); ++set) {
                QVariantList row;
                for (const Point &p : a->controlPoints(set))
                    row += pointRow(p, a->pointDimension());
                e.points.push_back(row);
            }
        // The name is recorded by its own line (renames first, so later lines find the item).
        for (const ParameterInfo &p : item->parameters())
            if (!p.readOnly && p.key != QLatin1String("name"))
                e.parameters[p.key] = item->parameter(p.key);
        s[item] = std::move(e);
    }
    return s;
}

void ScriptRecorder::onItemChanged(Item *item)
{
    m_changed.insert(item);
    m_dirty = true;
}

void ScriptRecorder::onIndexChanged()
{
    // The edits of a drag merge into one step: recorded once, when it ends.
    if (m_project->gestureActive()) {
        m_dirty = true;
        return;
    }
    process();
}

void ScriptRecorder::append(const QString &lines, bool aligned)
{
    m_steps << lines;
    if (!aligned)
        m_aligned = false;
    emit recorded(lines);
}

void ScriptRecorder::process()
{
    const std::vector<const QUndoCommand *> now = commands();
    const QUndoStack *stack = m_project->undoStack();
    const int index = stack->index();
    const bool sameList = now == m_commands;
    if (sameList && index != m_index) {
        // Undo or redo in the window: the same in the script while its steps keep step.
        const bool undo = index < m_index;
        if (m_aligned && index >= m_floor) {
            for (int i = 0; i < std::abs(index - m_index); ++i)
                append(undo ? QStringLiteral("project.undo()") : QStringLiteral("project.redo()"),
                       true);
            m_snapshot = take();
        } else {
            const Snapshot after = take();
            const QStringList lines = diff(m_snapshot, after);
            if (!lines.isEmpty())
                append(block(lines, undo ? tr("Undo") : tr("Redo")), false);
            m_snapshot = after;
        }
        m_lastIsPush = false;
    } else if (sameList) {
        if (m_dirty) {
            const Snapshot after = take();
            if (m_lastIsPush && !m_steps.isEmpty()) {
                // A later edit merged into the last step (or a drag's moves): its lines anew.
                const QStringList lines = diff(m_stepBase, after);
                m_steps.last() = block(lines, stack->text(index - 1));
                emit lastReplaced(m_steps.last());
            } else {
                const QStringList lines = diff(m_snapshot, after);
                if (!lines.isEmpty())
                    append(block(lines, tr("Edit")), false);
            }
            m_snapshot = after;
        }
    } else {
        const Snapshot after = take();
        const QStringList lines = diff(m_snapshot, after);
        if (now.empty()) {
            // The history was cleared (not undone): the script keeps its steps, the window
            // cannot undo below this point any more.
            if (!lines.isEmpty())
                append(block(lines, tr("Edit")), true);
            m_floor = 0;
            m_lastIsPush = false;
        } else if (lines.isEmpty()) {
            // A step that changes nothing a file holds: the script has no step for it.
            m_aligned = false;
            m_lastIsPush = false;
        } else {
            append(block(lines, stack->text(index - 1)), index == int(now.size()));
            m_stepBase = std::move(m_snapshot);
            m_lastIsPush = true;
        }
        m_snapshot = after;
    }
    m_commands = now;
    m_index = index;
    m_dirty = false;
    m_changed.clear();
}

QString ScriptRecorder::block(const QStringList &lines, const QString &text) const
{
    if (lines.size() == 1)
        return lines.first();
    QStringList out{QStringLiteral("with project.edit(%1):").arg(pyString(text))};
    for (const QString &line : lines)
        for (const QString &part : line.split('\n'))
            out << "    " + part;
    return out.join('\n');
}

QStringList ScriptRecorder::diff(const Snapshot &before, const Snapshot &after) const
{
    QStringList lines;
    auto present = [](const Snapshot &s, const Item *item) { return s.count(item) > 0; };
    // Removed items (an item removed with its parent goes with it).
    for (const auto &[item, e] : before)
        if (!present(after, item) && !(e.parent && !present(after, e.parent)))
            lines << QStringLiteral("project.remove(%1)").arg(pyString(e.name));
    // Renamed items, first, so that every later line finds its item by its new name.
    std::map<QString, QString> renamed;
    for (const auto &[item, e] : after)
        if (const auto b = before.find(item); b != before.end() && b->second.name != e.name) {
            lines << QStringLiteral("project.item(%1).name = %2")
                         .arg(pyString(b->second.name), pyString(e.name));
            renamed[b->second.name] = e.name;
        }
    // Moves among the items that stay, placed in their final order.
    {
        std::map<const Item *, std::vector<const Item *>> sim;
        std::vector<std::pair<int, const Item *>> rows;
        for (const auto &[item, e] : before)
            if (present(after, item))
                rows.push_back({e.row, item});
        std::sort(rows.begin(), rows.end(), [&](const auto &x, const auto &y) {
            return x.first < y.first;
        });
        for (const auto &[row, item] : rows)
            sim[before.at(item).parent].push_back(item);
        for (Item *item : m_project->items()) {
            if (!present(before, item))
                continue;
            auto &mine = sim[item->parentItem()];
            int k = 0;
            for (int r = 0; r < m_project->rowOf(item); ++r) {
                const Item *sibling = item->parentItem() ? item->parentItem()->child(r)
                                                         : m_project->child(r);
                if (present(before, sibling))
                    ++k;
            }
            if (k < int(mine.size()) && mine[size_t(k)] == item)
                continue;
            for (auto &[p, list] : sim)
                list.erase(std::remove(list.begin(), list.end(), item), list.end());
            mine.insert(mine.begin() + std::min<size_t>(size_t(k), mine.size()), item);
            const Item *parent = item->parentItem();
            lines << QStringLiteral("project.move(%1, parent=%2, index=%3)")
                         .arg(pyString(item->name()),
                              parent ? pyString(parent->name()) : QStringLiteral("None"))
                         .arg(k);
        }
    }
    // Added items, in tree order, each with its children.
    for (Item *item : m_project->items()) {
        if (present(before, item) || (item->parentItem() && !present(before, item->parentItem())))
            continue;  // stays, or comes with its added parent
        const Item *parent = item->parentItem();
        const int row = m_project->rowOf(item);
        const int siblings = parent ? parent->childCount() : m_project->childCount();
        QString args = pyValue(ProjectIO::itemToJson(*item));
        if (parent)
            args += ", parent=" + pyString(parent->name());
        if (row != siblings - 1)
            args += QStringLiteral(", index=%1").arg(row);
        lines << QStringLiteral("project.add(%1)").arg(args);
    }
    // The inputs of the items that stay.
    for (Item *item : m_project->items())
        if (const auto b = before.find(item); b != before.end())
            lines += itemLines(b->second, after.at(item), renamed);
    return lines;
}

QStringList ScriptRecorder::itemLines(const Entry &before, const Entry &after,
                                      const std::map<QString, QString> &renamed) const
{
    QJsonObject start = followRenames(before.json, renamed).toObject();
    start["name"] = after.name;
    if (start == after.json)
        return {};
    const QString ref = QStringLiteral("project.item(%1)").arg(pyString(after.name));
    QStringList lines;
    std::unique_ptr<Item> scratch = ProjectIO::itemFromJson(start, nullptr);
    bool replayed = scratch != nullptr;
    // The Properties dock's parameters, choices (which change the others) first.
    if (replayed) {
        std::vector<ParameterInfo> changed;
        for (const ParameterInfo &p : scratch->parameters()) {
            const auto b = before.parameters.find(p.key);
            const auto a = after.parameters.find(p.key);
            if (b != before.parameters.end() && a != after.parameters.end()
                && b->second != a->second)
                changed.push_back(p);
        }
        std::stable_partition(changed.begin(), changed.end(), [](const ParameterInfo &p) {
            return p.type == ParameterInfo::Type::Choice;
        });
        for (const ParameterInfo &p : changed) {
            const QVariant v = after.parameters.at(p.key);
            if (!scratch->setParameter(p.key, v)) {
                replayed = false;
                break;
            }
            QString literal;
            using T = ParameterInfo::Type;
            switch (p.type) {
            case T::Real: {
                literal = pyNumber(v.toDouble());
                if (!literal.contains('.') && !literal.contains('e') && !literal.contains('n'))
                    literal += ".0";
                break;
            }
            case T::Integer:
                literal = QString::number(v.toInt());
                break;
            case T::Choice:
                // The index (the texts are translated); the text as a comment.
                literal = QString::number(v.toInt());
                if (v.toInt() >= 0 && v.toInt() < p.choices.size())
                    literal += QStringLiteral("  # ") + p.choices[v.toInt()];
                break;
            case T::Complex:
                literal = QStringLiteral("complex(%1, %2)")
                              .arg(pyNumber(v.toPointF().x()), pyNumber(v.toPointF().y()));
                break;
            case T::Bool:
                literal = v.toBool() ? QStringLiteral("True") : QStringLiteral("False");
                break;
            case T::Text:
                literal = pyString(v.toString());
                break;
            }
            lines << QStringLiteral("%1.parameters[%2] = %3").arg(ref, pyString(p.key), literal);
        }
    }
    // Control points: a point moved, or the whole set.
    auto *points = replayed ? qobject_cast<AttractorItem *>(scratch.get()) : nullptr;
    if (points && before.points.size() == after.points.size()) {
        const int dim = points->pointDimension();
        for (size_t set = 0; set < after.points.size(); ++set) {
            const QVariantList &b = before.points[set], &a = after.points[set];
            if (b == a)
                continue;
            const QString target = set == 0 ? ref + ".control_points"
                                            : QStringLiteral("%1.point_sets[%2]").arg(ref).arg(set);
            std::vector<int> moved;
            if (a.size() == b.size())
                for (int i = 0; i < a.size() / dim; ++i)
                    if (a.mid(i * dim, dim) != b.mid(i * dim, dim))
                        moved.push_back(i);
            auto point = [&](int i) {
                Point p;
                p.x = a[i * dim].toDouble();
                p.y = a[i * dim + 1].toDouble();
                if (dim == 3)
                    p.z = a[i * dim + 2].toDouble();
                return p;
            };
            if (a.size() == b.size() && moved.size() <= 4) {
                for (int i : moved) {
                    points->moveControlPoint(i, point(i), 0, int(set));
                    lines << QStringLiteral("%1[%2] = %3")
                                 .arg(target)
                                 .arg(i)
                                 .arg(pointsLiteral(a.mid(i * dim, dim), dim).mid(1).chopped(1));
                }
            } else {
                const int n = int(a.size()) / dim, old = int(b.size()) / dim;
                std::map<int, Point> moves;
                for (int i = 0; i < std::min(n, old); ++i)
                    moves[i] = point(i);
                points->moveControlPoints(moves, 0, int(set));
                for (int i = old; i < n; ++i)
                    points->insertControlPoint(i, point(i), int(set));
                std::vector<int> gone;
                for (int i = n; i < old; ++i)
                    gone.push_back(i);
                if (!gone.empty())
                    points->removeControlPoints(gone, int(set));
                lines << (set == 0 ? QStringLiteral("%1 = %2").arg(target, pointsLiteral(a, dim))
                                   : QStringLiteral("%1.assign(%2)")
                                         .arg(target, pointsLiteral(a, dim)));
            }
        }
    }
    // What the lines above do not say: the remaining fields, in one update.
    QJsonObject reached = start;
    if (replayed)
        reached = withoutChildren(ProjectIO::itemToJson(*scratch));
    else
        lines.clear();
    QJsonObject fields;
    QStringList keys = after.json.keys();
    for (const QString &k : reached.keys())
        if (!keys.contains(k))
            keys << k;
    for (const QString &k : keys)
        if (reached.value(k) != after.json.value(k) && k != "type" && k != "name")
            fields[k] = after.json.value(k);
    if (!fields.isEmpty())
        lines << QStringLiteral("%1.update(%2)").arg(ref, pyValue(fields));
    return lines;
}

QString ScriptRecorder::pyString(const QString &s)
{
    const QByteArray json = QJsonDocument(QJsonArray{s}).toJson(QJsonDocument::Compact);
    return QString::fromUtf8(json.mid(1, json.size() - 2));
}

QString ScriptRecorder::pyNumber(double v)
{
    if (!std::isfinite(v))
        return v != v ? QStringLiteral("float(\"nan\")")
                      : (v > 0 ? QStringLiteral("float(\"inf\")")
                               : QStringLiteral("-float(\"inf\")"));
    return QString::number(v, 'g', QLocale::FloatingPointShortest);
}

QString ScriptRecorder::pyValue(const QJsonValue &v)
{
    switch (v.type()) {
    case QJsonValue::Null:
    case QJsonValue::Undefined:
        return QStringLiteral("None");
    case QJsonValue::Bool:
        return v.toBool() ? QStringLiteral("True") : QStringLiteral("False");
    case QJsonValue::Double: {
        // Whole numbers as Python ints ("samples": 100000, not 1e+05): the file writes both
        // the same way.
        const double d = v.toDouble();
        if (d == std::floor(d) && std::abs(d) < 1e15)
            return QString::number(qint64(d));
        return pyNumber(d);
    }
    case QJsonValue::String:
        return pyString(v.toString());
    case QJsonValue::Array: {
        QStringList parts;
        for (const QJsonValue &e : v.toArray())
            parts << pyValue(e);
        return "[" + parts.join(", ") + "]";
    }
    case QJsonValue::Object: {
        QStringList parts;
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it)
            parts << pyString(it.key()) + ": " + pyValue(it.value());
        return "{" + parts.join(", ") + "}";
    }
    }
    return QStringLiteral("None");
}

QString ScriptRecorder::script() const
{
    QStringList out;
    const QString version = QCoreApplication::applicationVersion();
    out << QStringLiteral("# Attractor Workbench%1: the edits of %2, recorded %3.")
               .arg(version.isEmpty() ? QString() : " " + version,
                    m_baseFile.isEmpty() ? QStringLiteral("a new project")
                                         : "\"" + m_baseFile + "\"",
                    QDateTime::currentDateTime().toString(Qt::ISODate));
    out << QStringLiteral("# Replays them:  python3 THIS.py [PROJECT.awb [OUT.awb]]");
    out << QStringLiteral("#   PROJECT.awb  the file they start from (default: the one recorded)");
    out << QStringLiteral("#   OUT.awb      where the result is saved (default: not saved)");
    out << QStringLiteral("import sys") << QString()
        << QStringLiteral("import attractor_workbench as awb") << QString();
    if (m_baseFile.isEmpty())
        out << QStringLiteral("project = awb.open(sys.argv[1]) if len(sys.argv) > 1 else "
                              "awb.Project()");
    else
        out << QStringLiteral("project = awb.open(sys.argv[1] if len(sys.argv) > 1 else %1)")
                   .arg(pyString(m_baseFile));
    out << QString();
    out += m_steps;
    out << QString() << QStringLiteral("if len(sys.argv) > 2:")
        << QStringLiteral("    project.save(sys.argv[2])");
    return out.join('\n') + '\n';
}

} // namespace awb
