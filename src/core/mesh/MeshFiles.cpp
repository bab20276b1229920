// The mesh files of MeshFiles.h.
// OBJ goes through tinyobjloader. A scan of the same lines beside it gives every statement its
// line for messages, reads the coordinates exactly (std::from_chars; tinyobjloader's own number
// parser is off by a few units in the last place, so that a file of writeObj would not read back
// to the same doubles) and refuses what tinyobjloader takes silently: a coordinate that is not a
// number (read as 0) or not finite, a face of fewer than 3 vertices (dropped), an index out of
// range (kept) or beyond int (wrapped by atoi). Only the v and f lines reach tinyobjloader (the
// others as empty lines, so that its line numbers stay the file's): its extensions allocate what
// a line claims (a tag line `t a 8192/8192/8192`: 8192 values of each kind).
// OFF (here) and PLY (MeshFilesPly.cpp): own readers. Debian 12 has no maintained library that hands these files back as
// written with the place of each fault: assimp and OpenMesh build their own mesh structures
// (OpenMesh skips the faces its half-edge structure cannot hold), and CGAL's polygon-soup
// readers, which keep the numbering, would bring CGAL and Boost into the core for two small
// formats and answer a fault with `false`.
#include "core/mesh/MeshFiles.h"

#include "core/Messages.h"
#include "core/mesh/MeshFilesText.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <iterator>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace awb {

