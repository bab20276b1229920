// SurfaceView: construction, the data setters, the meshes built on the mesh worker and the CPU
// frames drawn on the frame worker. The camera, painting and input live in the other
// SurfaceView*.cpp units; the GL window in SurfaceGLWindow.cpp.

#include "gui/views/SurfaceView.h"

#include "gui/views/BackgroundPriority.h"
#include "gui/views/LatestJobWorker.h"
#include "gui/views/SurfaceGLWindow.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace awb {

SurfaceView::SurfaceView(QWidget *parent, bool allowGl)
    : QWidget(parent), m_allowGl(allowGl), m_meshWorker(std::make_unique<LatestJobWorker>()),
      m_frameWorker(std::make_unique<LatestJobWorker>()),
      m_baseWorker(std::make_unique<LatestJobWorker>())
{
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setAttribute(Qt::WA_OpaquePaintEvent);
    // A software GL renderer draws these frames slower than the CPU path (measured with
    // bench/bench_window.cpp): GL only on a GPU, or when asked for.
    m_useGl = allowGl && glAvailable()
              && (!glIsSoftware() || qEnvironmentVariableIntValue("AWB_GL") != 0);
    m_settle.setSingleShot(true);
    m_settle.setInterval(150);
    connect(&m_settle, &QTimer::timeout, this, [this] {
        m_moving = false;
        requestFrame();
    });
    m_dataTimer.setSingleShot(true);
    m_dataTimer.setInterval(0);
    connect(&m_dataTimer, &QTimer::timeout, this, &SurfaceView::startMeshJob);
}

SurfaceView::~SurfaceView()
{
    // Joins the workers before the members their jobs post to go away.
    m_meshWorker.reset();
    m_frameWorker.reset();
    m_baseWorker.reset();
}

bool SurfaceView::glAvailable()
{
    // The offscreen and minimal platforms have no GL worth trying (tests, batch figures); a
    // context that cannot be made current means the same on a real display.
    if (qEnvironmentVariableIntValue("AWB_NO_GL") != 0)
        return false;
    const QString platform = QGuiApplication::platformName();
    if (platform == QLatin1String("offscreen") || platform == QLatin1String("minimal"))
        return false;
    static const bool ok = [] {
        QOpenGLContext context;
        if (!context.create())
            return false;
        QOffscreenSurface surface;
        surface.setFormat(context.format());
        surface.create();
        return surface.isValid() && context.makeCurrent(&surface);
    }();
    return ok;
}

bool SurfaceView::glIsSoftware()
{
    if (!glAvailable())
        return false;
    static const bool software = [] {
        QOpenGLContext context;
        QOffscreenSurface surface;
        if (!context.create())
            return false;
        surface.setFormat(context.format());
        surface.create();
        if (!context.makeCurrent(&surface))
            return false;
        const auto *name = reinterpret_cast<const char *>(
            context.functions()->glGetString(GL_RENDERER));
        const QString renderer = QString::fromLatin1(name ? name : "").toLower();
        context.doneCurrent();
        return renderer.contains(QLatin1String("llvmpipe"))
               || renderer.contains(QLatin1String("softpipe"))
               || renderer.contains(QLatin1String("swrast"))
               || renderer.contains(QLatin1String("software"));
    }();
    return software;
}

void SurfaceView::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    // The GL window is made when the view is first shown, not before: a window that never
    // shows a surface has no GL surface in it.
    if (m_useGl && !m_glWindow) {
        m_glWindow = new SurfaceGLWindow(this);
        m_glContainer = QWidget::createWindowContainer(m_glWindow, this);
        m_glContainer->setFocusPolicy(Qt::NoFocus);
        m_glContainer->setGeometry(rect());
        m_glContainer->show();
    }
    requestFrame();
}

// ---- data ----------------------------------------------------------------------------------

namespace {

// Whether two IFS draw the same images (maps and views; the probabilities do not matter here).
bool sameImages(const Ifs *a, const Ifs *b)
{
    if (!a || !b)
        return a == b;
    const auto sameMat = [](const Mat &x, const Mat &y) {
        return x.rows() == y.rows() && x.cols() == y.cols() && x == y;
    };
    if (a->maps.size() != b->maps.size() || a->views.size() != b->views.size())
        return false;
    for (std::size_t i = 0; i < a->maps.size(); ++i)
        if (!sameMat(a->maps[i].A, b->maps[i].A) || !sameMat(a->maps[i].b, b->maps[i].b))
            return false;
    for (std::size_t i = 0; i < a->views.size(); ++i)
        if (!sameMat(a->views[i].V, b->views[i].V) || !sameMat(a->views[i].c, b->views[i].c))
            return false;
    return true;
}

} // namespace

