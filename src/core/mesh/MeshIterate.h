#pragma once
// The images of a mesh's IFS with condensation (MeshPieces.h) at a depth: every piece of the
// isolated mesh is carried down its maps, and each image of the start set is sent to a sink
// like awb::iterateParallel does for one IFS. The image of a start point x under the maps
// f_w = f_{w_1} ... f_{w_K} of the lifted space is computed as w S_{w_K} ... S_{w_1} P: its
// weights over the net P of the piece it starts in, carried by the matrices -- the projection
// of x P^-1 S_w P.

#include "core/ifs/Attractor.h"
#include "core/mesh/MeshPieces.h"

namespace awb {

struct MeshStart {
    enum class Kind {
        // The limit stencils of each piece's corners: depth K gives exactly the limit
        // positions of the vertices of the mesh refined K times.
        VertexLimits,
        // Each piece's corners themselves: depth K gives the vertices of the mesh refined K
        // times (the classic refinement), which converge to the surface.
        ControlPoints,
        // A set of points of R^3 (any StartSet kind), taken into the lifted space of each
        // piece type by its least-norm weights over the net of the type's first piece below
        // the root (the root's own net for the root's type): any start set converges to the
        // attractor (000 §2), like 2^-K on regular pieces.
        Points,
    };
    Kind kind = Kind::VertexLimits;
    StartSet points;
    // Addresses that show the construction: an image inside the neighbourhood of an
    // extraordinary vertex gets as first symbol its level k (it lies in f^k(C)), an image of a
    // regular patch its first map as usual.
    bool levelAddresses = false;
};

// The number of points iterateMesh sends at `depth`.
double meshPointCount(const MeshPieces &pieces, const MeshStart &start, int depth);

// Streams the images of depth `depth` to `sinks` (one thread each, pieces shared out). The
// address of an image is the path of maps from its root piece (map 0 of a vertex piece: the
// neighbourhood one level finer). Depths below the isolation steps (VertexLimits,
// ControlPoints) send the refined mesh's vertex limits or vertices in one image. Throws
// InputError for a depth outside 0..64, more than 2^31 points, or a start set that is not 3D.
IterationStats iterateMesh(const MeshPieces &pieces, const Mat &inputVertices,
                           const MeshStart &start, int depth,
                           const std::vector<AttractorSink *> &sinks,
                           const IterationControl &control = {});

} // namespace awb
