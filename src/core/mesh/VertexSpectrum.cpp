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

// The real basis of the eigenspace of a double eigenvalue `value` of S (ring x 2).
Mat eigenPlane(const Mat &S, double value)
{
    const Mat shifted = S - value * Mat::Identity(S.rows(), S.cols());
    Eigen::JacobiSVD<Mat> svd(shifted, Eigen::ComputeFullV);
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
        t = refinedTopology(r);
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
    // its cells are.
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

// ---- On the boundary and at sharp features (issue 44) -----------------------------------------

namespace {

// The generalized eigenspace of `value`, of algebraic multiplicity m: the null space of
// (S - value I)^m (its last m right singular vectors), ring x m; and whether the eigenvalue is
// defective (fewer than m independent eigenvectors: a Jordan block).
Mat generalizedSpace(const Mat &S, double value, int m, bool *defective)
{
    const Mat shifted = S - value * Mat::Identity(S.rows(), S.cols());
    Eigen::JacobiSVD<Mat> once(shifted);
    const auto &sigma = once.singularValues();
    const double tol = 1e-7 * std::max(1.0, sigma(0));
    int geometric = 0;
    while (geometric < sigma.size() && sigma(sigma.size() - 1 - geometric) < tol)
        ++geometric;
    *defective = geometric < m;
    Mat power = shifted;
    for (int k = 1; k < m; ++k)
        power = power * shifted;
    Eigen::JacobiSVD<Mat> svd(power, Eigen::ComputeFullV);
    return svd.matrixV().rightCols(m);
}

// The combinations of `basis`'s columns that vary most on `rows`: its restriction's right
// singular vectors, the largest first, as long as they are not zero there.
Mat seenOn(const Mat &basis, const std::vector<int> &rows, int most)
{
    if (basis.cols() == 0)
        return Mat(basis.rows(), 0);
    Mat restricted(Eigen::Index(rows.size()), basis.cols());
    for (std::size_t r = 0; r < rows.size(); ++r)
        restricted.row(Eigen::Index(r)) = basis.row(rows[r]);
    Eigen::JacobiSVD<Mat> svd(restricted, Eigen::ComputeFullV);
    const auto &sigma = svd.singularValues();
    Eigen::Index k = 0;
    while (k < sigma.size() && k < most && sigma(k) > 1e-6)
        ++k;
    return basis * svd.matrixV().leftCols(k);
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
    const Spectrum sp = spectrum(out.S, 1e-9);
    out.eigenvalues = sp.values;
    // The distinct eigenvalues below 1 and their eigenspaces (complex ones: no space, counted
    // in every sector).
    const double tol = 1e-9;
    struct Cluster {
        Complex value;
        Mat space;             // the generalized eigenspace (real values)
        int multiplicity = 1;  // algebraic
        bool defective = false;
    };
    std::vector<Cluster> clusters;
    // A defective eigenvalue comes out of the eigensolver split by up to eps^(1/3) (a triple
    // 1/4 as 1/4 +- 7e-9 i): values within 1e-5 are one cluster, at their mean, real when
    // its imaginary part is below 1e-5, its algebraic multiplicity the count.
    const double near = 1e-5;
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
            continue;  // the dominant eigenvalue: the limit position
        if (std::abs(value) < 1e-12)
            break;
        Cluster c{value, Mat(), multiplicity};
        if (value.imag() == 0.0)
            c.space = generalizedSpace(out.S, value.real(), multiplicity, &c.defective);
        clusters.push_back(std::move(c));
    }
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
        // The sector's eigenvalues, each as often as its eigenvectors are independent there.
        // (A defective eigenvalue, whose Jordan chain adds k lambda^k terms, is marked.)
        std::vector<std::pair<Complex, Mat>> seen;
        std::vector<char> defective;
        for (const Cluster &c : clusters) {
            if (c.space.cols() == 0) {  // complex: taken as seen
                seen.push_back({c.value, Mat()});
                defective.push_back(0);
                continue;
            }
            const Mat vectors = seenOn(c.space, sectorRows, 3);
            for (Eigen::Index k = 0; k < vectors.cols(); ++k) {
                seen.push_back({c.value, vectors.col(k)});
                defective.push_back(c.defective);
            }
            if (seen.size() >= 4)
                break;
        }
        const auto real = [&](std::size_t k) {
            return k < seen.size() && seen[k].second.size() > 0 && seen[k].first.real() > tol;
        };
        if (seen.size() >= 2) {
            v.lambda1 = std::abs(seen[0].first);
            v.lambda2 = std::abs(seen[1].first);
        }
        for (std::size_t k = 2; k < seen.size(); ++k)
            if (std::abs(seen[k].first) < v.lambda2 - 1e-7) {
                v.mu = std::abs(seen[k].first);
                break;
            }
        const bool separated =
            seen.size() < 3 || std::abs(seen[2].first) < v.lambda2 - 1e-7;
        // A Jordan block at lambda1 > lambda2 (or at lambda2 alone) multiplies its term by k:
        // the char map of the two eigenvectors still describes the limit. At lambda1 = lambda2
        // the criterion does not apply: not decided.
        // Likewise lambda2 = lambda3 inside a Jordan block: its chain's top term k lambda^k
        // dominates the others, so the moduli alone do not separate them.
        v.decided = !(seen.size() >= 2 && std::abs(seen[0].first - seen[1].first) < near
                      && defective[0])
                    && !(seen.size() >= 3 && std::abs(seen[1].first - seen[2].first) < near
                         && defective[1]);
        v.spectral = real(0) && real(1) && separated;
        if (!real(0) || !real(1))
            v.reason = coreTranslate("awb::mesh", "its largest eigenvalues below 1 are not "
                                                  "real and positive");
        else if (!v.decided)
            v.reason = formatMessage(
                coreTranslate("awb::mesh", "%1 is a defective eigenvalue (a Jordan block) among "
                                           "the two largest: Reif's criterion takes them "
                                           "diagonalizable (not decided)"),
                streamedNumber(v.lambda2));
        else if (!separated)
            v.reason = formatMessage(
                coreTranslate("awb::mesh", "lambda2 = lambda3 = %1: the tangent plane is not "
                                           "determined by the two largest"),
                streamedNumber(v.lambda2));
        if (v.spectral) {
            Mat Q(m, 2);
            Q.col(0) = seen[0].second.col(0);
            Q.col(1) = seen[1].second.col(0);
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
