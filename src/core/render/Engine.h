#pragma once
// The attractor raster engine: streams F^k(X0) (deterministic iteration) or the orbit of a
// random iteration straight into a DensityImage, on several threads with one histogram each,
// merged at the end. Memory is the histograms only, whatever the depth or the sample count.
//
// Kernels (Engine.cpp) are templates on the IFS dimension D (1..12): maps and points are
// fixed-size arrays, no allocation and no virtual call per point.
// - Random iteration runs the kChaosStreams streams of Random.h, four orbits interleaved per
//   thread so that the latency of one map application hides behind the others; with AVX2 and
//   at most 8 maps, the four orbits' choices and map applications run in the lanes of vector
//   registers (the same operations in the same order: the same cells).
// - A picture whose labels all have one colour is drawn as one label into a counts-only
//   histogram (4 bytes a cell instead of 8): the same picture, half the memory touched.
//   Random iteration with 2 to 4 labels counts each label in its own plane (Density.h's
//   label planes): the same picture, the scattered hits in one colour's cache lines where
//   the labels' parts do not overlap. Deterministic iteration keeps its buckets, which cost
//   less to clear, merge and tone map per picture (measured on drags: 1.7 vs 2.0 ms at depth
//   8, 6.2 vs 6.8 ms at depth 11).
// - Deterministic iteration walks the words depth first with one buffer per level; the last
//   map is fused with the projection to the raster (x A_i V + b_i V + c: 2D instead of D^2 + 2D
//   flops per vertex), and the innermost levels are split across threads.
// - Start sets drawn as segments or polygons are rasterised as lines and filled polygons; an
//   image within a 2 x 2 block of cells (deep levels) adds one hit to each cell it covers,
//   and one inside a single cell one hit there.
// - The leaves' loops exist for the baseline and for AVX2 (x86-64), chosen at run time, with
//   the same rounding: the same cells either way.
// Larger dimensions and custom iterations (automata) use the same rasteriser through
// DensitySink, fed by the sink-based iterate()/chaosGame() of ifs/Attractor.h.

#include "core/ifs/Attractor.h"
#include "core/render/Density.h"

namespace awb {

// Colour labels: an image's label is its first `prefix` address symbols (address[0] is the
// outermost map) read as a number in base N (the number of maps); prefix 0 gives every image
// label 0 (one colour). labelColours holds the colour of each label (N^prefix entries).
struct EngineColours {
    int prefix = 1;
    std::vector<Rgb8> labelColours;
};

struct EngineJob {
    const Ifs *ifs = nullptr;
    std::vector<Projection> views;   // empty: ifs->views
    StartSet start;
    bool random = false;
    int depth = 8;                   // deterministic
    std::uint64_t samples = 100000;  // random, from the first start vertex
    std::uint64_t seed = 1;
    int skip = 32;
    RasterFrame frame;
    Accumulation accumulation = Accumulation::Hits;
    EngineColours colours;
    int threads = 1;
    // Random iteration with 2 to CellLayout::kMaxPlanes labels keeps a plane of counts per
    // label (Density.h); false keeps 8-byte buckets, the same picture (the benches compare).
    bool labelPlanes = true;
};

// Accumulates the job into `out` (sized to the frame's cells, cleared first). Throws
// InputError for bad input (a non-finite start set, a bad depth or sample count, a frame
// too large); returns with stats.cancelled when control.cancel was set.
IterationStats accumulate(const EngineJob &job, DensityImage &out,
                          const IterationControl &control = {});

// The same histogram from any iteration: rasterises every image it receives (points as
// cells, polylines as lines, polygons filled), coloured by its address.
class DensitySink : public AttractorSink {
public:
    DensitySink(const RasterFrame &frame, std::vector<Projection> views, Accumulation mode,
                const EngineColours &colours, int maps);
    void consume(const Mat &v, StartSet::Kind kind, const std::uint8_t *address,
                 int length) override;
    // The views: the iteration fuses them with its last map.
    const std::vector<Projection> *projections() const override { return &m_views; }
    void consumeProjected(const std::vector<Mat> &projected, StartSet::Kind kind,
                          const std::uint8_t *address, int length) override;
    DensityImage &image() { return m_image; }
    const DensityImage &image() const { return m_image; }

private:
    RasterFrame m_frame;
    std::vector<Projection> m_views;
    const EngineColours &m_colours;
    int m_maps;
    DensityImage m_image;
    std::vector<std::uint8_t> m_coords;
    std::vector<double> m_screen;
    // One image through one view (n x 2 plane points) into the image.
    void plot(const Mat &p, StartSet::Kind kind, std::uint32_t label);
};

// The vector kernels the engine runs here: "avx2" (x86-64 processors that have it) or
// "baseline". forceBaselineKernels(true) selects the baseline ones for the renders that start
// afterwards (tests compare the two: they give the same cells).
const char *engineKernels();
void forceBaselineKernels(bool on);
// The flame game's AVX-512 step off (the AVX2 kernels and the scalar step run instead) for the
// renders that start afterwards: tests compare the two.
void forceAvx2Kernels(bool on);

// Label of an address (address[0] outermost) for `prefix` symbols of N maps.
std::uint32_t addressLabel(const std::uint8_t *address, int length, int prefix, int maps);

} // namespace awb
