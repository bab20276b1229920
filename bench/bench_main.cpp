// attractor-bench: throughput of the attractor engine on this machine, next to the machine's
// own limits and to plain kernels written here, all measured in the same run. Prints figures
// only; goals live in the issue tracker. Run: build/bin/attractor-bench [--quick]
//
// Lines (scripts parse the first words and the "Mpoints/s" figure):
//   machine        the limits: random increments into a histogram of the picture's size, and
//                  sequential stores of the picture's bytes;
//   plain kernel   a chaos game and a depth-first iteration of ~100 lines each (fixed
//                  dimension, xoshiro, one uint32 histogram): what a plain program reaches;
//   deterministic  the engine (core/render/Engine.h) drawing F^k(X0) into its histogram;
//   chaos game     the engine's random iteration into its histogram (one colour: counts
//                  alone; colour by map: a plane of counts per map; "by map, buckets": the
//                  same picture in 8-byte buckets of counts and colour sums, for comparison);
//   normal-vector  001's Koch scheme (polygons, not the raster engine).
// Each engine line ends with its ratio to the plain kernel and to the machine limit.

#include "core/ifs/Attractor.h"
#include "core/Threads.h"
#include "core/ifs/Random.h"
#include "core/render/Engine.h"
#include "core/schemes/ControlPointFractal.h"
#include "core/schemes/NormalVectorScheme.h"
#include "core/schemes/Scheme.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

using namespace awb;

