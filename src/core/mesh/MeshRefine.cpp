#include "core/mesh/MeshRefine.h"

#include "core/Messages.h"
#include "core/mesh/MeshRules.h"
#include "core/mesh/MeshSheets.h"
#include "core/mesh/MeshTags.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace awb {

void mergeStencil(MeshStencil &s)
{
    std::sort(s.begin(), s.end());
    std::size_t n = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (n > 0 && s[n - 1].first == s[i].first)
            s[n - 1].second += s[i].second;
        else
            s[n++] = s[i];
    }
    s.resize(n);
}

namespace {

using namespace meshrules;

MeshStencil merged(MeshStencil s)
{
    mergeStencil(s);
    return s;
}

void addFaceCentroid(MeshStencil &s, std::span<const int> face, double weight)
{
    for (int v : face)
        s.emplace_back(v, weight / double(face.size()));
}

// The other ends of the first and last sharp edges at v (its crease when it has two).
std::pair<int, int> creaseEnds(const MeshTopology &t, int v, const std::vector<float> &sharpness)
{
    const auto edges = t.ring(v).edges;
    std::size_t first = 0, last = edges.size() - 1;
    while (first < last && !crease::isSharp(sharpness[first]))
        ++first;
    while (last > first && !crease::isSharp(sharpness[last]))
        --last;
    return {t.otherEnd(edges[first], v), t.otherEnd(edges[last], v)};
}

MeshStencil creaseMask(int v, std::pair<int, int> ends, double self, double neighbour)
{
    return merged({{v, self}, {ends.first, neighbour}, {ends.second, neighbour}});
}

// The smooth vertex point of an interior vertex, into s.
void smoothVertex(const MeshTopology &t, int v, MeshScheme scheme, MeshStencil &s)
{
    const auto ring = t.ring(v);
    const int n = int(ring.edges.size());
    s.clear();
    if (scheme == MeshScheme::Loop) {
        const double beta = loopBeta(n);
        s.emplace_back(v, 1.0 - n * beta);
        for (int e : ring.edges)
            s.emplace_back(t.otherEnd(e, v), beta);
        mergeStencil(s);
        return;
    }
    s.emplace_back(v, catmarkVertexSelf(n));
    for (int e : ring.edges)
        s.emplace_back(t.otherEnd(e, v), catmarkVertexRing(n));
    for (int f : ring.faces)
        addFaceCentroid(s, t.face(f), catmarkVertexRing(n));
    mergeStencil(s);
}

MeshStencil smoothVertex(const MeshTopology &t, int v, MeshScheme scheme)
{
    MeshStencil s;
    smoothVertex(t, v, scheme, s);
    return s;
}

// The vertex point of v under `rule` with edge sharpness `sharpness` around it.
MeshStencil ruleVertex(const MeshTopology &t, int v, MeshScheme scheme, VertexRule rule,
                       const std::vector<float> &sharpness)
{
    switch (rule) {
    case VertexRule::Smooth:
    case VertexRule::Dart:
        return smoothVertex(t, v, scheme);
    case VertexRule::Crease:
        return creaseMask(v, creaseEnds(t, v, sharpness), kCreaseSelf, kCreaseNeighbour);
    case VertexRule::Corner:
        break;
    }
    return MeshStencil{{v, 1.0}};
}

// vertexPoint at a vertex of rule `pRule` (crease or corner) with its ring's sharpness.
MeshStencil vertexPointSharp(const MeshTopology &t, int v, MeshScheme scheme,
                             const std::vector<float> &parent, float parentVertex, VertexRule pRule)
{
    MeshStencil mask = ruleVertex(t, v, scheme, pRule, parent);
    const CreaseMethod method = t.options().creaseMethod;
    const std::vector<float> child = crease::subdivideAroundVertex(parent, method);
    const float childVertex = crease::decrement(parentVertex);
    const VertexRule cRule = crease::vertexRule(childVertex, child);
    if (cRule == pRule)
        return mask;
    const double w = crease::fractionalWeight(parentVertex, childVertex, parent, child, method);
    for (auto &entry : mask)
        entry.second *= w;
    for (const auto &[p, u] : ruleVertex(t, v, scheme, cRule, child))
        mask.emplace_back(p, (1.0 - w) * u);
    return merged(std::move(mask));
}

// The vertex point, as Sdc::Scheme::ComputeVertexVertexMask: the rule of the vertex, and where
// a semi-sharp feature ends at this level, that rule blended with the next level's. Into s.
void vertexPoint(const MeshTopology &t, int v, MeshScheme scheme, MeshStencil &s)
{
    const auto ring = t.ring(v);
    if (ring.edges.empty()) {
        s.assign({{v, 1.0}});
        return;
    }
    if (!t.hasSharpness()) {  // the common case, without a vector per vertex: only the boundary
        if (ring.boundary)
            s = creaseMask(v, {t.otherEnd(ring.edges.front(), v), t.otherEnd(ring.edges.back(), v)},
                           kCreaseSelf, kCreaseNeighbour);
        else
            smoothVertex(t, v, scheme, s);
        return;
    }
    const std::vector<float> parent = t.ringSharpness(v);
    const float parentVertex = t.vertexSharpness(v);
    const VertexRule pRule = crease::vertexRule(parentVertex, parent);
    if (pRule == VertexRule::Smooth || pRule == VertexRule::Dart) {
        smoothVertex(t, v, scheme, s);
        return;
    }
    s = vertexPointSharp(t, v, scheme, parent, parentVertex, pRule);
}

// The corner of triangle f opposite edge e.
int opposite(const MeshTopology &t, int f, int e)
{
    const auto &edge = t.edge(e);
    for (int c : t.face(f))
        if (c != edge.v[0] && c != edge.v[1])
            return c;
    return edge.v[0];
}

void smoothEdge(const MeshTopology &t, int e, MeshScheme scheme, MeshStencil &s)
{
    const auto &edge = t.edge(e);
    if (scheme == MeshScheme::Loop) {
        s.assign({{edge.v[0], 0.375},
                  {edge.v[1], 0.375},
                  {opposite(t, edge.face[0], e), 0.125},
                  {opposite(t, edge.face[1], e), 0.125}});
        mergeStencil(s);
        return;
    }
    // OpenSubdiv's "smooth triangles": 0.47 toward a triangle's centre instead of 1/4.
    double face = 0.25;
    if (t.options().triangles == TriangleSubdivision::Smooth) {
        const bool tri0 = t.face(edge.face[0]).size() == 3, tri1 = t.face(edge.face[1]).size() == 3;
        if (tri0 || tri1)
            face = 0.5 * ((tri0 ? 0.470 : 0.25) + (tri1 ? 0.470 : 0.25));
    }
    const double vertex = 0.5 * (1.0 - 2.0 * face);
    s.assign({{edge.v[0], vertex}, {edge.v[1], vertex}});
    addFaceCentroid(s, t.face(edge.face[0]), face);
    addFaceCentroid(s, t.face(edge.face[1]), face);
    mergeStencil(s);
}

// The sharpness one level down of the half of edge e at its end v.
float childHalf(const MeshTopology &t, int e, int v)
{
    const float s = t.edgeSharpness(e);
    if (t.options().creaseMethod == CreaseMethod::Uniform || !crease::isSemiSharp(s))
        return crease::decrement(s);
    const auto edges = t.ring(v).edges;
    const auto k = std::size_t(std::find(edges.begin(), edges.end(), e) - edges.begin());
    return crease::subdivideAroundVertex(t.ringSharpness(v), CreaseMethod::Chaikin)[k];
}

// The edge point, as Sdc::Scheme::ComputeEdgeVertexMask: the midpoint of a sharp edge whose
// halves stay sharp, the smooth rule of a smooth edge, and the two blended by the sharpness of
// an edge that becomes smooth at this level.
void edgePoint(const MeshTopology &t, int e, MeshScheme scheme, MeshStencil &mask)
{
    const auto &edge = t.edge(e);
    const float s = t.edgeSharpness(e);
    if (!crease::isSharp(s)) {
        smoothEdge(t, e, scheme, mask);
        return;
    }
    const MeshStencil mid = merged({{edge.v[0], 0.5}, {edge.v[1], 0.5}});
    if (edge.boundary() || crease::isInfinite(s)
        || (crease::isSharp(childHalf(t, e, edge.v[0]))
            && crease::isSharp(childHalf(t, e, edge.v[1])))) {
        mask = mid;
        return;
    }
    const double w = s;
    smoothEdge(t, e, scheme, mask);
    for (auto &entry : mask)
        entry.second *= 1.0 - w;
    for (const auto &[p, u] : mid)
        mask.emplace_back(p, w * u);
    mergeStencil(mask);
}

// The exact limit of a dart (one sharp edge ends at v): the left eigenvector for eigenvalue 1
// of the subdivision matrix of its invariant neighbourhood -- v, its edge neighbours and (for
// Catmull-Clark) the far corners of its quads -- built from the rules themselves. (The smooth
// limit mask that OpenSubdiv's Limit() applies there ignores that the sharp edge's point is
// its midpoint: an approximation that shrinks with the level.) nullopt for Catmull-Clark with a
// face at v that is not a quad (taken after one step). With semi-sharp edges at v (before the
// prelude's end) it is the fixed point of this level's rules, not yet the limit.
std::optional<MeshStencil> dartLimit(const MeshTopology &t, int v, MeshScheme scheme)
{
    const auto ring = t.ring(v);
    std::vector<int> points{v};
    std::vector<MeshStencil> rows(1);
    vertexPoint(t, v, scheme, rows.back());
    for (int e : ring.edges) {
        points.push_back(t.otherEnd(e, v));
        edgePoint(t, e, scheme, rows.emplace_back());
    }
    if (scheme == MeshScheme::CatmullClark)
        for (int f : ring.faces) {
            const auto face = t.face(f);
            if (face.size() != 4)
                return std::nullopt;
            const int corner = int(std::find(face.begin(), face.end(), v) - face.begin());
            points.push_back(face[std::size_t(corner + 2) % 4]);
            MeshStencil centre;
            addFaceCentroid(centre, face, 1.0);
            rows.push_back(merged(std::move(centre)));
        }
    const int m = int(points.size());
    Mat S = Mat::Zero(m, m);
    for (int i = 0; i < m; ++i)
        for (const auto &[p, w] : rows[std::size_t(i)]) {
            const auto it = std::find(points.begin(), points.end(), p);
            if (it == points.end())  // the rules' stencils stay in the neighbourhood
                throw std::logic_error("dart limit: a stencil leaves the neighbourhood");
            S(i, Eigen::Index(it - points.begin())) += w;
        }
    // l^T S = l^T, sum l = 1: the null space of (S - I)^T with the sum as one more equation.
    Mat A(m + 1, m);
    A.topRows(m) = (S - Mat::Identity(m, m)).transpose();
    A.row(m).setOnes();
    Eigen::VectorXd b = Eigen::VectorXd::Zero(m + 1);
    b(m) = 1.0;
    const Eigen::VectorXd l = A.colPivHouseholderQr().solve(b);
    MeshStencil s;
    for (int i = 0; i < m; ++i)
        if (l(i) != 0.0)
            s.emplace_back(points[std::size_t(i)], l(i));
    return merged(std::move(s));
}

// The limit stencil of v by its rule (Sdc::Scheme::ComputeVertexLimitMask): smooth vertices
// the smooth mask (when every face at v is a quad for Catmull-Clark; nullopt otherwise), darts
// their exact limit (above), crease vertices the crease mask, corners and vertices of no face
// stay.
std::optional<MeshStencil> directLimit(const MeshTopology &t, int v, MeshScheme scheme)
{
    const auto ring = t.ring(v);
    if (ring.edges.empty())
        return MeshStencil{{v, 1.0}};
    if (!t.hasSharpness()) {  // the common case, without a vector per vertex
        if (ring.boundary)
            return creaseMask(v,
                              {t.otherEnd(ring.edges.front(), v),
                               t.otherEnd(ring.edges.back(), v)},
                              kCreaseLimitSelf, kCreaseLimitNeighbour);
    } else {
        const std::vector<float> sharpness = t.ringSharpness(v);
        switch (crease::vertexRule(t.vertexSharpness(v), sharpness)) {
        case VertexRule::Crease:
            return creaseMask(v, creaseEnds(t, v, sharpness), kCreaseLimitSelf,
                              kCreaseLimitNeighbour);
        case VertexRule::Corner:
            return MeshStencil{{v, 1.0}};
        case VertexRule::Dart:
            return dartLimit(t, v, scheme);
        case VertexRule::Smooth:
            break;
        }
    }
    const int n = int(ring.edges.size());
    if (scheme == MeshScheme::Loop) {
        const double chi = loopLimitNeighbour(n);
        MeshStencil s{{v, 1.0 - n * chi}};
        for (int e : ring.edges)
            s.emplace_back(t.otherEnd(e, v), chi);
        return merged(std::move(s));
    }
    MeshStencil s{{v, catmarkLimitSelf(n)}};
    for (int e : ring.edges)
        s.emplace_back(t.otherEnd(e, v), catmarkLimitEdge(n));
    for (int f : ring.faces) {
        const auto face = t.face(f);
        if (face.size() != 4)
            return std::nullopt;
        const int corner = int(std::find(face.begin(), face.end(), v) - face.begin());
        s.emplace_back(face[std::size_t(corner + 2) % 4], catmarkLimitDiagonal(n));
    }
    return merged(std::move(s));
}

// The sharp features of the refined mesh of r (faces in refineTopology's order).
MeshSharpness childSharpness(const MeshTopology &t, MeshScheme scheme)
{
    MeshSharpness out;
    out.options = t.options();
    const int nf = t.faceCount();
    if (t.hasHoles())
        for (int f = 0; f < nf; ++f)
            for (std::size_t k = 0, c = scheme == MeshScheme::Loop ? 4 : t.face(f).size(); k < c;
                 ++k)
                out.holes.push_back(t.hole(f) ? 1 : 0);
    if (!t.hasSharpness())
        return out;
    out.vertices.resize(std::size_t(t.vertexCount()));
    for (int v = 0; v < t.vertexCount(); ++v)
        out.vertices[std::size_t(v)] = crease::decrement(t.vertexSharpness(v));
    // The child sharpness of every half edge, around each vertex at once.
    std::vector<std::vector<float>> around(std::size_t(t.vertexCount()));
    for (int v = 0; v < t.vertexCount(); ++v)
        around[std::size_t(v)] =
            crease::subdivideAroundVertex(t.ringSharpness(v), t.options().creaseMethod);
    const auto half = [&](int e, int v) {
        const auto edges = t.ring(v).edges;
        const auto k = std::size_t(std::find(edges.begin(), edges.end(), e) - edges.begin());
        return around[std::size_t(v)][k];
    };
    for (int f = 0; f < nf; ++f) {
        const auto c = t.face(f);
        const auto e = t.faceEdges(f);
        const std::size_t k = c.size();
        if (scheme == MeshScheme::CatmullClark) {
            for (std::size_t i = 0; i < k; ++i)  // {v_i, e_i, f, e_(i-1)}
                out.faceEdges.push_back({half(e[i], c[i]), kSharpnessSmooth, kSharpnessSmooth,
                                         half(e[(i + k - 1) % k], c[i])});
        } else {  // {c0, e0, e2}, {c1, e1, e0}, {c2, e2, e1}, {e0, e1, e2}
            for (std::size_t i = 0; i < 3; ++i)
                out.faceEdges.push_back(
                    {half(e[i], c[i]), kSharpnessSmooth, half(e[(i + 2) % 3], c[i])});
            out.faceEdges.push_back({kSharpnessSmooth, kSharpnessSmooth, kSharpnessSmooth});
        }
    }
    return out;
}

} // namespace

