#pragma once
// WheelGuard (layer 3, GUI): value editors (spin boxes, combo boxes, sliders) inside a
// scrolling panel take the mouse wheel only when they have the keyboard focus. Without it,
// scrolling the Properties dock over an editor changes the value under the pointer (and pushes
// an undo step). A guarded editor gets Qt::StrongFocus (a click or Tab focuses it, the wheel
// does not) and an event filter that passes an unfocused wheel on to the scroll area.
#include <QObject>

class QWidget;

namespace awb {

class WheelGuard : public QObject {
    Q_OBJECT
public:
    // The one guard of the application (a parentless singleton: filters need no per-widget
    // state).
    static WheelGuard *instance();
    // Guards every spin box, combo box and slider in `root` (and `root` itself).
    static void guardChildren(QWidget *root);
    static void guard(QWidget *editor);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    using QObject::QObject;
};

} // namespace awb
