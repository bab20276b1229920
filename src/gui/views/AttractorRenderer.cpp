#include "gui/views/AttractorRenderer.h"

#include "core/analysis/Spectrum.h"

#include <QElapsedTimer>
#include <QMetaObject>
#include <QThread>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

// Per-thread rasters cost 8 bytes a pixel; beyond this budget fewer threads are used.
constexpr double kRasterBudgetBytes = 256.0 * 1024 * 1024;

struct Pass {
    int depth = 0;
    std::uint64_t samples = 0;
    double images = 0;
    bool final = false;
};

int effectivePrefix(const RenderRequest &r, int depth)
{
    if (r.colorMode != AttractorColorMode::ByAddress)
        return 1;
    int L = std::clamp(r.prefixLength, 1, 3);
    if (r.mode == RenderRequest::Mode::Deterministic)
        L = std::min(L, std::max(1, depth));
    return L;
}

QColor gradientAt(const QList<QColor> &stops, double t)
{
    if (stops.isEmpty())
        return QColor(Qt::black);
    if (stops.size() == 1)
        return stops.front();
    const double x = std::clamp(t, 0.0, 1.0) * double(stops.size() - 1);
    const int i = std::min(int(x), int(stops.size()) - 2);
    const double u = x - i;
    const QColor &a = stops[i], &b = stops[i + 1];
    return QColor::fromRgbF(float(a.redF() + u * (b.redF() - a.redF())),
                            float(a.greenF() + u * (b.greenF() - a.greenF())),
                            float(a.blueF() + u * (b.blueF() - a.blueF())));
}

