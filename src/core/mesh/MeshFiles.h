#pragma once
// Polygon mesh files for the mesh room (issue 30): Wavefront OBJ, OFF and PLY read into a Mesh,
// and OBJ written from one. A mesh read keeps the file's own vertex numbering (0-based), its face
// order and its polygons as written: nothing is triangulated, welded or dropped, so that the
// vertex and face numbers of later messages (checkMesh, the refinement) are the file's.
// Whatever a reader cannot take whole is an InputError naming the file and the place -- the line
// of a text file, the element of a binary PLY -- and the problem: an index out of range, a
// coordinate that is not a finite number, a face of fewer than 3 vertices, a file that is empty,
// not of its format or truncated, counts that the rest of the file cannot hold (checked before
// anything is allocated for them), data after the last face. The topology (manifold,
// orientation) is checkMesh's (Mesh.h). Qt-free.
//   OBJ  `v` and `f` statements (tinyobjloader, 1-based and negative relative indices,
//        v/vt/vn corners); everything else (vt, vn, groups, materials, lines) is ignored.
//   OFF  ASCII, header OFF or [ST][C][N]OFF (or none), `#` comments, extra columns ignored.
//   PLY  ascii, binary_little_endian and binary_big_endian 1.0: element vertex with x, y, z of
//        any numeric type, element face with the list vertex_indices (or vertex_index); other
//        properties and elements are skipped, and header lines of other keywords (an
//        exporter's own) with a note.
// Text files may start with a byte-order mark: UTF-8's is dropped, UTF-16 (either order) is
// read as the text it encodes.

#include "core/mesh/Mesh.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace awb {

enum class MeshFormat { Obj, Off, Ply };

// "obj", "off", "ply".
std::string toString(MeshFormat format);
// The format of `path` by its extension (.obj, .off, .ply, in any case); InputError naming the
// extension otherwise.
MeshFormat meshFormatForPath(const std::string &path);

// The mesh of the file at `path`, in the format of its extension. OBJ's OpenSubdiv tag lines
// (its regression shapes' `t crease 2/1/0 a b s`, `t corner`, `t hole`,
// `t interpolateboundary`, `t creasemethod`, `t smoothtriangles`; vertices and faces counted
// from 0) become the mesh's tags (MeshTags.h), read as OpenSubdiv's regression reader reads
// them. `notes`, when given, receives what the file holds that the mesh does not keep, one
// sentence each naming the file and the lines: the tags of other names (vertexedit, edgeedit,
// face-varying options). A caller shows them; nothing a file says is dropped without a word.
Mesh readMesh(const std::string &path, std::vector<std::string> *notes = nullptr);
// The mesh of `in`, read to its end (open it in binary mode for a binary PLY); `name` stands for
// the file in messages.
Mesh readMesh(std::istream &in, MeshFormat format, const std::string &name,
              std::vector<std::string> *notes = nullptr);

// Writes `mesh` as OBJ: each line of `comment` as a `# ` line, then `v x y z` with 17
// significant digits (readMesh gives the same doubles back), `f i j k ...` 1-based, and the
// mesh's tags as OpenSubdiv's `t` lines. A mesh
// that readMesh would refuse (no vertices or faces, coordinates that are not finite numbers,
// faces of fewer than 3 vertices or with an index out of range) is an InputError, and nothing is
// written. The caller checks `out`'s state.
void writeObj(std::ostream &out, const Mesh &mesh, const std::string &comment);

} // namespace awb
