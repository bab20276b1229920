// attractor_workbench.Project: a document of the model (model/Project.h), its items, its one
// undo stack and its file.

#include "python/Internal.h"

#include "model/Item.h"
#include "model/Project.h"
#include "model/ProjectIO.h"
#include "model/ScriptRecorder.h"


namespace awb::python {

namespace {

ItemHandle handleOf(const ProjectRef &p, Item *item) { return ItemHandle(p, item); }

Item *resolveItem(const ProjectRef &p, const py::handle &which, const char *what)
{
    if (which.is_none())
        return nullptr;
    if (py::isinstance<ItemHandle>(which)) {
        const auto &h = which.cast<const ItemHandle &>();
        if (h.project->project != p->project)
            throw Error(QString("%1: the item belongs to another project").arg(what));
        return &h.get();
    }
    const QString name = toQString(which, what);
    Item *item = p->get().findItem(name);
    if (!item)
        throw Error(QString("no item named '%1'").arg(name));
    return item;
}

// A recording of the project's edits as Python (model/ScriptRecorder, as the console's).
struct RecordingHandle {
    ProjectRef project;
    std::shared_ptr<ScriptRecorder> recorder;
};

// One undo step of everything done inside `with project.edit("text"):`.
struct EditScope {
    ProjectRef project;
    QString text;
    bool open = false;
};

} // namespace

void defineProjectClass(py::module_ &m)
{
    py::class_<EditScope>(m, "_Edit", "What Project.edit() returns: a context manager.")
        .def("__enter__",
             [](EditScope &e) {
                 if (e.open)
                     throw Error("this edit block is open already");
                 e.project->get().beginCompound(e.text);
                 e.open = true;
                 ++e.project->openEdits;
                 return &e;
             })
        .def("__exit__", [](EditScope &e, py::args) {
            if (e.open) {
                e.project->get().endCompound();
                --e.project->openEdits;
            }
            e.open = false;
            return false;
        });

    py::class_<RecordingHandle>(
        m, "Recording",
        "The edits of a project since record() (or restart()) as the Python lines that make "
        "them, as the application's console records them (docs/python.md: the format).")
        .def_property_readonly(
            "steps",
            [](const RecordingHandle &r) {
                py::list l;
                for (const QString &s : r.recorder->steps())
                    l.append(toPy(s));
                return l;
            },
            "One str per undo step (a block `with project.edit(...):` when it has several "
            "lines).")
        .def(
            "script", [](const RecordingHandle &r) { return toPy(r.recorder->script()); },
            "script() -> str: a script that replays the steps: `python3 SCRIPT [PROJECT.awb "
            "[OUT.awb]]`.")
        .def(
            "restart", [](const RecordingHandle &r) { r.recorder->restart(); },
            "restart(): forgets the steps; the project as it is now is the start.")
        .def_property_readonly(
            "base_file", [](const RecordingHandle &r) { return toPy(r.recorder->baseFile()); },
            "The file the recording starts from ('' for a new project).");

    py::class_<ProjectHandle, ProjectRef>(
        m, "Project",
        "A project: an ordered tree of items, one undo stack every edit goes through, and the "
        "file it was opened from or saved to. Project() is an empty project; open(path) reads "
        "one.")
        .def(py::init([] { return std::make_shared<ProjectHandle>(); }))
        .def_property_readonly(
            "items",
            [](const ProjectRef &p) {
                py::list l;
                for (Item *item : p->get().items())
                    l.append(py::cast(handleOf(p, item)));
                return l;
            },
            "Every item, depth first in tree order (an eigenvalue plot after the curve it "
            "analyses).")
        .def(
            "item",
            [](const ProjectRef &p, const py::object &name) {
                if (name.is_none())
                    throw Error("item(): which item? give its name");
                return handleOf(p, resolveItem(p, name, "name"));
            },
            py::arg("name"), "item(name) -> Item\n\nThe item of that name; Error if none.")
        .def("__getitem__",
             [](const ProjectRef &p, const py::object &name) {
                 if (name.is_none())
                     throw py::key_error("None is not an item's name");
                 return handleOf(p, resolveItem(p, name, "name"));
             })
        .def("__contains__",
             [](const ProjectRef &p, const py::object &name) {
                 return py::isinstance<py::str>(name)
                        && p->get().findItem(toQString(name, "name")) != nullptr;
             })
        .def("__len__", [](const ProjectRef &p) { return p->get().items().size(); })
        .def("__iter__",
             [](const ProjectRef &p) {
                 py::list l;
                 for (Item *item : p->get().items())
                     l.append(py::cast(handleOf(p, item)));
                 return py::iter(l);
             })
        .def(
            "add",
            [](const ProjectRef &p, const py::object &json, const py::object &parent, int index) {
                QString why;
                std::unique_ptr<Item> item =
                    ProjectIO::itemFromJson(toJsonObject(json, "item"), &why);
                if (!item)
                    throw Error("add(): " + why);
                Item *under = resolveItem(p, parent, "parent");
                Project &project = p->get();
                if (index < -1 || index > project.childCount(under))
                    throw Error(QString("index %1 is out of range 0..%2")
                                    .arg(index)
                                    .arg(project.childCount(under)));
                return handleOf(p, project.addItem(std::move(item), under, index));
            },
            py::arg("item"), py::arg("parent") = py::none(), py::arg("index") = -1,
            "add(item, parent=None, index=-1) -> Item\n\nAdds an item given as its JSON object "
            "(a dict as in the project file, with \"type\"), at the end or at `index` under "
            "`parent` (an Item or a name; None: the top level). One undo step. A name already "
            "taken gets a number (\"Koch 2\").")
        .def(
            "remove",
            [](const ProjectRef &p, const py::object &which) {
                Item *item = resolveItem(p, which, "item");
                if (!item)
                    throw Error("remove(): which item?");
                p->get().removeItem(item);
            },
            py::arg("item"), "remove(item)\n\nRemoves an item (an Item or a name) and its "
                             "children. One undo step.")
        .def(
            "move",
            [](const ProjectRef &p, const py::object &which, const py::object &parent,
               int index) {
                Item *item = resolveItem(p, which, "item");
                Item *under = resolveItem(p, parent, "parent");
                if (!item || !p->get().moveItem(item, under, index))
                    throw Error("the move is refused: into the item itself or one of its "
                                "children, out of range, or changing nothing");
            },
            py::arg("item"), py::arg("parent") = py::none(), py::arg("index") = 0,
            "move(item, parent=None, index=0)\n\nMoves an item to row `index` under `parent`. "
            "One undo step.")
        .def(
            "save",
            [](const ProjectRef &p, const py::object &path) {
                QString why;
                Project &project = p->get();
                bool ok = false;
                if (path.is_none()) {
                    if (project.fileName().isEmpty())
                        throw Error("save(): the project has no file yet: give a path");
                    ok = project.save(&why);
                } else {
                    ok = project.saveAs(pathArg(path, "save()"), &why);
                }
                if (!ok)
                    throw Error(why);
            },
            py::arg("path") = py::none(),
            "save(path=None)\n\nWrites the project (atomically: a failed save leaves the old "
            "file) to `path`, or to its file.")
        .def(
            "undo",
            [](const ProjectRef &p) {
                if (p->openEdits > 0)
                    throw Error("undo() inside `with project.edit(...)`: the block becomes one "
                                "step when it ends; undo after it");
                QUndoStack *s = p->get().undoStack();
                if (!s->canUndo())
                    throw Error("nothing to undo");
                s->undo();
            },
            "undo()\n\nUndoes the last edit (of a script or of the window).")
        .def(
            "redo",
            [](const ProjectRef &p) {
                if (p->openEdits > 0)
                    throw Error("redo() inside `with project.edit(...)`: the block becomes one "
                                "step when it ends; redo after it");
                QUndoStack *s = p->get().undoStack();
                if (!s->canRedo())
                    throw Error("nothing to redo");
                s->redo();
            },
            "redo()\n\nRedoes the last undone edit.")
        .def_property_readonly(
            "can_undo", [](const ProjectRef &p) { return p->get().undoStack()->canUndo(); },
            "Whether there is an edit to undo.")
        .def_property_readonly(
            "can_redo", [](const ProjectRef &p) { return p->get().undoStack()->canRedo(); },
            "Whether there is an undone edit to redo.")
        .def_property_readonly(
            "undo_text",
            [](const ProjectRef &p) { return toPy(p->get().undoStack()->undoText()); },
            "The name of the edit undo() would undo (as in Edit > Undo).")
        .def(
            "edit",
            [](const ProjectRef &p, const py::object &text) {
                return EditScope{p, toQString(text, "text"), false};
            },
            py::arg("text") = "Script",
            "edit(text='Script') -> context manager\n\n`with project.edit(\"Sweep\"): ...` makes "
            "the edits of the block one undo step.")
        .def(
            "record",
            [](const ProjectRef &p) {
                return RecordingHandle{p, std::make_shared<ScriptRecorder>(&p->get())};
            },
            "record() -> Recording\n\nStarts recording every edit of the project (from "
            "scripts and, in the console, from the window) as Python lines.")
        .def_property_readonly(
            "modified", [](const ProjectRef &p) { return p->get().isModified(); },
            "Whether there are edits since the last open or save.")
        .def_property_readonly(
            "file_name", [](const ProjectRef &p) { return toPy(p->get().fileName()); },
            "The file the project was opened from or saved to ('' for none).")
        .def(
            "to_json", [](const ProjectRef &p) { return toPy(ProjectIO::toJson(p->get())); },
            "to_json() -> dict\n\nThe project as the JSON object its file holds.")
        .def(
            "problems",
            [](const ProjectRef &p) {
                py::list l;
                for (const QString &s : p->get().problems())
                    l.append(toPy(s));
                return l;
            },
            "problems() -> list of str\n\nEvery item whose IFS cannot be computed, as "
            "\"name: reason\" (what attractor-cli check reports).")
        .def("__repr__", [](const ProjectRef &p) {
            const Project &project = p->get();
            return QString("<attractor_workbench.Project %1, %2 items%3>")
                .arg(project.fileName().isEmpty() ? QString("(no file)")
                                                  : "'" + project.fileName() + "'")
                .arg(project.items().size())
                .arg(project.isModified() ? ", modified" : "")
                .toStdString();
        });
}

} // namespace awb::python
