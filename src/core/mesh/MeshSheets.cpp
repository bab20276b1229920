#include "core/mesh/MeshSheets.h"

#include "core/Messages.h"
#include "core/mesh/MeshHalfEdges.h"

#include <algorithm>
#include <numeric>

namespace awb {

namespace {

int findRoot(std::vector<int> &parent, int x)
{
    while (parent[std::size_t(x)] != x) {
        parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])];
        x = parent[std::size_t(x)];
    }
    return x;
}

std::uint64_t edgeKey(int a, int b)
{
    return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
}

} // namespace

std::optional<ManifoldSheets> manifoldSheets(const Mesh &mesh)
{
    const int n = int(mesh.vertices.rows());
    // Faces that are not well formed are checkMesh's to name. A face may name a vertex twice
    // (OpenSubdiv's degenerate edges, as in its "quad poles"): each corner is a corner.
    for (const auto &loop : mesh.faces) {
        if (loop.size() < 3)
            return std::nullopt;
        for (int v : loop)
            if (v < 0 || v >= n)
                return std::nullopt;
    }
    const MeshHalfEdges h(n, mesh.faces);
    const int count = h.count();
    // Per half-edge: its twin across a manifold edge, or what else its edge is. Two faces along
    // it in opposite directions: manifold; one face: the boundary; anything else (three or more
    // faces, one direction, a degenerate edge, one face naming it twice) is not.
    const MeshHalfEdges::Pairing pairing = h.pairing();
    std::vector<int> twin(std::size_t(count), -1);
    std::vector<char> nonManifold(std::size_t(count), 0), boundary(std::size_t(count), 0);
    bool anyNonManifold = false;
    for (int e = 0; e < count; ++e) {
        const int opposite = pairing.opposite[std::size_t(e)];
        const int halves = pairing.halves[std::size_t(e)];
        const bool degenerate = h.from[std::size_t(e)] == h.to[std::size_t(e)];
        if (!degenerate && halves == 2 && opposite >= 0
            && h.face[std::size_t(opposite)] != h.face[std::size_t(e)])
            twin[std::size_t(e)] = opposite;
        else if (!degenerate && halves == 1)
            boundary[std::size_t(e)] = 1;
        else
            nonManifold[std::size_t(e)] = anyNonManifold = 1;
    }
    // The fans: the corners at a vertex joined across its manifold edges.
    std::vector<int> parent(static_cast<std::size_t>(count));
    std::iota(parent.begin(), parent.end(), 0);
    for (int e = 0; e < count; ++e) {
        const int across = twin[std::size_t(h.previous(e))];  // leaves the same vertex
        if (across >= 0)
            parent[std::size_t(findRoot(parent, e))] = findRoot(parent, across);
    }
    std::vector<int> vertexOf(std::size_t(count), -1);  // per corner, its vertex in the sheets
    std::vector<int> original(static_cast<std::size_t>(n));
    std::iota(original.begin(), original.end(), 0);
    std::vector<int> fans(std::size_t(n), 0);
    // Per fan (by its root half-edge), its vertex; valid where marked for the current vertex.
    std::vector<int> fanVertex(std::size_t(count), -1), fanMark(std::size_t(count), -1);
    for (int v = 0; v < n; ++v) {
        int fanCount = 0;
        for (int i = h.outStart[std::size_t(v)]; i < h.outStart[std::size_t(v) + 1]; ++i) {
            const int e = h.out[std::size_t(i)], root = findRoot(parent, e);
            if (fanMark[std::size_t(root)] != v) {
                fanMark[std::size_t(root)] = v;
                // The first fan keeps the vertex's number, the others are appended.
                fanVertex[std::size_t(root)] = fanCount++ == 0 ? v : int(original.size());
                if (fanVertex[std::size_t(root)] != v)
                    original.push_back(v);
            }
            vertexOf[std::size_t(e)] = fanVertex[std::size_t(root)];
        }
        fans[std::size_t(v)] = fanCount;
    }
    if (!anyNonManifold && int(original.size()) == n)
        return std::nullopt;
    // Two corners of one face in one fan would make a face that names a vertex twice in the
    // sheets too: checkMesh refuses it.
    std::vector<int> corners;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        corners.assign(vertexOf.begin() + h.first[f], vertexOf.begin() + h.first[f + 1]);
        std::sort(corners.begin(), corners.end());
        if (std::adjacent_find(corners.begin(), corners.end()) != corners.end())
            return std::nullopt;
    }

    // The half-edges of each edge, sorted by vertex pair (and in half-edge order within one):
    // the tags and the non-manifold vertices are read by edge.
    std::vector<std::pair<std::uint64_t, int>> byEdge(static_cast<std::size_t>(count));
    for (int e = 0; e < count; ++e)
        byEdge[std::size_t(e)] = {edgeKey(h.from[std::size_t(e)], h.to[std::size_t(e)]), e};
    std::sort(byEdge.begin(), byEdge.end());
    ManifoldSheets out;
    out.original = std::move(original);
    out.copies = int(out.original.size()) - n;
    out.mesh.vertices = mesh.vertices(out.original, Eigen::all);
    out.mesh.faces = mesh.faces;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (std::size_t k = 0; k < mesh.faces[f].size(); ++k)
            out.mesh.faces[f][k] = vertexOf[std::size_t(h.first[f]) + k];
    out.mesh.tags.options = mesh.tags.options;

    for (const SharpEdge &tag : mesh.tags.edges)
        if (tag.a < 0 || tag.a >= n || tag.b < 0 || tag.b >= n)
            throw InputError(formatMessage(
                coreTranslate("awb::mesh",
                              "a crease names vertices %1 and %2, but no edge joins them"),
                tag.a, tag.b));
    for (const SharpVertex &tag : mesh.tags.vertices)
        if (tag.vertex < 0 || tag.vertex >= n)
            throw InputError(formatMessage(
                coreTranslate("awb::mesh", "a corner names vertex %1, but the mesh has %2 "
                                           "vertices (0 to %3)"),
                tag.vertex, n, n - 1));

    // The half-edges of an edge, found by its vertex pair.
    const auto halves = [&](int a, int b) {
        const std::uint64_t key = edgeKey(a, b);
        const auto lo = std::lower_bound(byEdge.begin(), byEdge.end(),
                                         std::pair<std::uint64_t, int>{key, -1});
        auto hi = lo;
        while (hi != byEdge.end() && hi->first == key)
            ++hi;
        return std::make_pair(lo, hi);
    };
    // The user's edge sharpness by vertex pair (the larger of repeated tags).
    // The user's sharpness of an edge: its last tag's, as OpenSubdiv assigns them in order.
    const auto byKey = [](const auto &x, const auto &y) { return x.first < y.first; };
    std::vector<std::pair<std::uint64_t, float>> userEdges;
    for (const SharpEdge &tag : mesh.tags.edges)
        userEdges.push_back({edgeKey(tag.a, tag.b), tag.sharpness});
    std::stable_sort(userEdges.begin(), userEdges.end(), byKey);
    const auto userSharpness = [&](int a, int b) {
        auto it = std::upper_bound(userEdges.begin(), userEdges.end(),
                                   std::pair<std::uint64_t, float>{edgeKey(a, b), 0.0f}, byKey);
        return it != userEdges.begin() && (it - 1)->first == edgeKey(a, b) ? (it - 1)->second
                                                                            : kSharpnessSmooth;
    };
    // Every sheet edge of an input edge with its sharpness: infinite on a non-manifold edge.
    std::vector<std::pair<std::uint64_t, float>> sheetEdges;
    const auto tagSheets = [&](int a, int b, float sharpness) {
        const auto [lo, hi] = halves(a, b);
        for (auto i = lo; i != hi; ++i) {
            const int e = i->second;
            sheetEdges.push_back({edgeKey(vertexOf[std::size_t(e)],
                                          vertexOf[std::size_t(h.next(e))]),
                                  sharpness});
        }
    };
    for (const SharpEdge &tag : mesh.tags.edges) {
        const auto [lo, hi] = halves(tag.a, tag.b);
        if (lo == hi || !(tag.sharpness >= 0.0f))  // checkMesh names the problem
            out.mesh.tags.edges.push_back(tag);
        else if (!nonManifold[std::size_t(lo->second)])
            tagSheets(tag.a, tag.b, tag.sharpness);
    }
    for (int e = 0; e < count; ++e)
        if (nonManifold[std::size_t(e)])
            sheetEdges.push_back({edgeKey(vertexOf[std::size_t(e)],
                                          vertexOf[std::size_t(h.next(e))]),
                                  kSharpnessInfinite});
    std::stable_sort(sheetEdges.begin(), sheetEdges.end(), byKey);
    for (std::size_t i = 0; i < sheetEdges.size(); ++i) {
        if (i + 1 < sheetEdges.size() && sheetEdges[i + 1].first == sheetEdges[i].first)
            continue;  // the last assigned wins (a non-manifold edge's infinity comes last)
        const std::uint64_t key = sheetEdges[i].first;
        out.mesh.tags.edges.push_back({int(key >> 32), int(key & 0xffffffffu),
                                       sheetEdges[i].second});
    }

    // The non-manifold edges and vertices, and the sharpness of each vertex's copies.
    std::vector<float> vertexSharpness(std::size_t(n), kSharpnessSmooth);
    for (const SharpVertex &tag : mesh.tags.vertices) {
        if (!(tag.sharpness >= 0.0f))  // checkMesh names it
            out.mesh.tags.vertices.push_back(tag);
        else  // the last tag of a vertex wins, as in OpenSubdiv
            vertexSharpness[std::size_t(tag.vertex)] = tag.sharpness;
    }
    for (const auto &[key, e] : byEdge)
        if (nonManifold[std::size_t(e)]
            && (out.edges.empty() || edgeKey(out.edges.back().first, out.edges.back().second)
                                         != key))
            out.edges.push_back({int(key >> 32), int(key & 0xffffffffu)});
    std::vector<char> holes(mesh.faces.size(), 0);
    for (int f : mesh.tags.holes)
        if (f >= 0 && f < int(holes.size()))
            holes[std::size_t(f)] = 1;
    bool moreHoles = false;
    std::vector<int> neighbours;
    for (int v = 0; v < n; ++v) {
        const int begin = h.outStart[std::size_t(v)], end = h.outStart[std::size_t(v) + 1];
        if (begin == end)
            continue;
        // The distinct edges at v (OpenSubdiv's vertex-edges) and what they are.
        neighbours.clear();
        bool vertexNonManifold = fans[std::size_t(v)] > 1;
        for (int i = begin; i < end; ++i) {
            const int e = h.out[std::size_t(i)];
            neighbours.push_back(h.to[std::size_t(e)]);
            neighbours.push_back(h.from[std::size_t(h.previous(e))]);
        }
        std::sort(neighbours.begin(), neighbours.end());
        neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
        // OpenSubdiv counts a degenerate edge (v, v) twice at v, once per end.
        int nonManifoldEdges = 0, boundaryEdges = 0, untaggedBoundary = 0, degenerate = 0;
        for (int i = begin; i < end; ++i)
            degenerate += h.to[std::size_t(h.out[std::size_t(i)])] == v;
        if (degenerate > 0) {
            vertexNonManifold = true;
            nonManifoldEdges += 2 * degenerate;
            neighbours.erase(std::find(neighbours.begin(), neighbours.end(), v));
        }
        float otherSharp = kSharpnessSmooth;
        int edgeCount = 2 * degenerate;
        for (int b : neighbours) {
            const auto [lo, hi] = halves(v, b);
            const int e = lo->second;
            // OpenSubdiv makes a new instance of an edge each time a face names it again.
            int instances = 1;
            for (auto i = lo + 1; i != hi; ++i)
                instances += h.face[std::size_t(i->second)] == h.face[std::size_t((i - 1)->second)];
            edgeCount += instances;
            if (nonManifold[std::size_t(e)]) {
                nonManifoldEdges += instances;
                vertexNonManifold = true;
            } else if (boundary[std::size_t(e)]) {
                ++boundaryEdges;
                untaggedBoundary += !crease::isInfinite(userSharpness(v, b));
            } else {
                otherSharp = std::max(otherSharp, userSharpness(v, b));
            }
        }
        const int faceCount = end - begin;
        // OpenSubdiv's boundary "none": the faces at a vertex with an untagged boundary edge
        // are holes, judged on the whole vertex (before the sharpening).
        if (mesh.tags.options.boundary == BoundaryInterpolation::None && untaggedBoundary > 0
            && (vertexNonManifold || faceCount != edgeCount))
            for (int i = begin; i < end; ++i) {
                const int f = h.face[std::size_t(h.out[std::size_t(i)])];
                moreHoles = moreHoles || !holes[std::size_t(f)];
                holes[std::size_t(f)] = 1;
            }
        if (!vertexNonManifold)
            continue;
        out.vertices.push_back(v);
        float &s = vertexSharpness[std::size_t(v)];
        if (nonManifoldEdges == 2 && boundaryEdges == 0 && faceCount > edgeCount) {
            out.creaseVertices.push_back(v);
            // Another sharp edge at a crease vertex counts in every sheet's rule.
            s = std::max(s, otherSharp);
        } else {
            s = kSharpnessInfinite;
        }
    }
    for (int c = 0; c < int(out.original.size()); ++c) {
        const float s = vertexSharpness[std::size_t(out.original[std::size_t(c)])];
        if (crease::isSharp(s))
            out.mesh.tags.vertices.push_back({c, s});
    }
    out.mesh.tags.holes = mesh.tags.holes;
    if (moreHoles) {
        out.mesh.tags.holes.clear();
        for (int f = 0; f < int(holes.size()); ++f)
            if (holes[std::size_t(f)])
                out.mesh.tags.holes.push_back(f);
    }
    return out;
}

