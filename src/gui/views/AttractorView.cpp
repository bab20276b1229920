#include "gui/views/AttractorView.h"

#include "core/Spectrum.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <optional>

namespace awb {

namespace {

constexpr double kHandleRadius = 5.0;      // screen pixels
constexpr double kHitRadius = 9.0;         // a little larger than drawn: easier to grab
constexpr double kFitMargin = 24.0;
constexpr double kMinScale = 1e-9, kMaxScale = 1e12;
// F^k(X0) is drawn as vectors up to this many vertices (it stays interactive).
constexpr std::size_t kMaxHutchinsonVertices = 50000;
// A render faster than this shows no progress text (it would only flicker).
constexpr int kQuietRenderMs = 250;
// A hidden view that never rendered draws its export raster synchronously, at most this big.
constexpr int kMaxExportRaster = 2048;
// An export draws the attractor as vector dots up to this many points.
constexpr std::size_t kMaxExportVectorVertices = 20000;
// The export's vector dots come from the renderer's streams, so they are the raster's points.
constexpr int kRandomStreams = AttractorRenderer::kRandomStreams;

const QColor kControlColour(40, 40, 40);
const QColor kStartColour(230, 120, 0);
const QColor kExactColour(20, 150, 60);
const QColor kSubdivisionColour(120, 120, 160);

QString subscript(int n)
{
    static const QChar digits[] = {QChar(0x2080), QChar(0x2081), QChar(0x2082), QChar(0x2083),
                                   QChar(0x2084), QChar(0x2085), QChar(0x2086), QChar(0x2087),
                                   QChar(0x2088), QChar(0x2089)};
    QString s;
    for (QChar c : QString::number(n))
        s += digits[c.digitValue()];
    return s;
}

QPolygonF toPolygon(const Mat &pts)
{
    QPolygonF out;
    if (pts.cols() < 2)
        return out;
    out.reserve(int(pts.rows()));
    for (Eigen::Index r = 0; r < pts.rows(); ++r)
        out << QPointF(pts(r, 0), pts(r, 1));
    return out;
}

QPainterPath polylinePath(const QPolygonF &poly, bool closed)
{
    QPainterPath path;
    path.addPolygon(poly);
    if (closed)
        path.closeSubpath();
    return path;
}

bool finitePoint(const QPointF &p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

// Bounds of the finite points of `poly` (a zero-size rectangle for one point); nullopt if none.
std::optional<QRectF> boundsOf(const QPolygonF &poly)
{
    std::optional<QRectF> r;
    for (const QPointF &p : poly) {
        if (!finitePoint(p))
            continue;
        if (!r) {
            r = QRectF(p, QSizeF(0, 0));
            continue;
        }
        // Not QRectF::united: it ignores zero-size rectangles.
        r->setLeft(std::min(r->left(), p.x()));
        r->setRight(std::max(r->right(), p.x()));
        r->setTop(std::min(r->top(), p.y()));
        r->setBottom(std::max(r->bottom(), p.y()));
    }
    return r;
}

// A "nice" grid step (1, 2 or 5 times a power of ten) close to `approx`.
double niceStep(double approx)
{
    const double e = std::pow(10.0, std::floor(std::log10(approx)));
    const double f = approx / e;
    return (f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0) * e;
}

} // namespace

// ---- mapping ----------------------------------------------------------------------------------

QPointF AttractorView::Mapping::map(const QPointF &w) const
{
    return {target.center().x() + (w.x() - center.x()) * scale,
            target.center().y() - (w.y() - center.y()) * scale};
}

QPointF AttractorView::Mapping::unmap(const QPointF &s) const
{
    return {center.x() + (s.x() - target.center().x()) / scale,
            center.y() - (s.y() - target.center().y()) / scale};
}

AttractorView::Mapping AttractorView::screenMapping() const
{
    return {m_center, m_scale, QRectF(rect())};
}

QPointF AttractorView::worldToScreen(const QPointF &world) const
{
    return screenMapping().map(world);
}

QPointF AttractorView::screenToWorld(const QPointF &screen) const
{
    return screenMapping().unmap(screen);
}

QRectF AttractorView::visibleWorldRect() const
{
    const Mapping m = screenMapping();
    const QPointF a = m.unmap(m.target.bottomLeft()), b = m.unmap(m.target.topRight());
    return QRectF(a, b).normalized();
}

void AttractorView::setView(const QPointF &center, double pixelsPerUnit)
{
    if (!finitePoint(center) || !std::isfinite(pixelsPerUnit))
        return;
    m_center = center;
    m_scale = std::clamp(pixelsPerUnit, kMinScale, kMaxScale);
    scheduleRender();
    update();
    emit viewChanged();
}

QPointF AttractorView::controlPointPosition(int i) const
{
    if (m_drag.kind == DragKind::ControlPoint && m_drag.index == i)
        return m_drag.currentWorld;
    return i >= 0 && i < int(m_control.size()) ? m_control[i] : QPointF();
}

QPointF AttractorView::startVertexPosition(int i) const
{
    if (m_drag.kind == DragKind::StartVertex && m_drag.index == i)
        return m_drag.currentWorld;
    return i >= 0 && i < int(m_startPlane.size()) ? m_startPlane[i] : QPointF();
}

// ---- construction and data --------------------------------------------------------------------

AttractorView::AttractorView(QWidget *parent) : QWidget(parent)
{
    setMouseTracking(true);
    setFocusPolicy(Qt::WheelFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);
    m_renderer = new AttractorRenderer(this);
    // Coalesce: all setters of one edit batch (and a burst of wheel events) make one request.
    m_renderTimer.setSingleShot(true);
    m_renderTimer.setInterval(10);
    connect(&m_renderTimer, &QTimer::timeout, this, &AttractorView::startRender);
    connect(m_renderer, &AttractorRenderer::imageReady, this,
            [this](const QImage &image, const RenderInfo &info) {
                m_image = image;
                m_imageInfo = info;
                m_error.clear();
                update();
                if (info.final)
                    emit renderFinished(info);
            });
    connect(m_renderer, &AttractorRenderer::progress, this, [this](double f) {
        m_progress = f;
        update();
        emit renderProgress(f);
    });
    connect(m_renderer, &AttractorRenderer::busyChanged, this, [this](bool busy) {
        m_busy = busy;
        if (busy)
            m_busySince.start();
        update();
    });
    connect(m_renderer, &AttractorRenderer::failed, this, [this](const QString &message) {
        // The old picture belongs to other data: showing it beside the error would mislead.
        m_image = QImage();
        m_imageInfo = RenderInfo();
        m_error = message;
        update();
        emit renderFailed(message);
    });
}

AttractorView::~AttractorView() = default;

void AttractorView::setIfs(std::shared_ptr<const Ifs> ifs, const StartSet &start,
                           CustomIterate iterate)
{
    m_ifs = std::move(ifs);
    m_iterate = std::move(iterate);
    m_start = start;
    if (!m_ifs) {
        // Nothing to draw: a picture of the previous IFS would be wrong.
        m_renderer->cancel();
        m_image = QImage();
        m_imageInfo = RenderInfo();
        m_error.clear();
    }
    updateStartPlane();
    updateHutchinson();
    dataChanged(true);
}

void AttractorView::setStartSet(const StartSet &start)
{
    m_start = start;
    updateStartPlane();
    updateHutchinson();
    dataChanged(true);
}

void AttractorView::setControlPoints(const Mat &points, bool closed)
{
    const QPolygonF poly = toPolygon(points);
    m_control.assign(poly.begin(), poly.end());
    m_controlClosed = closed;
    if (m_drag.kind == DragKind::ControlPoint && m_drag.index >= int(m_control.size()))
        m_drag = Drag();
    dataChanged(true);
}

void AttractorView::setExactCurve(const Mat &curve, const QString &label)
{
    m_exact = toPolygon(curve);
    m_exactLabel = m_exact.size() > 1 ? label : QString();
    update();
}

void AttractorView::setSubdivisionPolygons(const std::vector<Mat> &polygons)
{
    m_subdivision.clear();
    for (const Mat &m : polygons)
        m_subdivision.push_back(toPolygon(m));
    update();
}

void AttractorView::setHutchinsonStep(int k)
{
    m_hutchStep = std::max(-1, k);
    updateHutchinson();
    update();
}

void AttractorView::setRenderSettings(const RenderSettings &settings)
{
    m_settings = settings;
    dataChanged(false);
}

void AttractorView::setLayerVisible(Layer layer, bool visible)
{
    const std::uint32_t bit = 1u << int(layer);
    m_hiddenLayers = visible ? (m_hiddenLayers & ~bit) : (m_hiddenLayers | bit);
    if (layer == Layer::Attractor && visible)
        scheduleRender();
    update();
}

bool AttractorView::isLayerVisible(Layer layer) const
{
    return !(m_hiddenLayers & (1u << int(layer)));
}

void AttractorView::updateStartPlane()
{
    m_startPlane.clear();
    const Mat &X = m_start.vertices;
    if (X.rows() == 0)
        return;
    Mat plane;
    if (m_ifs && !m_ifs->views.empty() && X.cols() == m_ifs->dim())
        plane = project(m_ifs->views.front(), X);
    else if (X.cols() == 2)
        plane = X;
    const QPolygonF poly = toPolygon(plane);
    m_startPlane.assign(poly.begin(), poly.end());
}

void AttractorView::updateHutchinson()
{
    m_hutch.clear();
    m_hutchTooMany = false;
    if (m_hutchStep < 0 || !m_ifs)
        return;
    m_hutchTooMany = !vectorImages(m_hutchStep, kMaxHutchinsonVertices, &m_hutch);
}

bool AttractorView::vectorImages(int depth, std::size_t maxVertices,
                                 std::vector<VectorImage> *out) const
{
    out->clear();
    if (!m_ifs || m_ifs->size() == 0 || m_start.vertices.rows() == 0)
        return true;
    const double vertices = imageCount(*m_ifs, depth) * double(m_start.vertices.rows())
                            * double(m_ifs->views.size());
    if (vertices > double(maxVertices))
        return false;
    const RenderSettings &s = m_settings;
    const int maps = m_ifs->size();
    const auto &views = m_ifs->views;
    CallbackSink sink([&](const Mat &v, StartSet::Kind, const std::uint8_t *a, int n) {
        const QColor c = AttractorRenderer::addressColor(s.colorMode, s.prefixLength, s.palette,
                                                         maps, a, n);
        for (const Projection &view : views)
            out->push_back({toPolygon(project(view, v)), c});
    });
    try {
        iterate(*m_ifs, m_start, depth, sink);
    } catch (const std::exception &) {
        // Bad input shows up through the renderer's failed() message; draw nothing here.
        out->clear();
    }
    return true;
}

bool AttractorView::randomVectorImages(std::size_t maxVertices,
                                       std::vector<VectorImage> *out) const
{
    out->clear();
    if (!m_ifs || m_start.vertices.rows() == 0)
        return true;
    if (double(m_settings.samples) * double(m_ifs->views.size()) > double(maxVertices))
        return false;
    const RenderSettings &s = m_settings;
    const int maps = m_ifs->size();
    // One collector per stream, as in the renderer, so the dots are the raster's points.
    std::vector<std::vector<VectorImage>> parts(kRandomStreams);
    std::vector<std::unique_ptr<CallbackSink>> sinks;
    std::vector<AttractorSink *> raw;
    for (int t = 0; t < kRandomStreams; ++t) {
        sinks.push_back(std::make_unique<CallbackSink>(
            [&, t](const Mat &v, StartSet::Kind, const std::uint8_t *a, int n) {
                const QColor c = AttractorRenderer::addressColor(s.colorMode, s.prefixLength,
                                                                 s.palette, maps, a, n);
                for (const Projection &view : m_ifs->views)
                    parts[t].push_back({toPolygon(project(view, v)), c});
            }));
        raw.push_back(sinks.back().get());
    }
    ChaosOptions opt;
    opt.samples = s.samples;
    opt.seed = s.seed;
    opt.addressLength = std::clamp(s.prefixLength, 1, 3);
    try {
        chaosGameParallel(*m_ifs, m_start.vertices.row(0), opt, raw);
    } catch (const std::exception &) {
        return true;
    }
    for (auto &p : parts)
        out->insert(out->end(), p.begin(), p.end());
    return true;
}

void AttractorView::dataChanged(bool geometryChanged)
{
    if (geometryChanged && m_autoFit && m_drag.kind == DragKind::None && width() > 0)
        fitToContents();
    scheduleRender();
    update();
}

std::optional<QRectF> AttractorView::contentBounds() const
{
    QPolygonF all;
    auto add = [&](const QPolygonF &poly) {
        if (const auto b = boundsOf(poly))
            all << b->topLeft() << b->bottomRight();
    };
    add(QPolygonF(m_control.begin(), m_control.end()));
    add(QPolygonF(m_startPlane.begin(), m_startPlane.end()));
    add(m_exact);
    for (const QPolygonF &p : m_subdivision)
        add(p);
    for (const VectorImage &im : m_hutch)
        add(im.polygon);
    if (m_ifs && m_ifs->size() > 0 && m_start.vertices.rows() > 0) {
        // The attractor itself: a shallow level from one start point is already close to it
        // (each level shrinks the distance by the contraction factor).
        try {
            if (checkIfs(*m_ifs).contractive) {
                int depth = 0;
                while (depth < 40 && imageCount(*m_ifs, depth + 1) <= 20000 && m_ifs->size() > 1)
                    ++depth;
                BoundsSink bounds(m_ifs->views);
                iterate(*m_ifs, StartSet::points(m_start.vertices.topRows(1)), depth, bounds);
                if (!bounds.empty() && bounds.finite() && bounds.lo().size() >= 2)
                    add(QPolygonF{QPointF(bounds.lo()(0), bounds.lo()(1)),
                                  QPointF(bounds.hi()(0), bounds.hi()(1))});
            }
        } catch (const std::exception &) {
            // An invalid IFS is reported by the renderer; fit to the rest.
        }
    }
    return boundsOf(all);
}

void AttractorView::fitToContents()
{
    const std::optional<QRectF> bounds = contentBounds();
    if (!bounds) {
        setView(QPointF(0, 0), 50.0);
        return;
    }
    QRectF r = *bounds;
    // A single point or a straight horizontal/vertical set still needs a visible extent.
    const double extent = std::max({r.width(), r.height(), 1e-9 * std::abs(r.center().x()),
                                    1e-9 * std::abs(r.center().y()), 1e-12});
    if (r.width() < 1e-3 * extent)
        r.adjust(-0.5 * extent, 0, 0.5 * extent, 0);
    if (r.height() < 1e-3 * extent)
        r.adjust(0, -0.5 * extent, 0, 0.5 * extent);
    const double w = std::max(1.0, width() - 2 * kFitMargin);
    const double h = std::max(1.0, height() - 2 * kFitMargin);
    setView(r.center(), std::min(w / r.width(), h / r.height()));
}

void AttractorView::zoomBy(double factor, const QPointF &anchor)
{
    if (!(factor > 0) || !std::isfinite(factor))
        return;
    const QPointF w = screenToWorld(anchor);
    const double s = std::clamp(m_scale * factor, kMinScale, kMaxScale);
    const QPointF mid = QRectF(rect()).center();
    // Keep w under the anchor: anchor = mid + (w - c') s (x), anchor = mid - (w - c') s (y).
    setView(QPointF(w.x() - (anchor.x() - mid.x()) / s, w.y() + (anchor.y() - mid.y()) / s), s);
}

void AttractorView::userMovedView() { m_autoFit = false; }

// ---- rendering --------------------------------------------------------------------------------

void AttractorView::scheduleRender()
{
    if (isLayerVisible(Layer::Attractor))
        m_renderTimer.start();
}

void AttractorView::startRender()
{
    if (!m_ifs || !isVisible() || width() < 1 || height() < 1
        || !isLayerVisible(Layer::Attractor)) {
        return;
    }
    const QRectF world = visibleWorldRect();
    if (!(world.width() > 0) || !(world.height() > 0) || !std::isfinite(world.width())
        || !std::isfinite(world.height())) {
        return;
    }
    RenderRequest r;
    r.ifs = m_ifs;
    r.iterate = m_iterate;
    r.start = m_start;
    r.mode = m_settings.mode;
    r.depth = m_settings.depth;
    r.samples = m_settings.samples;
    r.seed = m_settings.seed;
    r.world = world;
    const double dpr = devicePixelRatioF();
    r.size = QSize(std::max(1, int(std::lround(width() * dpr))),
                   std::max(1, int(std::lround(height() * dpr))));
    r.colorMode = m_settings.colorMode;
    r.prefixLength = m_settings.prefixLength;
    r.palette = m_settings.palette;
    r.dotRadius = int(std::lround(m_settings.dotRadius * dpr));
    m_progress = 0.0;
    m_renderer->request(r);
}

// ---- painting ---------------------------------------------------------------------------------

void AttractorView::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    paintScene(p, screenMapping(), false);
    paintStatus(p);
}

void AttractorView::renderTo(QPainter *painter, const QRectF &target)
{
    if (!painter || target.isEmpty())
        return;
    // The same world rectangle as on screen, fitted into the target with equal scale.
    const QRectF vis = visibleWorldRect();
    Mapping m{m_center, std::min(target.width() / vis.width(), target.height() / vis.height()),
              target};
    painter->save();
    painter->setClipRect(target);
    painter->setRenderHint(QPainter::Antialiasing);
    paintScene(*painter, m, true);
    painter->restore();
}

void AttractorView::paintScene(QPainter &p, const Mapping &m, bool forExport)
{
    // Line widths and marker sizes follow the figure, not the device: an export at printer
    // resolution looks like the screen.
    const double u = m.scale / m_scale;
    p.fillRect(m.target, Qt::white);
    if (isLayerVisible(Layer::Grid))
        paintGrid(p, m);

    if (isLayerVisible(Layer::Subdivision) && !m_subdivision.empty()) {
        const int n = int(m_subdivision.size());
        for (int k = 0; k < n; ++k) {
            QColor c = kSubdivisionColour;
            c.setAlphaF(float(0.35 + 0.55 * (k + 1) / n)); // finer levels darker
            p.setPen(QPen(c, 1.0 * u, Qt::DashLine));
            p.setBrush(Qt::NoBrush);
            QPolygonF s;
            for (const QPointF &w : m_subdivision[k])
                s << m.map(w);
            p.drawPath(polylinePath(s, false));
        }
    }

    if (isLayerVisible(Layer::ExactCurve) && m_exact.size() > 1) {
        // A wide translucent band under the attractor: where they agree, the attractor shows
        // inside the band; where they differ, both stay visible.
        QPolygonF s;
        for (const QPointF &w : m_exact)
            s << m.map(w);
        QColor band = kExactColour;
        band.setAlphaF(0.3f);
        p.setPen(QPen(band, 7.0 * u, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.setBrush(Qt::NoBrush);
        p.drawPath(polylinePath(s, false));
    }

    if (isLayerVisible(Layer::Attractor)) {
        std::vector<VectorImage> dots;
        bool vector = false;
        if (forExport && m_ifs) {
            vector = m_settings.mode == RenderRequest::Mode::Deterministic
                         ? vectorImages(m_settings.depth, kMaxExportVectorVertices, &dots)
                         : randomVectorImages(kMaxExportVectorVertices, &dots);
            vector = vector && !dots.empty();
        }
        QImage image = m_image;
        RenderInfo info = m_imageInfo;
        if (forExport && !vector && image.isNull() && m_ifs && m_error.isEmpty())
            image = exportRaster(m, &info);
        if (vector) {
            paintVectorImages(p, m, dots, m_settings.mode == RenderRequest::Mode::Random
                                              ? StartSet::Kind::Points
                                              : m_start.kind);
        } else if (!image.isNull() && info.world.isValid()) {
            const QRectF w = info.world;
            const QRectF target(m.map(QPointF(w.left(), w.bottom())),
                                m.map(QPointF(w.right(), w.top())));
            // Nearest-neighbour scaling keeps a one-pixel curve crisp while zooming; the
            // next render replaces the stretched pixels anyway.
            p.save();
            p.setRenderHint(QPainter::SmoothPixmapTransform, false);
            p.drawImage(target, image);
            p.restore();
        }
    }

    if (isLayerVisible(Layer::Hutchinson) && !m_hutch.empty())
        paintVectorImages(p, m, m_hutch, m_start.kind);

    paintHandles(p, m);
    paintLegend(p, m);
}

void AttractorView::paintLegend(QPainter &p, const Mapping &m) const
{
    if (m_exactLabel.isEmpty() || !isLayerVisible(Layer::ExactCurve) || m_exact.size() < 2)
        return;
    const double u = m.scale / m_scale;
    p.save();
    const QFont f = sceneFont(1.0, u);
    p.setFont(f);
    const QFontMetricsF fm(f, p.device());
    const double pad = 5.0 * u, swatch = 22.0 * u;
    const QRectF text = fm.boundingRect(m_exactLabel);
    const QRectF box(m.target.left() + pad, m.target.top() + pad,
                     swatch + 3 * pad + text.width(), text.height() + 2 * pad);
    p.setPen(QPen(QColor(200, 200, 200), 1.0 * u));
    p.setBrush(QColor(255, 255, 255, 225));
    p.drawRect(box);
    QColor band = kExactColour;
    band.setAlphaF(0.3f);
    const double y = box.center().y();
    p.setPen(QPen(band, 7.0 * u, Qt::SolidLine, Qt::RoundCap));
    p.drawLine(QPointF(box.left() + pad, y), QPointF(box.left() + pad + swatch, y));
    p.setPen(QColor(40, 40, 40));
    p.drawText(QRectF(box.left() + 2 * pad + swatch, box.top() + pad, text.width() + pad,
                      text.height()),
               Qt::AlignLeft | Qt::AlignVCenter, m_exactLabel);
    p.restore();
}

QImage AttractorView::exportRaster(const Mapping &m, RenderInfo *info) const
{
    // Only for a view that never rendered on screen (hidden, or exported right after the
    // data arrived): the export must not silently lack the attractor.
    RenderRequest r;
    r.ifs = m_ifs;
    r.iterate = m_iterate;
    r.start = m_start;
    r.mode = m_settings.mode;
    r.depth = m_settings.depth;
    r.samples = m_settings.samples;
    r.seed = m_settings.seed;
    r.world = QRectF(m.unmap(m.target.bottomLeft()), m.unmap(m.target.topRight())).normalized();
    const double k = std::min(1.0, kMaxExportRaster / std::max(m.target.width(),
                                                               m.target.height()));
    r.size = QSize(std::max(1, int(m.target.width() * k)),
                   std::max(1, int(m.target.height() * k)));
    r.colorMode = m_settings.colorMode;
    r.prefixLength = m_settings.prefixLength;
    r.palette = m_settings.palette;
    r.dotRadius = m_settings.dotRadius;
    try {
        return AttractorRenderer::renderNow(r, info);
    } catch (const std::exception &) {
        return {};
    }
}

QFont AttractorView::sceneFont(double factor, double u) const
{
    // Sized in device pixels, not points: a point size would grow once more with the
    // resolution of a printer or PDF on top of the figure's scale u.
    QFont f = font();
    f.setPixelSize(std::max(1, int(std::lround(QFontInfo(font()).pixelSize() * factor * u))));
    return f;
}

void AttractorView::paintGrid(QPainter &p, const Mapping &m) const
{
    const QRectF w = QRectF(m.unmap(m.target.bottomLeft()), m.unmap(m.target.topRight()))
                         .normalized();
    const double step = niceStep(90.0 / m.scale * (m.scale / m_scale)); // ~90 screen px
    if (!(step > 0) || !std::isfinite(step) || w.width() / step > 400)
        return;
    const double u = m.scale / m_scale;
    p.save();
    p.setPen(QPen(QColor(232, 232, 236), 1.0 * u));
    for (double x = std::ceil(w.left() / step) * step; x <= w.right(); x += step)
        p.drawLine(m.map(QPointF(x, w.top())), m.map(QPointF(x, w.bottom())));
    for (double y = std::ceil(w.top() / step) * step; y <= w.bottom(); y += step)
        p.drawLine(m.map(QPointF(w.left(), y)), m.map(QPointF(w.right(), y)));
    p.setPen(QPen(QColor(200, 200, 208), 1.0 * u));
    if (w.left() <= 0 && w.right() >= 0)
        p.drawLine(m.map(QPointF(0, w.top())), m.map(QPointF(0, w.bottom())));
    if (w.top() <= 0 && w.bottom() >= 0)
        p.drawLine(m.map(QPointF(w.left(), 0)), m.map(QPointF(w.right(), 0)));
    // Tick labels along the bottom and left edges.
    const QFont f = sceneFont(0.85, u);
    p.setFont(f);
    p.setPen(QColor(130, 130, 140));
    const QFontMetricsF fm(f);
    auto label = [&](double v) {
        return QString::number(std::abs(v) < 1e-9 * step ? 0.0 : v, 'g', 6)
            .replace(QLatin1Char('-'), QChar(0x2212));
    };
    for (double x = std::ceil(w.left() / step) * step; x <= w.right(); x += step) {
        const QPointF s = m.map(QPointF(x, w.top()));
        p.drawText(QPointF(s.x() + 3 * u, m.target.bottom() - 4 * u), label(x));
    }
    for (double y = std::ceil(w.top() / step) * step; y <= w.bottom(); y += step) {
        const QPointF s = m.map(QPointF(w.left(), y));
        if (s.y() < m.target.bottom() - fm.height() - 4 * u)
            p.drawText(QPointF(m.target.left() + 4 * u, s.y() - 3 * u), label(y));
    }
    p.restore();
}

void AttractorView::paintVectorImages(QPainter &p, const Mapping &m,
                                      const std::vector<VectorImage> &images,
                                      StartSet::Kind kind) const
{
    const double u = m.scale / m_scale;
    p.save();
    for (const VectorImage &im : images) {
        QPolygonF s;
        s.reserve(im.polygon.size());
        for (const QPointF &w : im.polygon)
            s << m.map(w);
        if (kind == StartSet::Kind::Points || s.size() == 1) {
            p.setPen(Qt::NoPen);
            p.setBrush(im.colour);
            const double r = 1.6 * u;
            for (const QPointF &q : s)
                p.drawEllipse(q, r, r);
        } else if (kind == StartSet::Kind::Polyline) {
            p.setPen(QPen(im.colour, 1.3 * u));
            p.setBrush(Qt::NoBrush);
            p.drawPolyline(s);
        } else {
            QColor fill = im.colour;
            fill.setAlphaF(0.35f);
            p.setPen(QPen(im.colour, 1.0 * u));
            p.setBrush(fill);
            p.drawPolygon(s);
        }
    }
    p.restore();
}

void AttractorView::paintHandles(QPainter &p, const Mapping &m) const
{
    const double u = m.scale / m_scale;
    const bool onScreen = u == 1.0 && m.target == QRectF(rect());
    const QFont f = sceneFont(0.9, u);
    p.save();
    p.setFont(f);

    if (isLayerVisible(Layer::StartSet) && !m_startPlane.empty()) {
        QPolygonF s;
        for (int i = 0; i < int(m_startPlane.size()); ++i)
            s << m.map(startVertexPosition(i));
        QColor fill = kStartColour;
        fill.setAlphaF(0.12f);
        p.setPen(QPen(kStartColour, 1.5 * u));
        p.setBrush(m_start.kind == StartSet::Kind::Polygon ? QBrush(fill) : Qt::NoBrush);
        if (m_start.kind == StartSet::Kind::Polygon)
            p.drawPolygon(s);
        else if (m_start.kind == StartSet::Kind::Polyline)
            p.drawPolyline(s);
        const double r = kHandleRadius * u;
        for (int i = 0; i < s.size(); ++i) {
            const bool hot = onScreen && (i == m_hoverStart
                                          || (m_drag.kind == DragKind::StartVertex
                                              && m_drag.index == i));
            p.setPen(QPen(kStartColour.darker(130), 1.5 * u));
            p.setBrush(hot ? kStartColour : QColor(Qt::white));
            p.drawRect(QRectF(s[i].x() - r, s[i].y() - r, 2 * r, 2 * r));
        }
    }

    if (isLayerVisible(Layer::ControlPolygon) && !m_control.empty()) {
        QPolygonF s;
        for (int i = 0; i < int(m_control.size()); ++i)
            s << m.map(controlPointPosition(i));
        // One path (an SVG <path>, a PDF path) for the whole polygon. A light halo under it
        // keeps it readable over a dense attractor.
        const QPainterPath polygon = polylinePath(s, m_controlClosed);
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(QColor(255, 255, 255, 200), 3.5 * u, Qt::SolidLine, Qt::RoundCap,
                      Qt::RoundJoin));
        p.drawPath(polygon);
        p.setPen(QPen(kControlColour, 1.2 * u, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPath(polygon);
        const double r = kHandleRadius * u;
        for (int i = 0; i < s.size(); ++i) {
            const bool hot = onScreen && (i == m_hoverControl
                                          || (m_drag.kind == DragKind::ControlPoint
                                              && m_drag.index == i));
            p.setPen(QPen(kControlColour, 1.5 * u));
            p.setBrush(hot ? QColor(255, 200, 0) : QColor(Qt::white));
            p.drawEllipse(s[i], r, r);
            const QString text = QStringLiteral("p") + subscript(i);
            const QPointF at(s[i].x() + r + 2 * u, s[i].y() - r - 1 * u);
            // White outline text: readable over the attractor and the grid.
            QPainterPath path;
            path.addText(at, f, text);
            p.setPen(QPen(QColor(255, 255, 255, 220), 3.0 * u, Qt::SolidLine, Qt::RoundCap,
                          Qt::RoundJoin));
            p.setBrush(Qt::NoBrush);
            p.drawPath(path);
            p.setPen(Qt::NoPen);
            p.setBrush(kControlColour);
            p.drawPath(path);
        }
    }
    p.restore();
}

void AttractorView::paintStatus(QPainter &p) const
{
    QStringList lines;
    if (!m_error.isEmpty())
        lines << m_error;
    else if (m_busy && m_busySince.isValid() && m_busySince.elapsed() > kQuietRenderMs)
        lines << tr("Rendering… %1 %").arg(int(std::round(100 * m_progress)));
    if (m_hutchTooMany && isLayerVisible(Layer::Hutchinson))
        lines << tr("F^%1(X₀) has too many images to draw as vectors").arg(m_hutchStep);
    if (lines.isEmpty())
        return;
    p.save();
    QFont f = font();
    p.setFont(f);
    const QFontMetrics fm(f);
    const int pad = 6;
    int y = height() - pad;
    for (auto it = lines.crbegin(); it != lines.crend(); ++it) {
        const QRect box = fm.boundingRect(QRect(0, 0, std::max(50, width() - 4 * pad), 1000),
                                          Qt::TextWordWrap, *it);
        const QRect r(pad, y - box.height() - pad, box.width() + 2 * pad, box.height() + pad);
        p.fillRect(r, QColor(255, 255, 255, 225));
        p.setPen(!m_error.isEmpty() && *it == m_error ? QColor(190, 30, 30) : QColor(60, 60, 60));
        p.drawText(r.adjusted(pad, pad / 2, -pad, 0), Qt::TextWordWrap, *it);
        y = r.top() - 2;
    }
    p.restore();
}

// ---- events -----------------------------------------------------------------------------------

void AttractorView::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    if (m_autoFit)
        fitToContents();
    scheduleRender();
}

void AttractorView::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    scheduleRender();
}

int AttractorView::hitControlPoint(const QPointF &screen) const
{
    if (!m_editControl || !isLayerVisible(Layer::ControlPolygon))
        return -1;
    int best = -1;
    double bestD = kHitRadius;
    for (int i = 0; i < int(m_control.size()); ++i) {
        const double d = QLineF(worldToScreen(controlPointPosition(i)), screen).length();
        if (d <= bestD) {
            bestD = d;
            best = i;
        }
    }
    return best;
}

int AttractorView::hitStartVertex(const QPointF &screen) const
{
    if (!m_editStart || !isLayerVisible(Layer::StartSet))
        return -1;
    int best = -1;
    double bestD = kHitRadius;
    for (int i = 0; i < int(m_startPlane.size()); ++i) {
        const double d = QLineF(worldToScreen(startVertexPosition(i)), screen).length();
        if (d <= bestD) {
            bestD = d;
            best = i;
        }
    }
    return best;
}

void AttractorView::mousePressEvent(QMouseEvent *event)
{
    if (m_drag.kind != DragKind::None) {
        event->accept(); // a second button during a drag changes nothing
        return;
    }
    const QPointF pos = event->position();
    m_drag = Drag();
    m_drag.pressScreen = m_drag.lastScreen = pos;
    m_drag.pressWorld = screenToWorld(pos);
    if (event->button() == Qt::LeftButton) {
        // Control points win over start-set vertices: they are what a user edits most.
        if (const int i = hitControlPoint(pos); i >= 0) {
            m_drag.kind = DragKind::ControlPoint;
            m_drag.index = i;
            m_drag.startWorld = m_drag.currentWorld = m_control[i];
        } else if (const int j = hitStartVertex(pos); j >= 0) {
            m_drag.kind = DragKind::StartVertex;
            m_drag.index = j;
            m_drag.startWorld = m_drag.currentWorld = m_startPlane[j];
        }
        if (m_drag.kind != DragKind::None) {
            userMovedView(); // the content moves under the user's hand: no auto-fit now
            setCursor(Qt::ClosedHandCursor);
            if (m_drag.kind == DragKind::ControlPoint)
                emit controlPointPressed(m_drag.index);
            else
                emit startVertexPressed(m_drag.index);
            update();
        }
    } else if (event->button() == Qt::MiddleButton || event->button() == Qt::RightButton) {
        m_drag.kind = DragKind::Pan;
        setCursor(Qt::SizeAllCursor);
    }
    event->accept();
}

void AttractorView::mouseMoveEvent(QMouseEvent *event)
{
    const QPointF pos = event->position();
    emit cursorMoved(screenToWorld(pos));
    switch (m_drag.kind) {
    case DragKind::None: {
        const int c = hitControlPoint(pos);
        const int s = c >= 0 ? -1 : hitStartVertex(pos);
        if (c != m_hoverControl || s != m_hoverStart) {
            m_hoverControl = c;
            m_hoverStart = s;
            setCursor(c >= 0 || s >= 0 ? Qt::OpenHandCursor : Qt::ArrowCursor);
            update();
        }
        break;
    }
    case DragKind::Pan: {
        const QPointF d = pos - m_drag.lastScreen;
        m_drag.lastScreen = pos;
        if (!d.isNull()) {
            userMovedView();
            setView(m_center - QPointF(d.x() / m_scale, -d.y() / m_scale), m_scale);
        }
        break;
    }
    case DragKind::ControlPoint:
    case DragKind::StartVertex: {
        // Move by the cursor's displacement: grabbing a handle off-centre does not make it jump.
        const QPointF w = m_drag.startWorld + (screenToWorld(pos) - m_drag.pressWorld);
        if (w == m_drag.currentWorld)
            break;
        m_drag.currentWorld = w;
        m_drag.lastScreen = pos;
        if (m_drag.kind == DragKind::ControlPoint)
            emit controlPointDragged(m_drag.index, w);
        else
            emit startVertexDragged(m_drag.index, w);
        update();
        break;
    }
    }
    event->accept();
}

void AttractorView::mouseReleaseEvent(QMouseEvent *event)
{
    const Drag d = m_drag;
    const bool ends = (d.kind == DragKind::Pan && (event->button() == Qt::MiddleButton
                                                   || event->button() == Qt::RightButton))
                      || ((d.kind == DragKind::ControlPoint || d.kind == DragKind::StartVertex)
                          && event->button() == Qt::LeftButton);
    if (!ends) {
        event->accept();
        return;
    }
    m_drag = Drag();
    setCursor(Qt::ArrowCursor);
    if (d.kind == DragKind::ControlPoint)
        emit controlPointReleased(d.index, d.startWorld, d.currentWorld);
    else if (d.kind == DragKind::StartVertex)
        emit startVertexReleased(d.index, d.startWorld, d.currentWorld);
    update();
    event->accept();
}

void AttractorView::wheelEvent(QWheelEvent *event)
{
    const double notches = event->angleDelta().y() / 120.0;
    if (notches == 0) {
        event->ignore();
        return;
    }
    userMovedView();
    zoomBy(std::pow(1.2, notches), event->position());
    event->accept();
}

void AttractorView::keyPressEvent(QKeyEvent *event)
{
    switch (event->key()) {
    case Qt::Key_Home:
    case Qt::Key_F:
        fitToContents();
        break;
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        userMovedView();
        zoomIn();
        break;
    case Qt::Key_Minus:
        userMovedView();
        zoomOut();
        break;
    default:
        QWidget::keyPressEvent(event);
        return;
    }
    event->accept();
}

void AttractorView::leaveEvent(QEvent *event)
{
    QWidget::leaveEvent(event);
    if (m_hoverControl >= 0 || m_hoverStart >= 0) {
        m_hoverControl = m_hoverStart = -1;
        update();
    }
    emit cursorLeft();
}

} // namespace awb
