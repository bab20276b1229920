#pragma once
// The OpenGL half of SurfaceView: draws the view's point cloud as round, lit splats with a
// depth test, then lets the view paint its overlays with QPainter on top. It owns only GL
// objects, made in initializeGL and freed with the context (Qt's hellogl2 life cycle); no GL
// call happens outside initializeGL, resizeGL and paintGL (and the context's cleanup). Mouse
// and keys go to the view behind it: this widget is transparent for input.

#include <QOpenGLBuffer>
#include <QOpenGLFunctions>
#include <QOpenGLWidget>

#include <memory>

class QOpenGLShaderProgram;

namespace awb {

class SurfaceView;
struct SurfaceCloud;

class SurfaceGLWidget : public QOpenGLWidget, protected QOpenGLFunctions {
    Q_OBJECT
public:
    explicit SurfaceGLWidget(SurfaceView *view);
    ~SurfaceGLWidget() override;

    // The view has a new cloud: upload it at the next frame.
    void cloudChanged();
    // Whether initializeGL ran with a working context and shaders.
    bool ready() const { return m_ready; }

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;

private:
    void cleanup();
    void upload();

    SurfaceView *m_view;
    QOpenGLShaderProgram *m_program = nullptr;
    QOpenGLBuffer m_buffer{QOpenGLBuffer::VertexBuffer};
    std::shared_ptr<const SurfaceCloud> m_uploaded;
    std::size_t m_count = 0;
    bool m_dirty = true;
    bool m_ready = false;
};

} // namespace awb
