#include "core/render/Engine.h"

#include "core/Messages.h"
#include "core/ifs/Random.h"
#include "core/render/EngineShared.h"
#include "core/render/Plotter.h"

#include <algorithm>
#include <atomic>
#include <memory>

namespace awb {

using namespace engine;

namespace {
std::atomic<bool> g_baselineKernels{false};
std::atomic<bool> g_avx2Kernels{false};
} // namespace

bool engine::haveAvx2()
{
#if defined(AWB_AVX2_KERNELS)
    static const bool avx2 = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") != 0;
    }();
    return avx2 && !g_baselineKernels.load(std::memory_order_relaxed);
#else
    return false;
#endif
}

bool engine::haveAvx512()
{
#if defined(AWB_AVX2_KERNELS)
    static const bool avx512 = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq")
               && __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl");
    }();
    return avx512 && haveAvx2() && !g_avx2Kernels.load(std::memory_order_relaxed);
#else
    return false;
#endif
}

const char *engineKernels()
{
    return haveAvx2() ? "avx2" : "baseline";
}

void forceBaselineKernels(bool on)
{
    g_baselineKernels = on;
}

void forceAvx2Kernels(bool on)
{
    g_avx2Kernels = on;
}

std::uint32_t addressLabel(const std::uint8_t *address, int length, int prefix, int maps)
{
    std::uint32_t label = 0;
    for (int k = 0; k < prefix; ++k)
        label = label * std::uint32_t(maps) + (k < length ? address[k] : 0u);
    return label;
}

namespace {

// Per-thread histograms beyond this many bytes in all: fewer threads.
constexpr double kHistogramBudget = 192.0 * 1024 * 1024;

std::vector<CellView> cellViews(const std::vector<Projection> &views, const RasterFrame &f, int dim)
{
    const double sx = f.cellsX() / (f.x1 - f.x0), sy = f.cellsY() / (f.y1 - f.y0);
    std::vector<CellView> out;
    for (const Projection &v : views) {
        if (v.V.rows() != dim || v.V.cols() < 2 || v.c.size() != v.V.cols())
            throw InputError(coreTranslate("awb::render", "a view does not fit the IFS space"));
        CellView cv;
        cv.V.resize(dim, 2);
        cv.V.col(0) = v.V.col(0) * sx;
        cv.V.col(1) = -v.V.col(1) * sy;
        cv.c[0] = (v.c(0) - f.x0) * sx;
        cv.c[1] = (f.y1 - v.c(1)) * sy;
        out.push_back(std::move(cv));
    }
    return out;
}

// ---- fixed-dimension kernels ------------------------------------------------------------------

// The maps and views of one job in flat arrays: a[i][k][j] (y_j = b_j + sum_k x_k a_kj),

} // namespace

