#include "core/mesh/MeshRepair.h"

#include "core/Messages.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <tuple>

namespace awb {

namespace {

// "3, 8, 12" or "3, 8, 12, 20, 31 and 7 more".
std::string someOf(std::vector<int> list)
{
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    std::string s;
    const std::size_t shown = std::min<std::size_t>(list.size(), 5);
    for (std::size_t k = 0; k < shown; ++k)
        s += (k ? ", " : "") + std::to_string(list[k]);
    if (list.size() > shown)
        s += formatMessage(coreTranslate("awb::mesh", " and %1 more"), list.size() - shown);
    return s;
}

struct UnionFind {
    std::vector<int> parent;
    explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    int find(int x)
    {
        while (parent[std::size_t(x)] != x)
            x = parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])];
        return x;
    }
    void unite(int a, int b)
    {
        a = find(a), b = find(b);
        if (a != b)
            parent[std::size_t(std::max(a, b))] = std::min(a, b);
    }
};

// Every face side: the undirected edge (lo, hi), the face, and whether the face runs lo -> hi;
// sorted by edge.
struct Side {
    int lo, hi, face;
    bool forward;
    bool operator<(const Side &o) const
    {
        return std::tie(lo, hi, face) < std::tie(o.lo, o.hi, o.face);
    }
};

std::vector<Side> sidesOf(const std::vector<std::vector<int>> &faces)
{
    std::vector<Side> sides;
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (std::size_t k = 0; k < faces[f].size(); ++k) {
            const int a = faces[f][k], b = faces[f][(k + 1) % faces[f].size()];
            sides.push_back({std::min(a, b), std::max(a, b), int(f), a < b});
        }
    std::sort(sides.begin(), sides.end());
    return sides;
}

// Calls fn(begin, end) for each run of sides on one edge.
template <typename Fn>
void forEachEdge(const std::vector<Side> &sides, Fn fn)
{
    for (std::size_t i = 0; i < sides.size();) {
        std::size_t j = i + 1;
        while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi)
            ++j;
        fn(i, j);
        i = j;
    }
}

bool repeats(const std::vector<int> &loop)
{
    for (std::size_t i = 0; i < loop.size(); ++i)
        for (std::size_t j = i + 1; j < loop.size(); ++j)
            if (loop[i] == loop[j])
                return true;
    return false;
}

void collapse(Mesh &m, MeshRepairReport &r)
{
    std::vector<int> collapsed, removed, newIndex(m.faces.size(), -1);
    std::vector<std::vector<int>> kept;
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        std::vector<int> loop;
        for (int v : m.faces[f])
            if (loop.empty() || loop.back() != v)
                loop.push_back(v);
        while (loop.size() > 1 && loop.back() == loop.front())
            loop.pop_back();
        if (loop.size() != m.faces[f].size())
            collapsed.push_back(int(f));
        if (loop.size() < 3) {
            removed.push_back(int(f));
            continue;
        }
        newIndex[f] = int(kept.size());
        kept.push_back(std::move(loop));
    }
    if (collapsed.empty())
        return;
    r.collapsedFaces = int(collapsed.size() - removed.size());
    r.removedFaces = int(removed.size());
    r.changes.push_back(formatMessage(
        coreTranslate("awb::mesh", "%1 faces named a vertex twice in a row and now name it once "
                                   "(faces %2)"),
        collapsed.size(), someOf(collapsed)));
    if (!removed.empty())
        r.changes.push_back(formatMessage(
            coreTranslate("awb::mesh", "%1 faces were left with fewer than three vertices and "
                                       "were removed (faces %2; the later faces move up)"),
            removed.size(), someOf(removed)));
    m.faces = std::move(kept);
    std::vector<int> holes;
    for (int h : m.tags.holes)
        if (h >= 0 && std::size_t(h) < newIndex.size() && newIndex[std::size_t(h)] >= 0)
            holes.push_back(newIndex[std::size_t(h)]);
    m.tags.holes = holes;
}

