#pragma once
// Declared properties (layer 2, model). An item kind declares each of its inputs once -- key,
// type, range and validation, label and help, where the file keeps it, when it applies,
// whether an edit merges over a drag -- and gets from that declaration its file form (write,
// read; the loader keeps the fields it does not know), undoable edits with the refusal
// message, the Properties dock's editors, Python's item.parameters, the recorder's lines and
// `attractor-cli set`. FreeCAD's property containers are the model: an item kind is its
// declaration plus its maths (docs/adding-an-item-kind.md walks through one).
//
// The inputs of an item come in parts: values with exact equality that are checked and stored
// as a whole, by one undo command (a curve's scheme, the start set, the style). A property is
// one field of a part. Reading a file builds each part from its fields, checks it and stores
// it; an edit copies the part, changes the field and stores the copy through the part's
// checked setter -- one undo step, or one per drag.
//
// Three headers: this one is the table as the faces use it (the dock, Python, the recorder,
// the CLI); PropertyPart.h the parts and fields; PropertyDeclaration.h the builders the item
// kinds declare with. Item.h knows the table by name only.

#include "model/Item.h"

#include <QJsonObject>
#include <QJsonValue>

#include <memory>
#include <optional>
#include <vector>

namespace awb {

class FieldReader;

// A declared property as `attractor-cli set --list` and the docs show it: its parameter view
// (scalars) or its structured type, its place in the file and its current value there.
struct PropertyDescription {
    ParameterInfo info;   // key, label, group, tip, range, choices (translated)
    QString typeName;     // "real", "integer", "choice", ..., or "points", "matrices", ...
    QStringList spellings;  // a choice's spellings in the file (and on the command line)
    QString json;         // the field's path in the item's JSON object ("" when not saved)
    QJsonValue value;     // the current value in its file form
    bool scalar = true;   // an entry of item.parameters (structured values take JSON)
};

// ---- the type-erased part ---------------------------------------------------------------------

class PartBase {
public:
    virtual ~PartBase() = default;
    // Head parts (the name) come first in the dock and the file's reading order, then the
    // kind's own, the inputs every attractor has (start set, algorithm), then the tail
    // (style, animation).
    enum class Place { Head, Kind, Inputs, Tail };
    Place place = Place::Kind;

    virtual void parameters(const Item &item, QList<ParameterInfo> &out) const = 0;
    virtual std::optional<QVariant> value(const Item &item, const QString &key) const = 0;
    // nullopt: the key is none of this part's present parameters.
    virtual std::optional<bool> set(Item &item, const QString &key, const QVariant &value,
                                    int gesture, QString *error) const = 0;
    virtual std::optional<bool> setJson(Item &item, const QString &key, const QJsonValue &value,
                                        QString *error) const = 0;
    virtual void write(const Item &item, QJsonObject &json) const = 0;
    virtual void read(Item &item, const FieldReader &fields) const = 0;
    // Stores `from`'s value of this part into `to` through the checked setter (an update from
    // JSON); false with *error when refused.
    virtual bool transfer(const Item &from, Item &to, QString *error) const = 0;
    virtual void describe(const Item &item, QList<PropertyDescription> &out) const = 0;
    // The top-level JSON keys the part's fields live under.
    virtual QStringList jsonKeys() const = 0;
    virtual bool enabled(const Item &item, const QString &key) const = 0;
};

// ---- the table --------------------------------------------------------------------------------

// The declared properties of one item kind: its parts in order (the base kinds' first, as the
// declaration placed them). Built once per kind (a function-local static), shared by all its
// items.
class PropertyTable {
public:
    PropertyTable() = default;

    // The present scalar properties, elements expanded: the Properties dock's rows, Python's
    // item.parameters, what the recorder compares and animation may key.
    QList<ParameterInfo> parameters(const Item &item) const;
    // Invalid QVariant for an unknown key.
    QVariant value(const Item &item, const QString &key) const;
    bool enabled(const Item &item, const QString &key) const;
    // Undoable, one step; false with *error saying why.
    bool set(Item &item, const QString &key, const QVariant &value, int gesture,
             QString *error) const;
    // A property from its file form (structured values: points, matrices, ...), one undo step.
    bool setJson(Item &item, const QString &key, const QJsonValue &value, QString *error) const;
    // A scalar property from text as typed on a command line: numbers (3/8 and sqrt(3) too),
    // a choice's index, file spelling or text, true/false, a complex "re,im"; structured ones
    // as JSON.
    bool setText(Item &item, const QString &key, const QString &text, QString *error) const;

    void write(const Item &item, QJsonObject &json) const;
    void read(Item &item, const FieldReader &fields) const;
    // Changes the item's fields named in `patch` (its JSON form) as `ProjectIO::itemFromJson`
    // of the merged object would read them, each changed part through its checked setter, in
    // one undo step. False with *error (nothing changed) when the merged item does not read.
    bool update(Item &item, const QJsonObject &patch, QString *error) const;
    // Every present property with its current value.
    QList<PropertyDescription> describe(const Item &item) const;

    const std::vector<std::shared_ptr<const PartBase>> &parts() const { return m_parts; }

private:
    template <class T>
    friend class Declaration;
    std::vector<std::shared_ptr<const PartBase>> m_parts;
};

} // namespace awb
