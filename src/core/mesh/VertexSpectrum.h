#pragma once
// The local subdivision matrix of an interior vertex of valence n (issue 30) and what its
// eigenvalues say about the limit surface there (Doo-Sabin 1978, Reif 1995, Stam 1998,
// Peters-Reif 2008).
//
// The matrix is read off the scheme's own stencils (MeshRefine.h): a star of n sectors, regular
// but for its centre, is refined once, and S maps the ring of the centre -- every point within
// two faces of it: 6n + 1 points for Catmull-Clark (n quads around the vertex and the quads
// around those), 3n + 1 for Loop -- to the same ring one level finer. The ring holds every
// control point of the patches around the vertex, so its eigenvalues are those the analysis
// needs (the 1-ring's, and the smaller ones of the outer points: 1/8, 1/16, ...).

#include "core/mesh/Mesh.h"

#include <complex>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace awb {

// The characteristic map of `Q` (ring x 2, rows in the order of S) checked numerically: the
// star refined three times, the limit positions of its vertices, the signed area of the image
// of every face over the n faces around the centre (except those at the centre) -- the
// Jacobian's sign, cell by cell -- and the winding number of the image of their outer
// boundary around the centre's image.
// The image itself is kept for drawing (the characteristic map view, issue 31): every face of
// the refined star over the n faces around the centre as a loop of limit positions, its signed
// area (0 at the centre, where the Jacobian vanishes and nothing is checked) and its sector,
// and the image of the outer boundary, once around.
struct CharacteristicMap {
    double minArea = 0.0, maxArea = 0.0;  // signed areas of the faces' images
    int winding = 0;
    std::vector<std::vector<Eigen::Vector2d>> cells;
    std::vector<double> cellAreas;
    std::vector<int> cellSectors;
    std::vector<Eigen::Vector2d> outline;
    bool regular() const { return minArea > 0 || maxArea < 0; }
    bool injective() const { return regular() && (minArea > 0 ? winding == 1 : winding == -1); }
};

struct VertexSpectrum {
    MeshScheme scheme = MeshScheme::CatmullClark;
    int valence = 0;
    Mat S;                              // ring x ring, rows sum to 1
    std::vector<Complex> eigenvalues;   // by modulus, largest first (1 first)
    double subdominant = 0.0;           // lambda = lambda_2 = lambda_3
    double subsubdominant = 0.0;        // mu = |lambda_4|
    // The spectral part of Reif's C1 criterion: 1 = lambda_1 > lambda_2 = lambda_3 > |lambda_4|,
    // lambda_2 real.
    bool spectralC1 = false;
    // The characteristic map (the limit surface of the two real eigenvectors of lambda as
    // planar control points) over the n faces around the vertex: regular (its Jacobian keeps
    // one sign) and injective (regular, and the image of the faces' outer boundary winds once
    // around the vertex's image) -- Reif's criterion: spectralC1 and both make the surface C1
    // at the vertex for generic data.
    bool characteristicRegular = false;
    bool characteristicInjective = false;
    CharacteristicMap characteristic;   // when spectralC1: the map checked, for drawing
    bool c1 = false;
    // mu against lambda^2: "zero" (mu < lambda^2: the curvature vanishes at the vertex),
    // "bounded" (mu = lambda^2), "unbounded" (mu > lambda^2, for generic data).
    std::string curvature;
};

// The analysis of an interior vertex of valence n >= 3 (all faces around it quads for
// Catmull-Clark, triangles for Loop: the case after one step of any mesh). InputError for
// n < 3 or n > 64.
VertexSpectrum interiorVertexSpectrum(MeshScheme scheme, int valence);
// Whether interiorVertexSpectrum takes this valence (3 to 64).
inline bool ringAnalysable(int valence) { return valence >= 3 && valence <= 64; }

// The characteristic map of `Q` (see CharacteristicMap above).
CharacteristicMap checkCharacteristicMap(MeshScheme scheme, int valence, const Mat &Q);

// The subdominant eigenvalue in closed form: Catmull-Clark
// (5 + cos(2 pi/n) + cos(pi/n) sqrt(2 (9 + cos(2 pi/n)))) / 16 (Stam 1998), Loop
// 3/8 + cos(2 pi/n) / 4.
double closedFormSubdominant(MeshScheme scheme, int valence);

