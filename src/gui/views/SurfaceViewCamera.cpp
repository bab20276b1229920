// SurfaceView: the camera -- one orthographic camera (the core's OrthoCamera) for both paths,
// with an optional perspective for GL -- its projection of world points to the screen, and the
// orbit, pan, zoom and framing the user asks for.

#include "gui/views/SurfaceView.h"

#include <Eigen/Geometry>
#include <QVector4D>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

constexpr double degree = M_PI / 180.0;

QVector3D vec(const Eigen::Vector3d &v)
{
    return QVector3D(float(v.x()), float(v.y()), float(v.z()));
}
Eigen::Vector3d vec(const QVector3D &v) { return {v.x(), v.y(), v.z()}; }

} // namespace

QMatrix4x4 SurfaceViewCamera::matrix(double aspect, double depthRange) const
{
    // lookAt from the core camera's own frame, so that the orthographic matrix maps a world
    // point exactly where SurfaceRaster::toScreen puts it (one camera, two renderers).
    const OrthoCamera &c = ortho;
    const QVector3D centre = vec(c.centre), toward = vec(c.toward()), up = vec(c.up());
    const double hh = std::max(c.halfHeight, 1e-12);
    const double range = std::max(depthRange, 1e-9);
    const double distance = perspective ? hh / std::tan(0.5 * fieldOfView * degree)
                                        : 2.0 * range + hh;
    QMatrix4x4 view;
    view.lookAt(centre + toward * float(distance), centre, up);
    QMatrix4x4 projection;
    const double nearPlane = std::max(distance - 1.5 * range, distance * 0.01);
    const double farPlane = distance + 1.5 * range;
    if (perspective)
        projection.perspective(float(fieldOfView), float(aspect), float(nearPlane),
                               float(farPlane));
    else
        projection.ortho(float(-hh * aspect), float(hh * aspect), float(-hh), float(hh),
                         float(nearPlane), float(farPlane));
    return projection * view;
}

// ---- camera --------------------------------------------------------------------------------

double SurfaceView::depthRange() const
{
    const Mat b = sceneBounds();
    if (b.rows() != 2)
        return 1.0;
    const Eigen::Vector3d lo = b.row(0).transpose(), hi = b.row(1).transpose();
    return 0.5 * (hi - lo).norm() + (0.5 * (lo + hi) - m_camera.ortho.centre).norm() + 1e-9;
}

QMatrix4x4 SurfaceView::viewMatrix(QSizeF size) const
{
    // The CPU renderer is orthographic only: without GL the overlays (and picking) follow it,
    // so that the net stays on the surface it controls.
    SurfaceViewCamera camera = m_camera;
    camera.perspective = camera.perspective && m_useGl;
    return camera.matrix(size.width() / std::max(1.0, size.height()), depthRange());
}

QPointF SurfaceView::project(const QMatrix4x4 &mvp, const QRectF &target,
                             const QVector3D &w) const
{
    const QVector4D c = mvp * QVector4D(w, 1.0f);
    if (c.w() <= 0)
        return {qQNaN(), qQNaN()};
    const double x = c.x() / c.w(), y = c.y() / c.w();
    return {target.left() + 0.5 * (x + 1.0) * target.width(),
            target.top() + 0.5 * (1.0 - y) * target.height()};
}

QPointF SurfaceView::toScreen(const QVector3D &world) const
{
    return project(viewMatrix(QSizeF(size())), QRectF(rect()), world);
}

QVector3D SurfaceView::screenDelta(const QPointF &delta, const QVector3D &at) const
{
    // World units per pixel at the depth of `at`: constant for the orthographic camera, the
    // distance to the eye times the field of view for the perspective one.
    const OrthoCamera &c = m_camera.ortho;
    double halfHeight = c.halfHeight;
    if (m_camera.perspective && m_useGl) {
        const double t = std::tan(0.5 * m_camera.fieldOfView * degree);
        const double distance = c.halfHeight / t - (vec(at) - c.centre).dot(c.toward());
        halfHeight = std::max(distance, 1e-9) * t;
    }
    const double unitsPerPixel = 2.0 * halfHeight / std::max(1, height());
    return vec(unitsPerPixel * (delta.x() * c.right() - delta.y() * c.up()));
}

QPointF SurfaceView::controlPointScreen(int i) const
{
    if (i < 0 || i >= m_net.rows())
        return {};
    return toScreen(vec(Eigen::Vector3d(m_net.row(i).transpose())));
}

QPointF SurfaceView::startVertexScreen(int i) const
{
    if (i < 0 || i >= m_start3.rows())
        return {};
    return toScreen(vec(Eigen::Vector3d(m_start3.row(i).transpose())));
}

