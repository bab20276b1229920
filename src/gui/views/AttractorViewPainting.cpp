// AttractorView: painting of the scene (grid, subdivision polygons, exact curve, attractor
// raster or vector dots, Hutchinson images, handles, legend) on screen and into an export, and
// the status overlay (errors, render progress, a cancelled render).

#include "gui/views/AttractorView.h"
#include "render/CurvePaths.h"

#include "gui/views/AttractorViewDetail.h"
#include "gui/views/FrameLog.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

namespace awb {

using namespace attractor_view;

// ---- painting ---------------------------------------------------------------------------------

void AttractorView::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    paintScene(p, screenMapping(), false);
    paintStatus(p);
    p.end();
    if (framelog::enabled())
        logFrame();
}

void AttractorView::logFrame()
{
    QString handle = QStringLiteral("-"), shows = QStringLiteral("-");
    if (m_drag.kind == DragKind::ControlPoint || m_drag.kind == DragKind::StartVertex)
        handle = framelog::point(mapToGlobal(worldToScreen(m_drag.currentWorld).toPoint()));
    for (auto it = m_versionInput.rbegin(); it != m_versionInput.rend(); ++it)
        if (it->first <= m_imageVersion) {
            if (it->first + 1 > m_imageVersion) // the picture of exactly that edit
                shows = framelog::point(it->second);
            break;
        }
    const bool final = m_imageInfo.final && m_imageVersion == m_contentVersion;
    framelog::write("frame", QStringLiteral("attractor image=%1 final=%2 handle=%3 shows=%4 "
                                            "depth=%5 work=%6 ms=%7")
                                 .arg(m_imageSerial).arg(final ? 1 : 0).arg(handle, shows)
                                 .arg(m_imageInfo.depth).arg(m_imageInfo.images)
                                 .arg(m_imageInfo.seconds * 1e3, 0, 'f', 1));
    if (!final || m_drag.kind != DragKind::None)
        return;
    std::vector<QPoint> handles;
    for (int i = 0; i < int(m_control.size()); ++i)
        handles.push_back(mapToGlobal(worldToScreen(m_control[std::size_t(i)]).toPoint()));
    if (handles == m_loggedHandles)
        return;
    m_loggedHandles = handles;
    const QPoint o = mapToGlobal(QPoint(0, 0));
    framelog::write("area", QStringLiteral("attractor %1 %2 %3 %4")
                                .arg(o.x()).arg(o.y()).arg(width()).arg(height()));
    for (std::size_t i = 0; i < handles.size(); ++i)
        framelog::write("handle", QStringLiteral("attractor %1 %2 %3")
                                      .arg(i).arg(handles[i].x()).arg(handles[i].y()));
}

void AttractorView::renderTo(QPainter *painter, const QRectF &target, Framing framing)
{
    ExportStyle style;
    style.framing = framing;
    renderTo(painter, target, style);
}

void AttractorView::renderTo(QPainter *painter, const QRectF &target, const ExportStyle &style)
{
    m_exportCancelled = false;
    m_lastExportKind = QStringLiteral("none");
    if (!painter || target.isEmpty())
        return;
    // The same world rectangle as on screen, fitted into the target with equal scale.
    const QRectF vis = visibleWorldRect();
    Mapping m{m_center, std::min(target.width() / vis.width(), target.height() / vis.height()),
              target};
    m.unit = std::min(target.width() / std::max(1, width()),
                      target.height() / std::max(1, height()));
    if (style.framing == Framing::FitContents) {
        if (const auto r = fittedWorld()) {
            // The view's fit margin (or the style's), in the target's units.
            const double margin = (style.margin >= 0 ? style.margin : kFitMargin) * m.unit;
            const double w = std::max(1.0, target.width() - 2 * margin);
            const double h = std::max(1.0, target.height() - 2 * margin);
            m.center = r->center();
            m.scale = std::min(w / r->width(), h / r->height());
        }
    }
    m_exportStyle = style;
    painter->save();
    painter->setClipRect(target);
    painter->setRenderHint(QPainter::Antialiasing);
    // PDF writers and printers store images as JPEG unless told otherwise: keep the raster's
    // pixels exact (a one-pixel curve in JPEG grows grey halos).
    painter->setRenderHint(QPainter::LosslessImageRendering);
    paintScene(*painter, m, true);
    painter->restore();
    m_exportStyle = ExportStyle();
}

