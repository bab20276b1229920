#pragma once
// The Properties dock's editor of a flame's xforms (model/FlameItem.h), as Apophysis's editor
// offers them: pick an xform (or the final one), add, duplicate or delete xforms, set its
// weight, colour, colour speed and opacity, its variations and their weights (add any of
// flam3's 99, a weight of 0 removes one) and the parameters of the variations it uses. Its
// pre map is the triangle dragged in the attractor view (and the point table below). Every
// edit is one undo step through FlameItem::setFlame; a refused one is reported and the editor
// shows the model again.

#include <QPointer>
#include <QWidget>

#include <functional>

class QComboBox;
class QDoubleSpinBox;
class QPushButton;
class QTableWidget;

namespace awb {

class FlameItem;
namespace flame {
struct Flame;
struct FlameXform;
}

class FlameXformEditor : public QWidget {
    Q_OBJECT
public:
    FlameXformEditor(FlameItem *item, std::function<void(const QString &)> report,
                     QWidget *parent = nullptr);

    // For tests: "xform" (the combo box), "add", "duplicate", "delete", "weight", "color",
    // "color_speed", "opacity", "variations" (the table), "add_variation" (a combo box),
    // "parameters" (the table); nullptr for another name.
    QWidget *editor(const QString &name) const;
    int current() const;  // the xform shown: 0 .. n - 1, n for the final one

private:
    void refresh();
    // Applies `change` to a copy of the flame's current xform (and the flame), as one undo step.
    bool edit(const std::function<void(flame::Flame &, flame::FlameXform &)> &change);
    flame::FlameXform *xformOf(flame::Flame &f) const;
    // Appends an xform (one undo step) and shows it.
    void append(const flame::FlameXform &x);
    // Sets the item's flame (one undo step); false, reported, when refused.
    bool commit(const flame::Flame &f);

    QPointer<FlameItem> m_item;
    std::function<void(const QString &)> m_report;
    int m_updating = 0;
    QComboBox *m_which = nullptr;
    QPushButton *m_add = nullptr, *m_duplicate = nullptr, *m_delete = nullptr;
    QDoubleSpinBox *m_weight = nullptr, *m_colour = nullptr, *m_speed = nullptr,
                   *m_opacity = nullptr;
    QTableWidget *m_variations = nullptr, *m_parameters = nullptr;
    QComboBox *m_addVariation = nullptr;
};

} // namespace awb
