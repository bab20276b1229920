#pragma once
// One background computation at a time for a view (layer 3): start() cancels and joins the
// previous run, hands the new one a cancel flag and a generation number; results posted back
// with an older generation are stale and dropped by the view. The destructor cancels and joins,
// so a view never outlives its worker's access to it.

#include <QThread>

#include <atomic>
#include <functional>
#include <memory>

namespace awb {

class CancellableWorker {
public:
    CancellableWorker() = default;
    CancellableWorker(const CancellableWorker &) = delete;
    CancellableWorker &operator=(const CancellableWorker &) = delete;
    ~CancellableWorker() { stop(); }

    // Runs job(cancel flag, generation) on a new low-priority thread; returns the generation.
    quint64 start(std::function<void(const std::atomic<bool> *, quint64)> job)
    {
        const quint64 generation = bump();
        auto flag = std::make_shared<std::atomic<bool>>(false);
        m_flag = flag;
        m_thread = QThread::create([job = std::move(job), flag, generation] {
            job(flag.get(), generation);
        });
        m_thread->start(QThread::LowPriority);
        return generation;
    }
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
        if (m_thread) {
            m_thread->wait();
            delete m_thread;
            m_thread = nullptr;
        }
    }
    bool isCurrent(quint64 generation) const { return generation == m_generation; }

private:
    QThread *m_thread = nullptr;
    std::shared_ptr<std::atomic<bool>> m_flag;
    quint64 m_generation = 0;
};

} // namespace awb
