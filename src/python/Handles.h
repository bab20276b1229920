#pragma once
// The objects behind attractor_workbench's Python classes (internal to src/python): a project
// (owned by Python, or borrowed from the application), an item of it, and the two views of an
// item's inputs that behave like Python containers (its control points, its parameters).

#include <QPointer>
#include <QString>

#include <memory>
#include <stdexcept>
#include <string>

namespace awb {
class AttractorItem;
class Item;
class Project;
} // namespace awb

namespace awb::python {

// Raised for everything the user did wrong; Python sees attractor_workbench.Error (a
// ValueError) with the application's message.
struct Error : std::runtime_error {
    explicit Error(const QString &message) : std::runtime_error(message.toStdString()) {}
};

struct ProjectHandle {
    std::unique_ptr<Project> owned;  // null when borrowed
    QPointer<Project> project;
    int openEdits = 0;  // `with project.edit()` blocks open
    ProjectHandle();
    explicit ProjectHandle(Project *borrowed);
    ~ProjectHandle();
    Project &get() const;
};
using ProjectRef = std::shared_ptr<ProjectHandle>;

// An item, found again by name when its object left the project (an item replaced by
// Item.update(), or removed and brought back by undo).
struct ItemHandle {
    ItemHandle(ProjectRef of, Item *which);
    ProjectRef project;
    QPointer<Item> item;
    QString name;
    QPointer<Item> previous;  // the item update() replaced (back after an undo)
    Item &get() const;
    AttractorItem &attractor() const;
};

struct PointsHandle {
    ItemHandle item;
    int set = 0;
};

struct ParametersHandle {
    ItemHandle item;
};

} // namespace awb::python
