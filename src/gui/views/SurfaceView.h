#pragma once
// The 3D attractor view of surface items (000 §3): F^k(X0) of the current item's IFS -- the
// images of the start set, filled triangles for a polygon start set -- with the control net
// (and the classic subdivision mesh after k rounds) drawn over it. It takes plain core data
// through setters and reports edits as press/drag/release signals (one undo step per drag is
// the owner's job, as in AttractorView).
//
// The images are kept as a SurfaceMesh (world-space primitives, core/render/SurfaceMesh.h),
// built off the GUI thread once per edit: a coarse one (a lower depth: still closed, no holes)
// for frames while the camera or a point moves, and the full one at rest. A camera move draws
// the kept mesh again without iterating. Two ways to draw it, one camera, one look:
//  - the CPU: SurfaceRaster (z-buffered, shaded, coloured by map) on worker threads; also every
//    printed or exported figure, so a figure is what the screen shows;
//  - OpenGL, in a QOpenGLWindow of its own (SurfaceGLWindow, created when the view is first
//    shown): only this view is drawn through GL, never the rest of the window. Used where the
//    GL renderer is a GPU's; with a software renderer (Mesa llvmpipe) the CPU path draws the
//    same frames faster (bench/bench_window.cpp measures both: AWB_GL=1 forces GL).
// The overlays (net, handles, axes, box) are painted with QPainter through the same projection.

#include "core/mesh/MeshTags.h"
#include "core/render/SurfaceMesh.h"
#include "core/render/SurfaceRaster.h"
#include "gui/views/AttractorRenderer.h"
#include "gui/views/ThreadInbox.h"

#include <optional>
#include <QElapsedTimer>
#include <QImage>
#include <QMatrix4x4>
#include <QPointer>
#include <QTimer>
#include <QVector3D>
#include <QWidget>

#include <memory>
#include <vector>

class QMouseEvent;
class QPainter;

namespace awb {

class LatestJobWorker;
class SurfaceGLWindow;

// The camera shared by both paths: the core's orthographic camera (azimuth, elevation, centre,
// half height) plus an optional perspective with the same framing at the centre's depth.
struct SurfaceViewCamera {
    OrthoCamera ortho;
    bool perspective = false;
    double fieldOfView = 30.0;  // degrees, vertical (perspective only)
    // World -> clip coordinates for a viewport of `aspect` (width / height); `depthRange` is
    // the half extent of the scene along the view direction (near/far planes).
    QMatrix4x4 matrix(double aspect, double depthRange) const;
};

class SurfaceView : public QWidget {
    Q_OBJECT
public:
    struct RenderSettings {
        int depth = 8;                    // the item's depth (the budget may lower it)
        AttractorColouring colouring;     // an empty palette: the renderer's defaults
        double pointSize = 2.0;           // pixels, for point start sets
    };
    enum class Layer { Attractor, ControlNet, Mesh, Axes, Box };
    // How frames are drawn: GL (a GPU's context) or CPU (SurfaceRaster).
    enum class Path { OpenGL, Cpu };

    // `allowGl` false forces the CPU path (tests); otherwise GL is used when a context can be
    // made on this platform with a hardware renderer (not on "offscreen"/"minimal", nor with
    // AWB_NO_GL=1; a software renderer only with AWB_GL=1).
    explicit SurfaceView(QWidget *parent = nullptr, bool allowGl = true);
    ~SurfaceView() override;

    // Whether a GL context can be made here at all, and whether it is drawn by hardware.
    static bool glAvailable();
    static bool glIsSoftware();
    Path path() const { return m_useGl ? Path::OpenGL : Path::Cpu; }

