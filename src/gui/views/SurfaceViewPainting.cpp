// SurfaceView: painting -- the CPU frame with the overlays over it (the GL window paints its
// own), figures for print and export through the CPU renderer, and the frame log.

#include "gui/views/SurfaceView.h"

#include "gui/views/FrameLog.h"
#include "gui/views/SurfaceGLWindow.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <QResizeEvent>
#include <QVector4D>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>

namespace awb {

namespace {

constexpr double handleRadius = 4.5;

bool sameCamera(const OrthoCamera &a, const OrthoCamera &b)
{
    return a.azimuth == b.azimuth && a.elevation == b.elevation && a.centre == b.centre
           && a.halfHeight == b.halfHeight;
}

} // namespace

// The CPU frame of a mesh as an image (the raster's pixels are 0xAARRGGBB rows).
QImage SurfaceView::pixelsToImage(const std::vector<std::uint32_t> &pixels, QSize size)
{
    if (pixels.size() != std::size_t(size.width()) * std::size_t(size.height()))
        return {};
    QImage image(size, QImage::Format_RGB32);
    for (int y = 0; y < size.height(); ++y)
        std::copy_n(pixels.begin() + std::ptrdiff_t(y) * size.width(), size.width(),
                    reinterpret_cast<std::uint32_t *>(image.scanLine(y)));
    return image;
}

void SurfaceView::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    if (m_glContainer)
        m_glContainer->setGeometry(rect());
    if (!m_cameraSet && m_net.rows() > 0)
        resetCamera();
    else
        requestFrame();
}

void SurfaceView::paintEvent(QPaintEvent *)
{
    if (m_glContainer)
        return; // the GL window covers the view and paints the overlays itself
    QPainter p(this);
    p.fillRect(rect(), Qt::white);
    p.setRenderHint(QPainter::Antialiasing);
    if (!m_cpuImage.isNull() && isLayerVisible(Layer::Attractor)) {
        // A frame of another camera (the next one is on its way): scale it about the centre
        // so that zooming looks continuous; rotation just waits for the next frame.
        const double k = m_cpuImageCamera.halfHeight / std::max(m_camera.ortho.halfHeight, 1e-12);
        QRectF r(QPointF(0, 0), QSizeF(m_cpuImage.size()) / devicePixelRatioF() * k);
        r.moveCenter(QRectF(rect()).center());
        p.drawImage(r, m_cpuImage);
    }
    paintOverlay(p, viewMatrix(QSizeF(size())), QRectF(rect()), 1.0);
    p.setPen(QColor(110, 110, 110));
    QString label = isRendering() && !pointMoving() && !m_moving ? tr("Drawing… (CPU renderer)")
                                                                 : tr("CPU renderer");
    // A depth the detail budget lowered is said, not hidden (a mesh at depth 7 has 1.5 M
    // faces: the view draws depth 6 at rest and a coarser one while something moves).
    if (m_meshes.full && m_meshes.full->depth < m_settings.depth)
        label = tr("depth %1 of %2 (detail budget: %3 k primitives) · %4")
                    .arg(m_meshes.full->depth)
                    .arg(m_settings.depth)
                    .arg(m_fullBudget / 1000)
                    .arg(label);
    p.drawText(QRectF(rect()).adjusted(6, 4, -6, -4), Qt::AlignRight | Qt::AlignBottom, label);
    p.end();
    if (framelog::enabled()) {
        const bool final = !m_moving && !pointMoving() && !isRendering() && m_meshes.full
                           && m_cpuImageMesh == m_meshes.full
                           && sameCamera(m_cpuImageCamera, m_camera.ortho);
        logFrame(m_cpuPictures, final, m_cpuImageShows ? &m_cpuImageInput : nullptr);
    }
}

void SurfaceView::logFrame(std::uint64_t picture, bool final, const QPoint *shows)
{
    QString handle = QStringLiteral("-");
    if (m_drag.kind == DragKind::ControlPoint || m_drag.kind == DragKind::StartVertex)
        handle = framelog::point(mapToGlobal(toScreen(m_drag.currentWorld).toPoint()));
    framelog::write("frame", QStringLiteral("surface image=%1 final=%2 handle=%3 shows=%4 "
                                            "work=%5 ms=%6 mesh=%7")
                                 .arg(picture).arg(final ? 1 : 0)
                                 .arg(handle, shows ? framelog::point(*shows)
                                                    : QStringLiteral("-"))
                                 .arg(m_framePrimitives).arg(m_frameMs, 0, 'f', 1)
                                 .arg(m_meshSeconds * 1e3, 0, 'f', 1));
    if (!final || m_drag.kind != DragKind::None)
        return;
    std::vector<QPoint> handles;
    for (int i = 0; i < controlPointCount(); ++i)
        handles.push_back(mapToGlobal(controlPointScreen(i).toPoint()));
    if (handles == m_loggedHandles)
        return;
    m_loggedHandles = handles;
    const QPoint o = mapToGlobal(QPoint(0, 0));
    framelog::write("area", QStringLiteral("surface %1 %2 %3 %4")
                                .arg(o.x()).arg(o.y()).arg(width()).arg(height()));
    for (std::size_t i = 0; i < handles.size(); ++i)
        framelog::write("handle", QStringLiteral("surface %1 %2 %3")
                                      .arg(i).arg(handles[i].x()).arg(handles[i].y()));
}