namespace {

// The composition's sums into the thread's `met` (sorted) and `sum`.
struct ComposeMarks {
    std::vector<double> sum;
    std::vector<unsigned> stamp;
    unsigned current = 0;
    std::vector<int> met;
};

const ComposeMarks &composed(std::span<const StencilTable::Entry> outer, const StencilTable &inner)
{
    // A sum per point met, on marks reused from call to call (the isolation of a mesh of a
    // million faces composes a million stencils): the products are summed in the order met.
    thread_local ComposeMarks marks;
    auto &[sum, stamp, current, met] = marks;
    if (++current == 0) {
        std::fill(stamp.begin(), stamp.end(), 0u);
        current = 1;
    }
    met.clear();
    for (const auto &[p, w] : outer)
        for (const auto &[q, u] : inner[std::size_t(p)]) {
            if (std::size_t(q) >= stamp.size()) {
                stamp.resize(std::size_t(q) + 1, 0u);
                sum.resize(std::size_t(q) + 1);
            }
            if (stamp[std::size_t(q)] != current) {
                stamp[std::size_t(q)] = current;
                sum[std::size_t(q)] = 0.0;
                met.push_back(q);
            }
            sum[std::size_t(q)] += w * u;
        }
    std::sort(met.begin(), met.end());
    return marks;
}

} // namespace

