// attractor-bench-mesh: the limit positions of every vertex of a mesh refined K times (about
// 1 M vertices), four ways, in one run on this machine. Prints figures only.
//   IFS        the mesh's IFS with condensation (MeshPieces.h, MeshIterate.h) from the limit
//              stencils of the pieces' corners (MeshStart::VertexLimits) into sinks that only
//              sum the coordinates, 1 and 2 threads. "setup" is buildMeshPieces (topology of
//              the input only, whatever K). It emits the corners of every face of the refined
//              mesh: a vertex shared by m faces comes m times ("points" column);
//   plain      limitPositions(refineMesh(mesh, K)) (MeshRefine.h), 1 thread: the reference;
//   OSD        OpenSubdiv 3.5: TopologyRefinerFactory<TopologyDescriptor> + RefineUniform(K)
//              ("setup"), PrimvarRefiner::Interpolate level by level and PrimvarRefiner::Limit
//              on level K ("data");
//   OSD table  OpenSubdiv's stencil table of level K's vertices over the input's vertices
//              (StencilTableFactory: vertex interpolation, no intermediate levels, factorized
//              to level 0), then PrimvarRefiner::Limit's limit masks on level K. "setup" is the
//              refiner as above plus the table's creation; "data" is StencilTable::UpdateValues
//              (all of level K from the input, on 1 thread or split in two ranges on 2 threads)
//              plus PrimvarRefiner::Limit (1 thread: it takes no range).
// Every route runs in its own forked child: "peak MB" is the child's VmHWM less its VmRSS at the
// fork, the memory the route itself touched at its peak. Times are the best of --rounds runs of
// each phase; "total" is the sum of the phases' bests. Each route's points are matched to the
// reference's vertices by their positions (the numberings differ): "max diff" is the largest
// distance from a point to the nearest reference vertex over the bounding box's diagonal, and
// a route must reach every reference vertex. For the IFS this check walks the emitted points
// again (a sink that looks each one up): on the smallest depth of each mesh, or all with
// --check.
// Run: nice build/bin/attractor-bench-mesh [--quick] [--case NAME[:DEPTH]] [--rounds N] [--check]

#include "core/mesh/MeshExamples.h"
#include "core/mesh/MeshIterate.h"
#include "core/mesh/MeshPieces.h"
#include "core/mesh/MeshRefine.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <malloc.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

using namespace awb;
namespace osd = OpenSubdiv;

