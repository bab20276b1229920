#pragma once
// The rules of the two mesh schemes (issue 30), as OpenSubdiv 3.5's Sdc applies them with
// Sdc::Options::VTX_BOUNDARY_EDGE_ONLY and TRI_SUB_CATMARK: the weights only; MeshRefine.h
// applies them to a topology. Every boundary vertex (a corner of one face included) takes the
// crease rule (1/8, 3/4, 1/8) and the limit mask (1/6, 2/3, 1/6), so that the boundary is the
// cubic B-spline of the boundary polygon; a boundary edge point is the edge's midpoint.
//
// Catmull-Clark, interior vertex of valence n (any polygons around it):
//   face point   the centroid of the face;
//   edge point   (v0 + v1 + f0 + f1) / 4 with the points f of its two faces;
//   vertex point (n - 2)/n v + 1/n^2 sum of the n edge neighbours + 1/n^2 sum of the n face points;
//   limit (all faces around v quads)  (n^2 v + 4 sum e_j + sum d_j) / (n (n + 5)), with e_j the
//   edge neighbours and d_j the diagonal corners of the quads (Halstead, Kass, DeRose 1993).
// Loop, interior vertex of valence n (triangles):
//   edge point   3/8 (v0 + v1) + 1/8 (o0 + o1), o the corners opposite the edge;
//   vertex point (1 - n beta) v + beta sum of the n neighbours,
//                beta = (5/8 - (3/8 + cos(2 pi / n)/4)^2) / n  (Loop 1987);
//   limit        (1 - n chi) v + chi sum of the neighbours, chi = 1 / (3 / (8 beta) + n).

#include <cmath>

namespace awb::meshrules {

inline double loopBeta(int n)
{
    const double c = 3.0 / 8.0 + std::cos(2.0 * M_PI / n) / 4.0;
    return (5.0 / 8.0 - c * c) / n;
}

inline double loopLimitNeighbour(int n) { return 1.0 / (3.0 / (8.0 * loopBeta(n)) + n); }

// Catmull-Clark vertex point: the weight of the vertex, and of each edge neighbour and each
// face point.
inline double catmarkVertexSelf(int n) { return double(n - 2) / n; }
inline double catmarkVertexRing(int n) { return 1.0 / (double(n) * n); }

// Catmull-Clark limit of a vertex whose faces are all quads.
inline double catmarkLimitSelf(int n) { return double(n) / (n + 5); }
inline double catmarkLimitEdge(int n) { return 4.0 / (double(n) * (n + 5)); }
inline double catmarkLimitDiagonal(int n) { return 1.0 / (double(n) * (n + 5)); }

// Boundary (crease) rules of both schemes.
constexpr double kCreaseSelf = 0.75, kCreaseNeighbour = 0.125;
constexpr double kCreaseLimitSelf = 2.0 / 3.0, kCreaseLimitNeighbour = 1.0 / 6.0;

} // namespace awb::meshrules
