// SurfaceView: input -- picking and dragging net points and start vertices in the view plane,
// orbit, pan and zoom, the keyboard, and the frame log's pointer events. The GL window hands its
// events to these handlers (SurfaceGLWindow).

#include "gui/views/SurfaceView.h"

#include "gui/views/FrameLog.h"
#include "gui/views/SurfaceGLWindow.h"

#include <QKeyEvent>
#include <QPolygonF>
#include <QMouseEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <limits>

namespace awb {

namespace {

constexpr double hitRadius = 9.0;

} // namespace

void SurfaceView::logInput(const char *kind, const QMouseEvent *event)
{
    m_inputGlobal = event->globalPosition().toPoint();
    if (!framelog::enabled())
        return;
    framelog::write("input", QStringLiteral("surface %1 %2 %3")
                                 .arg(QLatin1String(kind))
                                 .arg(m_inputGlobal.x())
                                 .arg(m_inputGlobal.y()));
}

void SurfaceView::setViewCursor(Qt::CursorShape shape)
{
    setCursor(shape);
    if (m_glWindow)
        m_glWindow->setCursor(shape);
}


int SurfaceView::hit(const Mat &points, const QPointF &screen) const
{
    int best = -1;
    double bestDistance = hitRadius * hitRadius;
    for (int i = 0; i < points.rows(); ++i) {
        const QPointF d = toScreen(QVector3D(float(points(i, 0)), float(points(i, 1)),
                                             float(points(i, 2)))) - screen;
        const double dd = QPointF::dotProduct(d, d);
        if (dd <= bestDistance) {
            bestDistance = dd;
            best = i;
        }
    }
    return best;
}

int SurfaceView::hitMarker(const QPointF &screen) const
{
    int best = -1;
    double bestDistance = hitRadius * hitRadius;
    for (int i = 0; i < markerCount(); ++i) {
        if (!markerFacing(i))
            continue;  // behind the surface: not clickable through it
        const QPointF d = markerScreen(i) - screen;
        const double dd = QPointF::dotProduct(d, d);
        if (dd <= bestDistance) {
            bestDistance = dd;
            best = i;
        }
    }
    return best;
}

std::pair<int, int> SurfaceView::hitEdge(const QPointF &screen) const
{
    std::pair<int, int> best{-1, -1};
    double bestDistance = hitRadius * hitRadius;
    const auto at = [&](int i) {
        return toScreen(QVector3D(float(m_net(i, 0)), float(m_net(i, 1)), float(m_net(i, 2))));
    };
    for (const auto &f : m_netFaces)
        for (std::size_t k = 0; k < f.size(); ++k) {
            const int a = f[k], b = f[(k + 1) % f.size()];
            if (a < 0 || b < 0 || a >= m_net.rows() || b >= m_net.rows())
                continue;
            const QPointF p = at(a), q = at(b), d = q - p;
            const double length = QPointF::dotProduct(d, d);
            const double t = length > 0 ? std::clamp(QPointF::dotProduct(screen - p, d) / length,
                                                     0.0, 1.0)
                                        : 0.0;
            const QPointF off = p + t * d - screen;
            const double dd = QPointF::dotProduct(off, off);
            if (dd < bestDistance) {
                bestDistance = dd;
                best = {std::min(a, b), std::max(a, b)};
            }
        }
    return best;
}

int SurfaceView::hitFace(const QPointF &screen) const
{
    // The faces whose outline on screen holds the point; of those the nearest the eye (by its
    // centre: the net's faces are small and seldom cross).
    const Eigen::Vector3d toward = m_camera.ortho.toward();
    int best = -1;
    double nearest = -std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < m_netFaces.size(); ++f) {
        const auto &loop = m_netFaces[f];
        QPolygonF outline;
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        bool inside = loop.size() >= 3;
        for (int v : loop) {
            if (v < 0 || v >= m_net.rows()) {
                inside = false;
                break;
            }
            outline << toScreen(QVector3D(float(m_net(v, 0)), float(m_net(v, 1)),
                                          float(m_net(v, 2))));
            centre += m_net.row(v).transpose();
        }
        if (!inside || !outline.containsPoint(screen, Qt::OddEvenFill))
            continue;
        const double depth = (centre / double(loop.size())).dot(toward);
        if (depth > nearest) {
            nearest = depth;
            best = int(f);
        }
    }
    return best;
}