namespace {

volatile double g_sink = 0;  // keeps results alive

double seconds(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double timed(const std::function<void()> &fn)
{
    const auto t0 = std::chrono::steady_clock::now();
    fn();
    return seconds(t0);
}

// A field of /proc/self/status in kB (VmRSS, VmHWM), -1 if absent.
long statusKb(const char *field)
{
    std::ifstream in("/proc/self/status");
    std::string line;
    const std::size_t n = std::strlen(field);
    while (std::getline(in, line))
        if (line.compare(0, n, field) == 0 && line.size() > n && line[n] == ':')
            return std::stol(line.substr(n + 1));
    return -1;
}

// ---- checks -----------------------------------------------------------------------------------

// Nearest-vertex queries on the reference positions: a uniform grid of cells about two vertex
// spacings wide, hashed. A query looks in its own cell, and in the 26 around only when the
// best point found is farther than the cell's nearest wall (rare: the routes agree to 1e-12).
class PointGrid {
public:
    explicit PointGrid(const Mat &points) : m_points(points)
    {
        const Eigen::Index n = points.rows();
        const Eigen::RowVector3d lo = points.colwise().minCoeff(),
                                 hi = points.colwise().maxCoeff();
        // 1.7 (not 2): cell walls on no plane of symmetry of the meshes.
        m_h = std::max((hi - lo).norm(), 1e-300) * 1.7 /
              std::sqrt(double(std::max<Eigen::Index>(n, 1)));
        for (int k = 0; k < 3; ++k)
            m_lo[k] = lo(k) - m_h;
        std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(static_cast<std::size_t>(n));
        for (Eigen::Index i = 0; i < n; ++i) {
            const double x[3] = {points(i, 0), points(i, 1), points(i, 2)};
            int c[3];
            cellOf(x, c);
            keyed[std::size_t(i)] = {key(c[0], c[1], c[2]), std::uint32_t(i)};
        }
        std::sort(keyed.begin(), keyed.end());
        m_order.resize(keyed.size());
        std::size_t cells = 0;
        for (std::size_t i = 0; i < keyed.size(); ++i) {
            m_order[i] = keyed[i].second;
            cells += i == 0 || keyed[i].first != keyed[i - 1].first;
        }
        std::size_t size = 16;
        while (size < 2 * cells)
            size *= 2;
        m_mask = size - 1;
        m_slots.assign(size, Slot{});
        for (std::size_t i = 0; i < keyed.size();) {
            std::size_t j = i;
            while (j < keyed.size() && keyed[j].first == keyed[i].first)
                ++j;
            std::size_t s = hash(keyed[i].first);
            while (m_slots[s].key != kEmpty)
                s = (s + 1) & m_mask;
            m_slots[s] = {keyed[i].first, std::uint32_t(i), std::uint32_t(j)};
            i = j;
        }
    }

    // The row of the nearest reference vertex to x and its distance; (-1, inf) when none is
    // within a cell.
    std::pair<Eigen::Index, double> nearest(const double x[3]) const
    {
        int c[3];
        cellOf(x, c);
        Eigen::Index best = -1;
        double d2 = std::numeric_limits<double>::infinity();
        scan(x, c[0], c[1], c[2], best, d2);
        double wall = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 3; ++k) {
            const double lo = m_lo[k] + c[k] * m_h;
            wall = std::min({wall, x[k] - lo, lo + m_h - x[k]});
        }
        if (!(best >= 0 && std::sqrt(d2) <= wall))
            for (int a = -1; a <= 1; ++a)
                for (int b = -1; b <= 1; ++b)
                    for (int e = -1; e <= 1; ++e)
                        if (a || b || e)
                            scan(x, c[0] + a, c[1] + b, c[2] + e, best, d2);
        return {best, std::sqrt(d2)};
    }

    Eigen::Index size() const { return m_points.rows(); }

private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);
    static constexpr int kBits = 21;
    struct Slot {
        std::uint64_t key = kEmpty;
        std::uint32_t begin = 0, end = 0;
    };

    void cellOf(const double x[3], int c[3]) const
    {
        for (int k = 0; k < 3; ++k)
            c[k] = int(std::clamp(std::floor((x[k] - m_lo[k]) / m_h), 0.0,
                                  double((1 << kBits) - 1)));
    }
    static std::uint64_t key(int a, int b, int c)
    {
        return std::uint64_t(a) << (2 * kBits) | std::uint64_t(b) << kBits | std::uint64_t(c);
    }
    std::size_t hash(std::uint64_t k) const
    {
        return std::size_t((k * 0x9E3779B97F4A7C15ull) >> 20) & m_mask;
    }
    void scan(const double x[3], int a, int b, int c, Eigen::Index &best, double &d2) const
    {
        if (a < 0 || b < 0 || c < 0 || a >= (1 << kBits) || b >= (1 << kBits) || c >= (1 << kBits))
            return;
        const std::uint64_t k = key(a, b, c);
        for (std::size_t s = hash(k); m_slots[s].key != kEmpty; s = (s + 1) & m_mask) {
            if (m_slots[s].key != k)
                continue;
            for (std::uint32_t i = m_slots[s].begin; i < m_slots[s].end; ++i) {
                const Eigen::Index r = m_order[i];
                const double dx = m_points(r, 0) - x[0], dy = m_points(r, 1) - x[1],
                             dz = m_points(r, 2) - x[2];
                const double d = dx * dx + dy * dy + dz * dz;
                if (d < d2)
                    d2 = d, best = r;
            }
            return;
        }
    }

    const Mat &m_points;
    double m_lo[3] = {0, 0, 0}, m_h = 1;
    std::vector<std::uint32_t> m_order;
    std::vector<Slot> m_slots;
    std::size_t m_mask = 0;
};

