// AttractorView: the selected sub-copy f_w(A) (issue 16, addresses): its points drawn over the
// attractor in one strong colour, the control polygons S_w P of its pieces dashed with square
// markers, and a caption in the lower left corner. View state only; the owner (the address
// panel) computes what to show.

#include "gui/views/AttractorView.h"

#include "gui/views/AttractorViewDetail.h"

#include <QPainter>

namespace awb {

using namespace attractor_view;

namespace {

const QColor kHighlightColour(200, 0, 120);
const QColor kPolygonColour(90, 0, 70);

} // namespace

void AttractorView::setHighlight(const Highlight &highlight)
{
    m_highlight = highlight;
    update();
}

void AttractorView::paintHighlight(QPainter &p, const Mapping &m) const
{
    if (m_highlight.empty() && m_highlight.caption.isEmpty())
        return;
    const double u = m.unit;
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    if (m_highlight.points.rows() > 0 && m_highlight.points.cols() >= 2) {
        QPolygonF dots;
        dots.reserve(int(m_highlight.points.rows()));
        for (Eigen::Index i = 0; i < m_highlight.points.rows(); ++i)
            dots << m.map(QPointF(m_highlight.points(i, 0), m_highlight.points(i, 1)));
        // A white rim first: the sub-copy stays visible over an attractor of any colour.
        p.setPen(QPen(QColor(255, 255, 255, 220), 8.0 * u, Qt::SolidLine, Qt::RoundCap));
        p.drawPoints(dots);
        p.setPen(QPen(kHighlightColour, 5.0 * u, Qt::SolidLine, Qt::RoundCap));
        p.drawPoints(dots);
    }
    const double r = 3.5 * u;
    for (const Mat &polygon : m_highlight.controlPolygons) {
        if (polygon.cols() < 2 || polygon.rows() == 0)
            continue;
        QPolygonF s;
        for (Eigen::Index i = 0; i < polygon.rows(); ++i)
            s << m.map(QPointF(polygon(i, 0), polygon(i, 1)));
        // Darker and dashed: told apart from the sub-copy it lies close to.
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(kPolygonColour, 1.3 * u, Qt::DashLine));
        p.drawPath(polylinePath(s, false));
        p.setPen(QPen(kPolygonColour, 1.2 * u));
        p.setBrush(QColor(255, 255, 255));
        for (const QPointF &q : s)
            p.drawRect(QRectF(q.x() - r, q.y() - r, 2 * r, 2 * r));
    }
    if (!m_highlight.caption.isEmpty()) {
        const QFont f = sceneFont(0.95, u);
        p.setFont(f);
        const QFontMetricsF fm(f, p.device());
        const double pad = 5.0 * u;
        const QRectF text = fm.boundingRect(m_highlight.caption);
        const QSizeF size(text.width() + 3 * pad, text.height() + 2 * pad);
        // A bottom corner above the grid's axis labels (left first), or a top one: the one
        // that covers the fewest control points and points of the sub-copy.
        const double above = isLayerVisible(Layer::Grid) ? fm.height() + 2 * pad : pad;
        const double left = m.target.left() + 4 * pad;
        const double right = m.target.right() - 2 * pad - size.width();
        const double bottom = m.target.bottom() - above - size.height();
        const double top = m.target.top() + 6 * pad + fm.height();   // under a legend
        QRectF box;
        int fewest = -1;
        for (const QPointF corner : {QPointF(left, bottom), QPointF(right, bottom),
                                     QPointF(right, top), QPointF(left, top)}) {
            const QRectF candidate(corner, size);
            const QRectF grown = candidate.adjusted(-2 * r, -2 * r, 2 * r, 2 * r);
            int covered = 0;
            for (int i = 0; i < int(m_control.size()); ++i)
                covered += 100 * grown.contains(m.map(controlPointPosition(i)));
            for (Eigen::Index i = 0; i < m_highlight.points.rows(); i += 16)
                covered += grown.contains(
                    m.map(QPointF(m_highlight.points(i, 0), m_highlight.points(i, 1))));
            if (fewest < 0 || covered < fewest) {
                fewest = covered;
                box = candidate;
            }
        }
        p.setPen(QPen(kHighlightColour, 1.0 * u));
        p.setBrush(QColor(255, 255, 255, 230));
        p.drawRect(box);
        p.setPen(QColor(40, 40, 40));
        p.drawText(box.adjusted(pad, pad, -pad, -pad), Qt::AlignLeft | Qt::AlignVCenter,
                   m_highlight.caption);
    }
    p.restore();
}

} // namespace awb
