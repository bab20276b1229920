#include "gui/views/ThreadInbox.h"

#include <QCoreApplication>
#include <QEvent>

namespace awb {

namespace {
QEvent::Type wakeEventType()
{
    static const auto type = QEvent::Type(QEvent::registerEventType());
    return type;
}
} // namespace

// Receives the wake-up events in the receiver's thread.
class ThreadInbox::Waker : public QObject {
public:
    Waker(ThreadInbox *inbox, QObject *receiver) : QObject(receiver), m_inbox(inbox) {}
    bool event(QEvent *e) override
    {
        bool wake;
        {
            // The lock first: the wake-up event was allocated on the worker under this mutex,
            // and taking it makes that visible to ThreadSanitizer before e is read. Cleared
            // before draining: a function queued from now on posts a new event.
            std::lock_guard lock(m_inbox->m_mutex);
            wake = e->type() == wakeEventType();
            if (wake)
                m_inbox->m_wakePending = false;
        }
        if (!wake)
            return QObject::event(e);
        m_inbox->drain();
        return true;
    }

private:
    ThreadInbox *m_inbox;
};

ThreadInbox::ThreadInbox(QObject *receiver) : m_waker(new Waker(this, receiver)) {}

ThreadInbox::~ThreadInbox()
{
    delete m_waker; // and with it its pending wake-up event
}

void ThreadInbox::post(std::function<void()> fn)
{
    QEvent *wake = nullptr;
    {
        std::lock_guard lock(m_mutex);
        m_queue.push_back(std::move(fn));
        if (!m_wakePending) {
            m_wakePending = true;
            wake = new QEvent(wakeEventType());
        }
    }
    if (wake)
        QCoreApplication::postEvent(m_waker, wake);
}

void ThreadInbox::drain()
{
    for (;;) {
        std::function<void()> fn;
        {
            std::lock_guard lock(m_mutex);
            if (m_queue.empty())
                return;
            fn = std::move(m_queue.front());
            m_queue.pop_front();
        }
        fn();
    }
}

void ThreadInbox::clear()
{
    std::deque<std::function<void()>> dropped;
    std::lock_guard lock(m_mutex);
    dropped.swap(m_queue);
}

} // namespace awb