void SurfaceView::setIfs(std::shared_ptr<const Ifs> ifs, const StartSet &start,
                         std::vector<int> colourIndex, OwnIteration own)
{
    // The owner sends the data again after edits that did not change it (the end of a drag,
    // a dock's refresh): keep the meshes.
    if (sameImages(ifs.get(), m_ifs.get()) && start.kind == m_start.kind
        && start.vertices.rows() == m_start.vertices.rows()
        && start.vertices.cols() == m_start.vertices.cols() && start.vertices == m_start.vertices
        && colourIndex == m_colourIndex && own.identity == m_own.identity) {
        m_ifs = std::move(ifs);
        m_own = std::move(own);
        return;
    }
    m_ifs = std::move(ifs);
    m_own = std::move(own);
    m_start = start;
    m_colourIndex = std::move(colourIndex);
    dataChanged();
}

void SurfaceView::setControlNet(const Mat &points, const std::vector<std::vector<int>> &faces,
                                std::vector<SharpEdge> sharp, std::vector<int> holes)
{
    m_net = points.cols() == 3 ? points : Mat();
    m_netFaces = faces;
    m_sharpEdges = std::move(sharp);
    m_holes = std::move(holes);
    if (m_selectedFace >= int(m_netFaces.size()))
        m_selectedFace = -1;
    if (m_selectedEdge.second >= m_net.rows())
        m_selectedEdge = {-1, -1};
    if (m_selected >= m_net.rows())
        m_selected = -1;
    update();
    if (m_glWindow)
        m_glWindow->update();
}

void SurfaceView::setStartVertices(const Mat &points)
{
    m_start3 = points.cols() == 3 ? points : Mat();
    update();
    if (m_glWindow)
        m_glWindow->update();
}

void SurfaceView::setMarkers(std::vector<Marker> markers)
{
    if (markers.size() != m_markers.size())
        m_selectedMarker = -1;
    m_markers = std::move(markers);
    update();
    if (m_glWindow)
        m_glWindow->update();
}

void SurfaceView::setSelectedMarker(int index)
{
    m_selectedMarker = index >= 0 && index < markerCount() ? index : -1;
    update();
    if (m_glWindow)
        m_glWindow->update();
}

void SurfaceView::setRefinedNet(const Mat &points, const std::vector<std::vector<int>> &faces)
{
    m_refined = points.cols() == 3 ? points : Mat();
    m_refinedFaces = faces;
    update();
    if (m_glWindow)
        m_glWindow->update();
}

void SurfaceView::setRenderSettings(const RenderSettings &settings)
{
    const bool same = settings.depth == m_settings.depth
                      && settings.colouring == m_settings.colouring
                      && settings.pointSize == m_settings.pointSize;
    m_settings = settings;
    if (!same)
        dataChanged();
}

void SurfaceView::setGestureActive(bool active)
{
    if (active == m_externalGesture)
        return;
    m_externalGesture = active;
    if (!active)
        m_dataTimer.start(); // full detail
}

void SurfaceView::setLayerVisible(Layer layer, bool visible)
{
    const std::uint32_t bit = 1u << int(layer);
    m_hidden = visible ? (m_hidden & ~bit) : (m_hidden | bit);
    update();
    requestFrame();
}

bool SurfaceView::isLayerVisible(Layer layer) const { return !(m_hidden & (1u << int(layer))); }

void SurfaceView::setDetailBudget(std::size_t full, std::size_t moving)
{
    m_fullBudget = std::max<std::size_t>(1, full);
    m_movingBudget = std::max<std::size_t>(1, std::min(moving, m_fullBudget));
    dataChanged();
}

void SurfaceView::dataChanged()
{
    ++m_dataSerial;
    if (!m_cameraSet && m_net.rows() > 0)
        resetCamera();
    m_dataTimer.start();
}

bool SurfaceView::pointMoving() const
{
    return m_drag.kind == DragKind::ControlPoint || m_drag.kind == DragKind::StartVertex
           || m_externalGesture;
}

