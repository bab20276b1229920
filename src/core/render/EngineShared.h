#pragma once
// What Engine.cpp and the engine's kernels share (private to core/render/Engine*.cpp): the
// Stores a kernel writes its hits in, the views as affine maps to raster cells, the threads and
// their histograms, and the entry to the fixed-dimension kernels of each Store, compiled in
// files of their own (EngineRun.h). Engine.cpp includes this and not the kernels, so that an edit
// of it compiles none of them.

#include "core/Threads.h"
#include "core/render/Engine.h"

#include <cmath>
#include <thread>
#include <vector>

namespace awb::engine {


constexpr int kMaxFixedDim = 12;
constexpr int kInterleave = 4;  // orbits advanced together per thread

// x86-64 with GCC or Clang: the kernels exist twice, for the baseline and for AVX2 (chosen at
// run time by haveAvx2). Defined here, where Engine.cpp (haveAvx2 itself) sees it too: defined
// only beside the kernels, haveAvx2 was compiled without it and every render ran the baseline.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define AWB_AVX2_KERNELS 1
#define AWB_AVX2_TARGET __attribute__((target("avx2")))
#define AWB_INLINE_BODY __attribute__((always_inline)) inline
#else
#define AWB_INLINE_BODY inline
#endif

// Whether the AVX2 kernels run: the processor has AVX2 and forceBaselineKernels is off
// (Engine.cpp).
bool haveAvx2();
// Whether the AVX-512 kernels (the flame game's step) run: the processor has AVX-512 F, DQ, BW
// and VL, haveAvx2() holds and forceAvx2Kernels is off (Engine.cpp).
bool haveAvx512();

// How a kernel stores a hit (DensityImage's layouts): in buckets, the smallest label (hits) or
// the colour coordinate (density); the count alone (a one-label image: a picture of one
// colour, in either mode); the count in the label's plane (label planes).
enum class Store { Hits, Colours, Counts, Planes };

// A view as an affine map from IFS space straight to raster cells: cell = x V + c.
struct CellView {
    Mat V;      // D x 2
    double c[2];
};

// The histograms of one render: images[0] is the caller's picture, the others the threads'
// own, reused from one render to the next; clean[t]: images[t] is known to be empty (taken
// whole by the last merge) and of this size and mode, so it needs no reset.
struct Histograms {
    std::vector<DensityImage *> images;
    std::vector<char> clean;
    CellLayout layout;  // buckets, one label's counts (one colour), or label planes

    // Called by thread t before it draws.
    void prepare(int t, const EngineJob &job) const
    {
        DensityImage &img = *images[std::size_t(t)];
        if (!clean[std::size_t(t)] || img.cellsX() != job.frame.cellsX()
            || img.cellsY() != job.frame.cellsY() || img.mode() != job.accumulation
            || !(img.layout() == layout))
            img.reset(job.frame.cellsX(), job.frame.cellsY(), job.accumulation, layout);
    }
};

// The fixed-dimension kernels for IFS of dimensions Lo..Hi (<= kMaxFixedDim), writing in Store
// `store`, one histogram per thread (EngineRun.h). Each range is compiled in a file of its own
// (EngineDims*.cpp): the kernels of one dimension, shared by the four Stores, are compiled once,
// and the files compile in parallel.
template <int Lo, int Hi>
IterationStats runFixedRange(Store store, int dim, const EngineJob &job,
                             const std::vector<CellView> &cv, const Histograms &hist,
                             const IterationControl &control);

#define AWB_ENGINE_DIMS(Lo, Hi)                                                               \
    template IterationStats runFixedRange<Lo, Hi>(Store, int, const EngineJob &,               \
                                                  const std::vector<CellView> &,               \
                                                  const Histograms &, const IterationControl &)
extern AWB_ENGINE_DIMS(1, 4);
extern AWB_ENGINE_DIMS(5, 8);
extern AWB_ENGINE_DIMS(9, kMaxFixedDim);

// The fixed-dimension kernels for an IFS of dimension `dim` <= kMaxFixedDim.
inline IterationStats runFixedDims(Store store, int dim, const EngineJob &job,
                                   const std::vector<CellView> &cv, const Histograms &hist,
                                   const IterationControl &control)
{
    if (dim <= 4)
        return runFixedRange<1, 4>(store, dim, job, cv, hist, control);
    if (dim <= 8)
        return runFixedRange<5, 8>(store, dim, job, cv, hist, control);
    return runFixedRange<9, kMaxFixedDim>(store, dim, job, cv, hist, control);
}

} // namespace awb::engine
