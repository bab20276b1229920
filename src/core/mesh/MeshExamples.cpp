#include "core/mesh/MeshExamples.h"

#include "core/Messages.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace awb {

void orientOutward(Mesh &m)
{
    const Eigen::RowVector3d centre = m.vertices.colwise().mean();
    for (auto &f : m.faces) {
        Eigen::RowVector3d c = Eigen::RowVector3d::Zero();
        for (int v : f)
            c += m.vertices.row(v);
        c /= double(f.size());
        const Eigen::Vector3d a = (m.vertices.row(f[1]) - m.vertices.row(f[0])).transpose();
        const Eigen::Vector3d b = (m.vertices.row(f[2]) - m.vertices.row(f[0])).transpose();
        if (a.cross(b).dot((c - centre).transpose()) < 0)
            std::reverse(f.begin(), f.end());
    }
}

Mesh cubeMesh()
{
    Mesh m;
    m.vertices.resize(8, 3);
    for (int v = 0; v < 8; ++v)
        m.vertices.row(v) << (v & 1 ? 1 : -1), (v & 2 ? 1 : -1), (v & 4 ? 1 : -1);
    m.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    orientOutward(m);
    return m;
}

Mesh tetrahedronMesh()
{
    Mesh m;
    m.vertices.resize(4, 3);
    m.vertices << 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1;
    m.faces = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    orientOutward(m);
    return m;
}

Mesh octahedronMesh()
{
    Mesh m;
    m.vertices.resize(6, 3);
    m.vertices << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
    for (int x : {0, 1})
        for (int y : {2, 3})
            for (int z : {4, 5})
                m.faces.push_back({x, y, z});
    orientOutward(m);
    return m;
}

// The twelve vertices (0, +-1, +-phi) and their cyclic shifts; a face is three vertices at
// distance 2 of each other.
Mesh icosahedronMesh()
{
    const double p = (1 + std::sqrt(5.0)) / 2;
    Mesh m;
    m.vertices.resize(12, 3);
    int k = 0;
    for (int a : {-1, 1})
        for (int b : {-1, 1}) {
            m.vertices.row(k++) << 0, a, b * p;
            m.vertices.row(k++) << a, b * p, 0;
            m.vertices.row(k++) << b * p, 0, a;
        }
    const auto edge = [&](int i, int j) {
        return std::abs((m.vertices.row(i) - m.vertices.row(j)).norm() - 2) < 1e-9;
    };
    for (int i = 0; i < 12; ++i)
        for (int j = i + 1; j < 12; ++j)
            for (int l = j + 1; l < 12; ++l)
                if (edge(i, j) && edge(j, l) && edge(i, l))
                    m.faces.push_back({i, j, l});
    orientOutward(m);
    return m;
}

Mesh pentagonalPrismMesh()
{
    Mesh m;
    m.vertices.resize(10, 3);
    for (int k = 0; k < 5; ++k) {
        const double a = 2 * M_PI * k / 5;
        m.vertices.row(k) << std::cos(a), std::sin(a), 1;
        m.vertices.row(k + 5) << std::cos(a), std::sin(a), -1;
    }
    m.faces = {{0, 1, 2, 3, 4}, {5, 6, 7, 8, 9}};
    for (int k = 0; k < 5; ++k)
        m.faces.push_back({k, (k + 1) % 5, (k + 1) % 5 + 5, k + 5});
    orientOutward(m);
    return m;
}

namespace {

Mesh gridVertices(int w, int h)
{
    if (w < 1 || h < 1 || w > 1000 || h > 1000)
        throw InputError(formatMessage(
            coreTranslate("awb::mesh", "a grid needs 1 to 1000 quads a side, got %1 x %2"), w, h));
    Mesh m;
    m.vertices.resize((w + 1) * (h + 1), 3);
    for (int j = 0; j <= h; ++j)
        for (int i = 0; i <= w; ++i)
            m.vertices.row(j * (w + 1) + i) << i, j, std::sin(1.3 * i + 0.7 * j);
    return m;
}

} // namespace

