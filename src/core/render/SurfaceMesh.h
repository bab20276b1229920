#pragma once
// F^k(X0) of a 3D attractor as flat primitives in world space: the images of the start set
// (triangles of a polygon start set, fan-triangulated; segments of a polyline; points), each
// with a colour index and, for triangles, its unit normal. Built once per IFS, start set and
// depth, it is drawn from any camera without iterating again: the 3D view's frames (SurfaceRaster
// on the CPU, or OpenGL), its exports and prints draw the same primitives in the same colours.
// Qt-free.

#include "core/ifs/Attractor.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace awb {

struct SurfaceMesh {
    enum class Kind { Points, Segments, Triangles };
    Kind kind = Kind::Triangles;
    std::vector<double> positions;      // 3 per vertex, vertices() per primitive
    std::vector<float> normals;         // 3 per primitive (triangles; zero when degenerate)
    std::vector<std::uint32_t> labels;  // colour index per primitive
    // Built with a weight (buildSurfaceMesh's `weight`): each vertex's coefficient on one
    // control point (SubdivisionIfs::netCoordinates), 1 per vertex; empty otherwise.
    std::vector<double> weights;
    int depth = 0;
    double area = 0.0;                  // total area of the triangles
    std::uint64_t nonFinite = 0;        // images left out: a coordinate was NaN or infinite

    int vertices() const { return kind == Kind::Points ? 1 : kind == Kind::Segments ? 2 : 3; }
    std::size_t size() const { return labels.size(); }
    bool empty() const { return labels.empty(); }
    // Appends `other` (same kind).
    void append(const SurfaceMesh &other);
};

// The colour index of an image from its address (address[0] = the outermost map), e.g. the
// map's colour, or the address prefix's place in a gradient.
using ImageLabel = std::function<std::uint32_t(const std::uint8_t *address, int length)>;

// Collects the images it is fed (one sink per thread; append the results in thread order).
class SurfaceMeshSink : public AttractorSink {
public:
    // `weight` (D x 1 and its constant; no columns: none) gives each vertex its weight.
    SurfaceMeshSink(std::vector<Projection> views, ImageLabel label, SurfaceMesh::Kind kind,
                    Projection weight = {});
    // Room for this many primitives (an estimate: more still fit).
    void reserve(std::size_t primitives);
    void consume(const Mat &v, StartSet::Kind k, const std::uint8_t *a, int n) override;
    // The views, then the weight when there is one: the iteration fuses them with its last map.
    const std::vector<Projection> *projections() const override { return &m_projections; }
    void consumeProjected(const std::vector<Mat> &projected, StartSet::Kind k,
                          const std::uint8_t *a, int n) override;
    SurfaceMesh mesh;

private:
    // One image through one view (n x 3) as primitives; `weights` one per vertex or null.
    void add(const Mat &p, const double *weights, std::uint32_t label);

    std::vector<Projection> m_views;
    ImageLabel m_label;
    Projection m_weight;
    bool m_weighted = false;
    std::vector<Projection> m_projections;  // m_views, then m_weight if weighted
    Mat m_projected;                // the image through a view, reused
    std::vector<double> m_vertexWeight;  // the image's vertices' weights, reused
};

// What an image of `start` becomes: points, segments or triangles.
SurfaceMesh::Kind surfaceMeshKind(const StartSet &start);

// Items drawn by their own iteration (mesh items: an IFS with condensation, its images
// streamed like iterateParallel's): used instead of iterating the Ifs, whose views still say
// how a point is drawn. An empty start set then means the item's exact start (a mesh's vertex
// limits: its images are faces). `identity` is the same object while the data is the same.
struct OwnIteration {
    std::function<IterationStats(const StartSet &, int, const std::vector<AttractorSink *> &,
                                 const IterationControl &)>
        iterate;
    std::function<double(const StartSet &, int)> pointCount;  // points a depth makes
    std::shared_ptr<const void> identity;
};

// F^depth(start) through ifs.views (3 columns each) on `threads` threads (0: all cores).
// Throws InputError like iterate(); an empty mesh when control.cancel stopped it. With a
// `weight` (one column: a control point's column of SubdivisionIfs::netCoordinates) every
// vertex also gets its weight (not with `own`, whose points are not of the IFS space).
SurfaceMesh buildSurfaceMesh(const Ifs &ifs, const StartSet &start, int depth,
                             const ImageLabel &label, const IterationControl &control = {},
                             int threads = 0, const OwnIteration &own = {},
                             const Projection &weight = {});

// The weight of control point `j` as buildSurfaceMesh takes it: column j of the coefficients.
Projection netWeight(const Projection &netCoordinates, int j);

// `base` (built with a weight) drawn after its control point moved by `delta`, each image's
// coefficients on the control points held: every vertex moves by its weight times `delta`,
// and the normals and the area follow. For a lifted IFS this is F^k of the start set carried
// along with the net, sub-pixel from F^k(start) at the view's depths: what a drag of a net
// point shows at full detail in O(vertices) per move, until the release builds F^k(start).
SurfaceMesh movedNetPoint(const SurfaceMesh &base, const Eigen::Vector3d &delta);

// The largest depth <= `depth` whose primitives (images times the primitives of one image;
// with `own`, its points) number at most `budget` (at least 0).
int surfaceMeshDepth(const Ifs &ifs, const StartSet &start, int depth, double budget,
                     const OwnIteration &own = {});

} // namespace awb
