#include "cli/FigureRenderer.h"

#include <QPainter>
#include <QPainterPath>
#include <cmath>

namespace awb {

QColor mapColor(int i)
{
    static const QColor palette[] = {QColor(31, 119, 180), QColor(214, 39, 40), QColor(44, 160, 44),
                                     QColor(148, 103, 189), QColor(255, 127, 14),
                                     QColor(140, 86, 75), QColor(227, 119, 194),
                                     QColor(23, 190, 207), QColor(188, 189, 34)};
    return palette[((i % 9) + 9) % 9];
}

namespace {

constexpr double kVectorLimit = 4000; // images drawn as vector shapes below this count

struct Frame {
    double x0, y0, x1, y1;
    QRectF target;
    QPointF map(double x, double y) const
    {
        return {target.left() + (x - x0) / (x1 - x0) * target.width(),
                target.top() + (y1 - y) / (y1 - y0) * target.height()};
    }
};

// Bounds of everything drawn in all panels, padded, with equal scale on both axes.
Frame frameFor(const FigureSpec &spec, const QRectF &target)
{
    BoundsSink bounds(spec.ifs->views);
    int shallow = 0;
    for (const auto &p : spec.panels)
        shallow = std::max(shallow, std::min(p.depth, 10));
    iterate(*spec.ifs, spec.start, shallow, bounds);
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    auto grow = [&](const Mat &m) {
        for (Eigen::Index r = 0; r < m.rows(); ++r)
            for (int a = 0; a < 2; ++a) {
                lo[a] = std::min(lo[a], m(r, a));
                hi[a] = std::max(hi[a], m(r, a));
            }
    };
    if (!bounds.empty() && bounds.finite())
        grow(Mat(bounds.lo()).leftCols(2)), grow(Mat(bounds.hi()).leftCols(2));
    // The start set as drawn (depth 0) counts too.
    for (const Projection &v : spec.ifs->views)
        grow(project(v, spec.start.vertices).leftCols(2));
    if (spec.controlPoints.rows() > 0)
        grow(spec.controlPoints);
    double w = hi[0] - lo[0], h = hi[1] - lo[1];
    const double pad = 0.06 * std::max({w, h, 1e-9});
    lo[0] -= pad, lo[1] -= pad, hi[0] += pad, hi[1] += pad;
    w = hi[0] - lo[0], h = hi[1] - lo[1];
    const double scale = std::min(target.width() / w, target.height() / h);
    const double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]);
    const double hw = 0.5 * target.width() / scale, hh = 0.5 * target.height() / scale;
    return {cx - hw, cy - hh, cx + hw, cy + hh, target};
}

void drawVector(QPainter &p, const FigureSpec &spec, const Frame &f, int depth)
{
    CallbackSink sink([&](const Mat &v, StartSet::Kind kind, const std::uint8_t *a, int n) {
        const QColor c = mapColor(n > 0 ? a[0] : 0);
        for (const Projection &view : spec.ifs->views) {
            const Mat q = project(view, v);
            QPolygonF poly;
            for (Eigen::Index r = 0; r < q.rows(); ++r)
                poly << f.map(q(r, 0), q(r, 1));
            if (kind == StartSet::Kind::Points || q.rows() == 1) {
                p.setPen(Qt::NoPen);
                p.setBrush(c);
                const double radius = depth <= 3 ? 3.5 : 2.2;
                for (const QPointF &pt : poly)
                    p.drawEllipse(pt, radius, radius);
            } else if (kind == StartSet::Kind::Polyline) {
                p.setPen(QPen(c, 1.6));
                p.setBrush(Qt::NoBrush);
                p.drawPolyline(poly);
            } else {
                QColor fill = c;
                fill.setAlpha(90);
                p.setPen(QPen(c, 1.0));
                p.setBrush(fill);
                p.drawPolygon(poly);
            }
        }
    });
    iterate(*spec.ifs, spec.start, depth, sink);
}

void drawRaster(QPainter &p, const FigureSpec &spec, const Frame &f, int depth)
{
    const int w = int(f.target.width()), h = int(f.target.height());
    RasterSink raster(w, h, f.x0, f.y0, f.x1, f.y1, spec.ifs->views);
    RasterSink second(w, h, f.x0, f.y0, f.x1, f.y1, spec.ifs->views);
    iterateParallel(*spec.ifs, spec.start, depth, {&raster, &second});
    raster.merge(second);
    QImage img(w, h, QImage::Format_ARGB32_Premultiplied);
    img.fill(Qt::transparent);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (raster.hits(x, y))
                img.setPixelColor(x, y, mapColor(int(raster.label(x, y)) - 1));
    p.drawImage(f.target.topLeft(), img);
}

} // namespace

QImage renderFigure(const FigureSpec &spec)
{
    if (!spec.ifs)
        throw InputError("no IFS to render");
    const int n = int(spec.panels.size());
    const int titleH = spec.title.isEmpty() ? 0 : 34;
    const int captionH = 26;
    QImage image(spec.panelWidth * n, spec.panelHeight + titleH + captionH,
                 QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    QFont font = p.font();
    font.setPixelSize(15);
    p.setFont(font);
    if (titleH) {
        QFont bold = font;
        bold.setBold(true);
        bold.setPixelSize(17);
        p.setFont(bold);
        p.setPen(Qt::black);
        p.drawText(QRectF(0, 0, image.width(), titleH), Qt::AlignCenter, spec.title);
        p.setFont(font);
    }
    for (int i = 0; i < n; ++i) {
        const QRectF cell(i * spec.panelWidth + 8, titleH + 4, spec.panelWidth - 16,
                          spec.panelHeight - 8);
        const Frame f = frameFor(spec, cell);
        p.setPen(QPen(QColor(200, 200, 200), 1));
        p.setBrush(Qt::NoBrush);
        p.drawRect(cell);
        p.save();
        p.setClipRect(cell);
        for (const Mat &o : spec.overlays) {
            QPolygonF poly;
            for (Eigen::Index r = 0; r < o.rows(); ++r)
                poly << f.map(o(r, 0), o(r, 1));
            p.setPen(QPen(QColor(60, 60, 60, 110), 4));
            p.drawPolyline(poly);
        }
        if (spec.controlPoints.rows() > 0) {
            QPolygonF poly;
            for (Eigen::Index r = 0; r < spec.controlPoints.rows(); ++r)
                poly << f.map(spec.controlPoints(r, 0), spec.controlPoints(r, 1));
            p.setPen(QPen(QColor(40, 150, 60), 1.5, Qt::DashLine));
            p.drawPolyline(poly);
            p.setPen(QPen(Qt::black, 1));
            p.setBrush(QColor(40, 150, 60));
            for (const QPointF &pt : poly)
                p.drawRect(QRectF(pt - QPointF(3.5, 3.5), QSizeF(7, 7)));
        }
        const int depth = spec.panels[i].depth;
        if (imageCount(*spec.ifs, depth) * double(spec.start.vertices.rows()) <= kVectorLimit)
            drawVector(p, spec, f, depth);
        else
            drawRaster(p, spec, f, depth);
        p.restore();
        p.setPen(Qt::black);
        p.drawText(QRectF(i * spec.panelWidth, titleH + spec.panelHeight - 2, spec.panelWidth,
                          captionH),
                   Qt::AlignCenter, spec.panels[i].caption);
    }
    return image;
}

} // namespace awb