namespace {

using namespace meshtext;

// ---- OBJ -----------------------------------------------------------------------------------

// The vertex number of an OBJ face corner v, v/vt, v//vn or v/vt/vn (each a nonzero whole
// number; vt and vn are not used), or false.
bool cornerVertex(std::string_view w, long long &v)
{
    std::string_view part[3];
    int parts = 0;
    for (std::size_t start = 0;; start = w.find('/', start) + 1) {
        if (parts == 3)
            return false;
        part[parts++] = w.substr(start, w.find('/', start) - start);
        if (w.find('/', start) == npos)
            break;
    }
    for (int k = 1; k < parts; ++k) {
        int n = 0;
        if (!(k == 1 && parts == 3 && part[1].empty()) && (!parse(part[k], n) || n == 0))
            return false;
    }
    return parse(part[0], v) && v != 0;
}

// OpenSubdiv's tag lines (its regression shapes' `t name intcount/floatcount/stringcount ...`)
// that this reader does not apply (vertexedit, edgeedit, the face-varying options, ...): per tag
// name, how many and the first and last line.
struct TagLines {
    std::string name;
    long long count = 0;
    std::size_t first = 0, last = 0;
};

void noteTags(const std::vector<TagLines> &tags, const std::string &name,
              std::vector<std::string> *notes)
{
    if (!notes)
        return;
    for (const TagLines &t : tags)
        notes->push_back(
            t.name.empty()
                ? formatMessage(coreTranslate("awb::mesh",
                                              "%1, lines %2 to %3: %4 more OpenSubdiv tag lines "
                                              "of other names are not applied either"),
                                name, t.first, t.last, t.count)
            : t.count == 1
                ? formatMessage(coreTranslate("awb::mesh",
                                              "%1, line %2: the OpenSubdiv tag 't %3' is not "
                                              "applied (this version applies crease, corner, "
                                              "hole, interpolateboundary, creasemethod and "
                                              "smoothtriangles), so the surface differs from "
                                              "OpenSubdiv's where it acts"),
                                name, t.first, t.name)
                : formatMessage(coreTranslate("awb::mesh",
                                              "%1, lines %2 to %3: %4 OpenSubdiv tags 't %5' "
                                              "are not applied (this version applies crease, "
                                              "corner, hole, interpolateboundary, creasemethod "
                                              "and smoothtriangles), so the surface differs "
                                              "from OpenSubdiv's where they act"),
                                name, t.first, t.last, t.count, t.name));
}

// A tag line of one of the kinds applied, parsed: its place and arguments.
struct ObjTag {
    std::size_t line = 0;
    std::string name;
    std::vector<long long> ints;
    std::vector<float> floats;
    std::vector<std::string> strings;
};

bool appliedTag(std::string_view name)
{
    for (const char *known : {"crease", "corner", "hole", "interpolateboundary", "creasemethod",
                              "smoothtriangles"})
        if (name == known)
            return true;
    return false;
}

// `t name i/f/s ints floats strings`, as OpenSubdiv's Shape::tag::parseTag reads it: the
// counts must match the words that follow.
template<class Where>
ObjTag parseTag(const Words &w, std::size_t line, const Where &where)
{
    ObjTag tag;
    tag.line = line;
    tag.name = std::string(w[1]);
    long long count[3] = {0, 0, 0};
    const std::string_view counts = w.size() > 2 ? w[2] : std::string_view();
    std::size_t at = 0;
    for (int k = 0; k < 3; ++k) {
        const std::size_t slash = k < 2 ? counts.find('/', at) : counts.size();
        if (slash == npos || !parse(counts.substr(at, slash - at), count[k]) || count[k] < 0)
            refuse(coreTranslate("awb::mesh", "%1: the tag 't %2' needs its counts as "
                                              "ints/floats/strings (like 2/1/0), got '%3'"),
                   where(), tag.name, shown(counts));
        at = slash + 1;
    }
    // Each count against the words there are before any sum: counts near 2^63 (a fuzzer's
    // find) must not overflow.
    const long long words = static_cast<long long>(w.size()) - 3;
    const bool fits = count[0] <= words && count[1] <= words && count[2] <= words;
    if (!fits || count[0] + count[1] + count[2] != words)
        refuse(coreTranslate("awb::mesh",
                             "%1: the tag 't %2' announces %3 values but has %4"),
               where(), tag.name,
               fits ? std::to_string(count[0] + count[1] + count[2]) : shown(counts), words);
    std::size_t k = 3;
    for (long long i = 0; i < count[0]; ++i, ++k) {
        long long v = 0;
        if (!parse(w[k], v))
            refuse(coreTranslate("awb::mesh", "%1: '%2' is not a whole number"), where(),
                   shown(w[k]));
        tag.ints.push_back(v);
    }
    for (long long i = 0; i < count[1]; ++i, ++k) {
        double x = 0;
        if (!parse(w[k], x) || std::isnan(x))
            refuse(coreTranslate("awb::mesh", "%1: '%2' is not a number"), where(), shown(w[k]));
        tag.floats.push_back(float(x));
    }
    for (long long i = 0; i < count[2]; ++i, ++k)
        tag.strings.emplace_back(w[k]);
    return tag;
}

// The applied tags on the mesh, checked against its vertex and face counts: OpenSubdiv's
// regression reader's meaning (far_utils.h): a crease takes vertex pairs and one sharpness or
// one per pair, a corner vertices and one sharpness or one per vertex, a negative sharpness is
// 0; interpolateboundary 0 none, 1 edge-and-corner, 2 edge-only; creasemethod normal or
// chaikin; smoothtriangles catmark or smooth.
void applyTags(const std::vector<ObjTag> &tags, Mesh &mesh, const std::string &name)
{
    const long long vertices = mesh.vertices.rows();
    const long long faces = static_cast<long long>(mesh.faces.size());
    for (const ObjTag &tag : tags) {
        const auto where = [&] { return atLine(name, tag.line); };
        const auto need = [&](bool ok, const std::string &what) {
            if (!ok)
                refuse(coreTranslate("awb::mesh", "%1: the tag 't %2' needs %3"), where(),
                       tag.name, what);
        };
        const auto sharpness = [&](std::size_t k) {
            const float s = tag.floats.size() > 1 ? tag.floats[k] : tag.floats[0];
            return std::max(0.0f, s);
        };
        const auto vertex = [&](long long v) {
            if (v < 0 || v >= vertices)  // tags count vertices from 0, as OpenSubdiv does
                refuse(coreTranslate("awb::mesh", "%1: the tag 't %2' names vertex %3, but the "
                                                  "file has %4 vertices (tags count from 0: 0 "
                                                  "to %5)"),
                       where(), tag.name, v, vertices, vertices - 1);
            return int(v);
        };
        if (tag.name == "crease") {
            need(tag.ints.size() >= 2 && tag.ints.size() % 2 == 0
                     && (tag.floats.size() == 1 || tag.floats.size() == tag.ints.size() / 2),
                 coreTranslate("awb::mesh", "pairs of vertices and one sharpness, or one per pair"));
            for (std::size_t j = 0; j + 1 < tag.ints.size(); j += 2)
                mesh.tags.edges.push_back(
                    {vertex(tag.ints[j]), vertex(tag.ints[j + 1]), sharpness(j / 2)});
        } else if (tag.name == "corner") {
            need(!tag.ints.empty()
                     && (tag.floats.size() == 1 || tag.floats.size() == tag.ints.size()),
                 coreTranslate("awb::mesh", "vertices and one sharpness, or one per vertex"));
            for (std::size_t j = 0; j < tag.ints.size(); ++j)
                mesh.tags.vertices.push_back({vertex(tag.ints[j]), sharpness(j)});
        } else if (tag.name == "hole") {
            need(!tag.ints.empty(), coreTranslate("awb::mesh", "the faces it makes holes"));
            for (long long f : tag.ints) {
                if (f < 0 || f >= faces)
                    refuse(coreTranslate("awb::mesh", "%1: the hole names face %2, but the "
                                                      "file has %3 faces (0 to %4)"),
                           where(), f, faces, faces - 1);
                mesh.tags.holes.push_back(int(f));
            }
        } else if (tag.name == "interpolateboundary") {
            need(tag.ints.size() == 1 && tag.ints[0] >= 0 && tag.ints[0] <= 2,
                 coreTranslate("awb::mesh", "one whole number: 0 none, 1 edge and corner, 2 edge only"));
            mesh.tags.options.boundary = tag.ints[0] == 0   ? BoundaryInterpolation::None
                                         : tag.ints[0] == 1 ? BoundaryInterpolation::EdgeAndCorner
                                                            : BoundaryInterpolation::EdgeOnly;
        } else if (tag.name == "creasemethod") {
            need(tag.strings.size() == 1
                     && (tag.strings[0] == "normal" || tag.strings[0] == "chaikin"),
                 coreTranslate("awb::mesh", "one word: normal or chaikin"));
            mesh.tags.options.creaseMethod =
                tag.strings[0] == "chaikin" ? CreaseMethod::Chaikin : CreaseMethod::Uniform;
        } else if (tag.name == "smoothtriangles") {
            need(tag.strings.size() == 1
                     && (tag.strings[0] == "catmark" || tag.strings[0] == "smooth"),
                 coreTranslate("awb::mesh", "one word: catmark or smooth"));
            mesh.tags.options.triangles = tag.strings[0] == "smooth"
                                              ? TriangleSubdivision::Smooth
                                              : TriangleSubdivision::Catmark;
        }
    }
}

Mesh readObj(std::string_view text, const std::string &name, std::vector<std::string> *notes)
{
    std::vector<TagLines> tags;
    std::vector<ObjTag> applied;
    std::vector<double> xyz;            // 3 per vertex
    std::vector<int> corners;           // per face
    std::vector<std::size_t> faceLines; // per face
    std::vector<long long> indices;     // per corner, 0-based, checked against the end below
    std::string kept;                   // the v and f lines, the others empty
    kept.reserve(text.size());
    Lines lines(text);
    for (std::string_view line; lines.next(line); kept.push_back('\n')) {
        const Words w = words(line);
        if (!w.empty() && w[0] == "t" && w.size() > 1 && appliedTag(w[1])) {
            applied.push_back(
                parseTag(w, lines.number(), [&] { return atLine(name, lines.number()); }));
            continue;
        }
        if (!w.empty() && w[0] == "t") {
            const std::string tag(w.size() > 1 ? w[1] : std::string_view("?"));
            auto it = std::find_if(tags.begin(), tags.end(),
                                   [&](const TagLines &t) { return t.name == tag; });
            // OpenSubdiv names seven kinds; past 16 names, the rest share one note (the entry
            // of empty name), not one each.
            if (it == tags.end()) {
                const bool full = tags.size() >= 16;
                it = full ? std::find_if(tags.begin(), tags.end(),
                                         [](const TagLines &t) { return t.name.empty(); })
                          : tags.end();
                if (it == tags.end()) {
                    tags.push_back({full ? std::string() : tag, 0, lines.number(), 0});
                    it = tags.end() - 1;
                }
            }
            ++it->count;
            it->last = lines.number();
            continue;
        }
        if (w.empty() || (w[0] != "v" && w[0] != "f"))
            continue;
        const auto where = [&] { return atLine(name, lines.number()); };
        kept.append(line);
        if (w[0] == "v") {
            for (double x : vertexCoordinates(w, 1, where))
                xyz.push_back(x);
            continue;
        }
        requireFaceSize(static_cast<long long>(w.size()) - 1, where);
        const long long preceding = static_cast<long long>(xyz.size() / 3);
        for (std::size_t k = 1; k < w.size(); ++k) {
            long long v = 0;
            if (!cornerVertex(w[k], v))
                refuse(coreTranslate("awb::mesh", "%1: '%2' is not a face corner (v, v/vt, "
                                                  "v//vn or v/vt/vn, nonzero whole numbers)"),
                       where(), shown(w[k]));
            if (v < 0 && preceding + v < 0)
                refuse(coreTranslate("awb::mesh", "%1: relative vertex index %2 is out of "
                                                  "range (%3 vertices precede it)"),
                       where(), v, preceding);
            indices.push_back(v > 0 ? v - 1 : preceding + v);
        }
        corners.push_back(int(w.size() - 1));
        faceLines.push_back(lines.number());
    }
    const long long vertexCount = static_cast<long long>(xyz.size() / 3);
    requireMesh(vertexCount, corners.size(), name);
    for (std::size_t f = 0, k = 0; f < corners.size(); ++f)
        for (int c = 0; c < corners[f]; ++c, ++k)
            requireIndex(indices[k] + 1, 1, vertexCount,
                         [&] { return atLine(name, faceLines[f]); });

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning, error;
    std::istringstream stream(kept);
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &stream, nullptr,
                          /*triangulate=*/false, /*default_vcols_fallback=*/false)) {
        while (!error.empty() && (error.back() == '\n' || error.back() == '.'))
            error.pop_back();
        refuse(coreTranslate("awb::mesh", "%1 is not a valid OBJ file (tinyobjloader: %2)"),
               name, error);
    }
    // Its faces, in file order (no line that starts a new shape is passed), must be the scan's:
    // a difference is a bug of this reader, not of the file. A face's count is a byte there
    // (faces of 256 vertices or more wrap): the scan's counts split the indices.
    Mesh mesh;
    mesh.faces.reserve(corners.size());
    bool same = attrib.vertices.size() == xyz.size();
    std::size_t k = 0;
    for (const tinyobj::shape_t &shape : shapes) {
        const auto &found = shape.mesh.indices;
        std::size_t at = 0;
        for (unsigned char count : shape.mesh.num_face_vertices) {
            const std::size_t f = mesh.faces.size();
            same = same && f < corners.size() && count == static_cast<unsigned char>(corners[f])
                   && at + std::size_t(corners[f]) <= found.size();
            if (!same)
                break;
            std::vector<int> face(static_cast<std::size_t>(corners[f]));
            for (int &v : face) {
                v = found[at++].vertex_index;
                same = same && v == indices[k++];
            }
            mesh.faces.push_back(std::move(face));
        }
        same = same && at == found.size();
    }
    if (!same || mesh.faces.size() != corners.size())
        throw std::logic_error(name + ": tinyobjloader and the line scan read different meshes");
    mesh.vertices = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
        xyz.data(), Eigen::Index(vertexCount), 3);
    applyTags(applied, mesh, name);
    noteTags(tags, name, notes);
    // A feature tagged twice is one feature, its last sharpness OpenSubdiv's: merged, said.
    const RepeatedTags repeated = mergeRepeatedTags(mesh.tags);
    if (notes && repeated.edges > 0)
        notes->push_back(formatMessage(
            coreTranslate("awb::mesh", "%1: %2 crease tags name an edge tagged before (the "
                                       "first: %3 %4): each edge keeps its last sharpness, as "
                                       "OpenSubdiv applies them"),
            name, repeated.edges, repeated.firstEdge.a, repeated.firstEdge.b));
    if (notes && repeated.vertices > 0)
        notes->push_back(formatMessage(
            coreTranslate("awb::mesh", "%1: %2 corner tags name a vertex tagged before (the "
                                       "first: %3): each vertex keeps its last sharpness, as "
                                       "OpenSubdiv applies them"),
            name, repeated.vertices, repeated.firstVertex));
    if (notes && repeated.holes > 0)
        notes->push_back(formatMessage(
            coreTranslate("awb::mesh", "%1: %2 hole tags name a face made a hole before"), name,
            repeated.holes));
    return mesh;
}

