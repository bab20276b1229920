#include "gui/views/SurfaceGLWindow.h"

#include "core/render/SurfaceMesh.h"
#include "gui/views/SurfaceView.h"

#include <Eigen/Geometry>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLShaderProgram>
#include <QPainter>
#include <QWheelEvent>

#include <cstring>
#include <vector>

namespace awb {

namespace {

// GLSL 1.20: what every compatibility context (Mesa llvmpipe included) compiles.
const char *vertexShader = R"(
#version 120
attribute vec3 position;
attribute vec3 normal;
attribute vec4 colour;
uniform mat4 mvp;
uniform vec3 light;
uniform float pointSize;
varying vec3 shaded;
void main()
{
    gl_Position = mvp * vec4(position, 1.0);
    gl_PointSize = pointSize;
    // Two-sided Lambert with the CPU renderer's light and factors (SurfaceRaster::shade): a
    // surface patch has no inside; points and segments have no normal and are lit as facing
    // the viewer.
    float lambert = length(normal) > 0.5 ? abs(dot(normalize(normal), light)) : 1.0;
    shaded = min(colour.rgb * (0.3 + 0.75 * lambert), vec3(1.0));
}
)";

const char *fragmentShader = R"(
#version 120
varying vec3 shaded;
uniform bool roundPoints;
void main()
{
    if (roundPoints) {
        vec2 d = gl_PointCoord - vec2(0.5);
        if (dot(d, d) > 0.25)
            discard;
    }
    gl_FragColor = vec4(shaded, 1.0);
}
)";

// Enums of desktop GL that QOpenGLFunctions (the ES 2 subset) does not name.
constexpr GLenum programPointSize = 0x8642;  // GL_PROGRAM_POINT_SIZE
constexpr GLenum pointSprite = 0x8861;       // GL_POINT_SPRITE (compatibility profiles)

struct Vertex {
    float position[3];
    float normal[3];
    std::uint8_t colour[4];
};

std::uint64_t paletteKey(const std::vector<std::uint32_t> &palette)
{
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint32_t c : palette)
        h = (h ^ c) * 1099511628211ull;
    return h;
}

} // namespace

SurfaceGLWindow::SurfaceGLWindow(SurfaceView *view)
    : QOpenGLWindow(QOpenGLWindow::NoPartialUpdate), m_view(view)
{
    // The mesh needs a depth test, QPainter's GL engine a stencil buffer for the overlays'
    // paths (without one it fills their bounding boxes): ask for both whatever the default.
    QSurfaceFormat f = format();
    f.setDepthBufferSize(24);
    f.setStencilBufferSize(8);
    setFormat(f);
}

SurfaceGLWindow::~SurfaceGLWindow()
{
    cleanup();
    if (QOpenGLContext *c = context())
        disconnect(c, &QOpenGLContext::aboutToBeDestroyed, this, &SurfaceGLWindow::cleanup);
}

void SurfaceGLWindow::cleanup()
{
    // GL objects die with the context they were made in: make it current first.
    if (!m_program && !m_slots[0].buffer.isCreated() && !m_slots[1].buffer.isCreated())
        return;
    makeCurrent();
    for (Upload &u : m_slots) {
        u.buffer.destroy();
        u.mesh.reset();
    }
    delete m_program;
    m_program = nullptr;
    doneCurrent();
}

void SurfaceGLWindow::initializeGL()
{
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &SurfaceGLWindow::cleanup,
            Qt::UniqueConnection);
    initializeOpenGLFunctions();
    m_program = new QOpenGLShaderProgram;
    m_ready = m_program->addShaderFromSourceCode(QOpenGLShader::Vertex, vertexShader)
              && m_program->addShaderFromSourceCode(QOpenGLShader::Fragment, fragmentShader);
    m_program->bindAttributeLocation("position", 0);
    m_program->bindAttributeLocation("normal", 1);
    m_program->bindAttributeLocation("colour", 2);
    m_ready = m_ready && m_program->link();
    if (!m_ready)
        qWarning("SurfaceGLWindow: %s", qPrintable(m_program->log()));
    for (Upload &u : m_slots)
        u.buffer.create();
}

