// attractor-bench-interactive: the interactive path of the desktop application, measured
// without a window. For a drag step on the Sierpinski-with-control-points item (000 Fig. 11):
// the time from a control-point move (one undoable model edit) to the finished raster —
// derived IFS rebuilt, attractor rendered on all cores into an 800 x 800 image, colourised.
// Prints the median and quartiles over many steps at depths 8, 11 and 13 (3^k images of the
// start triangle), through the renderer's synchronous path (the same engine as the view's).
// Run: build/bin/attractor-bench-interactive [examples dir]

#include "gui/views/AttractorRenderer.h"
#include "model/AttractorItem.h"
#include "model/Project.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

using namespace awb;

namespace {

struct Figures {
    double median, q1, q3;
};

// The view's request for the item draws lit pixels grown by one (point size 2) and fills
// the triangle images: `dotRadius` 1 is what a drag in the window asks for.
Figures measure(Project &project, AttractorItem *item, int depth, int steps, int dotRadius = 0,
                int threads = 0)
{
    AlgorithmSpec alg = item->algorithm();
    alg.depth = depth;
    item->setAlgorithm(alg);
    const Point home = item->controlPoints().at(3);
    std::vector<double> ms;
    for (int s = 0; s < steps; ++s) {
        // A drag: small moves of one control point, all in one gesture.
        const int gesture = project.beginGesture();
        const Point p{home.x + 0.002 * (s % 17), home.y - 0.0015 * (s % 11)};
        QElapsedTimer t;
        t.start();
        item->moveControlPoint(3, p, gesture);
        const auto d = item->derivedIfs();
        RenderRequest r;
        r.ifs = std::make_shared<const Ifs>(d->ifs);
        r.start = item->coreStartSet(*d);
        r.depth = depth;
        r.world = QRectF(-0.1, -0.2, 1.2, 1.2);
        r.size = QSize(800, 800);
        r.dotRadius = dotRadius;
        r.threads = threads;
        RenderInfo info;
        const QImage img = AttractorRenderer::renderNow(r, &info);
        ms.push_back(t.nsecsElapsed() * 1e-6);
        if (img.isNull() || info.litPixels == 0) {
            std::fprintf(stderr, "render failed\n");
            std::exit(1);
        }
    }
    std::sort(ms.begin(), ms.end());
    return {ms[ms.size() / 2], ms[ms.size() / 4], ms[3 * ms.size() / 4]};
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QString dir = argc > 1 ? QString::fromLocal8Bit(argv[1])
                                 : QStringLiteral(AWB_BENCH_SOURCE_DIR "/examples");
    Project project;
    QString error;
    if (!project.open(dir + "/000-fig11-sierpinski-with-control-points.awb", &error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    auto *item = qobject_cast<AttractorItem *>(project.child(0));
    const int ownDepth = item->algorithm().depth;
    std::printf("drag step -> finished 800x800 raster, Sierpinski with control points (000 Fig. 11)\n");
    std::printf("(the item's own depth is %d)\n", ownDepth);
    for (auto [depth, steps] : {std::pair{8, 60}, std::pair{11, 40}, std::pair{13, 12}}) {
        const Figures f = measure(project, item, depth, steps);
        std::printf("  depth %2d (%9.0f images of the start triangle): median %8.1f ms  "
                    "(quartiles %.1f .. %.1f ms, %d steps)\n",
                    depth, std::pow(3.0, depth), f.median, f.q1, f.q3, steps);
    }
    // As the window asks: point size 2 (dot radius 1), and the fixed part of a picture
    // (depth 0: clearing, tone mapping, growing the dots) on all cores and on one.
    std::printf("as the attractor view asks (dot radius 1):\n");
    for (auto [depth, steps, threads] : {std::tuple{0, 60, 0}, std::tuple{0, 60, 1},
                                         std::tuple{8, 60, 0}, std::tuple{8, 60, 1},
                                         std::tuple{11, 40, 0}, std::tuple{11, 40, 1}}) {
        const Figures f = measure(project, item, depth, steps, 1, threads);
        std::printf("  depth %2d, %s: median %8.1f ms  (quartiles %.1f .. %.1f ms, %d "
                    "steps)\n",
                    depth, threads == 1 ? "1 thread  " : "all cores ", f.median, f.q1, f.q3,
                    steps);
    }
    return 0;
}
