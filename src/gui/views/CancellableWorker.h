#pragma once
// One background computation at a time for a view (layer 3): start() cancels and joins the
// previous run, hands the new one a cancel flag and a generation number; the job hands its
// results to the view's thread with post() (a ThreadInbox), and results of an older generation
// are stale and dropped by the view. The destructor cancels and joins, so a view never
// outlives its worker's access to it.

#include "gui/views/BackgroundPriority.h"
#include "gui/views/ThreadInbox.h"

#include <atomic>
#include <functional>
#include <memory>
#include <thread>

namespace awb {

class CancellableWorker {
public:
    // Results posted by the jobs run on the thread of `receiver` (the view).
    explicit CancellableWorker(QObject *receiver) : m_inbox(receiver) {}
    CancellableWorker(const CancellableWorker &) = delete;
    CancellableWorker &operator=(const CancellableWorker &) = delete;
    ~CancellableWorker() { stop(); }

    // Runs job(cancel flag, generation) on a new thread of lower priority (the pictures'
    // workers come first, BackgroundPriority.h); returns the generation.
    quint64 start(std::function<void(const std::atomic<bool> *, quint64)> job)
    {
        const quint64 generation = bump();
        auto flag = std::make_shared<std::atomic<bool>>(false);
        m_flag = flag;
        m_thread = std::thread([job = std::move(job), flag, generation] {
            lowerThisThreadPriority();
            job(flag.get(), generation);
        });
        return generation;
    }
    // From the job: runs `fn` on the receiver's thread, in the order posted.
    void post(std::function<void()> fn) { m_inbox.post(std::move(fn)); }
    // Cancels and joins the running job and makes its pending results stale.
    quint64 bump()
    {
        stop();
        return ++m_generation;
    }
    void cancel()
    {
        if (m_flag)
            m_flag->store(true);
    }
    void stop()
    {
        cancel();
        if (m_thread.joinable())
            m_thread.join();
    }
    bool isCurrent(quint64 generation) const { return generation == m_generation; }

private:
    ThreadInbox m_inbox; // before m_thread: outlives the job
    std::thread m_thread;
    std::shared_ptr<std::atomic<bool>> m_flag;
    quint64 m_generation = 0;
};

} // namespace awb
