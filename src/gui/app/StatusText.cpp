#include "gui/app/StatusText.h"

#include <QEvent>
#include <QFontMetrics>
#include <QPainter>

namespace awb {

StatusText::StatusText(const QString &sample, QWidget *parent)
    : QWidget(parent), m_sample(sample)
{
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Preferred);
}

void StatusText::setText(const QString &text)
{
    if (text == m_text)
        return;
    m_text = text;
    setToolTip(text);
    update();
}

QSize StatusText::sizeHint() const
{
    const QFontMetrics fm(font());
    return {fm.horizontalAdvance(m_sample) + 8, fm.height() + 4};
}

void StatusText::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setPen(palette().color(QPalette::WindowText));
    const QRect r = rect().adjusted(4, 0, -4, 0);
    p.drawText(r, Qt::AlignLeft | Qt::AlignVCenter,
               fontMetrics().elidedText(m_text, Qt::ElideRight, r.width()));
}

void StatusText::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange)
        updateGeometry();
}

} // namespace awb