// A route's points against the reference: the farthest point from its nearest reference vertex,
// and the reference vertices no point was nearest to.
struct Check {
    explicit Check(const PointGrid &g) : grid(g), hit(std::size_t(g.size()), 0) {}
    void add(const double x[3])
    {
        const auto [row, d] = grid.nearest(x);
        worst = std::max(worst, d);
        if (row >= 0)
            hit[std::size_t(row)] = 1;
    }
    void addRows(const Mat &m)
    {
        for (Eigen::Index i = 0; i < m.rows(); ++i) {
            const double x[3] = {m(i, 0), m(i, 1), m(i, 2)};
            add(x);
        }
    }
    double missing() const { return double(std::count(hit.begin(), hit.end(), 0)); }

    const PointGrid &grid;
    std::vector<char> hit;
    double worst = 0;
};

// The IFS's sinks: the sum of the coordinates (so that nothing is optimised away), one sink per
// thread, on its own cache lines.
class alignas(64) SumSink : public AttractorSink {
public:
    void consume(const Mat &v, StartSet::Kind, const std::uint8_t *, int) override
    {
        sum += v.sum();
        points += std::uint64_t(v.rows());
    }
    double sum = 0;
    std::uint64_t points = 0;
};

// "; thread 0 drew 50%" for two or more sinks: how the roots were shared out.
std::string firstShare(const std::vector<std::unique_ptr<SumSink>> &sinks)
{
    if (sinks.size() < 2)
        return "";
    double all = 0;
    for (const auto &s : sinks)
        all += double(s->points);
    char buf[48];
    std::snprintf(buf, sizeof buf, "; thread 0 drew %.0f%%",
                  100.0 * double(sinks.front()->points) / std::max(all, 1.0));
    return buf;
}

class CheckSink : public AttractorSink {
public:
    explicit CheckSink(Check &c) : check(c) {}
    void consume(const Mat &v, StartSet::Kind, const std::uint8_t *, int) override
    {
        check.addRows(v);
    }
    Check &check;
};

// ---- routes in child processes ----------------------------------------------------------------

// One line of the table, passed from the child through a pipe (plain data).
struct Figures {
    char route[40] = "";
    int threads = 1;
    double setup = NAN, data = NAN, total = NAN;  // seconds
    double points = NAN;    // points the route produced
    double peakMb = NAN;
    double diff = NAN;      // max distance to the reference over the diagonal; NAN: not checked
    double missing = 0;     // reference vertices no point reached
    char notes[200] = "";
    char error[200] = "";
};

struct Reference {
    const PointGrid *grid = nullptr;
    double diagonal = 1;
};

long g_forkRssKb = 0;  // the child's VmRSS at the fork

double peakMbSinceFork()
{
    const long hwm = statusKb("VmHWM");
    return hwm < 0 ? NAN : double(hwm - g_forkRssKb) / 1024.0;
}

void fillDiff(Figures &f, const Check &c, const Reference &ref)
{
    f.diff = c.worst / ref.diagonal;
    f.missing = c.missing();
}

bool writeAll(int fd, const void *p, std::size_t n)
{
    const char *c = static_cast<const char *>(p);
    while (n > 0) {
        const ssize_t w = write(fd, c, n);
        if (w <= 0)
            return false;
        c += w, n -= std::size_t(w);
    }
    return true;
}

bool readAll(int fd, void *p, std::size_t n)
{
    char *c = static_cast<char *>(p);
    while (n > 0) {
        const ssize_t r = read(fd, c, n);
        if (r <= 0)
            return false;
        c += r, n -= std::size_t(r);
    }
    return true;
}

