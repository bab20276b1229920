#include "gui/views/AutomatonGraph.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace awb {

namespace {

constexpr double kStateRadius = 24.0;  // a state's disc radius, pixels

QPointF unitVector(const QPointF &v)
{
    const double n = std::hypot(v.x(), v.y());
    return n > 0 ? v / n : QPointF(0, -1);
}

QPointF rotated(const QPointF &v, double degrees)
{
    const double a = degrees * std::numbers::pi / 180.0;
    return {v.x() * std::cos(a) - v.y() * std::sin(a), v.x() * std::sin(a) + v.y() * std::cos(a)};
}

QPointF bezier(const QPointF &a, const QPointF &c, const QPointF &b, double t)
{
    return (1 - t) * (1 - t) * a + 2 * (1 - t) * t * c + t * t * b;
}

} // namespace

AutomatonGraph::AutomatonGraph(QWidget *parent) : QWidget(parent)
{
    setMouseTracking(false);
    setBackgroundRole(QPalette::Base);
    setAutoFillBackground(true);
    setFocusPolicy(Qt::ClickFocus);
    setAccessibleName(tr("Automaton graph"));
}

void AutomatonGraph::setAutomaton(std::vector<State> states, std::vector<Arc> arcs)
{
    m_states = std::move(states);
    m_arcs = std::move(arcs);
    if (m_state >= int(m_states.size()))
        m_state = -1;
    if (m_arc >= int(m_arcs.size()))
        m_arc = -1;
    update();
}

void AutomatonGraph::selectState(int state)
{
    m_state = state >= 0 && state < int(m_states.size()) ? state : -1;
    if (m_state >= 0)
        m_arc = -1;
    update();
}

void AutomatonGraph::selectArc(int arc)
{
    m_arc = arc >= 0 && arc < int(m_arcs.size()) ? arc : -1;
    if (m_arc >= 0)
        m_state = -1;
    update();
}

double AutomatonGraph::radius() const
{
    // Room for the loops outside the states' ellipse.
    return kStateRadius + 56.0;
}

QPointF AutomatonGraph::stateCentre(int s) const
{
    const QPointF centre(width() / 2.0, height() / 2.0);
    const int n = int(m_states.size());
    if (n <= 1)
        return centre;
    // On an ellipse filling the widget, the first state at the top, the others clockwise; two
    // states side by side.
    // At least two discs apart vertically, so that the top and bottom states never touch.
    const double rx = std::max(2.0 * kStateRadius, width() / 2.0 - radius());
    const double ry = std::max(2.0 * kStateRadius, height() / 2.0 - radius());
    if (n == 2)
        return centre + QPointF((s == 0 ? -1 : 1) * rx, 0);
    const double a = -std::numbers::pi / 2 + 2 * std::numbers::pi * s / n;
    return centre + QPointF(rx * std::cos(a), ry * std::sin(a));
}

AutomatonGraph::Curve AutomatonGraph::curve(int arc) const
{
    const Arc &t = m_arcs[size_t(arc)];
    // Its rank among the arcs joining the same two states (either way), to fan them out.
    int rank = 0;
    for (int k = 0; k < arc; ++k) {
        const Arc &o = m_arcs[size_t(k)];
        if ((o.from == t.from && o.to == t.to) || (o.from == t.to && o.to == t.from))
            ++rank;
    }
    const QPointF a = stateCentre(t.from), b = stateCentre(t.to);
    Curve c;
    if (t.from == t.to) {
        c.loop = true;
        const QPointF centre(width() / 2.0, height() / 2.0);
        const QPointF out = rotated(m_states.size() <= 1 ? QPointF(0, -1) : unitVector(a - centre),
                                    (rank % 2 ? 1 : -1) * 38.0 * ((rank + 1) / 2));
        c.start = a + kStateRadius * rotated(out, -28);
        c.end = a + kStateRadius * rotated(out, 28);
        c.control = a + (kStateRadius + 62.0) * out;
        c.label = a + (kStateRadius + 40.0) * out;
        return c;
    }
    const QPointF d = unitVector(b - a);
    const QPointF normal(-d.y(), d.x());
    const double bend = 14.0 + 22.0 * rank;
    const QPointF mid = (a + b) / 2.0 + bend * normal;
    c.control = (a + b) / 2.0 + 2 * bend * normal;
    c.start = a + kStateRadius * unitVector(c.control - a);
    c.end = b + kStateRadius * unitVector(c.control - b);
    c.label = mid + 9.0 * normal;
    return c;
}

int AutomatonGraph::stateAt(const QPointF &p) const
{
    for (int s = 0; s < int(m_states.size()); ++s) {
        const QPointF d = p - stateCentre(s);
        if (std::hypot(d.x(), d.y()) <= kStateRadius)
            return s;
    }
    return -1;
}

int AutomatonGraph::arcAt(const QPointF &p) const
{
    int best = -1;
    double bestDistance = 7.0;
    for (int t = 0; t < int(m_arcs.size()); ++t) {
        const Curve c = curve(t);
        for (int k = 0; k <= 32; ++k) {
            const QPointF d = bezier(c.start, c.control, c.end, k / 32.0) - p;
            const double dist = std::hypot(d.x(), d.y());
            if (dist < bestDistance) {
                bestDistance = dist;
                best = t;
            }
        }
        const QPointF l = c.label - p;
        if (std::hypot(l.x(), l.y()) < bestDistance) {
            bestDistance = std::hypot(l.x(), l.y());
            best = t;
        }
    }
    return best;
}

