#pragma once
// Work handed from worker threads to the thread of one QObject (the GUI thread), in the order
// posted (layer 3). Every result of a background computation (a render, a mesh, a frame, an
// analysis) comes back through one of these, not through a queued Qt connection: the functions
// are kept in a queue under a std::mutex and the receiving thread is woken by an eventfd. Both
// are synchronisation that ThreadSanitizer sees (scripts/sanitize.sh thread), whereas Qt's own
// event queue is guarded by futexes inside an uninstrumented Qt, so that a lambda built on a
// worker and run by the event loop looked like a data race to it.
//
// The owner declares its inbox before its workers, so that the workers are joined before the
// inbox goes; functions still queued then are dropped (as Qt drops the events of a deleted
// receiver).

#include <QObject>

#include <deque>
#include <functional>
#include <mutex>

class QSocketNotifier;

namespace awb {

class ThreadInbox {
public:
    // Runs the posted functions in the thread of `receiver` (the caller's thread).
    explicit ThreadInbox(QObject *receiver);
    ~ThreadInbox();
    ThreadInbox(const ThreadInbox &) = delete;
    ThreadInbox &operator=(const ThreadInbox &) = delete;

    // From any thread.
    void post(std::function<void()> fn);
    // Runs what is queued now (the receiver's thread; the notifier calls it). Re-entrant: a
    // function that spins an event loop lets later ones run inside it, in order.
    void drain();
    // Drops what is queued (the receiver's thread).
    void clear();

private:
    std::mutex m_mutex;
    std::deque<std::function<void()>> m_queue; // guarded by m_mutex
    int m_fd = -1;
    QSocketNotifier *m_notifier = nullptr;
};

} // namespace awb
