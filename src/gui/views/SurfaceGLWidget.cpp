#include "gui/views/SurfaceGLWidget.h"

#include "gui/views/SurfaceView.h"

#include <Eigen/Geometry>
#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QOpenGLShaderProgram>
#include <QPainter>

#include <cstring>

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
    // Two-sided Lambert as the CPU renderer (SurfaceRaster::shade): a surface patch has no
    // inside; points without a normal are lit as if facing the viewer.
    float lambert = length(normal) > 0.5 ? abs(dot(normalize(normal), light)) : 1.0;
    shaded = min(colour.rgb * (0.3 + 0.75 * lambert), vec3(1.0));
}
)";

const char *fragmentShader = R"(
#version 120
varying vec3 shaded;
void main()
{
    // Round splats: square points look like a mosaic when the cloud is sparse.
    vec2 d = gl_PointCoord - vec2(0.5);
    if (dot(d, d) > 0.25)
        discard;
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

} // namespace

SurfaceGLWidget::SurfaceGLWidget(SurfaceView *view) : QOpenGLWidget(view), m_view(view)
{
    setAttribute(Qt::WA_TransparentForMouseEvents);
    // The point cloud needs a depth test: ask for a depth buffer whatever the default.
    QSurfaceFormat f = format();
    f.setDepthBufferSize(24);
    setFormat(f);
    setFocusPolicy(Qt::NoFocus);
}

SurfaceGLWidget::~SurfaceGLWidget()
{
    cleanup();
    // ~QOpenGLWidget destroys the context after this object stops being a SurfaceGLWidget:
    // its aboutToBeDestroyed must not call cleanup() then (UBSan: a downcast to a destroyed
    // type).
    if (QOpenGLContext *c = context())
        disconnect(c, &QOpenGLContext::aboutToBeDestroyed, this, &SurfaceGLWidget::cleanup);
}

void SurfaceGLWidget::cloudChanged()
{
    m_dirty = true;
    update();
}

void SurfaceGLWidget::cleanup()
{
    // GL objects die with the context they were made in: make it current first.
    if (!m_program && !m_buffer.isCreated())
        return;
    makeCurrent();
    m_buffer.destroy();
    delete m_program;
    m_program = nullptr;
    doneCurrent();
}

void SurfaceGLWidget::initializeGL()
{
    // A widget moved to another window gets a new context: free the old objects with the old.
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &SurfaceGLWidget::cleanup,
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
        qWarning("SurfaceGLWidget: %s", qPrintable(m_program->log()));
    m_buffer.create();
    m_dirty = true;
}

void SurfaceGLWidget::resizeGL(int, int) {}

void SurfaceGLWidget::upload()
{
    // Interleaved (28 bytes a point): one buffer, one bind per frame.
    m_uploaded = m_view->m_cloud;
    const SurfaceCloud &c = *m_uploaded;
    std::vector<Vertex> data(c.size());
    for (std::size_t i = 0; i < c.size(); ++i) {
        Vertex &v = data[i];
        std::memcpy(v.position, &c.positions[3 * i], sizeof v.position);
        std::memcpy(v.normal, &c.normals[3 * i], sizeof v.normal);
        const std::uint32_t argb = c.colours[i];
        v.colour[0] = std::uint8_t(argb >> 16);
        v.colour[1] = std::uint8_t(argb >> 8);
        v.colour[2] = std::uint8_t(argb);
        v.colour[3] = 255;
    }
    m_buffer.bind();
    m_buffer.allocate(data.data(), int(data.size() * sizeof(Vertex)));
    m_buffer.release();
    m_count = data.size();
    m_dirty = false;
}

void SurfaceGLWidget::paintGL()
{
    QElapsedTimer timer;
    timer.start();
    glClearColor(1.f, 1.f, 1.f, 1.f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const qreal dpr = devicePixelRatioF();
    const QSizeF size(width(), height());
    const QMatrix4x4 mvp = m_view->viewMatrix(size);
    std::size_t drawn = 0;
    if (m_ready && m_view->isLayerVisible(SurfaceView::Layer::Attractor)) {
        if (m_dirty || m_uploaded != m_view->m_cloud)
            upload();
        // While the camera moves only a prefix of the (shuffled) cloud is drawn: an even
        // sample that keeps llvmpipe near interactive rates.
        drawn = m_view->m_moving ? std::min(m_count, m_view->m_movingBudget) : m_count;
        if (drawn > 0) {
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LESS);
            glEnable(programPointSize);
            glEnable(pointSprite);
            glGetError(); // a core profile refuses GL_POINT_SPRITE: harmless, forget it
            m_program->bind();
            m_program->setUniformValue("mvp", mvp);
            const OrthoCamera &c = m_view->m_camera.ortho;
            // SurfaceRaster's key light (upper left, in front), from screen to world axes.
            const Eigen::Vector3d light =
                (-0.6 * c.right() + 0.7 * c.up() + 0.55 * c.toward()).normalized();
            m_program->setUniformValue("light", QVector3D(light.x(), light.y(), light.z()));
            m_program->setUniformValue("pointSize", GLfloat(m_view->splatSize(drawn, dpr)));
            m_buffer.bind();
            m_program->enableAttributeArray(0);
            m_program->enableAttributeArray(1);
            m_program->enableAttributeArray(2);
            m_program->setAttributeBuffer(0, GL_FLOAT, offsetof(Vertex, position), 3,
                                          sizeof(Vertex));
            m_program->setAttributeBuffer(1, GL_FLOAT, offsetof(Vertex, normal), 3,
                                          sizeof(Vertex));
            glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                                  reinterpret_cast<const void *>(offsetof(Vertex, colour)));
            glDrawArrays(GL_POINTS, 0, GLsizei(drawn));
            m_program->disableAttributeArray(0);
            m_program->disableAttributeArray(1);
            m_program->disableAttributeArray(2);
            m_buffer.release();
            m_program->release();
            glDisable(GL_DEPTH_TEST);
            // The frame time must include the rasterisation, which llvmpipe defers.
            glFinish();
        }
    }
    m_view->m_frameMs = double(timer.nsecsElapsed()) / 1e6;
    m_view->m_framePoints = drawn;
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    m_view->paintOverlay(painter, mvp, QRectF(QPointF(0, 0), size), 1.0);
    painter.end();
    emit m_view->frameDrawn(m_view->m_frameMs, qulonglong(drawn));
}

} // namespace awb
