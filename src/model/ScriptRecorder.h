#pragma once
// The recording of a project's edits as Python (layer 2, model), as ParaView traces and FreeCAD
// records macros: every undo step of the project, whoever made it (a drag in a view, the
// Properties dock, a menu, a script), becomes the attractor_workbench lines that make it, e.g.
//   project.item("Fig. 2").control_points[3] = [1.0, 2.5]
//   project.item("Fig. 2").parameters["scheme.omega"] = 0.1
//   project.undo()
// The lines come from the document itself, not from the code that edited it: after each step
// the recorder compares the items that changed with its snapshot of them (names, places,
// control points, the Properties dock's parameters, the remaining JSON fields) and writes the
// shortest lines whose replay on the snapshot gives the new JSON (checked on a copy of the item:
// what the lines cannot say goes into one item.update({...})). A step of several lines is one
// `with project.edit(...)` block, so that the script's undo stack keeps step with the
// window's, and undo and redo are recorded as project.undo() and project.redo(). The edits of
// one drag (a gesture) are one step, recorded when the drag ends.
// Opening or clearing the document starts a new recording; script() is a replayable file.

#include <QJsonObject>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QVariant>

#include <map>
#include <set>
#include <vector>

class QUndoCommand;

namespace awb {

class Item;
class Project;

class ScriptRecorder : public QObject {
    Q_OBJECT
public:
    explicit ScriptRecorder(Project *project, QObject *parent = nullptr);
    ~ScriptRecorder() override;

    // The lines since the recording started (one entry per undo step; an entry may hold
    // several lines).
    const QStringList &steps() const { return m_steps; }
    // The file the recording starts from (the document's file at the last open; "" for a new
    // document).
    QString baseFile() const { return m_baseFile; }
    // A script that replays the steps: `python3 SCRIPT [PROJECT.awb [OUT.awb]]` opens
    // PROJECT.awb (default: baseFile()), replays, and saves to OUT.awb when given.
    QString script() const;
    // Forgets the steps and takes the document as it is now as the start.
    void restart();
    // The document was opened as a copy of `file` (an example of the gallery): the recording
    // starts from that file, as the script's default, until another document replaces it.
    void setOrigin(const QString &file);

    // Python literals, shared with the tests: a string, a number (shortest text that reads
    // back to the same double), a JSON value (dicts, lists, True, None).
    static QString pyString(const QString &s);
    static QString pyNumber(double v);
    static QString pyValue(const QJsonValue &v);

signals:
    // A new step: its lines (several lines joined by '\n').
    void recorded(const QString &lines);
    // The recording starts again (the document was opened, cleared, or Clear Recording).
    void restarted(const QString &baseFile);
    // The last step's lines changed (a later edit merged into the same undo step).
    void lastReplaced(const QString &lines);

private:
    QString m_origin;
    struct Entry {
        QPointer<Item> item;
        QString name;
        const Item *parent = nullptr;
        int row = 0;
        QJsonObject json;  // without "children"
        std::vector<QVariantList> points;  // per set: x, y(, z) per point
        std::map<QString, QVariant> parameters;
    };
    using Snapshot = std::map<const Item *, Entry>;

    Snapshot take() const;
    void onIndexChanged();
    void onItemChanged(Item *item);
    void process();
    QStringList diff(const Snapshot &before, const Snapshot &after) const;
    QStringList itemLines(const Entry &before, const Entry &after,
                          const std::map<QString, QString> &renamed) const;
    QString block(const QStringList &lines, const QString &text) const;
    std::vector<const QUndoCommand *> commands() const;
    void append(const QString &lines, bool aligned);

    Project *m_project;
    Snapshot m_snapshot;      // the document after the last recorded step
    Snapshot m_stepBase;      // the document before the last recorded step (for merges)
    std::set<const Item *> m_changed;  // items whose inputs changed since the last snapshot
    std::vector<const QUndoCommand *> m_commands;
    int m_index = 0;
    int m_floor = 0;          // the stack's index when the recording started
    bool m_dirty = false;
    bool m_lastIsPush = false;
    bool m_aligned = true;    // the script's undo stack has one step per window step
    QStringList m_steps;
    QString m_baseFile;
};

} // namespace awb