    // ---- data (copies; the document stays the owner) ----
    // The IFS (views give 3 columns) and its start set; `colourIndex[k]` is the colour index
    // of map k (the analysis map when a subset of maps is used; empty: k).
    // Items drawn by their own iteration (mesh items) add `own` (core/render/SurfaceMesh.h).
    void setIfs(std::shared_ptr<const Ifs> ifs, const StartSet &start,
                std::vector<int> colourIndex = {}, OwnIteration own = {});
    // How a point of the IFS space is drawn from the control net (SubdivisionIfs::
    // netCoordinates; no columns: unknown). Set before setIfs. With it, a drag of a net point
    // draws the coarse mesh of the press moved by each vertex's weight (core movedNetPoint)
    // instead of iterating again for every move.
    void setNetCoordinates(Projection coordinates) { m_netCoordinates = std::move(coordinates); }
    // The start set is made of net points (start set kind "net"): its coefficients on the net
    // are unit vectors whatever the points' positions, so a net point's drag moves F^k(X0)
    // exactly (the full mesh of the press, moved, is the picture at the release).
    void setStartFollowsNet(bool follows) { m_startFollowsNet = follows; }
    // A start set whose images tile the attractor (a lattice patch's corner limits, SurfaceIfs::
    // cornerLimitStart; empty: none), set before setIfs: the coarse meshes drawn while
    // something moves start from it, a closed surface at any depth instead of the scattered
    // small images of the item's own start set (issue 47: a dot cloud during a drag).
    void setTilingStart(StartSet start) { m_tilingStart = std::move(start); }
    // The control net: points n x 3 and faces (index lists); empty to hide. `sharp`: its sharp
    // edges (a mesh's creases, issue 44) as vertex pairs with their sharpness, drawn over it.
    void setControlNet(const Mat &points, const std::vector<std::vector<int>> &faces,
                       std::vector<SharpEdge> sharp = {}, std::vector<int> holes = {});
    // The start-set vertices (n x 3, drawn and draggable as handles).
    void setStartVertices(const Mat &points);
    // The subdivided net after k rounds (n x 3 with faces): the classic route beside the IFS.
    void setRefinedNet(const Mat &points, const std::vector<std::vector<int>> &faces);
    void setRenderSettings(const RenderSettings &settings);
    RenderSettings renderSettings() const { return m_settings; }
    void setLayerVisible(Layer layer, bool visible);
    bool isLayerVisible(Layer layer) const;
    void setControlPointsEditable(bool editable) { m_editable = editable; }
    // A gesture elsewhere (a slider, an animation) changes the data many times a second:
    // coarse meshes meanwhile, full detail when it ends.
    void setGestureActive(bool active);
    // Primitives (triangles, segments or points) of the full mesh at most, and of the coarse
    // one drawn while something moves.
    void setDetailBudget(std::size_t full, std::size_t moving);
    std::size_t detailBudget() const { return m_fullBudget; }

    // ---- camera ----
    SurfaceViewCamera camera() const { return m_camera; }
    void setCamera(const SurfaceViewCamera &camera);
    // Perspective applies to the GL path; the CPU path (and so print) stays orthographic.
    void setPerspective(bool on);
    // Orbit by screen pixels (turntable: horizontal turns about z, vertical tilts).
    void orbit(double dxPixels, double dyPixels);
    void pan(double dxPixels, double dyPixels);
    // Zooms by `factor` about the view centre, or keeping the point under `anchor` (the
    // mouse wheel's cursor) where it is.
    void zoomBy(double factor, std::optional<QPointF> anchor = std::nullopt);
    // Frames the net, the start set and the mesh from the default direction.
    void resetCamera();
    // The direction resetCamera() looks from (the item's saved camera, degrees); a new
    // direction resets the camera to it.
    void setHomeDirection(double azimuth, double elevation);
    // Screen position (widget pixels) of a world point, and the world vector of a screen move
    // in the view plane through `at`.
    QPointF toScreen(const QVector3D &world) const;
    QVector3D screenDelta(const QPointF &delta, const QVector3D &at) const;
    QPointF controlPointScreen(int i) const;
    int controlPointCount() const { return int(m_net.rows()); }
    // The control point picked last by a click (-1: none); drawn highlighted.
    int selectedControlPoint() const { return m_selected; }
    // The net edge picked last by a click on it, as its two vertices ({-1, -1}: none); drawn
    // highlighted. A click on a control point clears it, and the other way round.
    std::pair<int, int> selectedNetEdge() const { return m_selectedEdge; }
    void setSelectedNetEdge(int a, int b);
    // The net face picked last by a click inside it, away from its edges and points (-1:
    // none; the front one where faces overlap on screen); drawn outlined. Holes are hatched.
    int selectedNetFace() const { return m_selectedFace; }
    void setSelectedNetFace(int face);
    // Marked points with a label (the extraordinary vertices of a mesh at their limit
    // positions, labelled with their valence): drawn over the surface, one of them selected; a
    // click on one (press and release without moving) reports markerClicked.
    struct Marker {
        QVector3D at;
        QString label;
        // The outward unit normal of a closed surface at `at`: the marker is hidden behind the
        // surface when it faces away from the viewer (faded, no label, not clickable). Zero
        // (an open surface, whose back is seen, or no normal): always shown.
        QVector3D normal;
    };
    void setMarkers(std::vector<Marker> markers);
    int markerCount() const { return int(m_markers.size()); }
    QPointF markerScreen(int i) const;
    // Whether marker i faces the viewer (see Marker::normal).
    bool markerFacing(int i) const;
    void setSelectedMarker(int index);
    int selectedMarker() const { return m_selectedMarker; }
    QPointF startVertexScreen(int i) const;
    int startVertexCount() const { return int(m_start3.rows()); }