// ---- OFF -----------------------------------------------------------------------------------

Mesh readOff(std::string_view text, const std::string &name)
{
    Lines lines(text);
    std::string_view line;
    Words w;
    const auto next = [&] { // the next line with words (before any '#'), false at the end
        while (lines.next(line))
            if (w = words(line.substr(0, line.find('#'))); !w.empty())
                return true;
        return false;
    };
    const auto where = [&] { return atLine(name, lines.number()); };
    if (!next())
        refuse(coreTranslate("awb::mesh", "%1 is empty"), name);
    std::size_t first = 0; // the counts' first word
    if (w[0].size() >= 3 && w[0].substr(w[0].size() - 3) == "OFF") {
        std::string_view prefix = w[0].substr(0, w[0].size() - 3);
        for (std::string_view flag : {"ST", "C", "N"})
            if (prefix.substr(0, flag.size()) == flag)
                prefix.remove_prefix(flag.size());
        if (!prefix.empty() || (w.size() > 1 && w[1] == "BINARY"))
            refuse(coreTranslate("awb::mesh", "%1: '%2' is not a header this reader takes: "
                                              "ASCII OFF of 3D points ([ST][C][N]OFF)"),
                   where(), shown(line));
        first = w.size() > 1 || !next() ? 1 : 0; // the counts on the header's line or the next
    }
    long long counts[3] = {0, 0, 0};
    bool valid = w.size() - first == 2 || w.size() - first == 3;
    for (std::size_t k = first; valid && k < w.size(); ++k)
        valid = parse(w[k], counts[k - first]) && counts[k - first] >= 0;
    if (!valid)
        refuse(coreTranslate("awb::mesh", "%1: '%2' is not the counts line (vertices, faces and "
                                          "edges) of an OFF file"),
               where(), shown(line));
    const long long nv = counts[0], nf = counts[1];
    requireMesh(nv, std::size_t(nf), name);
    // Every vertex and face takes a line: no allocation for counts the file cannot hold.
    const std::string_view rest = text.substr(lines.offset());
    const long long lineCount = 1 + std::count(rest.begin(), rest.end(), '\n')
                                + std::count(rest.begin(), rest.end(), '\r');
    if (nv > std::min<long long>(lineCount, INT_MAX)
        || nf > std::min<long long>(lineCount - nv, INT_MAX))
        refuse(coreTranslate("awb::mesh", "%1: %2 vertices and %3 faces need more lines than the "
                                          "%4 left in the file"),
               where(), nv, nf, lineCount);
    Mesh mesh;
    mesh.vertices.resize(Eigen::Index(nv), 3);
    for (long long v = 0; v < nv; ++v) {
        if (!next())
            refuse(coreTranslate("awb::mesh", "%1 ends after %2 of its %3 vertices"), name, v, nv);
        const std::array<double, 3> p = vertexCoordinates(w, 0, where);
        mesh.vertices.row(Eigen::Index(v)) << p[0], p[1], p[2];
    }
    mesh.faces.reserve(std::size_t(nf));
    for (long long f = 0; f < nf; ++f) {
        if (!next())
            refuse(coreTranslate("awb::mesh", "%1 ends after %2 of its %3 faces"), name, f, nf);
        const long long k = wholeNumber(w[0], where);
        requireFaceSize(k, where);
        if (k > static_cast<long long>(w.size()) - 1)
            refuse(coreTranslate("awb::mesh", "%1: the face announces %2 vertices but lists %3"),
                   where(), k, w.size() - 1);
        std::vector<int> face(static_cast<std::size_t>(k));
        for (std::size_t c = 0; c < face.size(); ++c) {
            const long long v = wholeNumber(w[c + 1], where);
            requireIndex(v, 0, nv, where);
            face[c] = int(v);
        }
        mesh.faces.push_back(std::move(face));
    }
    if (next())
        refuse(coreTranslate("awb::mesh", "%1: data after the last face (the counts announce %2 "
                                          "vertices and %3 faces)"),
               where(), nv, nf);
    return mesh;
}

} // namespace