// interiorVertexSpectrum, computed once per (scheme, valence) in the process and shared
// (thread-safe): a mesh's analysis and the valence explorer ask for the same few valences
// again on every edit.
std::shared_ptr<const VertexSpectrum> sharedVertexSpectrum(MeshScheme scheme, int valence);

// The valence explorer's table (issue 31): the spectra of n = from ... to.
std::vector<VertexSpectrum> valenceSpectra(MeshScheme scheme, int from, int to);

// ---- On the boundary and at sharp features (issue 44) -----------------------------------------

// A vertex on the boundary or with infinitely sharp features, as a canonical star: its valence
// (edges), whether its fan is open (a boundary vertex: edges 0 and valence - 1 are the
// boundary), which of its edges are infinitely sharp in ring order (boundary edges included),
// and whether the vertex itself is (a corner tag). The creases go on straight through the star.
struct SharpNeighbourhood {
    int valence = 0;
    bool boundary = false;
    std::vector<char> sharpEdges;
    bool sharpVertex = false;
    auto operator<=>(const SharpNeighbourhood &) const = default;
};

// Reif's criterion sector by sector (Zorin 2000; Biermann, Levin and Zorin 2000): a sector is a
// run of faces between two sharp edges, or the whole disk around an interior vertex with fewer
// than two. Its points one level finer are combinations of its own, so it has its own matrix
// (S on the sector's rows): the limit there is C1 for generic data (up to the creases, which
// are the sector's boundary) when that matrix's two largest eigenvalues below 1 are real and
// positive, lambda1 >= lambda2 > |lambda3|, and the characteristic map of their eigenvectors
// is regular and injective on the sector (a wedge: its boundary's image a simple curve).
// Jordan blocks (Peters and Reif 2008): a chain at lambda2 < lambda1 leaves the map of the two
// eigenvectors in charge; a chain of two at lambda1 = lambda2 shears the rings, and the map of
// its eigenvector and generalized eigenvector is the one checked (VertexSpectrum.cpp,
// readPair). Curvature: mu against lambda2^2, as inside.
struct SectorVerdict {
    int firstFace = 0;  // in ring order
    int faces = 0;
    double lambda1 = 0.0, lambda2 = 0.0, mu = 0.0;
    bool spectral = false, regular = false, injective = false;
    // False where both eigenvectors vanish on a crease that bounds the sector and the crease's
    // own tangent (a smaller eigenvalue) leaves their plane (VertexSpectrum.cpp,
    // leavesThePlane): the spectrum may pass, the surface is not C1 there. The map is then not
    // checked (it sends the whole crease to the vertex).
    bool creaseInPlane = true;
    // False where the criterion does not apply: a longer chain at lambda1 = lambda2, or a chain
    // beside a second eigenvector of the same value.
    bool decided = true;
    bool c1() const { return decided && spectral && creaseInPlane && regular && injective; }
    std::string reason;     // why not C1, or ""
    std::string chain;      // how a Jordan block among the two largest was read, or ""
    std::string curvature;  // "zero", "bounded", "unbounded"
    CharacteristicMap map;  // when spectral and creaseInPlane
};

struct SharpVertexSpectrum {
    MeshScheme scheme = MeshScheme::CatmullClark;
    SharpNeighbourhood neighbourhood;
    VertexRule rule = VertexRule::Smooth;
    Mat S;                             // the ring's, as VertexSpectrum's
    std::vector<Complex> eigenvalues;  // by modulus, largest first
    std::vector<SectorVerdict> sectors;
    std::optional<bool> c1;            // every sector; nothing when one is not decided
    std::string curvature;             // the worst sector's
};

// InputError for a valence outside 3 to 64 or a sharpEdges of another length.
SharpVertexSpectrum sharpVertexSpectrum(MeshScheme scheme, const SharpNeighbourhood &star);
// Computed once per (scheme, neighbourhood) in the process and shared (thread-safe).
std::shared_ptr<const SharpVertexSpectrum> sharedSharpVertexSpectrum(
    MeshScheme scheme, const SharpNeighbourhood &star);

} // namespace awb
