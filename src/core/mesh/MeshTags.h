#pragma once
// The sharp features of a mesh and the options of its rules (issue 44), as OpenSubdiv 3.5 takes
// them (Sdc::Options, Sdc::Crease, the tags of Far::TopologyRefinerFactory and of its regression
// shapes' OBJ `t` lines):
//   edge sharpness    0 smooth, (0, 10) semi-sharp (sharp for that many levels, then smooth),
//                     >= 10 infinitely sharp (a crease); boundary edges are always infinite;
//   vertex sharpness  the same scale: > 0 makes the vertex a corner while it lasts;
//   holes             faces that are refined with the others but not part of the surface;
//   boundary          how the boundary is interpolated: "none" (the faces at a boundary vertex
//                     are holes), "edge-only" (a boundary vertex of one face is a crease
//                     vertex) or "edge-and-corner" (it is a corner: the surface passes through it);
//   crease method     "uniform" (a sharpness drops by 1 per level) or "chaikin" (at a vertex
//                     where several semi-sharp edges meet, 3/4 of its own and 1/4 of the
//                     others' mean, then minus 1);
//   triangles         "catmark" or "smooth" (Catmull-Clark's edge points next to triangles
//                     weighted 0.47 toward the face: OpenSubdiv's TRI_SUB_SMOOTH).
// Sharpness values are floats, as OpenSubdiv keeps them, so that its arithmetic (7.9 - 1 - ...)
// and ours give the same weights. Qt-free.

#include <string>
#include <vector>

namespace awb {

constexpr float kSharpnessSmooth = 0.0f;
constexpr float kSharpnessInfinite = 10.0f;

enum class BoundaryInterpolation { None, EdgeOnly, EdgeAndCorner };
enum class CreaseMethod { Uniform, Chaikin };
enum class TriangleSubdivision { Catmark, Smooth };

struct MeshOptions {
    BoundaryInterpolation boundary = BoundaryInterpolation::EdgeOnly;
    CreaseMethod creaseMethod = CreaseMethod::Uniform;
    TriangleSubdivision triangles = TriangleSubdivision::Catmark;
    bool operator==(const MeshOptions &) const = default;
};

struct SharpEdge {
    int a = 0, b = 0;  // the edge's two vertices, in either order
    float sharpness = kSharpnessInfinite;
    bool operator==(const SharpEdge &) const = default;
};

struct SharpVertex {
    int vertex = 0;
    float sharpness = kSharpnessInfinite;
    bool operator==(const SharpVertex &) const = default;
};

struct MeshTags {
    std::vector<SharpEdge> edges;
    std::vector<SharpVertex> vertices;
    std::vector<int> holes;  // faces
    MeshOptions options;
    bool empty() const
    {
        return edges.empty() && vertices.empty() && holes.empty() && options == MeshOptions{};
    }
    bool operator==(const MeshTags &) const = default;
};

// Tags that name an edge, a vertex or a hole already named, merged as OpenSubdiv applies them
// (in order: the last sharpness wins; a hole twice is one hole), each kept at its first place.
// Returns what was merged: counts, and the first repeated edge and vertex.
struct RepeatedTags {
    int edges = 0, vertices = 0, holes = 0;
    SharpEdge firstEdge;
    int firstVertex = -1;
    int count() const { return edges + vertices + holes; }
};
RepeatedTags mergeRepeatedTags(MeshTags &tags);

// "none", "edge-only", "edge-and-corner"; "uniform", "chaikin"; "catmark", "smooth".
std::string toString(BoundaryInterpolation value);
std::string toString(CreaseMethod value);
std::string toString(TriangleSubdivision value);
// The inverses; false for a name they do not know.
bool parseBoundaryInterpolation(const std::string &name, BoundaryInterpolation *out);
bool parseCreaseMethod(const std::string &name, CreaseMethod *out);
bool parseTriangleSubdivision(const std::string &name, TriangleSubdivision *out);

// Sdc::Crease: the rule of a vertex from its sharpness and its edges'.
enum class VertexRule { Smooth, Dart, Crease, Corner };
std::string toString(VertexRule rule);

namespace crease {

inline bool isSharp(float s) { return s > kSharpnessSmooth; }
inline bool isInfinite(float s) { return s >= kSharpnessInfinite; }
inline bool isSemiSharp(float s) { return s > kSharpnessSmooth && s < kSharpnessInfinite; }

// One level down: infinite stays, above 1 loses 1, the rest becomes smooth.
inline float decrement(float s)
{
    if (!isSharp(s))
        return kSharpnessSmooth;
    if (isInfinite(s))
        return kSharpnessInfinite;
    return s > 1.0f ? s - 1.0f : kSharpnessSmooth;
}

VertexRule vertexRule(float vertexSharpness, int sharpEdgeCount);
VertexRule vertexRule(float vertexSharpness, const std::vector<float> &edgeSharpness);

// The sharpness one level down of each edge at a vertex (the half of the edge at that vertex).
std::vector<float> subdivideAroundVertex(const std::vector<float> &edgeSharpness,
                                         CreaseMethod method);

// The weight of the parent's rule in a vertex point whose rule changes between the levels.
float fractionalWeight(float parentVertex, float childVertex, const std::vector<float> &parent,
                       const std::vector<float> &child, CreaseMethod method);

} // namespace crease

} // namespace awb
