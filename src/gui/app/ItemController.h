#pragma once
// ItemController: binds the current item of the project to the views (attractor, matrices,
// spectrum, analysis charts). It reads the item's derived data whenever the item changes and
// turns view gestures (control point drags, start vertex drags, matrix cell edits) into the
// item's undoable setters: a drag is one gesture and so one undo step. It owns no data: the
// item stays the single source of truth. Heavy analysis (distances, box counting) runs on a
// worker thread that a newer edit cancels.
#include "core/Types.h"
#include "model/Item.h"
#include "gui/views/ThreadInbox.h"
#include "model/NamedMatrix.h"
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QVector3D>
#include <atomic>
#include <functional>
#include <memory>
#include <thread>

class QMenu;

namespace awb {

class AnalysisCharts;
class AttractorItem;
class AttractorView;
class EigenvaluePlotItem;
class FrameBudget;
class Item;
class MatrixView;
class RegularityPanel;
class SubdivisionCurveItem;
class Messages;
class Project;
class SpectrumView;
class SubdivisionMeshItem;
class SurfaceView;
class ValenceChart;
class VertexPanel;
struct AnalysisResult;
class CurveScheme;
struct Contractivity;
struct ExtraordinaryVertex;
struct MapSpectrum;

struct DerivedIfs;


class ItemController : public QObject {
    Q_OBJECT
public:
    // `budget` coalesces the docks' updates during gestures (nullptr: the controller's own).
    ItemController(AttractorView *attractor, MatrixView *matrices, SpectrumView *spectrum,
                   AnalysisCharts *charts, FrameBudget *budget = nullptr,
                   QObject *parent = nullptr);
    ~ItemController() override;

    void setItem(Item *item);
    Item *item() const { return m_item; }
    // Shows `frame` -- a copy of the current item at a time of its animation, in no project
    // (AnimationPanel) -- in the views instead of the item, keeping the view's framing; the
    // views refuse edits meanwhile. nullptr returns to the item.
    void showFrame(std::shared_ptr<Item> frame);
    const Item *frame() const { return m_frame.get(); }
    // The 3D view that shows items with 3D points (surfaces) instead of the attractor view.
    void setSurfaceView(SurfaceView *view);
    SurfaceView *surfaceView() const { return m_surface; }
    // Whether the current item is shown by the surface view.
    bool showsSurface() const;
    // The item whose attractor the views draw: the current item, or for an eigenvalue plot
    // its source (nullptr when there is none).
    AttractorItem *drawnItem() const;
    // Default render depth when an item asks for more than the preferences allow (0: none).
    void setMaxDepth(int depth) { m_maxDepth = depth; refreshNow(); }
    void setPalette(const QList<QColor> &palette) { m_palette = palette; refreshNow(); }
    // Classic subdivision polygons beside the IFS: how many steps (0 hides them).
    void setSubdivisionSteps(int steps);
    // The central view of an eigenvalue plot item: its eigenvalues in the complex plane, large.
    void setPlotView(SpectrumView *view);
    // The panel that shows the current curve scheme's certified regularity (issue 16).
    void setRegularityPanel(RegularityPanel *panel);
    // The certificate of the current curve's exact Hölder exponent (the Analysis dock's Save
    // Certificate), as `attractor-cli analyse --certificate` writes it; false with the reason.
    bool saveCertificate(const QString &file, QString *error = nullptr);
    static QString regularityKey(const SubdivisionCurveItem &curve);
    int subdivisionSteps() const { return m_subdivisionSteps; }
    // Pushes the item's current data to every view and dock at once (normally deferred to the
    // event loop so that a burst of edits costs one update, and the docks to the FrameBudget).
    void refreshNow();
    FrameBudget *frameBudget() const { return m_budget; }
    // Whether the analysis worker is running.
    bool analysisRunning() const { return m_worker.joinable() && !m_workerDone; }
    void cancelAnalysis();

    // Asked when a matrix cell edit would break only its row's sum (the rows of a subdivision
    // matrix are affine combinations): whether to take the difference from the largest other
    // entry of the row. True applies the edit and the compensation as one undo step; without
    // an answerer (or on false) the edit is refused.
    void setRebalanceQuestion(std::function<bool(const QString &question)> ask)
    {
        m_askRebalance = std::move(ask);
    }

    // The attractor view's context menu for a right click at `screen` (widget pixels): insert
    // a point on the edge or before/after the handle there, delete that point, append one at
    // the cursor, fit the view. Every point edit is one undo step (ControlPointEdits).
    void fillContextMenu(QMenu *menu, const QPointF &screen);

    // Draws the points of map `map` (0-based) in their colour and the others in grey, to show
    // that map's part of the attractor (-1: all in their colours). Reset by a new item.
    void setHighlightedMap(int map);
    int highlightedMap() const { return m_highlightedMap; }