void appendComposed(StencilTable &out, std::span<const StencilTable::Entry> outer,
                    const StencilTable &inner)
{
    const ComposeMarks &m = composed(outer, inner);
    thread_local MeshStencil s;
    s.clear();
    for (int q : m.met)
        s.emplace_back(q, m.sum[std::size_t(q)]);
    out.push_back(s);
}

Refinement refineTopology(const MeshTopology &t, MeshScheme scheme)
{
    Refinement r;
    const int nv = t.vertexCount(), ne = t.edgeCount(), nf = t.faceCount();
    if (scheme == MeshScheme::Loop)
        for (int f = 0; f < nf; ++f)
            if (t.face(f).size() != 3)
                throw InputError(formatMessage(
                    coreTranslate("awb::mesh",
                                  "face %1 has %2 vertices; Loop subdivision takes triangles only"),
                    f, t.face(f).size()));
    const std::size_t corners = std::size_t(t.faces().start(std::size_t(nf)));
    r.stencils.reserve(std::size_t(nv + ne + (scheme == MeshScheme::CatmullClark ? nf : 0)),
                       scheme == MeshScheme::Loop ? 7 * std::size_t(nv) + 4 * std::size_t(ne)
                                                  : 3 * corners + 6 * std::size_t(ne) + corners);
    MeshStencil s;
    for (int v = 0; v < nv; ++v) {
        vertexPoint(t, v, scheme, s);
        r.stencils.push_back(s);
    }
    for (int e = 0; e < ne; ++e) {
        edgePoint(t, e, scheme, s);
        r.stencils.push_back(s);
    }
    const auto edgeChild = [nv](int e) { return nv + e; };
    if (scheme == MeshScheme::CatmullClark) {
        r.faces.reserve(std::size_t(t.faces().start(std::size_t(nf))),
                        4 * std::size_t(t.faces().start(std::size_t(nf))));
        for (int f = 0; f < nf; ++f) {
            s.clear();
            addFaceCentroid(s, t.face(f), 1.0);
            mergeStencil(s);
            r.stencils.push_back(s);
        }
        for (int f = 0; f < nf; ++f) {
            const auto face = t.face(f);
            const auto edges = t.faceEdges(f);
            const std::size_t k = face.size();
            for (std::size_t i = 0; i < k; ++i)
                r.faces.push_back({face[i], edgeChild(edges[i]), nv + ne + f,
                                   edgeChild(edges[(i + k - 1) % k])});
        }
    } else {
        r.faces.reserve(4 * std::size_t(nf), 12 * std::size_t(nf));
        for (int f = 0; f < nf; ++f) {
            const auto c = t.face(f);
            const auto e = t.faceEdges(f);
            const int e0 = edgeChild(e[0]), e1 = edgeChild(e[1]), e2 = edgeChild(e[2]);
            r.faces.push_back({c[0], e0, e2});
            r.faces.push_back({c[1], e1, e0});
            r.faces.push_back({c[2], e2, e1});
            r.faces.push_back({e0, e1, e2});
        }
    }
    r.sharpness = childSharpness(t, scheme);
    r.pointCount = int(r.stencils.size());
    r.scheme = scheme;
    return r;
}