namespace {

constexpr int kSide = 1024;  // histogram side of every raster figure

double seconds(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Best of `reps` runs of fn() (seconds): the machine is shared, the best run is the machine.
template <typename Fn>
double best(int reps, Fn fn)
{
    double t = 1e300;
    for (int r = 0; r < reps; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        fn();
        t = std::min(t, seconds(t0));
    }
    return t;
}

volatile std::uint64_t g_sink = 0;  // keeps results alive

// ---- the machine's limits ---------------------------------------------------------------------

// Independent random increments into per-thread uint32 histograms of kSide^2 cells.
double randomIncrements(int threads, std::uint64_t perThread)
{
    std::vector<std::vector<std::uint32_t>> h(threads, std::vector<std::uint32_t>(kSide * kSide));
    const double t = best(3, [&] {
        onThreads(threads, [&](int k) {
            Xoshiro256 rng(7, std::uint64_t(k));
            auto &hist = h[k];
            for (std::uint64_t i = 0; i < perThread; ++i)
                ++hist[rng.next() >> 44];  // 20 bits: kSide^2 cells
        });
    });
    std::uint64_t s = 0;
    for (auto &v : h)
        s += v[12345];
    g_sink = g_sink + s;
    return double(perThread) * threads / t / 1e6;
}

// Sequential stores of a 32-bit picture of kSide^2 pixels (GB/s).
double sequentialStores()
{
    std::vector<std::uint32_t> img(kSide * kSide);
    const int reps = 200;
    const double t = best(3, [&] {
        for (int r = 0; r < reps; ++r) {
            std::fill(img.begin(), img.end(), std::uint32_t(r));
            g_sink = g_sink + img[std::size_t(r) * 977 % img.size()];
        }
    });
    return 4.0 * img.size() * reps / t / 1e9;
}

// ---- plain kernels ----------------------------------------------------------------------------

// The three-map Sierpinski gasket in the plane, f_i(z) = z/2 + v_i/2, onto [0,1]^2.
Ifs sierpinski2d()
{
    Ifs ifs;
    const double v[3][2] = {{0, 0}, {1, 0}, {0.5, 1}};
    for (auto &p : v) {
        AffineMap f;
        f.A = Mat::Identity(2, 2) * 0.5;
        f.b = RowVec(2);
        f.b << p[0] / 2, p[1] / 2;
        ifs.maps.push_back(f);
    }
    Projection view;
    view.V = Mat::Identity(2, 2);
    view.c = RowVec::Zero(2);
    ifs.views.push_back(view);
    return ifs;
}

// A plain chaos game: one orbit per thread, xoshiro, z -> z/2 + v/2, one uint32 histogram.
double plainChaos(int threads, std::uint64_t samples)
{
    std::vector<std::vector<std::uint32_t>> h(threads, std::vector<std::uint32_t>(kSide * kSide));
    const double vx[3] = {0, 0.5, 0.25}, vy[3] = {0, 0, 0.5};
    const double t = best(2, [&] {
        onThreads(threads, [&](int k) {
            Xoshiro256 rng(3, std::uint64_t(k));
            double x = 0.3, y = 0.3;
            auto &hist = h[k];
            const std::uint64_t n = samples / threads;
            for (std::uint64_t i = 0; i < n; ++i) {
                const int m = int(((rng.next() >> 32) * 3) >> 32);
                x = 0.5 * x + vx[m];
                y = 0.5 * y + vy[m];
                const int px = int(x * kSide), py = int((1.0 - y) * kSide);
                if (px >= 0 && py >= 0 && px < kSide && py < kSide)
                    ++hist[std::size_t(py) * kSide + px];
            }
        });
    });
    std::uint64_t s = 0;
    for (auto &v : h)
        s += v[kSide * kSide - kSide / 2];
    g_sink = g_sink + s;
    return double(samples) / t / 1e6;
}

// A plain depth-first iteration in dimension D: one buffer per level, the point projected to
// the histogram at the leaves.
template <int D>
struct PlainDfs {
    const Ifs &ifs;
    int depth;
    std::vector<double> a, b;  // a[i][k][j], b[i][j]
    double v[D][2], c[2];
    std::vector<std::uint32_t> hist = std::vector<std::uint32_t>(kSide * kSide);
    double x[65][D];

    PlainDfs(const Ifs &f, int k, const Projection &view, double x0, double y0, double scale)
        : ifs(f), depth(k)
    {
        for (const AffineMap &m : f.maps) {
            for (int q = 0; q < D; ++q)
                for (int j = 0; j < D; ++j)
                    a.push_back(m.A(q, j));
            for (int j = 0; j < D; ++j)
                b.push_back(m.b(j));
        }
        for (int q = 0; q < D; ++q)
            v[q][0] = view.V(q, 0) * scale, v[q][1] = -view.V(q, 1) * scale;
        c[0] = (view.c(0) - x0) * scale;
        c[1] = (y0 - view.c(1)) * scale;
    }
    void walk(int l)
    {
        if (l == depth) {
            double sx = c[0], sy = c[1];
            for (int j = 0; j < D; ++j)
                sx += x[l][j] * v[j][0], sy += x[l][j] * v[j][1];
            if (sx >= 0 && sy >= 0 && sx < kSide && sy < kSide)
                ++hist[std::size_t(sy) * kSide + std::size_t(sx)];
            return;
        }
        for (int i = 0; i < ifs.size(); ++i) {
            const double *A = &a[std::size_t(i) * D * D], *B = &b[std::size_t(i) * D];
            for (int j = 0; j < D; ++j) {
                double s = B[j];
                for (int q = 0; q < D; ++q)
                    s += x[l][q] * A[q * D + j];
                x[l + 1][j] = s;
            }
            walk(l + 1);
        }
    }
};

struct Frame {
    double x0, y0, x1, y1;
};

Frame frameOf(const Ifs &ifs, const StartSet &start)
{
    BoundsSink bounds(ifs.views);
    iterate(ifs, start, 7, bounds);
    const RowVec lo = bounds.lo(), hi = bounds.hi();
    const double side = std::max(hi(0) - lo(0), hi(1) - lo(1)) * 1.05;
    const double cx = 0.5 * (lo(0) + hi(0)), cy = 0.5 * (lo(1) + hi(1));
    return {cx - side / 2, cy - side / 2, cx + side / 2, cy + side / 2};
}

template <int D>
double plainDeterministic(const Ifs &ifs, const StartSet &start, int depth, int threads)
{
    const Frame f = frameOf(ifs, start);
    const double scale = kSide / (f.x1 - f.x0);
    // Threads split the first level's maps (N >= threads here).
    std::vector<std::unique_ptr<PlainDfs<D>>> k;
    for (int t = 0; t < threads; ++t) {
        k.push_back(std::make_unique<PlainDfs<D>>(ifs, depth, ifs.views.front(), f.x0, f.y1, scale));
        for (int j = 0; j < D; ++j)
            k.back()->x[0][j] = start.vertices(0, j);
    }
    const double t = best(5, [&] {
        onThreads(threads, [&](int th) {
            PlainDfs<D> &w = *k[th];
            for (int i = th; i < ifs.size(); i += threads) {
                const AffineMap &m = ifs.maps[i];
                for (int j = 0; j < D; ++j) {
                    double s = m.b(j);
                    for (int q = 0; q < D; ++q)
                        s += w.x[0][q] * m.A(q, j);
                    w.x[1][j] = s;
                }
                w.walk(1);
            }
        });
    });
    g_sink = g_sink + k[0]->hist[kSide * kSide / 2];
    return t;
}

// ---- the engine -------------------------------------------------------------------------------

EngineJob jobFor(const Ifs &ifs, const StartSet &start, int threads)
{
    const Frame f = frameOf(ifs, start);
    EngineJob job;
    job.ifs = &ifs;
    job.start = start;
    job.frame.width = job.frame.height = kSide;
    job.frame.x0 = f.x0, job.frame.y0 = f.y0, job.frame.x1 = f.x1, job.frame.y1 = f.y1;
    job.colours.prefix = 1;
    job.colours.labelColours.assign(std::size_t(ifs.size()), Rgb8{200, 60, 30});
    job.threads = threads;
    return job;
}

struct Limits {
    double increments[3] = {0, 0, 0};  // by threads
};

void deterministic(const std::string &name, const Ifs &ifs, const StartSet &start, int depth,
                   int threads, double plainSeconds)
{
    EngineJob job = jobFor(ifs, start, threads);
    job.depth = depth;
    DensityImage img;
    IterationStats st;
    const double dt = best(5, [&] { st = accumulate(job, img, {}); });
    std::printf("deterministic  %-28s dim %d  depth %2d  threads %d  %12llu points  %8.4f s  "
                "%7.2f Mpoints/s",
                name.c_str(), ifs.dim(), depth, threads, (unsigned long long)st.images, dt,
                st.images / dt / 1e6);
    if (plainSeconds > 0)
        std::printf("  (%.2fx the plain kernel's time %.4f s)", dt / plainSeconds, plainSeconds);
    std::printf("\n");
}

enum class Colouring { One, ByMap, ByMapInBuckets };

void chaos(const std::string &name, const Ifs &ifs, const RowVec &x0, std::uint64_t samples,
           int threads, double plainRate, double incrementRate,
           Colouring colouring = Colouring::One)
{
    EngineJob job = jobFor(ifs, StartSet::points(Mat(x0)), threads);
    if (colouring != Colouring::One)  // a colour per map: the histogram keeps the maps apart
        for (std::size_t i = 0; i < job.colours.labelColours.size(); ++i)
            job.colours.labelColours[i] = Rgb8{std::uint8_t(60 * i), 120, std::uint8_t(200 - 60 * i)};
    job.labelPlanes = colouring != Colouring::ByMapInBuckets;
    job.random = true;
    job.samples = samples;
    job.accumulation = Accumulation::Density;
    DensityImage img;
    IterationStats st;
    const double dt = best(2, [&] { st = accumulate(job, img, {}); });
    const double rate = st.images / dt / 1e6;
    std::printf("chaos game     %-28s dim %d  samples %.0e  threads %d  %8.3f s  "
                "%7.2f Mpoints/s",
                name.c_str(), ifs.dim(), double(samples), threads, dt, rate);
    if (plainRate > 0)
        std::printf("  (%.2fx the plain kernel, %.2fx random increments)", rate / plainRate,
                    rate / incrementRate);
    std::printf("\n");
}

// Normal-vector Koch scheme (001 scheme 5) for 7 steps from the unit segment, repeated until
// the time is measurable. On 2 threads the polygon after the first step is split into two
// halves subdivided independently (valid here: Koch's beta signs depend on neither level nor
// edge).
void normalVectorKoch(int threads)
{
    const NormalVectorPreset preset = normalVectorPreset(NormalVectorPresetId::Koch);
    const NormalVectorScheme &scheme = preset.scheme;
    std::uint64_t points = 0;
    int reps = 0;
    const auto t0 = std::chrono::steady_clock::now();
    while (seconds(t0) < 0.5) {
        if (threads == 1) {
            points += std::uint64_t(scheme.subdivide(preset.polygon, 7).points.rows());
        } else {
            const ControlPolygon first = scheme.step(preset.polygon, 0);
            const Eigen::Index mid = first.points.rows() / 2;
            ControlPolygon a{first.points.topRows(mid + 1), false};
            ControlPolygon b{first.points.bottomRows(first.points.rows() - mid), false};
            std::uint64_t na = 0, nb = 0;
            std::thread t([&] { na = scheme.subdivide(a, 6, 1).points.rows(); });
            nb = std::uint64_t(scheme.subdivide(b, 6, 1).points.rows());
            t.join();
            points += na + nb - 1;
        }
        ++reps;
    }
    const double dt = seconds(t0);
    std::printf("normal-vector  %-28s 7 steps  threads %d  %12llu points  %8.3f s  "
                "%7.2f Mpoints/s  (%d runs)\n",
                "Koch (001 scheme 5)", threads, (unsigned long long)points, dt,
                points / dt / 1e6, reps);
}

} // namespace

int main(int argc, char **argv)
{
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    std::printf("attractor-bench: %u hardware threads; rasters %dx%d\n",
                std::thread::hardware_concurrency(), kSide, kSide);

    Limits limits;
    for (int threads : {1, 2}) {
        limits.increments[threads] = randomIncrements(threads, quick ? 50'000'000 : 200'000'000);
        std::printf("machine        random increments into %dx%d uint32   threads %d  "
                    "%9.1f Mpoints/s\n",
                    kSide, kSide, threads, limits.increments[threads]);
    }
    const double stores = sequentialStores();
    std::printf("machine        sequential stores of a %dx%d picture          %9.1f GB/s "
                "(%.0f Mpixels/s)\n",
                kSide, kSide, stores, stores * 1e9 / 4 / 1e6);

    // The three-map Sierpinski gasket (000 Fig. 11's maps in the plane): the chaos game.
    const Ifs sier2 = sierpinski2d();
    const std::uint64_t chaosSamples = quick ? 100'000'000 : 400'000'000;
    double plainRate[3] = {0, 0, 0};
    for (int threads : {1, 2}) {
        plainRate[threads] = plainChaos(threads, chaosSamples);
        std::printf("plain kernel   chaos game, Sierpinski in the plane       threads %d  "
                    "%9.1f Mpoints/s  (%.2fx random increments)\n",
                    threads, plainRate[threads], plainRate[threads] / limits.increments[threads]);
    }
    RowVec z0(2);
    z0 << 0.3, 0.3;
    for (int threads : {1, 2})
        chaos("Sierpinski in the plane", sier2, z0, chaosSamples, threads, plainRate[threads],
              limits.increments[threads]);
    for (int threads : {1, 2})
        chaos("Sierpinski, colour by map", sier2, z0, chaosSamples, threads, plainRate[threads],
              limits.increments[threads], Colouring::ByMap);
    for (int threads : {1, 2})
        chaos("Sierpinski, by map, buckets", sier2, z0, chaosSamples, threads, plainRate[threads],
              limits.increments[threads], Colouring::ByMapInBuckets);

    // 000 §4.2: the Sierpinski gasket with 6 control points (lifted 6 x 6 matrices) at depth 13.
    const SubdivisionIfs sier = controlPointFractalIfs(sierpinskiControlPointFractal());
    const StartSet sierStart = StartSet::points(sier.toIfsSpace(Mat::Constant(1, 2, 0.37)));
    double plainSeconds[3] = {0, 0, 0};
    for (int threads : {1, 2}) {
        plainSeconds[threads] = sier.ifs.dim() == 5
                                    ? plainDeterministic<5>(sier.ifs, sierStart, 13, threads)
                                    : 0;
        std::printf("plain kernel   depth-first, Sierpinski, control points   threads %d  "
                    "%9.4f s  (dim %d, depth 13)\n",
                    threads, plainSeconds[threads], sier.ifs.dim());
    }
    for (int threads : {1, 2})
        deterministic("Sierpinski, control points", sier.ifs, sierStart, 13, threads,
                      plainSeconds[threads]);
    chaos("Sierpinski, control points", sier.ifs, sierStart.vertices.row(0),
          quick ? 20'000'000 : 100'000'000, 1, 0, 0);

    for (int threads : {1, 2})
        normalVectorKoch(threads);

    Mat P5(5, 2), P7(7, 2);
    P5 << 0, 0, 1.2, 2.6, 3.2, 3.0, 4.6, 0.6, 6.2, 1.8;
    P7 << 0, 0, 1, 2, 2.5, 2.4, 3.5, 0.6, 5, 0.2, 6, 2.2, 7.5, 2.5;
    const std::vector<std::pair<std::string, SubdivisionIfs>> cases = {
        {"cubic B-spline (5 points)", buildSubdivisionIfs(bsplineScheme(3), P5)},
        {"four-point (7 points)", buildSubdivisionIfs(fourPointScheme(1.0 / 16), P7)},
    };
    const int maxDepth = quick ? 16 : 20;
    for (const auto &[name, s] : cases) {
        const StartSet start = StartSet::points(s.toIfsSpace(Mat::Constant(1, 2, 0.37)));
        for (int depth = 12; depth <= maxDepth; depth += 4)
            for (int threads : {1, 2})
                deterministic(name, s.ifs, start, depth, threads, 0);
        for (int threads : {1, 2})
            chaos(name, s.ifs, start.vertices.row(0), quick ? 10'000'000 : 50'000'000, threads,
                  0, 0);
    }
    return 0;
}
