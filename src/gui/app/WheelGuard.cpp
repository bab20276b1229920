#include "gui/app/WheelGuard.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QEvent>
#include <QWidget>

namespace awb {

namespace {

bool isValueEditor(const QWidget *w)
{
    return qobject_cast<const QAbstractSpinBox *>(w) || qobject_cast<const QComboBox *>(w)
           || qobject_cast<const QAbstractSlider *>(w);
}

} // namespace

WheelGuard *WheelGuard::instance()
{
    static WheelGuard *guard = new WheelGuard;
    return guard;
}

void WheelGuard::guard(QWidget *editor)
{
    if (!editor || !isValueEditor(editor))
        return;
    // A scroll bar is the scrolling itself: it keeps the wheel.
    if (editor->inherits("QScrollBar"))
        return;
    editor->setFocusPolicy(Qt::StrongFocus);
    editor->removeEventFilter(instance()); // installed once, however often guarded
    editor->installEventFilter(instance());
}

void WheelGuard::guardChildren(QWidget *root)
{
    if (!root)
        return;
    guard(root);
    for (QWidget *w : root->findChildren<QWidget *>())
        guard(w);
}

bool WheelGuard::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Wheel) {
        auto *w = qobject_cast<QWidget *>(watched);
        if (w && !w->hasFocus()) {
            // Not ours: QApplication hands an ignored wheel event to the parent widgets, up
            // to the scroll area.
            event->ignore();
            return true;
        }
    }
    return QObject::eventFilter(watched, event);
}

} // namespace awb
