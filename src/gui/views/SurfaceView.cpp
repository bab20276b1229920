#include "gui/views/SurfaceView.h"

#include "gui/views/SurfaceGLWidget.h"

#include <Eigen/Geometry>

#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QPainter>
#include <QPainterPath>
#include <QVector4D>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <random>
#include <thread>

namespace awb {

// Runs only the latest posted job on one thread; posting cancels the running one (its cancel
// flag goes up), so a burst of edits never queues stale work. The destructor waits for it.
class LatestJobWorker {
public:
    using Job = std::function<void(const std::atomic<bool> &cancel)>;
    LatestJobWorker() : m_thread([this] { loop(); }) {}
    ~LatestJobWorker()
    {
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
            m_cancel = true;
        }
        m_wake.notify_all();
        m_thread.join();
    }
    void post(Job job)
    {
        {
            std::lock_guard lock(m_mutex);
            m_pending = std::move(job);
            m_cancel = true;
        }
        m_wake.notify_one();
    }

private:
    void loop()
    {
        for (;;) {
            Job job;
            {
                std::unique_lock lock(m_mutex);
                m_wake.wait(lock, [this] { return m_stop || bool(m_pending); });
                if (m_stop)
                    return;
                job = std::move(m_pending);
                m_pending = nullptr;
                m_cancel = false;
            }
            job(m_cancel);
        }
    }

    std::mutex m_mutex;
    std::condition_variable m_wake;
    Job m_pending;
    bool m_stop = false;
    std::atomic<bool> m_cancel{false};
    std::thread m_thread;
};