// The tags of vertices renamed by `to` (several may become one: the sharper tag stays).
void renameTags(MeshTags &tags, const std::vector<int> &to)
{
    const auto name = [&](int v) {
        return v >= 0 && std::size_t(v) < to.size() ? to[std::size_t(v)] : v;
    };
    std::map<std::pair<int, int>, float> edges;
    for (const SharpEdge &e : tags.edges) {
        const int a = name(e.a), b = name(e.b);
        auto &s = edges[{std::min(a, b), std::max(a, b)}];
        s = std::max(s, e.sharpness);
    }
    std::map<int, float> vertices;
    for (const SharpVertex &c : tags.vertices) {
        auto &s = vertices[name(c.vertex)];
        s = std::max(s, c.sharpness);
    }
    tags.edges.clear();
    for (const auto &[ab, s] : edges)
        tags.edges.push_back({ab.first, ab.second, s});
    tags.vertices.clear();
    for (const auto &[v, s] : vertices)
        tags.vertices.push_back({v, s});
}

void weld(Mesh &m, MeshRepairReport &r)
{
    const int n = int(m.vertices.rows());
    const std::vector<Side> sides = sidesOf(m.faces);
    std::vector<char> boundary(std::size_t(n), 0);
    forEachEdge(sides, [&](std::size_t i, std::size_t j) {
        if (j - i == 1)
            boundary[std::size_t(sides[i].lo)] = boundary[std::size_t(sides[i].hi)] = 1;
    });
    std::vector<int> order;
    for (int v = 0; v < n; ++v)
        if (boundary[std::size_t(v)] && m.vertices.row(v).allFinite())
            order.push_back(v);
    const auto position = [&](int v) {
        return std::make_tuple(m.vertices(v, 0), m.vertices(v, 1), m.vertices(v, 2));
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return position(a) < position(b); });
    std::vector<int> to(static_cast<std::size_t>(n));
    std::iota(to.begin(), to.end(), 0);
    std::vector<std::vector<int>> groups;
    for (std::size_t i = 0; i < order.size();) {
        std::size_t j = i + 1;
        while (j < order.size() && position(order[j]) == position(order[i]))
            ++j;
        if (j - i > 1)
            groups.emplace_back(order.begin() + std::ptrdiff_t(i),
                                order.begin() + std::ptrdiff_t(j));
        i = j;
    }
    if (groups.empty())
        return;
    std::vector<int> groupOf(std::size_t(n), -1);
    std::vector<char> active(groups.size(), 1);
    for (std::size_t g = 0; g < groups.size(); ++g)
        for (int v : groups[g])
            groupOf[std::size_t(v)] = int(g);
    // Weld every group, then undo the groups whose weld made a face name a vertex twice or an
    // edge of three faces, until none does.
    for (int round = 0; round < 8; ++round) {
        for (int v = 0; v < n; ++v) {
            const int g = groupOf[std::size_t(v)];
            to[std::size_t(v)] = g >= 0 && active[std::size_t(g)] ? groups[std::size_t(g)].front()
                                                                  : v;
        }
        std::vector<std::vector<int>> faces = m.faces;
        bool undone = false;
        const auto undo = [&](int original) {
            const int g = groupOf[std::size_t(original)];
            if (g >= 0 && active[std::size_t(g)]) {
                active[std::size_t(g)] = 0;
                undone = true;
            }
        };
        for (std::size_t f = 0; f < faces.size(); ++f) {
            for (int &v : faces[f])
                v = to[std::size_t(v)];
            if (repeats(faces[f]) && !repeats(m.faces[f]))
                for (int v : m.faces[f])
                    if (to[std::size_t(v)] != v)
                        undo(v);
        }
        const std::vector<Side> welded = sidesOf(faces);
        forEachEdge(welded, [&](std::size_t i, std::size_t j) {
            if (j - i <= 2)
                return;
            for (std::size_t k = i; k < j; ++k)
                for (int v : m.faces[std::size_t(welded[k].face)])
                    if (to[std::size_t(v)] == welded[k].lo || to[std::size_t(v)] == welded[k].hi)
                        if (to[std::size_t(v)] != v)
                            undo(v);
        });
        if (!undone) {
            std::vector<int> joined;
            int count = 0;
            for (int v = 0; v < n; ++v)
                if (to[std::size_t(v)] != v) {
                    ++count;
                    joined.push_back(v);
                }
            if (count == 0)
                return;
            m.faces = std::move(faces);
            renameTags(m.tags, to);
            r.weldedVertices = count;
            r.changes.push_back(formatMessage(
                coreTranslate("awb::mesh", "%1 boundary vertices at the position of another were "
                                           "welded into it (vertices %2; they stay, used by no "
                                           "face)"),
                count, someOf(joined)));
            return;
        }
    }
}

