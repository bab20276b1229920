#include "render/SurfaceFigure.h"

#include "render/FigureFile.h"

#include <QCoreApplication>
#include <QFontMetrics>
#include <QPainter>

#include <algorithm>
#include <thread>

namespace awb {

namespace {

constexpr int kCaptionHeight = 26;

int pictureHeight(const SurfaceFigureSpec &spec)
{
    return std::max(16, spec.height - (spec.caption.isEmpty() ? 0 : kCaptionHeight));
}

int threadCount(const SurfaceFigureSpec &spec)
{
    const int hw = int(std::max(1u, std::thread::hardware_concurrency()));
    return std::clamp(spec.threads > 0 ? spec.threads : hw, 1, 64);
}

} // namespace

OrthoCamera surfaceCamera(const SurfaceFigureSpec &spec, int height)
{
    // A coarse iterate (about 4096 images) tells where the attractor is; the frame points
    // (the control net) are added so that the net is in the picture too.
    std::vector<Mat> parts;
    if (spec.framePoints.rows() > 0)
        parts.push_back(spec.framePoints);
    if (spec.ifs && spec.iterate && !spec.ifs->views.empty()) {
        // The item's own images at depth 0: its pieces.
        PointCollector c(spec.ifs->views.front(), 200000);
        try {
            spec.iterate(spec.start, 0, {&c}, {});
            if (c.points().cols() == 3 && c.points().allFinite())
                parts.push_back(c.points());
        } catch (const InputError &) {
        }
    } else if (spec.ifs && spec.ifs->size() > 0 && !spec.ifs->views.empty()) {
        int depth = 0;
        while (depth < spec.depth && imageCount(*spec.ifs, depth + 1) <= 4096)
            ++depth;
        PointCollector c(spec.ifs->views.front(), 200000);
        try {
            iterate(*spec.ifs, spec.start, depth, c);
            if (c.points().cols() == 3 && c.points().allFinite())
                parts.push_back(c.points());
        } catch (const InputError &) {
        }
    }
    Eigen::Index n = 0;
    for (const Mat &m : parts)
        n += m.rows();
    Mat all(n, 3);
    Eigen::Index r = 0;
    for (const Mat &m : parts) {
        all.middleRows(r, m.rows()) = m;
        r += m.rows();
    }
    return OrthoCamera::fit(all, spec.azimuth, spec.elevation,
                            double(spec.width) / std::max(height, 1));
}

QImage renderSurfaceFigure(const SurfaceFigureSpec &spec, IterationStats *statsOut)
{
    const int h = pictureHeight(spec);
    const OrthoCamera camera = surfaceCamera(spec, h);
    const int threads = threadCount(spec);
    std::vector<std::unique_ptr<SurfaceRaster>> rasters;
    std::vector<AttractorSink *> sinks;
    IterationStats stats;
    if (spec.ifs && (spec.ifs->size() > 0 || spec.iterate)) {
        for (int t = 0; t < threads; ++t) {
            rasters.push_back(std::make_unique<SurfaceRaster>(
                spec.width, h, camera, spec.ifs->views, spec.mapColors, spec.pointRadius));
            sinks.push_back(rasters.back().get());
        }
        const IterationControl &control = spec.control;
        if (spec.iterate) {
            stats = spec.iterate(spec.start, spec.depth, sinks, control);
        } else if (spec.random) {
            ChaosOptions options;
            options.samples = spec.samples;
            options.seed = spec.seed;
            const RowVec x0 = spec.start.vertices.row(0);
            stats = chaosGameParallel(*spec.ifs, x0, options, sinks, control);
        } else {
            stats = iterateParallel(*spec.ifs, spec.start, spec.depth, sinks, control);
        }
        if (statsOut)
            *statsOut = stats;
        if (stats.cancelled)
            return {};
        for (size_t t = 1; t < rasters.size(); ++t)
            rasters.front()->merge(*rasters[t]);
        rasters.front()->fillPinholes();
    }
    std::vector<std::uint32_t> palette;
    for (const QColor &c : spec.palette)
        palette.push_back(c.rgb() & 0xffffffu);
    QImage image(spec.width, spec.height, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter p(&image);
    if (!rasters.empty()) {
        const std::vector<std::uint32_t> pixels = rasters.front()->shade(palette);
        const QImage picture(reinterpret_cast<const uchar *>(pixels.data()), spec.width, h,
                             spec.width * 4, QImage::Format_ARGB32);
        p.drawImage(0, 0, picture);
    }
    // The control net over the picture, as 000 Figs. 6-8 draw it.
    if (spec.netPoints.rows() > 0 && spec.netPoints.cols() == 3) {
        SurfaceRaster projector(spec.width, h, camera, {});
        std::vector<QPointF> s(size_t(spec.netPoints.rows()));
        for (Eigen::Index k = 0; k < spec.netPoints.rows(); ++k) {
            const Eigen::Vector3d q = projector.toScreen(spec.netPoints.row(k).transpose());
            s[size_t(k)] = {q.x(), q.y()};
        }
        p.setRenderHint(QPainter::Antialiasing);
        p.setPen(QPen(QColor(40, 40, 40, 150), 1.0));
        for (const auto &face : spec.netFaces)
            for (size_t k = 0; k < face.size(); ++k)
                p.drawLine(s[size_t(face[k])], s[size_t(face[(k + 1) % face.size()])]);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(30, 30, 30));
        for (const QPointF &q : s)
            p.drawEllipse(q, 2.5, 2.5);
    }
    if (!spec.caption.isEmpty()) {
        p.setPen(Qt::black);
        QFont f = p.font();
        f.setPixelSize(14);
        // A long caption (name, maps, view) shrinks to fit the width rather than being cut.
        while (f.pixelSize() > 9
               && QFontMetrics(f).horizontalAdvance(spec.caption) > spec.width - 16)
            f.setPixelSize(f.pixelSize() - 1);
        p.setFont(f);
        p.drawText(QRect(8, h, spec.width - 16, spec.height - h), Qt::AlignVCenter | Qt::AlignLeft,
                   spec.caption);
    }
    return image;
}

bool writeSurfaceFigure(const SurfaceFigureSpec &spec, const QString &fileName, QString *error,
                        const QString &format)
{
    const QImage image = renderSurfaceFigure(spec);
    if (image.isNull()) {
        if (error)
            *error = QCoreApplication::translate("awb::ItemFigure",
                                                 "the rendering was cancelled");
        return false;
    }
    PaintedFigureOptions o;
    o.title = spec.caption;
    o.metadata = spec.metadata;
    o.format = format;
    return writePaintedFigure(fileName, image.size(),
                              [&](QPainter &p) { p.drawImage(0, 0, image); }, error, o);
}

} // namespace awb
