#pragma once
// Repairs of a non-manifold or refused mesh (issue 44: `import-mesh --repair`, and the
// question File > Import Mesh asks), each only where it is well defined:
//   - a face that names the same vertex twice in a row names it once (a face left with fewer
//     than three vertices is removed);
//   - boundary vertices at exactly the same position are welded, one group at a time, when the
//     weld leaves no face naming a vertex twice and no edge of three faces (seams of exporters
//     that split vertices by texture coordinates);
//   - the faces of each connected surface are turned to one orientation, the majority's (a
//     surface that cannot be oriented, a Möbius band, is left as it is and said);
//   - a vertex whose faces form several fans (a "bowtie") becomes one vertex per fan: the first
//     keeps the number, the others are appended, at the same position.
// Edges of three or more faces are not repaired (no choice of sheets is canonical); they are
// said, and drawn as OpenSubdiv draws them (MeshSheets.h), as every unrepaired non-manifold
// mesh is: the repairs are the user's choice of another surface. The vertices keep their numbers (a welded vertex stays, used by no face), tags follow
// the vertices and faces they name. Qt-free.

#include "core/mesh/Mesh.h"

#include <string>
#include <vector>

namespace awb {

struct MeshRepairReport {
    int collapsedFaces = 0;   // faces whose repeated vertices were named once
    int removedFaces = 0;     // faces left with fewer than three vertices
    int weldedVertices = 0;   // vertices welded into another at the same position
    int turnedFaces = 0;      // faces turned over
    int splitVertices = 0;    // bowtie vertices split
    int addedVertices = 0;    // the vertices those splits added
    // What was changed and what could not be, one sentence each (first few faces or vertices
    // named, 0-based as the item numbers them).
    std::vector<std::string> changes;
    std::vector<std::string> unrepaired;
    bool changed() const
    {
        return collapsedFaces + removedFaces + weldedVertices + turnedFaces + splitVertices > 0;
    }
};

Mesh repairMesh(const Mesh &mesh, MeshRepairReport *report);

} // namespace awb
