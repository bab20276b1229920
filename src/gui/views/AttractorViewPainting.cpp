// AttractorView: painting of the scene (grid, subdivision polygons, exact curve, attractor
// raster or vector dots, Hutchinson images, handles, legend) on screen and into an export, and
// the status overlay (errors, render progress, a cancelled render).

#include "gui/views/AttractorView.h"

#include "gui/views/AttractorViewDetail.h"

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
}

void AttractorView::renderTo(QPainter *painter, const QRectF &target, Framing framing)
{
    m_exportCancelled = false;
    if (!painter || target.isEmpty())
        return;
    // The same world rectangle as on screen, fitted into the target with equal scale.
    const QRectF vis = visibleWorldRect();
    Mapping m{m_center, std::min(target.width() / vis.width(), target.height() / vis.height()),
              target};
    m.unit = std::min(target.width() / std::max(1, width()),
                      target.height() / std::max(1, height()));
    if (framing == Framing::FitContents) {
        if (const auto r = fittedWorld()) {
            // The view's fit margin, in the target's units.
            const double margin = kFitMargin * m.unit;
            const double w = std::max(1.0, target.width() - 2 * margin);
            const double h = std::max(1.0, target.height() - 2 * margin);
            m.center = r->center();
            m.scale = std::min(w / r->width(), h / r->height());
        }
    }
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
    const double u = m.unit;
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
        // An export renders its own raster when the view's does not cover its framing (a
        // figure fitted to the page, a target of another aspect ratio) or there is none yet.
        const QRectF needed = QRectF(m.unmap(m.target.bottomLeft()),
                                     m.unmap(m.target.topRight())).normalized();
        const double slack = 1e-6 * std::max(needed.width(), needed.height());
        const bool current = info.final && m_imageVersion == m_contentVersion;
        const bool covers = current && !image.isNull() && info.world.isValid()
                            && info.world.adjusted(-slack, -slack, slack, slack).contains(needed);
        if (forExport && !vector && !covers && m_ifs && m_error.isEmpty())
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

    paintHighlight(p, m);
    paintHandles(p, m);
    paintLegend(p, m);
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

QImage AttractorView::exportRaster(const Mapping &m, RenderInfo *info) const
{
    // Only for a view that never rendered on screen (hidden, or exported right after the
    // data arrived): the export must not silently lack the attractor.
    const double k = std::min(1.0, kMaxExportRaster / std::max(m.target.width(),
                                                               m.target.height()));
    const RenderRequest r = renderRequest(
        QRectF(m.unmap(m.target.bottomLeft()), m.unmap(m.target.topRight())).normalized(),
        QSize(std::max(1, int(m.target.width() * k)), std::max(1, int(m.target.height() * k))),
        1.0);
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
    QFont f = font();
    f.setPixelSize(std::max(1, int(std::lround(QFontInfo(font()).pixelSize() * factor * u))));
    return f;
}

void AttractorView::paintGrid(QPainter &p, const Mapping &m) const
{
    const QRectF w = QRectF(m.unmap(m.target.bottomLeft()), m.unmap(m.target.topRight()))
                         .normalized();
    const double step = niceStep(90.0 * m.unit / m.scale); // ~90 screen px
    if (!(step > 0) || !std::isfinite(step) || w.width() / step > 400)
        return;
    const double u = m.unit;
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

} // namespace awb