SurfaceView::Colours SurfaceView::colours() const
{
    // A colour index per image and the palette it indexes, shared by both paths and the
    // figures: by the outermost map (its analysis map's colour, so that switching maps off does
    // not repaint the others), by the address prefix (a gradient), or one colour.
    Colours c;
    const AttractorColouring &colouring = m_settings.colouring;
    const QList<QColor> &palette = colouring.palette;
    const int maps = m_ifs ? m_ifs->size() : 0;
    switch (colouring.mode) {
    case AttractorColorMode::Single: {
        const QColor colour = palette.isEmpty() ? QColor(70, 110, 160) : palette.front();
        c.palette = {std::uint32_t(colour.rgb()) & 0xffffffu};
        c.label = [](const std::uint8_t *, int) { return 0u; };
        break;
    }
    case AttractorColorMode::ByMap: {
        const int n = palette.isEmpty() ? std::max(maps, 9) : int(palette.size());
        for (int i = 0; i < n; ++i) {
            const QColor colour = palette.isEmpty() ? AttractorRenderer::mapColor(i) : palette[i];
            c.palette.push_back(std::uint32_t(colour.rgb()) & 0xffffffu);
        }
        c.label = [index = m_colourIndex](const std::uint8_t *a, int n) {
            const int k = n > 0 ? a[0] : 0;
            return std::uint32_t(k < int(index.size()) ? index[std::size_t(k)] : k);
        };
        break;
    }
    case AttractorColorMode::ByAddress: {
        const int base = std::max(1, maps);
        int length = std::clamp(colouring.prefixLength, 1, 3);
        while (length > 1 && std::pow(double(base), length) > 4096)
            --length;
        int codes = 1;
        for (int k = 0; k < length; ++k)
            codes *= base;
        std::vector<std::uint8_t> digits(std::size_t(length), 0);
        for (int code = 0; code < codes; ++code) {
            for (int k = length - 1, v = code; k >= 0; --k, v /= base)
                digits[std::size_t(k)] = std::uint8_t(v % base);
            c.palette.push_back(std::uint32_t(AttractorRenderer::addressColor(
                                                  colouring, maps, digits.data(), length)
                                                  .rgb())
                                & 0xffffffu);
        }
        c.label = [base, length](const std::uint8_t *a, int n) {
            std::uint32_t code = 0;
            for (int k = 0; k < length; ++k)
                code = code * std::uint32_t(base) + (k < n ? a[k] : 0u);
            return code;
        };
        break;
    }
    }
    return c;
}