Mesh gridMesh(int w, int h, bool triangles)
{
    Mesh m = gridVertices(w, h);
    const auto id = [w](int i, int j) { return j * (w + 1) + i; };
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            if (triangles) {
                m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
                m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
            } else {
                m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
            }
        }
    return m;
}

Mesh uvSphereMesh(int segments, int rings)
{
    Mesh mesh;
    mesh.vertices.resize(2 + (rings - 1) * segments, 3);
    mesh.vertices.row(0) << 0, 0, 1;
    const auto at = [&](int ring, int k) { return 1 + (ring - 1) * segments + k % segments; };
    for (int ring = 1; ring < rings; ++ring)
        for (int k = 0; k < segments; ++k) {
            const double th = M_PI * ring / rings, ph = 2 * M_PI * k / segments;
            mesh.vertices.row(at(ring, k)) << std::sin(th) * std::cos(ph),
                std::sin(th) * std::sin(ph), std::cos(th);
        }
    const int south = int(mesh.vertices.rows()) - 1;
    mesh.vertices.row(south) << 0, 0, -1;
    for (int k = 0; k < segments; ++k) {
        mesh.faces.push_back({0, at(1, k), at(1, k + 1)});
        for (int ring = 1; ring + 1 < rings; ++ring)
            mesh.faces.push_back({at(ring, k), at(ring + 1, k), at(ring + 1, k + 1), at(ring, k + 1)});
        mesh.faces.push_back({at(rings - 1, k), south, at(rings - 1, k + 1)});
    }
    return mesh;
}

Mesh torusMesh(int n, int m, bool triangles)
{
    Mesh mesh;
    mesh.vertices.resize(n * m, 3);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / m;
            mesh.vertices.row(i * m + j) << (3 + std::cos(v)) * std::cos(u),
                (3 + std::cos(v)) * std::sin(u), std::sin(v);
        }
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            const int a = i * m + j, b = ((i + 1) % n) * m + j, c = ((i + 1) % n) * m + (j + 1) % m,
                      d = i * m + (j + 1) % m;
            if (triangles) {
                mesh.faces.push_back({a, b, c});
                mesh.faces.push_back({a, c, d});
            } else {
                mesh.faces.push_back({a, b, c, d});
            }
        }
    return mesh;
}

Mesh diagonalGridMesh(int w, int h, unsigned seed)
{
    Mesh m = gridVertices(w, h);
    const auto id = [w](int i, int j) { return j * (w + 1) + i; };
    std::uint32_t state = seed * 2654435761u + 12345u;
    const auto next = [&state] {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return state;
    };
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            if (next() & 1) {
                m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
                m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
            } else {
                m.faces.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
                m.faces.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
            }
        }
    for (Eigen::Index v = 0; v < m.vertices.rows(); ++v)
        m.vertices(v, 2) += 0.25 * (double(next() % 1000) / 1000.0 - 0.5);
    return m;
}

const std::vector<std::string> &exampleMeshNames()
{
    static const std::vector<std::string> names{"cube",       "tetrahedron",      "octahedron",
                                                "icosahedron", "pentagonal-prism", "grid",
                                                "diagonal-grid"};
    return names;
}

Mesh exampleMesh(const std::string &name)
{
    if (name == "cube")
        return cubeMesh();
    if (name == "tetrahedron")
        return tetrahedronMesh();
    if (name == "octahedron")
        return octahedronMesh();
    if (name == "icosahedron")
        return icosahedronMesh();
    if (name == "pentagonal-prism")
        return pentagonalPrismMesh();
    if (name == "grid")
        return gridMesh(4, 4, false);
    if (name == "diagonal-grid")
        return diagonalGridMesh(6, 6, 1);
    throw InputError(formatMessage(coreTranslate("awb::mesh", "there is no example mesh '%1'"),
                                   name));
}

} // namespace awb
