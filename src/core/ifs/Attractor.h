#pragma once
// Drawing attractors: deterministic iteration of the Hutchinson operator F(X) = U f_i(X) from
// any start set, and random iteration (chaos game). Both stream what they make to a sink, so a
// deep level never needs all N^k images in memory.

#include "core/ifs/Ifs.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>

namespace awb {

// A compact start set X_0 in the IFS space. Images of segments and polygons under affine maps
// are segments and polygons, so only the vertices travel through the maps.
struct StartSet {
    enum class Kind { Points, Polyline, Polygon };
    Kind kind = Kind::Points;
    Mat vertices; // n x D

    static StartSet points(const Mat &pts) { return {Kind::Points, pts}; }
    static StartSet polyline(const Mat &pts) { return {Kind::Polyline, pts}; }
    static StartSet polygon(const Mat &pts) { return {Kind::Polygon, pts}; }
};
std::string toString(StartSet::Kind kind);

// Receives the image f_w(X_0) of the start set for each address w. address[0] is the map
// applied last (the outermost one, i.e. which of the N pieces the image lies in).
class AttractorSink {
public:
    virtual ~AttractorSink() = default;
    virtual void consume(const Mat &vertices, StartSet::Kind kind, const std::uint8_t *address,
                         int length) = 0;
    // A sink that needs the images only through fixed affine maps x -> x V + c (a 3D view's
    // world coordinates, a control point's weight) may list them here. Deterministic iteration
    // then applies the last map and each of them as one product, x (A_i V) + (b_i V + c): D x k
    // per vertex instead of D x D, several times less work on the lifted spaces of surfaces
    // (D = 11 to 36). It calls consumeProjected with one matrix per listed map, in the list's
    // order (0 columns where V does not have D rows); images of depth 0, and of a depth the
    // task split reaches, still come to consume(). The list must not change during a run.
    virtual const std::vector<Projection> *projections() const { return nullptr; }
    virtual void consumeProjected(const std::vector<Mat> &projected, StartSet::Kind kind,
                                  const std::uint8_t *address, int length)
    {
        (void)projected, (void)kind, (void)address, (void)length;
    }
};

struct IterationControl {
    const std::atomic<bool> *cancel = nullptr;    // polled; set it to stop early
    std::function<void(double)> progress;         // fraction done, called from worker threads
};

struct IterationStats {
    std::uint64_t images = 0;  // start-set images emitted
    bool cancelled = false;
};

// Number of images F^depth makes: N^depth (as a double, it may be huge).
double imageCount(const Ifs &ifs, int depth);

// Throws InputError for a bad IFS, start set (empty, non-finite, wrong dimension) or depth.
void checkIterateInputs(const Ifs &ifs, const StartSet &start, int depth);
// F^depth(X_0), every image sent to sink. depth 0 emits X_0 itself. Throws InputError for
// depth < 0 or > 64, or an invalid IFS.
IterationStats iterate(const Ifs &ifs, const StartSet &start, int depth, AttractorSink &sink,
                       const IterationControl &control = {});
// The same on sinks.size() threads; each thread feeds its own sink (merge them afterwards).
// F^depth(X_0) like iterate(), but the images come in the order of their addresses read
// outermost map first (f_{w1} o ... o f_{wk}(X_0) for w in lexicographic order): for the IFS of
// a curve this is the order along the curve, so neighbouring images touch (vector export joins
// them into one path). iterate() instead varies the innermost map fastest, which is cheaper.
// Each step composes two affine maps (D^3 flops); single-threaded.
IterationStats iterateAlong(const Ifs &ifs, const StartSet &start, int depth, AttractorSink &sink,
                            const IterationControl &control = {});
IterationStats iterateParallel(const Ifs &ifs, const StartSet &start, int depth,
                               const std::vector<AttractorSink *> &sinks,
                               const IterationControl &control = {});

struct ChaosOptions {
    std::uint64_t samples = 100000;
    std::uint64_t seed = 1;
    int skip = 32;            // first iterates not emitted (the orbit is not yet on the attractor)
    int addressLength = 8;    // how many of the latest maps are passed as the address
};
// Random iteration from start point x0 (1 x D) with the IFS's probabilities (uniform if none):
// kChaosStreams independent streams (Random.h) share the samples, spread over the sinks (one
// thread each), so the points drawn do not depend on the number of sinks.
inline constexpr std::uint64_t kMaxChaosSamples = 1'000'000'000'000ULL;  // 1e12
// The most maps an IFS may have for iteration (addresses are bytes); the readers of other
// tools' files refuse larger ones at import.
inline constexpr int kMaxMaps = 255;
// Throws InputError for a bad IFS, start point or sample count.
void checkChaosInputs(const Ifs &ifs, const RowVec &x0, std::uint64_t samples);
IterationStats chaosGame(const Ifs &ifs, const RowVec &x0, const ChaosOptions &options,
                         AttractorSink &sink, const IterationControl &control = {});
IterationStats chaosGameParallel(const Ifs &ifs, const RowVec &x0, const ChaosOptions &options,
                                 const std::vector<AttractorSink *> &sinks,
                                 const IterationControl &control = {});

// ---- sinks ------------------------------------------------------------------------------------

class CallbackSink : public AttractorSink {
public:
    using Fn = std::function<void(const Mat &, StartSet::Kind, const std::uint8_t *, int)>;
    explicit CallbackSink(Fn fn) : m_fn(std::move(fn)) {}
    void consume(const Mat &v, StartSet::Kind k, const std::uint8_t *a, int n) override
    {
        m_fn(v, k, a, n);
    }

private:
    Fn m_fn;
};

// Collects the projected vertices of every image for one view, with the first address symbol.
class PointCollector : public AttractorSink {
public:
    explicit PointCollector(Projection view, std::size_t maxPoints = 50'000'000);
    void consume(const Mat &v, StartSet::Kind k, const std::uint8_t *a, int n) override;
    // All collected points, one per row (k columns).
    Mat points() const;
    const std::vector<std::uint8_t> &firstSymbols() const { return m_symbols; }
    bool truncated() const { return m_truncated; }

private:
    Projection m_view;
    std::size_t m_max;
    std::vector<double> m_data;
    std::vector<std::uint8_t> m_symbols;
    bool m_truncated = false;
};

// Axis-aligned bounds of the projected images (all views).
class BoundsSink : public AttractorSink {
public:
    explicit BoundsSink(std::vector<Projection> views) : m_views(std::move(views)) {}
    void consume(const Mat &v, StartSet::Kind k, const std::uint8_t *a, int n) override;
    bool empty() const { return m_lo.size() == 0; }
    RowVec lo() const { return m_lo; }
    RowVec hi() const { return m_hi; }
    bool finite() const { return m_finite; }

private:
    std::vector<Projection> m_views;
    RowVec m_lo, m_hi;
    bool m_finite = true;
};

// The box that holds `share` of the points it is fed, per axis of the projected images (all
// views): the quantiles (1 - share) / 2 and (1 + share) / 2 of each coordinate. Fed by the
// chaos game, the box of that share of the invariant measure: the frame of an IFS that
// contracts only on average (a flame's), whose orbit has heavy tails (a bounding box of every
// point would show the bulk as a dot).
class QuantileBoundsSink : public AttractorSink {
public:
    QuantileBoundsSink(std::vector<Projection> views, double share)
        : m_views(std::move(views)), m_share(share)
    {}
    void consume(const Mat &v, StartSet::Kind k, const std::uint8_t *a, int n) override;
    bool empty() const { return m_coords.empty() || m_coords.front().empty(); }
    RowVec lo() const { return columnQuantile(m_coords, 0.5 * (1 - m_share)); }
    RowVec hi() const { return columnQuantile(m_coords, 0.5 * (1 + m_share)); }
    // The q-quantile (0..1, nearest rank) of each column of values (0 for an empty one).
    static RowVec columnQuantile(std::vector<std::vector<double>> columns, double q);

private:
    std::vector<Projection> m_views;
    double m_share;
    std::vector<std::vector<double>> m_coords;  // per axis, the finite values seen
};

// The frame of an IFS that contracts on average only: the box (lo, hi, in the views'
// coordinates) of `share` of its invariant measure, from `samples` points of the chaos game
// from x0 with `seed` (QuantileBoundsSink). nullopt when no point was finite. The CLI's
// figures and the window's fit both frame such an IFS with it.
std::optional<std::pair<RowVec, RowVec>> measureBox(const Ifs &ifs, const RowVec &x0,
                                                    std::uint64_t seed, double share = 0.99,
                                                    std::uint64_t samples = 20000);

// Rasters of these images: DensitySink and the engine's kernels (core/render/Engine.h).

} // namespace awb
