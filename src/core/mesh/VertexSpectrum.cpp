#include "core/mesh/VertexSpectrum.h"

#include "core/Decompositions.h"
#include "core/Messages.h"
#include "core/analysis/Spectrum.h"
#include "core/mesh/MeshRefine.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <set>
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

// The ring of S: the centre, then per sector the points within two faces of it.
std::vector<std::pair<int, int>> ringSector(MeshScheme scheme)
{
    if (scheme == MeshScheme::CatmullClark)
        return {{1, 0}, {1, 1}, {2, 0}, {2, 1}, {2, 2}, {1, 2}};
    return {{1, 0}, {2, 0}, {1, 1}};
}

std::vector<int> ringPoints(Star &star, MeshScheme scheme, int n)
{
    std::vector<int> ids{star.id(0, 0, 0)};
    for (int s = 0; s < n; ++s)
        for (const auto &[i, j] : ringSector(scheme))
            ids.push_back(star.id(s, i, j));
    return ids;
}

double signedArea(const Mat &p, const std::vector<int> &loop)
{
    double a = 0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
        const int u = loop[k], w = loop[(k + 1) % loop.size()];
        a += p(u, 0) * p(w, 1) - p(w, 0) * p(u, 1);
    }
    return a / 2;
}

// The real basis of the eigenspace of a double eigenvalue `value` of S (ring x 2).
Mat eigenPlane(const Mat &S, double value)
{
    const Mat shifted = S - value * Mat::Identity(S.rows(), S.cols());
    Eigen::JacobiSVD<Mat> svd(shifted, Eigen::ComputeFullV);
    return svd.matrixV().rightCols(2);
}

} // namespace

