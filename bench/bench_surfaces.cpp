// attractor-bench-surfaces: time to draw each surface patch of 000 §3 at depth 6 and 8 on this
// machine: deterministic iteration of a start triangle through the lifted IFS into the CPU
// surface raster (900 x 700, the CLI's render path), on 1 thread and on all cores; and the
// 3D view's path, the mesh of the same images (world-space triangles, one per image and view)
// on all cores.
// Run: build/bin/attractor-bench-surfaces [--quick]   (quick: depth 6 only)

#include "core/ifs/SurfaceIfs.h"
#include "core/render/SurfaceMesh.h"
#include "core/render/SurfaceRaster.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <thread>

using namespace awb;

namespace {

double drawSeconds(const SurfaceIfs &s, const StartSet &start, int depth, int threads,
                   std::uint64_t *covered)
{
    const OrthoCamera camera = OrthoCamera::fit(s.ifs.controlPoints, -60, 30, 900.0 / 700.0);
    std::vector<std::unique_ptr<SurfaceRaster>> rasters;
    std::vector<AttractorSink *> sinks;
    for (int t = 0; t < threads; ++t) {
        rasters.push_back(std::make_unique<SurfaceRaster>(900, 700, camera, s.ifs.ifs.views));
        sinks.push_back(rasters.back().get());
    }
    const auto t0 = std::chrono::steady_clock::now();
    iterateParallel(s.ifs.ifs, start, depth, sinks);
    for (size_t t = 1; t < rasters.size(); ++t)
        rasters.front()->merge(*rasters[t]);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    *covered = rasters.front()->coveredPixels();
    return sec;
}

double meshSeconds(const SurfaceIfs &s, const StartSet &start, int depth, int threads,
                   std::size_t *triangles)
{
    const auto t0 = std::chrono::steady_clock::now();
    const SurfaceMesh mesh = buildSurfaceMesh(s.ifs.ifs, start, depth, {}, {}, threads);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    *triangles = mesh.size();
    return sec;
}

} // namespace

int main(int argc, char **argv)
{
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    struct Case {
        const char *name;
        LatticeScheme (*scheme)();
        const char *layout;
    };
    const Case cases[] = {{"bicubic/square", bicubicScheme, "square"},
                          {"loop/triangle", loopScheme, "triangle"},
                          {"loop/hexagon", loopScheme, "hexagon"},
                          {"sqrt3/triangle", sqrt3Scheme, "triangle"},
                          {"sqrt3/hexagon", sqrt3Scheme, "hexagon"}};
    std::printf("# surface patches: start triangle -> F^k(X0) -> 900x700 z-buffer raster\n");
    std::printf("# %-15s %5s %4s %12s %9s %10s %10s %9s %10s %10s\n", "scheme/layout", "maps",
                "dim", "depth:images", "", "1 thread", "threads", "pixels", "3D mesh", "triangles");
    for (const Case &c : cases) {
        const LatticeScheme scheme = c.scheme();
        const PatchLayout layout = patchLayout(scheme, c.layout);
        const SurfaceMatrices m = surfaceMatrices(scheme, layout);
        Mat P(Eigen::Index(m.net.size()), 3);
        for (size_t k = 0; k < m.net.size(); ++k) {
            const Eigen::Vector2d x =
                latticePosition(scheme.lattice(), {double(m.net[k].i), double(m.net[k].j)});
            P.row(Eigen::Index(k)) << x.x(), x.y(), 0.25 * x.squaredNorm() + 0.1 * std::sin(3 * x.x());
        }
        const SurfaceIfs s = buildSurfaceIfs(scheme, layout, m.net, P);
        const Mat tri = s.ifs.toIfsSpace(P.topRows(3));
        const StartSet start = StartSet::polygon(tri);
        for (int depth : {6, 8}) {
            if (quick && depth == 8)
                continue;
            const double images = imageCount(s.ifs.ifs, depth);
            if (images > 2147483648.0) {
                std::printf("%-17s %5d %4d %3d:%-9.3g refused: more than 2^31 images\n", c.name,
                            s.ifs.ifs.size(), s.ifs.ifs.dim(), depth, images);
                continue;
            }
            std::uint64_t covered = 0;
            const double one = images > 5e7 ? NAN : drawSeconds(s, start, depth, 1, &covered);
            const double all = drawSeconds(s, start, depth, cores, &covered);
            std::size_t triangles = 0;
            const double mesh = images * s.ifs.ifs.views.size() > 2e7
                                    ? NAN : meshSeconds(s, start, depth, cores, &triangles);
            std::printf("%-17s %5d %4d %3d:%-9.3g %9s %8.3f s %8.3f s %9llu %8.3f s %10zu\n",
                        c.name, s.ifs.ifs.size(), s.ifs.ifs.dim(), depth, images, "", one, all,
                        (unsigned long long)covered, mesh, triangles);
            std::fflush(stdout);
        }
    }
    return 0;
}
