#pragma once
// The base of every document item (layer 2, model). An item holds only inputs: its name, its
// display style and whatever its kind adds (scheme, control points, ...). Derived data
// (matrices, IFS, spectra) lives in DerivedCache members, is recomputed on first use after an
// edit and is never saved. Items form an ordered tree owned by the Project; every user edit goes
// through an undo command on the project's stack (STYLE.md §5-6). An item that is not in a
// project (being built, or loaded) applies its setters directly.

#include "model/Animation.h"
#include "model/ItemValues.h"
#include "model/Parameters.h"

#include <QJsonObject>
#include <QObject>

#include <functional>
#include <memory>
#include <vector>

class QUndoCommand;

namespace awb {

class FieldReader;
class Project;
class PropertyTable;
template <class>
class Declaration;

// A derived value computed lazily from an item's inputs, or the reason it could not be
// computed (the core's InputError message). Owned by the item, dropped on every edit.
template <class T>
class DerivedCache {
public:
    // Computes on first use; `compute` returns T or throws (InputError / std::exception).
    template <class Compute>
    std::shared_ptr<const T> get(Compute &&compute) const
    {
        if (m_valid)
            return m_value;
        if (m_computing) // an item that (indirectly) reads itself
            return fail(QCoreApplication::translate("awb::Item", "circular reference"));
        m_computing = true;
        try {
            m_value = std::make_shared<const T>(compute());
            m_error.clear();
        } catch (const std::bad_alloc &) {
            m_value.reset();
            m_error = QCoreApplication::translate(
                "awb::Item", "there is not enough memory to compute it");
        } catch (const std::exception &e) {
            m_value.reset();
            m_error = QString::fromStdString(e.what());
        }
        m_computing = false;
        m_valid = true;
        return m_value;
    }
    // Empty when the last computation succeeded (or nothing was computed yet).
    const QString &error() const { return m_error; }
    // Drops the cached value; true when there was one (value or error) to drop.
    bool drop()
    {
        const bool was = m_valid;
        m_valid = false;
        m_value.reset();
        m_error.clear();
        return was;
    }

private:
    std::shared_ptr<const T> fail(const QString &message) const
    {
        m_error = message;
        return nullptr;
    }
    mutable std::shared_ptr<const T> m_value;
    mutable QString m_error;
    mutable bool m_valid = false;
    mutable bool m_computing = false;
};

class Item : public QObject {
    Q_OBJECT
public:
    ~Item() override;

    // The JSON "type" of the item kind ("subdivision-curve") and its translated display name.
    virtual QString type() const = 0;
    virtual QString typeName() const = 0;

    QString name() const { return m_name; }
    // Undoable. Refused (false) for an empty name or one another item of the project has;
    // items that refer to this one by name are updated in the same undo step.
    bool setName(const QString &name);

    const StyleSpec &style() const { return m_style; }
    MaybeProblem checkStyle(const StyleSpec &style) const { return style.check(); }
    // Undoable; refused when checkStyle() complains. Edits sharing a nonzero gesture id
    // (Project::beginGesture) merge into one undo step.
    bool setStyle(const StyleSpec &style, int gesture = 0);

    // Keyframed parameters (Animation.h). Undoable, one step; refused (false, *error says why)
    // when animationProblem() objects. An empty spec removes the animation.
    const AnimationSpec &animation() const { return m_animation; }
    bool setAnimation(const AnimationSpec &animation, QString *error = nullptr);
    // animationProblem() of a spec, its field in the message; none for an empty spec.
    MaybeProblem checkAnimation(const AnimationSpec &animation) const;

    // Position in the tree. Top-level items have no parent item.
    Project *project() const { return m_project; }
    Item *parentItem() const { return m_parent; }
    int childCount() const { return int(m_children.size()); }
    Item *child(int row) const;
    int indexOfChild(const Item *child) const;
    bool isAncestorOf(const Item *other) const;

    // Increases with every input edit (undo and redo included): a key for views' caches.
    quint64 generation() const { return m_generation; }

    // Names of the items this one reads (an eigenvalue plot reads its source). The project
    // recomputes this item when one of them changes and keeps the names on rename.
    virtual QStringList references() const { return {}; }
    // Why this item's derived data cannot be computed ("" when it can, or has none).
    virtual QString derivedError() const { return {}; }

