#pragma once
// The 3D attractor view of surface items (000 §3): the attractor of the current item's IFS as
// a lit point cloud, with the control net (and the classic subdivision mesh after k rounds)
// drawn over it. It takes plain core data through setters and reports edits as
// press/drag/release signals (one undo step per drag is the owner's job, as in AttractorView).
//
// Two ways to draw, one camera: with an OpenGL context (a SurfaceGLWidget child, points with
// depth test and lighting from the normals of the start-set images), or without one (the
// offscreen platform, a machine with no GL) through the core's CPU z-buffer SurfaceRaster. The
// overlays (net, handles, axes, box) are painted with QPainter through the same projection, and
// printing always uses the CPU renderer, so a figure matches the screen wherever it is made.
// The point cloud is computed off the GUI thread; a newer edit cancels the running job.

#include "core/ifs/Attractor.h"
#include "core/render/SurfaceRaster.h"
#include "gui/views/AttractorRenderer.h"

#include <QElapsedTimer>
#include <QImage>
#include <QMatrix4x4>
#include <QTimer>
#include <QVector3D>
#include <QWidget>

#include <memory>
#include <vector>

class QPainter;

namespace awb {

class SurfaceGLWidget;
class LatestJobWorker;

// The points a GL frame draws: positions, normals (zero when unknown) and colours, in a random
// order so that any prefix is an even sample of the whole (decimation = drawing fewer).
struct SurfaceCloud {
    std::vector<float> positions;        // 3 per point
    std::vector<float> normals;          // 3 per point
    std::vector<std::uint32_t> colours;  // 0xAARRGGBB per point
    int depth = 0;
    double area = 0.0;     // world area the points stand for (sum of the images' areas)
    double seconds = 0.0;
    std::size_t size() const { return colours.size(); }
};

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
        double pointSize = 2.0;           // pixels
    };
    enum class Layer { Attractor, ControlNet, Mesh, Axes, Box };
    // How frames are drawn: GL (a context was created) or CPU (SurfaceRaster).
    enum class Path { OpenGL, Cpu };

    // `allowGl` false forces the CPU path (tests); otherwise GL is used when a context can be
    // created on this platform (not on "offscreen"/"minimal", nor with AWB_NO_GL=1).
    explicit SurfaceView(QWidget *parent = nullptr, bool allowGl = true);
    ~SurfaceView() override;

    static bool glAvailable();
    Path path() const { return m_gl ? Path::OpenGL : Path::Cpu; }

    // ---- data (copies; the document stays the owner) ----
    // The IFS (views give 3 columns) and its start set; `colourIndex[k]` is the colour index
    // of map k (the analysis map when a subset of maps is used; empty: k).
    void setIfs(std::shared_ptr<const Ifs> ifs, const StartSet &start,
                std::vector<int> colourIndex = {});
    // The control net: points n x 3 and faces (index lists); empty to hide.
    void setControlNet(const Mat &points, const std::vector<std::vector<int>> &faces);
    // The start-set vertices (n x 3, drawn and draggable as handles).
    void setStartVertices(const Mat &points);
    // The subdivided net after k rounds (n x 3 with faces): the classic route beside the IFS.
    void setMesh(const Mat &points, const std::vector<std::vector<int>> &faces);
    void setRenderSettings(const RenderSettings &settings);
    RenderSettings renderSettings() const { return m_settings; }
    void setLayerVisible(Layer layer, bool visible);
    bool isLayerVisible(Layer layer) const;
    void setControlPointsEditable(bool editable) { m_editable = editable; }
    // A gesture elsewhere (a slider, an animation) changes the data many times a second:
    // decimated clouds meanwhile, full detail when it ends.
    void setGestureActive(bool active);
    // Points of the cloud at most (full detail) and while the camera moves (decimated).
    void setPointBudget(std::size_t full, std::size_t moving = 150000);
    std::size_t pointBudget() const { return m_budget; }

    // ---- camera ----
    SurfaceViewCamera camera() const { return m_camera; }
    void setCamera(const SurfaceViewCamera &camera);
    // Perspective applies to the GL path; the CPU path (and so print) stays orthographic.
    void setPerspective(bool on);
    // Orbit by screen pixels (turntable: horizontal turns about z, vertical tilts).
    void orbit(double dxPixels, double dyPixels);
    void pan(double dxPixels, double dyPixels);
    void zoomBy(double factor);
    // Frames the net, the start set and the cloud from the default direction.
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
    QPointF startVertexScreen(int i) const;
    int startVertexCount() const { return int(m_start3.rows()); }

    // ---- output ----
    // The latest cloud (GL path) or CPU frame, and whether the view is still computing.
    const SurfaceCloud &cloud() const { return *m_cloud; }
    QImage cpuImage() const { return m_cpuImage; }
    bool isRendering() const { return m_busy; }
    // Paints the figure into `target` with the CPU renderer (same camera, colours, overlays):
    // for printing, export and the batch mode. Runs on the calling thread.
    void renderTo(QPainter *painter, const QRectF &target) const;
    // The CPU picture alone at `size` (no overlays): tests compare it to references.
    QImage renderImage(QSize size, bool overlays = true) const;
    // Milliseconds of the last GL frame (draw + glFinish), and the points it drew.
    double lastFrameMs() const { return m_frameMs; }
    std::size_t lastFramePoints() const { return m_framePoints; }
    bool cameraMoving() const { return m_moving; }
    // Splat diameter in device pixels for `points` points of the cloud: the style's point
    // size, or larger where the points are too sparse to close the surface.
    double splatSize(std::size_t points, double devicePixelRatio) const;

    QSize sizeHint() const override { return {640, 480}; }

