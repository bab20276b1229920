#include "gui/views/ComplexPlanePicker.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

// The shown part of the plane: Re t in [-0.6, 1.6], Im t in [-1.1, 1.1] (both discs).
constexpr double kReMin = -0.6, kReMax = 1.6, kImMax = 1.1;
const QColor kLens(120, 190, 120, 90);
const QColor kDisc(110, 110, 110);
const QColor kInside(20, 120, 40);
const QColor kOutside(200, 40, 40);

} // namespace

ComplexPlanePicker::ComplexPlanePicker(QWidget *parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    setCursor(Qt::CrossCursor);
    setToolTip(tr("Drag t in the complex plane. The attractor exists inside the lens where "
                  "|t| < 1 and |1 − t| < 1 (both maps contract, 004 Fig. 3.3)."));
}

int ComplexPlanePicker::heightForWidth(int w) const
{
    return std::clamp(int(w * 2 * kImMax / (kReMax - kReMin)), 80, 260);
}

void ComplexPlanePicker::setValue(const QPointF &t)
{
    if (t == m_value)
        return;
    m_value = t;
    update();
}

double ComplexPlanePicker::scale() const
{
    return std::max(1.0, std::min((width() - 8) / (kReMax - kReMin), (height() - 8) / (2 * kImMax)));
}

QPointF ComplexPlanePicker::origin() const
{
    // The middle of the shown range at the widget's centre.
    const double s = scale();
    return {width() / 2.0 - s * (kReMin + kReMax) / 2.0, height() / 2.0};
}

QPointF ComplexPlanePicker::toScreen(const QPointF &t) const
{
    const QPointF o = origin();
    return {o.x() + scale() * t.x(), o.y() - scale() * t.y()};
}

QPointF ComplexPlanePicker::toPlane(const QPointF &screen) const
{
    const QPointF o = origin();
    return {(screen.x() - o.x()) / scale(), (o.y() - screen.y()) / scale()};
}

bool ComplexPlanePicker::inLens(const QPointF &t)
{
    return std::hypot(t.x(), t.y()) < 1.0 && std::hypot(1.0 - t.x(), t.y()) < 1.0;
}

void ComplexPlanePicker::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().base());
    const double s = scale();
    const QPointF o = toScreen({0, 0}), one = toScreen({1, 0});
    // Axes.
    p.setPen(QPen(palette().mid().color(), 1));
    p.drawLine(QPointF(0, o.y()), QPointF(width(), o.y()));
    p.drawLine(QPointF(o.x(), 0), QPointF(o.x(), height()));
    // The lens |t| < 1 and |1 - t| < 1, then the two circles.
    QPainterPath a, b;
    a.addEllipse(o, s, s);
    b.addEllipse(one, s, s);
    p.fillPath(a.intersected(b), kLens);
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(kDisc, 1, Qt::DashLine));
    p.drawEllipse(o, s, s);
    p.drawEllipse(one, s, s);
    p.setPen(palette().text().color());
    p.drawText(o + QPointF(3, -3), QStringLiteral("0"));
    p.drawText(one + QPointF(3, -3), QStringLiteral("1"));
    // t.
    const bool inside = inLens(m_value);
    const QPointF at = toScreen(m_value);
    p.setPen(QPen(inside ? kInside : kOutside, 2));
    p.setBrush(m_dragging ? QColor(255, 200, 0) : QColor(Qt::white));
    p.drawEllipse(at, 5, 5);
    p.setPen(palette().text().color());
    const QString label = QStringLiteral("t");
    const double x = std::min(at.x() + 8, width() - 12.0);
    p.drawText(QPointF(x, std::clamp(at.y() - 6, 12.0, height() - 4.0)), label);
}

void ComplexPlanePicker::mousePressEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton)
        return QWidget::mousePressEvent(event);
    m_dragging = true;
    emit pressed();
    emit moved(toPlane(event->position()));
    update();
}

void ComplexPlanePicker::mouseMoveEvent(QMouseEvent *event)
{
    if (!m_dragging)
        return QWidget::mouseMoveEvent(event);
    emit moved(toPlane(event->position()));
}

void ComplexPlanePicker::mouseReleaseEvent(QMouseEvent *event)
{
    if (!m_dragging || event->button() != Qt::LeftButton)
        return QWidget::mouseReleaseEvent(event);
    m_dragging = false;
    emit released();
    update();
}

} // namespace awb