CharacteristicMap checkCharacteristicMap(MeshScheme scheme, int n, const Mat &Q)
{
    Star star(scheme, n);
    const std::vector<int> ring = ringPoints(star, scheme, n);
    if (Q.rows() != Eigen::Index(ring.size()) || Q.cols() != 2)
        throw InputError(coreTranslate("awb::mesh", "a characteristic map needs ring x 2 points"));
    // The data outside the ring is never reached by the limit over the faces around the centre
    // (their patches' support is the ring): zeros there.
    Mat data = Mat::Zero(star.vertexCount(), 2);
    for (std::size_t r = 0; r < ring.size(); ++r)
        data.row(ring[r]) = Q.row(Eigen::Index(r));
    std::vector<std::vector<int>> faces = star.faces();
    // ancestor[f]: the face of the star that face f of the current level lies in.
    std::vector<int> ancestor(faces.size());
    for (std::size_t f = 0; f < faces.size(); ++f)
        ancestor[f] = int(f);
    const MeshTopology coarse(star.vertexCount(), faces);
    std::vector<bool> around(faces.size(), false);
    for (int f : coarse.ring(0).faces)
        around[std::size_t(f)] = true;
    int vertices = star.vertexCount();
    for (int level = 0; level < 3; ++level) {
        const MeshTopology t(vertices, faces);
        Refinement r = refineTopology(t, scheme);
        data = applyStencils(r.stencils, data);
        std::vector<int> next;
        for (std::size_t f = 0; f < faces.size(); ++f)
            next.insert(next.end(), scheme == MeshScheme::Loop ? 4 : faces[f].size(), ancestor[f]);
        ancestor = std::move(next);
        faces = std::move(r.faces);
        vertices = int(r.stencils.size());
    }
    const MeshTopology fine(vertices, faces);
    const Mat limit = applyStencils(limitStencils(fine, scheme), data);
    CharacteristicMap out;
    out.minArea = std::numeric_limits<double>::infinity();
    out.maxArea = -out.minArea;
    std::map<int, int> boundaryNext;  // a -> b along the outer boundary of the faces around
    std::set<std::pair<int, int>> halfEdges;
    for (std::size_t f = 0; f < faces.size(); ++f)
        if (around[std::size_t(ancestor[f])])
            for (std::size_t k = 0; k < faces[f].size(); ++k)
                halfEdges.emplace(faces[f][k], faces[f][(k + 1) % faces[f].size()]);
    for (std::size_t f = 0; f < faces.size(); ++f) {
        if (!around[std::size_t(ancestor[f])])
            continue;
        const auto &loop = faces[f];
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const int a = loop[k], b = loop[(k + 1) % loop.size()];
            if (!halfEdges.count({b, a}))
                boundaryNext[a] = b;
        }
        std::vector<Eigen::Vector2d> cell;
        for (int v : loop)
            cell.emplace_back(limit(v, 0), limit(v, 1));
        out.cells.push_back(std::move(cell));
        out.cellSectors.push_back(ancestor[f] / (Star::K * Star::K));
        if (std::find(loop.begin(), loop.end(), 0) != loop.end()) {
            out.cellAreas.push_back(0.0);
            continue;  // at the centre the map's Jacobian vanishes
        }
        const double area = signedArea(limit, loop);
        out.cellAreas.push_back(area);
        out.minArea = std::min(out.minArea, area);
        out.maxArea = std::max(out.maxArea, area);
    }
    // The winding number of the boundary's image around the centre's image.
    const Eigen::RowVector2d centre = limit.row(0);
    double turn = 0;
    if (!boundaryNext.empty()) {
        const int start = boundaryNext.begin()->first;
        int at = start;
        for (std::size_t steps = 0; steps <= boundaryNext.size(); ++steps) {
            const int to = boundaryNext.at(at);
            out.outline.emplace_back(limit(at, 0), limit(at, 1));
            const Eigen::RowVector2d u = limit.row(at) - centre, w = limit.row(to) - centre;
            turn += std::atan2(u.x() * w.y() - u.y() * w.x(), u.dot(w));
            at = to;
            if (at == start)
                break;
        }
    }
    out.winding = int(std::lround(turn / (2 * M_PI)));
    return out;
}

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
    const std::vector<int> coarse = ringPoints(star, scheme, n);
    std::vector<int> fine{0};
    for (int s = 0; s < n; ++s)
        for (const auto &[i, j] : ringSector(scheme))
            fine.push_back(star.child(topology, s, i, j));
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
    if (out.spectralC1) {
        const CharacteristicMap map =
            checkCharacteristicMap(scheme, n, eigenPlane(out.S, l2.real()));
        out.characteristicRegular = map.regular();
        out.characteristicInjective = map.injective();
        out.characteristic = map;
    }
    out.c1 = out.spectralC1 && out.characteristicRegular && out.characteristicInjective;
    const double l2sq = out.subdominant * out.subdominant;
    out.curvature = out.subsubdominant < l2sq - tol   ? "zero"
                    : out.subsubdominant > l2sq + tol ? "unbounded"
                                                      : "bounded";
    return out;
}

std::shared_ptr<const VertexSpectrum> sharedVertexSpectrum(MeshScheme scheme, int n)
{
    static std::mutex mutex;
    static std::map<std::pair<MeshScheme, int>, std::shared_ptr<const VertexSpectrum>> known;
    {
        std::lock_guard<std::mutex> lock(mutex);
        if (const auto it = known.find({scheme, n}); it != known.end())
            return it->second;
    }
    // Computed outside the lock (two threads may compute the same one: the first kept wins).
    auto s = std::make_shared<const VertexSpectrum>(interiorVertexSpectrum(scheme, n));
    std::lock_guard<std::mutex> lock(mutex);
    return known.emplace(std::pair{scheme, n}, std::move(s)).first->second;
}

std::vector<VertexSpectrum> valenceSpectra(MeshScheme scheme, int from, int to)
{
    std::vector<VertexSpectrum> out;
    for (int n = from; n <= to; ++n)
        out.push_back(*sharedVertexSpectrum(scheme, n));
    return out;
}

} // namespace awb
