#pragma once
// The attractor view: the current item's attractor (rendered off the GUI thread by an
// AttractorRenderer) with the control polygon, start set, exact curve, classic subdivision
// polygons and Hutchinson iterates painted on top as vector overlays. It takes plain core data
// through setters and reports edits as press/drag/release signals (one undo step per drag is
// the owner's job); it never changes the data itself. The plane is shown with equal axis scale.
// A running render can be cancelled (Esc, cancelRender()) and started again (F5, renderAgain()).
// The class is defined across AttractorView.cpp, AttractorViewPainting.cpp,
// AttractorViewEvents.cpp, AttractorViewImages.cpp and AttractorViewHighlight.cpp (helpers:
// AttractorViewDetail.h).

#include "gui/views/AttractorRenderer.h"

#include <QElapsedTimer>
#include <QPointF>
#include <QPolygonF>
#include <QTimer>
#include <QWidget>

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

class QMouseEvent;
class QPainter;

namespace awb {

class AttractorView : public QWidget {
    Q_OBJECT
public:
    // How the attractor raster is made and coloured.
    struct RenderSettings {
        RenderRequest::Mode mode = RenderRequest::Mode::Deterministic;
        int depth = 12;
        std::uint64_t samples = 300000;
        std::uint64_t seed = 1;
        AttractorColouring colouring;  // an empty palette: the renderer's defaults
        int dotRadius = 1;       // in screen pixels: a one-pixel curve is hard to see
        ToneSettings tone;       // hits (crisp) or log density of the invariant measure
    };
    enum class Layer { Attractor, ControlPolygon, StartSet, ExactCurve, Subdivision, Hutchinson,
                       Grid };

    explicit AttractorView(QWidget *parent = nullptr);
    ~AttractorView() override;

    // ---- data (plain core types; the view keeps copies, the owner stays the document) ----
    // The IFS and its start set X0 (in the IFS space; drawn through the IFS's first view).
    // `iterate` draws automata (CIFS states): then only the views of `ifs` are used. `chaos`
    // draws an item with a chaos game of its own (a flame; random mode only): its picture and
    // frame are the chaos game's, `ifs` is not drawn.
    void setIfs(std::shared_ptr<const Ifs> ifs, const StartSet &start,
                CustomIterate iterate = {}, CustomChaos chaos = {});
    void setStartSet(const StartSet &start);
    // Control points m x 2 (one per row), drawn as the control polygon; empty to hide.
    void setControlPoints(const Mat &points, bool closed = false);
    // Several control polygons (a union of Bézier curves, the two curves and the handles of a
    // junction): drawn one after another, the points of set k labelled with the k-th letter
    // of p, q, r, s, ... Handles are addressed by one flat index (set 0 first) in
    // controlPointPosition() and the press/drag/release signals; controlPointSet() splits it.
    void setControlPolygons(const std::vector<Mat> &sets, const std::vector<bool> &closed = {});
    int controlPolygonCount() const { return int(m_controlSets.size()); }
    // {set, index within the set} of flat handle index `flat`; {-1, -1} when out of range.
    std::pair<int, int> controlPointSet(int flat) const;
    // The exact limit curve (n x 2) where one exists; empty to clear. A non-empty `label`
    // (what the curve is, e.g. "Takagi image c(x + 2iy·T(x))") is drawn as a legend entry.
    void setExactCurve(const Mat &curve, const QString &label = {});
    QString exactCurveLabel() const { return m_exactLabel; }
    int exactCurvePointCount() const { return int(m_exact.size()); }
    // Classic subdivision polygons, coarse to fine (k x 2 each).
    // closed[k]: polygon k is closed (its last point joins the first); missing entries: open.
    void setSubdivisionPolygons(const std::vector<Mat> &polygons,
                                const std::vector<bool> &closed = {});
    // Draw F^k(X0) as vectors (the papers' step-by-step figures); -1 turns it off.
    void setHutchinsonStep(int k);
    int hutchinsonStep() const { return m_hutchStep; }
    // Images of F^k(X0) currently drawn (0 when off or too many to draw as vectors).
    int hutchinsonImageCount() const { return int(m_hutch.size()); }
    void setRenderSettings(const RenderSettings &settings);
    RenderSettings renderSettings() const { return m_settings; }
    void setLayerVisible(Layer layer, bool visible);
    bool isLayerVisible(Layer layer) const;
    void setControlPointsEditable(bool editable) { m_editControl = editable; }
    bool controlPointsEditable() const { return m_editControl; }
    void setStartSetEditable(bool editable) { m_editStart = editable; }
    // Fit the view to the content whenever data arrives, until the user zooms or pans.
    void setAutoFit(bool on) { m_autoFit = on; }
    // A gesture elsewhere (a slider, a drag in another view, an animation) changes the data
    // many times a second: draw interactive pictures that fit the frame budget meanwhile, and
    // the full picture when it ends or pauses. The view's own drags, pans and wheel zooms are
    // gestures without being told.
    void setGestureActive(bool active);
    bool isInteractive() const;

