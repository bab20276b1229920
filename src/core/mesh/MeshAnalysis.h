#pragma once
// What the eigenvalues say at every extraordinary vertex of a mesh (issue 30): the vertex's
// local subdivision matrix, its spectrum, Reif's C1 criterion and the curvature verdict
// (VertexSpectrum.h), the limit position and the tangent plane (the left eigenvectors of S on
// the vertex piece's net, MeshPieces.h).

#include "core/mesh/MeshPieces.h"
#include "core/mesh/VertexSpectrum.h"

#include <complex>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace awb {

// A matrix analysed and its spectrum, shared by every vertex of the same kind (a mesh of a
// million faces has hundreds of thousands of extraordinary vertices and a few kinds).
struct AnalysedMatrix {
    Mat S;
    std::vector<Complex> eigenvalues;  // by modulus, largest first
};

struct ExtraordinaryVertex {
    int vertex = -1;  // the input's vertex, or -1
    int face = -1;    // a Catmull-Clark face that is not a quad, whose centre this is, or -1
    int valence = 0;
    bool boundary = false;
    // Its rule once its semi-sharp features have ended (MeshTags.h): "smooth", "dart" (one
    // sharp edge), "crease" (two), "corner" (more, or a sharp vertex); a boundary vertex is a
    // crease or corner.
    std::string rule = "smooth";
    // A smooth interior vertex: the ring analysis (VertexSpectrum.h) applies; elsewhere the
    // vertex piece's own S.
    bool smoothInterior() const { return !boundary && rule == "smooth"; }
    // The matrix analysed: at a smooth interior vertex, the ring of every point within two faces
    // (6n + 1 points for Catmull-Clark, 3n + 1 for Loop, VertexSpectrum); on the boundary and at
    // sharp features, the vertex piece's net.
    std::string ring;
    int ringSize = 0;
    std::shared_ptr<const AnalysedMatrix> matrix;  // none when not analysed
    // That matrix, ringSize x ringSize (empty when not analysed), and its eigenvalues.
    const Mat &S() const;
    const std::vector<Complex> &eigenvalues() const;
    double subdominant = 0.0;          // lambda
    double subsubdominant = 0.0;       // mu: the largest modulus below lambda
    // Smooth inside: Reif's criterion (spectral and characteristic map) and mu against
    // lambda^2. On the boundary and at sharp features: the same sector by sector, on the
    // canonical star of the vertex's neighbourhood (`sharp`, VertexSpectrum.h); not decided
    // (nullopt, "") above valence 64.
    std::optional<bool> c1;
    std::string curvature;
    std::shared_ptr<const SharpVertexSpectrum> sharp;  // on the boundary, at sharp features
    RowVec limit;   // 1 x 3
    RowVec normal;  // 1 x 3, unit (zero when the tangents are parallel)
    // Why the ring was not analysed (an interior valence of 2, or above 64), or "".
    std::string note;
};

// Interior vertices of valence != 4 (Catmull-Clark) or != 6 (Loop), boundary vertices of two
// or more faces and valence != 3 or 4, and the centres of Catmull-Clark faces that are not
// quads; in the order: input vertices, then faces.
std::vector<ExtraordinaryVertex> extraordinaryVertices(const MeshPieces &pieces,
                                                       const Mat &inputVertices);
// How many extraordinaryVertices() lists, without analysing them (import's report).
int extraordinaryCount(const MeshPieces &pieces);

} // namespace awb