IterationStats accumulate(const EngineJob &job, DensityImage &out, const IterationControl &control)
{
    if (!job.ifs)
        throw InputError(coreTranslate("awb::render", "there is no IFS to draw"));
    job.frame.validate();
    const Ifs &ifs = *job.ifs;
    const std::vector<Projection> &views = job.views.empty() ? ifs.views : job.views;
    if (views.empty())
        throw InputError(coreTranslate("awb::render", "the IFS has no view to draw it with"));
    std::uint64_t labels = 1;
    for (int k = 0; k < job.colours.prefix; ++k)
        labels *= std::uint64_t(std::max(1, ifs.size()));
    if (job.colours.prefix < 0 || job.colours.prefix > 3
        || job.colours.labelColours.size() < labels)
        throw InputError(coreTranslate("awb::render", "the colour table does not cover the address "
                                                      "labels"));
    if (job.random) {
        checkChaosInputs(ifs, job.start.vertices.row(0), job.samples);
    } else {
        checkIterateInputs(ifs, job.start, job.depth);
    }
    const std::vector<CellView> cv = cellViews(views, job.frame, ifs.dim());

    // One histogram per thread, within the memory budget; thread 0 fills `out` itself.
    const double bytes = 16.0 * job.frame.cellsX() * job.frame.cellsY();
    int threads = std::clamp(job.threads, 1, kChaosStreams);
    // A small picture's work is less than starting threads and merging their histograms.
    const double work = job.random ? double(job.samples)
                                   : imageCount(ifs, job.depth) * double(job.start.vertices.rows());
    if (work < 2e5)
        threads = 1;
    threads = std::max(1, std::min(threads, int(kHistogramBudget / std::max(1.0, bytes))));
    // The other threads' histograms are kept per calling thread and reused by the next
    // picture of the same size (live drags render one picture after another). The merge
    // below empties them, so the next picture of that size skips their reset; each thread
    // resets its own otherwise (the kernels; here for the sink path).
    struct Spare {
        std::unique_ptr<DensityImage> image;
        bool clean = false;
    };
    static thread_local std::vector<Spare> spare;
    if (spare.size() < std::size_t(threads))
        spare.resize(std::size_t(threads));
    Histograms hist;
    hist.images.push_back(&out);
    hist.clean.push_back(0);
    for (int t = 1; t < threads; ++t) {
        if (!spare[t].image)
            spare[t].image = std::make_unique<DensityImage>();
        hist.images.push_back(spare[t].image.get());
        hist.clean.push_back(spare[t].clean ? 1 : 0);
        spare[t].clean = false;  // until the merge empties it again
    }
    const std::vector<DensityImage *> &images = hist.images;
    // A much larger earlier picture's memory is not kept.
    auto release = [&] {
        for (auto &s : spare)
            if (s.image && s.image->size() > 4 * std::size_t(job.frame.cellsX()) * job.frame.cellsY())
                s.image.reset(), s.clean = false;
    };
    const bool fixed = ifs.dim() <= kMaxFixedDim && ifs.size() > 0;
    if (!fixed)
        for (int t = 0; t < threads; ++t)
            hist.prepare(t, job);

    IterationStats stats;
    if (fixed) {
        // A picture whose labels all have one colour is the same picture with one label: its
        // histograms keep the counts alone (half the memory the hits touch), and the kernels
        // skip the labels' arithmetic.
        bool oneColour = true;
        for (std::uint64_t l = 1; l < labels; ++l) {
            const Rgb8 &a = job.colours.labelColours[l], &b = job.colours.labelColours[0];
            oneColour = oneColour && a.r == b.r && a.g == b.g && a.b == b.b;
        }
        // The random iteration's hits scatter over the whole picture: with few labels, one
        // plane of counts per label touches the memory of one colour where the labels' parts
        // do not overlap (Density.h). Deterministic iteration hits its cells in the order of
        // the addresses, where 8-byte buckets cost less to clear, merge and tone map.
        const bool planes =
            job.labelPlanes && job.random && labels >= 2 && labels <= CellLayout::kMaxPlanes;
        if (oneColour) {
            hist.layout = CellLayout::oneLabel();
            EngineJob one = job;
            one.colours.prefix = 0;
            one.colours.labelColours.resize(1);
            stats = runFixedDims(Store::Counts, ifs.dim(), one, cv, hist, control);
        } else if (planes) {
            hist.layout = CellLayout::labelPlanes(
                int(labels), labelCoordinates(job.colours.labelColours.size()));
            stats = runFixedDims(Store::Planes, ifs.dim(), job, cv, hist, control);
        } else {
            stats = job.accumulation == Accumulation::Hits
                        ? runFixedDims(Store::Hits, ifs.dim(), job, cv, hist, control)
                        : runFixedDims(Store::Colours, ifs.dim(), job, cv, hist, control);
        }
    } else {
        // Large dimensions: the sink-based iteration into the same rasteriser.
        std::vector<std::unique_ptr<DensitySink>> sinks;
        std::vector<AttractorSink *> raw;
        for (int t = 0; t < threads; ++t) {
            sinks.push_back(std::make_unique<DensitySink>(job.frame, views, job.accumulation,
                                                          job.colours, ifs.size()));
            raw.push_back(sinks.back().get());
        }
        if (job.random) {
            ChaosOptions opt;
            opt.samples = job.samples;
            opt.seed = job.seed;
            opt.skip = job.skip;
            opt.addressLength = std::max(1, job.colours.prefix);
            stats = chaosGameParallel(ifs, job.start.vertices.row(0), opt, raw, control);
        } else {
            stats = iterateParallel(ifs, job.start, job.depth, raw, control);
        }
        for (int t = 0; t < threads; ++t)
            images[t]->merge(sinks[t]->image());
    }
    if (stats.cancelled)
        return stats;
    if (images.size() > 1) {
        // Thread t moves every other histogram's band t of cells into `out`, leaving them
        // empty for the next picture.
        const std::size_t cells = out.size();
        onThreads(threads, [&](int t) {
            const std::size_t first = cells * std::size_t(t) / std::size_t(threads);
            const std::size_t last = cells * std::size_t(t + 1) / std::size_t(threads);
            for (std::size_t k = 1; k < images.size(); ++k)
                out.takeCells(*images[k], first, last);
        });
        for (std::size_t k = 1; k < images.size(); ++k) {
            out.takeRest(*images[k]);
            spare[k].clean = true;
        }
    }
    release();
    if (control.progress)
        control.progress(1.0);
    return stats;
}

DensitySink::DensitySink(const RasterFrame &frame, std::vector<Projection> views,
                         Accumulation mode, const EngineColours &colours, int maps)
    : m_frame(frame), m_views(std::move(views)), m_colours(colours), m_maps(std::max(1, maps)),
      m_image(frame.cellsX(), frame.cellsY(), mode),
      m_coords(labelCoordinates(colours.labelColours.size()))
{
    frame.validate();
}

void DensitySink::consume(const Mat &v, StartSet::Kind kind, const std::uint8_t *a, int n)
{
    const std::uint32_t label = addressLabel(a, n, m_colours.prefix, m_maps);
    for (const Projection &view : m_views)
        plot(project(view, v), kind, label);
}

void DensitySink::consumeProjected(const std::vector<Mat> &projected, StartSet::Kind kind,
                                   const std::uint8_t *a, int n)
{
    const std::uint32_t label = addressLabel(a, n, m_colours.prefix, m_maps);
    for (const Mat &p : projected)
        if (p.cols() >= 2)
            plot(p, kind, label);
}

void DensitySink::plot(const Mat &p, StartSet::Kind kind, std::uint32_t label)
{
    const double sx = m_frame.cellsX() / (m_frame.x1 - m_frame.x0);
    const double sy = m_frame.cellsY() / (m_frame.y1 - m_frame.y0);
    Plotter plotter{m_image, m_image.cellsX(), m_image.cellsY(), m_coords.data()};
    std::vector<double> xs;
    m_screen.resize(std::size_t(p.rows()) * 2);
    for (Eigen::Index r = 0; r < p.rows(); ++r) {
        m_screen[2 * r] = (p(r, 0) - m_frame.x0) * sx;
        m_screen[2 * r + 1] = (m_frame.y1 - p(r, 1)) * sy;
    }
    plotter.image(m_screen.data(), int(p.rows()), kind, label, xs);
}

} // namespace awb