std::string toString(MeshFormat format)
{
    return format == MeshFormat::Obj ? "obj" : format == MeshFormat::Off ? "off" : "ply";
}

MeshFormat meshFormatForPath(const std::string &path)
{
    const std::size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        refuse(coreTranslate("awb::mesh", "%1 has no file extension (expected .obj, .off or "
                                          ".ply)"),
               path);
    std::string extension = path.substr(dot);
    for (char &c : extension)
        c = char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    for (MeshFormat format : {MeshFormat::Obj, MeshFormat::Off, MeshFormat::Ply})
        if (std::string_view(extension).substr(1) == toString(format))
            return format;
    refuse(coreTranslate("awb::mesh", "unknown mesh file extension '%1' of %2 (expected .obj, "
                                      ".off or .ply)"),
           shown(path.substr(dot)), path);
}

namespace {

// The UTF-16 text after a byte-order mark (FF FE little, FE FF big endian) as UTF-8. InputError
// for an odd length or a lone surrogate.
std::string utf16ToUtf8(const std::string &bytes, const std::string &name)
{
    if (bytes.size() % 2 != 0)
        refuse(coreTranslate("awb::mesh", "%1: UTF-16 text of an odd number of bytes"), name);
    const bool little = bytes[0] == '\xFF';
    const auto unit = [&](std::size_t i) {
        const auto a = static_cast<unsigned char>(bytes[i]);
        const auto b = static_cast<unsigned char>(bytes[i + 1]);
        return little ? std::uint32_t(a | (b << 8)) : std::uint32_t((a << 8) | b);
    };
    std::string out;
    out.reserve(bytes.size() / 2);
    for (std::size_t i = 2; i < bytes.size(); i += 2) {
        std::uint32_t c = unit(i);
        if (c >= 0xD800 && c < 0xDC00 && i + 3 < bytes.size()) {
            const std::uint32_t low = unit(i + 2);
            if (low >= 0xDC00 && low < 0xE000) {
                c = 0x10000 + ((c - 0xD800) << 10) + (low - 0xDC00);
                i += 2;
            }
        }
        if (c >= 0xD800 && c < 0xE000)
            refuse(coreTranslate("awb::mesh", "%1: invalid UTF-16 text (a lone surrogate)"), name);
        if (c < 0x80) {
            out.push_back(char(c));
        } else if (c < 0x800) {
            out.push_back(char(0xC0 | (c >> 6)));
            out.push_back(char(0x80 | (c & 0x3F)));
        } else if (c < 0x10000) {
            out.push_back(char(0xE0 | (c >> 12)));
            out.push_back(char(0x80 | ((c >> 6) & 0x3F)));
            out.push_back(char(0x80 | (c & 0x3F)));
        } else {
            out.push_back(char(0xF0 | (c >> 18)));
            out.push_back(char(0x80 | ((c >> 12) & 0x3F)));
            out.push_back(char(0x80 | ((c >> 6) & 0x3F)));
            out.push_back(char(0x80 | (c & 0x3F)));
        }
    }
    return out;
}

} // namespace

