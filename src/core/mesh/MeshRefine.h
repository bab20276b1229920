#pragma once
// One step of Catmull-Clark or Loop on a mesh of any topology, and the limit positions of its
// vertices (issue 30), as stencils: each new point a weighted sum of the old ones. The same
// stencils move positions, build the local subdivision matrix of a vertex (VertexSpectrum.h),
// and compose into limit stencils, so that nothing is computed twice in two ways.
//
// Numbering of the refined mesh: the vertex points first, with the numbers of their vertices
// (vertex v of the input is vertex v at every level), then one point per edge (in the
// topology's edge order), then, for Catmull-Clark, one per face.

#include "core/mesh/Mesh.h"

#include <initializer_list>
#include <iterator>
#include <span>
#include <utility>
#include <vector>

namespace awb {

// (old point, weight), weights sum to 1. (Not LatticeScheme.h's Stencil, on lattice points.)
using MeshStencil = std::vector<std::pair<int, double>>;

// Many stencils in one table (OpenSubdiv's Far::StencilTable): a million points' stencils are
// three allocations, not a million; points and weights side by side, as OpenSubdiv keeps them
// (12 bytes an entry, where a (point, weight) pair takes 16: a large mesh's isolation is a
// tenth of its peak). Stencil i is read as a range of (point, weight).
class StencilTable {
public:
    using Entry = std::pair<int, double>;
    class Stencil {
    public:
        class iterator {
        public:
            using iterator_category = std::input_iterator_tag;
            using value_type = Entry;
            using difference_type = std::ptrdiff_t;
            using reference = Entry;
            using pointer = void;
            iterator() = default;
            iterator(const int *p, const double *w) : m_p(p), m_w(w) {}
            Entry operator*() const { return {*m_p, *m_w}; }
            iterator &operator++()
            {
                ++m_p;
                ++m_w;
                return *this;
            }
            iterator operator++(int)
            {
                iterator was = *this;
                ++*this;
                return was;
            }
            bool operator==(const iterator &o) const { return m_p == o.m_p; }

        private:
            const int *m_p = nullptr;
            const double *m_w = nullptr;
        };
        Stencil(const int *points, const double *weights, std::size_t n)
            : m_points(points), m_weights(weights), m_size(n)
        {
        }
        iterator begin() const { return {m_points, m_weights}; }
        iterator end() const { return {m_points + m_size, m_weights + m_size}; }
        std::size_t size() const { return m_size; }

    private:
        const int *m_points;
        const double *m_weights;
        std::size_t m_size;
    };

    std::size_t size() const { return m_start.size() - 1; }
    bool empty() const { return size() == 0; }
    Stencil operator[](std::size_t i) const
    {
        return {m_points.data() + m_start[i], m_weights.data() + m_start[i],
                m_start[i + 1] - m_start[i]};
    }
    std::size_t entryCount() const { return m_points.size(); }
    void reserve(std::size_t stencils, std::size_t entries)
    {
        m_start.reserve(stencils + 1);
        m_points.reserve(entries);
        m_weights.reserve(entries);
    }
    template <class Range>
    void push_back(const Range &stencil)
    {
        for (const auto &[p, w] : stencil) {
            m_points.push_back(p);
            m_weights.push_back(w);
        }
        m_start.push_back(m_points.size());
    }
    void push_back(std::initializer_list<Entry> stencil)
    {
        push_back(std::span<const Entry>(stencil.begin(), stencil.size()));
    }
    // Keeps the first n stencils.
    void truncate(std::size_t n)
    {
        if (n >= size())
            return;
        m_start.resize(n + 1);
        m_points.resize(m_start.back());
        m_weights.resize(m_start.back());
    }

private:
    BigVector<std::size_t> m_start{0};
    BigVector<int> m_points;
    BigVector<double> m_weights;
};

struct Refinement {
    IndexRows faces;                      // of the refined mesh, counter-clockwise
    StencilTable stencils;                // one per point of the refined mesh (numbered as above)
    int pointCount = 0;                   // the points of the refined mesh (stencils' count)
    MeshScheme scheme = MeshScheme::CatmullClark;  // whose step made it
    MeshSharpness sharpness;              // its sharp features one level down (MeshTags.h)
};

// Sorts a stencil by point and sums the weights of each point, in place.
void mergeStencil(MeshStencil &stencil);

// Appends to `out` the stencil `outer` (over the points of a refinement) as a stencil over the
// old points, given the refinement's stencils `inner`.
void appendComposed(StencilTable &out, std::span<const StencilTable::Entry> outer,
                    const StencilTable &inner);

// One step on a topology (checked: triangles only for Loop; InputError otherwise), with the
// rules of its sharp features as OpenSubdiv 3.5 applies them (Sdc::Scheme's masks with the
// rule of each vertex and edge, semi-sharp features blended where they end).
Refinement refineTopology(const MeshTopology &topology, MeshScheme scheme);

// The topology of the refined mesh, with its sharp features, its relations derived from those
// of `parent`, the topology refined (the second takes the refinement's faces).
MeshTopology refinedTopology(const MeshTopology &parent, const Refinement &refinement);
MeshTopology refinedTopology(const MeshTopology &parent, Refinement &&refinement);

// The tags that give `topology`'s sharp features back (interior edges and vertices of nonzero
// sharpness, holes, options).
MeshTags tagsOf(const MeshTopology &topology);

// rows of data (one per old point) -> one row per stencil.
Mat applyStencils(const StencilTable &stencils, const Mat &data);

// The mesh after `steps` steps (checked by checkMesh first). A non-manifold mesh is refined as
// its manifold sheets (MeshSheets.h): a vertex on a non-manifold edge or vertex appears once
// per sheet, at one position, and the sharp features carry OpenSubdiv's rules there.
Mesh refineMesh(const Mesh &mesh, MeshScheme scheme, int steps = 1);

// The limit position of every vertex of the topology as a stencil on its vertices: the masks of
// MeshRules.h by each vertex's rule at this level (as OpenSubdiv's PrimvarRefiner::Limit: a
// semi-sharp feature counts as sharp; limitPositions() refines past them first); for a Catmull-Clark vertex next to a face that is not a quad, the mask of its
// point after one step composed with that step. A vertex of no face stays where it is.
StencilTable limitStencils(const MeshTopology &topology, MeshScheme scheme);

// The limit positions of the mesh's vertices (n x 3; a non-manifold mesh's from its sheets,
// MeshSheets.h): the limit stencils after the levels
// that its semi-sharp features last (at most 10; InputError when that mesh would pass
// kMaxPreludeFaces faces).
constexpr long long kMaxPreludeFaces = 4000000;
// The levels the semi-sharp features of `topology` last (0 when none).
int preludeLevels(const MeshTopology &topology);
Mat limitPositions(const Mesh &mesh, MeshScheme scheme);

} // namespace awb
