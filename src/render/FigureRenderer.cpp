#include "render/FigureRenderer.h"

#include "render/AttractorBounds.h"
#include "render/CurvePaths.h"
#include "render/FigureFile.h"
#include "core/analysis/Spectrum.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPaintEngine>
#include <QPainter>
#include <QPainterPath>
#include <atomic>
#include <cmath>
#include <thread>

namespace awb {

QColor mapColor(int i) { return attractorMapColor(i); }

namespace {

constexpr double kVectorLimit = 4000; // images drawn as vector shapes below this count

const std::vector<Projection> &viewsOf(const FigureSpec &spec)
{
    return spec.views.empty() ? spec.ifs->views : spec.views;
}

IterationStats runIterate(const FigureSpec &spec, int depth, const std::vector<AttractorSink *> &sinks)
{
    if (spec.iterate)
        return spec.iterate(spec.start, depth, sinks, {});
    if (spec.random) {
        ChaosOptions opt;
        opt.samples = spec.samples;
        opt.seed = spec.seed;
        return chaosGameParallel(*spec.ifs, spec.start.vertices.row(0), opt, sinks);
    }
    return iterateParallel(*spec.ifs, spec.start, depth, sinks);
}

bool hasAttractor(const FigureSpec &spec)
{
    return spec.iterate || spec.chaos || (spec.ifs && spec.ifs->size() > 0);
}

double imagesAt(const FigureSpec &spec, int depth)
{
    if (spec.random)
        return double(spec.samples);
    const double perImage = std::max<double>(1, spec.start.vertices.rows());
    if (spec.ifs && spec.ifs->size() > 0)
        return imageCount(*spec.ifs, depth) * perImage;
    return 1e18; // an automaton: count unknown, use the raster
}

struct Frame {
    double x0, y0, x1, y1;
    QRectF target;
    QPointF map(double x, double y) const
    {
        return {target.left() + (x - x0) / (x1 - x0) * target.width(),
                target.top() + (y1 - y) / (y1 - y0) * target.height()};
    }
};

} // namespace

QRectF contentBounds(const FigureSpec &spec)
{
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    auto grow = [&](const Mat &m) {
        for (Eigen::Index r = 0; r < m.rows(); ++r)
            for (int a = 0; a < 2; ++a)
                if (std::isfinite(m(r, a))) {
                    lo[a] = std::min(lo[a], m(r, a));
                    hi[a] = std::max(hi[a], m(r, a));
                }
    };
    // The attractor as every face frames it (render/AttractorBounds.h).
    if (hasAttractor(spec)) {
        AttractorExtent a;
        a.ifs = spec.ifs;
        a.views = viewsOf(spec);
        a.iterate = spec.iterate;
        a.chaos = spec.chaos;
        a.start = spec.start;
        for (const auto &p : spec.panels)
            a.depth = std::max(a.depth, p.depth);
        a.random = spec.random;
        a.samples = spec.samples;
        a.seed = spec.seed;
        if (const auto box = attractorBounds(a)) {
            Mat corners(2, 2);
            corners << box->left(), box->top(), box->right(), box->bottom();
            grow(corners);
        }
    }
    for (const Mat &m : spec.controlPolygons)
        grow(m);
    for (const Mat &m : spec.polygons)
        grow(m);
    if (lo[0] > hi[0])
        return QRectF(0, 0, -1, -1); // nothing: a negative size (a point has size 0)
    return QRectF(QPointF(lo[0], lo[1]), QPointF(hi[0], hi[1]));
}

QRectF figureWorld(const QRectF &content, const QSizeF &target)
{
    double lo[2] = {content.left(), content.top()}, hi[2] = {content.right(), content.bottom()};
    if (content.width() < 0)
        lo[0] = lo[1] = -1, hi[0] = hi[1] = 1;
    double w = hi[0] - lo[0], h = hi[1] - lo[1];
    const double pad = 0.06 * std::max({w, h, 1e-9});
    lo[0] -= pad, lo[1] -= pad, hi[0] += pad, hi[1] += pad;
    w = hi[0] - lo[0], h = hi[1] - lo[1];
    const double scale = std::min(target.width() / w, target.height() / h);
    const double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]);
    const double hw = 0.5 * target.width() / scale, hh = 0.5 * target.height() / scale;
    return QRectF(QPointF(cx - hw, cy - hh), QPointF(cx + hw, cy + hh));
}

