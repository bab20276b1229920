#pragma once
// ComplexPlanePicker: the plane of the de Casteljau split parameter t (004 §3.7, Fig. 3.3).
// It draws the discs |t| < 1 and |1 - t| < 1, whose intersection (the lens) is where both maps
// f_1(z) = t z and f_2(z) = (1 - t) z + t contract and the complex Bézier IFS has an
// attractor, and t as a handle the user drags. Like the other views it never changes the
// document: it reports press / move / release and shows what it is given.

#include <QPointF>
#include <QWidget>

namespace awb {

class ComplexPlanePicker : public QWidget {
    Q_OBJECT
public:
    explicit ComplexPlanePicker(QWidget *parent = nullptr);

    // t = value.x() + i value.y().
    void setValue(const QPointF &t);
    QPointF value() const { return m_value; }
    // Where t is drawn, in widget pixels, and the t under a widget point (equal axis scale).
    QPointF toScreen(const QPointF &t) const;
    QPointF toPlane(const QPointF &screen) const;
    // Inside both discs (|t| < 1 and |1 - t| < 1).
    static bool inLens(const QPointF &t);

    QSize sizeHint() const override { return {240, 150}; }
    QSize minimumSizeHint() const override { return {120, 80}; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int w) const override;

signals:
    // A drag: pressed once, moved for every step (the first at the press point), released once.
    void pressed();
    void moved(const QPointF &t);
    void released();

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;

private:
    double scale() const;
    QPointF origin() const;  // screen point of t = 0

    QPointF m_value{0.5, 0.0};
    bool m_dragging = false;
};

} // namespace awb
