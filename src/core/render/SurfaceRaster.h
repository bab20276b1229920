#pragma once
// The CPU renderer of 3D attractors (000 §3 surfaces): an orthographic camera, a z-buffer of
// the images of the start set (points as round splats, segments as lines, polygons as filled
// triangles) with the map index of each pixel, and shading from normals estimated on the
// depth buffer. Role in the core: the headless picture of a surface item for the CLI, for
// printing and for tests, the same for any start set and any subset of maps; it needs no GL.
// Qt-free: it hands out 32-bit ARGB pixels (0xAARRGGBB), row 0 at the top.

#include "core/ifs/Attractor.h"
#include "core/render/SurfaceMesh.h"

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace awb {

// Looks at `centre` from the direction (azimuth, elevation) in degrees: azimuth turns about
// the z axis from the x axis, elevation lifts above the xy plane. Screen x grows along right(),
// screen y along up(); depth grows toward the viewer.
struct OrthoCamera {
    double azimuth = -60.0;
    double elevation = 30.0;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double halfHeight = 1.0;  // world units from the centre to the top edge of the picture

    Eigen::Vector3d toward() const;  // unit vector from the centre to the viewer
    Eigen::Vector3d right() const;
    Eigen::Vector3d up() const;
    // Frames the points (n x 3) for a picture of the given aspect (width / height) with a
    // margin (fraction of the picture on each side).
    static OrthoCamera fit(const Mat &points, double azimuth, double elevation, double aspect,
                           double margin = 0.06);
};

class SurfaceRaster : public AttractorSink {
public:
    // views: how an IFS point becomes a 3D point (3 columns). labels[i]: the colour index of
    // the map with address symbol i (empty: i itself). pointRadius in pixels.
    SurfaceRaster(int width, int height, const OrthoCamera &camera, std::vector<Projection> views,
                  std::vector<int> labels = {}, double pointRadius = 1.0);
    // The buffers go back to a small pool of the thread that destroys the raster, and the
    // next raster of that thread takes them: frames drawn one after another do not fault in
    // fresh pages for every picture.
    ~SurfaceRaster() override;
    SurfaceRaster(const SurfaceRaster &) = default;
    SurfaceRaster &operator=(const SurfaceRaster &) = default;
    void consume(const Mat &v, StartSet::Kind k, const std::uint8_t *a, int n) override;
    // The views: the iteration fuses them with its last map.
    const std::vector<Projection> *projections() const override { return &m_views; }
    void consumeProjected(const std::vector<Mat> &projected, StartSet::Kind k,
                          const std::uint8_t *a, int n) override;
    // Draws primitives [first, last) of a mesh built in advance (the same pixels as consume()
    // of the images they came from; label = 1 + the primitive's colour index).
    void draw(const SurfaceMesh &mesh, std::size_t first, std::size_t last);
    // Keeps the nearer sample of each pixel (for per-thread rasters).
    void merge(const SurfaceRaster &other);

    int width() const { return m_w; }
    int height() const { return m_h; }
    const OrthoCamera &camera() const { return m_camera; }
    // Screen position (x right, y down, in pixels) and depth of a world point.
    Eigen::Vector3d toScreen(const Eigen::Vector3d &p) const;
    bool covered(int x, int y) const { return m_label[index(x, y)] != 0; }
    // 1 + colour index of the nearest sample; 0 where nothing was drawn.
    std::uint32_t label(int x, int y) const { return m_label[index(x, y)]; }
    float depth(int x, int y) const { return m_depth[index(x, y)]; }
    std::uint64_t coveredPixels() const;
    std::uint64_t nonFinite() const { return m_nonFinite; }

    // Closes gaps of up to 3 pixels between splats inside the picture, not its outline (call
    // once, after merging, before shade()).
    void fillPinholes();
    // palette[i]: colour (0xRRGGBB) of colour index i (cycled); lambert shading from a light
    // above left of the viewer on normals taken from the depth buffer.
    // `threads` > 1 shades bands of rows at once (the picture is the same).
    std::vector<std::uint32_t> shade(const std::vector<std::uint32_t> &palette,
                                     std::uint32_t background = 0xffffffu,
                                     int threads = 1) const;

private:
    std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(m_w) + x; }
    std::uint32_t imageLabel(const std::uint8_t *a, int n) const;
    // One image through one view (n x 3 world points).
    void drawImage(const Mat &p, StartSet::Kind kind, std::uint32_t label);
    void plot(int x, int y, float z, std::uint32_t label);
    void splat(const Eigen::Vector3d &s, std::uint32_t label);
    void line(const Eigen::Vector3d &a, const Eigen::Vector3d &b, std::uint32_t label);
    void triangle(const Eigen::Vector3d &a, const Eigen::Vector3d &b, const Eigen::Vector3d &c,
                  std::uint32_t label);

    int m_w, m_h;
    OrthoCamera m_camera;
    std::vector<Projection> m_views;
    std::vector<int> m_labels;
    double m_radius;
    double m_pixelsPerUnit;
    Eigen::Vector3d m_right, m_up, m_toward;
    std::vector<float> m_depth;
    std::vector<std::uint32_t> m_label;
    std::vector<Eigen::Vector3d> m_screen;  // screen positions of the image being drawn
    std::uint64_t m_nonFinite = 0;
};

// The shaded picture (0xAARRGGBB, row 0 at the top) of `mesh` from `camera`, drawn on
// `threads` threads (0: all cores) and merged, pinholes filled: the 3D view's CPU frames and
// its exports draw this. An empty vector when `cancel` stopped it.
std::vector<std::uint32_t> drawSurfaceMesh(const SurfaceMesh &mesh, int width, int height,
                                           const OrthoCamera &camera, double pointRadius,
                                           const std::vector<std::uint32_t> &palette,
                                           int threads = 0,
                                           const std::atomic<bool> *cancel = nullptr);

} // namespace awb