bool SurfaceView::markerFacing(int i) const
{
    if (i < 0 || i >= markerCount())
        return false;
    const Marker &m = m_markers[std::size_t(i)];
    if (m.normal.isNull())
        return true;
    // Toward the eye: the view direction (orthographic), or from the point to the eye.
    const OrthoCamera &c = m_camera.ortho;
    Eigen::Vector3d toward = c.toward();
    if (m_camera.perspective && m_useGl) {
        const double t = std::tan(0.5 * m_camera.fieldOfView * degree);
        const Eigen::Vector3d eye = c.centre + c.toward() * (c.halfHeight / t);
        toward = (eye - vec(m.at)).normalized();
    }
    // A little past the silhouette still counts as seen: the marker sits on the rim.
    return vec(m.normal).dot(toward) > -0.05;
}

QPointF SurfaceView::markerScreen(int i) const
{
    if (i < 0 || i >= markerCount())
        return {};
    return toScreen(m_markers[std::size_t(i)].at);
}

Mat SurfaceView::sceneBounds() const
{
    std::vector<const Mat *> sets{&m_net, &m_start3, &m_refined};
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(qInf()), hi = -lo;
    for (const Mat *m : sets)
        for (Eigen::Index r = 0; r < m->rows(); ++r) {
            lo = lo.cwiseMin(m->row(r).transpose());
            hi = hi.cwiseMax(m->row(r).transpose());
        }
    if (!lo.allFinite() || !hi.allFinite())
        return {};
    Mat b(2, 3);
    b.row(0) = lo.transpose();
    b.row(1) = hi.transpose();
    return b;
}

void SurfaceView::setCamera(const SurfaceViewCamera &camera)
{
    m_camera = camera;
    m_cameraSet = true;
    cameraMoved();
}

void SurfaceView::setPerspective(bool on)
{
    m_camera.perspective = on;
    cameraMoved();
}

void SurfaceView::setHomeDirection(double azimuth, double elevation)
{
    if (azimuth == m_homeAzimuth && elevation == m_homeElevation)
        return;
    m_homeAzimuth = azimuth;
    m_homeElevation = elevation;
    // The document took the direction the user turned the view to (cameraTurned): the view
    // keeps its zoom and pan. Another direction (typed in Properties, undone) turns the view.
    const OrthoCamera &c = m_camera.ortho;
    if (std::abs(c.azimuth - azimuth) < 1e-9 && std::abs(c.elevation - elevation) < 1e-9)
        return;
    if (m_net.rows() > 0)
        resetCamera();
}

void SurfaceView::resetCamera()
{
    const Mat b = sceneBounds();
    const double aspect = double(std::max(1, width())) / std::max(1, height());
    // The net frames the picture (the surface lies in its convex hull); a start set far off
    // would only shrink it. Without a net: the 8 corners of the scene's box.
    Mat corners(8, 3);
    if (b.rows() == 2)
        for (int k = 0; k < 8; ++k)
            for (int j = 0; j < 3; ++j)
                corners(k, j) = b((k >> j) & 1, j);
    const bool perspective = m_camera.perspective;
    // From above at 40 degrees: a patch z = f(x, y) and the holes of a subset of maps
    // (000 Fig. 9) both show.
    m_camera.ortho = OrthoCamera::fit(m_net.rows() > 0 ? m_net
                                                       : b.rows() == 2 ? corners : Mat(),
                                      m_homeAzimuth, m_homeElevation, aspect, 0.05);
    m_camera.perspective = perspective;
    m_cameraSet = false;
    m_moving = false;
    requestFrame();
    update();
    emit cameraChanged();
}

void SurfaceView::cameraMoved()
{
    // Coarse while moving, full detail once the camera rests for a moment.
    m_moving = true;
    m_settle.start();
    requestFrame();
    update();
    emit cameraChanged();
}

void SurfaceView::orbit(double dx, double dy)
{
    // Turntable orbit: the z axis stays up on screen, which keeps a surface z = f(x, y)
    // readable; 0.4 degree a pixel turns half around across a typical view.
    OrthoCamera &c = m_camera.ortho;
    // Azimuth in (-180, 180], as the Properties dock shows it.
    c.azimuth = std::remainder(c.azimuth - 0.4 * dx, 360.0);
    if (c.azimuth <= -180.0)
        c.azimuth += 360.0;
    c.elevation = std::clamp(c.elevation + 0.4 * dy, -89.0, 89.0);
    m_cameraSet = true;
    cameraMoved();
}

void SurfaceView::pan(double dx, double dy)
{
    m_camera.ortho.centre -= vec(screenDelta(QPointF(dx, dy), vec(m_camera.ortho.centre)));
    m_cameraSet = true;
    cameraMoved();
}

void SurfaceView::zoomBy(double factor, std::optional<QPointF> anchor)
{
    factor = std::clamp(factor, 1e-3, 1e3);
    if (anchor) {
        // The point under the anchor (at the depth of the centre) stays under it.
        const QPointF offset = *anchor - QRectF(rect()).center();
        m_camera.ortho.centre += (1.0 - 1.0 / factor)
                                 * vec(screenDelta(offset, vec(m_camera.ortho.centre)));
    }
    m_camera.ortho.halfHeight /= factor;
    m_cameraSet = true;
    cameraMoved();
}

} // namespace awb