// Grows lit pixels by r in each direction (a square), keeping the smallest label: a min filter
// that treats 0 (unlit) as infinity, done separably along rows and then columns.
std::vector<std::uint32_t> grownLabels(const RasterSink &raster, int r)
{
    const int w = raster.width(), h = raster.height();
    std::vector<std::uint32_t> labels(std::size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            labels[std::size_t(y) * w + x] = raster.label(x, y);
    if (r <= 0)
        return labels;
    auto better = [](std::uint32_t a, std::uint32_t b) {
        return a == 0 ? b : b == 0 ? a : std::min(a, b);
    };
    std::vector<std::uint32_t> tmp(labels.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint32_t best = 0;
            for (int k = std::max(0, x - r); k <= std::min(w - 1, x + r); ++k)
                best = better(best, labels[std::size_t(y) * w + k]);
            tmp[std::size_t(y) * w + x] = best;
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint32_t best = 0;
            for (int k = std::max(0, y - r); k <= std::min(h - 1, y + r); ++k)
                best = better(best, tmp[std::size_t(k) * w + x]);
            labels[std::size_t(y) * w + x] = best;
        }
    return labels;
}

// Turns the merged raster into pixels. Unlit pixels stay transparent so that the view (or an
// export) decides the background.
QImage colourise(const RasterSink &raster, const RenderRequest &r, int prefix, int maps)
{
    QImage img(raster.width(), raster.height(), QImage::Format_ARGB32_Premultiplied);
    img.fill(Qt::transparent);
    // Labels repeat a lot (one per piece): remember the last one's colour.
    std::uint32_t lastLabel = 0;
    QRgb lastColour = 0;
    std::uint8_t address[4] = {0, 0, 0, 0};
    const std::vector<std::uint32_t> labels = grownLabels(raster, std::clamp(r.dotRadius, 0, 4));
    for (int y = 0; y < raster.height(); ++y) {
        auto *line = reinterpret_cast<QRgb *>(img.scanLine(y));
        for (int x = 0; x < raster.width(); ++x) {
            const std::uint32_t label = labels[std::size_t(y) * raster.width() + x];
            if (label == 0)
                continue;
            if (label != lastLabel) {
                // The label is 1 + the base-256 number of the first `prefix` symbols.
                const std::uint32_t code = label - 1;
                for (int k = 0; k < prefix; ++k)
                    address[k] = std::uint8_t((code >> (8 * (prefix - 1 - k))) & 0xFF);
                lastColour = AttractorRenderer::addressColor(r.colorMode, prefix, r.palette,
                                                             maps, address, prefix)
                                 .rgba();
                lastLabel = label;
            }
            line[x] = lastColour;
        }
    }
    return img;
}

void checkRequest(const RenderRequest &r)
{
    if (!r.ifs || (r.ifs->size() == 0 && !r.iterate))
        throw InputError("there is no IFS to draw");
    if (r.ifs->views.empty())
        throw InputError("the IFS has no view to draw it with");
    if (r.size.width() < 1 || r.size.height() < 1)
        throw InputError("the image is empty");
    if (!r.iterate) {
        const IfsCheck check = checkIfs(*r.ifs);
        if (!check.contractive)
            throw InputError(check.message);
    }
    if (r.start.vertices.rows() == 0)
        throw InputError("the start set is empty");
}

int threadsFor(const RenderRequest &r)
{
    if (r.mode == RenderRequest::Mode::Random)
        return AttractorRenderer::kRandomStreams;
    const double perRaster = 8.0 * r.size.width() * r.size.height();
    const int byMemory = std::max(1, int(kRasterBudgetBytes / std::max(1.0, perRaster)));
    return std::clamp(QThread::idealThreadCount(), 1, std::min(8, byMemory));
}

// One pass into per-thread rasters; returns false when cancelled.
bool renderPass(const RenderRequest &r, const Pass &pass, const IterationControl &control,
                QImage *image, RenderInfo *info)
{
    QElapsedTimer timer;
    timer.start();
    const int prefix = effectivePrefix(r, pass.depth);
    const QRectF w = r.world.normalized();
    std::vector<std::unique_ptr<RasterSink>> rasters;
    std::vector<AttractorSink *> sinks;
    for (int t = 0, n = threadsFor(r); t < n; ++t) {
        rasters.push_back(std::make_unique<RasterSink>(r.size.width(), r.size.height(), w.left(),
                                                       w.top(), w.right(), w.bottom(),
                                                       r.ifs->views, prefix));
        sinks.push_back(rasters.back().get());
    }
    IterationStats stats;
    if (r.iterate) {
        stats = r.iterate(r.start, pass.depth, sinks, control);
    } else if (r.mode == RenderRequest::Mode::Deterministic) {
        stats = iterateParallel(*r.ifs, r.start, pass.depth, sinks, control);
    } else {
        ChaosOptions opt;
        opt.samples = pass.samples;
        opt.seed = r.seed;
        opt.addressLength = std::max(prefix, 1);
        stats = chaosGameParallel(*r.ifs, r.start.vertices.row(0), opt, sinks, control);
    }
    if (stats.cancelled)
        return false;
    for (std::size_t t = 1; t < rasters.size(); ++t)
        rasters.front()->merge(*rasters[t]);
    *image = colourise(*rasters.front(), r, prefix, std::max(1, r.ifs->size()));
    info->depth = r.mode == RenderRequest::Mode::Deterministic ? pass.depth : 0;
    info->images = double(stats.images);
    info->seconds = timer.nsecsElapsed() * 1e-9;
    info->final = pass.final;
    info->world = w;
    info->litPixels = rasters.front()->litPixels();
    return true;
}

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

QColor AttractorRenderer::mapColor(int i)
{
    // Qualitative colours that read on white and in print (Tableau 10 without grey).
    static const QColor palette[] = {QColor(31, 119, 180), QColor(214, 39, 40),
                                     QColor(44, 160, 44),  QColor(148, 103, 189),
                                     QColor(255, 127, 14), QColor(140, 86, 75),
                                     QColor(227, 119, 194), QColor(23, 190, 207),
                                     QColor(188, 189, 34)};
    return palette[((i % 9) + 9) % 9];
}

QList<QColor> AttractorRenderer::defaultGradient()
{
    // Dark enough everywhere to stay visible on a white background.
    return {QColor(68, 1, 84), QColor(59, 82, 139), QColor(33, 145, 140), QColor(53, 170, 80),
            QColor(200, 150, 20), QColor(214, 39, 40)};
}

QColor AttractorRenderer::addressColor(AttractorColorMode mode, int prefixLength,
                                       const QList<QColor> &palette, int maps,
                                       const std::uint8_t *address, int length)
{
    switch (mode) {
    case AttractorColorMode::Single:
        return palette.isEmpty() ? QColor(20, 20, 20) : palette.front();
    case AttractorColorMode::ByMap: {
        const int map = length > 0 ? address[0] : 0;
        return palette.isEmpty() ? mapColor(map) : palette[map % palette.size()];
    }
    case AttractorColorMode::ByAddress: {
        // Dense index of the prefix in base N: neighbouring pieces of the curve get
        // neighbouring colours of the gradient.
        const int L = std::min(std::clamp(prefixLength, 1, 3), std::max(length, 1));
        const double N = std::max(1, maps);
        double index = 0;
        for (int k = 0; k < L; ++k)
            index = index * N + (k < length ? address[k] : 0);
        return gradientAt(palette.isEmpty() ? defaultGradient() : palette,
                          (index + 0.5) / std::pow(N, L));
    }
    }
    return QColor(Qt::black);
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

QImage AttractorRenderer::renderNow(const RenderRequest &r, RenderInfo *info,
                                   const IterationControl &control)
{
    checkRequest(r);
    QImage image;
    RenderInfo local;
    if (!renderPass(r, passesFor(r).back(), control, &image, info ? info : &local))
        return {};
    return image;
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
        checkRequest(r);
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
            QImage image;
            RenderInfo info;
            if (!renderPass(r, pass, control, &image, &info) || m_cancel.load())
                return;
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