// Runs fn(figures, positions) in a forked child; returns its figures, and its positions (n x 3)
// in *positions when given. A child that dies gives one line with the error.
template <typename Fn>
std::vector<Figures> inChild(const char *route, Fn fn, Mat *positions = nullptr)
{
    std::fflush(stdout);
    int fd[2];
    if (pipe(fd) != 0) {
        Figures f;
        std::snprintf(f.route, sizeof f.route, "%s", route);
        std::snprintf(f.error, sizeof f.error, "pipe() failed");
        return {f};
    }
    const pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        g_forkRssKb = statusKb("VmRSS");
        std::vector<Figures> out;
        Mat pos;
        try {
            fn(out, pos);
        } catch (const std::exception &e) {
            Figures f;
            std::snprintf(f.route, sizeof f.route, "%s", route);
            std::snprintf(f.error, sizeof f.error, "%s", e.what());
            out.assign(1, f);
        }
        const std::uint64_t count = out.size(), rows = std::uint64_t(pos.rows());
        const bool ok = writeAll(fd[1], &count, sizeof count) &&
                        writeAll(fd[1], out.data(), count * sizeof(Figures)) &&
                        writeAll(fd[1], &rows, sizeof rows) &&
                        writeAll(fd[1], pos.data(), rows * 3 * sizeof(double));
        _exit(ok ? 0 : 1);
    }
    close(fd[1]);
    std::vector<Figures> out;
    std::uint64_t count = 0, rows = 0;
    bool ok = pid > 0 && readAll(fd[0], &count, sizeof count) && count < 100;
    if (ok) {
        out.resize(count);
        ok = readAll(fd[0], out.data(), count * sizeof(Figures)) &&
             readAll(fd[0], &rows, sizeof rows);
    }
    if (ok && positions) {
        positions->resize(Eigen::Index(rows), 3);
        ok = readAll(fd[0], positions->data(), rows * 3 * sizeof(double));
    }
    close(fd[0]);
    int status = 0;
    if (pid > 0)
        waitpid(pid, &status, 0);
    if (!ok) {
        Figures f;
        std::snprintf(f.route, sizeof f.route, "%s", route);
        if (WIFSIGNALED(status))
            std::snprintf(f.error, sizeof f.error, "the child died of signal %d (%s)",
                          WTERMSIG(status), strsignal(WTERMSIG(status)));
        else
            std::snprintf(f.error, sizeof f.error, "the child failed (status %d)", status);
        out.assign(1, f);
    }
    return out;
}

struct Case {
    std::string name;  // mesh-scheme
    Mesh mesh;
    MeshScheme scheme;
    int depth;
    bool checkIfs;  // match the IFS's emitted points to the reference too
};

// Route 1: buildMeshPieces, then iterateMesh on 1 and 2 sinks.
std::vector<Figures> ifsRoute(const Case &c, int rounds, const Reference &ref)
{
    MeshPieces pieces;
    double setup = 1e300;
    for (int r = 0; r < rounds; ++r)
        setup = std::min(setup, timed([&] { pieces = buildMeshPieces(c.mesh, c.scheme); }));
    std::vector<Figures> out;
    for (int threads : {1, 2}) {
        std::vector<std::unique_ptr<SumSink>> sinks;
        std::vector<AttractorSink *> ptrs;
        for (int t = 0; t < threads; ++t) {
            sinks.push_back(std::make_unique<SumSink>());
            ptrs.push_back(sinks.back().get());
        }
        double data = 1e300, points = 0;
        for (int r = 0; r < rounds; ++r) {
            for (auto &s : sinks)
                *s = SumSink();
            data = std::min(data, timed([&] {
                iterateMesh(pieces, c.mesh.vertices, MeshStart{}, c.depth, ptrs, {});
            }));
            points = 0;
            for (auto &s : sinks)
                g_sink = g_sink + s->sum, points += double(s->points);
        }
        Figures f;
        std::snprintf(f.route, sizeof f.route, "IFS with condensation");
        f.threads = threads;
        f.setup = setup;
        f.data = data;
        f.total = setup + data;
        f.points = points;
        std::snprintf(f.notes, sizeof f.notes, "%d isolation steps, %zu piece types, %zu roots%s",
                      pieces.steps, pieces.types.size(), pieces.roots.size(),
                      firstShare(sinks).c_str());
        out.push_back(f);
    }
    const double peak = peakMbSinceFork();
    for (Figures &f : out)
        f.peakMb = peak;
    if (c.checkIfs) {
        Check check(*ref.grid);
        CheckSink sink(check);
        iterateMesh(pieces, c.mesh.vertices, MeshStart{}, c.depth, {&sink}, {});
        for (Figures &f : out)
            fillDiff(f, check, ref);
    }
    return out;
}