    // ---- a selected sub-copy (view state, not a document edit): points of f_w(A) drawn over
    // the attractor, the control polygons S_w P of its pieces, and a caption. Drawn in
    // exports too. An empty highlight (no points, no polygons) clears it.
    struct Highlight {
        Mat points;                         // n x 2, plane coordinates
        std::vector<Mat> controlPolygons;   // m x 2 each
        QString caption;                    // e.g. "w = 0,1,1   t in [0.375, 0.5]"
        bool empty() const { return points.rows() == 0 && controlPolygons.empty(); }
    };
    void setHighlight(const Highlight &highlight);
    const Highlight &highlight() const { return m_highlight; }

    // ---- world <-> screen (widget pixels), equal scale on both axes, y up ----
    QPointF worldToScreen(const QPointF &world) const;
    QPointF screenToWorld(const QPointF &screen) const;
    double pixelsPerUnit() const { return m_scale; }
    QPointF viewCenter() const { return m_center; }
    QRectF visibleWorldRect() const;
    void setView(const QPointF &center, double pixelsPerUnit);
    // Control points and start-set vertices as drawn (in world coordinates).
    QPointF controlPointPosition(int i) const;
    QPointF startVertexPosition(int i) const;
    int controlPointCount() const { return int(m_control.size()); }
    // The editable control point handle under `screen` (flat index), or -1.
    int controlPointAt(const QPointF &screen) const { return hitControlPoint(screen); }
    // The edge of an editable control polygon under `screen`: the flat index of its first
    // point (the last point of a closed set for its closing edge), or -1; *world gets the
    // nearest point of the edge.
    int controlEdgeAt(const QPointF &screen, QPointF *world = nullptr) const;
    int startVertexCount() const { return int(m_startPlane.size()); }

    // How an export frames the world: as the view shows it (zoom and pan included), or
    // fitted to the content (control points, start set, overlays and the attractor), as a
    // printed figure wants it.
    enum class Framing { AsShown, FitContents };
    // Paints the figure into `target` of any painter (SVG, PDF, printer, image): overlays as
    // vector paths, the attractor as a raster made for the target's framing (the view's own
    // raster when it covers it), or as vector dots when the drawing has few points.
    void renderTo(QPainter *painter, const QRectF &target, Framing framing = Framing::AsShown);
    // What an exported figure shows, beyond the view's own layers.
    struct ExportStyle {
        Framing framing = Framing::AsShown;
        bool grid = true;           // the grid and its labels (when the view shows them)
        bool handles = true;        // control polygons, start set, their handles and labels
        QString fontFamily;         // empty: the view's font
        double fontPoints = 0;      // 0: the view's size; else points at the screen's 96 dpi
        double margin = -1;         // FitContents margin in screen pixels (< 0: the view's)
    };
    // Curves (polyline start sets, deterministic iteration) go to SVG, PDF and printers as
    // joined vector paths (render/CurvePaths.h); other content and PNG get a raster made at
    // the device resolution of the target, never a stretched screen raster.
    void renderTo(QPainter *painter, const QRectF &target, const ExportStyle &style);
    // The world rectangle a FitContents export frames (content bounds), if there is content.
    std::optional<QRectF> exportBounds() const { return fittedWorld(); }
    // The raw density (hits per pixel, render/DensityFile.h) of the attractor as the view
    // frames it, at `size` pixels, with the current data and settings: File > Export Figure
    // to .exr. Throws InputError when there is no attractor to count.
    AttractorDensity rawDensity(QSize size) const;
    // What the last renderTo drew the attractor as: "vector" (dots or shapes), "curve paths",
    // "raster WxH" (the raster's pixel size), or "none". For tests and the batch mode's log.
    QString lastExportKind() const { return m_lastExportKind; }
    // An export that needs its own raster computes it on a worker thread and, while it runs,
    // calls `progress` on the calling thread every ~50 ms with the fraction done; returning
    // false cancels it (the export then lacks the attractor and exportCancelled() is true
    // until the next renderTo). Without a callback the export simply waits.
    using ExportProgress = std::function<bool(double fraction)>;
    void setExportProgress(ExportProgress progress) { m_exportProgress = std::move(progress); }
    bool exportCancelled() const { return m_exportCancelled; }
    // The latest rendered attractor raster and what it shows.
    QImage currentImage() const { return m_image; }
    RenderInfo currentImageInfo() const { return m_imageInfo; }
    QString lastError() const { return m_error; }
    // Why the current item cannot be drawn (the owner's words), shown in the view while it
    // has no IFS to draw; empty when it can be drawn.
    void setProblem(const QString &problem)
    {
        if (problem != m_problem) {
            m_problem = problem;
            update();
        }
    }
    QString problem() const { return m_problem; }
    AttractorRenderer *renderer() const { return m_renderer; }
    // True while the renderer works on a request of this view (coarse or full pass).
    bool isRendering() const { return m_busy; }

