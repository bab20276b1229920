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


#include "BenchMesh.h"

#include <malloc.h>

#include <atomic>
#include <limits>
#include <memory>
#include <thread>

using namespace awb;
using namespace awb::benchmesh;

namespace {

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

// Route 1: buildMeshPieces, then iterateMesh on 1 and 2 sinks.
std::vector<Figures> ifsRoute(const Case &c, int rounds, const Reference &ref)
{
    MeshPieces pieces;
    double setup = 1e300;
    for (int r = 0; r < rounds; ++r) {
        pieces = {};  // the last round's released first: the peak is one set of pieces'
        setup = std::min(setup, timed([&] { pieces = buildMeshPieces(c.mesh, c.scheme); }));
    }
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
