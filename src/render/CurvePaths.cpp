#include "render/CurvePaths.h"

#include <QPaintEngine>
#include <QPainter>

#include <cmath>

namespace awb {

namespace {

double distance(QPointF a, QPointF b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

} // namespace

CurvePathSink::CurvePathSink(std::vector<Projection> views, QTransform toLogical,
                             double devicePixelsPerLogical, ColourFn colour,
                             std::size_t maxVertices, double tolerance)
    : m_views(std::move(views)), m_toLogical(toLogical), m_colour(std::move(colour)),
      m_maxVertices(maxVertices), m_tracks(m_views.size())
{
    const double k = devicePixelsPerLogical > 0 ? devicePixelsPerLogical : 1.0;
    m_tolerance = tolerance / k;
    // Images closer than about a device pixel are one stroke on paper: join them.
    m_join = std::max(2 * tolerance, 0.75) / k;
}

void CurvePathSink::setOverflow()
{
    m_overflow = true;
    if (m_overflowFlag)
        m_overflowFlag->store(true);
}

void CurvePathSink::flush(Track &t)
{
    if (t.open && t.hasPending) {
        m_paths[size_t(t.path)].path.lineTo(t.pending);
        ++m_paths[size_t(t.path)].vertices;
        ++m_kept;
        t.last = t.pending;
        t.hasPending = false;
    }
}

void CurvePathSink::lineTo(Track &t, QPointF q)
{
    if (distance(q, t.last) < m_tolerance) {
        t.pending = q;
        t.hasPending = true;
        return;
    }
    m_paths[size_t(t.path)].path.lineTo(q);
    ++m_paths[size_t(t.path)].vertices;
    ++m_kept;
    t.last = q;
    t.hasPending = false;
}

void CurvePathSink::consume(const Mat &v, StartSet::Kind kind, const std::uint8_t *address,
                            int length)
{
    if (m_overflow)
        return;
    if (kind != StartSet::Kind::Polyline || v.rows() < 2) {
        setOverflow();
        return;
    }
    const QColor colour = m_colour ? m_colour(address, length) : QColor(Qt::black);
    for (size_t k = 0; k < m_views.size(); ++k) {
        const Projection &view = m_views[k];
        Track &t = m_tracks[k];
        if (view.V.cols() < 2 || view.V.rows() != v.cols()) {
            setOverflow();
            return;
        }
        for (Eigen::Index r = 0; r < v.rows(); ++r) {
            double x = view.c.size() > 0 ? view.c(0) : 0.0;
            double y = view.c.size() > 1 ? view.c(1) : 0.0;
            for (Eigen::Index j = 0; j < v.cols(); ++j) {
                x += v(r, j) * view.V(j, 0);
                y += v(r, j) * view.V(j, 1);
            }
            const QPointF q = m_toLogical.map(QPointF(x, y));
            if (!std::isfinite(q.x()) || !std::isfinite(q.y())) {
                setOverflow();
                return;
            }
            if (r > 0) {
                lineTo(t, q);
                continue;
            }
            // The first vertex of an image: continue the open subpath when the image starts
            // where the last one ended and has its colour; otherwise begin a new one.
            const QPointF tail = t.hasPending ? t.pending : t.last;
            const bool touches = t.open && distance(q, tail) <= m_join;
            const bool sameColour = t.open && m_paths[size_t(t.path)].colour == colour;
            if (touches && sameColour) {
                lineTo(t, q);
                continue;
            }
            flush(t);
            auto add = [&](bool move, QPointF at) {
                Path &path = m_paths[size_t(t.path)];
                if (move)
                    path.path.moveTo(at);
                else
                    path.path.lineTo(at);
                ++path.vertices;
                ++m_kept;
            };
            if (!sameColour) {
                // A colour run ends: the new run starts at the old tail when they touch, so
                // the stroke has no gap where the colour changes.
                m_paths.push_back({colour, QPainterPath(), 0});
                t.path = int(m_paths.size()) - 1;
                if (touches)
                    add(true, t.last);
            }
            add(!(touches && !sameColour), q);
            t.last = q;
            t.hasPending = false;
            t.open = true;
        }
    }
    if (m_kept > m_maxVertices)
        setOverflow();
}

std::vector<CurvePathSink::Path> CurvePathSink::finish()
{
    for (Track &t : m_tracks) {
        flush(t);
        t.open = false;
    }
    std::vector<Path> out;
    out.swap(m_paths);
    return out;
}

void drawCurvePaths(QPainter &p, const std::vector<CurvePathSink::Path> &paths, double width)
{
    p.save();
    p.setBrush(Qt::NoBrush);
    for (const CurvePathSink::Path &path : paths) {
        p.setPen(QPen(path.colour, width, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPath(path.path);
    }
    p.restore();
}

double devicePixelsPerLogical(const QPainter &p)
{
    const QTransform t = p.deviceTransform();
    const double k = std::sqrt(std::abs(t.determinant()));
    return k > 0 && std::isfinite(k) ? k : 1.0;
}

bool isVectorDevice(const QPainter &p)
{
    const QPaintEngine *engine = p.paintEngine();
    if (!engine)
        return false;
    const auto type = engine->type();
    return type == QPaintEngine::SVG || type == QPaintEngine::Pdf
           || type == QPaintEngine::Picture;
}

} // namespace awb
