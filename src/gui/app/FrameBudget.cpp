#include "gui/app/FrameBudget.h"

#include <QEvent>
#include <QWidget>

#include <algorithm>

namespace awb {

FrameBudget::FrameBudget(QObject *parent) : QObject(parent)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &FrameBudget::service);
}

int FrameBudget::addPanel(QWidget *widget, std::function<void()> update)
{
    Panel p;
    p.widget = widget;
    p.hasWidget = widget != nullptr;
    p.update = std::move(update);
    m_panels.append(p);
    if (widget)
        widget->installEventFilter(this);
    return int(m_panels.size()) - 1;
}

bool FrameBudget::visible(const Panel &p) const
{
    if (!p.hasWidget)
        return true;
    return p.widget && p.widget->isVisible();
}

void FrameBudget::run(Panel &p)
{
    p.dirty = false;
    p.last.start();
    if (!p.hasWidget || p.widget)
        p.update();
}

void FrameBudget::markDirty(int panel)
{
    if (panel < 0 || panel >= m_panels.size())
        return;
    m_panels[panel].dirty = true;
    if (!m_timer.isActive())
        m_timer.start(0);
}

bool FrameBudget::isDirty(int panel) const
{
    return panel >= 0 && panel < m_panels.size() && m_panels[panel].dirty;
}

void FrameBudget::flush()
{
    m_timer.stop();
    for (Panel &p : m_panels)
        if (p.dirty)
            run(p);
}

void FrameBudget::service()
{
    int wait = -1;
    for (Panel &p : m_panels) {
        if (!p.dirty)
            continue;
        if (!inGesture()) {
            // At rest every panel follows the document (exports and prints read them).
            run(p);
            continue;
        }
        if (!visible(p))
            continue;
        const qint64 since = p.last.isValid() ? p.last.elapsed() : m_interval;
        if (since >= m_interval)
            run(p);
        else
            wait = wait < 0 ? int(m_interval - since) : std::min(wait, int(m_interval - since));
    }
    if (wait >= 0)
        m_timer.start(wait);
}

void FrameBudget::beginGesture()
{
    if (m_gestures++ == 0)
        emit gestureChanged(true);
}

void FrameBudget::endGesture()
{
    if (m_gestures == 0)
        return;
    if (--m_gestures == 0) {
        emit gestureChanged(false);
        // Every panel is brought up to date at once.
        flush();
    }
}

bool FrameBudget::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Show) {
        for (Panel &p : m_panels)
            if (p.hasWidget && p.widget == watched && p.dirty && !m_timer.isActive())
                m_timer.start(0);
    }
    return QObject::eventFilter(watched, event);
}

} // namespace awb
