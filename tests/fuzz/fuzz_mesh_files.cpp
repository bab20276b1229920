// libFuzzer targets of the mesh files (issue 30): any bytes as an OBJ (AWB_FUZZ_MESH_FORMAT=0,
// fuzz_mesh_obj), OFF (1, fuzz_mesh_off) or PLY file (2, fuzz_mesh_ply) through readMesh
// (core/mesh/MeshFiles.h). An InputError is a refusal, as it should be; any other exception, a
// crash, a hang or an allocation beyond libFuzzer's limit is a bug. A mesh read must hold what
// the reader promises (n x 3 finite coordinates, faces of 3 or more vertices in range), read
// back the same from writeObj, and go through checkMesh's topology (InputError allowed), as
// its repairs (repairMesh) do.
#include "core/mesh/MeshFiles.h"
#include "core/mesh/MeshRepair.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#ifndef AWB_FUZZ_MESH_FORMAT
#error "AWB_FUZZ_MESH_FORMAT (0: OBJ, 1: OFF, 2: PLY) selects the reader"
#endif

namespace {

[[noreturn]] void fail(const char *what)
{
    std::fprintf(stderr, "fuzz_mesh_files: %s\n", what);
    std::abort();
}

awb::Mesh read(const std::string &bytes, awb::MeshFormat format)
{
    std::istringstream in(bytes);
    return awb::readMesh(in, format, "fuzz." + awb::toString(format));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const auto format = static_cast<awb::MeshFormat>(AWB_FUZZ_MESH_FORMAT);
    awb::Mesh mesh;
    try {
        mesh = read(std::string(reinterpret_cast<const char *>(data), size), format);
    } catch (const awb::InputError &) {
        return 0; // refused with a message
    }
    // Anything but an InputError escapes and aborts the run: a bug.
    const Eigen::Index n = mesh.vertices.rows();
    if (n == 0 || mesh.vertices.cols() != 3 || !mesh.vertices.allFinite() || mesh.faces.empty())
        fail("a mesh read without vertices, faces or finite coordinates");
    for (const auto &face : mesh.faces) {
        if (face.size() < 3)
            fail("a face of fewer than 3 vertices read");
        for (int v : face)
            if (v < 0 || v >= n)
                fail("a vertex index out of range read");
    }
    std::ostringstream out;
    awb::writeObj(out, mesh, "fuzz");
    const awb::Mesh back = read(out.str(), awb::MeshFormat::Obj);
    if (back.vertices.rows() != n || back.vertices != mesh.vertices || back.faces != mesh.faces)
        fail("writeObj and readMesh do not give the mesh back");
    try {
        awb::checkMesh(mesh, awb::MeshScheme::CatmullClark);
    } catch (const awb::InputError &) {
    }
    // The repairs (MeshRepair.h) keep every index in range and every face of 3 or more
    // vertices, and only add vertices; their result goes through the checks as any mesh.
    awb::MeshRepairReport report;
    const awb::Mesh repaired = awb::repairMesh(mesh, &report);
    if (repaired.vertices.rows() != n + report.addedVertices)
        fail("the repairs changed the vertex count otherwise than by their splits");
    for (const auto &face : repaired.faces) {
        if (face.size() < 3)
            fail("a repaired face of fewer than 3 vertices");
        for (int v : face)
            if (v < 0 || v >= repaired.vertices.rows())
                fail("a repaired vertex index out of range");
    }
    try {
        awb::checkMesh(repaired, awb::MeshScheme::CatmullClark);
    } catch (const awb::InputError &) {
    }
    return 0;
}