namespace {

// Bounds of everything drawn in all panels (or the spec's own), padded, with equal scale on
// both axes.
Frame frameFor(const FigureSpec &spec, const QRectF &target)
{
    const QRectF content = spec.bounds.isValid() ? spec.bounds : contentBounds(spec);
    const QRectF w = figureWorld(content, target.size());
    return {w.left(), w.top(), w.right(), w.bottom(), target};
}

// The colour of an image with address a (n symbols) in the figure's colouring.
QColor styleColor(const FigureSpec &spec, const std::uint8_t *a, int n)
{
    const int maps = spec.ifs ? std::max(1, spec.ifs->size()) : 1;
    return attractorAddressColor(spec.colouring, maps, a, n);
}

void drawVector(QPainter &p, const FigureSpec &spec, const Frame &f, int depth)
{
    CallbackSink sink([&](const Mat &v, StartSet::Kind kind, const std::uint8_t *a, int n) {
        const QColor c = styleColor(spec, a, n);
        for (const Projection &view : viewsOf(spec)) {
            const Mat q = project(view, v);
            QPolygonF poly;
            for (Eigen::Index r = 0; r < q.rows(); ++r)
                poly << f.map(q(r, 0), q(r, 1));
            if (kind == StartSet::Kind::Points || q.rows() == 1) {
                p.setPen(Qt::NoPen);
                p.setBrush(c);
                const double radius = depth <= 3 && !spec.random ? 3.5 : 2.0;
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
    runIterate(spec, depth, {&sink});
}

// A curve (polyline start set, deterministic, one IFS) on a vector device: joined paths.
bool drawCurvePaths(QPainter &p, const FigureSpec &spec, const Frame &f, int depth)
{
    if (!isVectorDevice(p) || spec.random || spec.iterate || !spec.ifs || spec.ifs->size() == 0
        || spec.start.kind != StartSet::Kind::Polyline || imageCount(*spec.ifs, depth) > 2e7)
        return false;
    const double sx = f.target.width() / (f.x1 - f.x0), sy = f.target.height() / (f.y1 - f.y0);
    const QTransform toLogical(sx, 0, 0, -sy, f.target.left() - f.x0 * sx,
                               f.target.top() + f.y1 * sy);
    CurvePathSink sink(viewsOf(spec), toLogical, devicePixelsPerLogical(p),
                       [&spec](const std::uint8_t *a, int n) { return styleColor(spec, a, n); });
    std::atomic<bool> stop{false};
    IterationControl control;
    control.cancel = &stop;
    sink.setOverflowFlag(&stop);
    iterateAlong(*spec.ifs, spec.start, depth, sink, control);
    if (sink.overflowed())
        return false;
    drawCurvePaths(p, sink.finish(), 1.6);
    return true;
}

void drawRaster(QPainter &p, const FigureSpec &spec, const Frame &f, int depth)
{
    // Rasterise at the device resolution of the target (a PDF's 300 dpi, a PNG's pixels;
    // an SVG, which has none, gets twice its user units), through the one engine the view
    // uses (render/AttractorImage.h).
    const double scale = std::clamp(p.paintEngine() && p.paintEngine()->type() == QPaintEngine::SVG
                                        ? 2.0
                                        : devicePixelsPerLogical(p),
                                    1.0, 8.0);
    RenderRequest r;
    auto ifs = std::make_shared<Ifs>(spec.ifs ? *spec.ifs : Ifs{});
    ifs->views = viewsOf(spec);
    r.ifs = ifs;
    r.iterate = spec.iterate;
    r.chaos = spec.chaos;
    r.start = spec.start;
    r.mode = spec.random ? RenderRequest::Mode::Random : RenderRequest::Mode::Deterministic;
    r.depth = depth;
    r.samples = spec.samples;
    r.seed = spec.seed;
    r.world = QRectF(f.x0, f.y0, f.x1 - f.x0, f.y1 - f.y0);
    r.size = QSize(std::max(1, int(f.target.width() * scale)),
                   std::max(1, int(f.target.height() * scale)));
    r.colouring = spec.colouring;
    r.tone = spec.tone;
    r.supersample = spec.supersample;
    r.threads = spec.threads;
    // Thicken single pixels a little so that a thin curve reads at print size.
    r.dotRadius = scale > 1.5 && spec.tone.mode == Accumulation::Hits ? 1 : 0;
    IterationControl control;
    control.cancel = spec.cancel;
    control.progress = spec.progress;
    const QImage img = renderAttractorImage(r, nullptr, control);
    p.save();
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    p.setRenderHint(QPainter::LosslessImageRendering); // PDF: no JPEG halos
    p.drawImage(f.target, img);
    p.restore();
}

void drawPolyline(QPainter &p, const Frame &f, const Mat &m, bool closed)
{
    QPolygonF poly;
    for (Eigen::Index r = 0; r < m.rows(); ++r)
        poly << f.map(m(r, 0), m(r, 1));
    if (closed)
        p.drawPolygon(poly);
    else
        p.drawPolyline(poly);
}

} // namespace

QSize figureSize(const FigureSpec &spec)
{
    const int titleH = spec.title.isEmpty() ? 0 : 34;
    return {spec.panelWidth * int(std::max<size_t>(1, spec.panels.size())),
            spec.panelHeight + titleH + 26};
}

void paintFigure(QPainter &p, const FigureSpec &spec)
{
    if (!spec.ifs && !spec.iterate && spec.polygons.empty())
        throw InputError(
            QCoreApplication::translate("awb::cli", "nothing to draw").toStdString());
    const int n = int(spec.panels.size());
    const int titleH = spec.title.isEmpty() ? 0 : 34;
    const int captionH = 26;
    const QSize size = figureSize(spec);
    p.fillRect(QRect(QPoint(0, 0), size), Qt::white);
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
        p.drawText(QRectF(0, 0, size.width(), titleH), Qt::AlignCenter, spec.title);
        p.setFont(font);
    }
    for (int i = 0; i < n; ++i) {
        const QRectF cell(i * spec.panelWidth + 8, titleH + 4, spec.panelWidth - 16,
                          spec.panelHeight - 8);
        const Frame f = frameFor(spec, cell);
        p.setPen(QPen(QColor(200, 200, 200), 1));
        p.setBrush(Qt::NoBrush);
        p.drawRect(cell);
        {
            // Restored also when drawing the attractor throws (an IFS that does not contract):
            // the painter then ends without a saved state left over.
            const struct Saved {
                QPainter &painter;
                explicit Saved(QPainter &q) : painter(q) { painter.save(); }
                ~Saved() { painter.restore(); }
            } saved(p);
            p.setClipRect(cell);
            p.setBrush(Qt::NoBrush);
            for (const Mat &o : spec.overlays) {
                p.setPen(QPen(QColor(60, 60, 60, 110), 4));
                drawPolyline(p, f, o, false);
            }
            for (size_t c = 0; c < spec.controlPolygons.size(); ++c) {
                const Mat &m = spec.controlPolygons[c];
                p.setPen(QPen(QColor(40, 150, 60), 1.5, Qt::DashLine));
                p.setBrush(Qt::NoBrush);
                drawPolyline(p, f, m, c < spec.controlClosed.size() && spec.controlClosed[c]);
                p.setPen(QPen(Qt::black, 1));
                p.setBrush(QColor(40, 150, 60));
                for (Eigen::Index r = 0; r < m.rows(); ++r)
                    p.drawRect(QRectF(f.map(m(r, 0), m(r, 1)) - QPointF(3.5, 3.5),
                                      QSizeF(7, 7)));
            }
            p.setBrush(Qt::NoBrush);
            for (size_t c = 0; c < spec.polygons.size(); ++c) {
                p.setPen(QPen(mapColor(0), 1.2));
                drawPolyline(p, f, spec.polygons[c],
                             c < spec.polygonsClosed.size() && spec.polygonsClosed[c]);
            }
            const int depth = spec.panels[i].depth;
            if (spec.chaos) {
                drawRaster(p, spec, f, depth);  // its own chaos game: the raster path only
            } else if (hasAttractor(spec)) {
                if (imagesAt(spec, depth) <= kVectorLimit)
                    drawVector(p, spec, f, depth);
                else if (!drawCurvePaths(p, spec, f, depth))
                    drawRaster(p, spec, f, depth);
            }
        }
        p.setPen(Qt::black);
        // A long caption shrinks to the panel's width (down to 9 px, then it is elided).
        QFont captionFont = font;
        while (captionFont.pixelSize() > 9
               && QFontMetricsF(captionFont).horizontalAdvance(spec.panels[i].caption)
                      > spec.panelWidth - 8)
            captionFont.setPixelSize(captionFont.pixelSize() - 1);
        p.setFont(captionFont);
        p.drawText(QRectF(i * spec.panelWidth, titleH + spec.panelHeight - 2, spec.panelWidth,
                          captionH),
                   Qt::AlignCenter,
                   QFontMetricsF(captionFont).elidedText(spec.panels[i].caption, Qt::ElideRight,
                                                         spec.panelWidth - 8));
        p.setFont(font);
    }
}

QImage renderFigure(const FigureSpec &spec)
{
    QImage image(figureSize(spec), QImage::Format_ARGB32_Premultiplied);
    QPainter p(&image);
    paintFigure(p, spec);
    return image;
}

bool writeFigure(const FigureSpec &spec, const QString &fileName, QString *error,
                 const QString &format)
{
    PaintedFigureOptions o;
    o.title = spec.title;
    o.metadata = spec.metadata;
    o.format = format;
    return writePaintedFigure(fileName, figureSize(spec),
                              [&](QPainter &p) { paintFigure(p, spec); }, error, o);
}

} // namespace awb
