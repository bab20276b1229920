#pragma once
// A heat map of one real matrix for the Matrices dock: the S_i of a surface (16 x 16 up to
// 37 x 37) do not fit a table on screen, but their sparsity pattern and weights read at a
// glance as colour. Hovering a cell shows its exact value (a fraction where one is exact) in
// a tooltip. A view only: it never edits the matrix.

#include "core/Types.h"

#include <QString>
#include <QWidget>

namespace awb {

class MatrixHeatMap : public QWidget {
    Q_OBJECT
public:
    explicit MatrixHeatMap(QWidget *parent = nullptr);

    void setMatrix(const QString &name, const Mat &values);
    // The cell (row, column) under a widget point, or (-1, -1).
    QPoint cellAt(const QPointF &pos) const;
    // The tooltip text of a cell: "S₁ (r, c) = 3/8".
    QString cellText(int row, int column) const;
    QColor cellColour(double value) const;
    // The colour of an entry on the scale ending at |largest| (the figure sheet's too).
    static QColor colour(double value, double largest);

    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;
    bool event(QEvent *event) override;

private:
    QRectF grid() const;

    QString m_name;
    Mat m_values;
    double m_max = 1.0;  // largest |entry|: the colour scale's end
};

} // namespace awb
