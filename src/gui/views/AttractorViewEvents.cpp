// AttractorView: widget events: resize and show (refit, render), picking and dragging of
// handles, panning, wheel zoom, the context-menu click and the double click on a polygon edge
// (the owner inserts a point there), and the keyboard (fit, zoom, cancel and repeat the render).

#include "gui/views/AttractorView.h"

#include "gui/views/AttractorViewDetail.h"

#include "gui/views/FrameLog.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace awb {

using namespace attractor_view;

// ---- events -----------------------------------------------------------------------------------

void AttractorView::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    if (m_autoFit)
        fitToContents();
    scheduleRender();
}

void AttractorView::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    scheduleRender();
}

int AttractorView::hitControlPoint(const QPointF &screen) const
{
    if (!m_editControl || !isLayerVisible(Layer::ControlPolygon))
        return -1;
    int best = -1;
    double bestD = kHitRadius;
    for (int i = 0; i < int(m_control.size()); ++i) {
        const double d = QLineF(worldToScreen(controlPointPosition(i)), screen).length();
        if (d <= bestD) {
            bestD = d;
            best = i;
        }
    }
    return best;
}

int AttractorView::hitStartVertex(const QPointF &screen) const
{
    if (!m_editStart || !isLayerVisible(Layer::StartSet))
        return -1;
    int best = -1;
    double bestD = kHitRadius;
    for (int i = 0; i < int(m_startPlane.size()); ++i) {
        const double d = QLineF(worldToScreen(startVertexPosition(i)), screen).length();
        if (d <= bestD) {
            bestD = d;
            best = i;
        }
    }
    return best;
}

int AttractorView::controlEdgeAt(const QPointF &screen, QPointF *world) const
{
    if (!m_editControl || !isLayerVisible(Layer::ControlPolygon))
        return -1;
    int best = -1, first = 0;
    double bestD = kHitRadius;
    QPointF bestPoint;
    for (std::size_t k = 0; k < m_controlSets.size(); ++k) {
        const int n = m_controlSets[k];
        const bool closed = k < m_controlClosedSets.size() && m_controlClosedSets[k];
        for (int i = 0; i + 1 < n || (closed && n > 2 && i < n); ++i) {
            const int a = first + i, b = first + (i + 1) % n;
            const QPointF pa = worldToScreen(controlPointPosition(a));
            const QPointF pb = worldToScreen(controlPointPosition(b));
            const QPointF ab = pb - pa;
            const double len2 = QPointF::dotProduct(ab, ab);
            const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(screen - pa, ab) / len2,
                                                   0.0, 1.0)
                                      : 0.0;
            const QPointF q = pa + t * ab;
            const double d = QLineF(q, screen).length();
            if (d <= bestD) {
                bestD = d;
                best = a;
                bestPoint = q;
            }
        }
        first += n;
    }
    if (best >= 0 && world)
        *world = screenToWorld(bestPoint);
    return best;
}

void AttractorView::mousePressEvent(QMouseEvent *event)
{
    logInput("press", event);
    if (m_drag.kind != DragKind::None) {
        event->accept(); // a second button during a drag changes nothing
        return;
    }
    const QPointF pos = event->position();
    m_drag = Drag();
    m_clickPress.reset();
    m_drag.pressScreen = m_drag.lastScreen = pos;
    m_drag.pressWorld = screenToWorld(pos);
    if (event->button() == Qt::LeftButton) {
        // Control points win over start-set vertices: they are what a user edits most.
        if (const int i = hitControlPoint(pos); i >= 0) {
            m_drag.kind = DragKind::ControlPoint;
            m_drag.index = i;
            m_drag.startWorld = m_drag.currentWorld = m_control[i];
        } else if (const int j = hitStartVertex(pos); j >= 0) {
            m_drag.kind = DragKind::StartVertex;
            m_drag.index = j;
            m_drag.startWorld = m_drag.currentWorld = m_startPlane[j];
        }
        if (m_drag.kind != DragKind::None) {
            userMovedView(); // the content moves under the user's hand: no auto-fit now
            setCursor(Qt::ClosedHandCursor);
            if (m_drag.kind == DragKind::ControlPoint)
                emit controlPointPressed(m_drag.index);
            else
                emit startVertexPressed(m_drag.index);
            update();
        } else {
            m_clickPress = pos;
        }
    } else if (event->button() == Qt::MiddleButton || event->button() == Qt::RightButton) {
        m_drag.kind = DragKind::Pan;
        setCursor(Qt::SizeAllCursor);
    }
    event->accept();
}

