#include "core/render/SurfaceMesh.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <memory>
#include <thread>

namespace awb {

namespace {

// Primitives of one image of a start set with `n` vertices.
double primitivesPerImage(const StartSet &start)
{
    const double n = double(std::max<Eigen::Index>(1, start.vertices.rows()));
    switch (surfaceMeshKind(start)) {
    case SurfaceMesh::Kind::Points: return n;
    case SurfaceMesh::Kind::Segments: return std::max(1.0, n - 1);
    case SurfaceMesh::Kind::Triangles: return std::max(1.0, n - 2);
    }
    return n;
}

} // namespace

void SurfaceMesh::append(const SurfaceMesh &other)
{
    positions.insert(positions.end(), other.positions.begin(), other.positions.end());
    normals.insert(normals.end(), other.normals.begin(), other.normals.end());
    labels.insert(labels.end(), other.labels.begin(), other.labels.end());
    weights.insert(weights.end(), other.weights.begin(), other.weights.end());
    area += other.area;
    nonFinite += other.nonFinite;
}

SurfaceMesh::Kind surfaceMeshKind(const StartSet &start)
{
    const Eigen::Index n = start.vertices.rows();
    if (start.kind == StartSet::Kind::Points || n == 1)
        return SurfaceMesh::Kind::Points;
    if (start.kind == StartSet::Kind::Polyline || n == 2)
        return SurfaceMesh::Kind::Segments;
    return SurfaceMesh::Kind::Triangles;
}

SurfaceMeshSink::SurfaceMeshSink(std::vector<Projection> views, ImageLabel label,
                                 SurfaceMesh::Kind kind, Projection weight)
    : m_views(std::move(views)), m_label(std::move(label)), m_weight(std::move(weight))
{
    mesh.kind = kind;
    m_weighted = m_weight.V.cols() == 1;
    if (m_weighted && m_weight.c.size() != 1)
        m_weight.c = RowVec::Zero(1);
    m_projections = m_views;
    if (m_weighted)
        m_projections.push_back(m_weight);
}

void SurfaceMeshSink::reserve(std::size_t primitives)
{
    const std::size_t v = std::size_t(mesh.vertices());
    mesh.positions.reserve(3 * v * primitives);
    mesh.labels.reserve(primitives);
    if (m_weighted)
        mesh.weights.reserve(v * primitives);
    if (mesh.kind == SurfaceMesh::Kind::Triangles)
        mesh.normals.reserve(3 * primitives);
}

void SurfaceMeshSink::consume(const Mat &v, StartSet::Kind, const std::uint8_t *a, int n)
{
    const std::uint32_t label = m_label ? m_label(a, n) : std::uint32_t(n > 0 ? a[0] : 0);
    const bool weighted = m_weighted && m_weight.V.rows() == v.cols();
    if (weighted) {
        m_vertexWeight.resize(std::size_t(v.rows()));
        for (Eigen::Index r = 0; r < v.rows(); ++r) {
            double s = m_weight.c(0);
            for (Eigen::Index j = 0; j < v.cols(); ++j)
                s += v(r, j) * m_weight.V(j, 0);
            m_vertexWeight[std::size_t(r)] = s;
        }
    }
    for (const Projection &view : m_views) {
        if (view.V.cols() != 3 || view.V.rows() != v.cols())
            continue;
        // Into the sink's own buffer: an image is a few vertices, an allocation would cost
        // more than the product. Plain loops: for a lifted dimension of 18 (Loop's hexagon)
        // Eigen's dynamic product takes its blocked GEMM path, whose packing costs more than
        // the 3 x 18 x 3 multiplications.
        Mat &p = m_projected;
        p.resize(v.rows(), 3);
        const Eigen::Index D = v.cols();
        for (int k = 0; k < 3; ++k) {
            const double *col = view.V.data() + k * D;
            for (Eigen::Index r = 0; r < v.rows(); ++r) {
                double s = 0;
                for (Eigen::Index j = 0; j < D; ++j)
                    s += v(r, j) * col[j];
                p(r, k) = s + view.c(k);
            }
        }
        add(p, weighted ? m_vertexWeight.data() : nullptr, label);
    }
}

void SurfaceMeshSink::consumeProjected(const std::vector<Mat> &projected, StartSet::Kind,
                                       const std::uint8_t *a, int n)
{
    const std::uint32_t label = m_label ? m_label(a, n) : std::uint32_t(n > 0 ? a[0] : 0);
    const Mat *weight = m_weighted ? &projected[m_views.size()] : nullptr;
    const double *weights = weight && weight->cols() == 1 ? weight->data() : nullptr;
    for (std::size_t i = 0; i < m_views.size(); ++i)
        if (projected[i].cols() == 3)
            add(projected[i], weights, label);
}

void SurfaceMeshSink::add(const Mat &p, const double *weights, std::uint32_t label)
{
    if (!p.allFinite()) {
        ++mesh.nonFinite;
        return;
    }
    const auto put = [&](Eigen::Index r) {
        for (int k = 0; k < 3; ++k)
            mesh.positions.push_back(p(r, k));
        if (weights)
            mesh.weights.push_back(weights[r]);
    };
    switch (mesh.kind) {
    case SurfaceMesh::Kind::Points:
        for (Eigen::Index r = 0; r < p.rows(); ++r) {
            put(r);
            mesh.labels.push_back(label);
        }
        break;
    case SurfaceMesh::Kind::Segments:
        for (Eigen::Index r = 0; r + 1 < p.rows(); ++r) {
            put(r);
            put(r + 1);
            mesh.labels.push_back(label);
        }
        break;
    case SurfaceMesh::Kind::Triangles:
        // A fan from the first vertex, as SurfaceRaster fills a polygon image.
        for (Eigen::Index r = 1; r + 1 < p.rows(); ++r) {
            put(0);
            put(r);
            put(r + 1);
            const Eigen::Vector3d e1 = (p.row(r) - p.row(0)).transpose();
            const Eigen::Vector3d e2 = (p.row(r + 1) - p.row(0)).transpose();
            Eigen::Vector3d normal = e1.cross(e2);
            const double len = normal.norm();
            mesh.area += 0.5 * len;
            normal = len > 0 ? Eigen::Vector3d(normal / len) : Eigen::Vector3d::Zero();
            for (int k = 0; k < 3; ++k)
                mesh.normals.push_back(float(normal[k]));
            mesh.labels.push_back(label);
        }
        break;
    }
}

SurfaceMesh buildSurfaceMesh(const Ifs &ifs, const StartSet &start, int depth,
                             const ImageLabel &label, const IterationControl &control,
                             int threads, const OwnIteration &own, const Projection &weight)
{
    if (!own.iterate)
        checkIterateInputs(ifs, start, depth);
    // An item's own exact start sends faces.
    const SurfaceMesh::Kind kind = own.iterate && start.vertices.rows() == 0
                                       ? SurfaceMesh::Kind::Triangles
                                       : surfaceMeshKind(start);
    const int hw = int(std::max(1u, std::thread::hardware_concurrency()));
    const int n = std::clamp(threads > 0 ? threads : hw, 1, 64);
    std::vector<std::unique_ptr<SurfaceMeshSink>> sinks;
    std::vector<AttractorSink *> raw;
    // Each sink's share reserved up front (the images of a task of the split vary little):
    // growing by doubling would copy and fault in the arrays twice over.
    const double images = own.iterate ? 0.0
                                      : imageCount(ifs, depth) * double(ifs.views.size())
                                            * primitivesPerImage(start) / n;
    const std::size_t share = images < 2e7 ? std::size_t(images * 1.05) : 0;
    for (int t = 0; t < n; ++t) {
        sinks.push_back(
            std::make_unique<SurfaceMeshSink>(ifs.views, label, kind,
                                              own.iterate ? Projection{} : weight));
        sinks.back()->reserve(share);
        raw.push_back(sinks.back().get());
    }
    const IterationStats stats = own.iterate ? own.iterate(start, depth, raw, control)
                                             : iterateParallel(ifs, start, depth, raw, control);
    SurfaceMesh mesh;
    mesh.kind = kind;
    mesh.depth = depth;
    if (stats.cancelled)
        return mesh;
    if (sinks.size() == 1) {
        mesh = std::move(sinks.front()->mesh);
        mesh.depth = depth;
        return mesh;
    }
    std::size_t primitives = 0;
    for (const auto &s : sinks)
        primitives += s->mesh.size();
    mesh.positions.reserve(primitives * std::size_t(3 * mesh.vertices()));
    mesh.labels.reserve(primitives);
    if (!sinks.empty() && !sinks.front()->mesh.weights.empty())
        mesh.weights.reserve(primitives * std::size_t(mesh.vertices()));
    if (mesh.kind == SurfaceMesh::Kind::Triangles)
        mesh.normals.reserve(3 * primitives);
    for (const auto &s : sinks)
        mesh.append(s->mesh);
    return mesh;
}

Projection netWeight(const Projection &netCoordinates, int j)
{
    if (j < 0 || j >= netCoordinates.V.cols())
        return {};
    Projection w;
    w.V = netCoordinates.V.col(j);
    w.c = RowVec::Constant(1, netCoordinates.c.size() > j ? netCoordinates.c(j) : 0.0);
    return w;
}

SurfaceMesh movedNetPoint(const SurfaceMesh &base, const Eigen::Vector3d &delta)
{
    SurfaceMesh out;
    out.kind = base.kind;
    out.depth = base.depth;
    out.nonFinite = base.nonFinite;
    out.labels = base.labels;
    out.weights = base.weights;
    out.positions.resize(base.positions.size());
    const std::size_t vertices = base.positions.size() / 3;
    if (base.weights.size() != vertices) {
        out.positions = base.positions;
        out.normals = base.normals;
        out.area = base.area;
        return out;
    }
    const double *from = base.positions.data();
    double *to = out.positions.data();
    for (std::size_t v = 0; v < vertices; ++v) {
        const double w = base.weights[v];
        to[3 * v] = from[3 * v] + w * delta.x();
        to[3 * v + 1] = from[3 * v + 1] + w * delta.y();
        to[3 * v + 2] = from[3 * v + 2] + w * delta.z();
    }
    if (out.kind != SurfaceMesh::Kind::Triangles)
        return out;
    const std::size_t triangles = out.labels.size();
    out.normals.resize(3 * triangles);
    for (std::size_t t = 0; t < triangles; ++t) {
        const Eigen::Map<const Eigen::Vector3d> a(to + 9 * t), b(to + 9 * t + 3), c(to + 9 * t + 6);
        Eigen::Vector3d normal = (b - a).cross(c - a);
        const double len = normal.norm();
        out.area += 0.5 * len;
        normal = len > 0 ? Eigen::Vector3d(normal / len) : Eigen::Vector3d::Zero();
        for (int k = 0; k < 3; ++k)
            out.normals[3 * t + std::size_t(k)] = float(normal[k]);
    }
    return out;
}

int surfaceMeshDepth(const Ifs &ifs, const StartSet &start, int depth, double budget,
                     const OwnIteration &own)
{
    int k = std::max(0, depth);
    if (own.pointCount) {
        while (k > 0 && own.pointCount(start, k) > budget)
            --k;
        return k;
    }
    const double per = primitivesPerImage(start);
    while (k > 0 && imageCount(ifs, k) * double(std::max<std::size_t>(1, ifs.views.size()))
                            * per
                        > budget)
        --k;
    return k;
}

} // namespace awb
