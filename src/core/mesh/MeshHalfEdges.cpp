#include "core/mesh/MeshHalfEdges.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace awb {

MeshHalfEdges::MeshHalfEdges(int vertexCount, const IndexRows &faces) : first(faces.starts())
{
    const std::size_t n = std::size_t(first.back());
    from.resize(n);
    to.resize(n);
    face.resize(n);
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto loop = faces[f];
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const std::size_t h = std::size_t(first[f]) + k;
            from[h] = loop[k];
            to[h] = loop[k + 1 < loop.size() ? k + 1 : 0];
            face[h] = int(f);
        }
    }
    outStart.assign(std::size_t(vertexCount) + 1, 0);
    for (int v : from)
        ++outStart[std::size_t(v) + 1];
    for (std::size_t v = 0; v < std::size_t(vertexCount); ++v)
        outStart[v + 1] += outStart[v];
    out.resize(n);
    BigVector<int> fill(outStart.begin(), outStart.end() - 1);
    for (int h = 0; h < int(n); ++h)
        out[std::size_t(fill[std::size_t(from[std::size_t(h)])]++)] = h;
}

int MeshHalfEdges::next(int h) const
{
    const int b = first[std::size_t(face[std::size_t(h)])];
    const int n = first[std::size_t(face[std::size_t(h)]) + 1] - b;
    return b + (h - b + 1) % n;
}

int MeshHalfEdges::previous(int h) const
{
    const int b = first[std::size_t(face[std::size_t(h)])];
    const int n = first[std::size_t(face[std::size_t(h)]) + 1] - b;
    return b + (h - b + n - 1) % n;
}

MeshHalfEdges::Pairing MeshHalfEdges::pairing() const
{
    const int n = count();
    Pairing p;
    p.same.assign(std::size_t(n), -1);
    p.opposite.assign(std::size_t(n), -1);
    p.halves.assign(std::size_t(n), 0);
    int busiest = 0;
    for (std::size_t v = 0; v + 1 < outStart.size(); ++v)
        busiest = std::max(busiest, outStart[v + 1] - outStart[v]);
    if (busiest <= 64) {
        for (int h = 0; h < n; ++h) {
            const int a = from[std::size_t(h)], b = to[std::size_t(h)];
            int same = -1, opposite = -1, halves = 0;
            for (int i = outStart[std::size_t(a)]; i < outStart[std::size_t(a) + 1]; ++i) {
                const int g = out[std::size_t(i)];  // in half-edge order: the first found first
                if (to[std::size_t(g)] == b) {
                    same = same < 0 ? g : same;
                    ++halves;
                }
            }
            for (int i = outStart[std::size_t(b)]; i < outStart[std::size_t(b) + 1] && a != b;
                 ++i) {
                const int g = out[std::size_t(i)];
                if (to[std::size_t(g)] == a) {
                    opposite = opposite < 0 ? g : opposite;
                    ++halves;
                }
            }
            p.same[std::size_t(h)] = same;
            p.opposite[std::size_t(h)] = opposite;
            p.halves[std::size_t(h)] = halves;
        }
        return p;
    }
    std::vector<std::pair<std::uint64_t, int>> byEdge(static_cast<std::size_t>(n));
    for (int h = 0; h < n; ++h) {
        const int a = from[std::size_t(h)], b = to[std::size_t(h)];
        byEdge[std::size_t(h)] = {(std::uint64_t(std::uint32_t(std::min(a, b))) << 32)
                                      | std::uint32_t(std::max(a, b)),
                                  h};
    }
    std::sort(byEdge.begin(), byEdge.end());
    for (std::size_t lo = 0, hi = 0; lo < byEdge.size(); lo = hi) {
        while (hi < byEdge.size() && byEdge[hi].first == byEdge[lo].first)
            ++hi;
        // The first half-edge of each direction (the group is in half-edge order).
        const int low = int(byEdge[lo].first >> 32);
        int firstLow = -1, firstHigh = -1;
        for (std::size_t i = lo; i < hi; ++i) {
            const int h = byEdge[i].second;
            int &firstOf = from[std::size_t(h)] == low ? firstLow : firstHigh;
            if (firstOf < 0)
                firstOf = h;
        }
        for (std::size_t i = lo; i < hi; ++i) {
            const int h = byEdge[i].second;
            const bool fromLow = from[std::size_t(h)] == low;
            p.same[std::size_t(h)] = fromLow ? firstLow : firstHigh;
            p.opposite[std::size_t(h)] = fromLow ? firstHigh : firstLow;
            p.halves[std::size_t(h)] = int(hi - lo);
        }
    }
    return p;
}

} // namespace awb
