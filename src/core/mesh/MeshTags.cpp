#include "core/mesh/MeshTags.h"

#include <algorithm>
#include <map>
#include <set>

namespace awb {

RepeatedTags mergeRepeatedTags(MeshTags &tags)
{
    RepeatedTags out;
    {
        std::map<std::pair<int, int>, std::size_t> at;  // edge -> its place in `kept`
        std::vector<SharpEdge> kept;
        for (const SharpEdge &e : tags.edges) {
            const auto key = std::minmax(e.a, e.b);
            const auto [it, added] = at.try_emplace({key.first, key.second}, kept.size());
            if (added) {
                kept.push_back(e);
                continue;
            }
            if (out.edges++ == 0)
                out.firstEdge = e;
            kept[it->second].sharpness = e.sharpness;
        }
        tags.edges = std::move(kept);
    }
    {
        std::map<int, std::size_t> at;
        std::vector<SharpVertex> kept;
        for (const SharpVertex &v : tags.vertices) {
            const auto [it, added] = at.try_emplace(v.vertex, kept.size());
            if (added) {
                kept.push_back(v);
                continue;
            }
            if (out.vertices++ == 0)
                out.firstVertex = v.vertex;
            kept[it->second].sharpness = v.sharpness;
        }
        tags.vertices = std::move(kept);
    }
    std::set<int> seen;
    std::vector<int> holes;
    for (int f : tags.holes) {
        if (seen.insert(f).second)
            holes.push_back(f);
        else
            ++out.holes;
    }
    tags.holes = std::move(holes);
    return out;
}

std::string toString(BoundaryInterpolation value)
{
    switch (value) {
    case BoundaryInterpolation::None:
        return "none";
    case BoundaryInterpolation::EdgeAndCorner:
        return "edge-and-corner";
    case BoundaryInterpolation::EdgeOnly:
        break;
    }
    return "edge-only";
}

std::string toString(CreaseMethod value)
{
    return value == CreaseMethod::Chaikin ? "chaikin" : "uniform";
}

std::string toString(TriangleSubdivision value)
{
    return value == TriangleSubdivision::Smooth ? "smooth" : "catmark";
}

std::string toString(VertexRule rule)
{
    switch (rule) {
    case VertexRule::Dart:
        return "dart";
    case VertexRule::Crease:
        return "crease";
    case VertexRule::Corner:
        return "corner";
    case VertexRule::Smooth:
        break;
    }
    return "smooth";
}

bool parseBoundaryInterpolation(const std::string &name, BoundaryInterpolation *out)
{
    for (auto v : {BoundaryInterpolation::None, BoundaryInterpolation::EdgeOnly,
                   BoundaryInterpolation::EdgeAndCorner})
        if (toString(v) == name) {
            *out = v;
            return true;
        }
    return false;
}

bool parseCreaseMethod(const std::string &name, CreaseMethod *out)
{
    for (auto v : {CreaseMethod::Uniform, CreaseMethod::Chaikin})
        if (toString(v) == name) {
            *out = v;
            return true;
        }
    return false;
}

bool parseTriangleSubdivision(const std::string &name, TriangleSubdivision *out)
{
    for (auto v : {TriangleSubdivision::Catmark, TriangleSubdivision::Smooth})
        if (toString(v) == name) {
            *out = v;
            return true;
        }
    return false;
}

namespace crease {

VertexRule vertexRule(float vertexSharpness, int sharpEdgeCount)
{
    if (isSharp(vertexSharpness) || sharpEdgeCount > 2)
        return VertexRule::Corner;
    return sharpEdgeCount == 2   ? VertexRule::Crease
           : sharpEdgeCount == 1 ? VertexRule::Dart
                                 : VertexRule::Smooth;
}

VertexRule vertexRule(float vertexSharpness, const std::vector<float> &edgeSharpness)
{
    int sharp = 0;
    for (float s : edgeSharpness)
        sharp += isSharp(s) ? 1 : 0;
    return vertexRule(vertexSharpness, sharp);
}

std::vector<float> subdivideAroundVertex(const std::vector<float> &parent, CreaseMethod method)
{
    std::vector<float> child(parent.size());
    float sum = 0.0f;
    int count = 0;
    for (float s : parent)
        if (isSemiSharp(s)) {
            ++count;
            sum += s;
        }
    for (std::size_t i = 0; i < parent.size(); ++i) {
        const float s = parent[i];
        if (method == CreaseMethod::Uniform || parent.size() < 2 || count < 2
            || !isSemiSharp(s)) {
            child[i] = decrement(s);
            continue;
        }
        // Chaikin: 3/4 of its own and 1/4 of the mean of the other semi-sharp edges, minus 1.
        const float others = (sum - s) / float(count - 1);
        const float c = (0.75f * s + 0.25f * others) - 1.0f;
        child[i] = isSharp(c) ? c : kSharpnessSmooth;
    }
    return child;
}

float fractionalWeight(float parentVertex, float childVertex, const std::vector<float> &parent,
                       const std::vector<float> &child, CreaseMethod method)
{
    int count = 0;
    float sum = 0.0f;
    if (isSharp(parentVertex) && !isSharp(childVertex)) {
        count = 1;
        sum = parentVertex;
    }
    for (std::size_t i = 0; i < parent.size(); ++i) {
        const bool transition = method == CreaseMethod::Uniform
                                    ? isSharp(parent[i]) && parent[i] <= 1.0f
                                    : isSharp(parent[i]) && !isSharp(child[i]);
        if (transition) {
            sum += parent[i];
            ++count;
        }
    }
    if (count == 0)
        return 0.0f;
    const float weight = sum / float(count);
    return weight > 1.0f ? 1.0f : weight;
}

} // namespace crease

} // namespace awb