MeshTopology refinedTopology(const MeshTopology &parent, Refinement &&r)
{
    MeshTopology child(parent, r.scheme, std::move(r.faces));
    child.applySharpness(r.sharpness);
    return child;
}

MeshTopology refinedTopology(const MeshTopology &parent, const Refinement &r)
{
    MeshTopology child(parent, r.scheme, r.faces);
    child.applySharpness(r.sharpness);
    return child;
}

Mat applyStencils(const StencilTable &stencils, const Mat &data)
{
    Mat out = Mat::Zero(Eigen::Index(stencils.size()), data.cols());
    for (std::size_t i = 0; i < stencils.size(); ++i)
        for (const auto &[p, w] : stencils[i])
            out.row(Eigen::Index(i)) += w * data.row(p);
    return out;
}

Mesh refineMesh(const Mesh &input, MeshScheme scheme, int steps)
{
    if (steps == 0) {
        checkDrawnMesh(input, scheme);
        return input;
    }
    DrawnMesh drawn = drawnMesh(input, scheme);
    const Mesh &mesh = drawn.mesh(input);
    MeshTopology t = std::move(drawn.topology);
    Mesh m;
    m.vertices = mesh.vertices;
    for (int k = 0; k < steps; ++k) {
        Refinement r = refineTopology(t, scheme);
        m.vertices = applyStencils(r.stencils, m.vertices);
        t = refinedTopology(t, std::move(r));
    }
    m.faces = t.faces().toVectors();
    if (t.hasSharpness() || t.hasHoles() || !(t.options() == MeshOptions{}))
        m.tags = tagsOf(t);
    return m;
}