namespace {

constexpr double degree = M_PI / 180.0;
constexpr double handleRadius = 4.5;
constexpr double hitRadius = 9.0;
// CPU frames: start-set images at most (a filled triangle each) while the camera moves, when
// it rests, and for a printed figure.
constexpr std::size_t cpuMovingImages = 8000;
constexpr std::size_t cpuImages = 120000;
constexpr std::size_t printImages = 400000;

QVector3D vec(const Eigen::Vector3d &v)
{
    return QVector3D(float(v.x()), float(v.y()), float(v.z()));
}
Eigen::Vector3d vec(const QVector3D &v) { return {v.x(), v.y(), v.z()}; }

// The deepest level (at most `depth`) whose images, `perImage` points each, fit the budget:
// the work of F^k grows as N^k, so the budget, not the item's depth, bounds a frame's cost.
int depthWithin(const Ifs &ifs, int depth, double perImage, double budget)
{
    int k = std::max(0, depth);
    while (k > 0 && imageCount(ifs, k) * perImage > budget)
        --k;
    return k;
}

// Collects one point per start-set image: the centroid of a triangle image with its normal
// (the cross product of two edges: exact for an affine image of a flat start set), or every
// vertex of a point start set (no normal).
class CloudSink : public AttractorSink {
public:
    CloudSink(const std::vector<Projection> &views, std::function<std::uint32_t(
                  const std::uint8_t *, int)> colour)
        : m_views(views), m_colour(std::move(colour))
    {
    }
    void consume(const Mat &v, StartSet::Kind kind, const std::uint8_t *a, int n) override
    {
        const std::uint32_t c = m_colour(a, n);
        for (const Projection &view : m_views) {
            const Mat p = project(view, v);
            if (p.cols() != 3 || !p.allFinite())
                continue;
            if (kind == StartSet::Kind::Points || p.rows() < 3) {
                for (Eigen::Index r = 0; r < p.rows(); ++r)
                    add(p.row(r).transpose(), Eigen::Vector3d::Zero(), c);
                continue;
            }
            // The fan's summed cross products: twice the (flat) polygon's area along its
            // normal, for a triangle and for a polygon start set alike.
            const Eigen::Vector3d p0 = p.row(0).transpose();
            Eigen::Vector3d normal = Eigen::Vector3d::Zero();
            for (Eigen::Index r = 1; r + 1 < p.rows(); ++r) {
                const Eigen::Vector3d a = p.row(r).transpose() - p0;
                const Eigen::Vector3d b = p.row(r + 1).transpose() - p0;
                normal += a.cross(b);
            }
            const double len = normal.norm();
            cloud.area += 0.5 * len;
            normal = len > 0 ? Eigen::Vector3d(normal / len) : Eigen::Vector3d::Zero();
            add(p.colwise().mean().transpose(), normal, c);
        }
    }
    SurfaceCloud cloud;

private:
    void add(const Eigen::Vector3d &x, const Eigen::Vector3d &n, std::uint32_t c)
    {
        for (int k = 0; k < 3; ++k) {
            cloud.positions.push_back(float(x[k]));
            cloud.normals.push_back(float(n[k]));
        }
        cloud.colours.push_back(c);
    }
    const std::vector<Projection> &m_views;
    std::function<std::uint32_t(const std::uint8_t *, int)> m_colour;
};

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

SurfaceView::SurfaceView(QWidget *parent, bool allowGl)
    : QWidget(parent), m_worker(std::make_unique<LatestJobWorker>()),
      m_cloud(std::make_shared<SurfaceCloud>())
{
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setAutoFillBackground(false);
    if (allowGl && glAvailable())
        m_gl = new SurfaceGLWidget(this);
    m_settle.setSingleShot(true);
    m_settle.setInterval(250);
    connect(&m_settle, &QTimer::timeout, this, [this] {
        m_moving = false;
        if (m_gl)
            m_gl->update();
        else
            requestCpuFrame();
    });
    m_dataTimer.setSingleShot(true);
    m_dataTimer.setInterval(0);
    connect(&m_dataTimer, &QTimer::timeout, this, &SurfaceView::startJob);
}

SurfaceView::~SurfaceView()
{
    // Joins the worker before the members its job reads go away.
    m_worker.reset();
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

// ---- data ----------------------------------------------------------------------------------

void SurfaceView::setIfs(std::shared_ptr<const Ifs> ifs, const StartSet &start,
                         std::vector<int> colourIndex)
{
    m_ifs = std::move(ifs);
    m_start = start;
    m_colourIndex = std::move(colourIndex);
    dataChanged();
}

void SurfaceView::setControlNet(const Mat &points, const std::vector<std::vector<int>> &faces)
{
    m_net = points.cols() == 3 ? points : Mat();
    m_netFaces = faces;
    if (m_selected >= m_net.rows())
        m_selected = -1;
    update();
    if (m_gl)
        m_gl->update();
}

void SurfaceView::setStartVertices(const Mat &points)
{
    m_start3 = points.cols() == 3 ? points : Mat();
    update();
    if (m_gl)
        m_gl->update();
}

void SurfaceView::setMesh(const Mat &points, const std::vector<std::vector<int>> &faces)
{
    m_mesh = points.cols() == 3 ? points : Mat();
    m_meshFaces = faces;
    update();
    if (m_gl)
        m_gl->update();
}

void SurfaceView::setRenderSettings(const RenderSettings &settings)
{
    const bool same = settings.depth == m_settings.depth
                      && settings.colouring == m_settings.colouring;
    m_settings = settings;
    if (!same)
        dataChanged();
    else if (m_gl)
        m_gl->update();
    else
        requestCpuFrame();
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
    if (m_gl)
        m_gl->update();
    else if (layer == Layer::Attractor)
        requestCpuFrame();
}

bool SurfaceView::isLayerVisible(Layer layer) const { return !(m_hidden & (1u << int(layer))); }

void SurfaceView::setPointBudget(std::size_t full, std::size_t moving)
{
    m_budget = std::max<std::size_t>(1, full);
    m_movingBudget = std::max<std::size_t>(1, moving);
    dataChanged();
}

void SurfaceView::dataChanged()
{
    if (!m_cameraSet && m_net.rows() > 0)
        resetCamera();
    m_dataTimer.start();
}

std::vector<std::uint32_t> SurfaceView::paletteArgb(int maps) const
{
    std::vector<std::uint32_t> out;
    const QList<QColor> &palette = m_settings.colouring.palette;
    if (m_settings.colouring.mode == AttractorColorMode::Single) {
        const QColor c = palette.isEmpty() ? QColor(70, 110, 160) : palette.front();
        return {std::uint32_t(c.rgb()) & 0xffffffu};
    }
    const int n = palette.isEmpty() ? std::max(maps, 9) : int(palette.size());
    for (int i = 0; i < n; ++i) {
        const QColor c = palette.isEmpty() ? AttractorRenderer::mapColor(i) : palette[i];
        out.push_back(std::uint32_t(c.rgb()) & 0xffffffu);
    }
    return out;
}

std::vector<int> SurfaceView::rasterLabels() const
{
    // SurfaceRaster colours by the outermost map: map k of the IFS gets its analysis map's
    // colour, so switching maps off does not repaint the others.
    std::vector<int> labels;
    const int n = m_ifs ? m_ifs->size() : 0;
    for (int k = 0; k < n; ++k) {
        if (m_settings.colouring.mode == AttractorColorMode::Single)
            labels.push_back(0);
        else
            labels.push_back(k < int(m_colourIndex.size()) ? m_colourIndex[std::size_t(k)] : k);
    }
    return labels;
}

void SurfaceView::startJob()
{
    const std::uint64_t serial = ++m_serial;
    if (!m_ifs || m_ifs->size() == 0 || m_start.vertices.rows() == 0) {
        m_cloud = std::make_shared<SurfaceCloud>();
        m_cpuImage = QImage();
        m_busy = false;
        if (m_gl)
            m_gl->cloudChanged();
        update();
        return;
    }
    if (!m_gl) {
        requestCpuFrame();
        return;
    }
    m_busy = true;
    const bool dragging = m_drag.kind == DragKind::ControlPoint
                          || m_drag.kind == DragKind::StartVertex || m_externalGesture;
    const double budget = double(dragging ? m_movingBudget : m_budget);
    auto ifs = m_ifs;
    const StartSet start = m_start;
    const RenderSettings settings = m_settings;
    const std::vector<int> colourIndex = m_colourIndex;
    const int maps = ifs->size();
    const std::vector<std::uint32_t> palette = paletteArgb(maps);
    m_worker->post([this, serial, ifs, start, settings, colourIndex, maps, palette,
                    budget](const std::atomic<bool> &cancel) {
        auto cloud = std::make_shared<SurfaceCloud>();
        QElapsedTimer timer;
        timer.start();
        try {
            const double perImage =
                start.kind == StartSet::Kind::Points ? double(start.vertices.rows()) : 1.0;
            cloud->depth = depthWithin(*ifs, settings.depth, perImage, budget);
            const auto colour = [&](const std::uint8_t *a, int n) -> std::uint32_t {
                if (settings.colouring.mode == AttractorColorMode::ByMap) {
                    const int k = n > 0 ? a[0] : 0;
                    const int c = k < int(colourIndex.size()) ? colourIndex[std::size_t(k)] : k;
                    return palette[std::size_t(c) % palette.size()];
                }
                if (settings.colouring.mode == AttractorColorMode::Single)
                    return palette.front();
                return AttractorRenderer::addressColor(settings.colouring, maps, a, n).rgb();
            };
            CloudSink a(ifs->views, colour), b(ifs->views, colour);
            IterationControl control;
            control.cancel = &cancel;
            iterateParallel(*ifs, start, cloud->depth, {&a, &b}, control);
            if (cancel)
                return;
            const double area = a.cloud.area + b.cloud.area;
            *cloud = std::move(a.cloud);
            cloud->area = area;
            cloud->positions.insert(cloud->positions.end(), b.cloud.positions.begin(),
                                    b.cloud.positions.end());
            cloud->normals.insert(cloud->normals.end(), b.cloud.normals.begin(),
                                  b.cloud.normals.end());
            cloud->colours.insert(cloud->colours.end(), b.cloud.colours.begin(),
                                  b.cloud.colours.end());
            cloud->depth = depthWithin(*ifs, settings.depth, perImage, budget);
            // A fixed shuffle: any prefix is an even sample (decimation while moving), and
            // equal data give equal frames.
            std::mt19937 random(12345);
            for (std::size_t i = cloud->size(); i > 1; --i) {
                const std::size_t j = std::uniform_int_distribution<std::size_t>(0, i - 1)(random);
                std::swap(cloud->colours[i - 1], cloud->colours[j]);
                for (int k = 0; k < 3; ++k) {
                    std::swap(cloud->positions[3 * (i - 1) + k], cloud->positions[3 * j + k]);
                    std::swap(cloud->normals[3 * (i - 1) + k], cloud->normals[3 * j + k]);
                }
            }
        } catch (const std::exception &) {
            cloud = std::make_shared<SurfaceCloud>();
        }
        cloud->seconds = double(timer.nsecsElapsed()) / 1e9;
        QMetaObject::invokeMethod(this, [this, serial, cloud] {
            if (serial != m_serial)
                return;
            m_cloud = cloud;
            m_busy = false;
            if (m_gl)
                m_gl->cloudChanged();
            emit frameReady();
        }, Qt::QueuedConnection);
    });
}

double SurfaceView::splatSize(std::size_t points, double dpr) const
{
    // n points covering area A lie about sqrt(A / n) apart; at ppu pixels a unit, a splat of
    // 1.5 spacings closes the surface without blurring it much.
    const double ppu = dpr * height() / (2.0 * std::max(m_camera.ortho.halfHeight, 1e-12));
    const double spacing = points > 0 ? ppu * std::sqrt(m_cloud->area / double(points)) : 0.0;
    return std::clamp(std::max(m_settings.pointSize * dpr, 1.5 * spacing), 1.0, 24.0 * dpr);
}

// ---- CPU path ------------------------------------------------------------------------------

QImage SurfaceView::cpuRaster(QSize size, const OrthoCamera &camera, std::size_t budget,
                              const std::atomic<bool> *cancel) const
{
    if (!m_ifs || m_ifs->size() == 0 || m_start.vertices.rows() == 0 || size.isEmpty())
        return {};
    const double perImage =
        m_start.kind == StartSet::Kind::Points ? double(m_start.vertices.rows()) : 1.0;
    const int depth = depthWithin(*m_ifs, m_settings.depth, perImage, double(budget));
    const double radius = std::max(0.5, 0.5 * m_settings.pointSize
                                            * (double(size.height()) / std::max(1, height())));
    const std::vector<int> labels = rasterLabels();
    SurfaceRaster a(size.width(), size.height(), camera, m_ifs->views, labels, radius);
    SurfaceRaster b(size.width(), size.height(), camera, m_ifs->views, labels, radius);
    IterationControl control;
    control.cancel = cancel;
    iterateParallel(*m_ifs, m_start, depth, {&a, &b}, control);
    if (cancel && *cancel)
        return {};
    a.merge(b);
    const std::vector<std::uint32_t> pixels = a.shade(paletteArgb(m_ifs->size()));
    QImage image(size, QImage::Format_ARGB32);
    for (int y = 0; y < size.height(); ++y)
        std::copy_n(pixels.begin() + std::ptrdiff_t(y) * size.width(), size.width(),
                    reinterpret_cast<std::uint32_t *>(image.scanLine(y)));
    return image;
}

void SurfaceView::requestCpuFrame()
{
    if (m_gl)
        return;
    const std::uint64_t serial = ++m_serial;
    if (!m_ifs || !isLayerVisible(Layer::Attractor)) {
        m_cpuImage = QImage();
        m_busy = false;
        update();
        return;
    }
    m_busy = true;
    const QSize size = this->size().expandedTo(QSize(16, 16));
    const OrthoCamera camera = m_camera.ortho;
    const std::size_t budget = m_moving || m_drag.kind == DragKind::ControlPoint
                                       || m_drag.kind == DragKind::StartVertex
                                   ? cpuMovingImages : std::min(cpuImages, m_budget);
    // The job gets copies: the GUI thread may change the view's data meanwhile.
    auto ifs = m_ifs;
    const StartSet start = m_start;
    const RenderSettings settings = m_settings;
    const std::vector<int> labels = rasterLabels();
    const std::vector<std::uint32_t> palette = paletteArgb(ifs->size());
    m_worker->post([this, serial, ifs, start, settings, labels, palette, size, camera,
                    budget](const std::atomic<bool> &cancel) {
        QImage image;
        try {
            const double perImage =
                start.kind == StartSet::Kind::Points ? double(start.vertices.rows()) : 1.0;
            const int depth = depthWithin(*ifs, settings.depth, perImage, double(budget));
            const double radius = std::max(0.5, 0.5 * settings.pointSize);
            SurfaceRaster a(size.width(), size.height(), camera, ifs->views, labels, radius);
            SurfaceRaster b(size.width(), size.height(), camera, ifs->views, labels, radius);
            IterationControl control;
            control.cancel = &cancel;
            iterateParallel(*ifs, start, depth, {&a, &b}, control);
            if (cancel)
                return;
            a.merge(b);
            const std::vector<std::uint32_t> pixels = a.shade(palette);
            image = QImage(size, QImage::Format_ARGB32);
            for (int y = 0; y < size.height(); ++y)
                std::copy_n(pixels.begin() + std::ptrdiff_t(y) * size.width(), size.width(),
                            reinterpret_cast<std::uint32_t *>(image.scanLine(y)));
        } catch (const std::exception &) {
            image = QImage();
        }
        QMetaObject::invokeMethod(this, [this, serial, image, camera] {
            if (serial != m_serial)
                return;
            m_cpuImage = image;
            m_cpuImageCamera = camera;
            m_busy = false;
            update();
            emit frameReady();
        }, Qt::QueuedConnection);
    });
}

QImage SurfaceView::renderImage(QSize size, bool overlays) const
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    if (overlays) {
        renderTo(&p, QRectF(QPointF(0, 0), QSizeF(size)));
    } else {
        OrthoCamera camera = m_camera.ortho;
        const double aspectView = double(std::max(1, width())) / std::max(1, height());
        const double aspect = double(size.width()) / std::max(1, size.height());
        if (aspect < aspectView)
            camera.halfHeight *= aspectView / aspect;
        const QImage raster = cpuRaster(size, camera, printImages, nullptr);
        if (!raster.isNull())
            p.drawImage(0, 0, raster);
    }
    return image;
}

void SurfaceView::renderTo(QPainter *painter, const QRectF &target) const
{
    // Keep what the screen shows across the width when the figure is narrower than the view.
    SurfaceView *self = const_cast<SurfaceView *>(this);
    const SurfaceViewCamera saved = m_camera;
    const double aspectView = double(std::max(1, width())) / std::max(1, height());
    const double aspect = target.width() / std::max(1.0, target.height());
    if (aspect < aspectView)
        self->m_camera.ortho.halfHeight *= aspectView / aspect;
    // Device pixels of the target, capped: a printer page at 1200 dpi needs no 10k raster.
    const QTransform t = painter->deviceTransform();
    const QRectF device = t.mapRect(target);
    double k = std::min(1.0, 2400.0 / std::max(1.0, device.width()));
    QSize pixels = (device.size() * k).toSize().expandedTo(QSize(1, 1));
    if (isLayerVisible(Layer::Attractor)) {
        const QImage raster = cpuRaster(pixels, m_camera.ortho, printImages, nullptr);
        if (!raster.isNull())
            painter->drawImage(target, raster);
    }
    // The overlays as vectors, through the same (orthographic) camera.
    SurfaceViewCamera ortho = m_camera;
    ortho.perspective = false;
    self->m_camera = ortho;
    const QMatrix4x4 mvp = viewMatrix(target.size());
    const double unit = std::max(1.0, target.height() / std::max(1, height()));
    painter->save();
    painter->setClipRect(target);
    paintOverlay(*painter, mvp, target, unit);
    painter->restore();
    self->m_camera = saved;
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
    camera.perspective = camera.perspective && m_gl;
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
    if (m_camera.perspective && m_gl) {
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

Mat SurfaceView::sceneBounds() const
{
    std::vector<const Mat *> sets{&m_net, &m_start3, &m_mesh};
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
    if (m_gl)
        m_gl->update();
    else
        requestCpuFrame();
    update();
    emit cameraChanged();
}

void SurfaceView::cameraMoved()
{
    // Coarse while moving, full detail once the camera rests for a moment.
    m_moving = true;
    m_settle.start();
    if (m_gl)
        m_gl->update();
    else
        requestCpuFrame();
    update();
    emit cameraChanged();
}

void SurfaceView::orbit(double dx, double dy)
{
    // Turntable orbit: the z axis stays up on screen, which keeps a surface z = f(x, y)
    // readable; 0.4 degree a pixel turns half around across a typical view.
    OrthoCamera &c = m_camera.ortho;
    c.azimuth = std::fmod(c.azimuth - 0.4 * dx, 360.0);
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

void SurfaceView::zoomBy(double factor)
{
    m_camera.ortho.halfHeight /= std::clamp(factor, 1e-3, 1e3);
    m_cameraSet = true;
    cameraMoved();
}

// ---- painting ------------------------------------------------------------------------------

void SurfaceView::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    if (m_gl)
        m_gl->setGeometry(rect());
    if (!m_cameraSet && m_net.rows() > 0)
        resetCamera();
    else if (!m_gl)
        requestCpuFrame();
}

void SurfaceView::paintEvent(QPaintEvent *)
{
    if (m_gl)
        return; // the GL child covers the view and paints the overlays itself
    QPainter p(this);
    p.fillRect(rect(), Qt::white);
    p.setRenderHint(QPainter::Antialiasing);
    if (!m_cpuImage.isNull() && isLayerVisible(Layer::Attractor)) {
        // A frame of another camera (the next one is on its way): scale it about the centre
        // so that zooming looks continuous; rotation just waits for the next frame.
        const double k = m_cpuImageCamera.halfHeight / std::max(m_camera.ortho.halfHeight, 1e-12);
        QRectF r(QPointF(0, 0), QSizeF(m_cpuImage.size()) * k);
        r.moveCenter(QRectF(rect()).center());
        p.drawImage(r, m_cpuImage);
    }
    paintOverlay(p, viewMatrix(QSizeF(size())), QRectF(rect()), 1.0);
    p.setPen(QColor(110, 110, 110));
    p.drawText(QRectF(rect()).adjusted(6, 4, -6, -4), Qt::AlignRight | Qt::AlignBottom,
               m_busy ? tr("Drawing… (CPU renderer)") : tr("CPU renderer"));
}

void SurfaceView::paintOverlay(QPainter &p, const QMatrix4x4 &mvp, const QRectF &target,
                               double unit) const
{
    const auto at = [&](const Mat &m, int r) {
        return project(mvp, target, QVector3D(float(m(r, 0)), float(m(r, 1)), float(m(r, 2))));
    };
    const auto faces = [&](const Mat &points, const std::vector<std::vector<int>> &list,
                           const QPen &pen) {
        // Each edge once: shared edges drawn twice look heavier where antialiased.
        QPainterPath path;
        for (const auto &f : list)
            for (std::size_t k = 0; k < f.size(); ++k) {
                const int i = f[k], j = f[(k + 1) % f.size()];
                if (i > j && f.size() > 1)
                    continue;
                if (i < 0 || j < 0 || i >= points.rows() || j >= points.rows())
                    continue;
                path.moveTo(at(points, i));
                path.lineTo(at(points, j));
            }
        // Edges with i > j that have no partner (the border) must still be drawn.
        for (const auto &f : list)
            for (std::size_t k = 0; k < f.size(); ++k) {
                const int i = f[k], j = f[(k + 1) % f.size()];
                if (i <= j || i >= points.rows() || j < 0)
                    continue;
                bool shared = false;
                for (const auto &g : list)
                    for (std::size_t l = 0; l < g.size() && !shared; ++l)
                        shared = g[l] == j && g[(l + 1) % g.size()] == i;
                if (!shared) {
                    path.moveTo(at(points, i));
                    path.lineTo(at(points, j));
                }
            }
        p.setPen(pen);
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
    };
    const Mat b = sceneBounds();
    if (b.rows() == 2 && (isLayerVisible(Layer::Box) || isLayerVisible(Layer::Axes))) {
        Mat corners(8, 3);
        for (int k = 0; k < 8; ++k)
            for (int j = 0; j < 3; ++j)
                corners(k, j) = b((k >> j) & 1, j);
        if (isLayerVisible(Layer::Box)) {
            p.setPen(QPen(QColor(190, 190, 190), unit, Qt::DashLine));
            for (int k = 0; k < 8; ++k)
                for (int j = 0; j < 3; ++j)
                    if (!((k >> j) & 1))
                        p.drawLine(at(corners, k), at(corners, k | (1 << j)));
        }
        if (isLayerVisible(Layer::Axes)) {
            const QColor colours[] = {QColor(200, 40, 40), QColor(40, 150, 40),
                                      QColor(40, 70, 200)};
            const QString names[] = {tr("x"), tr("y"), tr("z")};
            // Fonts set in pixels (a printer's) have no point size: scale what is set.
            // The widget's text size in screen pixels times `unit`, whatever the painter's
            // device: a printed figure's labels look as on screen.
            QFont font = this->font();
            font.setPixelSize(std::max(1, int(std::lround(0.9 * QFontInfo(this->font())
                                                                      .pixelSize() * unit))));
            p.setFont(font);
            for (int j = 0; j < 3; ++j) {
                const QPointF o = at(corners, 0), e = at(corners, 1 << j);
                p.setPen(QPen(colours[j], 1.6 * unit));
                p.drawLine(o, e);
                p.drawText(e + QPointF(4, -4) * unit, names[j]);
            }
        }
    }
    if (isLayerVisible(Layer::Mesh) && m_mesh.rows() > 0)
        faces(m_mesh, m_meshFaces, QPen(QColor(120, 120, 120, 150), 0.8 * unit));
    if (isLayerVisible(Layer::ControlNet) && m_net.rows() > 0) {
        faces(m_net, m_netFaces, QPen(QColor(40, 40, 40, 200), 1.2 * unit));
        p.setPen(QPen(QColor(30, 30, 30), 1.2 * unit));
        for (int i = 0; i < m_net.rows(); ++i) {
            const bool active = (m_drag.kind == DragKind::ControlPoint && m_drag.index == i)
                                || m_selected == i;
            p.setBrush(active ? QColor(230, 80, 40) : QColor(255, 255, 255));
            p.drawEllipse(at(m_net, i), handleRadius * unit, handleRadius * unit);
        }
    }
    if (m_start3.rows() > 0) {
        p.setPen(QPen(QColor(200, 110, 0), 1.2 * unit));
        p.setBrush(QColor(255, 200, 120));
        for (int i = 0; i < m_start3.rows(); ++i) {
            const QPointF c = at(m_start3, i);
            const double r = 0.8 * handleRadius * unit;
            p.drawRect(QRectF(c - QPointF(r, r), c + QPointF(r, r)));
        }
    }
}

// ---- input ---------------------------------------------------------------------------------

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

void SurfaceView::mousePressEvent(QMouseEvent *event)
{
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
    if (c >= 0) {
        m_drag.kind = DragKind::ControlPoint;
        m_drag.index = c;
        m_selected = c;
        m_drag.startWorld = m_drag.currentWorld = QVector3D(
            float(m_net(c, 0)), float(m_net(c, 1)), float(m_net(c, 2)));
        m_cameraSet = true; // the view must not refit under the user's hand
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
        const bool over = (m_editable && hit(m_net, pos) >= 0) || hit(m_start3, pos) >= 0;
        setCursor(over ? Qt::PointingHandCursor : Qt::ArrowCursor);
        break;
    }
    }
}

void SurfaceView::mouseReleaseEvent(QMouseEvent *event)
{
    Q_UNUSED(event);
    const Drag drag = m_drag;
    m_drag = Drag{};
    if (drag.kind == DragKind::ControlPoint)
        emit controlPointReleased(drag.index, drag.startWorld, drag.currentWorld);
    else if (drag.kind == DragKind::StartVertex)
        emit startVertexReleased(drag.index, drag.startWorld, drag.currentWorld);
    if (drag.kind == DragKind::ControlPoint || drag.kind == DragKind::StartVertex)
        m_dataTimer.start(); // full detail after the drag's coarse clouds
    update();
    if (m_gl)
        m_gl->update();
}

void SurfaceView::wheelEvent(QWheelEvent *event)
{
    // 15 degrees of a wheel notch (120 units) zoom by 1.2.
    zoomBy(std::pow(1.2, event->angleDelta().y() / 120.0));
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
    case Qt::Key_Left: orbit(-15, 0); break;
    case Qt::Key_Right: orbit(15, 0); break;
    case Qt::Key_Up: orbit(0, -15); break;
    case Qt::Key_Down: orbit(0, 15); break;
    default:
        QWidget::keyPressEvent(event);
    }
}

} // namespace awb