SurfaceGLWindow::Upload &SurfaceGLWindow::uploaded(const std::shared_ptr<const SurfaceMesh> &mesh)
{
    const std::vector<std::uint32_t> palette = m_view->colours().palette;
    const std::uint64_t key = paletteKey(palette);
    for (Upload &u : m_slots)
        if (u.mesh == mesh && u.paletteKey == key)
            return u;
    Upload &u = m_slots[m_nextSlot];
    m_nextSlot = 1 - m_nextSlot;
    // A vertex per corner, with its primitive's normal and colour (flat shading).
    const SurfaceMesh &m = *mesh;
    const int nv = m.vertices();
    std::vector<Vertex> data(m.size() * std::size_t(nv));
    for (std::size_t i = 0; i < m.size(); ++i) {
        const std::uint32_t rgb = palette.empty() ? 0x808080u : palette[m.labels[i] % palette.size()];
        for (int k = 0; k < nv; ++k) {
            Vertex &v = data[i * std::size_t(nv) + std::size_t(k)];
            for (int c = 0; c < 3; ++c) {
                v.position[c] = float(m.positions[3 * (i * std::size_t(nv) + std::size_t(k)) + c]);
                v.normal[c] = m.normals.empty() ? 0.f : m.normals[3 * i + std::size_t(c)];
            }
            v.colour[0] = std::uint8_t(rgb >> 16);
            v.colour[1] = std::uint8_t(rgb >> 8);
            v.colour[2] = std::uint8_t(rgb);
            v.colour[3] = 255;
        }
    }
    u.buffer.bind();
    u.buffer.allocate(data.data(), int(data.size() * sizeof(Vertex)));
    u.buffer.release();
    u.mesh = mesh;
    u.paletteKey = key;
    u.vertices = int(data.size());
    return u;
}