void AttractorView::mouseMoveEvent(QMouseEvent *event)
{
    logInput("move", event);
    const QPointF pos = event->position();
    emit cursorMoved(screenToWorld(pos));
    switch (m_drag.kind) {
    case DragKind::None: {
        const int c = hitControlPoint(pos);
        const int s = c >= 0 ? -1 : hitStartVertex(pos);
        if (c != m_hoverControl || s != m_hoverStart) {
            m_hoverControl = c;
            m_hoverStart = s;
            setCursor(c >= 0 || s >= 0 ? Qt::OpenHandCursor : Qt::ArrowCursor);
            update();
        }
        break;
    }
    case DragKind::Pan: {
        const QPointF d = pos - m_drag.lastScreen;
        m_drag.lastScreen = pos;
        if (!d.isNull()) {
            userMovedView();
            setView(m_center - QPointF(d.x() / m_scale, -d.y() / m_scale), m_scale);
        }
        break;
    }
    case DragKind::ControlPoint:
    case DragKind::StartVertex: {
        // Move by the cursor's displacement: grabbing a handle off-centre does not make it jump.
        const QPointF w = m_drag.startWorld + (screenToWorld(pos) - m_drag.pressWorld);
        if (w == m_drag.currentWorld)
            break;
        m_drag.currentWorld = w;
        m_drag.lastScreen = pos;
        if (m_drag.kind == DragKind::ControlPoint)
            emit controlPointDragged(m_drag.index, w);
        else
            emit startVertexDragged(m_drag.index, w);
        update();
        break;
    }
    }
    event->accept();
}

void AttractorView::mouseReleaseEvent(QMouseEvent *event)
{
    logInput("release", event);
    const Drag d = m_drag;
    const bool ends = (d.kind == DragKind::Pan && (event->button() == Qt::MiddleButton
                                                   || event->button() == Qt::RightButton))
                      || ((d.kind == DragKind::ControlPoint || d.kind == DragKind::StartVertex)
                          && event->button() == Qt::LeftButton);
    if (!ends) {
        if (d.kind == DragKind::None && event->button() == Qt::LeftButton && m_clickPress
            && QLineF(*m_clickPress, event->position()).length() < kClickSlop)
            emit attractorClicked(screenToWorld(event->position()));
        m_clickPress.reset();
        event->accept();
        return;
    }
    m_drag = Drag();
    setCursor(Qt::ArrowCursor);
    // A right click that did not pan asks for the context menu.
    if (d.kind == DragKind::Pan && event->button() == Qt::RightButton
        && QLineF(d.pressScreen, event->position()).length() < kClickSlop) {
        emit contextMenuRequested(event->position(), event->globalPosition().toPoint());
        event->accept();
        return;
    }
    if (d.kind == DragKind::ControlPoint)
        emit controlPointReleased(d.index, d.startWorld, d.currentWorld);
    else if (d.kind == DragKind::StartVertex)
        emit startVertexReleased(d.index, d.startWorld, d.currentWorld);
    // The gesture is over: the full picture now, not after the pause of a gesture.
    if (!isInteractive())
        refineRender();
    update();
    event->accept();
}

void AttractorView::mouseDoubleClickEvent(QMouseEvent *event)
{
    QPointF world;
    const QPointF pos = event->position();
    if (event->button() == Qt::LeftButton && hitControlPoint(pos) < 0) {
        if (const int edge = controlEdgeAt(pos, &world); edge >= 0) {
            emit controlEdgeDoubleClicked(edge, world);
            event->accept();
            return;
        }
    }
    // Elsewhere a double click is two clicks (a handle is grabbed again, nothing else).
    mousePressEvent(event);
}

void AttractorView::wheelEvent(QWheelEvent *event)
{
    const double notches = event->angleDelta().y() / 120.0;
    if (notches == 0) {
        event->ignore();
        return;
    }
    userMovedView();
    m_wheelGesture.start(); // a burst of wheel events: interactive pictures until it pauses
    zoomBy(std::pow(1.2, notches), event->position());
    event->accept();
}

void AttractorView::keyPressEvent(QKeyEvent *event)
{
    switch (event->key()) {
    case Qt::Key_Home:
    case Qt::Key_F:
        fitToContents();
        break;
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        userMovedView();
        zoomIn();
        break;
    case Qt::Key_Minus:
        userMovedView();
        zoomOut();
        break;
    case Qt::Key_Escape:
        if (!isRendering()) {
            // Nothing to stop: let a parent (a dialog, the main window) have the key.
            QWidget::keyPressEvent(event);
            return;
        }
        cancelRender();
        break;
    case Qt::Key_F5:
        renderAgain();
        break;
    default:
        QWidget::keyPressEvent(event);
        return;
    }
    event->accept();
}

void AttractorView::logInput(const char *kind, const QMouseEvent *event) const
{
    if (!framelog::enabled())
        return;
    const QPoint g = event->globalPosition().toPoint();
    framelog::write("input", QStringLiteral("attractor %1 %2 %3")
                                 .arg(QLatin1String(kind)).arg(g.x()).arg(g.y()));
}

void AttractorView::leaveEvent(QEvent *event)
{
    QWidget::leaveEvent(event);
    if (m_hoverControl >= 0 || m_hoverStart >= 0) {
        m_hoverControl = m_hoverStart = -1;
        update();
    }
    emit cursorLeft();
}

} // namespace awb
