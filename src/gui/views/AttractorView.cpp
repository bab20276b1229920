// AttractorView: construction, the data setters, world <-> screen mapping, fitting and zoom,
// and the render orchestration (requests to the AttractorRenderer, cancel, render again).
// Painting, widget events and the vector images of F^k(X0) live in the other
// AttractorView*.cpp units.

#include "gui/views/AttractorView.h"

#include "render/AttractorBounds.h"

#include "gui/views/AttractorViewDetail.h"

#include "core/analysis/Spectrum.h"
#include "gui/views/FrameLog.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace awb {

using namespace attractor_view;

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
    return {m_center, m_scale, QRectF(rect()), 1.0};
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
    m_refineTimer.setSingleShot(true);
    m_refineTimer.setInterval(kRefineDelayMs);
    connect(&m_refineTimer, &QTimer::timeout, this, &AttractorView::refineRender);
    connect(m_renderer, &AttractorRenderer::imageReady, this,
            [this](const QImage &image, const RenderInfo &info) {
                m_image = image;
                m_imageInfo = info;
                // The request's tag is the content version it drew.
                m_imageVersion = info.tag;
                ++m_imageSerial;
                m_error.clear();
                update();
                if (info.final && m_imageVersion == m_contentVersion)
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
                           CustomIterate iterate, CustomChaos chaos)
{
    m_ifs = std::move(ifs);
    m_iterate = std::move(iterate);
    m_chaos = std::move(chaos);
    m_start = start;
    if (!m_ifs) {
        // Nothing to draw: a picture of the previous IFS would be wrong.
        m_renderer->cancel();
        m_image = QImage();
        m_imageInfo = RenderInfo();
        m_error.clear();
        m_cancelled = false;
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
    setControlPolygons(points.rows() > 0 ? std::vector<Mat>{points} : std::vector<Mat>{},
                       {closed});
}

void AttractorView::setControlPolygons(const std::vector<Mat> &sets,
                                       const std::vector<bool> &closed)
{
    m_control.clear();
    m_controlSets.clear();
    m_controlClosedSets.clear();
    for (std::size_t k = 0; k < sets.size(); ++k) {
        const QPolygonF poly = toPolygon(sets[k]);
        m_control.insert(m_control.end(), poly.begin(), poly.end());
        m_controlSets.push_back(int(poly.size()));
        m_controlClosedSets.push_back(k < closed.size() && closed[k]);
    }
    if (m_drag.kind == DragKind::ControlPoint && m_drag.index >= int(m_control.size()))
        m_drag = Drag();
    dataChanged(true);
}

std::pair<int, int> AttractorView::controlPointSet(int flat) const
{
    if (flat < 0)
        return {-1, -1};
    for (int k = 0; k < int(m_controlSets.size()); ++k) {
        if (flat < m_controlSets[std::size_t(k)])
            return {k, flat};
        flat -= m_controlSets[std::size_t(k)];
    }
    return {-1, -1};
}

void AttractorView::setExactCurve(const Mat &curve, const QString &label)
{
    m_exact = toPolygon(curve);
    m_exactLabel = m_exact.size() > 1 ? label : QString();
    update();
}

void AttractorView::setSubdivisionPolygons(const std::vector<Mat> &polygons,
                                           const std::vector<bool> &closed)
{
    m_subdivision.clear();
    m_subdivisionClosed.clear();
    for (size_t k = 0; k < polygons.size(); ++k) {
        m_subdivision.push_back(toPolygon(polygons[k]));
        m_subdivisionClosed.push_back(k < closed.size() && closed[k]);
    }
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
    // A chaos game of its own (a flame) starts from random points: no start set to show.
    if (X.rows() == 0 || m_chaos)
        return;
    Mat plane;
    if (m_ifs && !m_ifs->views.empty() && X.cols() == m_ifs->dim())
        plane = project(m_ifs->views.front(), X);
    else if (X.cols() == 2)
        plane = X;
    const QPolygonF poly = toPolygon(plane);
    m_startPlane.assign(poly.begin(), poly.end());
}

void AttractorView::dataChanged(bool geometryChanged)
{
    ++m_contentVersion;
    if (framelog::enabled() && (m_drag.kind == DragKind::ControlPoint
                                || m_drag.kind == DragKind::StartVertex)) {
        m_versionInput.emplace_back(m_contentVersion,
                                    mapToGlobal(m_drag.lastScreen.toPoint()));
        if (m_versionInput.size() > 256)
            m_versionInput.erase(m_versionInput.begin(), m_versionInput.begin() + 128);
    }
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
    // The attractor, framed as a figure file frames it (render/AttractorBounds.h).
    if (m_ifs) {
        AttractorExtent a;
        a.ifs = m_ifs.get();
        a.iterate = m_iterate;
        a.chaos = m_chaos;
        a.start = m_start;
        a.depth = m_settings.depth;
        a.random = m_settings.mode == RenderRequest::Mode::Random;
        a.samples = m_settings.samples;
        a.seed = m_settings.seed;
        if (const auto box = attractorBounds(a))
            all << box->topLeft() << box->bottomRight();
    }
    return boundsOf(all);
}

std::optional<QRectF> AttractorView::fittedWorld() const
{
    const std::optional<QRectF> bounds = contentBounds();
    if (!bounds)
        return std::nullopt;
    QRectF r = *bounds;
    // A single point or a straight horizontal/vertical set still needs a visible extent.
    const double extent = std::max({r.width(), r.height(), 1e-9 * std::abs(r.center().x()),
                                    1e-9 * std::abs(r.center().y()), 1e-12});
    if (r.width() < 1e-3 * extent)
        r.adjust(-0.5 * extent, 0, 0.5 * extent, 0);
    if (r.height() < 1e-3 * extent)
        r.adjust(0, -0.5 * extent, 0, 0.5 * extent);
    return r;
}

void AttractorView::fitToContents()
{
    const std::optional<QRectF> fitted = fittedWorld();
    if (!fitted) {
        setView(QPointF(0, 0), 50.0);
        return;
    }
    const QRectF r = *fitted;
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

void AttractorView::setGestureActive(bool active)
{
    if (active == m_externalGesture)
        return;
    m_externalGesture = active;
    if (!active && !isInteractive())
        refineRender();
}

bool AttractorView::isInteractive() const
{
    return m_externalGesture || m_drag.kind != DragKind::None
           || (m_wheelGesture.isValid() && m_wheelGesture.elapsed() < kRefineDelayMs);
}

void AttractorView::scheduleRender()
{
    if (!isLayerVisible(Layer::Attractor))
        return;
    // During a gesture a render starts at the next turn of the event loop (the edits of one
    // pointer event coalesce); otherwise after a short pause (a burst of setters).
    m_renderTimer.start(isInteractive() ? 0 : 10);
}

void AttractorView::startRender()
{
    requestRender(isInteractive() ? RenderKind::Interactive : RenderKind::Full);
}

void AttractorView::requestRender(RenderKind kind)
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
    const double dpr = devicePixelRatioF();
    const RenderRequest r = renderRequest(world,
                                          QSize(std::max(1, int(std::lround(width() * dpr))),
                                                std::max(1, int(std::lround(height() * dpr)))),
                                          dpr);
    if (kind == RenderKind::Interactive) {
        // A frame's worth of picture now, the full one when the gesture pauses or ends.
        m_requestedVersion = m_contentVersion;
        m_fullRequest.reset();
        m_cancelled = false;
        m_renderer->request(r, AttractorRenderer::Quality::Interactive, m_contentVersion);
        m_refineTimer.start();
        return;
    }
    m_refineTimer.stop();
    const std::pair<std::uint64_t, QRectF> key{m_contentVersion, world};
    const bool done = m_imageVersion == m_contentVersion && m_imageInfo.final
                      && m_imageInfo.world == world && m_image.size() == r.size;
    // The full picture of this content is drawn or being drawn (a release after a pause).
    if (kind != RenderKind::Again && ((m_fullRequest == key && m_busy) || done))
        return;
    m_fullRequest = key;
    m_requestedVersion = m_contentVersion;
    m_cancelled = false; // a new render replaces the "cancelled" note
    m_progress = 0.0;
    // An interactive picture of this very content is shown: no coarse level first.
    const bool shown = !m_image.isNull() && m_imageInfo.interactive
                       && m_imageVersion == m_contentVersion && m_imageInfo.world == world
                       && m_image.size() == r.size;
    m_renderer->request(r, shown ? AttractorRenderer::Quality::Refine
                                 : AttractorRenderer::Quality::Full,
                        m_contentVersion);
}

void AttractorView::refineRender()
{
    m_renderTimer.stop();
    requestRender(RenderKind::Full);
}

RenderRequest AttractorView::renderRequest(const QRectF &world, QSize size,
                                           double pixelsPerScreenPixel) const
{
    RenderRequest r;
    r.ifs = m_ifs;
    r.iterate = m_iterate;
    r.chaos = m_chaos;
    r.start = m_start;
    r.mode = m_settings.mode;
    r.depth = m_settings.depth;
    r.samples = m_settings.samples;
    r.seed = m_settings.seed;
    r.world = world;
    r.size = size;
    r.colouring = m_settings.colouring;
    r.dotRadius = int(std::lround(m_settings.dotRadius * pixelsPerScreenPixel));
    r.tone = m_settings.tone;
    // Exports and prints drawn at more pixels than the screen: anti-alias the edges.
    r.supersample = pixelsPerScreenPixel > 1.5 ? 2 : 1;
    return r;
}

AttractorDensity AttractorView::rawDensity(QSize size) const
{
    if (!m_ifs)
        throw InputError(tr("there is no attractor to count").toStdString());
    QRectF world = visibleWorldRect();
    // The view's frame at the export's proportions (centred, one scale on both axes).
    const double k = std::max(world.width() / size.width(), world.height() / size.height());
    world = QRectF(world.center() - QPointF(0.5 * k * size.width(), 0.5 * k * size.height()),
                   QSizeF(k * size.width(), k * size.height()));
    RenderRequest r = renderRequest(world, size, 1.0);
    r.supersample = 1;
    return renderAttractorDensity(r);
}

void AttractorView::cancelRender()
{
    if (!isRendering())
        return;
    // A render scheduled meanwhile (a zoom during the render) would restart the work at once.
    m_renderTimer.stop();
    m_cancelled = true;
    m_cancelledAt = m_progress;
    // The renderer drops everything the cancelled request still posts and reports not busy
    // (busyChanged) right away; m_image keeps the last finished pass, e.g. the coarse one.
    m_renderer->cancel();
    update();
    emit renderCancelled();
}

void AttractorView::renderAgain()
{
    m_renderTimer.stop();
    m_cancelled = false;
    requestRender(RenderKind::Again);
    update();
}

} // namespace awb