void SurfaceView::startMeshJob()
{
    m_dataTimer.stop(); // called directly too (a release): the timer's turn is this one
    if (!hasImages()) {
        m_meshes = MeshState{};
        m_meshes.serial = m_dataSerial;
        m_cpuImage = QImage();
        m_cpuImageMesh.reset();
        m_meshBusy = false;
        requestFrame();
        update();
        return;
    }
    const bool moving = pointMoving();
    // The full mesh of this very data is there (a gesture that changed nothing ended): draw.
    if (!moving && m_meshes.serial == m_dataSerial && m_meshes.full && !m_fullPending) {
        m_meshBusy = false;
        requestFrame();
        return;
    }
    // The full mesh of this very data is being built (asked for again, e.g. by the release
    // and then by the end of the gesture): let it finish.
    if (!moving && m_fullPending && m_fullSerial == m_dataSerial)
        return;
    // The coarse mesh of this very data is there (the last move of a drag): only the full one.
    const bool haveCoarse = m_meshes.serial == m_dataSerial && m_meshes.coarse;
    const int fullDepth =
        surfaceMeshDepth(*m_ifs, m_start, m_settings.depth, double(m_fullBudget), m_own);
    // Coarse meshes start from the tiling start when there is one (a closed surface at any
    // depth, not a cloud of small images); then they are never the full mesh.
    const StartSet &coarseFrom = coarseStart();
    const int coarseDepth = surfaceMeshDepth(*m_ifs, coarseFrom, m_settings.depth,
                                             coarseBudget(), m_own);
    const bool coarseIsFull = &coarseFrom == &m_start && coarseDepth == fullDepth;
    const std::uint64_t serial = m_dataSerial;
    const QPoint input = m_inputGlobal;
    const bool fromDrag =
        m_drag.kind == DragKind::ControlPoint || m_drag.kind == DragKind::StartVertex;
    auto ifs = m_ifs;
    // The worker's copy without the identity (the item's derived data, Qt values inside): it
    // is released on the GUI thread, never last on the worker.
    OwnIteration own = m_own;
    own.identity.reset();
    const StartSet start = m_start;
    const StartSet coarseFromCopy = coarseFrom;
    const ImageLabel label = colours().label;
    // While a point moves, the coarse mesh being built ends and shows (a frame a little
    // behind the pointer beats none: cancelling each would starve the drag); a full build is
    // long and of data that changed, so it is cancelled.
    const bool cancelRunning = !moving || m_fullPending;
    m_fullPending = !moving;
    m_fullSerial = m_dataSerial;
    m_meshBusy = true;
    // Posted per mesh, in order: the coarse one first (a frame now), then the full one.
    const auto deliver = [this, serial, input, fromDrag](std::shared_ptr<const SurfaceMesh> mesh,
                                                        bool full, double seconds,
                                                        bool moved = false) {
        m_inbox.post([=, this] {
            if (serial < m_meshes.serial)
                return; // older than the mesh shown
            if (full && serial == m_dataSerial)
                m_fullPending = false;
            if (m_meshes.serial != serial) {
                m_meshes = MeshState{};
                m_meshes.serial = serial;
            }
            m_meshes.input = input;
            m_meshes.fromDrag = fromDrag;
            m_meshes.coarse = full && m_meshes.coarse ? m_meshes.coarse : mesh;
            if (full) {
                m_meshes.full = mesh;
                m_meshes.fullMoved = moved;
            }
            m_meshSeconds = seconds;
            m_meshBusy = serial != m_dataSerial || (!full && !pointMoving());
            requestFrame();
            emit frameReady();
        });
    };
    // A net point released with its full base ready and exact for the new net (the start's
    // coefficients did not change): that mesh moved is the full mesh, no iteration. When not
    // exact the full mesh is built below: with the last map fused into the view it takes
    // about as long as drawing the moved base would, which would only delay it.
    if (!moving && m_release.base && m_release.exact && m_release.base->depth == fullDepth) {
        auto base = std::move(m_release.base);
        const Eigen::Vector3d d = m_release.delta;
        m_release = Release{};
        m_meshWorker->post([base, d, deliver](const std::atomic<bool> &) {
            QElapsedTimer timer;
            timer.start();
            deliver(std::make_shared<SurfaceMesh>(movedNetPoint(*base, d)), true,
                    timer.nsecsElapsed() * 1e-9, true);
        }, cancelRunning);
        return;
    }
    m_release = Release{};
    // A net point dragged from a base with its weights: the full mesh moved, in O(vertices).
    if (const auto delta = moving ? dragBaseMove() : std::nullopt) {
        m_meshWorker->post([base = m_dragBase.mesh, d = *delta, deliver](
                               const std::atomic<bool> &) {
            QElapsedTimer timer;
            timer.start();
            deliver(std::make_shared<SurfaceMesh>(movedNetPoint(*base, d)), false,
                    timer.nsecsElapsed() * 1e-9);
        }, cancelRunning);
        return;
    }
    m_meshWorker->post([ifs, own, start, coarseFromCopy, label, fullDepth, coarseDepth,
                        coarseIsFull, moving, haveCoarse,
                        deliver](const std::atomic<bool> &cancel) {
        QElapsedTimer timer;
        timer.start();
        IterationControl control;
        control.cancel = &cancel;
        try {
            if (moving || (!coarseIsFull && !haveCoarse)) {
                auto coarse = std::make_shared<SurfaceMesh>(
                    buildSurfaceMesh(*ifs, coarseFromCopy, coarseDepth, label, control, 0, own));
                if (cancel)
                    return;
                deliver(coarse, coarseIsFull, timer.nsecsElapsed() * 1e-9);
                if (moving || coarseIsFull)
                    return;
            }
            auto full = std::make_shared<SurfaceMesh>(
                buildSurfaceMesh(*ifs, start, fullDepth, label, control, 0, own));
            if (cancel)
                return;
            deliver(full, true, timer.nsecsElapsed() * 1e-9);
        } catch (const std::exception &) {
            deliver(std::make_shared<SurfaceMesh>(), true, timer.nsecsElapsed() * 1e-9);
        }
    }, cancelRunning);
}