void SurfaceView::setSelectedNetFace(int face)
{
    m_selectedFace = face >= 0 && face < int(m_netFaces.size()) ? face : -1;
    if (m_selectedFace >= 0) {
        m_selected = -1;
        m_selectedEdge = {-1, -1};
    }
    update();
    if (m_glWindow)
        m_glWindow->update();
}

void SurfaceView::setSelectedNetEdge(int a, int b)
{
    m_selectedEdge = a >= 0 && b >= 0 ? std::pair{std::min(a, b), std::max(a, b)}
                                      : std::pair{-1, -1};
    if (m_selectedEdge.first >= 0) {
        m_selected = -1;
        m_selectedFace = -1;
    }
    update();
    if (m_glWindow)
        m_glWindow->update();
}

void SurfaceView::mousePressEvent(QMouseEvent *event)
{
    logInput("press", event);
    const QPointF pos = event->position();
    m_drag = Drag{};
    m_drag.press = m_drag.last = pos;
    const bool panButton = event->button() == Qt::MiddleButton
                           || event->button() == Qt::RightButton
                           || (event->button() == Qt::LeftButton
                               && (event->modifiers() & Qt::ShiftModifier));
    if (panButton) {
        m_drag.kind = DragKind::Pan;
        return;
    }
    if (event->button() != Qt::LeftButton)
        return;
    int c = m_editable && isLayerVisible(Layer::ControlNet) ? hit(m_net, pos) : -1;
    int s = m_editable ? hit(m_start3, pos) : -1;
    // Start vertices often sit next to net points (limit points at the corners): the handle
    // nearer to the mouse wins.
    if (c >= 0 && s >= 0) {
        const QPointF dc = controlPointScreen(c) - pos, ds = startVertexScreen(s) - pos;
        if (QPointF::dotProduct(ds, ds) < QPointF::dotProduct(dc, dc))
            c = -1;
        else
            s = -1;
    }
    // A marker under the press: a click (no drag) selects its vertex, also when a control point
    // lies under it too (its drag still moves the point).
    m_drag.marker = hitMarker(pos);
    if (c >= 0) {
        m_drag.kind = DragKind::ControlPoint;
        m_drag.index = c;
        m_selected = c;
        m_selectedEdge = {-1, -1};
        m_selectedFace = -1;
        m_drag.startWorld = m_drag.currentWorld = QVector3D(
            float(m_net(c, 0)), float(m_net(c, 1)), float(m_net(c, 2)));
        m_cameraSet = true; // the view must not refit under the user's hand
        startDragBase(c);
        emit controlPointPressed(c);
    } else if (s >= 0) {
        m_drag.kind = DragKind::StartVertex;
        m_drag.index = s;
        m_drag.startWorld = m_drag.currentWorld = QVector3D(
            float(m_start3(s, 0)), float(m_start3(s, 1)), float(m_start3(s, 2)));
        m_cameraSet = true;
        emit startVertexPressed(s);
    } else {
        m_drag.kind = DragKind::Orbit;
    }
    update();
}

void SurfaceView::mouseMoveEvent(QMouseEvent *event)
{
    logInput("move", event);
    const QPointF pos = event->position();
    const QPointF step = pos - m_drag.last;
    m_drag.last = pos;
    switch (m_drag.kind) {
    case DragKind::Orbit:
        orbit(step.x(), step.y());
        break;
    case DragKind::Pan:
        pan(step.x(), step.y());
        break;
    case DragKind::ControlPoint:
    case DragKind::StartVertex: {
        // In the view plane through the point's start: the depth stays as it was on press.
        m_drag.currentWorld = m_drag.startWorld + screenDelta(pos - m_drag.press,
                                                              m_drag.startWorld);
        if (m_drag.kind == DragKind::ControlPoint)
            emit controlPointDragged(m_drag.index, m_drag.currentWorld);
        else
            emit startVertexDragged(m_drag.index, m_drag.currentWorld);
        break;
    }
    case DragKind::None: {
        const bool over = (m_editable && hit(m_net, pos) >= 0) || hit(m_start3, pos) >= 0
                          || hitMarker(pos) >= 0;
        setViewCursor(over ? Qt::PointingHandCursor : Qt::ArrowCursor);
        break;
    }
    }
}

