#include "gui/views/ThreadInbox.h"

#include <QSocketNotifier>

#include <cstdint>
#include <stdexcept>

#include <sys/eventfd.h>
#include <unistd.h>

namespace awb {

ThreadInbox::ThreadInbox(QObject *receiver)
{
    m_fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
    if (m_fd < 0)
        throw std::runtime_error("eventfd failed: no file descriptor left for a worker's results");
    m_notifier = new QSocketNotifier(m_fd, QSocketNotifier::Read, receiver);
    QObject::connect(m_notifier, &QSocketNotifier::activated, m_notifier, [this] {
        std::uint64_t count;
        [[maybe_unused]] const ssize_t n = read(m_fd, &count, sizeof count); // resets it
        drain();
    });
}

ThreadInbox::~ThreadInbox()
{
    delete m_notifier;
    close(m_fd);
}

void ThreadInbox::post(std::function<void()> fn)
{
    {
        std::lock_guard lock(m_mutex);
        m_queue.push_back(std::move(fn));
    }
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t n = write(m_fd, &one, sizeof one);
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
