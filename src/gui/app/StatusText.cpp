#include "gui/app/StatusText.h"

#include <QEvent>
#include <QFontMetrics>
#include <QPainter>

#include <algorithm>

namespace awb {

QString elidedAtWord(const QFontMetrics &fm, const QString &text, int width)
{
    if (fm.horizontalAdvance(text) <= width)
        return text;
    const QString ellipsis = QStringLiteral(" …");
    const QString cut = fm.elidedText(text, Qt::ElideRight, width);
    // What elidedText kept, less its "…", back to the last space; one long word is cut.
    QString kept = cut.left(std::max<qsizetype>(0, cut.size() - 1));
    const qsizetype space = kept.lastIndexOf(QLatin1Char(' '));
    if (space > 0 && space < text.size() && text.at(kept.size()) != QLatin1Char(' '))
        kept = kept.left(space);
    while (!kept.isEmpty()
           && (kept.back().isSpace() || kept.back() == QLatin1Char(',')
               || kept.back() == QLatin1Char(';') || kept.back() == QLatin1Char(':')))
        kept.chop(1);
    while (!kept.isEmpty() && fm.horizontalAdvance(kept + ellipsis) > width) {
        const qsizetype s = kept.lastIndexOf(QLatin1Char(' '));
        kept = s > 0 ? kept.left(s) : QString();
    }
    return kept.isEmpty() ? cut : kept + ellipsis;
}

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