Mesh readMesh(const std::string &path, std::vector<std::string> *notes)
{
    const MeshFormat format = meshFormatForPath(path);
    std::ifstream in(path, std::ios::binary);
    if (!in)
        refuse(coreTranslate("awb::mesh", "cannot open %1"), path);
    return readMesh(in, format, path, notes);
}

Mesh readMesh(std::istream &in, MeshFormat format, const std::string &name,
              std::vector<std::string> *notes)
{
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad())
        refuse(coreTranslate("awb::mesh", "cannot read %1"), name);
    // A byte-order mark (editors on Windows write one): UTF-8's is dropped, UTF-16 is read as
    // the text it encodes.
    if (bytes.size() >= 3 && bytes.compare(0, 3, "\xEF\xBB\xBF") == 0)
        bytes.erase(0, 3);
    else if (bytes.size() >= 2 && (bytes.compare(0, 2, "\xFF\xFE") == 0
                                   || bytes.compare(0, 2, "\xFE\xFF") == 0))
        bytes = utf16ToUtf8(bytes, name);
    if (bytes.find_first_not_of(" \t\r\n\f\v") == std::string::npos)
        refuse(coreTranslate("awb::mesh", "%1 is empty"), name);
    if (format == MeshFormat::Ply)
        return readPly(bytes, name, notes);
    if (const std::size_t nul = bytes.find('\0'); nul != std::string::npos) {
        Lines lines(std::string_view(bytes).substr(0, nul + 1));
        for (std::string_view line; lines.next(line);) {
        }
        refuse(coreTranslate("awb::mesh", "%1: a NUL byte: not a text file"),
               atLine(name, lines.number()));
    }
    return format == MeshFormat::Obj ? readObj(bytes, name, notes) : readOff(bytes, name);
}

