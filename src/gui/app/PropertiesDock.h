#pragma once
// PropertiesDock's content: editors for everything of the current item, built generically from
// Item::parameters() (spin boxes, a slider where the parameter has a slider range, a combo box
// for a choice, two spin boxes for a complex number) plus the shared inputs of attractor items
// (name, start set, algorithm, style, control points). Every edit goes through the item's
// undoable setters; one slider drag is one gesture and so one undo step. A refused value is
// reported through Messages and the editor shows the model's value again.
#include "model/Item.h"
#include "model/Parameters.h"
#include <QHash>
#include <QPointer>
#include <QWidget>
#include <functional>

class QFormLayout;
class QTableWidget;
class QVBoxLayout;

namespace awb {

class Item;
class Messages;

class PropertiesWidget : public QWidget {
    Q_OBJECT
public:
    explicit PropertiesWidget(Messages *messages, QWidget *parent = nullptr);

    void setItem(Item *item);
    Item *item() const { return m_item; }
    // The editor of a parameter (QDoubleSpinBox, QSpinBox, QComboBox, QCheckBox, or for a
    // complex value the real part's spin box); nullptr for an unknown key. For tests.
    QWidget *editor(const QString &key) const;
    QWidget *slider(const QString &key) const;

private:
    struct Binding {
        QString key;
        std::function<void()> update;  // shows the model's value
    };
    void rebuild();
    void updateValues();
    void onItemChanged();
    bool apply(const QString &key, const QVariant &value, int gesture = 0);
    void addParameter(QFormLayout *form, const ParameterInfo &info);
    void addAttractorEditors();
    void report(const QString &message);
    int beginGesture();

    Messages *m_messages;
    QPointer<Item> m_item;
    QMetaObject::Connection m_connection;
    QVBoxLayout *m_layout = nullptr;
    QWidget *m_content = nullptr;
    QStringList m_keys;  // parameter keys the editors were built for
    QList<Binding> m_bindings;
    QHash<QString, QWidget *> m_editors, m_sliders;
    QTableWidget *m_points = nullptr;
    int m_updating = 0;
};

} // namespace awb
