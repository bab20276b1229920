#pragma once
// One worker thread that runs only the latest job posted (layer 3): a burst of posts never
// queues stale work. A post may cancel the running job (its cancel flag goes up: a long
// computation of data that changed) or let it end (a short frame whose picture is still worth
// showing). The destructor cancels and waits.

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace awb {

class LatestJobWorker {
public:
    using Job = std::function<void(const std::atomic<bool> &cancel)>;
    LatestJobWorker() : m_thread([this] { loop(); }) {}
    ~LatestJobWorker()
    {
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
            m_cancel = true;
        }
        m_wake.notify_all();
        m_thread.join();
    }
    LatestJobWorker(const LatestJobWorker &) = delete;
    LatestJobWorker &operator=(const LatestJobWorker &) = delete;

    void post(Job job, bool cancelRunning = true)
    {
        {
            std::lock_guard lock(m_mutex);
            m_pending = std::move(job);
            if (cancelRunning)
                m_cancel = true;
        }
        m_wake.notify_one();
    }

private:
    void loop()
    {
        for (;;) {
            Job job;
            {
                std::unique_lock lock(m_mutex);
                m_wake.wait(lock, [this] { return m_stop || bool(m_pending); });
                if (m_stop)
                    return;
                job = std::move(m_pending);
                m_pending = nullptr;
                m_cancel = false;
            }
            job(m_cancel);
        }
    }

    std::mutex m_mutex;
    std::condition_variable m_wake;
    Job m_pending;
    bool m_stop = false;
    std::atomic<bool> m_cancel{false};
    std::thread m_thread;
};

} // namespace awb