void orient(Mesh &m, MeshRepairReport &r)
{
    const std::size_t nf = m.faces.size();
    const std::vector<Side> sides = sidesOf(m.faces);
    // Neighbours across edges of exactly two faces: (face, other face, same direction).
    std::vector<std::vector<std::pair<int, bool>>> next(nf);
    forEachEdge(sides, [&](std::size_t i, std::size_t j) {
        if (j - i != 2 || sides[i].face == sides[i + 1].face)
            return;
        const bool same = sides[i].forward == sides[i + 1].forward;
        next[std::size_t(sides[i].face)].push_back({sides[i + 1].face, same});
        next[std::size_t(sides[i + 1].face)].push_back({sides[i].face, same});
    });
    std::vector<int> flip(nf, -1);
    std::vector<int> turned, moebius;
    for (std::size_t start = 0; start < nf; ++start) {
        if (flip[start] >= 0)
            continue;
        std::vector<int> component{int(start)};
        flip[start] = 0;
        bool orientable = true;
        for (std::size_t k = 0; k < component.size(); ++k) {
            const int f = component[k];
            for (const auto &[g, same] : next[std::size_t(f)]) {
                const int want = flip[std::size_t(f)] ^ (same ? 1 : 0);
                if (flip[std::size_t(g)] < 0) {
                    flip[std::size_t(g)] = want;
                    component.push_back(g);
                } else if (flip[std::size_t(g)] != want) {
                    orientable = false;
                }
            }
        }
        if (!orientable) {
            moebius.push_back(int(start));
            continue;
        }
        std::size_t flipped = 0;
        for (int f : component)
            flipped += std::size_t(flip[std::size_t(f)]);
        const int keep = 2 * flipped > component.size() ? 1 : 0;  // the majority's orientation
        for (int f : component)
            if (flip[std::size_t(f)] != keep) {
                auto &loop = m.faces[std::size_t(f)];
                std::reverse(loop.begin() + 1, loop.end());
                turned.push_back(f);
            }
    }
    if (!turned.empty()) {
        r.turnedFaces = int(turned.size());
        r.changes.push_back(formatMessage(
            coreTranslate("awb::mesh", "%1 faces were turned over to the orientation of the "
                                       "surface they belong to (faces %2)"),
            turned.size(), someOf(turned)));
    }
    if (!moebius.empty())
        r.unrepaired.push_back(formatMessage(
            coreTranslate("awb::mesh", "the surface of face %1 cannot be oriented (it is a "
                                       "Möbius band or contains one): left as it is"),
            someOf(moebius)));
}