    // The text shown when the item cannot be drawn (empty when it can).
    QString problem() const { return m_problem; }
    // A mesh item's extraordinary vertices (issue 31): the Analysis dock's Vertex tab and the
    // valence chart, and the vertex whose local subdivision matrix the Matrices and Spectrum
    // docks show instead of the mesh's own -- an index into the item's extraordinary() list,
    // chosen by a click on its marker in the 3D view (-1: none; reset by a new item).
    void setVertexViews(VertexPanel *panel, ValenceChart *chart);
    void setFocusedVertex(int index);
    int focusedVertex() const { return m_focusedVertex; }
    // "vertex 3" or "the centre of face 2" for entry `index` of the drawn mesh's list ("" when
    // there is none).
    QString focusedVertexName() const;
    // Adds an eigenvalue plot item of the focused vertex under the mesh item (one undo step).
    Item *addVertexPlot();
    // The focused vertex's local subdivision matrix (empty when none is focused).
    QList<NamedMatrix> focusedMatrices() const;
    // The contraction of a row-stochastic S (an automaton's arc, a vertex's local subdivision
    // matrix) on the sum-preserving directions it acts in.
    static Contractivity stochasticContractivity(const Mat &S);
    // Points of the exact curve the analysis compares with (ItemControllerAnalysis.cpp).
    static constexpr int kExactSamples = 600;

signals:
    void problemChanged(const QString &problem);
    // An edit from a view was refused by the item (the message says why).
    void editRefused(const QString &message);
    // Something the user asked for was done (a file written): one line for the status bar.
    void notice(const QString &message);
    void analysisStarted();
    void analysisProgress(double fraction);
    void analysisFinished(bool cancelled);
    // The views got the drawn item's current data (after refreshNow()).
    void refreshed();
    void focusedVertexChanged(int index);

private:
    void scheduleRefresh();
    // The central view (attractor or 3D) now; the docks are marked for the FrameBudget.
    void refreshViews();
    void markPanelsDirty();
    // The docks, each brought up to date with the drawn item (FrameBudget panels).
    void showMatrices();
    void showSpectrum();
    void showCharts();
    void showVertex();
    // ItemControllerVertex.cpp: the focused vertex's S for the Spectrum and Matrices docks
    // (empty when none is focused), and the markers of a mesh item's extraordinary vertices.
    QList<MapSpectrum> focusedSpectra() const;
    void showMeshMarkers(const SubdivisionMeshItem *mesh);
    // The focused vertex of the drawn mesh (null: none), with the list that holds it.
    const ExtraordinaryVertex *focused(
        std::shared_ptr<const std::vector<ExtraordinaryVertex>> *list) const;
    std::shared_ptr<const DerivedIfs> drawnDerived() const;
    QList<MapSpectrum> currentSpectra() const;
    // A drag in a view: one gesture of the project (one undo step, FrameBudget's gesture).
    void beginGesture();
    void endGesture();
    void updateRegularity();
    void clearViews();
    void startAnalysis();
    void applyAnalysis(const std::shared_ptr<AnalysisResult> &result);
    // The real curve scheme of a subdivision-curve item (null for others and complex ones).
    static std::shared_ptr<const CurveScheme> realScheme(const Item *item);
    void onControlPressed(int index);
    void onControlDragged(int index, const QPointF &world);
    void onControlReleased(int index, const QPointF &start, const QPointF &end);
    void onStartPressed(int index);
    void onStartDragged(int index, const QPointF &world);
    void onStartReleased(int index, const QPointF &start, const QPointF &end);
    void onCellEdited(int matrix, int row, int column, double value);
    // Own matrices: -1 adds a copy of the last map, k removes map k (one undo step each).
    void onMapCountEdited(int removed);
    // Double click on an edge of the control polygon: a new point there (ItemControllerMenu).
    void onEdgeDoubleClicked(int flatIndex, const QPointF &world);
    // The surface view's part of refreshNow() (items with 3D points).
    void refreshSurface(AttractorItem *item, const DerivedIfs &d);
    // A start-set vertex dragged in either view (one undo step per drag, by gesture).
    void moveStartVertex(int index, const Point &to);
    void onSurfacePressed();
    void onControlDragged3D(int index, const QVector3D &world);
    void onStartDragged3D(int index, const QVector3D &world);

    AttractorView *m_attractor;
    MatrixView *m_matrices;
    SpectrumView *m_spectrum;
    AnalysisCharts *m_charts;
    QPointer<RegularityPanel> m_regularity;
    SurfaceView *m_surface = nullptr;
    QPointer<Item> m_item;
    std::shared_ptr<Item> m_frame;  // an animation frame shown instead of m_item
    QList<QMetaObject::Connection> m_connections;
    QTimer m_refreshTimer;
    QTimer m_analysisTimer;
    FrameBudget *m_budget;
    int m_matricesPanel = -1, m_spectrumPanel = -1, m_chartsPanel = -1, m_plotPanel = -1;
    int m_vertexPanel = -1;
    QPointer<VertexPanel> m_vertexView;
    QPointer<ValenceChart> m_valences;
    int m_focusedVertex = -1;
    SpectrumView *m_plotView = nullptr;
    QPointer<Project> m_gestureProject;
    int m_gesture = 0;
    int m_maxDepth = 0;
    int m_subdivisionSteps = 0;
    int m_highlightedMap = -1;
    QList<QColor> m_palette;
    QString m_problem;
    // Whether the drawn mesh is closed (its far-side markers hide), for the topology at key.
    const void *m_closedMeshKey = nullptr;
    bool m_closedMesh = false;
    ThreadInbox m_inbox{this}; // the analysis' results; declared before m_worker: outlives it
    std::thread m_worker;
    std::atomic<bool> m_cancel{false};
    std::atomic<bool> m_workerDone{true};
    quint64 m_analysisTicket = 0;
    std::function<bool(const QString &)> m_askRebalance;
};

} // namespace awb