void SurfaceView::startDragBase(int point)
{
    dropDragBase();
    if (!hasImages() || m_own.iterate || m_ifs->views.size() != 1
        || m_netCoordinates.V.rows() != m_ifs->dim() || m_netCoordinates.V.cols() != m_net.rows()
        || m_start.vertices.cols() != m_ifs->dim())
        return;
    const Projection weight = netWeight(m_netCoordinates, point);
    if (weight.V.cols() != 1)
        return;
    // At the moving budget, from the coarse meshes' start: the drag draws what it drew, moved.
    const int depth = surfaceMeshDepth(*m_ifs, coarseStart(), m_settings.depth, coarseBudget(),
                                       m_own);
    // Then the full mesh, moved at the release: F^k(X0) itself when no start vertex has a
    // coefficient on the point (its coefficients then do not depend on where the point is).
    const int fullDepth =
        surfaceMeshDepth(*m_ifs, m_start, m_settings.depth, double(m_fullBudget), m_own);
    // A start vertex with a coefficient on the point: c P^ = [X0, 1] forces c to change with
    // any move of it, so the moved full mesh could never be F^k(X0): not built -- unless the
    // start is made of net points, which move with the net (their coefficients stay e_j).
    const Mat coefficients = startCoefficients();
    const bool fullCanBeExact =
        m_startFollowsNet
        || (point < coefficients.cols() && coefficients.col(point).cwiseAbs().maxCoeff() < 1e-12);
    m_baseWorker->post([this, ifs = m_ifs, coarse = coarseStart(), start = m_start,
                        label = colours().label, depth, fullDepth, coefficients, weight, point,
                        net = m_net, fullCanBeExact](const std::atomic<bool> &cancel) {
        IterationControl control;
        control.cancel = &cancel;
        for (const bool full : {false, true}) {
            if (full && !fullCanBeExact)
                return;
            std::shared_ptr<const SurfaceMesh> mesh;
            try {
                // The full one at background priority (this worker's thread stays there):
                // the drag's frames come first.
                if (full)
                    lowerThisThreadPriority();
                mesh = std::make_shared<SurfaceMesh>(buildSurfaceMesh(
                    *ifs, full ? start : coarse, full ? fullDepth : depth, label, control, 0, {},
                    weight));
            } catch (const std::exception &) {
                return; // the drag's coarse meshes say what is wrong
            }
            if (cancel || mesh->empty())
                return;
            m_inbox.post([this, mesh, point, net, full, coefficients] {
                if (m_drag.kind != DragKind::ControlPoint || m_drag.index != point
                    || (full && m_dragBase.point != point))
                    return; // released (or another drag) meanwhile
                if (full) {
                    m_dragBase.full = mesh;
                    return;
                }
                m_dragBase = DragBase{mesh, nullptr, point, net, coefficients};
                if (!m_dataTimer.isActive() && dragBaseMove())
                    startMeshJob(); // the moves so far, at full detail now
            });
        }
    });
}

Mat SurfaceView::startCoefficients() const
{
    if (m_netCoordinates.V.cols() == 0 || m_start.vertices.cols() != m_netCoordinates.V.rows())
        return {};
    return (m_start.vertices * m_netCoordinates.V).rowwise() + m_netCoordinates.c;
}

void SurfaceView::dropDragBase()
{
    m_dragBase = DragBase{};
    m_baseWorker->post([](const std::atomic<bool> &) {}, true);
}

std::optional<Eigen::Vector3d> SurfaceView::dragBaseMove() const
{
    const DragBase &b = m_dragBase;
    if (!b.mesh || m_drag.kind != DragKind::ControlPoint || m_drag.index != b.point
        || m_own.iterate || m_net.rows() != b.net.rows() || m_net.cols() != 3
        || b.net.cols() != 3)
        return std::nullopt;
    for (Eigen::Index r = 0; r < m_net.rows(); ++r)
        if (r != b.point && m_net.row(r) != b.net.row(r))
            return std::nullopt;
    return Eigen::Vector3d((m_net.row(b.point) - b.net.row(b.point)).transpose());
}

std::shared_ptr<const SurfaceMesh> SurfaceView::frameMesh() const
{
    const bool coarse = m_moving || pointMoving() || !m_meshes.full;
    return coarse && m_meshes.coarse ? m_meshes.coarse : m_meshes.full;
}