void splitFans(Mesh &m, MeshRepairReport &r)
{
    const int n = int(m.vertices.rows());
    // The corners of each vertex: (face, position in the loop).
    std::vector<std::vector<std::pair<int, int>>> corners(static_cast<std::size_t>(n));
    for (std::size_t f = 0; f < m.faces.size(); ++f)
        for (std::size_t k = 0; k < m.faces[f].size(); ++k)
            if (m.faces[f][k] >= 0 && m.faces[f][k] < n)
                corners[std::size_t(m.faces[f][k])].push_back({int(f), int(k)});
    std::vector<int> origin(static_cast<std::size_t>(n));
    std::iota(origin.begin(), origin.end(), 0);
    std::vector<Eigen::RowVectorXd> added;
    std::vector<int> split;
    for (int v = 0; v < n; ++v) {
        const auto &at = corners[std::size_t(v)];
        if (at.size() < 2)
            continue;
        // The faces at v, united when they share an edge at v.
        std::map<int, int> local;  // face -> index
        for (const auto &[f, k] : at)
            local.emplace(f, int(local.size()));
        UnionFind fans(local.size());
        std::map<int, int> firstFaceTo;  // other end of an edge at v -> a face on it
        for (const auto &[f, k] : at) {
            const auto &loop = m.faces[std::size_t(f)];
            const std::size_t s = loop.size();
            for (int w : {loop[(std::size_t(k) + 1) % s], loop[(std::size_t(k) + s - 1) % s]}) {
                const auto [it, added] = firstFaceTo.emplace(w, f);
                if (!added)
                    fans.unite(local[it->second], local[f]);
            }
        }
        std::map<int, int> fanVertex;  // root -> vertex number
        for (const auto &[f, k] : at) {
            const int root = fans.find(local[f]);
            auto it = fanVertex.find(root);
            if (it == fanVertex.end()) {
                const int id = fanVertex.empty() ? v : n + int(added.size());
                if (id != v) {
                    added.push_back(m.vertices.row(v));
                    origin.push_back(v);
                }
                it = fanVertex.emplace(root, id).first;
            }
            m.faces[std::size_t(f)][std::size_t(k)] = it->second;
        }
        if (fanVertex.size() > 1)
            split.push_back(v);
    }
    if (split.empty())
        return;
    const int total = n + int(added.size());
    Mat vertices(total, m.vertices.cols());
    vertices.topRows(n) = m.vertices;
    for (std::size_t k = 0; k < added.size(); ++k)
        vertices.row(n + Eigen::Index(k)) = added[k];
    m.vertices = std::move(vertices);
    // Tags: a corner goes to every copy; a crease to the copies whose edge it names.
    if (!m.tags.vertices.empty() || !m.tags.edges.empty()) {
        std::vector<SharpVertex> vertexTags;
        for (const SharpVertex &c : m.tags.vertices)
            for (int x = 0; x < total; ++x)
                if (origin[std::size_t(x)] == c.vertex)
                    vertexTags.push_back({x, c.sharpness});
        std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edgesByOrigin;
        for (const Side &s : sidesOf(m.faces)) {
            const int a = origin[std::size_t(s.lo)], b = origin[std::size_t(s.hi)];
            edgesByOrigin[{std::min(a, b), std::max(a, b)}].push_back({s.lo, s.hi});
        }
        std::vector<SharpEdge> edgeTags;
        for (const SharpEdge &e : m.tags.edges) {
            const auto it = edgesByOrigin.find({std::min(e.a, e.b), std::max(e.a, e.b)});
            if (it == edgesByOrigin.end()) {
                edgeTags.push_back(e);  // checkMesh names it
                continue;
            }
            auto pairs = it->second;
            std::sort(pairs.begin(), pairs.end());
            pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
            for (const auto &[a, b] : pairs)
                edgeTags.push_back({a, b, e.sharpness});
        }
        m.tags.vertices = vertexTags;
        m.tags.edges = edgeTags;
    }
    r.splitVertices = int(split.size());
    r.addedVertices = int(added.size());
    r.changes.push_back(formatMessage(
        coreTranslate("awb::mesh", "%1 vertices whose faces formed several fans were split, one "
                                   "vertex per fan (vertices %2; the %3 new vertices are "
                                   "numbered from %4)"),
        split.size(), someOf(split), added.size(), n));
}

void sayNonManifoldEdges(const Mesh &m, MeshRepairReport &r)
{
    const std::vector<Side> sides = sidesOf(m.faces);
    std::vector<std::string> edges;
    int count = 0;
    forEachEdge(sides, [&](std::size_t i, std::size_t j) {
        if (j - i <= 2)
            return;
        ++count;
        if (edges.size() < 5)
            edges.push_back(formatMessage(coreTranslate("awb::mesh", "(%1, %2)"), sides[i].lo,
                                          sides[i].hi));
    });
    if (count == 0)
        return;
    std::string list;
    for (const std::string &e : edges)
        list += (list.empty() ? "" : ", ") + e;
    if (count > int(edges.size()))
        list += formatMessage(coreTranslate("awb::mesh", " and %1 more"), count - int(edges.size()));
    r.unrepaired.push_back(formatMessage(
        coreTranslate("awb::mesh", "%1 edges join three or more faces (%2): no choice of sheets "
                                   "is canonical, so they are not repaired; they are drawn as "
                                   "OpenSubdiv draws them, as infinitely sharp creases"),
        count, list));
}

} // namespace

Mesh repairMesh(const Mesh &mesh, MeshRepairReport *report)
{
    MeshRepairReport local;
    MeshRepairReport &r = report ? *report : local;
    r = {};
    Mesh m = mesh;
    const int n = int(m.vertices.rows());
    for (const auto &loop : m.faces)
        for (int v : loop)
            if (v < 0 || v >= n)
                return m;  // indices out of range: the checks name them, nothing to repair
    collapse(m, r);
    weld(m, r);
    orient(m, r);
    splitFans(m, r);
    sayNonManifoldEdges(m, r);
    return m;
}

} // namespace awb
