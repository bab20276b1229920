#pragma once
// AutomatonGraph: the graph of a controlled IFS (layer 3, views) -- its states as discs on a
// circle, each with its name and dimension, its arcs as arrows (self-loops outside the circle,
// parallel arcs fanned out), with their names. The drawn states are filled; a click selects a
// state or an arc. It shows what it is given and owns no document: the Automaton panel
// (gui/app/AutomatonPanel.h) feeds it from the item and turns its clicks into edits.

#include <QWidget>

#include <vector>

namespace awb {

class AutomatonGraph : public QWidget {
    Q_OBJECT
public:
    struct State {
        QString name;
        int dimension = 0;
        bool drawn = false;
    };
    struct Arc {
        QString name;
        int from = 0, to = 0;
    };

    explicit AutomatonGraph(QWidget *parent = nullptr);

    void setAutomaton(std::vector<State> states, std::vector<Arc> arcs);
    // -1: none. Selecting one clears the other.
    void selectState(int state);
    void selectArc(int arc);
    int selectedState() const { return m_state; }
    int selectedArc() const { return m_arc; }

    // Where state `s`'s disc is, and the arc a point lies on (-1: none): for the tests and the
    // clicks.
    QPointF stateCentre(int s) const;
    int stateAt(const QPointF &p) const;
    int arcAt(const QPointF &p) const;

    QSize sizeHint() const override { return {320, 240}; }
    QSize minimumSizeHint() const override { return {160, 120}; }

signals:
    void stateClicked(int state);
    void arcClicked(int arc);

protected:
    void paintEvent(QPaintEvent *) override;
    void mousePressEvent(QMouseEvent *event) override;
    bool event(QEvent *event) override;

private:
    double radius() const;
    // The arc's curve: from its start to its end through `control` (a quadratic Bézier), and
    // where its label goes.
    struct Curve {
        QPointF start, control, end, label;
        bool loop = false;
    };
    Curve curve(int arc) const;

    std::vector<State> m_states;
    std::vector<Arc> m_arcs;
    int m_state = -1, m_arc = -1;
};

} // namespace awb
