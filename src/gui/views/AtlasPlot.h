#pragma once
// The regularity atlas's chart (issue 48). One parameter: the certified bounds on the Hölder
// exponent r against the parameter (lower and upper curves), the line r = k, and the intervals
// of certified C^k shaded. Two parameters: the parameter plane, each row a rectangle of its
// grid cell (finer where the atlas refined) coloured by its certified class C^0, C^1, C^2, ...;
// rows whose bounds cannot tell C^k are outlined. A tooltip gives a row's certified bracket;
// a click asks for an item at that parameter (rowClicked). QCustomPlot stays out of this header.

#include "core/analysis/RegularityAtlas.h"

#include <QColor>
#include <QString>
#include <QWidget>

#include <optional>
#include <vector>

class QCustomPlot;
class QLabel;

namespace awb {

class AtlasCells;

class AtlasPlot : public QWidget {
    Q_OBJECT
public:
    explicit AtlasPlot(QWidget *parent = nullptr);
    ~AtlasPlot() override;

    // A new atlas: its axes and the class asked for; clears the rows.
    void start(const std::vector<AtlasAxis> &axes, int smoothness);
    // Rows as they arrive, each with the size of its cell (2D; empty in 1D).
    void addRows(const std::vector<AtlasRow> &rows, const std::vector<std::vector<double>> &cells);
    // The final rows (replacing those added) and, in 1D, the runs of certified C^k.
    void finish(const std::vector<AtlasRow> &rows, const std::vector<std::vector<double>> &cells,
                const std::vector<AtlasRun> &runs);

    const std::vector<AtlasRow> &rows() const { return m_rows; }
    const std::vector<AtlasAxis> &axes() const { return m_axes; }
    // The row under a point of the plot widget (its cell in 2D, the nearest in 1D).
    std::optional<size_t> rowAt(const QPointF &plotPos) const;
    // Where a row is drawn, in the plot widget's coordinates (tests click there).
    QPointF rowPosition(size_t index) const;
    QString rowText(const AtlasRow &row) const;
    QCustomPlot *plot() const { return m_plot; }
    // The colour of a certified class (-1: not even C^0) in the 2D map.
    static QColor classColour(int smoothness);

signals:
    void rowClicked(int index, const QPoint &globalPos);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void redraw();

    QCustomPlot *m_plot = nullptr;
    QLabel *m_legend = nullptr;
    AtlasCells *m_cells = nullptr;
    std::vector<AtlasAxis> m_axes;
    int m_smoothness = 1;
    std::vector<AtlasRow> m_rows;
    std::vector<std::vector<double>> m_cellSizes;
    std::vector<AtlasRun> m_runs;
    bool m_redrawPending = false;
};

} // namespace awb