    // ---- output ----
    // The full mesh (or the coarse one while only that exists), and whether the view is still
    // computing a mesh or a CPU frame.
    const SurfaceMesh &mesh() const;
    bool isFullDetail() const;
    double meshSeconds() const { return m_meshSeconds; }
    QImage cpuImage() const { return m_cpuImage; }
    bool isRendering() const { return m_meshBusy || m_frameBusy; }
    // The full mesh of the data shown is being built (from the release of a drag on).
    bool fullMeshPending() const { return m_fullPending && m_fullSerial == m_dataSerial; }
    // The full mesh shown is the one built at a net point's press, moved by the point's weights
    // at the release (exact there: no start vertex has a coefficient on the point).
    bool fullMeshMovedFromPress() const
    {
        return m_meshes.full && m_meshes.fullMoved && m_meshes.serial == m_dataSerial;
    }
    // A net point's drag has its press's mesh with the point's weights: the coarse one, and
    // with `full` the full one too.
    bool hasDragBase(bool full) const
    {
        return full ? bool(m_dragBase.full) : bool(m_dragBase.mesh);
    }
    // Paints the figure into `target` of any painter with the CPU renderer (same camera,
    // colours, overlays): for printing, export and the batch mode. On the calling thread.
    void renderTo(QPainter *painter, const QRectF &target) const;
    // The CPU picture alone at `size` (no overlays): tests compare it to references.
    QImage renderImage(QSize size, bool overlays = true) const;
    // Milliseconds of the last frame drawn (GL: draw + glFinish; CPU: the raster), and the
    // primitives it drew.
    double lastFrameMs() const { return m_frameMs; }
    std::size_t lastFramePrimitives() const { return m_framePrimitives; }
    bool cameraMoving() const { return m_moving; }
    // GL path only: the window's frame as an image, and a request for a new frame.
    QImage grabGlFrame() const;
    void requestGlFrame();