    // ---- declared properties (PropertyTable.h): every input the item saves, declared once by
    // its kind with key, type, range, texts and place in the file. The table of Item itself
    // holds the name, the style and the animation; each kind adds its own.
    virtual const PropertyTable &properties() const;
    static const PropertyTable &itemProperties();

    // The scalar properties that apply now, by key ("scheme.omega", "style.point_size"):
    // the Properties dock's rows, Python's item.parameters, what animations key. The list
    // depends on the state (ω only for the four-point scheme).
    QList<ParameterInfo> parameters() const;
    // Invalid QVariant for an unknown key.
    QVariant parameter(const QString &key) const;
    // Undoable, one step (edits sharing a nonzero gesture merge where the property merges).
    // False when the key is unknown or the value refused; *error then says why, in words for
    // the user.
    bool setParameter(const QString &key, const QVariant &value, int gesture = 0,
                      QString *error = nullptr);

    // Serialization, from the declaration: the unknown fields, then every part. "type" and
    // "children" are handled by ProjectIO. read() throws LoadError.
    void write(QJsonObject &json) const;
    void read(const FieldReader &fields);
    // The fields of a file written by an older version, in this version's form (ProjectIO
    // reads these); the default keeps them as they are.
    virtual QJsonObject upgradedFields(const QJsonObject &json) const { return json; }
    // Checks that need all fields read (e.g. depth against the number of maps). Throws
    // LoadError.
    virtual void checkLoaded(const FieldReader &fields) const;

    // Fields of the file this version does not know: written back unchanged.
    const QJsonObject &unknownFields() const { return m_unknownFields; }

signals:
    void nameChanged();
    void styleChanged();
    void animationChanged();
    // Any input of this item changed (after the property's own signal).
    void changed();
    // Cached derived data was dropped: views showing it should ask again.
    void derivedChanged();

public:
    // While one is alive, the item's property edits are named `text` on the undo stack: a
    // declared field's edit (the Properties dock, Python, `set`) names the field, not the part
    // that holds it ("Change Gamma of flame", not "Change flame of flame").
    class EditName {
    public:
        EditName(Item &item, const QString &text) : m_item(item), m_before(item.m_editName)
        {
            item.m_editName = text;
        }
        ~EditName() { m_item.m_editName = m_before; }
        EditName(const EditName &) = delete;
        EditName &operator=(const EditName &) = delete;

    private:
        Item &m_item;
        QString m_before;
    };

protected:
    explicit Item(const QString &defaultName);

    // The property template (Commands.h): skips a no-op change, otherwise runs a
    // PropertyCommand that swaps the field and emits `signal`.
    template <class Owner, class Value>
    void applyProperty(Value Owner::*field, const Value &value, void (Owner::*signal)(),
                       const QString &text, int gesture = 0);
    // Pushes on the project's stack, or applies at once when the item is not in a project.
    void execute(QUndoCommand *command);
    // execute() for a property's command, with refitDependents() in the same undo step.
    void executeProperty(QUndoCommand *command, int gesture);
    // For the commands, after they stored an input and before the property's own signal:
    // bumps the generation, drops the derived data and emits derivedChanged().
    void inputsChanged();
    // Called after every input change, before the change signals: drop derived caches here.
    // Returns true when something was cached.
    virtual bool dropDerived() { return false; }
    // Rename support: point references to `from` at `to` (through undoable setters).
    virtual void renameReference(const QString &from, const QString &to);
    // Values whose validity depends on another property's shape (an attractor's start set of
    // net points on its net's count): a property edit that is not a gesture is followed, in
    // the same undo step, by refitDependents(), which makes them valid again.
    virtual bool hasDependents() const { return false; }
    virtual void refitDependents() {}

private:
    friend class Project;
    friend class ProjectIO; // attaches children and unknown fields while reading
    template <class, class>
    friend class PropertyCommand;
    template <class>
    friend class Declaration;  // the declared parts store through applyProperty()

    QString m_name;
    QString m_editName;  // EditName's, or empty
    StyleSpec m_style;
    AnimationSpec m_animation{0.0, 25.0, {}};
    QJsonObject m_unknownFields;
    Project *m_project = nullptr;
    Item *m_parent = nullptr;
    std::vector<std::unique_ptr<Item>> m_children;
    quint64 m_generation = 0;
};

} // namespace awb