std::string describe(const ManifoldSheets &sheets)
{
    std::string edges, vertices;
    for (std::size_t k = 0; k < sheets.edges.size() && k < 5; ++k)
        edges += formatMessage(coreTranslate("awb::mesh", "%1(%2, %3)"), k ? ", " : "",
                               sheets.edges[k].first, sheets.edges[k].second);
    if (sheets.edges.size() > 5)
        edges += formatMessage(coreTranslate("awb::mesh", " and %1 more"),
                               sheets.edges.size() - 5);
    for (std::size_t k = 0; k < sheets.vertices.size() && k < 5; ++k)
        vertices += (k ? ", " : "") + std::to_string(sheets.vertices[k]);
    if (sheets.vertices.size() > 5)
        vertices += formatMessage(coreTranslate("awb::mesh", " and %1 more"),
                                  sheets.vertices.size() - 5);
    const std::size_t corners = sheets.vertices.size() - sheets.creaseVertices.size();
    const std::string how =
        corners == sheets.vertices.size()
            ? coreTranslate("awb::mesh", "the vertices as corners")
            : formatMessage(coreTranslate("awb::mesh",
                                          "%1 of the vertices as corners, the others on the "
                                          "creases"),
                            corners);
    if (sheets.edges.empty())
        return formatMessage(coreTranslate("awb::mesh",
                                           "non-manifold: %1 vertices (%2), drawn as OpenSubdiv "
                                           "draws them: %3"),
                             sheets.vertices.size(), vertices, how);
    return formatMessage(
        coreTranslate("awb::mesh",
                      "non-manifold: %1 edges (%2) and %3 vertices (%4), drawn as OpenSubdiv "
                      "draws them: the edges as infinitely sharp creases, %5"),
        sheets.edges.size(), edges, sheets.vertices.size(), vertices, how);
}

DrawnMesh drawnMesh(const Mesh &mesh, MeshScheme scheme)
{
    try {
        return DrawnMesh{std::nullopt, checkMesh(mesh, scheme)};
    } catch (const InputError &) {
        std::optional<ManifoldSheets> sheets = manifoldSheets(mesh);
        if (!sheets)
            throw;
        MeshTopology topology = checkMesh(sheets->mesh, scheme);
        return DrawnMesh{std::move(sheets), std::move(topology)};
    }
}

} // namespace awb
