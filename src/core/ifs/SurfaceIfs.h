#pragma once
// The IFS of a subdivision surface patch (000 §3): f_i(X) = X P^-1 S_i P with control points in
// R^3 lifted as for curves (000 §2), over any subset of the layout's maps (000 Fig. 9: a
// subset draws a fractal lying on the surface). Role in the core: what a surface document item
// derives from its inputs.

#include "core/ifs/Ifs.h"
#include "core/schemes/SurfacePatch.h"

namespace awb {

struct SurfaceIfs {
    PatchLayout layout;
    std::vector<LatticePoint> lattice;  // the user's lattice coordinates, one per control point
    std::vector<Mat> S;                 // every map's S_i, rows/columns in the user's order
    std::vector<int> mapsUsed;          // 0-based, ascending; the IFS has these maps in order
    SubdivisionIfs ifs;                 // of the used maps (lifted, or barycentric when P is flat)
    // The limit point at each corner of the domain (d columns), and the same points in the IFS
    // space (the barycentric limit weights lambda times the lifted P, or lambda itself in
    // barycentric form). Started from the latter, F^k(X0) is exactly the set of limit points
    // of the level-k corners; started from the former (plane coordinates lifted with zero extra
    // coordinates, another point of the lifted space) it only converges to the surface.
    Mat cornerLimitPoints;
    Mat cornerLimitStart;
};

// Throws InputError naming the problem: a net that is not the layout's (matchNet), non-finite
// control points, an empty or out-of-range subset of maps. The lifting's free rows are chosen
// by affineBasisRows(); a net in one plane falls back to the barycentric form.
SurfaceIfs buildSurfaceIfs(const LatticeScheme &scheme, const PatchLayout &layout,
                           const std::vector<LatticePoint> &lattice, const Mat &P,
                           std::vector<int> mapsUsed = {});
// The same with the layout's canonical matrices already computed (surfaceMatrices(scheme,
// layout)): callers that rebuild the IFS on every edit keep them.
SurfaceIfs buildSurfaceIfs(const LatticeScheme &scheme, const PatchLayout &layout,
                           const SurfaceMatrices &canonical,
                           const std::vector<LatticePoint> &lattice, const Mat &P,
                           std::vector<int> mapsUsed = {});

} // namespace awb
