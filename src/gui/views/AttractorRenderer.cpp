#include "gui/views/AttractorRenderer.h"

#include <QMetaObject>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

constexpr std::size_t kCostSamples = 12;
// An interactive pass always draws at least this many images or samples: cheap everywhere.
constexpr double kMinInteractiveWork = 2000;

struct Pass {
    int depth = 0;
    std::uint64_t samples = 0;
    double images = 0;
    bool final = false;
};

double viewsOf(const RenderRequest &r)
{
    return double(std::max<std::size_t>(1, r.ifs->views.size()));
}

std::vector<Pass> fullPasses(const RenderRequest &r, bool coarseFirst)
{
    std::vector<Pass> out;
    const double views = viewsOf(r);
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
        if (coarseFirst && coarse < r.depth && N > 1)
            out.push_back({coarse, 0, imageCount(*r.ifs, coarse) * views, false});
        out.push_back({r.depth, 0, imageCount(*r.ifs, r.depth) * views, true});
    } else {
        const auto coarse = std::uint64_t(std::max(1.0, r.coarseImages));
        if (coarseFirst && coarse < r.samples)
            out.push_back({0, coarse, double(coarse), false});
        out.push_back({0, r.samples, double(r.samples), true});
    }
    return out;
}

} // namespace

// ---- cost model -------------------------------------------------------------------------------

void PassCostModel::add(double work, double ms, QSize size)
{
    if (!(work > 0) || !(ms >= 0) || !std::isfinite(ms))
        return;
    std::lock_guard lock(m_mutex);
    if (size != m_size) {
        m_size = size;
        m_samples.clear();
    }
    if (m_samples.size() == kCostSamples)
        m_samples.erase(m_samples.begin());
    m_samples.push_back({work, ms});
}

bool PassCostModel::fit(double *fixed, double *perUnit) const
{
    if (m_samples.empty())
        return false;
    // Least squares of ms = a + b work; with one distinct work the line goes through 0.
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const Sample &s : m_samples) {
        n += 1;
        sx += s.work;
        sy += s.ms;
        sxx += s.work * s.work;
        sxy += s.work * s.ms;
    }
    const double det = n * sxx - sx * sx;
    double a = 0, b = 0;
    if (det > 1e-9 * n * sxx) {
        b = (n * sxy - sx * sy) / det;
        a = (sy - b * sx) / n;
    }
    if (!(b > 0)) {
        // No slope measured (equal works, or noise): the costliest pass per unit of work.
        a = 0;
        for (const Sample &s : m_samples)
            b = std::max(b, s.ms / s.work);
    }
    *fixed = std::max(0.0, a);
    *perUnit = b;
    return b > 0;
}

double PassCostModel::predict(double work, QSize size) const
{
    std::lock_guard lock(m_mutex);
    double a = 0, b = 0;
    if (size != m_size || !fit(&a, &b))
        return -1;
    return a + b * work;
}

double PassCostModel::workWithin(double budgetMs, QSize size) const
{
    std::lock_guard lock(m_mutex);
    double a = 0, b = 0;
    if (size != m_size || !fit(&a, &b))
        return -1;
    return std::max(0.0, (budgetMs - a) / b);
}

// ---- renderer ---------------------------------------------------------------------------------

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

void AttractorRenderer::setBusy(bool busy)
{
    if (busy == m_busy)
        return;
    m_busy = busy;
    emit busyChanged(busy);
}

void AttractorRenderer::request(const RenderRequest &r, Quality quality, std::uint64_t tag)
{
    const std::uint64_t serial = ++m_serial;
    {
        std::lock_guard lock(m_mutex);
        m_pending = Job{r, serial, quality, tag};
        // An interactive pass is a frame's work: let it end and show its picture.
        if (m_runningCancellable)
            m_cancel = true;
    }
    m_wake.notify_all();
    if (quality != Quality::Interactive) {
        m_busySerial = serial;
        setBusy(true);
    } else {
        m_busySerial = 0; // a Full request before it is superseded
        setBusy(false);
    }
}

void AttractorRenderer::cancel()
{
    {
        std::lock_guard lock(m_mutex);
        m_pending.reset();
        m_cancel = true;
    }
    m_floor = ++m_serial; // drop whatever the running job still posts
    m_busySerial = 0;
    setBusy(false);
}

