#pragma once
// Helpers shared by the tests of the item kinds (test_<kind>_item.cpp): load a project from
// JSON text, expect a load error, and check that saving is stable.

#include "model/AttractorItem.h"
#include "model/ProjectIO.h"
#include "model/PropertyTable.h"

#include "TestProjects.h"

namespace awb::test {

inline QByteArray projectJson(const QByteArray &items)
{
    return R"({"format": "attractor-workbench", "version": 1, "items": [)" + items + "]}";
}

// Parses `items` (the JSON of the items, comma-separated) into `project`; false on error.
inline bool load(Project &project, const QByteArray &items, QString *error = nullptr)
{
    ProjectData data;
    QString message;
    if (!ProjectIO::parse(projectJson(items), "t.awb", &data, &message)) {
        if (error)
            *error = message;
        return false;
    }
    project.adopt(std::move(data), {}, false);
    return true;
}

// The load error of one item, e.g. `t.awb: item 1 ("x"): field "preset": missing`.
inline QString loadError(const QByteArray &items)
{
    Project p;
    QString error;
    return load(p, items, &error) ? QString() : error;
}

// Save -> load -> save gives the same bytes.
inline bool reloadsIdentically(const Project &project)
{
    ProjectData data;
    QString error;
    const QByteArray first = project.serialize();
    if (!ProjectIO::parse(first, "t.awb", &data, &error))
        return false;
    Project again;
    again.adopt(std::move(data), {}, false);
    return again.serialize() == first;
}

// The parameters an item kind declares itself: without the name, start set, algorithm and
// style every item has (Item::itemProperties(), AttractorItem::attractorProperties()).
inline QList<ParameterInfo> ownParameters(const Item &item)
{
    const PropertyTable &base = qobject_cast<const AttractorItem *>(&item)
                                    ? AttractorItem::attractorProperties()
                                    : Item::itemProperties();
    QStringList shared;
    for (const ParameterInfo &p : base.parameters(item))
        shared << p.key;
    QList<ParameterInfo> own;
    for (const ParameterInfo &p : item.parameters())
        if (!shared.contains(p.key))
            own << p;
    return own;
}

} // namespace awb::test
