#include "core/render/SurfaceRaster.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <thread>

namespace awb {

namespace {

constexpr double degree = M_PI / 180.0;
constexpr float empty = -std::numeric_limits<float>::infinity();

// Buffers of rasters destroyed on this thread, taken again by the next ones.
template <class T>
std::vector<std::vector<T>> &pool()
{
    thread_local std::vector<std::vector<T>> buffers;
    return buffers;
}

template <class T>
std::vector<T> recycled(std::size_t n, T value)
{
    auto &buffers = pool<T>();
    for (auto it = buffers.begin(); it != buffers.end(); ++it)
        if (it->capacity() >= n && it->capacity() <= 4 * n + 4096) {
            std::vector<T> v = std::move(*it);
            buffers.erase(it);
            v.assign(n, value);
            return v;
        }
    return std::vector<T>(n, value);
}

template <class T>
void giveBack(std::vector<T> &v)
{
    auto &buffers = pool<T>();
    if (v.capacity() == 0 || buffers.size() >= 4)
        return;
    buffers.push_back(std::move(v));
}

} // namespace

Eigen::Vector3d OrthoCamera::toward() const
{
    const double a = azimuth * degree, e = elevation * degree;
    return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

Eigen::Vector3d OrthoCamera::right() const
{
    const double a = azimuth * degree;
    return {-std::sin(a), std::cos(a), 0.0};
}

Eigen::Vector3d OrthoCamera::up() const { return toward().cross(right()); }

OrthoCamera OrthoCamera::fit(const Mat &points, double azimuth, double elevation, double aspect,
                             double margin)
{
    OrthoCamera c;
    c.azimuth = azimuth;
    c.elevation = elevation;
    if (points.rows() == 0 || points.cols() != 3)
        return c;
    const Eigen::Vector3d lo = points.colwise().minCoeff().transpose();
    const Eigen::Vector3d hi = points.colwise().maxCoeff().transpose();
    c.centre = 0.5 * (lo + hi);
    double maxX = 0.0, maxY = 0.0;
    const Eigen::Vector3d r = c.right(), u = c.up();
    for (Eigen::Index k = 0; k < points.rows(); ++k) {
        const Eigen::Vector3d p = points.row(k).transpose() - c.centre;
        maxX = std::max(maxX, std::abs(p.dot(r)));
        maxY = std::max(maxY, std::abs(p.dot(u)));
    }
    const double half = std::max({maxY, maxX / std::max(aspect, 1e-6), 1e-9});
    c.halfHeight = half / std::max(1.0 - 2.0 * margin, 0.1);
    return c;
}

SurfaceRaster::SurfaceRaster(int width, int height, const OrthoCamera &camera,
                             std::vector<Projection> views, std::vector<int> labels,
                             double pointRadius)
    : m_w(std::max(width, 1)), m_h(std::max(height, 1)), m_camera(camera),
      m_views(std::move(views)), m_labels(std::move(labels)), m_radius(pointRadius),
      m_pixelsPerUnit(0.5 * m_h / camera.halfHeight), m_right(camera.right()),
      m_up(camera.up()), m_toward(camera.toward()),
      m_depth(recycled<float>(std::size_t(m_w) * m_h, empty)),
      m_label(recycled<std::uint32_t>(std::size_t(m_w) * m_h, 0u))
{
}

SurfaceRaster::~SurfaceRaster()
{
    giveBack(m_depth);
    giveBack(m_label);
}

Eigen::Vector3d SurfaceRaster::toScreen(const Eigen::Vector3d &p) const
{
    const Eigen::Vector3d q = p - m_camera.centre;
    return {0.5 * m_w + q.dot(m_right) * m_pixelsPerUnit,
            0.5 * m_h - q.dot(m_up) * m_pixelsPerUnit, q.dot(m_toward)};
}

void SurfaceRaster::plot(int x, int y, float z, std::uint32_t label)
{
    if (x < 0 || y < 0 || x >= m_w || y >= m_h)
        return;
    const std::size_t i = index(x, y);
    if (z > m_depth[i]) {
        m_depth[i] = z;
        m_label[i] = label;
    }
}

namespace {

// Screen positions this far off the picture are not drawn: converting them to pixel
// indices would overflow an int, and nothing of them could be seen anyway.
constexpr double kFarOff = 1e7;

bool drawable(const Eigen::Vector3d &s)
{
    return std::abs(s.x()) < kFarOff && std::abs(s.y()) < kFarOff && std::isfinite(s.z());
}

} // namespace

void SurfaceRaster::splat(const Eigen::Vector3d &s, std::uint32_t label)
{
    if (!drawable(s))
        return;
    const double r = std::max(m_radius, 0.5);
    const int x0 = int(std::floor(s.x() - r)), x1 = int(std::ceil(s.x() + r));
    const int y0 = int(std::floor(s.y() - r)), y1 = int(std::ceil(s.y() + r));
    if (x1 < 0 || y1 < 0 || x0 >= m_w || y0 >= m_h)
        return;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double dx = x + 0.5 - s.x(), dy = y + 0.5 - s.y();
            if (dx * dx + dy * dy <= r * r)
                plot(x, y, float(s.z()), label);
        }
}

void SurfaceRaster::line(const Eigen::Vector3d &a, const Eigen::Vector3d &b, std::uint32_t label)
{
    if (!drawable(a) || !drawable(b))
        return;
    const double len = std::max(std::abs(b.x() - a.x()), std::abs(b.y() - a.y()));
    const int steps = int(std::min(len, 4.0 * (m_w + m_h))) + 1;
    for (int k = 0; k <= steps; ++k) {
        const Eigen::Vector3d p = a + (b - a) * (double(k) / steps);
        plot(int(std::floor(p.x())), int(std::floor(p.y())), float(p.z()), label);
    }
}

void SurfaceRaster::triangle(const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                             const Eigen::Vector3d &c, std::uint32_t label)
{
    if (!drawable(a) || !drawable(b) || !drawable(c))
        return;
    const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    const int x0 = std::max(0, int(std::floor(std::min({a.x(), b.x(), c.x()}))));
    const int x1 = std::min(m_w - 1, int(std::ceil(std::max({a.x(), b.x(), c.x()}))));
    const int y0 = std::max(0, int(std::floor(std::min({a.y(), b.y(), c.y()}))));
    const int y1 = std::min(m_h - 1, int(std::ceil(std::max({a.y(), b.y(), c.y()}))));
    if (x0 > x1 || y0 > y1)
        return;
    // Smaller than a pixel, or seen edge-on: a splat at its centre keeps it visible (and the
    // gaps between such images are closed by fillPinholes).
    if (std::abs(area) < 1.0 || (x1 - x0) * (y1 - y0) <= 1) {
        splat((a + b + c) / 3.0, label);
        return;
    }
    // The barycentric weights as affine functions of the pixel centre, w_k = A_k x + B_k y +
    // C_k, and each row's span where all three are >= 0 found from them (widened by a pixel
    // against rounding, the test per pixel decides): a thin or slanted triangle costs its
    // pixels, not its bounding box, and a pixel costs two multiply-adds and no division.
    const double inv = 1.0 / area;
    const double A0 = -(c.y() - b.y()) * inv, B0 = (c.x() - b.x()) * inv;
    const double C0 = -(A0 * b.x() + B0 * b.y());
    const double A1 = -(a.y() - c.y()) * inv, B1 = (a.x() - c.x()) * inv;
    const double C1 = -(A1 * c.x() + B1 * c.y());
    const double A[3] = {A0, A1, -A0 - A1};
    constexpr double eps = 1e-9;
    const double az = a.z(), bz = b.z(), cz = c.z();
    for (int y = y0; y <= y1; ++y) {
        const double py = y + 0.5;
        const double K0 = B0 * py + C0, K1 = B1 * py + C1;
        const double K[3] = {K0, K1, 1.0 - K0 - K1};
        double lo = x0 + 0.5, hi = x1 + 0.5;
        bool none = false;
        for (int k = 0; k < 3; ++k) {
            if (A[k] > 0)
                lo = std::max(lo, (-eps - K[k]) / A[k]);
            else if (A[k] < 0)
                hi = std::min(hi, (-eps - K[k]) / A[k]);
            else if (K[k] < -eps)
                none = true;
        }
        if (none || !(lo <= hi + 2.0))
            continue;
        const int from = std::max(x0, int(std::ceil(lo - 0.5)) - 1);
        const int to = std::min(x1, int(std::floor(hi - 0.5)) + 1);
        float *depth = m_depth.data() + index(0, y);
        std::uint32_t *labels = m_label.data() + index(0, y);
        for (int x = from; x <= to; ++x) {
            const double px = x + 0.5;
            const double w0 = A0 * px + K0, w1 = A1 * px + K1;
            const double w2 = 1.0 - w0 - w1;
            if (w0 < -eps || w1 < -eps || w2 < -eps)
                continue;
            const float z = float(w0 * az + w1 * bz + w2 * cz);
            if (z > depth[x]) {
                depth[x] = z;
                labels[x] = label;
            }
        }
    }
}

std::uint32_t SurfaceRaster::imageLabel(const std::uint8_t *a, int n) const
{
    const int symbol = n > 0 ? a[0] : 0;
    return 1u + std::uint32_t(symbol < int(m_labels.size()) ? m_labels[size_t(symbol)] : symbol);
}

void SurfaceRaster::consume(const Mat &v, StartSet::Kind kind, const std::uint8_t *a, int n)
{
    const std::uint32_t label = imageLabel(a, n);
    for (const Projection &view : m_views) {
        const Mat p = project(view, v);
        if (p.cols() == 3)
            drawImage(p, kind, label);
    }
}

void SurfaceRaster::consumeProjected(const std::vector<Mat> &projected, StartSet::Kind kind,
                                     const std::uint8_t *a, int n)
{
    const std::uint32_t label = imageLabel(a, n);
    for (const Mat &p : projected)
        if (p.cols() == 3)
            drawImage(p, kind, label);
}

void SurfaceRaster::drawImage(const Mat &p, StartSet::Kind kind, std::uint32_t label)
{
    if (!p.allFinite()) {
        ++m_nonFinite;
        return;
    }
    std::vector<Eigen::Vector3d> &s = m_screen;  // reused: no allocation per image
    s.resize(size_t(p.rows()));
    for (Eigen::Index r = 0; r < p.rows(); ++r)
        s[size_t(r)] = toScreen(p.row(r).transpose());
    if (kind == StartSet::Kind::Points || s.size() == 1) {
        for (const auto &q : s)
            splat(q, label);
    } else if (kind == StartSet::Kind::Polyline || s.size() == 2) {
        for (size_t r = 0; r + 1 < s.size(); ++r)
            line(s[r], s[r + 1], label);
    } else {
        for (size_t r = 1; r + 1 < s.size(); ++r)
            triangle(s[0], s[r], s[r + 1], label);
    }
}

void SurfaceRaster::draw(const SurfaceMesh &mesh, std::size_t first, std::size_t last)
{
    const int nv = mesh.vertices();
    const auto at = [&](std::size_t primitive, int vertex) {
        const double *p = mesh.positions.data() + 3 * (primitive * std::size_t(nv) + vertex);
        return toScreen(Eigen::Vector3d(p[0], p[1], p[2]));
    };
    last = std::min(last, mesh.size());
    for (std::size_t i = first; i < last; ++i) {
        const std::uint32_t label = 1u + mesh.labels[i];
        switch (mesh.kind) {
        case SurfaceMesh::Kind::Points: splat(at(i, 0), label); break;
        case SurfaceMesh::Kind::Segments: line(at(i, 0), at(i, 1), label); break;
        case SurfaceMesh::Kind::Triangles: triangle(at(i, 0), at(i, 1), at(i, 2), label); break;
        }
    }
}

std::vector<std::uint32_t> drawSurfaceMesh(const SurfaceMesh &mesh, int width, int height,
                                           const OrthoCamera &camera, double pointRadius,
                                           const std::vector<std::uint32_t> &palette,
                                           int threads, const std::atomic<bool> *cancel)
{
    const int hw = int(std::max(1u, std::thread::hardware_concurrency()));
    // A thread per 20 000 primitives at most: small meshes do not pay for the merges.
    const int n = std::clamp(threads > 0 ? threads : hw, 1,
                             std::max(1, int(mesh.size() / 20000) + 1));
    std::vector<std::unique_ptr<SurfaceRaster>> rasters;
    for (int t = 0; t < n; ++t)
        rasters.push_back(std::make_unique<SurfaceRaster>(width, height, camera,
                                                          std::vector<Projection>{},
                                                          std::vector<int>{}, pointRadius));
    // Contiguous ranges in mesh order: the nearer sample wins, a tie keeps the earlier range,
    // so the picture does not depend on the number of threads.
    const auto range = [&](int t) {
        return std::pair{mesh.size() * std::size_t(t) / std::size_t(n),
                         mesh.size() * std::size_t(t + 1) / std::size_t(n)};
    };
    std::vector<std::thread> workers;
    for (int t = 1; t < n; ++t)
        workers.emplace_back([&, t] {
            const auto [a, b] = range(t);
            rasters[std::size_t(t)]->draw(mesh, a, b);
        });
    const auto [a, b] = range(0);
    rasters.front()->draw(mesh, a, b);
    for (std::thread &w : workers)
        w.join();
    if (cancel && cancel->load())
        return {};
    for (int t = 1; t < n; ++t)
        rasters.front()->merge(*rasters[std::size_t(t)]);
    rasters.front()->fillPinholes();
    // Shading is per pixel, whatever the mesh: every thread asked for takes a band.
    return rasters.front()->shade(palette, 0xffffffu,
                                  std::clamp(threads > 0 ? threads : hw, 1, hw));
}

void SurfaceRaster::merge(const SurfaceRaster &other)
{
    if (other.m_w != m_w || other.m_h != m_h)
        return;
    for (std::size_t i = 0; i < m_depth.size(); ++i)
        if (other.m_depth[i] > m_depth[i]) {
            m_depth[i] = other.m_depth[i];
            m_label[i] = other.m_label[i];
        }
    m_nonFinite += other.m_nonFinite;
}

std::uint64_t SurfaceRaster::coveredPixels() const
{
    return std::uint64_t(std::count_if(m_label.begin(), m_label.end(),
                                       [](std::uint32_t l) { return l != 0; }));
}

void SurfaceRaster::fillPinholes()
{
    // Splats of neighbouring images leave small empty gaps where the images are sparser than
    // the splats are wide: an empty pixel lying between covered pixels -- within 2 pixels on
    // both sides along one of the four directions (a row, a column, two diagonals) --
    // takes the nearest of its covered 8-neighbours (depth and label), as point renderers do.
    // The coverage decided on is the raster's before filling, so the outline does not grow.
    // A byte per pixel with a border of 2 (no bounds checks), and only the rows and columns
    // around what is covered are visited: the background costs nothing.
    const int pad = 2, W = m_w + 2 * pad, H = m_h + 2 * pad;
    std::vector<std::uint8_t> cov(std::size_t(W) * std::size_t(H), 0);
    int x0 = m_w, x1 = -1, y0 = m_h, y1 = -1;
    for (int y = 0; y < m_h; ++y)
        for (int x = 0; x < m_w; ++x)
            if (m_label[index(x, y)]) {
                cov[std::size_t(y + pad) * std::size_t(W) + std::size_t(x + pad)] = 1;
                x0 = std::min(x0, x), x1 = std::max(x1, x);
                y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
    if (x1 < 0)
        return;
    const std::ptrdiff_t steps[4] = {1, W, W + 1, W - 1}; // row, column, two diagonals
    std::vector<std::pair<std::size_t, std::size_t>> fills; // hole, the neighbour it copies
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const std::size_t i = index(x, y);
            if (m_label[i])
                continue;
            const std::uint8_t *c = cov.data() + std::size_t(y + pad) * std::size_t(W)
                                    + std::size_t(x + pad);
            int between = 0;
            for (const std::ptrdiff_t d : steps)
                between += (c[d] | c[2 * d]) & (c[-d] | c[-2 * d]);
            if (between == 0)
                continue;
            std::size_t best = i;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    if (c[dy * W + dx]) {
                        const std::size_t j = index(x + dx, y + dy);
                        if (best == i || m_depth[j] > m_depth[best])
                            best = j;
                    }
            fills.emplace_back(i, best);
        }
    for (const auto &[hole, from] : fills) {
        m_depth[hole] = m_depth[from];
        m_label[hole] = m_label[from];
    }
}

std::vector<std::uint32_t> SurfaceRaster::shade(const std::vector<std::uint32_t> &palette,
                                                std::uint32_t background, int threads) const
{
    std::vector<std::uint32_t> out(m_depth.size(), 0xff000000u | background);
    // World units per pixel, and the largest depth step still taken as the same surface.
    const double unit = 1.0 / m_pixelsPerUnit;
    const double jump = 4.0 * unit;
    // A key light from the upper left, in front of the surface: slopes facing it are bright.
    const Eigen::Vector3d light = Eigen::Vector3d(-0.6, 0.7, 0.55).normalized();
    // Central differences over a few pixels: splats are flat discs, so neighbouring pixels
    // often share one depth; a wider stencil sees the surface's slope across them.
    const auto slope = [&](int x, int y, int dx, int dy) {
        const float z = m_depth[index(x, y)];
        for (int reach : {4, 2, 1}) {
            double sum = 0.0;
            int count = 0;
            for (int s : {-1, 1}) {
                const int nx = x + s * reach * dx, ny = y + s * reach * dy;
                if (nx < 0 || ny < 0 || nx >= m_w || ny >= m_h)
                    continue;
                const float zn = m_depth[index(nx, ny)];
                if (zn == empty || std::abs(zn - z) > jump * reach)
                    continue;
                sum += s * (zn - z) / (reach * unit);
                ++count;
            }
            if (count == 2 || (count == 1 && reach == 1))
                return sum / count;
        }
        return 0.0;
    };
    const auto rows = [&](int from, int to) {
    for (int y = from; y < to; ++y)
        for (int x = 0; x < m_w; ++x) {
            const std::uint32_t l = m_label[index(x, y)];
            if (!l)
                continue;
            // dz/dx along screen x (right); screen y grows downward, so up = -dy.
            const double gx = slope(x, y, 1, 0), gy = -slope(x, y, 0, 1);
            const Eigen::Vector3d normal = Eigen::Vector3d(-gx, -gy, 1.0).normalized();
            // Depths of absurd size (a net point at 1e300) give no slope: lit face on.
            const double lambert =
                std::isfinite(gx) && std::isfinite(gy) ? std::abs(normal.dot(light)) : 1.0;
            const double shadeFactor = 0.3 + 0.75 * lambert;
            const std::uint32_t base =
                palette.empty() ? 0x808080u : palette[(l - 1) % palette.size()];
            const auto channel = [&](int shift) {
                const double c = double((base >> shift) & 0xffu) * shadeFactor;
                return std::uint32_t(std::clamp(c + 0.5, 0.0, 255.0)) << shift;
            };
            out[index(x, y)] = 0xff000000u | channel(16) | channel(8) | channel(0);
        }
    };
    const int n = std::clamp(threads, 1, std::max(1, m_h / 64));
    std::vector<std::thread> bands;
    for (int t = 1; t < n; ++t)
        bands.emplace_back(rows, m_h * t / n, m_h * (t + 1) / n);
    rows(0, m_h / n);
    for (std::thread &b : bands)
        b.join();
    return out;
}

} // namespace awb