    QSize sizeHint() const override { return {640, 480}; }

signals:
    void controlPointPressed(int index);
    void controlPointDragged(int index, const QVector3D &world);
    void controlPointReleased(int index, const QVector3D &start, const QVector3D &end);
    void startVertexPressed(int index);
    void startVertexDragged(int index, const QVector3D &world);
    void startVertexReleased(int index, const QVector3D &start, const QVector3D &end);
    void markerClicked(int index);
    // A click (no drag) on an edge of the control net, away from its points (issue 44: the
    // edge to crease).
    void netEdgeClicked(int a, int b);
    // A click (no drag) inside a face of the control net (issue 44: the face to make a hole).
    void netFaceClicked(int face);
    void cameraChanged();
    // The user turned the view (the end of an orbit drag, an arrow key): the direction the
    // document may keep (the item's camera, which exports and the CLI use), in degrees.
    void cameraTurned(double azimuth, double elevation);
    // A mesh (GL) or a CPU frame arrived.
    void frameReady();
    void frameDrawn(double milliseconds, qulonglong primitives);

protected:
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void showEvent(QShowEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;

private:
    friend class SurfaceGLWindow;
    // The CPU frame of a mesh (0xAARRGGBB rows) as an image.
    static QImage pixelsToImage(const std::vector<std::uint32_t> &pixels, QSize size);
    enum class DragKind { None, Orbit, Pan, ControlPoint, StartVertex };
    struct Drag {
        DragKind kind = DragKind::None;
        int index = -1;
        int marker = -1;  // the marker under the press (an orbit drag that does not move)
        QPointF press, last;
        QVector3D startWorld, currentWorld;
    };
    // The colours of the primitives: a colour index per image, and the palette it indexes.
    struct Colours {
        ImageLabel label;
        std::vector<std::uint32_t> palette;  // 0xRRGGBB
    };
    // A mesh and what it was made from (the pointer position of a drag, for the frame log).
    struct MeshState {
        std::shared_ptr<const SurfaceMesh> coarse, full;
        std::uint64_t serial = 0;      // the data it was made of (m_dataSerial then)
        QPoint input;
        bool fromDrag = false;
        bool fullMoved = false;  // the full mesh is the press's full mesh moved (exact)
    };

    // ---- SurfaceView.cpp: data and jobs
    void dataChanged();
    void startMeshJob();
    void requestFrame();
    void requestCpuFrame();
    Colours colours() const;
    bool pointMoving() const;
    // The mesh a frame draws now: the coarse one while something moves, else the full one.
    std::shared_ptr<const SurfaceMesh> frameMesh() const;
    // A mesh of the current data for a figure (the full one when it is there).
    std::shared_ptr<const SurfaceMesh> figureMesh() const;
    // ---- SurfaceViewCamera.cpp
    QMatrix4x4 viewMatrix(QSizeF size) const;
    double depthRange() const;
    QPointF project(const QMatrix4x4 &mvp, const QRectF &target, const QVector3D &w) const;
    Mat sceneBounds() const;  // 2 x 3: lo, hi of net, start and refined net
    void cameraMoved();
    // ---- SurfaceViewPainting.cpp
    // Everything painted over the surface, through `mvp` onto `target`.
    void paintOverlay(QPainter &p, const QMatrix4x4 &mvp, const QRectF &target,
                      double unit) const;
    // The frame log (gui/views/FrameLog.h): a presented frame, and the handles at rest.
    void logFrame(std::uint64_t picture, bool final, const QPoint *shows);
    // ---- SurfaceViewInput.cpp
    int hit(const Mat &points, const QPointF &screen) const;
    int hitMarker(const QPointF &screen) const;
    // The net edge nearest to `screen` within the hit radius, or {-1, -1}.
    std::pair<int, int> hitEdge(const QPointF &screen) const;
    void logInput(const char *kind, const QMouseEvent *event);
    void setViewCursor(Qt::CursorShape shape);

    // GL: the window (created at the first show), its container and whether it is used.
    bool m_allowGl = true;
    bool m_useGl = false;
    SurfaceGLWindow *m_glWindow = nullptr;
    QWidget *m_glContainer = nullptr;

    ThreadInbox m_inbox{this}; // the workers' results; declared before them, so it outlives them
    std::unique_ptr<LatestJobWorker> m_meshWorker, m_frameWorker, m_baseWorker;
    std::shared_ptr<const Ifs> m_ifs;
    OwnIteration m_own;
    // Whether there is anything to iterate: maps and a start set, or the item's own iteration.
    bool hasImages() const
    {
        return m_ifs && ((m_ifs->size() > 0 && m_start.vertices.rows() > 0) || m_own.iterate);
    }
    StartSet m_start;
    std::vector<int> m_colourIndex;
    Mat m_net, m_start3, m_refined;
    std::vector<Marker> m_markers;
    int m_selectedMarker = -1;
    std::vector<std::vector<int>> m_netFaces, m_refinedFaces;
    std::vector<SharpEdge> m_sharpEdges;
    int hitFace(const QPointF &screen) const;
    RenderSettings m_settings;
    std::uint32_t m_hidden = 0;
    bool m_editable = true;
    bool m_externalGesture = false;
    std::size_t m_fullBudget = 400'000, m_movingBudget = 40'000;

    SurfaceViewCamera m_camera;
    bool m_cameraSet = false;    // the user moved the camera: data changes keep it
    double m_homeAzimuth = -60.0, m_homeElevation = 40.0;
    bool m_moving = false;       // the camera moves: frames draw the coarse mesh
    QTimer m_settle;             // the camera stopped -> full detail
    QTimer m_dataTimer;          // coalesces edits into one job

    MeshState m_meshes;
    // The full mesh of the data a net-point drag started from, with the dragged point's
    // weights (built on m_baseWorker at the press): each move draws it moved; the release
    // builds the exact one.
    struct DragBase {
        std::shared_ptr<const SurfaceMesh> mesh;
        std::shared_ptr<const SurfaceMesh> full;  // F^k(X0) at full detail, with the weights
        int point = -1;
        Mat net;           // the net it was built of
        Mat coefficients;  // the start vertices' coefficients on the net then
    };
    // The start vertices' coefficients on the control points (SubdivisionIfs::netCoordinates):
    // when a drag leaves them as they were, the press's mesh moved is F^k(X0) exactly (not when
    // a start vertex has a coefficient on the point, nor when the lifting chose other rows).
    Mat startCoefficients() const;
    DragBase m_dragBase;
    // What a release hands to startMeshJob: the full base and the point's move.
    struct Release {
        std::shared_ptr<const SurfaceMesh> base;
        Eigen::Vector3d delta = Eigen::Vector3d::Zero();
        bool exact = false;
    };
    Release m_release;
    Projection m_netCoordinates;
    bool m_startFollowsNet = false;
    StartSet m_tilingStart;
    // The coarse meshes' primitives at most: a tiling start's triangles cover the whole
    // surface (each pixel several times where a patch's pieces overlap, 1.5x per level for
    // Loop's hexagon), where a small start's are specks, so they get a quarter of the budget.
    double coarseBudget() const
    {
        return double(m_movingBudget) / (&coarseStart() == &m_tilingStart ? 4.0 : 1.0);
    }
    const StartSet &coarseStart() const
    {
        return m_tilingStart.vertices.rows() > 0 && m_tilingStart.vertices.cols() == m_start.vertices.cols()
                       && !m_own.iterate
                   ? m_tilingStart
                   : m_start;
    }
    void startDragBase(int point);
    void dropDragBase();
    // The dragged point's move since the base, when only it moved; nothing otherwise.
    std::optional<Eigen::Vector3d> dragBaseMove() const;
    std::uint64_t m_dataSerial = 0;  // bumped by every data change
    double m_meshSeconds = 0.0;
    bool m_meshBusy = false, m_frameBusy = false;
    bool m_fullPending = false;      // a full mesh job was posted and has not delivered
    std::uint64_t m_fullSerial = 0;  // the data serial of that job
    std::uint64_t m_frameSerial = 0, m_frameDelivered = 0;
    // What the last CPU frame request drew (an equal request is not drawn again).
    std::shared_ptr<const SurfaceMesh> m_requestedFrameMesh;
    QSize m_requestedFrameSize;
    OrthoCamera m_requestedFrameCamera;
    std::vector<std::uint32_t> m_requestedFramePalette;
    double m_requestedFrameRadius = 0.0;
    // The CPU frame on screen: its camera, mesh and the pointer position it shows.
    QImage m_cpuImage;
    OrthoCamera m_cpuImageCamera;
    std::shared_ptr<const SurfaceMesh> m_cpuImageMesh;
    QPoint m_cpuImageInput;
    bool m_cpuImageShows = false;
    std::uint64_t m_cpuPictures = 0;
    double m_frameMs = 0.0;
    std::size_t m_framePrimitives = 0;
    Drag m_drag;
    int m_selected = -1;
    std::pair<int, int> m_selectedEdge{-1, -1};
    int m_selectedFace = -1;
    std::vector<int> m_holes;  // faces of the net that are holes
    // Frame log: the last pointer position (global) and the handles written last.
    QPoint m_inputGlobal;
    std::vector<QPoint> m_loggedHandles;
};

} // namespace awb