// Route 2, the reference: limitPositions(refineMesh(mesh, K)).
std::vector<Figures> plainRoute(const Case &c, int rounds, Mat &positions)
{
    double refine = 1e300, limit = 1e300;
    for (int r = 0; r < rounds; ++r) {
        Mesh refined;
        refine = std::min(refine, timed([&] { refined = refineMesh(c.mesh, c.scheme, c.depth); }));
        limit = std::min(limit, timed([&] { positions = limitPositions(refined, c.scheme); }));
    }
    Figures f;
    std::snprintf(f.route, sizeof f.route, "plain: refineMesh+limitPositions");
    f.total = refine + limit;
    f.points = double(positions.rows());
    f.peakMb = peakMbSinceFork();
    f.diff = 0;
    std::snprintf(f.notes, sizeof f.notes, "reference; refineMesh %.4f s, limitPositions %.4f s",
                  refine, limit);
    return {f};
}

// OpenSubdiv's primvar: three doubles with the two members PrimvarRefiner and StencilTable use.
struct OsdPoint {
    double p[3];
    void Clear(void * = nullptr) { p[0] = p[1] = p[2] = 0; }
    void AddWithWeight(const OsdPoint &s, double w)
    {
        p[0] += w * s.p[0];
        p[1] += w * s.p[1];
        p[2] += w * s.p[2];
    }
};