void AttractorView::paintScene(QPainter &p, const Mapping &m, bool forExport)
{
    // Line widths and marker sizes follow the figure, not the device: an export at printer
    // resolution looks like the screen.
    const double u = m.unit;
    p.fillRect(m.target, Qt::white);
    if (isLayerVisible(Layer::Grid) && (!forExport || m_exportStyle.grid))
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
            p.drawPath(polylinePath(s, m_subdivisionClosed[size_t(k)]));
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
        // An export to a vector device draws a curve as paths; other content as vector dots
        // or shapes when there are few, else as a raster of the target's device resolution.
        if (forExport && isVectorDevice(p) && paintCurvePaths(p, m)) {
            m_lastExportKind = QStringLiteral("curve paths");
        } else {
            paintAttractorImages(p, m, forExport);
        }
    }

    if (isLayerVisible(Layer::Hutchinson) && !m_hutch.empty())
        paintVectorImages(p, m, m_hutch, m_start.kind);

    paintHighlight(p, m);
    if (!forExport || m_exportStyle.handles)
        paintHandles(p, m);
    paintLegend(p, m);
}

void AttractorView::paintAttractorImages(QPainter &p, const Mapping &m, bool forExport)
{
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
    // The raster an export needs: the target's framing at the device's resolution (a PNG's
    // pixels, a PDF's dpi). The view's own raster serves only when it covers that framing at
    // that resolution or finer; otherwise the export renders its own.
    const double device = forExport ? devicePixelsPerLogical(p) : 1.0;
    const QSize pixels(std::max(1, int(std::lround(m.target.width() * device))),
                       std::max(1, int(std::lround(m.target.height() * device))));
    const QRectF needed = QRectF(m.unmap(m.target.bottomLeft()), m.unmap(m.target.topRight()))
                              .normalized();
    const double slack = 1e-6 * std::max(needed.width(), needed.height());
    const bool current = info.final && m_imageVersion == m_contentVersion;
    const bool covers = current && !image.isNull() && info.world.isValid()
                        && info.world.adjusted(-slack, -slack, slack, slack).contains(needed)
                        && image.width() / info.world.width()
                               >= 0.999 * m.scale * device;
    if (forExport && !vector && !covers && m_ifs && m_error.isEmpty())
        image = exportRaster(m, pixels, &info);
    if (vector) {
        paintVectorImages(p, m, dots, m_settings.mode == RenderRequest::Mode::Random
                                          ? StartSet::Kind::Points
                                          : m_start.kind);
        m_lastExportKind = QStringLiteral("vector");
    } else if (!image.isNull() && info.world.isValid()) {
        const QRectF w = info.world;
        const QRectF target(m.map(QPointF(w.left(), w.bottom())),
                            m.map(QPointF(w.right(), w.top())));
        // Nearest-neighbour scaling keeps a one-pixel curve crisp while zooming; the next
        // render replaces the stretched pixels anyway. An export's raster is made at the
        // device's resolution, so it is drawn 1:1.
        p.save();
        p.setRenderHint(QPainter::SmoothPixmapTransform, false);
        p.drawImage(target, image);
        p.restore();
        m_lastExportKind = QStringLiteral("raster %1x%2").arg(image.width()).arg(image.height());
    }
}

bool AttractorView::paintCurvePaths(QPainter &p, const Mapping &m) const
{
    // Automata (m_iterate) emit their images in no useful order: they get a raster.
    if (m_settings.mode != RenderRequest::Mode::Deterministic
        || m_start.kind != StartSet::Kind::Polyline || m_iterate || m_chaos || !m_ifs
        || m_ifs->size() == 0 || m_ifs->views.empty() || !m_error.isEmpty())
        return false;
    // Past this many images the iteration itself takes seconds; a raster is as good on paper.
    if (imageCount(*m_ifs, m_settings.depth) > kMaxExportCurveImages)
        return false;
    const QTransform toLogical(m.scale, 0, 0, -m.scale,
                               m.target.center().x() - m.center.x() * m.scale,
                               m.target.center().y() + m.center.y() * m.scale);
    const RenderSettings &s = m_settings;
    const int maps = m_ifs->size();
    CurvePathSink sink(m_ifs->views, toLogical, devicePixelsPerLogical(p),
                       [&s, maps](const std::uint8_t *a, int n) {
                           return AttractorRenderer::addressColor(s.colouring, maps, a, n);
                       },
                       kMaxExportCurveVertices);
    // In address order, so that neighbouring pieces of the curve come one after the other;
    // stopped as soon as the paths would be too big.
    std::atomic<bool> stop{false};
    IterationControl control;
    control.cancel = &stop;
    sink.setOverflowFlag(&stop);
    try {
        iterateAlong(*m_ifs, m_start, m_settings.depth, sink, control);
    } catch (const std::exception &) {
        return false;
    }
    if (sink.overflowed())
        return false;
    drawCurvePaths(p, sink.finish(), 1.3 * m.unit);
    return true;
}