void writeObj(std::ostream &out, const Mesh &mesh, const std::string &comment)
{
    // What readMesh would refuse, in checkMesh's words (Mesh.cpp).
    const Mat &p = mesh.vertices;
    if (p.rows() == 0 || mesh.faces.empty())
        throw InputError(p.rows() == 0 ? coreTranslate("awb::mesh", "the mesh has no vertices")
                                       : coreTranslate("awb::mesh", "the mesh has no faces"));
    if (p.cols() != 3)
        refuse(coreTranslate("awb::mesh", "mesh vertices need 3 coordinates, got %1"), p.cols());
    for (Eigen::Index v = 0; v < p.rows(); ++v)
        if (!p.row(v).allFinite())
            refuse(coreTranslate("awb::mesh",
                                 "vertex %1 has a coordinate that is not a finite number"),
                   v);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        if (mesh.faces[f].size() < 3)
            refuse(coreTranslate("awb::mesh", "face %1 has %2 vertices; a face needs at least 3"),
                   f, mesh.faces[f].size());
        for (int v : mesh.faces[f])
            if (v < 0 || v >= p.rows())
                refuse(coreTranslate("awb::mesh", "face %1 refers to vertex %2, but the mesh has "
                                                  "%3 vertices (0 to %4)"),
                       f, v, p.rows(), p.rows() - 1);
    }
    std::string text;
    const auto flush = [&](std::size_t above) {
        if (text.size() > above)
            out.write(text.data(), std::streamsize(text.size())), text.clear();
    };
    for (std::size_t start = 0; start < comment.size();) {
        const std::size_t end = std::min(comment.find('\n', start), comment.size());
        std::string_view line = std::string_view(comment).substr(start, end - start);
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        text.append(line.empty() ? "#" : "# ").append(line).push_back('\n');
        start = end + 1;
    }
    char number[32];
    for (Eigen::Index v = 0; v < p.rows(); ++v, flush(1 << 16)) {
        text.push_back('v');
        for (int c = 0; c < 3; ++c)
            text.append(" ").append(number, std::to_chars(number, number + sizeof number, p(v, c),
                                                          std::chars_format::general, 17).ptr);
        text.push_back('\n');
    }
    for (std::size_t f = 0; f < mesh.faces.size(); ++f, flush(1 << 16)) {
        text.push_back('f');
        for (int v : mesh.faces[f])
            text.append(" ").append(std::to_string(v + 1));
        text.push_back('\n');
    }
    // The sharp features as OpenSubdiv's tag lines (vertices and faces counted from 0).
    const MeshTags &tags = mesh.tags;
    const auto sharpness = [](float s) { return shortestNumber(double(s)); };
    for (const SharpEdge &e : tags.edges) {
        text.append("t crease 2/1/0 ").append(std::to_string(e.a)).append(" ");
        text.append(std::to_string(e.b)).append(" ").append(sharpness(e.sharpness)).append("\n");
    }
    for (const SharpVertex &c : tags.vertices) {
        text.append("t corner 1/1/0 ").append(std::to_string(c.vertex)).append(" ");
        text.append(sharpness(c.sharpness)).append("\n");
    }
    if (!tags.holes.empty()) {
        text.append("t hole ").append(std::to_string(tags.holes.size())).append("/0/0");
        for (int f : tags.holes)
            text.append(" ").append(std::to_string(f));
        text.append("\n");
    }
    if (tags.options.boundary != BoundaryInterpolation::EdgeOnly)
        text.append("t interpolateboundary 1/0/0 ")
            .append(tags.options.boundary == BoundaryInterpolation::None ? "0" : "1")
            .append("\n");
    if (tags.options.creaseMethod == CreaseMethod::Chaikin)
        text.append("t creasemethod 0/0/1 chaikin\n");
    if (tags.options.triangles == TriangleSubdivision::Smooth)
        text.append("t smoothtriangles 0/0/1 smooth\n");
    flush(0);
}

} // namespace awb
