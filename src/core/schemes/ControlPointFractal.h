#pragma once
// Fractals with control points (000 §4): turning an IFS of affine maps into a subdivision scheme
// so that moving control points deforms the fractal. The core of the "fractal with control
// points" document item; the lifted IFS itself comes from buildSubdivisionIfs (000 §2).
//
// Conventions (as everywhere in awb::core): points are ROW vectors and a map acts as
// x |-> x A + b (A: d x d, b: 1 x d). Control points P: m x d, one point per row.
// S_i: m x m with rows summing to 1, built so that S_i P = f_i(P) (row j of f_i(P) is f_i(P_j)).

#include "core/ifs/Ifs.h"
#include "core/Types.h"

namespace awb {

// How each image point f_i(P_j) is written as an affine combination of P (000 eq. (5)).
// The combination is not unique once m > d + 1, so the caller chooses:
//  * NearestBarycentric: barycentric coordinates in the d + 1 nearest control points that are
//    affinely independent (what 000 §4.1 does for Koch with "the three closest"). Equally near
//    choices are broken towards the smallest sum |w| (a point inside its triangle gets
//    non-negative weights), then towards lower indices; that reproduces the printed Koch S_i.
//  * LeastNorm: the weights w (m of them) of least 2-norm with [P^T; 1^T] w = [y; 1]: every
//    control point takes part, so each one moves the whole fractal a little.
enum class AffineWeights { NearestBarycentric, LeastNorm };
std::string toString(AffineWeights mode);

struct ControlPointMatrices {
    std::vector<Mat> S;             // S_1..S_N, each m x m, rows sum to 1
    int overlap = 0;                // rows shared by consecutive S_i (curve-ordered pieces)
    AffineWeights mode = AffineWeights::NearestBarycentric;
    std::vector<double> residuals;  // per map: max over rows of |(S_i P - f_i(P))_j| (2-norm)
    double maxResidual = 0.0;       // max of residuals: ~1e-16 unless P is ill-conditioned
};

// The general recipe of 000 §4. maps: f_1..f_N in row convention (A: d x d, b: 1 x d);
// P: m x d with d = 2 or 3, m >= d + 1, not all on one line (plane in 3D). Returns N matrices
// m x m. Throws InputError for no maps, maps of the wrong size, non-finite numbers, too few or
// collinear control points.
ControlPointMatrices controlPointMatrices(const std::vector<AffineMap> &maps, const Mat &P,
                                          AffineWeights mode = AffineWeights::NearestBarycentric);

// The weights of one point y (1 x d) against P (m x d): 1 x m, summing to 1, w P = y.
// Same validation as controlPointMatrices.
RowVec nearestBarycentricWeights(const Mat &P, const RowVec &y);
RowVec leastNormWeights(const Mat &P, const RowVec &y);
// The least-norm weights of every row of X (k x d) against P (m x d): k x m, rows summing to 1,
// W P = X. Any weights land on the same attractor, and these exist even for a degenerate
// frame (collinear P); no validation (the controlled IFS and junction items check P first).
Mat leastNormWeightsOfRows(const Mat &P, const Mat &X);

// A preset of 000 §4: the printed matrices, the canonical control points they were made for and
// the classic IFS (ordered so that S_i P = f_i(P) on the canonical P).
struct ControlPointFractal {
    std::string name;
    std::string source;              // paper section and figure
    Mat controlPoints;               // canonical P, m x 2
    std::vector<Mat> S;              // S_1..S_N exactly as printed, m x m
    int overlap = 0;                 // rows shared by consecutive S_i
    std::vector<AffineMap> classicMaps;  // the plane IFS, 2 x 2 linear parts
};

// 000 §4.1, Fig. 10: P = (0,0), (1/3,0), (1/2,√3/6), (2/3,0), (1,0); four maps of ratio 1/3 in
// curve order: f_1 scales about P_1, f_2 and f_3 are the pieces rotated by +60° and -60°, f_4
// scales about P_5. (The paper's prose lists the two end scalings first; its matrices S_1..S_4
// are in curve order, and so are these maps.)
ControlPointFractal kochControlPointFractal();
// 000 §4.2, Fig. 11: P = C_1, M_12, C_2, M_23, C_3, M_31 round the triangle
// C = (0,0), (1,0), (1/2,√3/2) (order per NOTES.md); f_i scales by 1/2 about C_i. S_i uses
// quadratic Lagrange rules on the outer edges and linear ones on the inner edges.
ControlPointFractal sierpinskiControlPointFractal();

// The classic IFS in the plane (2 x 2 maps, identity view, space "plane").
Ifs classicIfs(const ControlPointFractal &fractal);
// The subdivision IFS of the preset's S_i on control points P (m x 2): lifted (M_i m x m, maps
// (m-1) x (m-1)) when P lifts, barycentric otherwise (see buildSubdivisionIfs).
SubdivisionIfs controlPointFractalIfs(const ControlPointFractal &fractal, const Mat &P,
                                      IfsForm form = IfsForm::Automatic);
// The same on the canonical control points.
SubdivisionIfs controlPointFractalIfs(const ControlPointFractal &fractal);

} // namespace awb
