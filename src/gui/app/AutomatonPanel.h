#pragma once
// AutomatonPanel: the content of the Automaton dock (layer 3, GUI; issue 46). For a controlled
// IFS item (model/CifsItem.h) it shows the automaton's graph (gui/views/AutomatonGraph.h) and
// edits it: add or remove a state or an arc, rename them, pick an arc's states, weight and map
// -- as a matrix, as a plane affine map between the states' frame triangles, or as a piece of
// a curve scheme -- and choose the drawn state. Every edit is one undo step through
// CifsItem::setSpec; a refused edit says why. A state's control points are dragged in the
// attractor view like any point set. Below the editor: what the automaton contracts by (its
// constrained joint spectral radius and Lyapunov exponent, model/AutomatonAnalysisJson.h).

#include "model/CifsItem.h"

#include <QPointer>
#include <QWidget>

#include <memory>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QScrollArea;
class QSpinBox;
class QStackedWidget;
class QTableWidget;
class QTextBrowser;

namespace awb {

class AutomatonGraph;
class LatestJobWorker;
class Item;

class AutomatonPanel : public QWidget {
    Q_OBJECT
public:
    explicit AutomatonPanel(QWidget *parent = nullptr);
    ~AutomatonPanel() override;

    // The item edited: a CifsItem, or anything else (then the panel says what it is for).
    void setItem(Item *item);
    CifsItem *item() const { return m_item; }
    AutomatonGraph *graph() const { return m_graph; }
    // The automaton's whole analysis as text (for the Analysis dock's Automaton tab).
    QWidget *analysisView() const;

    // The edits, each one undo step; false with *error saying why (also emitted as problem).
    bool addState(int points, QString *error = nullptr);
    bool removeState(int state, QString *error = nullptr);
    bool renameState(int state, const QString &name, QString *error = nullptr);
    // A new arc from -> to with CifsSpec::defaultArcMatrix; it becomes the selection.
    bool addArc(int from, int to, QString *error = nullptr);
    bool removeArc(int arc, QString *error = nullptr);
    bool renameArc(int arc, const QString &name, QString *error = nullptr);
    // New states for an arc: its matrix is kept when it still fits, else the default one.
    bool setArcStates(int arc, int from, int to, QString *error = nullptr);
    bool setArcWeight(int arc, double weight, QString *error = nullptr);
    bool setArcMatrix(int arc, const Mat &S, QString *error = nullptr);
    // The arc's map in one of the file's forms ({"affine": ...}, {"scheme": ..., "piece"}).
    bool setArcMap(int arc, const QJsonObject &map, QString *error = nullptr);
    bool setDrawn(const QString &state, QString *error = nullptr);

    void selectState(int state);
    void selectArc(int arc);

signals:
    void problem(const QString &message);
    // The analysis of the automaton as it is now is shown (computed on a worker thread).
    void analysed();

private:
    void rebuild();
    void analyse();
    void showSelection();
    bool apply(const struct CifsSpec &spec, QString *error);
    void applyMatrixTable();
    void applyAffine();
    void applyScheme();

    QPointer<CifsItem> m_item;
    std::unique_ptr<LatestJobWorker> m_worker;
    int m_generation = 0;
    bool m_rebuilding = false;
    QLabel *m_intro = nullptr;
    QWidget *m_body = nullptr;
    QScrollArea *m_scroll = nullptr;
    QComboBox *m_drawn = nullptr;
    AutomatonGraph *m_graph = nullptr;
    QSpinBox *m_newPoints = nullptr;
    QPushButton *m_removeState = nullptr, *m_addArc = nullptr, *m_removeArc = nullptr;
    QStackedWidget *m_editor = nullptr;
    // The state page.
    QLineEdit *m_stateName = nullptr;
    QLabel *m_stateInfo = nullptr;
    // The arc page.
    QLineEdit *m_arcName = nullptr;
    QComboBox *m_from = nullptr, *m_to = nullptr;
    QDoubleSpinBox *m_weight = nullptr;
    QComboBox *m_mapForm = nullptr;
    QStackedWidget *m_mapPages = nullptr;
    QTableWidget *m_matrix = nullptr;
    QLineEdit *m_affine[6] = {};
    QComboBox *m_schemeKind = nullptr;
    QSpinBox *m_schemeDegree = nullptr, *m_schemePiece = nullptr;
    QLabel *m_mapNote = nullptr;
    QLabel *m_summary = nullptr;
    QPointer<QTextBrowser> m_analysis;  // shown in the Analysis dock, which may go first
};

} // namespace awb
