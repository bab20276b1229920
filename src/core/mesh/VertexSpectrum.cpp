#include "core/mesh/VertexSpectrum.h"

#include "core/Messages.h"
#include "core/analysis/Spectrum.h"
#include "core/mesh/MeshRefine.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

namespace awb {

namespace {

// A star of n sectors around vertex 0, each a grid of K rings: quads (i, j), 0 <= i, j <= K,
// for Catmull-Clark; triangles over the points i + j <= K for Loop. Sector s runs from spoke s
// (j = 0) to spoke s + 1 (i = 0), counter-clockwise.
class Star {
public:
    static constexpr int K = 3;

    Star(MeshScheme scheme, int n) : m_scheme(scheme), m_n(n)
    {
        const bool quads = scheme == MeshScheme::CatmullClark;
        id(0, 0, 0);
        for (int s = 0; s < n; ++s)
            for (int i = 0; i <= K; ++i)
                for (int j = 0; j <= K; ++j)
                    if (quads || i + j <= K)
                        id(s, i, j);
        for (int s = 0; s < n; ++s)
            for (int i = 0; i < K; ++i)
                for (int j = 0; j < K; ++j) {
                    if (quads) {
                        m_quad[{s, i, j}] = int(m_faces.size());
                        m_faces.push_back({id(s, i, j), id(s, i + 1, j), id(s, i + 1, j + 1),
                                           id(s, i, j + 1)});
                        continue;
                    }
                    if (i + j <= K - 1)
                        m_faces.push_back({id(s, i, j), id(s, i + 1, j), id(s, i, j + 1)});
                    if (i + j <= K - 2)
                        m_faces.push_back(
                            {id(s, i + 1, j), id(s, i + 1, j + 1), id(s, i, j + 1)});
                }
    }

    int vertexCount() const { return int(m_ids.size()); }
    const std::vector<std::vector<int>> &faces() const { return m_faces; }

    // The number of point (s, i, j); made on first use.
    int id(int s, int i, int j)
    {
        const auto k = canonical(s, i, j);
        const auto it = m_ids.find(k);
        if (it != m_ids.end())
            return it->second;
        const int next = int(m_ids.size());
        m_ids.emplace(k, next);
        return next;
    }

    // The point of the refined star at (s, a, b) in the coordinates of the finer level.
    int child(const MeshTopology &t, int s, int a, int b)
    {
        const int nv = t.vertexCount(), ne = t.edgeCount();
        const auto edge = [&](int i0, int j0, int i1, int j1) {
            const int e = t.findEdge(id(s, i0, j0), id(s, i1, j1));
            if (e < 0)
                throw std::logic_error("star: no such edge");
            return nv + e;
        };
        if (a % 2 == 0 && b % 2 == 0)
            return id(s, a / 2, b / 2);
        if (a % 2 == 1 && b % 2 == 0)
            return edge((a - 1) / 2, b / 2, (a + 1) / 2, b / 2);
        if (a % 2 == 0)
            return edge(a / 2, (b - 1) / 2, a / 2, (b + 1) / 2);
        if (m_scheme == MeshScheme::Loop)
            return edge((a - 1) / 2, (b + 1) / 2, (a + 1) / 2, (b - 1) / 2);
        return nv + ne + m_quad.at({s, (a - 1) / 2, (b - 1) / 2});
    }

private:
    std::tuple<int, int, int> canonical(int s, int i, int j) const
    {
        if (i == 0 && j == 0)
            return {0, 0, 0};
        if (i == 0)
            return {(s + 1) % m_n, j, 0};
        return {s, i, j};
    }

    MeshScheme m_scheme;
    int m_n;
    std::map<std::tuple<int, int, int>, int> m_ids;
    std::map<std::tuple<int, int, int>, int> m_quad;
    std::vector<std::vector<int>> m_faces;
};

} // namespace

double closedFormSubdominant(MeshScheme scheme, int n)
{
    const double c = std::cos(2.0 * M_PI / n);
    if (scheme == MeshScheme::Loop)
        return 3.0 / 8.0 + c / 4.0;
    return (5.0 + c + std::cos(M_PI / n) * std::sqrt(2.0 * (9.0 + c))) / 16.0;
}

VertexSpectrum interiorVertexSpectrum(MeshScheme scheme, int n)
{
    if (n < 3 || n > 64)
        throw InputError(formatMessage(
            coreTranslate("awb::mesh", "a vertex's valence must be 3 to 64, got %1"), n));
    Star star(scheme, n);
    const MeshTopology topology(star.vertexCount(), star.faces());
    const Refinement refinement = refineTopology(topology, scheme);
    // The ring: the centre, then per sector the points within two faces of it.
    std::vector<std::pair<int, int>> sector;
    if (scheme == MeshScheme::CatmullClark)
        sector = {{1, 0}, {1, 1}, {2, 0}, {2, 1}, {2, 2}, {1, 2}};
    else
        sector = {{1, 0}, {2, 0}, {1, 1}};
    std::vector<int> coarse{star.id(0, 0, 0)}, fine{0};
    for (int s = 0; s < n; ++s)
        for (const auto &[i, j] : sector) {
            coarse.push_back(star.id(s, i, j));
            fine.push_back(star.child(topology, s, i, j));
        }
    std::map<int, int> column;
    for (std::size_t c = 0; c < coarse.size(); ++c)
        column[coarse[c]] = int(c);
    const auto m = Eigen::Index(coarse.size());
    VertexSpectrum out;
    out.scheme = scheme;
    out.valence = n;
    out.S = Mat::Zero(m, m);
    for (Eigen::Index r = 0; r < m; ++r)
        for (const auto &[p, w] : refinement.stencils[std::size_t(fine[std::size_t(r)])]) {
            const auto it = column.find(p);
            if (it == column.end())  // the ring is invariant: a point outside it is a bug
                throw std::logic_error("local subdivision matrix: the ring is not invariant");
            out.S(r, it->second) += w;
        }
    const Spectrum sp = spectrum(out.S, 1e-9);
    out.eigenvalues = sp.values;
    if (out.eigenvalues.size() < 4)
        return out;
    const Complex l2 = out.eigenvalues[1], l3 = out.eigenvalues[2];
    out.subdominant = std::abs(l2);
    out.subsubdominant = std::abs(out.eigenvalues[3]);
    const double tol = 1e-9;
    out.spectralC1 = std::abs(out.eigenvalues[0] - 1.0) < tol && std::abs(l2.imag()) < tol
                     && std::abs(l3.imag()) < tol && std::abs(l2 - l3) < tol && l2.real() > 0
                     && l2.real() < 1.0 - tol && out.subsubdominant < out.subdominant - tol;
    const double l2sq = out.subdominant * out.subdominant;
    out.curvature = out.subsubdominant < l2sq - tol   ? "zero"
                    : out.subsubdominant > l2sq + tol ? "unbounded"
                                                      : "bounded";
    return out;
}

} // namespace awb
