#include "gui/views/MatrixHeatMap.h"

#include "model/NumberFormat.h"

#include <QHelpEvent>
#include <QPainter>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

constexpr int cell = 11;     // pixels per entry at the preferred size
constexpr int margin = 22;   // room for the row and column numbers

} // namespace

MatrixHeatMap::MatrixHeatMap(QWidget *parent) : QWidget(parent)
{
    setMouseTracking(true);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
}

void MatrixHeatMap::setMatrix(const QString &name, const Mat &values)
{
    m_name = name;
    m_values = values;
    m_max = values.size() ? std::max(values.cwiseAbs().maxCoeff(), 1e-300) : 1.0;
    updateGeometry();
    update();
}

QSize MatrixHeatMap::sizeHint() const
{
    return {margin + cell * int(m_values.cols()) + 4, margin + cell * int(m_values.rows()) + 4};
}

QRectF MatrixHeatMap::grid() const
{
    // Square cells as large as the widget allows, at least 3 pixels.
    const double k = std::max(3.0, std::min((width() - margin - 4.0) / std::max<Eigen::Index>(
                                                 1, m_values.cols()),
                                            (height() - margin - 4.0) / std::max<Eigen::Index>(
                                                 1, m_values.rows())));
    return {double(margin), double(margin), k * m_values.cols(), k * m_values.rows()};
}

QColor MatrixHeatMap::cellColour(double v) const { return colour(v, m_max); }

QColor MatrixHeatMap::colour(double v, double largest)
{
    // Diverging scale through white: zero entries vanish, so the sparsity pattern shows; the
    // square root lifts small weights (1/64 next to 3/4) into view.
    if (v == 0.0 || !(largest > 0))
        return Qt::white;
    const double t = std::sqrt(std::min(1.0, std::abs(v) / largest));
    const QColor end = v > 0 ? QColor(178, 24, 43) : QColor(33, 102, 172);
    const auto mix = [t](int a, int b) { return int(std::lround(a + (b - a) * t)); };
    return QColor(mix(255, end.red()), mix(255, end.green()), mix(255, end.blue()));
}

QPoint MatrixHeatMap::cellAt(const QPointF &pos) const
{
    const QRectF g = grid();
    if (!g.contains(pos) || m_values.size() == 0)
        return {-1, -1};
    const double k = g.width() / m_values.cols();
    return {int((pos.y() - g.top()) / k), int((pos.x() - g.left()) / k)};
}

QString MatrixHeatMap::cellText(int row, int column) const
{
    if (row < 0 || column < 0 || row >= m_values.rows() || column >= m_values.cols())
        return {};
    return tr("%1 (%2, %3) = %4")
        .arg(subscriptName(m_name))
        .arg(row + 1)
        .arg(column + 1)
        .arg(formatNumber(m_values(row, column), 10));
}

void MatrixHeatMap::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    const QRectF g = grid();
    if (m_values.size() == 0)
        return;
    const double k = g.width() / m_values.cols();
    for (Eigen::Index r = 0; r < m_values.rows(); ++r)
        for (Eigen::Index c = 0; c < m_values.cols(); ++c)
            p.fillRect(QRectF(g.left() + c * k, g.top() + r * k, k, k),
                       cellColour(m_values(r, c)));
    p.setPen(QColor(200, 200, 200));
    p.drawRect(g);
    // Every fifth index: enough to find a row without crowding.
    QFont f = font();
    f.setPixelSize(9);
    p.setFont(f);
    p.setPen(QColor(90, 90, 90));
    for (Eigen::Index i = 0; i < std::max(m_values.rows(), m_values.cols()); i += 5) {
        if (i < m_values.cols())
            p.drawText(QRectF(g.left() + i * k - 10, 0, k + 20, margin - 2),
                       Qt::AlignHCenter | Qt::AlignBottom, QString::number(i + 1));
        if (i < m_values.rows())
            p.drawText(QRectF(0, g.top() + i * k - 5, margin - 3, k + 10),
                       Qt::AlignRight | Qt::AlignVCenter, QString::number(i + 1));
    }
}

bool MatrixHeatMap::event(QEvent *event)
{
    if (event->type() == QEvent::ToolTip) {
        auto *help = static_cast<QHelpEvent *>(event);
        const QPoint c = cellAt(help->pos());
        if (c.x() >= 0)
            QToolTip::showText(help->globalPos(), cellText(c.x(), c.y()), this);
        else
            QToolTip::hideText();
        return true;
    }
    return QWidget::event(event);
}

} // namespace awb