// The mesh as OpenSubdiv's descriptor, with the options of tests/core/test_mesh_opensubdiv.cpp
// (the ones under which both agree): boundary vertices interpolated along edges only,
// triangles in a Catmull-Clark mesh by Catmull-Clark's rules.
struct OsdInput {
    explicit OsdInput(const Mesh &m, MeshScheme s) : scheme(s)
    {
        for (const auto &f : m.faces) {
            counts.push_back(int(f.size()));
            indices.insert(indices.end(), f.begin(), f.end());
        }
        desc.numVertices = int(m.vertices.rows());
        desc.numFaces = int(m.faces.size());
        desc.numVertsPerFace = counts.data();
        desc.vertIndicesPerFace = indices.data();
        control.resize(std::size_t(m.vertices.rows()));
        for (Eigen::Index v = 0; v < m.vertices.rows(); ++v)
            for (int k = 0; k < 3; ++k)
                control[std::size_t(v)].p[k] = m.vertices(v, k);
    }
    // Topology only: the factory and the uniform refinement to `levels`, with the full topology
    // of the last level (PrimvarRefiner::Limit needs it).
    std::unique_ptr<osd::Far::TopologyRefiner> refiner(int levels) const
    {
        osd::Sdc::Options options;
        options.SetVtxBoundaryInterpolation(osd::Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
        options.SetTriangleSubdivision(osd::Sdc::Options::TRI_SUB_CATMARK);
        using Factory = osd::Far::TopologyRefinerFactory<osd::Far::TopologyDescriptor>;
        const auto type =
            scheme == MeshScheme::Loop ? osd::Sdc::SCHEME_LOOP : osd::Sdc::SCHEME_CATMARK;
        std::unique_ptr<osd::Far::TopologyRefiner> r(
            Factory::Create(desc, Factory::Options(type, options)));
        osd::Far::TopologyRefiner::UniformOptions uniform(levels);
        uniform.fullTopologyInLastLevel = true;
        r->RefineUniform(uniform);
        return r;
    }

    MeshScheme scheme;
    std::vector<int> counts, indices;
    osd::Far::TopologyDescriptor desc;
    std::vector<OsdPoint> control;
};

// Route 3: refiner (setup), Interpolate level by level and Limit (data).
std::vector<Figures> osdRoute(const Case &c, int rounds, const Reference &ref)
{
    const OsdInput input(c.mesh, c.scheme);
    double setup = 1e300, interp = 1e300, limit = 1e300;
    std::vector<OsdPoint> limits;
    for (int r = 0; r < rounds; ++r) {
        std::unique_ptr<osd::Far::TopologyRefiner> refiner;
        setup = std::min(setup, timed([&] { refiner = input.refiner(c.depth); }));
        std::vector<OsdPoint> buffer;
        OsdPoint *src = nullptr;
        interp = std::min(interp, timed([&] {
            buffer.resize(std::size_t(refiner->GetNumVerticesTotal()));
            std::copy(input.control.begin(), input.control.end(), buffer.begin());
            osd::Far::PrimvarRefinerReal<double> primvar(*refiner);
            src = buffer.data();
            for (int level = 1; level <= c.depth; ++level) {
                OsdPoint *dst = src + refiner->GetLevel(level - 1).GetNumVertices();
                primvar.Interpolate(level, src, dst);
                src = dst;
            }
        }));
        limit = std::min(limit, timed([&] {
            limits.assign(std::size_t(refiner->GetLevel(c.depth).GetNumVertices()), OsdPoint{});
            osd::Far::PrimvarRefinerReal<double> primvar(*refiner);
            primvar.Limit(src, limits);
        }));
    }
    Figures f;
    std::snprintf(f.route, sizeof f.route, "OSD: Interpolate+Limit");
    f.setup = setup;
    f.data = interp + limit;
    f.total = setup + interp + limit;
    f.points = double(limits.size());
    f.peakMb = peakMbSinceFork();
    std::snprintf(f.notes, sizeof f.notes, "Interpolate %.4f s, Limit %.4f s", interp, limit);
    Check check(*ref.grid);
    for (const OsdPoint &p : limits)
        check.add(p.p);
    fillDiff(f, check, ref);
    return {f};
}

// Route 4: refiner and stencil table (setup), UpdateValues on 1 or 2 threads and Limit (data).
std::vector<Figures> osdTableRoute(const Case &c, int rounds, const Reference &ref)
{
    using Table = osd::Far::StencilTableReal<double>;
    using TableFactory = osd::Far::StencilTableFactoryReal<double>;
    const OsdInput input(c.mesh, c.scheme);
    double refine = 1e300, create = 1e300;
    std::unique_ptr<osd::Far::TopologyRefiner> refiner;
    std::unique_ptr<const Table> table;
    for (int r = 0; r < rounds; ++r) {
        table.reset();
        refiner.reset();
        refine = std::min(refine, timed([&] { refiner = input.refiner(c.depth); }));
        create = std::min(create, timed([&] {
            TableFactory::Options options;
            options.interpolationMode = TableFactory::INTERPOLATE_VERTEX;
            options.generateOffsets = true;  // UpdateValues on a range needs them
            options.generateControlVerts = false;
            options.generateIntermediateLevels = false;
            options.factorizeIntermediateLevels = true;
            options.maxLevel = unsigned(c.depth);
            table.reset(TableFactory::Create(*refiner, options));
        }));
    }
    const int n = table->GetNumStencils();
    std::vector<OsdPoint> level(static_cast<std::size_t>(n)), limits(static_cast<std::size_t>(n));
    double apply[3] = {0, 1e300, 1e300};
    for (int threads : {1, 2})
        for (int r = 0; r < rounds; ++r)
            apply[threads] = std::min(apply[threads], timed([&] {
                const OsdPoint *src = input.control.data();
                OsdPoint *dst = level.data();
                if (threads == 1) {
                    table->UpdateValues(src, dst);
                } else {
                    std::thread other([&] { table->UpdateValues(src, dst, n / 2, n); });
                    table->UpdateValues(src, dst, 0, n / 2);
                    other.join();
                }
            }));
    double limit = 1e300;
    const osd::Far::PrimvarRefinerReal<double> primvar(*refiner);
    for (int r = 0; r < rounds; ++r)
        limit = std::min(limit, timed([&] {
            const OsdPoint *src = level.data();
            primvar.Limit(src, limits);
        }));
    const double peak = peakMbSinceFork();
    Check check(*ref.grid);
    for (const OsdPoint &p : limits)
        check.add(p.p);
    std::vector<Figures> out;
    for (int threads : {1, 2}) {
        Figures f;
        std::snprintf(f.route, sizeof f.route, "OSD: stencil table+Limit");
        f.threads = threads;
        f.setup = refine + create;
        f.data = apply[threads] + limit;
        f.total = f.setup + f.data;
        f.points = double(n);
        f.peakMb = peak;
        std::snprintf(f.notes, sizeof f.notes,
                      "refiner %.4f s, table %.4f s (%.1f entries/stencil); UpdateValues "
                      "%.4f s, Limit %.4f s",
                      refine, create, double(table->GetWeights().size()) / std::max(n, 1),
                      apply[threads], limit);
        fillDiff(f, check, ref);
        out.push_back(f);
    }
    return out;
}

// ---- the table --------------------------------------------------------------------------------

void printHeader()
{
    std::printf("  %-32s %3s %9s %9s %9s %8s %8s %8s %8s %8s %9s  %s\n", "route", "thr", "setup s",
                "data s", "total s", "Mvtx/s", "Mvtx/s", "Mpts/s", "points", "peak MB",
                "max diff", "notes");
    std::printf("  %-32s %3s %9s %9s %9s %8s %8s %8s %8s %8s %9s\n", "", "", "", "", "", "data",
                "total", "data", "M", "", "/diag");
}

std::string fixed(double x, const char *format)
{
    if (std::isnan(x))
        return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, format, x);
    return buf;
}

