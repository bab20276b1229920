#pragma once
// A non-manifold mesh as OpenSubdiv 3.5 draws it (issue 44), made of manifold sheets with sharp
// features, so that every rule, piece and analysis of the mesh room applies unchanged.
//
// OpenSubdiv's rules (Vtr::Level::completeTopologyFromFaceVertices and
// Far::TopologyRefinerFactoryBase::prepareComponentTagsAndSharpness):
//   - an edge is non-manifold when more than two faces share it, or when its two faces run
//     along it in the same direction (their orientations disagree); both its ends are
//     non-manifold vertices, and so is a vertex whose faces form several fans (a "bowtie");
//   - a non-manifold edge is infinitely sharp;
//   - a non-manifold vertex is infinitely sharp (a corner), except on an interior
//     non-manifold crease: exactly two non-manifold edges, no boundary edge and more faces than
//     edges (fins along a crease), where the rule follows from its sharp edges as anywhere.
// Under these rules no subdivision mask reaches across a non-manifold edge or vertex but along
// the crease curves, which every sheet shares. So the mesh is cut there: each fan of faces
// around a vertex gets its own copy of the vertex (the first fan keeps the vertex's number,
// the others are appended), each non-manifold edge is tagged infinitely sharp in every sheet,
// and each non-manifold vertex's copies carry the sharpness OpenSubdiv gives it. The copies of
// a vertex move together at every level (corners stay, crease vertices follow the same crease
// rule on the same neighbours), so the sheets' limit surface is OpenSubdiv's (tested against
// it on its own non-manifold regression shapes). docs/mathematics.md, "Non-manifold meshes".
//
// Not reproduced: at a fin-crease vertex where a semi-sharp edge of one sheet meets the crease,
// OpenSubdiv counts that edge in every sheet's rule; here its copies carry the edge's sharpness
// as vertex sharpness, which gives the same rule at every level but may blend differently on
// the level where the edge's sharpness ends. Qt-free.

#include "core/mesh/Mesh.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace awb {

struct ManifoldSheets {
    Mesh mesh;                  // the input's vertices, then the copies; its faces; tags
    std::vector<int> original;  // per vertex of `mesh`: the input's vertex (identity below n)
    // What makes the input non-manifold, in the input's numbers, each sorted.
    std::vector<std::pair<int, int>> edges;  // non-manifold edges (a < b)
    std::vector<int> vertices;               // non-manifold vertices
    std::vector<int> creaseVertices;         // the ones on an interior crease (not corners)
    int copies = 0;                          // vertices appended
};

// The sheets of `mesh`, or nothing when it is manifold and consistently oriented (or when its
// faces are not well formed: checkMesh says why). Throws InputError for a tag that names a
// vertex the mesh does not have.
std::optional<ManifoldSheets> manifoldSheets(const Mesh &mesh);

// One sentence for the user: how many edges and vertices are non-manifold (the first few
// named) and how they are drawn.
std::string describe(const ManifoldSheets &sheets);

// The mesh as it is drawn and its checked topology: the mesh itself when checkMesh takes it
// (a manifold mesh costs one check, as before the sheets), else its manifold sheets, checked;
// when the mesh has no sheets either, checkMesh's refusal of the mesh itself.
struct DrawnMesh {
    std::optional<ManifoldSheets> sheets;
    MeshTopology topology;
    const Mesh &mesh(const Mesh &input) const { return sheets ? sheets->mesh : input; }
};
DrawnMesh drawnMesh(const Mesh &mesh, MeshScheme scheme);
inline void checkDrawnMesh(const Mesh &mesh, MeshScheme scheme) { drawnMesh(mesh, scheme); }

} // namespace awb