QImage SurfaceView::renderImage(QSize size, bool overlays) const
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    if (overlays) {
        renderTo(&p, QRectF(QPointF(0, 0), QSizeF(size)));
    } else if (const auto mesh = figureMesh(); mesh && isLayerVisible(Layer::Attractor)) {
        OrthoCamera camera = m_camera.ortho;
        const double aspectView = double(std::max(1, width())) / std::max(1, height());
        const double aspect = double(size.width()) / std::max(1, size.height());
        if (aspect < aspectView)
            camera.halfHeight *= aspectView / aspect;
        const double radius = std::max(0.5, 0.5 * m_settings.pointSize
                                                * (double(size.height()) / std::max(1, height())));
        const QImage raster = pixelsToImage(drawSurfaceMesh(*mesh, size.width(), size.height(), camera,
                                                      radius, colours().palette),
                                      size);
        if (!raster.isNull())
            p.drawImage(0, 0, raster);
    }
    return image;
}

void SurfaceView::renderTo(QPainter *painter, const QRectF &target) const
{
    // Keep what the screen shows across the width when the figure is narrower than the view.
    SurfaceView *self = const_cast<SurfaceView *>(this);
    const SurfaceViewCamera saved = m_camera;
    const double aspectView = double(std::max(1, width())) / std::max(1, height());
    const double aspect = target.width() / std::max(1.0, target.height());
    if (aspect < aspectView)
        self->m_camera.ortho.halfHeight *= aspectView / aspect;
    // Device pixels of the target, capped: a printer page at 1200 dpi needs no 10k raster.
    const QTransform t = painter->deviceTransform();
    const QRectF device = t.mapRect(target);
    const double k = std::min(1.0, 2400.0 / std::max(1.0, device.width()));
    const QSize pixels = (device.size() * k).toSize().expandedTo(QSize(1, 1));
    if (isLayerVisible(Layer::Attractor)) {
        // The screen's own mesh (the same primitives and colours as the frames on screen).
        if (const auto mesh = figureMesh()) {
            const double radius = std::max(0.5, 0.5 * m_settings.pointSize
                                                    * (double(pixels.height())
                                                       / std::max(1, height())));
            const QImage raster = pixelsToImage(drawSurfaceMesh(*mesh, pixels.width(), pixels.height(),
                                                          m_camera.ortho, radius,
                                                          colours().palette),
                                          pixels);
            if (!raster.isNull())
                painter->drawImage(target, raster);
        }
    }
    // The overlays as vectors, through the same (orthographic) camera.
    SurfaceViewCamera ortho = m_camera;
    ortho.perspective = false;
    self->m_camera = ortho;
    const QMatrix4x4 mvp = viewMatrix(target.size());
    const double unit = std::max(1.0, target.height() / std::max(1, height()));
    painter->save();
    painter->setClipRect(target);
    paintOverlay(*painter, mvp, target, unit);
    painter->restore();
    self->m_camera = saved;
}

QImage SurfaceView::grabGlFrame() const
{
    return m_glWindow ? m_glWindow->grabFramebuffer() : QImage();
}

void SurfaceView::requestGlFrame()
{
    if (m_glWindow)
        m_glWindow->update();
}

