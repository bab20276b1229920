#include "gui/views/AttractorRenderer.h"

#include <QElapsedTimer>
#include <QMetaObject>
#include <QThread>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

struct Pass {
    int depth = 0;
    std::uint64_t samples = 0;
    double images = 0;
    bool final = false;
};

std::vector<Pass> passesFor(const RenderRequest &r)
{
    std::vector<Pass> out;
    const double views = double(std::max<std::size_t>(1, r.ifs->views.size()));
    if (r.iterate) {
        // An automaton: the image count is not N^k, so draw the requested depth at once.
        out.push_back({r.depth, 0, 0.0, true});
        return out;
    }
    if (r.mode == RenderRequest::Mode::Deterministic) {
        const int N = r.ifs->size();
        int coarse = 0;
        while (coarse < r.depth && N > 1
               && imageCount(*r.ifs, coarse + 1) * views <= r.coarseImages)
            ++coarse;
        if (coarse < r.depth && N > 1)
            out.push_back({coarse, 0, imageCount(*r.ifs, coarse), false});
        out.push_back({r.depth, 0, imageCount(*r.ifs, r.depth), true});
    } else {
        const auto coarse = std::uint64_t(std::max(1.0, r.coarseImages));
        if (coarse < r.samples)
            out.push_back({0, coarse, double(coarse), false});
        out.push_back({0, r.samples, double(r.samples), true});
    }
    return out;
}

} // namespace

AttractorRenderer::AttractorRenderer(QObject *parent) : QObject(parent)
{
    qRegisterMetaType<awb::RenderInfo>();
    m_thread = std::thread([this] { workerLoop(); });
}

AttractorRenderer::~AttractorRenderer()
{
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
        m_pending.reset();
        m_cancel = true;
    }
    m_wake.notify_all();
    m_thread.join();
}

void AttractorRenderer::request(const RenderRequest &r)
{
    {
        std::lock_guard lock(m_mutex);
        m_pending = Job{r, ++m_serial};
        m_cancel = true;
    }
    m_wake.notify_all();
    if (!m_busy) {
        m_busy = true;
        emit busyChanged(true);
    }
}

void AttractorRenderer::cancel()
{
    {
        std::lock_guard lock(m_mutex);
        m_pending.reset();
        m_cancel = true;
        ++m_serial; // drop whatever the running job still posts
    }
    if (m_busy) {
        m_busy = false;
        emit busyChanged(false);
    }
}

void AttractorRenderer::workerLoop()
{
    for (;;) {
        Job job;
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [this] { return m_stop || m_pending.has_value(); });
            if (m_stop)
                return;
            job = std::move(*m_pending);
            m_pending.reset();
            // Reset under the lock: a request arriving after this point sets it again.
            m_cancel = false;
        }
        runJob(job);
    }
}

void AttractorRenderer::post(std::uint64_t serial, std::function<void()> fn)
{
    // Queued to the GUI thread; results of a request that has been superseded are dropped.
    QMetaObject::invokeMethod(
        this,
        [this, serial, fn = std::move(fn)] {
            if (serial == m_serial)
                fn();
        },
        Qt::QueuedConnection);
}

void AttractorRenderer::runJob(const Job &job)
{
    const RenderRequest &r = job.request;
    try {
        checkRenderRequest(r);
        const std::vector<Pass> passes = passesFor(r);
        double total = 0, before = 0;
        for (const Pass &p : passes)
            total += std::max(1.0, p.images);
        for (const Pass &pass : passes) {
            // The core calls this from all its threads: report whole percents only.
            std::atomic<int> lastPercent{-1};
            IterationControl control;
            control.cancel = &m_cancel;
            const double offset = before, weight = std::max(1.0, pass.images);
            control.progress = [&, offset, weight](double f) {
                const int percent = int(100.0 * (offset + f * weight) / total);
                int last = lastPercent.load();
                while (percent > last) {
                    if (lastPercent.compare_exchange_weak(last, percent)) {
                        post(job.serial, [this, percent] { emit progress(percent / 100.0); });
                        break;
                    }
                }
            };
            RenderInfo info;
            const QImage image = renderAttractorImage(r, pass.depth, pass.samples, &info, control);
            if (image.isNull() || m_cancel.load())
                return;
            info.final = pass.final;
            before += weight;
            post(job.serial, [this, image, info] {
                emit imageReady(image, info);
                if (info.final && m_busy) {
                    m_busy = false;
                    emit busyChanged(false);
                }
            });
        }
    } catch (const std::exception &e) {
        // The core's message names the problem (e.g. which map is not contractive).
        const QString message =
            tr("Cannot draw the attractor: %1").arg(QString::fromStdString(e.what()));
        post(job.serial, [this, message] {
            emit failed(message);
            if (m_busy) {
                m_busy = false;
                emit busyChanged(false);
            }
        });
    }
}

} // namespace awb