void printRow(const Figures &f, double vertices)
{
    if (f.error[0]) {
        std::printf("  %-32s %3d  failed: %s\n", f.route, f.threads, f.error);
        std::fflush(stdout);
        return;
    }
    std::string diff = fixed(f.diff, "%9.1e");
    if (f.missing > 0)
        diff = fixed(f.missing, "%.0f") + " missed";
    const bool ifs = std::strncmp(f.route, "IFS", 3) == 0;
    std::printf("  %-32s %3d %9s %9s %9s %8s %8s %8s %8s %8s %9s  %s\n", f.route, f.threads,
                fixed(f.setup, "%9.4f").c_str(), fixed(f.data, "%9.4f").c_str(),
                fixed(f.total, "%9.4f").c_str(), fixed(vertices / f.data / 1e6, "%8.2f").c_str(),
                fixed(vertices / f.total / 1e6, "%8.2f").c_str(),
                ifs ? fixed(f.points / f.data / 1e6, "%8.2f").c_str() : "-",
                fixed(f.points / 1e6, "%8.3f").c_str(), fixed(f.peakMb, "%8.1f").c_str(),
                diff.c_str(), f.notes);
    std::fflush(stdout);
}

void runCase(const Case &c, int rounds)
{
    Mat reference;
    const std::vector<Figures> plain =
        inChild("plain", [&](std::vector<Figures> &out, Mat &pos) {
            out = plainRoute(c, rounds, pos);
        }, &reference);
    const double vertices = double(reference.rows());
    const MeshPieces pieces = buildMeshPieces(c.mesh, c.scheme);
    const double emitted = meshPointCount(pieces, MeshStart{}, c.depth);
    std::printf("\n%s, depth %d: %zu faces -> %.0f vertices; the IFS emits %.0f points "
                "(%.2f per vertex)\n",
                c.name.c_str(), c.depth, c.mesh.faces.size(), vertices, emitted,
                emitted / vertices);
    printHeader();
    for (const Figures &f : plain)
        printRow(f, vertices);
    if (reference.rows() == 0)
        return;
    const PointGrid grid(reference);
    const Reference ref{
        &grid, (reference.colwise().maxCoeff() - reference.colwise().minCoeff()).norm()};
    malloc_trim(0);  // what the parent freed is not there for a child to reuse unseen
    const auto run = [&](const char *route, auto fn) {
        for (const Figures &f : inChild(route, [&](std::vector<Figures> &out, Mat &) {
                 out = fn(c, rounds, ref);
             }))
            printRow(f, vertices);
    };
    run("IFS", ifsRoute);
    run("OSD", osdRoute);
    run("OSD table", osdTableRoute);
}