void SurfaceGLWindow::paintGL()
{
    QElapsedTimer timer;
    timer.start();
    // The previous frame's QPainter (the overlays) leaves its GL state behind: a scissor
    // rectangle would clip the clear, blending and masks the mesh.
    glViewport(0, 0, int(width() * devicePixelRatio()), int(height() * devicePixelRatio()));
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glClearColor(1.f, 1.f, 1.f, 1.f);
    glClearDepthf(1.f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const QSizeF size(width(), height());
    const QMatrix4x4 mvp = m_view->viewMatrix(size);
    const auto mesh = m_view->frameMesh();
    std::size_t drawn = 0;
    if (m_ready && mesh && !mesh->empty()
        && m_view->isLayerVisible(SurfaceView::Layer::Attractor)) {
        Upload &u = uploaded(mesh);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        const bool points = mesh->kind == SurfaceMesh::Kind::Points;
        if (points) {
            glEnable(programPointSize);
            glEnable(pointSprite);
            glGetError(); // a core profile refuses GL_POINT_SPRITE: harmless, forget it
        }
        m_program->bind();
        m_program->setUniformValue("mvp", mvp);
        const OrthoCamera &c = m_view->m_camera.ortho;
        // SurfaceRaster's key light (upper left, in front), from screen to world axes.
        const Eigen::Vector3d light =
            (-0.6 * c.right() + 0.7 * c.up() + 0.55 * c.toward()).normalized();
        m_program->setUniformValue("light", QVector3D(light.x(), light.y(), light.z()));
        m_program->setUniformValue(
            "pointSize", GLfloat(std::max(1.0, m_view->m_settings.pointSize * devicePixelRatio())));
        m_program->setUniformValue("roundPoints", points);
        u.buffer.bind();
        m_program->enableAttributeArray(0);
        m_program->enableAttributeArray(1);
        m_program->enableAttributeArray(2);
        m_program->setAttributeBuffer(0, GL_FLOAT, offsetof(Vertex, position), 3, sizeof(Vertex));
        m_program->setAttributeBuffer(1, GL_FLOAT, offsetof(Vertex, normal), 3, sizeof(Vertex));
        glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                              reinterpret_cast<const void *>(offsetof(Vertex, colour)));
        const GLenum mode = points ? GL_POINTS
                            : mesh->kind == SurfaceMesh::Kind::Segments ? GL_LINES
                                                                       : GL_TRIANGLES;
        glDrawArrays(mode, 0, GLsizei(u.vertices));
        if (!points) {
            // Images smaller than a pixel fall between pixel centres: their corners drawn as
            // round splats too, as the CPU renderer draws them (SurfaceRaster::triangle), close
            // the surface.
            glEnable(programPointSize);
            glEnable(pointSprite);
            glGetError();
            m_program->setUniformValue("roundPoints", true);
            glDrawArrays(GL_POINTS, 0, GLsizei(u.vertices));
        }
        m_program->disableAttributeArray(0);
        m_program->disableAttributeArray(1);
        m_program->disableAttributeArray(2);
        u.buffer.release();
        m_program->release();
        glDisable(GL_DEPTH_TEST);
        // The frame time must include the rasterisation, which llvmpipe defers.
        glFinish();
        drawn = mesh->size();
    }
    m_view->m_frameMs = double(timer.nsecsElapsed()) / 1e6;
    m_view->m_framePrimitives = drawn;
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    m_view->paintOverlay(painter, mvp, QRectF(QPointF(0, 0), size), 1.0);
    painter.end();
    if (mesh.get() != m_lastMesh || mvp != m_lastMatrix) {
        ++m_pictures;
        m_lastMesh = mesh.get();
        m_lastMatrix = mvp;
    }
    const bool final = !m_view->m_moving && !m_view->pointMoving() && !m_view->isRendering()
                       && mesh && mesh == m_view->m_meshes.full;
    const bool orbit = m_view->m_drag.kind == SurfaceView::DragKind::Orbit
                       || m_view->m_drag.kind == SurfaceView::DragKind::Pan;
    const QPoint input = orbit ? m_view->m_inputGlobal : m_view->m_meshes.input;
    const bool shows = orbit || (m_view->m_meshes.fromDrag && m_view->pointMoving());
    m_view->logFrame(m_pictures, final, shows ? &input : nullptr);
    emit m_view->frameDrawn(m_view->m_frameMs, qulonglong(drawn));
}

bool SurfaceGLWindow::event(QEvent *e)
{
    // The view handles the pointer and the keys: the window is only where GL draws.
    switch (e->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
    case QEvent::MouseMove: {
        const auto *m = static_cast<QMouseEvent *>(e);
        QMouseEvent copy(e->type(), m->position(), m->globalPosition(), m->button(),
                         m->buttons(), m->modifiers());
        QCoreApplication::sendEvent(m_view, &copy);
        return true;
    }
    case QEvent::Wheel: {
        const auto *w = static_cast<QWheelEvent *>(e);
        QWheelEvent copy(w->position(), w->globalPosition(), w->pixelDelta(), w->angleDelta(),
                         w->buttons(), w->modifiers(), w->phase(), w->inverted());
        QCoreApplication::sendEvent(m_view, &copy);
        return true;
    }
    case QEvent::KeyPress:
    case QEvent::KeyRelease: {
        const auto *k = static_cast<QKeyEvent *>(e);
        QKeyEvent copy(e->type(), k->key(), k->modifiers(), k->text(), k->isAutoRepeat(),
                       ushort(k->count()));
        QCoreApplication::sendEvent(m_view, &copy);
        return true;
    }
    default:
        return QOpenGLWindow::event(e);
    }
}

} // namespace awb
