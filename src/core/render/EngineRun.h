#pragma once
// The fixed-dimension kernels of a range of dimensions, chosen by the Store and the dimension
// of the IFS (private to core/render/Engine*.cpp; each EngineDims*.cpp instantiates one range
// with AWB_ENGINE_DIMS).

#include "core/render/EngineChaos.h"
#include "core/render/EngineDfs.h"

namespace awb::engine {

template <int D, Store M>
IterationStats runFixed(const EngineJob &job, const std::vector<CellView> &cv,
                        const Histograms &hist, const IterationControl &control)
{
    const Flat<D> F(*job.ifs, cv);
    const std::vector<std::uint8_t> coords = labelCoordinates(job.colours.labelColours.size());
    const std::vector<DensityImage *> &images = hist.images;
    const int threads = int(images.size());
    std::atomic<std::uint64_t> done{0};
    std::vector<IterationStats> results(threads);
    if (job.random) {
        const AliasTable pick(job.ifs->probabilities, job.ifs->size());
        const Progress progress{control, done, std::max(1.0, double(job.samples))};
        RowVec x0 = job.start.vertices.row(0);
        // One view: the orbit runs in screen space (toScreenSpace).
        Flat<D> screen = F;
        double start[D];
        for (int k = 0; k < D; ++k)
            start[k] = x0(k);
        const bool inScreen = toScreenSpace(F, screen, start);
        RowVec x0Screen = x0;
        for (int k = 0; k < D; ++k)
            x0Screen(k) = start[k];
        // Thread t runs a contiguous block of streams.
        onThreads(threads, [&](int t) {
            hist.prepare(t, job);
            const int first = kChaosStreams * t / threads, last = kChaosStreams * (t + 1) / threads;
            results[t] = inScreen
                             ? chaosKernel<D, M, true>(screen, pick, x0Screen, job, coords.data(),
                                                       first, last, *images[t], progress)
                             : chaosKernel<D, M, false>(F, pick, x0, job, coords.data(), first,
                                                        last, *images[t], progress);
        });
    } else {
        const auto tasks = splitTasks(F.n, job.depth, threads, 8);
        const int split = tasks.empty() ? 0 : int(tasks.front().size());
        const FusedLeaves<D> fused(F, FusedLeaves<D>::levelsFor(F.n, job.depth - split));
        const Progress progress{control, done, std::max(1.0, imageCount(*job.ifs, job.depth))};
        std::atomic<std::size_t> next{0};
        std::atomic<bool> stopped{false};
        onThreads(threads, [&](int t) {
            hist.prepare(t, job);
            DfsKernel<D, M> walker(F, fused, job, coords.data(), *images[t], progress);
            for (;;) {
                const std::size_t k = next.fetch_add(1);
                if (k >= tasks.size() || stopped.load())
                    break;
                if (!walker.run(tasks[k])) {
                    stopped = true;
                    break;
                }
            }
            results[t].images = walker.emitted();
            results[t].cancelled = stopped.load();
        });
    }
    IterationStats stats;
    for (const auto &r : results) {
        stats.images += r.images;
        stats.cancelled = stats.cancelled || r.cancelled;
    }
    return stats;
}

template <Store M, int D, int Hi>
IterationStats dispatch(int dim, const EngineJob &job, const std::vector<CellView> &cv,
                        const Histograms &hist, const IterationControl &control)
{
    if constexpr (D > Hi) {
        return {};
    } else {
        if (dim == D)
            return runFixed<D, M>(job, cv, hist, control);
        return dispatch<M, D + 1, Hi>(dim, job, cv, hist, control);
    }
}

template <int Lo, int Hi>
IterationStats runFixedRange(Store store, int dim, const EngineJob &job,
                             const std::vector<CellView> &cv, const Histograms &hist,
                             const IterationControl &control)
{
    switch (store) {
    case Store::Hits:
        return dispatch<Store::Hits, Lo, Hi>(dim, job, cv, hist, control);
    case Store::Colours:
        return dispatch<Store::Colours, Lo, Hi>(dim, job, cv, hist, control);
    case Store::Counts:
        return dispatch<Store::Counts, Lo, Hi>(dim, job, cv, hist, control);
    case Store::Planes:
        return dispatch<Store::Planes, Lo, Hi>(dim, job, cv, hist, control);
    }
    return {};
}

} // namespace awb::engine
