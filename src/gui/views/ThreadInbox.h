#pragma once
// Work handed from worker threads to the thread of one QObject (the GUI thread), in the order
// posted (layer 3). Every result of a background computation (a render, a mesh, a frame, an
// analysis) comes back through one of these, not through a queued Qt connection: the functions
// are kept in a queue under a std::mutex, which ThreadSanitizer sees (scripts/sanitize.sh
// thread), whereas a lambda carried by Qt's event queue (guarded by futexes inside an
// uninstrumented Qt) was built on the worker and destroyed by the event loop, and looked like a
// data race to it. The receiving thread is woken by a bare QEvent, which Qt alone allocates and
// frees, posted once for any number of functions queued before it is handled. (An eventfd with
// a QSocketNotifier woke it too, but the GLib dispatcher serves socket notifiers behind the
// window's input and paint events: during a drag the attractor view drew 26-34 pictures a
// second instead of 53-57, measured with attractor-bench-window.)
//
// The owner declares its inbox before its workers, so that the workers are joined before the
// inbox goes; functions still queued then are dropped (as Qt drops the events of a deleted
// receiver).

#include <QObject>

#include <deque>
#include <functional>
#include <mutex>

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
    // Runs what is queued now (the receiver's thread; the wake-up event calls it). Re-entrant:
    // a function that spins an event loop lets later ones run inside it, in order.
    void drain();
    // Drops what is queued (the receiver's thread).
    void clear();

private:
    class Waker;
    std::mutex m_mutex;
    std::deque<std::function<void()>> m_queue; // guarded by m_mutex
    bool m_wakePending = false;                // guarded by m_mutex: a wake-up event is posted
                                               // and not yet handled
    Waker *m_waker = nullptr;                  // a child of the receiver, in its thread
};

} // namespace awb
