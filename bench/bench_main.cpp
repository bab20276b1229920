// attractor-bench: throughput of the attractor engine on this machine. Prints figures only;
// goals are set elsewhere. Run: build/bin/attractor-bench [--quick]

#include "core/ifs/Attractor.h"
#include "core/schemes/ControlPointFractal.h"
#include "core/schemes/NormalVectorScheme.h"
#include "core/schemes/Scheme.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>

using namespace awb;

namespace {

// Projects every image (as a renderer must) and folds it into a checksum, so that nothing is
// optimised away; no memory grows with the depth.
class ChecksumSink : public AttractorSink {
public:
    explicit ChecksumSink(Projection v) : m_view(std::move(v)) {}
    void consume(const Mat &v, StartSet::Kind, const std::uint8_t *a, int n) override
    {
        m_p.noalias() = v * m_view.V;
        m_sum += m_p.sum() + (n ? a[0] : 0);
        m_count += std::uint64_t(v.rows());
    }
    double sum() const { return m_sum; }
    std::uint64_t count() const { return m_count; }

private:
    Projection m_view;
    Mat m_p;
    double m_sum = 0;
    std::uint64_t m_count = 0;
};

double seconds(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Case {
    std::string name;
    SubdivisionIfs s;
};

void deterministic(const Case &c, int depth, int threads)
{
    std::vector<ChecksumSink> sinks(threads, ChecksumSink(c.s.ifs.views.front()));
    std::vector<AttractorSink *> ptrs;
    for (auto &s : sinks)
        ptrs.push_back(&s);
    const StartSet start = StartSet::points(c.s.toIfsSpace(Mat::Constant(1, 2, 0.37)));
    const auto t0 = std::chrono::steady_clock::now();
    const IterationStats st = iterateParallel(c.s.ifs, start, depth, ptrs);
    const double dt = seconds(t0);
    double sum = 0;
    for (auto &s : sinks)
        sum += s.sum();
    std::printf("deterministic  %-28s dim %d  depth %2d  threads %d  %12llu points  %8.3f s  "
                "%7.2f Mpoints/s  (checksum %.3g)\n",
                c.name.c_str(), c.s.ifs.dim(), depth, threads, (unsigned long long)st.images, dt,
                st.images / dt / 1e6, sum);
}

void chaos(const Case &c, std::uint64_t samples, int threads)
{
    std::vector<ChecksumSink> sinks(threads, ChecksumSink(c.s.ifs.views.front()));
    std::vector<AttractorSink *> ptrs;
    for (auto &s : sinks)
        ptrs.push_back(&s);
    ChaosOptions opt;
    opt.samples = samples;
    const auto t0 = std::chrono::steady_clock::now();
    const IterationStats st = chaosGameParallel(
        c.s.ifs, c.s.toIfsSpace(Mat::Constant(1, 2, 0.37)).row(0), opt, ptrs);
    const double dt = seconds(t0);
    std::printf("chaos game     %-28s dim %d  samples %.0e  threads %d  %8.3f s  "
                "%7.2f Mpoints/s\n",
                c.name.c_str(), c.s.ifs.dim(), double(samples), threads, dt,
                st.images / dt / 1e6);
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
    std::printf("attractor-bench: %u hardware threads\n", std::thread::hardware_concurrency());
    Mat P5(5, 2), P7(7, 2);
    P5 << 0, 0, 1.2, 2.6, 3.2, 3.0, 4.6, 0.6, 6.2, 1.8;
    P7 << 0, 0, 1, 2, 2.5, 2.4, 3.5, 0.6, 5, 0.2, 6, 2.2, 7.5, 2.5;
    const std::vector<Case> cases = {
        {"cubic B-spline (5 points)", buildSubdivisionIfs(bsplineScheme(3), P5)},
        {"four-point (7 points)", buildSubdivisionIfs(fourPointScheme(1.0 / 16), P7)},
    };
    // 000 §4.2: the Sierpinski gasket with 6 control points (lifted 6 x 6 matrices) at depth 13.
    const Case sierpinski{"Sierpinski, control points",
                          controlPointFractalIfs(sierpinskiControlPointFractal())};
    for (int threads : {1, 2})
        deterministic(sierpinski, 13, threads);
    for (int threads : {1, 2})
        normalVectorKoch(threads);
    const int maxDepth = quick ? 16 : 20;
    for (const Case &c : cases)
        for (int depth = 12; depth <= maxDepth; depth += 4)
            for (int threads : {1, 2})
                deterministic(c, depth, threads);
    for (const Case &c : cases)
        for (int threads : {1, 2})
            chaos(c, quick ? 1'000'000 : 10'000'000, threads);
    return 0;
}