void AutomatonGraph::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette &pal = palette();
    if (m_states.empty()) {
        p.setPen(pal.color(QPalette::PlaceholderText));
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, tr("No states"));
        return;
    }
    const QColor ink = pal.color(QPalette::Text);
    const QColor accent = pal.color(QPalette::Highlight);
    QFont small = font();
    small.setPointSizeF(std::max(7.0, font().pointSizeF() * 0.9));
    for (int t = 0; t < int(m_arcs.size()); ++t) {
        const Curve c = curve(t);
        const bool selected = t == m_arc;
        QPen pen(selected ? accent : ink, selected ? 2.4 : 1.3);
        p.setPen(pen);
        p.setBrush(Qt::NoBrush);
        QPainterPath path(c.start);
        path.quadTo(c.control, c.end);
        p.drawPath(path);
        // The arrowhead along the curve's end tangent.
        const QPointF dir = unitVector(c.end - c.control);
        const QPointF n(-dir.y(), dir.x());
        const QPolygonF head{c.end, c.end - 9 * dir + 4.5 * n, c.end - 9 * dir - 4.5 * n};
        p.setBrush(pen.color());
        p.drawPolygon(head);
        p.setFont(small);
        const QString label = m_arcs[size_t(t)].name;
        const QFontMetricsF fm(small);
        const double w = fm.horizontalAdvance(label) + 4, h = fm.height();
        QRectF at(c.label.x() - w / 2, c.label.y() - h / 2, w, h);
        // Kept inside the widget: a side state's loop label would be cut at the edge.
        at.moveLeft(std::clamp(at.left(), 0.0, std::max(0.0, width() - at.width())));
        at.moveTop(std::clamp(at.top(), 0.0, std::max(0.0, height() - at.height())));
        p.setPen(Qt::NoPen);
        p.setBrush(pal.color(QPalette::Base));
        p.drawRect(at);
        p.setPen(selected ? accent : ink);
        p.drawText(at, Qt::AlignCenter, label);
    }
    p.setFont(font());
    for (int s = 0; s < int(m_states.size()); ++s) {
        const State &q = m_states[size_t(s)];
        const QPointF c = stateCentre(s);
        const bool selected = s == m_state;
        QColor fill = q.drawn ? accent.lighter(170) : pal.color(QPalette::Base);
        p.setBrush(fill);
        p.setPen(QPen(selected ? accent : ink, selected ? 3.0 : 1.5));
        p.drawEllipse(c, kStateRadius, kStateRadius);
        p.setPen(ink);
        const QRectF box(c.x() - kStateRadius, c.y() - kStateRadius, 2 * kStateRadius,
                         2 * kStateRadius);
        // The name inside when it fits, else under the disc.
        const QFontMetricsF fm(font());
        if (fm.horizontalAdvance(q.name) <= 2 * kStateRadius - 6) {
            p.drawText(box.adjusted(0, 0, 0, -10), Qt::AlignCenter, q.name);
        } else {
            const QString name = fm.elidedText(q.name, Qt::ElideRight, 160);
            const double w = fm.horizontalAdvance(name) + 6;
            const QRectF under(c.x() - w / 2, c.y() + kStateRadius + 2, w, fm.height());
            p.setPen(Qt::NoPen);
            p.setBrush(pal.color(QPalette::Base));
            p.drawRect(under);
            p.setPen(selected ? accent : ink);
            p.drawText(under, Qt::AlignCenter, name);
            p.setPen(ink);
        }
        p.setFont(small);
        p.drawText(box.adjusted(0, fm.horizontalAdvance(q.name) <= 2 * kStateRadius - 6 ? 16 : 0,
                                0, 0),
                   Qt::AlignCenter, tr("%1 pts").arg(q.dimension));
        p.setFont(font());
    }
}

void AutomatonGraph::mousePressEvent(QMouseEvent *event)
{
    const QPointF at = event->position();
    if (const int s = stateAt(at); s >= 0) {
        selectState(s);
        emit stateClicked(s);
    } else if (const int t = arcAt(at); t >= 0) {
        selectArc(t);
        emit arcClicked(t);
    }
}

bool AutomatonGraph::event(QEvent *e)
{
    if (e->type() == QEvent::ToolTip) {
        const auto *h = static_cast<QHelpEvent *>(e);
        if (const int s = stateAt(h->pos()); s >= 0) {
            const State &q = m_states[size_t(s)];
            QToolTip::showText(h->globalPos(),
                               tr("State %1: %2 control points%3")
                                   .arg(q.name)
                                   .arg(q.dimension)
                                   .arg(q.drawn ? tr(", drawn") : QString()),
                               this);
        } else if (const int t = arcAt(h->pos()); t >= 0) {
            const Arc &a = m_arcs[size_t(t)];
            QToolTip::showText(h->globalPos(),
                               tr("Arc %1: %2 → %3 (maps the space of %3 into %2)")
                                   .arg(a.name, m_states[size_t(a.from)].name,
                                        m_states[size_t(a.to)].name),
                               this);
        } else {
            QToolTip::hideText();
        }
        return true;
    }
    return QWidget::event(e);
}

} // namespace awb