const SurfaceMesh &SurfaceView::mesh() const
{
    static const SurfaceMesh none;
    const auto m = m_meshes.full ? m_meshes.full : m_meshes.coarse;
    return m ? *m : none;
}

bool SurfaceView::isFullDetail() const
{
    return m_meshes.full && m_meshes.serial == m_dataSerial && !m_meshBusy;
}

std::shared_ptr<const SurfaceMesh> SurfaceView::figureMesh() const
{
    if (m_meshes.full && m_meshes.serial == m_dataSerial)
        return m_meshes.full;
    if (!hasImages())
        return nullptr;
    try {
        const int depth =
            surfaceMeshDepth(*m_ifs, m_start, m_settings.depth, double(m_fullBudget), m_own);
        return std::make_shared<SurfaceMesh>(
            buildSurfaceMesh(*m_ifs, m_start, depth, colours().label, {}, 0, m_own));
    } catch (const std::exception &) {
        return nullptr;
    }
}

void SurfaceView::requestFrame()
{
    if (m_glWindow)
        m_glWindow->update();
    else if (!m_useGl)
        requestCpuFrame();
}

void SurfaceView::requestCpuFrame()
{
    const auto mesh = frameMesh();
    if (!mesh || mesh->empty() || !isLayerVisible(Layer::Attractor) || !isVisible()) {
        if (!mesh || !isLayerVisible(Layer::Attractor)) {
            m_cpuImage = QImage();
            m_cpuImageMesh.reset();
            m_requestedFrameMesh.reset(); // drawn again when it shows again
        }
        m_frameBusy = false;
        update();
        return;
    }
    const qreal dpr = devicePixelRatioF();
    const QSize size = (QSizeF(this->size().expandedTo(QSize(16, 16))) * dpr).toSize();
    const OrthoCamera camera = m_camera.ortho;
    const std::vector<std::uint32_t> palette = colours().palette;
    const double radius = std::max(0.5, 0.5 * m_settings.pointSize * dpr);
    // The same picture asked for again (several setters of one edit, the end of a gesture):
    // it is drawn or being drawn.
    const auto sameCamera = [](const OrthoCamera &a, const OrthoCamera &b) {
        return a.azimuth == b.azimuth && a.elevation == b.elevation && a.centre == b.centre
               && a.halfHeight == b.halfHeight;
    };
    if (mesh == m_requestedFrameMesh && size == m_requestedFrameSize
        && sameCamera(camera, m_requestedFrameCamera)
        && palette == m_requestedFramePalette && radius == m_requestedFrameRadius)
        return;
    m_requestedFrameMesh = mesh;
    m_requestedFrameSize = size;
    m_requestedFrameCamera = camera;
    m_requestedFramePalette = palette;
    m_requestedFrameRadius = radius;
    const std::uint64_t serial = ++m_frameSerial;
    // The pointer position the frame shows: the drag's mesh, or the orbit's camera.
    const bool orbit = m_drag.kind == DragKind::Orbit || m_drag.kind == DragKind::Pan;
    const bool shows = orbit || (m_meshes.fromDrag && pointMoving());
    const QPoint input = orbit ? m_inputGlobal : m_meshes.input;
    m_frameBusy = true;
    // A frame is short: a newer request waits for it instead of cancelling it, so that a
    // moving camera gets a picture per frame the raster can draw.
    m_frameWorker->post([this, mesh, size, camera, palette, radius, serial, shows,
                         input](const std::atomic<bool> &) {
        QElapsedTimer timer;
        timer.start();
        const QImage image =
            pixelsToImage(drawSurfaceMesh(*mesh, size.width(), size.height(), camera, radius, palette),
                    size);
        const double ms = timer.nsecsElapsed() * 1e-6;
        m_inbox.post([=, this] {
            // Frames come in order; each is the newest picture there is when it comes (the
            // next one is being drawn), unless the data went away meanwhile.
            if (serial < m_frameDelivered || (!m_meshes.coarse && !m_meshes.full))
                return;
            m_frameDelivered = serial;
            if (serial == m_frameSerial)
                m_frameBusy = false;
            m_cpuImage = image;
            m_cpuImageCamera = camera;
            m_cpuImageMesh = mesh;
            m_cpuImageShows = shows;
            m_cpuImageInput = input;
            ++m_cpuPictures;
            m_frameMs = ms;
            m_framePrimitives = mesh->size();
            update();
            emit frameReady();
        });
    }, false);
}

} // namespace awb