StencilTable limitStencils(const MeshTopology &t, MeshScheme scheme)
{
    StencilTable out;
    out.reserve(std::size_t(t.vertexCount()), 9 * std::size_t(t.vertexCount()));
    std::vector<int> later;
    for (int v = 0; v < t.vertexCount(); ++v) {
        if (auto s = directLimit(t, v, scheme)) {
            out.push_back(*s);
        } else {
            later.push_back(v);
            out.push_back({});
        }
    }
    if (later.empty())
        return out;
    // After one step every face at a vertex point is a quad; the vertex keeps its number.
    const Refinement r = refineTopology(t, scheme);
    const MeshTopology child = refinedTopology(t, r);
    StencilTable all;
    all.reserve(out.size(), out.entryCount() + 25 * later.size());
    for (int v = 0, k = 0; v < t.vertexCount(); ++v) {
        if (k < int(later.size()) && later[std::size_t(k)] == v) {
            appendComposed(all, *directLimit(child, v, scheme), r.stencils);
            ++k;
        } else {
            all.push_back(out[std::size_t(v)]);
        }
    }
    return all;
}

MeshTags tagsOf(const MeshTopology &t)
{
    MeshTags tags;
    tags.options = t.options();
    if (t.hasSharpness()) {
        for (int e = 0; e < t.edgeCount(); ++e)
            if (!t.edge(e).boundary() && crease::isSharp(t.edgeSharpness(e)))
                tags.edges.push_back({t.edge(e).v[0], t.edge(e).v[1], t.edgeSharpness(e)});
        for (int v = 0; v < t.vertexCount(); ++v)
            if (crease::isSharp(t.vertexSharpness(v)))
                tags.vertices.push_back({v, t.vertexSharpness(v)});
    }
    for (int f = 0; f < t.faceCount() && t.hasHoles(); ++f)
        if (t.hole(f))
            tags.holes.push_back(f);
    return tags;
}