void AttractorView::paintLegend(QPainter &p, const Mapping &m) const
{
    if (m_exactLabel.isEmpty() || !isLayerVisible(Layer::ExactCurve) || m_exact.size() < 2)
        return;
    const double u = m.unit;
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

QImage AttractorView::exportRaster(const Mapping &m, QSize pixels, RenderInfo *info) const
{
    // At the device's resolution, within the engine's bounds on the picture's size.
    const double k = std::min(1.0, kMaxExportRaster / double(std::max(pixels.width(),
                                                                       pixels.height())));
    const QSize size(std::max(1, int(pixels.width() * k)), std::max(1, int(pixels.height() * k)));
    const RenderRequest r = renderRequest(
        QRectF(m.unmap(m.target.bottomLeft()), m.unmap(m.target.topRight())).normalized(), size,
        size.width() / std::max(1.0, m.target.width() / std::max(1e-9, m.unit)));
    if (!m_exportProgress) {
        try {
            return AttractorRenderer::renderNow(r, info);
        } catch (const std::exception &) {
            return {};
        }
    }
    // On a worker thread, so the caller can show progress and offer to cancel.
    std::atomic<bool> cancel{false}, done{false};
    std::atomic<double> fraction{0.0};
    QImage image;
    RenderInfo local;
    std::thread worker([&] {
        IterationControl control;
        control.cancel = &cancel;
        control.progress = [&fraction](double f) { fraction.store(f); };
        try {
            image = AttractorRenderer::renderNow(r, &local, control);
        } catch (const std::exception &) {
            image = QImage();
        }
        done.store(true);
    });
    while (!done.load()) {
        if (!cancel.load() && !m_exportProgress(fraction.load())) {
            cancel.store(true);
            m_exportCancelled = true;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    worker.join();
    if (info)
        *info = local;
    return image;
}

QFont AttractorView::sceneFont(double factor, double u) const
{
    // Sized in device pixels, not points: a point size would grow once more with the
    // resolution of a printer or PDF on top of the figure's scale u.
    // An export may ask for its own font: a size in points is read at the screen's 96 dpi,
    // as the figure's scale u maps screen pixels to the target's.
    QFont f = font();
    if (!m_exportStyle.fontFamily.isEmpty())
        f.setFamily(m_exportStyle.fontFamily);
    const double px = m_exportStyle.fontPoints > 0 ? m_exportStyle.fontPoints * 96.0 / 72.0
                                                   : QFontInfo(font()).pixelSize();
    f.setPixelSize(std::max(1, int(std::lround(px * factor * u))));
    return f;
}

void AttractorView::paintGrid(QPainter &p, const Mapping &m) const
{
    const QRectF w = QRectF(m.unmap(m.target.bottomLeft()), m.unmap(m.target.topRight()))
                         .normalized();
    const double step = niceStep(90.0 * m.unit / m.scale); // ~90 screen px
    // Whatever the coordinates (1e300, 1e-300), at most a few hundred lines per axis.
    const std::optional<GridLines> xs = gridLines(w.left(), w.right(), step, 400);
    const std::optional<GridLines> ys = gridLines(w.top(), w.bottom(), step, 400);
    if (!xs || !ys)
        return;
    const double u = m.unit;
    p.save();
    p.setPen(QPen(QColor(232, 232, 236), 1.0 * u));
    for (int i = 0; i < xs->count; ++i) {
        const double x = (xs->first + i) * step;
        p.drawLine(m.map(QPointF(x, w.top())), m.map(QPointF(x, w.bottom())));
    }
    for (int i = 0; i < ys->count; ++i) {
        const double y = (ys->first + i) * step;
        p.drawLine(m.map(QPointF(w.left(), y)), m.map(QPointF(w.right(), y)));
    }
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
    for (int i = 0; i < xs->count; ++i) {
        const double x = (xs->first + i) * step;
        const QPointF s = m.map(QPointF(x, w.top()));
        p.drawText(QPointF(s.x() + 3 * u, m.target.bottom() - 4 * u), label(x));
    }
    for (int i = 0; i < ys->count; ++i) {
        const double y = (ys->first + i) * step;
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
    const double u = m.unit;
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
    const double u = m.unit;
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
        int first = 0;
        for (std::size_t k = 0; k < m_controlSets.size(); ++k) {
            const int n = m_controlSets[k];
            QPolygonF s;
            for (int i = first; i < first + n; ++i)
                s << m.map(controlPointPosition(i));
            // One path (an SVG <path>, a PDF path) per polygon. A light halo under it keeps
            // it readable over a dense attractor.
            const QPainterPath polygon = polylinePath(s, m_controlClosedSets[k]);
            p.setBrush(Qt::NoBrush);
            p.setPen(QPen(QColor(255, 255, 255, 200), 3.5 * u, Qt::SolidLine, Qt::RoundCap,
                          Qt::RoundJoin));
            p.drawPath(polygon);
            p.setPen(QPen(kControlColour, 1.2 * u, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
            p.drawPath(polygon);
            const double r = kHandleRadius * u;
            // p, q, r, ... (after z: p again)
            const QChar letter(char16_t(u'a' + (15 + int(k)) % 26));
            for (int j = 0; j < n; ++j) {
                const int i = first + j;
                const bool hot = onScreen && (i == m_hoverControl
                                              || (m_drag.kind == DragKind::ControlPoint
                                                  && m_drag.index == i));
                p.setPen(QPen(kControlColour, 1.5 * u));
                p.setBrush(hot ? QColor(255, 200, 0) : QColor(Qt::white));
                p.drawEllipse(s[j], r, r);
                const QString text = QString(letter) + subscript(j);
                const QPointF at(s[j].x() + r + 2 * u, s[j].y() - r - 1 * u);
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
            first += n;
        }
    }
    p.restore();
}

void AttractorView::paintStatus(QPainter &p) const
{
    QStringList lines;
    // Why nothing is drawn (the item's own problem, e.g. a lifting that overflows): the view
    // says it where the picture would be.
    const QString problem = !m_ifs && m_error.isEmpty() ? m_problem : QString();
    if (!problem.isEmpty())
        lines << problem;
    if (!m_error.isEmpty())
        lines << m_error;
    else if (m_busy && m_busySince.isValid() && m_busySince.elapsed() > kQuietRenderMs)
        lines << tr("Rendering… %1 %").arg(int(std::round(100 * m_progress)));
    else if (m_cancelled)
        lines << tr("Rendering cancelled at %1 % — press F5 to render again")
                     .arg(int(std::round(100 * m_cancelledAt)));
    if (m_hutchTooMany && isLayerVisible(Layer::Hutchinson))
        lines << tr("F^%1(X₀) has too many images to draw as vectors").arg(m_hutchStep);
    if (lines.isEmpty())
        return;
    p.save();
    QFont f = font();
    p.setFont(f);
    const QFontMetrics fm(f);
    const int pad = 6;
    // Above the grid's x labels along the bottom edge.
    int y = height() - pad - (isLayerVisible(Layer::Grid) ? fm.height() + 2 : 0);
    for (auto it = lines.crbegin(); it != lines.crend(); ++it) {
        const QRect box = fm.boundingRect(QRect(0, 0, std::max(50, width() - 4 * pad), 1000),
                                          Qt::TextWordWrap, *it);
        const QRect r(pad, y - box.height() - pad, box.width() + 2 * pad, box.height() + pad);
        p.fillRect(r, QColor(255, 255, 255, 225));
        const bool bad = (!m_error.isEmpty() && *it == m_error) || (!problem.isEmpty() && *it == problem);
        p.setPen(bad ? QColor(190, 30, 30) : QColor(60, 60, 60));
        p.drawText(r.adjusted(pad, pad / 2, -pad, 0), Qt::TextWordWrap, *it);
        y = r.top() - 2;
    }
    p.restore();
}

} // namespace awb
