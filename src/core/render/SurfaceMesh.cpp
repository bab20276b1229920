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
                                 SurfaceMesh::Kind kind)
    : m_views(std::move(views)), m_label(std::move(label))
{
    mesh.kind = kind;
}

void SurfaceMeshSink::consume(const Mat &v, StartSet::Kind, const std::uint8_t *a, int n)
{
    const std::uint32_t label = m_label ? m_label(a, n) : std::uint32_t(n > 0 ? a[0] : 0);
    const auto put = [&](const Mat &p, Eigen::Index r) {
        for (int k = 0; k < 3; ++k)
            mesh.positions.push_back(p(r, k));
    };
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
        if (!p.allFinite()) {
            ++mesh.nonFinite;
            continue;
        }
        switch (mesh.kind) {
        case SurfaceMesh::Kind::Points:
            for (Eigen::Index r = 0; r < p.rows(); ++r) {
                put(p, r);
                mesh.labels.push_back(label);
            }
            break;
        case SurfaceMesh::Kind::Segments:
            for (Eigen::Index r = 0; r + 1 < p.rows(); ++r) {
                put(p, r);
                put(p, r + 1);
                mesh.labels.push_back(label);
            }
            break;
        case SurfaceMesh::Kind::Triangles:
            // A fan from the first vertex, as SurfaceRaster fills a polygon image.
            for (Eigen::Index r = 1; r + 1 < p.rows(); ++r) {
                put(p, 0);
                put(p, r);
                put(p, r + 1);
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
}

SurfaceMesh buildSurfaceMesh(const Ifs &ifs, const StartSet &start, int depth,
                             const ImageLabel &label, const IterationControl &control,
                             int threads, const OwnIteration &own)
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
    for (int t = 0; t < n; ++t) {
        sinks.push_back(
            std::make_unique<SurfaceMeshSink>(ifs.views, label, kind));
        raw.push_back(sinks.back().get());
    }
    const IterationStats stats = own.iterate ? own.iterate(start, depth, raw, control)
                                             : iterateParallel(ifs, start, depth, raw, control);
    SurfaceMesh mesh;
    mesh.kind = kind;
    mesh.depth = depth;
    if (stats.cancelled)
        return mesh;
    std::size_t primitives = 0;
    for (const auto &s : sinks)
        primitives += s->mesh.size();
    mesh.positions.reserve(primitives * std::size_t(3 * mesh.vertices()));
    mesh.labels.reserve(primitives);
    if (mesh.kind == SurfaceMesh::Kind::Triangles)
        mesh.normals.reserve(3 * primitives);
    for (const auto &s : sinks)
        mesh.append(s->mesh);
    return mesh;
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