int preludeLevels(const MeshTopology &t)
{
    if (!t.hasSharpness())
        return 0;
    float top = 0.0f;
    for (int e = 0; e < t.edgeCount(); ++e)
        if (crease::isSemiSharp(t.edgeSharpness(e)))
            top = std::max(top, t.edgeSharpness(e));
    for (int v = 0; v < t.vertexCount(); ++v)
        if (crease::isSemiSharp(t.vertexSharpness(v)))
            top = std::max(top, t.vertexSharpness(v));
    return int(std::ceil(top));
}

Mat limitPositions(const Mesh &input, MeshScheme scheme)
{
    // A vertex's copies in the sheets of a non-manifold mesh share its limit.
    DrawnMesh drawn = drawnMesh(input, scheme);
    const Mesh &mesh = drawn.mesh(input);
    MeshTopology t = std::move(drawn.topology);
    // Past the semi-sharp features (vertex v keeps its number at every level).
    Mat points = mesh.vertices;
    for (int level = 0, levels = preludeLevels(t); level < levels; ++level) {
        if ((long long)t.faceCount() * 4 > kMaxPreludeFaces)
            throw InputError(formatMessage(
                coreTranslate("awb::mesh",
                              "the semi-sharp features last %1 levels; the mesh would have "
                              "more than %2 faces before its limit positions can be taken"),
                levels, kMaxPreludeFaces));
        Refinement r = refineTopology(t, scheme);
        points = applyStencils(r.stencils, points);
        t = refinedTopology(t, std::move(r));
    }
    StencilTable limits = limitStencils(t, scheme);
    limits.truncate(std::size_t(input.vertices.rows()));
    return applyStencils(limits, points);
}

} // namespace awb