void SurfaceView::mouseReleaseEvent(QMouseEvent *event)
{
    logInput("release", event);
    const Drag drag = m_drag;
    // A net point's full base, moved at the release (startMeshJob), when only it moved.
    m_release = Release{};
    if (const auto delta = dragBaseMove(); delta && m_dragBase.full) {
        const Mat now = startCoefficients();
        const Mat &then = m_dragBase.coefficients;
        const bool exact = now.size() > 0 && now.rows() == then.rows()
                           && now.cols() == then.cols()
                           && (now - then).cwiseAbs().maxCoeff() < 1e-12;
        m_release = Release{m_dragBase.full, *delta, exact};
    }
    m_drag = Drag{};
    if (drag.kind == DragKind::ControlPoint || drag.kind == DragKind::StartVertex) {
        // Full detail after the drag's coarse meshes, started now on the mesh worker: the
        // owner's answer to the release (the end of the document's gesture, which brings every
        // dock up to date on this thread) then runs beside it instead of before it. The
        // gesture this drag made ends with it (setGestureActive(false) follows).
        m_externalGesture = false;
        dropDragBase();
        startMeshJob();
    }
    if (drag.kind == DragKind::ControlPoint)
        emit controlPointReleased(drag.index, drag.startWorld, drag.currentWorld);
    else if (drag.kind == DragKind::StartVertex)
        emit startVertexReleased(drag.index, drag.startWorld, drag.currentWorld);
    if (drag.kind == DragKind::Orbit || drag.kind == DragKind::Pan) {
        // The camera is where the user left it: full detail now, not after the settle time.
        m_settle.stop();
        m_moving = false;
    }
    const bool click = (drag.last - drag.press).manhattanLength() < 3;
    if (drag.kind == DragKind::Orbit && drag.last != drag.press)
        emit cameraTurned(m_camera.ortho.azimuth, m_camera.ortho.elevation);
    else if ((drag.kind == DragKind::Orbit || drag.kind == DragKind::ControlPoint) && click
             && drag.marker >= 0) {
        setSelectedMarker(drag.marker);
        emit markerClicked(drag.marker);
    } else if (drag.kind == DragKind::Orbit && click && m_editable
               && isLayerVisible(Layer::ControlNet)) {
        const auto [a, b] = hitEdge(drag.press);
        if (a >= 0) {
            setSelectedNetEdge(a, b);
            emit netEdgeClicked(a, b);
        } else if (const int f = hitFace(drag.press); f >= 0) {
            setSelectedNetFace(f);
            emit netFaceClicked(f);
        }
    }
    update();
    requestFrame();
}

void SurfaceView::wheelEvent(QWheelEvent *event)
{
    // 15 degrees of a wheel notch (120 units) zoom by 1.2.
    zoomBy(std::pow(1.2, event->angleDelta().y() / 120.0), event->position());
    event->accept();
}

void SurfaceView::keyPressEvent(QKeyEvent *event)
{
    switch (event->key()) {
    case Qt::Key_Home:
    case Qt::Key_R:
        resetCamera();
        break;
    case Qt::Key_P:
        setPerspective(!m_camera.perspective);
        break;
    case Qt::Key_Left:
    case Qt::Key_Right:
    case Qt::Key_Up:
    case Qt::Key_Down: {
        const int k = event->key();
        orbit(k == Qt::Key_Left ? -15 : k == Qt::Key_Right ? 15 : 0,
              k == Qt::Key_Up ? -15 : k == Qt::Key_Down ? 15 : 0);
        emit cameraTurned(m_camera.ortho.azimuth, m_camera.ortho.elevation);
        break;
    }
    default:
        QWidget::keyPressEvent(event);
    }
}

} // namespace awb
