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

    // `n` sectors; closed (around an interior vertex) or open (a boundary vertex: spokes 0 and
    // n are its boundary edges).
    Star(MeshScheme scheme, int n, bool closed = true) : m_scheme(scheme), m_n(n), m_closed(closed)
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
            return {m_closed ? (s + 1) % m_n : s + 1, j, 0};
        return {s, i, j};
    }

    MeshScheme m_scheme;
    int m_n;
    bool m_closed = true;
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

// The local subdivision matrix: row r is the stencil of the refined ring's point fine[r] over
// the ring's points coarse[...] (the ring is invariant: a point outside it is a bug).
Mat localMatrix(const Refinement &refinement, const std::vector<int> &coarse,
                const std::vector<int> &fine)
{
    std::map<int, int> column;
    for (std::size_t c = 0; c < coarse.size(); ++c)
        column[coarse[c]] = int(c);
    const auto m = Eigen::Index(coarse.size());
    Mat S = Mat::Zero(m, m);
    for (Eigen::Index r = 0; r < m; ++r)
        for (const auto &[p, w] : refinement.stencils[std::size_t(fine[std::size_t(r)])]) {
            const auto it = column.find(p);
            if (it == column.end())
                throw std::logic_error("local subdivision matrix: the ring is not invariant");
            S(r, it->second) += w;
        }
    return S;
}

// The real basis of the eigenspace of a double eigenvalue `value` of S (ring x 2). The
// divide-and-conquer SVD: a valence-64 pole's 385 x 385 matrix in a fifth of Jacobi's time
// (below 16 columns it is Jacobi's), its null space as exact. The sharp features' spaces below
// keep Jacobi's (their stars are small); their verdicts are the same under either (the table of
// valence 3 to 8, both schemes, compared).
Mat eigenPlane(const Mat &S, double value)
{
    const Mat shifted = S - value * Mat::Identity(S.rows(), S.cols());
    Eigen::BDCSVD<Mat> svd(shifted, Eigen::ComputeFullV);
    return svd.matrixV().rightCols(2);
}

} // namespace