struct CaseSpec {
    const char *name;
    Mesh (*mesh)();
    MeshScheme scheme;
    std::vector<int> depths, quickDepths;
};

Mesh diagonalGrid() { return diagonalGridMesh(20, 20, 1); }

// Production-sized meshes (issue 44): a torus of 200 x 200 quads each split in two triangles
// (80 000 triangles, interior valence 6) under Catmull-Clark, whose every face centre becomes a
// valence-3 vertex; a UV sphere of 64 segments and 32 rings, triangles at its two valence-64
// poles.
Mesh torusTriangles() { return torusMesh(200, 200, true); }
Mesh uvSphere() { return uvSphereMesh(64, 32); }

int usage(const char *argv0)
{
    std::fprintf(stderr,
                 "usage: %s [--quick] [--case NAME[:DEPTH]] [--rounds N] [--check]\n"
                 "cases: cube-catmull-clark, icosahedron-loop, diagonal-grid-loop, "
                 "diagonal-grid-catmull-clark, torus-triangles-catmull-clark, "
                 "uv-sphere-catmull-clark\n",
                 argv0);
    return 2;
}

} // namespace

int main(int argc, char **argv)
{
    bool quick = false, checkAll = false;
    int rounds = 3, onlyDepth = -1;
    std::string only;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--quick") {
            quick = true;
        } else if (a == "--check") {
            checkAll = true;
        } else if (a == "--rounds" && i + 1 < argc) {
            rounds = std::max(1, std::atoi(argv[++i]));
        } else if (a == "--case" && i + 1 < argc) {
            only = argv[++i];
            const std::size_t colon = only.find(':');
            if (colon != std::string::npos) {
                onlyDepth = std::atoi(only.c_str() + colon + 1);
                only.resize(colon);
            }
        } else {
            return usage(argv[0]);
        }
    }
    // ~1 M vertices: the cube 6 * 4^K faces, the icosahedron 20 * 4^K, the 20 x 20 grid of 800
    // triangles 800 * 4^K (Loop) or 2400 * 4^(K-1) quads (Catmull-Clark).
    const CaseSpec specs[] = {
        {"cube-catmull-clark", cubeMesh, MeshScheme::CatmullClark, {8, 9}, {5, 6}},
        {"icosahedron-loop", icosahedronMesh, MeshScheme::Loop, {8, 9}, {5, 6}},
        {"diagonal-grid-loop", diagonalGrid, MeshScheme::Loop, {6}, {4}},
        {"diagonal-grid-catmull-clark", diagonalGrid, MeshScheme::CatmullClark, {5}, {3}},
        // 80 000 triangles: 960 000 quads at K = 2; the sphere's 2 048 faces: 524 288 at K = 4.
        {"torus-triangles-catmull-clark", torusTriangles, MeshScheme::CatmullClark, {2}, {1}},
        {"uv-sphere-catmull-clark", uvSphere, MeshScheme::CatmullClark, {4}, {3}},
    };
    bool found = only.empty();
    for (const CaseSpec &s : specs)
        found = found || only == s.name;
    if (!found)
        return usage(argv[0]);
    std::printf("attractor-bench-mesh: limit positions of every vertex of a mesh refined K times; "
                "%u hardware threads, best of %d rounds%s\n",
                std::thread::hardware_concurrency(), rounds, quick ? ", quick" : "");
    std::printf("Mvtx/s: distinct vertices of the refined mesh per second; Mpts/s: points the "
                "IFS emits (face corners) per second; peak MB: the route's own (VmHWM less the "
                "RSS at its fork)\n");
    for (const CaseSpec &s : specs) {
        if (!only.empty() && only != s.name)
            continue;
        const std::vector<int> &depths = onlyDepth >= 0 ? std::vector<int>{onlyDepth}
                                         : quick       ? s.quickDepths
                                                       : s.depths;
        for (std::size_t d = 0; d < depths.size(); ++d) {
            const Case c{s.name, s.mesh(), s.scheme, depths[d], checkAll || d == 0};
            runCase(c, rounds);
        }
    }
    return 0;
}