void SurfaceView::paintOverlay(QPainter &p, const QMatrix4x4 &mvp, const QRectF &target,
                               double unit) const
{
    const auto at = [&](const Mat &m, int r) {
        return project(mvp, target, QVector3D(float(m(r, 0)), float(m(r, 1)), float(m(r, 2))));
    };
    const auto faces = [&](const Mat &points, const std::vector<std::vector<int>> &list,
                           const QPen &pen) {
        // Each edge once: shared edges drawn twice look heavier where antialiased.
        QPainterPath path;
        for (const auto &f : list)
            for (std::size_t k = 0; k < f.size(); ++k) {
                const int i = f[k], j = f[(k + 1) % f.size()];
                if (i > j && f.size() > 1)
                    continue;
                if (i < 0 || j < 0 || i >= points.rows() || j >= points.rows())
                    continue;
                path.moveTo(at(points, i));
                path.lineTo(at(points, j));
            }
        // Edges with i > j that have no partner (the border) must still be drawn. (The
        // partners by a set of directed edges: a scan of every face per edge was quadratic, a
        // minute per paint for a production mesh.)
        std::unordered_set<std::uint64_t> directed;
        const auto key = [](int a, int b) {
            return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
        };
        for (const auto &f : list)
            for (std::size_t k = 0; k < f.size(); ++k)
                directed.insert(key(f[k], f[(k + 1) % f.size()]));
        for (const auto &f : list)
            for (std::size_t k = 0; k < f.size(); ++k) {
                const int i = f[k], j = f[(k + 1) % f.size()];
                if (i <= j || i >= points.rows() || j < 0)
                    continue;
                if (!directed.count(key(j, i))) {
                    path.moveTo(at(points, i));
                    path.lineTo(at(points, j));
                }
            }
        p.setPen(pen);
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
    };
    const Mat b = sceneBounds();
    if (b.rows() == 2 && (isLayerVisible(Layer::Box) || isLayerVisible(Layer::Axes))) {
        Mat corners(8, 3);
        for (int k = 0; k < 8; ++k)
            for (int j = 0; j < 3; ++j)
                corners(k, j) = b((k >> j) & 1, j);
        if (isLayerVisible(Layer::Box)) {
            p.setPen(QPen(QColor(190, 190, 190), unit, Qt::DashLine));
            for (int k = 0; k < 8; ++k)
                for (int j = 0; j < 3; ++j)
                    if (!((k >> j) & 1))
                        p.drawLine(at(corners, k), at(corners, k | (1 << j)));
        }
        if (isLayerVisible(Layer::Axes)) {
            const QColor colours[] = {QColor(200, 40, 40), QColor(40, 150, 40),
                                      QColor(40, 70, 200)};
            const QString names[] = {tr("x"), tr("y"), tr("z")};
            // Fonts set in pixels (a printer's) have no point size: scale what is set.
            // The widget's text size in screen pixels times `unit`, whatever the painter's
            // device: a printed figure's labels look as on screen.
            QFont font = this->font();
            font.setPixelSize(std::max(1, int(std::lround(0.9 * QFontInfo(this->font())
                                                                      .pixelSize() * unit))));
            p.setFont(font);
            for (int j = 0; j < 3; ++j) {
                const QPointF o = at(corners, 0), e = at(corners, 1 << j);
                p.setPen(QPen(colours[j], 1.6 * unit));
                p.drawLine(o, e);
                p.drawText(e + QPointF(4, -4) * unit, names[j]);
            }
        }
    }
    if (isLayerVisible(Layer::Mesh) && m_refined.rows() > 0)
        faces(m_refined, m_refinedFaces, QPen(QColor(120, 120, 120, 150), 0.8 * unit));
    if (isLayerVisible(Layer::ControlNet) && m_net.rows() > 0) {
        faces(m_net, m_netFaces, QPen(QColor(40, 40, 40, 200), 1.2 * unit));
        // Holes hatched; the selected face outlined.
        const auto outline = [&](int f) {
            QPolygonF poly;
            for (int v : m_netFaces[std::size_t(f)])
                if (v >= 0 && v < m_net.rows())
                    poly << at(m_net, v);
            return poly;
        };
        for (int f : m_holes)
            if (f >= 0 && f < int(m_netFaces.size())) {
                p.setPen(Qt::NoPen);
                p.setBrush(QBrush(QColor(90, 90, 90, 150), Qt::BDiagPattern));
                p.drawPolygon(outline(f));
            }
        if (m_selectedFace >= 0 && m_selectedFace < int(m_netFaces.size())) {
            p.setPen(QPen(QColor(40, 110, 230), 3.0 * unit));
            p.setBrush(QColor(40, 110, 230, 40));
            p.drawPolygon(outline(m_selectedFace));
        }
        p.setBrush(Qt::NoBrush);
        // The selected edge: a wide halo under its crease, if it has one.
        if (const auto [a, b] = m_selectedEdge;
            a >= 0 && b >= 0 && a < m_net.rows() && b < m_net.rows()) {
            p.setPen(QPen(QColor(40, 110, 230), 6.0 * unit));
            p.drawLine(at(m_net, a), at(m_net, b));
        }
        // Sharp edges over the net: infinitely sharp ones solid, semi-sharp ones dashed, in the
        // colour of creases in modelling tools.
        for (const SharpEdge &e : m_sharpEdges) {
            if (e.a < 0 || e.b < 0 || e.a >= m_net.rows() || e.b >= m_net.rows()
                || !(e.sharpness > 0.0f))
                continue;
            const bool infinite = e.sharpness >= kSharpnessInfinite;
            p.setPen(QPen(QColor(225, 90, 20), (infinite ? 3.0 : 2.4) * unit,
                          infinite ? Qt::SolidLine : Qt::DashLine));
            p.drawLine(at(m_net, e.a), at(m_net, e.b));
        }
        p.setPen(QPen(QColor(30, 30, 30), 1.2 * unit));
        for (int i = 0; i < m_net.rows(); ++i) {
            const bool active = (m_drag.kind == DragKind::ControlPoint && m_drag.index == i)
                                || m_selected == i;
            p.setBrush(active ? QColor(230, 80, 40) : QColor(255, 255, 255));
            p.drawEllipse(at(m_net, i), handleRadius * unit, handleRadius * unit);
        }
    }
    if (!m_markers.empty()) {
        QFont font = this->font();
        font.setPixelSize(std::max(1, int(std::lround(0.9 * QFontInfo(this->font())
                                                                  .pixelSize() * unit))));
        font.setBold(true);
        p.setFont(font);
        const QFontMetricsF fm(font);
        // Markers behind a closed surface first, faded and unlabelled; then the seen ones,
        // the selected one last (on top). Hundreds of markers (a car, a scanned mesh) get
        // smaller diamonds, and a label only where it does not cover another (issue 47:
        // "a carpet of diamonds with stacked labels").
        std::vector<int> hidden, seen;
        for (int i = 0; i < markerCount(); ++i)
            (markerFacing(i) ? seen : hidden).push_back(i);
        std::stable_partition(seen.begin(), seen.end(),
                              [this](int i) { return i != m_selectedMarker; });
        const double size = seen.size() > 60 ? 0.8 : 1.25;
        for (int i : hidden) {
            const QPointF c = project(mvp, target, m_markers[std::size_t(i)].at);
            const double r = 0.8 * handleRadius * unit;
            QPolygonF diamond;
            diamond << c + QPointF(0, -r) << c + QPointF(r, 0) << c + QPointF(0, r)
                    << c + QPointF(-r, 0);
            p.setPen(QPen(QColor(60, 20, 90, 70), 1.0 * unit));
            p.setBrush(Qt::NoBrush);
            p.drawPolygon(diamond);
        }
        std::vector<QRectF> labelled;
        // The selected marker's label is placed first: it always shows.
        std::vector<int> order = seen;
        std::stable_partition(order.begin(), order.end(),
                              [this](int i) { return i == m_selectedMarker; });
        std::vector<char> showLabel(std::size_t(markerCount()), 0);
        for (int i : order) {
            const Marker &m = m_markers[std::size_t(i)];
            if (m.label.isEmpty())
                continue;
            const QPointF c = project(mvp, target, m.at);
            const double r = size * handleRadius * unit;
            const QRectF box = fm.boundingRect(m.label).translated(c + QPointF(r + 2 * unit, -r))
                                   .adjusted(-2 * unit, -2 * unit, 2 * unit, 2 * unit);
            if (std::any_of(labelled.begin(), labelled.end(),
                            [&](const QRectF &b) { return b.intersects(box); }))
                continue;
            labelled.push_back(box);
            showLabel[std::size_t(i)] = 1;
        }
        for (int i : seen) {
            const Marker &m = m_markers[std::size_t(i)];
            const QPointF c = project(mvp, target, m.at);
            const double r = size * handleRadius * unit;
            const bool selected = i == m_selectedMarker;
            QPolygonF diamond;
            diamond << c + QPointF(0, -r) << c + QPointF(r, 0) << c + QPointF(0, r)
                    << c + QPointF(-r, 0);
            p.setPen(QPen(selected ? QColor(120, 20, 0) : QColor(60, 20, 90), 1.2 * unit));
            p.setBrush(selected ? QColor(240, 90, 30) : QColor(150, 90, 210));
            p.drawPolygon(diamond);
            if (!showLabel[std::size_t(i)])
                continue;
            const QPointF at = c + QPointF(r + 2 * unit, -r);
            // A white halo keeps the label legible over the shaded surface.
            QPainterPath text;
            text.addText(at, font, m.label);
            p.setPen(QPen(QColor(255, 255, 255, 220), 3 * unit));
            p.setBrush(Qt::NoBrush);
            p.drawPath(text);
            p.setPen(Qt::NoPen);
            p.setBrush(selected ? QColor(150, 30, 0) : QColor(50, 10, 80));
            p.drawPath(text);
        }
    }
    if (m_start3.rows() > 0) {
        p.setPen(QPen(QColor(200, 110, 0), 1.2 * unit));
        p.setBrush(QColor(255, 200, 120));
        for (int i = 0; i < m_start3.rows(); ++i) {
            const QPointF c = at(m_start3, i);
            const double r = 0.8 * handleRadius * unit;
            p.drawRect(QRectF(c - QPointF(r, r), c + QPointF(r, r)));
        }
    }
}

} // namespace awb