namespace {

bool segmentsCross(const Eigen::RowVector2d &a, const Eigen::RowVector2d &b,
                   const Eigen::RowVector2d &c, const Eigen::RowVector2d &d)
{
    const auto side = [](const Eigen::RowVector2d &p, const Eigen::RowVector2d &q,
                         const Eigen::RowVector2d &r) {
        return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
    };
    const double d1 = side(c, d, a), d2 = side(c, d, b), d3 = side(a, b, c), d4 = side(a, b, d);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// The characteristic map of `Q` (ring x 2) over the faces around the star's centre in the
// sectors marked in `chosen`, the star carrying `tags`. A whole closed star is checked by the
// winding number of its outer boundary's image around the centre's image; a sector (a wedge
// whose boundary passes through the centre) by the simplicity of its boundary's image: a map
// whose Jacobian keeps one sign and whose boundary's image is a simple curve is injective.
CharacteristicMap characteristicMapOn(Star &star, MeshScheme scheme, const MeshTags &tags,
                                      const std::vector<int> &ring, const Mat &Q,
                                      const std::vector<char> &chosen)
{
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
    MeshTopology t =
        checkMesh(Mesh{Mat::Zero(star.vertexCount(), 3), faces, tags}, scheme);
    std::vector<bool> around(faces.size(), false);
    bool whole = true;
    for (std::size_t k = 0; k < chosen.size(); ++k)
        whole = whole && chosen[k];
    whole = whole && !t.onBoundary(0);
    for (int f : t.ring(0).faces)
        around[std::size_t(f)] = chosen[std::size_t(f / (Star::K * Star::K))] != 0;
    for (int level = 0; level < 3; ++level) {
        Refinement r = refineTopology(t, scheme);
        data = applyStencils(r.stencils, data);
        std::vector<int> next;
        for (std::size_t f = 0; f < faces.size(); ++f)
            next.insert(next.end(), scheme == MeshScheme::Loop ? 4 : faces[f].size(), ancestor[f]);
        ancestor = std::move(next);
        faces = r.faces.toVectors();
        t = refinedTopology(t, r);
    }
    const Mat limit = applyStencils(limitStencils(t, scheme), data);
    CharacteristicMap out;
    out.minArea = std::numeric_limits<double>::infinity();
    out.maxArea = -out.minArea;
    std::map<int, int> boundaryNext;  // a -> b along the boundary of the faces chosen
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
    // The boundary's image, once around.
    std::vector<int> outline;
    if (!boundaryNext.empty()) {
        const int start = whole ? boundaryNext.begin()->first : 0;
        int at = start;
        for (std::size_t steps = 0; steps <= boundaryNext.size(); ++steps) {
            const auto it = boundaryNext.find(at);
            if (it == boundaryNext.end())
                break;
            outline.push_back(at);
            out.outline.emplace_back(limit(at, 0), limit(at, 1));
            at = it->second;
            if (at == start)
                break;
        }
    }
    if (whole) {
        // The winding number of the boundary's image around the centre's image.
        const Eigen::RowVector2d centre = limit.row(0);
        double turn = 0;
        for (std::size_t k = 0; k < outline.size(); ++k) {
            const Eigen::RowVector2d u = limit.row(outline[k]) - centre,
                                     w = limit.row(outline[(k + 1) % outline.size()]) - centre;
            turn += std::atan2(u.x() * w.y() - u.y() * w.x(), u.dot(w));
        }
        out.winding = int(std::lround(turn / (2 * M_PI)));
        return out;
    }
    // A wedge: its boundary's image simple (no two segments but neighbours cross), wound as
    // its cells are. (A crease on which both vectors of the map vanish lands on the centre's
    // image, where which segments cross is rounding's: such sectors are judged before, on the
    // eigenvectors themselves, by leavesThePlane.)
    const std::size_t m = outline.size();
    bool simple = m >= 3 && m == boundaryNext.size();
    for (std::size_t i = 0; simple && i < m; ++i)
        for (std::size_t j = i + 2; simple && j < m; ++j) {
            if (i == 0 && j == m - 1)
                continue;
            simple = !segmentsCross(limit.row(outline[i]), limit.row(outline[(i + 1) % m]),
                                    limit.row(outline[j]), limit.row(outline[(j + 1) % m]));
        }
    double area = 0;
    for (std::size_t k = 0; k < m; ++k) {
        const Eigen::RowVector2d u = limit.row(outline[k]), w = limit.row(outline[(k + 1) % m]);
        area += u.x() * w.y() - w.x() * u.y();
    }
    out.winding = simple ? (area > 0 ? 1 : -1) : 0;
    return out;
}

} // namespace

CharacteristicMap checkCharacteristicMap(MeshScheme scheme, int n, const Mat &Q)
{
    Star star(scheme, n);
    return characteristicMapOn(star, scheme, {}, ringPoints(star, scheme, n), Q,
                               std::vector<char>(std::size_t(n), 1));
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
    VertexSpectrum out;
    out.scheme = scheme;
    out.valence = n;
    out.S = localMatrix(refinement, coarse, fine);
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
        // The plane's basis is any of the eigenspace: taken so that the map keeps the star's
        // orientation (the same picture and signs whichever basis the decomposition gave).
        Mat plane = eigenPlane(out.S, l2.real());
        CharacteristicMap map = checkCharacteristicMap(scheme, n, plane);
        if (map.winding < 0 || (map.winding == 0 && map.maxArea < 0)) {
            plane.col(1) = -plane.col(1);
            map = checkCharacteristicMap(scheme, n, plane);
        }
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

// ---- On the boundary and at sharp features (issue 44) -----------------------------------------

namespace {

// The generalized eigenspace of `value`, of algebraic multiplicity m: the null space of
// (S - value I)^m (its last m right singular vectors), ring x m; and how many independent
// eigenvectors it holds (fewer than m: a Jordan block).
Mat generalizedSpace(const Mat &S, double value, int m, int *geometric)
{
    const Mat shifted = S - value * Mat::Identity(S.rows(), S.cols());
    Eigen::JacobiSVD<Mat> once(shifted);
    const auto &sigma = once.singularValues();
    const double tol = 1e-7 * std::max(1.0, sigma(0));
    *geometric = 0;
    while (*geometric < sigma.size() && sigma(sigma.size() - 1 - *geometric) < tol)
        ++*geometric;
    Mat power = shifted;
    for (int k = 1; k < m; ++k)
        power = power * shifted;
    Eigen::JacobiSVD<Mat> svd(power, Eigen::ComputeFullV);
    return svd.matrixV().rightCols(m);
}

// The eigenvectors of the real eigenvalue `value`, k of them: the last k right singular
// vectors of S - value I.
Mat eigenvectorsOf(const Mat &S, double value, int k)
{
    Eigen::JacobiSVD<Mat> svd(S - value * Mat::Identity(S.rows(), S.cols()), Eigen::ComputeFullV);
    return svd.matrixV().rightCols(k);
}

// The eigenvector at the top of the one Jordan chain of a generalized eigenspace `space` (of
// the real eigenvalue `value`): (S - value I) maps the space onto it.
Vec chainTop(const Mat &S, double value, const Mat &space)
{
    const Mat image = S * space - value * space;
    Eigen::JacobiSVD<Mat> svd(image, Eigen::ComputeThinU);
    return svd.matrixU().col(0);
}

// A distinct eigenvalue of S below 1 in modulus (and not 0): its algebraic multiplicity, and
// for a real one among the two largest its independent eigenvectors and generalized eigenspace
// (the others keep geometric = multiplicity and no space).
struct Cluster {
    Complex value;
    Mat space;
    int multiplicity = 1;
    int geometric = 1;
    bool real() const { return value.imag() == 0.0; }
    bool defective() const { return geometric < multiplicity; }
};

// The clusters of S, largest modulus first. A defective eigenvalue comes out of the eigensolver
// split by up to eps^(1/3) (a triple 1/4 as 1/4 +- 7e-9 i): values within 1e-5 are one cluster,
// at their mean, real when its imaginary part is below 1e-5, its algebraic multiplicity the
// count. The dominant eigenvalue 1 (the limit position) is left out.
std::vector<Cluster> eigenClusters(const Mat &S)
{
    const Spectrum sp = spectrum(S, 1e-9);
    const double near = 1e-5;
    std::vector<Cluster> clusters;
    for (std::size_t k = 0; k < sp.values.size();) {
        std::size_t end = k + 1;
        Complex sum = sp.values[k];
        while (end < sp.values.size() && std::abs(sp.values[end] - sp.values[k]) < near)
            sum += sp.values[end++];
        Complex value = sum / double(end - k);
        const int multiplicity = int(end - k);
        k = end;
        if (std::abs(value.imag()) < near)
            value = value.real();
        if (std::abs(value - 1.0) < near)
            continue;
        if (std::abs(value) < 1e-12)
            break;
        Cluster c{value, Mat(), multiplicity, multiplicity};
        if (c.real() && clusters.size() < 2)  // readPair reads the two largest' structure only
            c.space = generalizedSpace(S, value.real(), multiplicity, &c.geometric);
        clusters.push_back(std::move(c));
    }
    return clusters;
}

// What a sector's two largest eigenvalues below 1 say (Reif 1995; the Jordan blocks by the
// shear argument of Peters and Reif 2008), from the clusters of the sector's own matrix. The
// limit's ring at level k is sum_j lambda_j^k psi_j c_j, and a Jordan chain v, w (S w = lambda
// w + v) adds k lambda^(k-1) psi_v c_w. So (docs/mathematics.md, "Jordan blocks"):
//   - lambda1 > lambda2, each simple, or lambda1 = lambda2 with two eigenvectors: Reif's
//     criterion on the two eigenvectors;
//   - a chain at lambda2 < lambda1: the top term k lambda2^(k-1) psi_v c_w of its one chain
//     dominates lambda2's others, the tangent plane converges (as 1/k) and the scaled rings
//     tend to the map of v1 and the chain's top eigenvector v;
//   - lambda1 = lambda2 with one eigenvector, a chain of two: the ring is lambda^k (psi_v (c_v
//     + k/lambda c_w) + psi_w c_w); in the plane of c_v, c_w its coordinates are the map
//     (psi_v, psi_w) sheared by k / lambda, a linear map of determinant 1: the criterion on the
//     eigenvector and the generalized eigenvector;
//   - lambda1 = lambda2 with two eigenvectors and one chain of two: the normal is c_w x c_a
//     (the c_v terms cancel) and the scaled rings tend to the map of the two eigenvectors;
//   - lambda2 = lambda3 with independent eigenvectors and no chain: the tangent plane is not
//     determined (not C1 for generic data);
//   - longer chains, or more than one: not decided.
struct PairVerdict {
    double lambda1 = 0.0, lambda2 = 0.0, mu = 0.0;
    bool real = false, separated = false, decided = true;
    std::string chain;  // how a Jordan chain was read, or ""
    Mat plane;          // rows x 2: the two vectors of the map, when real and separated
};

PairVerdict readPair(const Mat &S, const std::vector<Cluster> &clusters)
{
    PairVerdict p;
    if (clusters.empty())
        return p;
    const Cluster &a = clusters[0];
    const Cluster *b = a.multiplicity >= 2 ? &a : clusters.size() > 1 ? &clusters[1] : nullptr;
    if (!b)
        return p;
    p.lambda1 = std::abs(a.value);
    p.lambda2 = std::abs(b->value);
    // mu: the largest modulus below lambda2.
    for (const Cluster &c : clusters)
        if (std::abs(c.value) < p.lambda2 - 1e-7) {
            p.mu = std::abs(c.value);
            break;
        }
    p.real = a.real() && b->real() && a.value.real() > 0 && b->value.real() > 0;
    if (!p.real)
        return p;
    const int chains = b->multiplicity - b->geometric;  // generalized vectors beyond the eigenvectors
    p.plane.resize(S.rows(), 2);
    if (b == &a) {  // lambda1 = lambda2 = lambda
        const double lambda = a.value.real();
        if (a.geometric == 2 && chains <= 1) {
            p.plane = eigenvectorsOf(S, lambda, 2);
        } else if (a.geometric == 1 && a.multiplicity == 2) {
            p.plane = a.space;  // the eigenvector and its chain's next
        } else {
            p.decided = chains == 0;  // three or more eigenvectors: lambda2 = lambda3
            return p;
        }
        p.separated = true;
        if (chains > 0)
            p.chain = formatMessage(
                a.geometric == 1
                    ? coreTranslate("awb::mesh", "lambda1 = lambda2 = %1 is a Jordan block: the "
                                                 "rings shear, and Reif's criterion holds for "
                                                 "the map of its eigenvector and generalized "
                                                 "eigenvector")
                    : coreTranslate("awb::mesh", "lambda1 = lambda2 = %1 has two eigenvectors "
                                                 "and a Jordan chain: the normal and the rings "
                                                 "follow the map of the two eigenvectors"),
                streamedNumber(p.lambda1));
        return p;
    }
    // lambda1 simple; lambda2's one chain, if any, in charge through its top.
    const double lambda2 = b->value.real();
    if (b->geometric > 1 && chains != 1) {
        p.decided = chains == 0;  // lambda2 = lambda3 with independent eigenvectors
        return p;
    }
    p.separated = true;
    p.plane.col(0) = eigenvectorsOf(S, a.value.real(), 1);
    p.plane.col(1) = b->geometric == 1 ? Vec(eigenvectorsOf(S, lambda2, 1))
                                       : chainTop(S, lambda2, b->space);
    if (chains > 0)
        p.chain = formatMessage(
            coreTranslate("awb::mesh", "lambda2 = %1 is a Jordan block: its chain's top term "
                                       "k lambda2^k dominates, and Reif's criterion holds for the "
                                       "map of the eigenvectors of lambda1 and of the chain's "
                                       "top"),
            streamedNumber(p.lambda2));
    return p;
}

// Whether a crease that bounds a sector leaves the tangent plane (Biermann, Grundel and Zorin
// 2015 treat the boundary): the crease's points one level finer are combinations of its own,
// so an eigenvector whose eigenvalue is not one of the crease curve's vanishes on it. When both
// vectors of the map vanish on a crease, the crease comes into the vertex along its own
// tangent -- the coefficient of a smaller eigenvalue, independent of the plane's two for
// generic data -- and the surface folds there (the characteristic map sends the crease to the
// vertex; tests/core/test_mesh_creases.cpp measures the fold on limit surfaces). One case keeps
// the tangent in the plane: lambda2's chain v, w with v vanishing on the crease and w not, and
// no other eigenvector of lambda2 on it: the crease then moves as lambda2^k w c_w, and c_w is the
// plane's (the ring's top term is k lambda2^(k-1) v c_w). The first crease that leaves the plane
// (its spoke), or nothing.
std::optional<int> leavesThePlane(
    const Mat &S, const std::vector<Cluster> &clusters, const PairVerdict &pair,
    const std::vector<std::pair<int, std::vector<Eigen::Index>>> &creases)
{
    const auto vanishes = [](const Mat &vectors, const std::vector<Eigen::Index> &rows) {
        const double scale = vectors.cwiseAbs().maxCoeff();
        return vectors(rows, Eigen::all).cwiseAbs().maxCoeff() <= 1e-8 * scale;
    };
    for (const auto &[spoke, rows] : creases) {
        if (!vanishes(pair.plane, rows))
            continue;
        const Cluster *b = clusters.size() > 1 && clusters[0].multiplicity < 2 ? &clusters[1]
                                                                               : nullptr;
        const bool carried = b && b->defective() && b->real() && b->space.size() > 0
                             && !vanishes(b->space, rows)
                             && vanishes(eigenvectorsOf(S, b->value.real(), b->geometric), rows);
        if (!carried)
            return spoke;
    }
    return std::nullopt;
}

} // namespace

SharpVertexSpectrum sharpVertexSpectrum(MeshScheme scheme, const SharpNeighbourhood &star)
{
    const int n = star.valence;
    if (n < 3 || n > 64 || int(star.sharpEdges.size()) != n)
        throw InputError(formatMessage(
            coreTranslate("awb::mesh", "a vertex's valence must be 3 to 64, got %1"), n));
    const int sectors = star.boundary ? n - 1 : n;
    Star s(scheme, sectors, !star.boundary);
    // The creases: every sharp spoke, straight through the star; the corner tag.
    MeshTags tags;
    const int spokes = n;  // spoke k is ring edge k
    std::vector<char> sharp(std::size_t(spokes), 0);
    for (int k = 0; k < spokes; ++k) {
        const bool border = star.boundary && (k == 0 || k == n - 1);
        sharp[std::size_t(k)] = star.sharpEdges[std::size_t(k)] || border;
        if (!star.sharpEdges[std::size_t(k)] || border)
            continue;
        tags.edges.push_back({0, s.id(k, 1, 0), kSharpnessInfinite});
        tags.edges.push_back({s.id(k, 1, 0), s.id(k, 2, 0), kSharpnessInfinite});
        tags.edges.push_back({s.id(k, 2, 0), s.id(k, 3, 0), kSharpnessInfinite});
    }
    if (star.sharpVertex)
        tags.vertices.push_back({0, kSharpnessInfinite});
    const MeshTopology topology =
        checkMesh(Mesh{Mat::Zero(s.vertexCount(), 3), s.faces(), tags}, scheme);
    const Refinement refinement = refineTopology(topology, scheme);
    std::vector<int> coarse = ringPoints(s, scheme, sectors);
    std::vector<int> fine{0};
    for (int k = 0; k < sectors; ++k)
        for (const auto &[i, j] : ringSector(scheme))
            fine.push_back(s.child(topology, k, i, j));
    if (star.boundary)  // the last spoke, the boundary's other side
        for (int i : {1, 2}) {
            coarse.push_back(s.id(sectors, i, 0));
            fine.push_back(s.child(topology, sectors, i, 0));
        }
    std::map<int, int> column;
    for (std::size_t c = 0; c < coarse.size(); ++c)
        column[coarse[c]] = int(c);
    const auto m = Eigen::Index(coarse.size());
    SharpVertexSpectrum out;
    out.scheme = scheme;
    out.neighbourhood = star;
    out.rule = topology.rule(0);
    out.S = localMatrix(refinement, coarse, fine);
    out.eigenvalues = spectrum(out.S, 1e-9).values;
    // The sectors: runs of faces between sharp spokes.
    std::vector<int> cuts;
    for (int k = 0; k < spokes; ++k)
        if (sharp[std::size_t(k)])
            cuts.push_back(k);
    std::vector<std::pair<int, int>> runs;  // (first face, faces)
    if (star.boundary) {
        for (std::size_t c = 0; c + 1 < cuts.size(); ++c)
            runs.push_back({cuts[c], cuts[c + 1] - cuts[c]});
    } else if (cuts.size() < 2) {
        runs.push_back({0, n});
    } else {
        for (std::size_t c = 0; c < cuts.size(); ++c) {
            const int next = c + 1 < cuts.size() ? cuts[c + 1] : cuts[0] + n;
            runs.push_back({cuts[c], next - cuts[c]});
        }
    }
    const std::vector<std::pair<int, int>> perSector = ringSector(scheme);
    const double tol = 1e-9;
    bool failed = false, undecided = false;
    int worst = -1;  // the worst curvature verdict: 0 zero, 1 bounded, 2 unbounded
    for (const auto &[first, count] : runs) {
        SectorVerdict v;
        v.firstFace = first;
        v.faces = count;
        std::vector<char> chosen(std::size_t(sectors), 0);
        std::set<int> rows{0};
        for (int f = first; f < first + count; ++f) {
            const int k = f % sectors;
            chosen[std::size_t(k)] = 1;
            for (const auto &[i, j] : perSector)
                rows.insert(column.at(s.id(k, i, j)));
            for (int j : {1, 2})
                rows.insert(column.at(s.id(k, 0, j)));
        }
        const std::vector<int> sectorRows(rows.begin(), rows.end());
        // The sector's points one level finer are combinations of its own (the creases that
        // bound it follow their curve rule): its own matrix, whose eigenvalues are those seen
        // on it, and whose Jordan blocks are its own.
        const auto r = Eigen::Index(sectorRows.size());
        const Mat sectorS = out.S(sectorRows, sectorRows);
        const double outside = (out.S(sectorRows, Eigen::all).cwiseAbs().rowwise().sum()
                                - sectorS.cwiseAbs().rowwise().sum())
                                   .maxCoeff();
        if (outside > 1e-12)
            throw std::logic_error("sharpVertexSpectrum: a sector's points depend on others");
        const std::vector<Cluster> clusters = eigenClusters(sectorS);
        const PairVerdict pair = readPair(sectorS, clusters);
        v.lambda1 = pair.lambda1;
        v.lambda2 = pair.lambda2;
        v.mu = pair.mu;
        v.decided = pair.decided;
        v.chain = pair.chain;
        v.spectral = pair.real && pair.separated;
        if (!pair.real)
            v.reason = coreTranslate("awb::mesh", "its largest eigenvalues below 1 are not "
                                                  "real and positive");
        else if (!v.decided)
            v.reason = formatMessage(
                coreTranslate("awb::mesh", "%1 is a defective eigenvalue with a Jordan chain "
                                           "longer than two, or more than one chain: Reif's "
                                           "criterion is not decided there"),
                streamedNumber(v.lambda2));
        else if (!pair.separated)
            v.reason = formatMessage(
                coreTranslate("awb::mesh", "lambda2 = lambda3 = %1: the tangent plane is not "
                                           "determined by the two largest"),
                streamedNumber(v.lambda2));
        // The creases that bound the sector, each by its two ring points (sector rows).
        std::vector<std::pair<int, std::vector<Eigen::Index>>> creases;
        if (star.boundary || cuts.size() >= 2) {
            const auto local = [&](int point) {
                const int row = column.at(point);
                const auto at = std::lower_bound(sectorRows.begin(), sectorRows.end(), row);
                if (at == sectorRows.end() || *at != row)
                    throw std::logic_error("sharpVertexSpectrum: a crease outside its sector");
                return Eigen::Index(at - sectorRows.begin());
            };
            const int last = (first + count - 1) % sectors;
            creases.push_back({first % spokes, {local(s.id(first % sectors, 1, 0)),
                                                local(s.id(first % sectors, 2, 0))}});
            creases.push_back({(first + count) % spokes,
                               {local(s.id(last, 0, 1)), local(s.id(last, 0, 2))}});
        }
        if (v.spectral)
            if (const auto spoke = leavesThePlane(sectorS, clusters, pair, creases)) {
                v.creaseInPlane = false;
                v.reason = formatMessage(
                    coreTranslate("awb::mesh",
                                  "the eigenvectors of lambda1 and lambda2 vanish on the crease "
                                  "of edge %1, whose own tangent (a smaller eigenvalue) leaves "
                                  "their tangent plane: not C1 for generic data"),
                    *spoke);
            }
        if (v.spectral && v.creaseInPlane) {
            Mat Q = Mat::Zero(m, 2);
            for (Eigen::Index i = 0; i < r; ++i)
                Q.row(sectorRows[std::size_t(i)]) = pair.plane.row(i);
            v.map = characteristicMapOn(s, scheme, tags, coarse, Q, chosen);
            v.regular = v.map.regular();
            v.injective = v.map.injective();
            if (!v.regular)
                v.reason = coreTranslate("awb::mesh", "its characteristic map is not regular");
            else if (!v.injective)
                v.reason = coreTranslate("awb::mesh", "its characteristic map is not injective");
        }
        if (!v.decided)
            undecided = true;
        else
            failed = failed || !v.c1();
        const double l2sq = v.lambda2 * v.lambda2;
        const int verdict = v.mu < l2sq - tol ? 0 : v.mu > l2sq + tol ? 2 : 1;
        v.curvature = verdict == 0 ? "zero" : verdict == 2 ? "unbounded" : "bounded";
        worst = std::max(worst, verdict);
        out.sectors.push_back(std::move(v));
    }
    if (failed)
        out.c1 = false;
    else if (!undecided)
        out.c1 = true;
    out.curvature = worst == 0 ? "zero" : worst == 2 ? "unbounded" : worst == 1 ? "bounded" : "";
    return out;
}

std::shared_ptr<const SharpVertexSpectrum> sharedSharpVertexSpectrum(
    MeshScheme scheme, const SharpNeighbourhood &star)
{
    static std::mutex mutex;
    static std::map<std::pair<MeshScheme, SharpNeighbourhood>,
                    std::shared_ptr<const SharpVertexSpectrum>>
        known;
    {
        std::lock_guard<std::mutex> lock(mutex);
        if (const auto it = known.find({scheme, star}); it != known.end())
            return it->second;
    }
    auto s = std::make_shared<const SharpVertexSpectrum>(sharpVertexSpectrum(scheme, star));
    std::lock_guard<std::mutex> lock(mutex);
    return known.emplace(std::pair{scheme, star}, std::move(s)).first->second;
}

} // namespace awb