bool AttractorRenderer::drawingInteractive() const
{
    std::lock_guard lock(m_mutex);
    return m_runningInteractive;
}

int AttractorRenderer::interactiveDepth(const RenderRequest &r) const
{
    if (!r.ifs || r.iterate || r.ifs->size() < 2)
        return r.depth;
    const double views = viewsOf(r);
    double work = m_deterministicCost.workWithin(m_budgetMs, r.size);
    if (work < 0)
        work = r.coarseImages; // nothing measured yet: the coarse pass's size
    work = std::max(work, kMinInteractiveWork);
    int depth = 0;
    while (depth < r.depth && imageCount(*r.ifs, depth + 1) * views <= work)
        ++depth;
    return depth;
}

std::uint64_t AttractorRenderer::interactiveSamples(const RenderRequest &r) const
{
    double work = m_randomCost.workWithin(m_budgetMs, r.size);
    if (work < 0)
        work = r.coarseImages;
    work = std::max(work, kMinInteractiveWork);
    return std::min<std::uint64_t>(r.samples, std::uint64_t(work));
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
            // An automaton's interactive pass is its full depth: it may be long, so a newer
            // request cancels it like a Full one.
            m_runningCancellable = job.quality != Quality::Interactive || job.request.iterate;
            m_runningInteractive = job.quality == Quality::Interactive;
            // Reset under the lock: a request arriving after this point sets it again.
            m_cancel = false;
        }
        runJob(job);
        std::lock_guard lock(m_mutex);
        m_runningCancellable = false;
        m_runningInteractive = false;
    }
}

void AttractorRenderer::post(std::uint64_t serial, std::function<void()> fn)
{
    m_inbox.post([this, serial, fn = std::move(fn)] {
        if (serial < m_floor || serial < m_delivered)
            return;
        m_delivered = serial;
        fn();
    });
}

void AttractorRenderer::runJob(const Job &job)
{
    const RenderRequest &r = job.request;
    const bool interactive = job.quality == Quality::Interactive;
    const auto endBusy = [this, serial = job.serial] {
        if (serial == m_busySerial) {
            m_busySerial = 0;
            setBusy(false);
        }
    };
    try {
        checkRenderRequest(r);
        std::vector<Pass> passes;
        if (!interactive || r.iterate) {
            passes = fullPasses(r, job.quality == Quality::Full);
        } else if (r.mode == RenderRequest::Mode::Deterministic) {
            const int depth = interactiveDepth(r);
            passes.push_back({depth, 0, imageCount(*r.ifs, depth) * viewsOf(r),
                              depth == r.depth});
        } else {
            const std::uint64_t samples = interactiveSamples(r);
            passes.push_back({0, samples, double(samples), samples == r.samples});
        }
        double total = 0, before = 0;
        for (const Pass &p : passes)
            total += std::max(1.0, p.images);
        for (const Pass &pass : passes) {
            // The core calls this from all its threads: report whole percents only.
            std::atomic<int> lastPercent{-1};
            IterationControl control;
            control.cancel = &m_cancel;
            const double offset = before, weight = std::max(1.0, pass.images);
            if (!interactive) {
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
            }
            RenderInfo info;
            const QImage image = renderAttractorImage(r, pass.depth, pass.samples, &info, control);
            if (image.isNull() || m_cancel.load())
                return;
            if (!r.iterate && pass.images > 0) {
                PassCostModel &model = r.mode == RenderRequest::Mode::Deterministic
                                           ? m_deterministicCost
                                           : m_randomCost;
                model.add(pass.images, info.seconds * 1e3, r.size);
            }
            info.final = pass.final;
            info.tag = job.tag;
            info.interactive = interactive;
            before += weight;
            post(job.serial, [this, image, info, endBusy] {
                emit imageReady(image, info);
                if (info.final)
                    endBusy();
            });
        }
    } catch (const std::exception &e) {
        // The core's message names the problem (e.g. which map is not contractive).
        const QString message =
            tr("Cannot draw the attractor: %1").arg(QString::fromStdString(e.what()));
        post(job.serial, [this, message, endBusy] {
            emit failed(message);
            endBusy();
        });
    }
}

} // namespace awb
