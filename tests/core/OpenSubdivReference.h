#pragma once
// OpenSubdiv 3.5 as the mesh tests' reference (Debian libosd-dev, test-only): a refiner of a
// Mesh with its tags (creases, corners, holes, boundary interpolation, crease method, smooth
// triangles) and its uniform refinement with the limit positions of the last level, in double
// precision; and the open "star" meshes both compare on. Only the test files whose sources CMake gives OpenSubdiv's include path include it.

#include "core/mesh/Mesh.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <tuple>
#include <vector>

namespace awb::test {

namespace osd = OpenSubdiv;

struct OsdPoint {
    double p[3];
    void Clear(void * = nullptr) { p[0] = p[1] = p[2] = 0; }
    void AddWithWeight(const OsdPoint &s, double w)
    {
        for (int k = 0; k < 3; ++k)
            p[k] += w * s.p[k];
    }
};

struct OsdResult {
    Mat points;  // the vertices of the last level
    Mat limits;  // their limit positions (PrimvarRefiner::Limit: the rules of the last level)
};

inline std::unique_ptr<osd::Far::TopologyRefiner> openSubdivRefiner(const Mesh &m,
                                                                    MeshScheme scheme)
{
    using Factory = osd::Far::TopologyRefinerFactory<osd::Far::TopologyDescriptor>;
    const MeshOptions &o = m.tags.options;
    osd::Sdc::Options options;
    options.SetVtxBoundaryInterpolation(
        o.boundary == BoundaryInterpolation::None ? osd::Sdc::Options::VTX_BOUNDARY_NONE
        : o.boundary == BoundaryInterpolation::EdgeAndCorner
            ? osd::Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER
            : osd::Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    options.SetCreasingMethod(o.creaseMethod == CreaseMethod::Chaikin
                                  ? osd::Sdc::Options::CREASE_CHAIKIN
                                  : osd::Sdc::Options::CREASE_UNIFORM);
    options.SetTriangleSubdivision(o.triangles == TriangleSubdivision::Smooth
                                       ? osd::Sdc::Options::TRI_SUB_SMOOTH
                                       : osd::Sdc::Options::TRI_SUB_CATMARK);
    std::vector<int> counts, indices, pairs, corners, holes;
    std::vector<float> creaseWeights, cornerWeights;
    for (const auto &f : m.faces) {
        counts.push_back(int(f.size()));
        indices.insert(indices.end(), f.begin(), f.end());
    }
    for (const SharpEdge &e : m.tags.edges) {
        pairs.push_back(e.a);
        pairs.push_back(e.b);
        creaseWeights.push_back(e.sharpness);
    }
    for (const SharpVertex &c : m.tags.vertices) {
        corners.push_back(c.vertex);
        cornerWeights.push_back(c.sharpness);
    }
    holes = m.tags.holes;
    osd::Far::TopologyDescriptor desc;
    desc.numVertices = int(m.vertices.rows());
    desc.numFaces = int(m.faces.size());
    desc.numVertsPerFace = counts.data();
    desc.vertIndicesPerFace = indices.data();
    desc.numCreases = int(creaseWeights.size());
    desc.creaseVertexIndexPairs = pairs.data();
    desc.creaseWeights = creaseWeights.data();
    desc.numCorners = int(corners.size());
    desc.cornerVertexIndices = corners.data();
    desc.cornerWeights = cornerWeights.data();
    desc.numHoles = int(holes.size());
    desc.holeIndices = holes.data();
    const auto type =
        scheme == MeshScheme::Loop ? osd::Sdc::SCHEME_LOOP : osd::Sdc::SCHEME_CATMARK;
    return std::unique_ptr<osd::Far::TopologyRefiner>(
        Factory::Create(desc, Factory::Options(type, options)));
}

inline OsdResult openSubdiv(const Mesh &m, MeshScheme scheme, int levels)
{
    auto refiner = openSubdivRefiner(m, scheme);
    osd::Far::TopologyRefiner::UniformOptions uniform(levels);
    uniform.fullTopologyInLastLevel = true;
    refiner->RefineUniform(uniform);
    std::vector<OsdPoint> buffer(std::size_t(refiner->GetNumVerticesTotal()));
    for (Eigen::Index v = 0; v < m.vertices.rows(); ++v)
        for (int k = 0; k < 3; ++k)
            buffer[std::size_t(v)].p[k] = m.vertices(v, k);
    osd::Far::PrimvarRefinerReal<double> primvar(*refiner);
    OsdPoint *src = buffer.data();
    for (int level = 1; level <= levels; ++level) {
        OsdPoint *dst = src + refiner->GetLevel(level - 1).GetNumVertices();
        primvar.Interpolate(level, src, dst);
        src = dst;
    }
    const int n = refiner->GetLevel(levels).GetNumVertices();
    std::vector<OsdPoint> limit(static_cast<std::size_t>(n));
    primvar.Limit(src, limit);
    OsdResult r{Mat(n, 3), Mat(n, 3)};
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            r.points(i, k) = src[i].p[k];
            r.limits(i, k) = limit[std::size_t(i)].p[k];
        }
    return r;
}

// n sectors of k rings around vertex 0 (quads, or triangles), open at the rim: an interior
// vertex of valence n, boundary vertices of every kind around it.
inline Mesh star(int n, int k, bool triangles, std::mt19937 &random)
{
    std::uniform_real_distribution<double> jitter(-0.15, 0.15);
    Mesh m;
    std::vector<Eigen::RowVector3d> points;
    std::map<std::tuple<int, int, int>, int> ids;
    const auto id = [&](int s, int i, int j) {
        std::tuple<int, int, int> key = i == 0 && j == 0 ? std::tuple{0, 0, 0}
                                        : i == 0         ? std::tuple{(s + 1) % n, j, 0}
                                                         : std::tuple{s, i, j};
        const auto it = ids.find(key);
        if (it != ids.end())
            return it->second;
        const auto [ks, ki, kj] = key;
        const double a0 = 2 * M_PI * ks / n, a1 = 2 * M_PI * (ks + 1) / n;
        const Eigen::RowVector2d u(std::cos(a0), std::sin(a0)), w(std::cos(a1), std::sin(a1));
        const Eigen::RowVector2d xy = ki * u + kj * w;
        // Drawn in sequence (z, y, x: the order GCC evaluated the arguments in before), so that
        // every compiler builds the same stars.
        const double dz = jitter(random), dy = jitter(random), dx = jitter(random);
        points.emplace_back(xy.x() + dx, xy.y() + dy, 0.3 * std::sin(xy.x()) + dz);
        ids.emplace(key, int(points.size()) - 1);
        return int(points.size()) - 1;
    };
    for (int s = 0; s < n; ++s)
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k; ++j) {
                if (!triangles) {
                    m.faces.push_back({id(s, i, j), id(s, i + 1, j), id(s, i + 1, j + 1),
                                       id(s, i, j + 1)});
                } else {
                    if (i + j <= k - 1)
                        m.faces.push_back({id(s, i, j), id(s, i + 1, j), id(s, i, j + 1)});
                    if (i + j <= k - 2)
                        m.faces.push_back(
                            {id(s, i + 1, j), id(s, i + 1, j + 1), id(s, i, j + 1)});
                }
            }
    m.vertices.resize(Eigen::Index(points.size()), 3);
    for (std::size_t v = 0; v < points.size(); ++v)
        m.vertices.row(Eigen::Index(v)) = points[v];
    return m;
}

} // namespace awb::test
