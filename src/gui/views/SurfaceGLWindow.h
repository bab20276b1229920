#pragma once
// The OpenGL half of SurfaceView: a QOpenGLWindow of its own, shown in a window container over
// the view, so that GL draws this view only -- a QOpenGLWidget would send every repaint of the
// whole main window through GL composition (on a software renderer, a copy of the window per
// frame). It draws the view's mesh (the coarse one while something moves) with a depth test
// and the CPU renderer's light, then the overlays with QPainter. GL objects are made in
// initializeGL and freed with the context (Qt's hellogl2 life cycle). Pointer, wheel and key
// events go to the view's handlers: the window only draws.

#include <QMatrix4x4>
#include <QOpenGLBuffer>
#include <QOpenGLFunctions>
#include <QOpenGLWindow>

#include <memory>

class QOpenGLShaderProgram;

namespace awb {

class SurfaceView;
struct SurfaceMesh;

class SurfaceGLWindow : public QOpenGLWindow, protected QOpenGLFunctions {
    Q_OBJECT
public:
    explicit SurfaceGLWindow(SurfaceView *view);
    ~SurfaceGLWindow() override;

    // Whether initializeGL ran with a working context and shaders.
    bool ready() const { return m_ready; }

protected:
    void initializeGL() override;
    void paintGL() override;
    bool event(QEvent *event) override;

private:
    // A mesh uploaded to a buffer (interleaved: position, normal, colour per vertex).
    struct Upload {
        std::shared_ptr<const SurfaceMesh> mesh;
        std::uint64_t paletteKey = 0;
        QOpenGLBuffer buffer{QOpenGLBuffer::VertexBuffer};
        int vertices = 0;
    };
    void cleanup();
    Upload &uploaded(const std::shared_ptr<const SurfaceMesh> &mesh);

    SurfaceView *m_view;
    QOpenGLShaderProgram *m_program = nullptr;
    Upload m_slots[2];      // the coarse and the full mesh: switching costs no upload
    int m_nextSlot = 0;
    bool m_ready = false;
    // What the last frame drew: a new mesh or camera is a new picture (frame log).
    const SurfaceMesh *m_lastMesh = nullptr;
    QMatrix4x4 m_lastMatrix;
    std::uint64_t m_pictures = 0;
};

} // namespace awb