signals:
    void controlPointPressed(int index);
    void controlPointDragged(int index, const QVector3D &world);
    void controlPointReleased(int index, const QVector3D &start, const QVector3D &end);
    void startVertexPressed(int index);
    void startVertexDragged(int index, const QVector3D &world);
    void startVertexReleased(int index, const QVector3D &start, const QVector3D &end);
    void cameraChanged();
    // A cloud (GL) or a CPU frame arrived.
    void frameReady();
    void frameDrawn(double milliseconds, qulonglong points);

protected:
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;

private:
    friend class SurfaceGLWidget;
    enum class DragKind { None, Orbit, Pan, ControlPoint, StartVertex };
    struct Drag {
        DragKind kind = DragKind::None;
        int index = -1;
        QPointF press, last;
        QVector3D startWorld, currentWorld;
    };

    // Everything painted over the points, through `mvp` onto `target`.
    void paintOverlay(QPainter &p, const QMatrix4x4 &mvp, const QRectF &target,
                      double unit) const;
    QMatrix4x4 viewMatrix(QSizeF size) const;
    double depthRange() const;
    QPointF project(const QMatrix4x4 &mvp, const QRectF &target, const QVector3D &w) const;
    Mat sceneBounds() const;  // 2 x 3: lo, hi of net, start and cloud
    void dataChanged();
    void startJob();
    void cameraMoved();
    void requestCpuFrame();
    int hit(const Mat &points, const QPointF &screen) const;
    std::vector<std::uint32_t> paletteArgb(int maps) const;
    std::vector<int> rasterLabels() const;
    // The CPU raster of the current data at `size` for `camera` (blocking; cancellable).
    QImage cpuRaster(QSize size, const OrthoCamera &camera, std::size_t budget,
                     const std::atomic<bool> *cancel) const;

    SurfaceGLWidget *m_gl = nullptr;
    std::unique_ptr<LatestJobWorker> m_worker;
    std::shared_ptr<const Ifs> m_ifs;
    StartSet m_start;
    std::vector<int> m_colourIndex;
    Mat m_net, m_start3, m_mesh;
    std::vector<std::vector<int>> m_netFaces, m_meshFaces;
    RenderSettings m_settings;
    std::uint32_t m_hidden = 0;
    bool m_editable = true;
    bool m_externalGesture = false;
    std::size_t m_budget = 1'200'000, m_movingBudget = 150'000;

    SurfaceViewCamera m_camera;
    bool m_cameraSet = false;    // the user moved the camera: data changes keep it
    double m_homeAzimuth = -60.0, m_homeElevation = 40.0;
    bool m_moving = false;       // camera moving: GL decimates, CPU draws coarse
    QTimer m_settle;             // camera stopped -> full detail
    QTimer m_dataTimer;          // coalesces edits into one job

    std::shared_ptr<const SurfaceCloud> m_cloud;
    std::uint64_t m_serial = 0;
    bool m_busy = false;
    QImage m_cpuImage;
    OrthoCamera m_cpuImageCamera;
    double m_frameMs = 0.0;
    std::size_t m_framePoints = 0;
    Drag m_drag;
    int m_selected = -1;
};

} // namespace awb
