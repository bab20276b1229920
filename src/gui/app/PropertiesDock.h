#pragma once
// PropertiesDock's content: editors for everything of the current item, built from its declared
// properties (Item::parameters(), model/PropertyTable.h): spin boxes, a slider where the
// property has a slider range, a combo box for a choice, two spin boxes and a plane for a
// complex number, a check box, a line of text -- grouped by their headings, greyed where the
// declaration says they do not apply now. The structured inputs have their own editors: the
// control point table with add / insert / delete, the palette button of the style. Every edit
// goes through the item's undoable setters; one slider drag is one gesture and so one undo
// step. A refused value is reported through Messages and the editor shows the model's value
// again.
#include "model/Item.h"
#include "model/Parameters.h"
#include <QHash>
#include <QPointer>
#include <QWidget>
#include <functional>
#include <vector>

class QFormLayout;
class QTableWidget;
class QVBoxLayout;

namespace awb {

class FlameXformEditor;
class FrameBudget;
class Item;
class Messages;
class Project;

class PropertiesWidget : public QWidget {
    Q_OBJECT
public:
    explicit PropertiesWidget(Messages *messages, QWidget *parent = nullptr);

    void setItem(Item *item);
    Item *item() const { return m_item; }
    // The editor of a parameter (QDoubleSpinBox, QSpinBox, QComboBox, QCheckBox, QLineEdit, or
    // for a complex value the real part's spin box) by its declared key ("name",
    // "start_set.kind", "algorithm.depth", "style.color_by", "source", ...); nullptr for an
    // unknown key. For tests. Besides the parameters' keys: "style.colors" (the palette
    // button), "points" (the table), "points.set", "points.add", "points.insert",
    // "points.delete"; for a flame "xforms.NAME" (FlameXformEditor::editor).
    QWidget *editor(const QString &key) const;
    QWidget *slider(const QString &key) const;
    // The colours an item without its own uses (the preferences' palette; empty: the views').
    void setDefaultPalette(const QList<QColor> &palette);
    // Coalesces the dock's updates during gestures (nullptr: every change shows at once).
    void setFrameBudget(FrameBudget *budget);

private:
    // The parameters as they are now, by key (ranges and choices may follow the state).
    using Infos = QHash<QString, ParameterInfo>;
    struct Binding {
        QString key;
        std::function<void(const Infos &)> update;  // shows the model's value
    };
    Infos currentInfos() const;
    void rebuild();
    void updateValues();
    void onItemChanged();
    bool apply(const QString &key, const QVariant &value, int gesture = 0);
    void addParameter(QFormLayout *form, const ParameterInfo &info);
    // PropertiesEditors.cpp: the point table with its buttons, the palette button, the plot's
    // state (its eigenvalues, or why there are none).
    void addPointEditors();
    void addPaletteEditor(QFormLayout *form);
    void addEigenvaluePlotStatus(QFormLayout *form);
    // The selected rows of the point table (sorted), or the current row.
    std::vector<int> selectedPointRows() const;
    void report(const QString &message);
    // Reports an editor's refusal of a typed value ("Depth: 40 is outside 0 … 19.").
    std::function<void(const QString &)> refusal(const QString &label);
    // A slider or the complex plane held for `key`: one undo step until endGesture.
    int beginGesture(const QString &key);
    void endGesture(int gesture);

    Messages *m_messages;
    QPointer<Item> m_item;
    QList<QMetaObject::Connection> m_connections;
    QVBoxLayout *m_layout = nullptr;
    QWidget *m_content = nullptr;
    QStringList m_keys;  // parameter keys the editors were built for
    QList<Binding> m_bindings;
    QHash<QString, QWidget *> m_editors, m_sliders;
    QTableWidget *m_points = nullptr;
    FlameXformEditor *m_xforms = nullptr;  // a flame's xforms
    int m_pointSet = 0;  // the point set the table shows
    int m_updating = 0;
    FrameBudget *m_budget = nullptr;
    int m_budgetPanel = -1;
    QPointer<Project> m_gestureProject;
    int m_gesture = 0;
    QString m_gestureKey;
    QList<QColor> m_defaultPalette;
};

} // namespace awb