    QSize sizeHint() const override { return {640, 480}; }
    QSize minimumSizeHint() const override { return {160, 120}; }

public slots:
    void fitToContents();
    // Multiplies the scale by `factor`, keeping the world point under `screenAnchor` fixed.
    void zoomBy(double factor, const QPointF &screenAnchor);
    void zoomIn() { zoomBy(1.25, rect().center()); }
    void zoomOut() { zoomBy(0.8, rect().center()); }
    // Stops the running render (Esc): the last image (perhaps the coarse preview) stays, the
    // status overlay says the render was cancelled, and nothing more of it arrives. Does
    // nothing when no render is running. The next edit (or renderAgain) renders normally.
    void cancelRender();
    // Renders the current data again at once (F5), e.g. after a cancel.
    void renderAgain();

signals:
    void controlPointPressed(int index);
    void controlPointDragged(int index, const QPointF &world);
    void controlPointReleased(int index, const QPointF &startWorld, const QPointF &endWorld);
    void startVertexPressed(int index);
    void startVertexDragged(int index, const QPointF &world);
    void startVertexReleased(int index, const QPointF &startWorld, const QPointF &endWorld);
    // A right click (no drag) at `screen` (widget pixels): the owner shows a context menu.
    void contextMenuRequested(const QPointF &screen, const QPoint &global);
    // A double click on an edge of the control polygon: flat index of the edge's first point
    // and the point of the edge nearest to the click.
    void controlEdgeDoubleClicked(int flatIndex, const QPointF &world);
    // The world coordinates under the cursor (for a status bar); cursorLeft when it leaves.
    void cursorMoved(const QPointF &world);
    void cursorLeft();
    // A left click (no drag) away from the handles, e.g. on the attractor: the owner may
    // select the sub-copy there.
    void attractorClicked(const QPointF &world);
    void viewChanged();
    // Rendering state, forwarded from the renderer.
    void renderProgress(double fraction);
    void renderFinished(const awb::RenderInfo &info);
    void renderFailed(const QString &message);
    // The running render was stopped by cancelRender(); no renderFinished follows for it.
    void renderCancelled();

protected:
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void showEvent(QShowEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void leaveEvent(QEvent *event) override;

private:
    // World -> some device rectangle: the widget, or an export target.
    struct Mapping {
        QPointF center;       // world point at the middle of `target`
        double scale = 1.0;   // device pixels per world unit
        QRectF target;
        // Device pixels per screen pixel: line widths, markers and fonts follow the figure,
        // not the device (an export at printer resolution looks like the screen).
        double unit = 1.0;
        QPointF map(const QPointF &w) const;
        QPointF unmap(const QPointF &s) const;
    };
    // One start-set image of a vector drawing (Hutchinson step or few-point export).
    struct VectorImage {
        QPolygonF polygon;    // plane coordinates
        QColor colour;
    };
    enum class DragKind { None, ControlPoint, StartVertex, Pan };
    struct Drag {
        DragKind kind = DragKind::None;
        int index = -1;
        QPointF pressScreen, lastScreen;
        QPointF pressWorld, startWorld, currentWorld;
    };

    Mapping screenMapping() const;
    void paintScene(QPainter &p, const Mapping &m, bool forExport);
    // The attractor as the view's raster, an export's own raster, or vector dots or shapes.
    void paintAttractorImages(QPainter &p, const Mapping &m, bool forExport);
    void paintGrid(QPainter &p, const Mapping &m) const;
    QFont sceneFont(double factor, double u) const;
    // The attractor raster of an export, `pixels` device pixels for m.target.
    QImage exportRaster(const Mapping &m, QSize pixels, RenderInfo *info) const;
    // Draws a curve's images as joined vector paths; false when it is no curve or too many
    // vertices would remain (the caller draws a raster).
    bool paintCurvePaths(QPainter &p, const Mapping &m) const;
    void paintVectorImages(QPainter &p, const Mapping &m, const std::vector<VectorImage> &images,
                           StartSet::Kind kind) const;
    void paintHandles(QPainter &p, const Mapping &m) const;
    void paintLegend(QPainter &p, const Mapping &m) const;
    void paintHighlight(QPainter &p, const Mapping &m) const;
    void paintStatus(QPainter &p) const;

    // The render of `world` into `size` pixels with the current data and settings; dots are
    // `pixelsPerScreenPixel` times the settings' radius.
    RenderRequest renderRequest(const QRectF &world, QSize size,
                                double pixelsPerScreenPixel) const;

    void dataChanged(bool geometryChanged);
    void scheduleRender();
    // Interactive: a picture within the frame budget (during a gesture); Full: the full
    // picture, unless it is drawn or being drawn; Again: the full picture anew (F5).
    enum class RenderKind { Interactive, Full, Again };
    void startRender();
    void requestRender(RenderKind kind);
    // The full picture of the current content, after a gesture ends or pauses.
    void refineRender();
    void userMovedView();
    // The frame log (gui/views/FrameLog.h): a pointer event, a presented frame, the handles.
    void logInput(const char *kind, const QMouseEvent *event) const;
    void logFrame();
    void updateStartPlane();
    void updateHutchinson();
    // F^depth(X0) as vector images when there are at most `maxVertices` vertices; false if more.
    bool vectorImages(int depth, std::size_t maxVertices, std::vector<VectorImage> *out) const;
    bool randomVectorImages(std::size_t maxVertices, std::vector<VectorImage> *out) const;
    std::optional<QRectF> contentBounds() const;
    // contentBounds() with a visible extent even for a point or a straight set.
    std::optional<QRectF> fittedWorld() const;
    // Index of the handle under `screen`, or -1.
    int hitControlPoint(const QPointF &screen) const;
    int hitStartVertex(const QPointF &screen) const;

    AttractorRenderer *m_renderer = nullptr;
    QTimer m_renderTimer;
    QTimer m_refineTimer;         // a paused gesture gets its full picture
    std::optional<std::pair<std::uint64_t, QRectF>> m_fullRequest; // version, world
    QElapsedTimer m_wheelGesture; // wheel zooms less than a refine delay apart are a gesture
    bool m_externalGesture = false;

    std::shared_ptr<const Ifs> m_ifs;
    CustomIterate m_iterate;
    CustomChaos m_chaos;
    StartSet m_start;
    std::vector<QPointF> m_startPlane;
    std::vector<QPointF> m_control;          // all sets, flat
    std::vector<int> m_controlSets;          // number of points of each set
    std::vector<bool> m_controlClosedSets;   // per set
    QPolygonF m_exact;
    QString m_exactLabel;
    std::vector<QPolygonF> m_subdivision;
    std::vector<bool> m_subdivisionClosed;
    int m_hutchStep = -1;
    std::vector<VectorImage> m_hutch;
    bool m_hutchTooMany = false;
    RenderSettings m_settings;
    std::uint32_t m_hiddenLayers = 0;
    bool m_editControl = true, m_editStart = true;

    QPointF m_center{0, 0};
    double m_scale = 50.0;
    bool m_autoFit = true;

    QImage m_image;
    RenderInfo m_imageInfo;
    // Which content (data and settings) the screen raster shows: an export may reuse it only
    // when it is final and of the current content.
    std::uint64_t m_contentVersion = 0, m_requestedVersion = 0, m_imageVersion = 0;
    QString m_error;
    QString m_problem;
    double m_progress = 1.0;
    bool m_busy = false;
    QElapsedTimer m_busySince;
    bool m_cancelled = false;      // the last render was cancelled (until the next one starts)
    double m_cancelledAt = 0.0;    // its progress then

    ExportProgress m_exportProgress;
    ExportStyle m_exportStyle;              // of the renderTo in progress
    mutable QString m_lastExportKind;
    mutable bool m_exportCancelled = false;

    Drag m_drag;
    // Frame log: the pointer position (global) each content version came from during a drag,
    // the picture count, and the handles last written.
    std::vector<std::pair<std::uint64_t, QPoint>> m_versionInput;
    std::uint64_t m_imageSerial = 0;
    std::vector<QPoint> m_loggedHandles;
    int m_hoverControl = -1, m_hoverStart = -1;
    std::optional<QPointF> m_clickPress;   // a left press on empty space: maybe a click
    Highlight m_highlight;
};

} // namespace awb
