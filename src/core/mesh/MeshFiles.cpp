// The mesh files of MeshFiles.h.
// OBJ goes through tinyobjloader. A scan of the same lines beside it gives every statement its
// line for messages, reads the coordinates exactly (std::from_chars; tinyobjloader's own number
// parser is off by a few units in the last place, so that a file of writeObj would not read back
// to the same doubles) and refuses what tinyobjloader takes silently: a coordinate that is not a
// number (read as 0) or not finite, a face of fewer than 3 vertices (dropped), an index out of
// range (kept) or beyond int (wrapped by atoi). Only the v and f lines reach tinyobjloader (the
// others as empty lines, so that its line numbers stay the file's): its extensions allocate what
// a line claims (a tag line `t a 8192/8192/8192`: 8192 values of each kind).
// OFF and PLY: own readers. Debian 12 has no maintained library that hands these files back as
// written with the place of each fault: assimp and OpenMesh build their own mesh structures
// (OpenMesh skips the faces its half-edge structure cannot hold), and CGAL's polygon-soup
// readers, which keep the numbering, would bring CGAL and Boost into the core for two small
// formats and answer a fault with `false`.
#include "core/mesh/MeshFiles.h"

#include "core/Messages.h"

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

constexpr std::size_t npos = std::string_view::npos;
using Words = std::vector<std::string_view>;

template<class... Args>
[[noreturn]] void refuse(std::string_view pattern, const Args &...args)
{
    throw InputError(formatMessage(pattern, args...));
}

// The words of a line, split at spaces and tabs.
Words words(std::string_view line)
{
    Words out;
    for (std::size_t i = line.find_first_not_of(" \t"); i != npos;
         i = line.find_first_not_of(" \t", i)) {
        const std::size_t end = std::min(line.find_first_of(" \t", i), line.size());
        out.push_back(line.substr(i, end - i));
        i = end;
    }
    return out;
}

// The lines of a text, split at "\n", "\r\n" or a lone "\r" as tinyobjloader splits them,
// numbered from 1.
class Lines {
public:
    explicit Lines(std::string_view text) : m_text(text) {}
    bool next(std::string_view &line)
    {
        if (m_pos >= m_text.size())
            return false;
        const std::size_t end = std::min(m_text.find_first_of("\r\n", m_pos), m_text.size());
        line = m_text.substr(m_pos, end - m_pos);
        m_pos = end + (end < m_text.size()) + (m_text.compare(end, 2, "\r\n") == 0);
        ++m_number;
        return true;
    }
    std::size_t number() const { return m_number; }
    std::size_t offset() const { return m_pos; } // where the next line starts

private:
    std::string_view m_text;
    std::size_t m_pos = 0, m_number = 0;
};

// A word of the file as messages quote it: at most 40 bytes, control bytes as '?'.
std::string shown(std::string_view w)
{
    std::string s(w.substr(0, 40));
    for (char &c : s)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            c = '?';
    return w.size() > 40 ? s + "..." : s;
}

std::string atLine(const std::string &name, std::size_t line)
{
    return formatMessage(coreTranslate("awb::mesh", "%1, line %2"), name, line);
}

// A whole word as a number of type T (a leading '+' allowed, as C's strtod takes it), or false.
// Beyond T's range: +-HUGE_VAL or the saturated whole number.
template<class T>
bool parse(std::string_view w, T &x)
{
    if (w.size() > 1 && w[0] == '+' && w[1] != '-')
        w.remove_prefix(1);
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), x);
    if (w.empty() || end != w.data() + w.size()
        || (ec != std::errc() && ec != std::errc::result_out_of_range))
        return false;
    if (ec != std::errc() && std::is_floating_point_v<T>)
        x = T(w[0] == '-' ? -HUGE_VAL : HUGE_VAL); // 1e-400 too: a number no double holds
    else if (ec != std::errc())
        x = w[0] == '-' ? std::numeric_limits<T>::min() : std::numeric_limits<T>::max();
    return true;
}

// The helpers below take `where`, a callable that names the place ("cube.obj, line 7"): it runs
// for a message only, not for every line of a good file.
template<class Where>
double coordinate(std::string_view w, const Where &where)
{
    double x = 0;
    if (!parse(w, x))
        refuse(coreTranslate("awb::mesh", "%1: '%2' is not a number"), where(), shown(w));
    if (!std::isfinite(x))
        refuse(coreTranslate("awb::mesh", "%1: '%2' is not a finite number"), where(), shown(w));
    return x;
}

template<class Where>
long long wholeNumber(std::string_view w, const Where &where)
{
    long long n = 0;
    if (!parse(w, n))
        refuse(coreTranslate("awb::mesh", "%1: '%2' is not a whole number"), where(), shown(w));
    return n;
}

template<class Where>
std::array<double, 3> vertexCoordinates(const Words &w, std::size_t first, const Where &where)
{
    if (w.size() < first + 3)
        refuse(coreTranslate("awb::mesh", "%1: a vertex needs 3 coordinates, this one has %2"),
               where(), w.size() - first);
    return {coordinate(w[first], where), coordinate(w[first + 1], where),
            coordinate(w[first + 2], where)};
}

template<class Where>
void requireFaceSize(long long corners, const Where &where)
{
    if (corners < 3)
        refuse(coreTranslate("awb::mesh", "%1: a face needs at least 3 vertices, this one has %2"),
               where(), corners);
}

// Refuses `index` (as the file writes it) unless it is in [first, first + count).
template<class Where>
void requireIndex(long long index, long long first, long long count, const Where &where)
{
    if (index < first || index - first >= count)
        refuse(coreTranslate("awb::mesh",
                             "%1: vertex index %2 is out of range (the file has %3 vertices)"),
               where(), index, count);
}

void requireMesh(long long vertices, std::size_t faces, const std::string &name)
{
    if (vertices == 0)
        refuse(coreTranslate("awb::mesh", "%1 holds no vertices"), name);
    if (faces == 0)
        refuse(coreTranslate("awb::mesh", "%1 holds no faces: not a polygon mesh"), name);
}

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

Mesh readObj(std::string_view text, const std::string &name)
{
    std::vector<double> xyz;            // 3 per vertex
    std::vector<int> corners;           // per face
    std::vector<std::size_t> faceLines; // per face
    std::vector<long long> indices;     // per corner, 0-based, checked against the end below
    std::string kept;                   // the v and f lines, the others empty
    kept.reserve(text.size());
    Lines lines(text);
    for (std::string_view line; lines.next(line); kept.push_back('\n')) {
        const Words w = words(line);
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

// ---- PLY -----------------------------------------------------------------------------------

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool typeNamed(std::string_view s, Type &t)
{
    static const std::string_view names[][2] = {
        {"char", "int8"},   {"uchar", "uint8"},   {"short", "int16"},   {"ushort", "uint16"},
        {"int", "int32"},   {"uint", "uint32"},   {"float", "float32"}, {"double", "float64"}};
    for (int k = 0; k < 8; ++k)
        if (s == names[k][0] || s == names[k][1])
            return t = Type(k), true;
    return false;
}

std::size_t sizeOf(Type t) { return std::array<std::size_t, 8>{1, 1, 2, 2, 4, 4, 4, 8}[int(t)]; }
bool isWhole(Type t) { return t < Type::Float32; }

struct PlyProperty {
    std::string name;
    Type type = Type::Float32; // of the value, or of a list's items
    bool list = false;
    Type count = Type::UInt8;  // of a list's length
};

struct PlyElement {
    std::string name;
    long long count = 0;
    std::vector<PlyProperty> properties;
};

struct PlyHeader {
    enum { Ascii, Little, Big } format = Ascii;
    std::vector<PlyElement> elements;
    std::size_t dataOffset = 0, dataLine = 0;
    // The mesh: the vertex and face elements, the properties x, y, z and the face list in them.
    int vertex = -1, face = -1, list = -1;
    int axis[3] = {-1, -1, -1};
};

void readPlyProperty(const Words &w, std::vector<PlyElement> &elements, const std::string &where)
{
    if (elements.empty())
        refuse(coreTranslate("awb::mesh", "%1: a property outside any element"), where);
    PlyProperty p{std::string(w.back()), Type::Float32, w.size() == 5, Type::UInt8};
    for (std::size_t k = p.list ? 2 : 1; k + 1 < w.size(); ++k)
        if (!typeNamed(w[k], k == 2 && p.list ? p.count : p.type))
            refuse(coreTranslate("awb::mesh", "%1: unknown PLY property type '%2'"), where,
                   shown(w[k]));
    if (p.list && !isWhole(p.count))
        refuse(coreTranslate("awb::mesh", "%1: a list's length needs a whole-number type"),
               where);
    for (const PlyProperty &q : elements.back().properties)
        if (q.name == p.name)
            refuse(coreTranslate("awb::mesh", "%1: property %2 appears twice in element %3"),
                   where, shown(p.name), shown(elements.back().name));
    elements.back().properties.push_back(std::move(p));
}

PlyHeader readPlyHeader(std::string_view text, const std::string &name)
{
    Lines lines(text);
    std::string_view line;
    if (!lines.next(line) || line != "ply")
        refuse(coreTranslate("awb::mesh", "%1 is not a PLY file (its first line is not 'ply')"),
               name);
    PlyHeader h;
    bool format = false;
    for (;;) {
        if (!lines.next(line))
            refuse(coreTranslate("awb::mesh", "%1: the PLY header has no end_header line"), name);
        const std::string where = atLine(name, lines.number());
        const Words w = words(line);
        long long count = 0;
        if (w.empty() || w[0] == "comment" || w[0] == "obj_info")
            continue;
        if (w.size() == 1 && w[0] == "end_header")
            break;
        if (w.size() == 3 && w[0] == "format" && !format) {
            format = true;
            if (w[2] != "1.0" || (w[1] != "ascii" && w[1] != "binary_little_endian"
                                  && w[1] != "binary_big_endian"))
                refuse(coreTranslate("awb::mesh", "%1: unsupported PLY format '%2' (ascii, "
                                                  "binary_little_endian or binary_big_endian 1.0)"),
                       where, shown(line));
            h.format = w[1] == "ascii" ? h.Ascii : w[1][7] == 'l' ? h.Little : h.Big;
        } else if (w.size() == 3 && w[0] == "element") {
            if (!parse(w[2], count) || count < 0 || count > INT_MAX)
                refuse(coreTranslate("awb::mesh", "%1: '%2' is not a valid count"), where,
                       shown(w[2]));
            for (const PlyElement &e : h.elements)
                if (e.name == w[1])
                    refuse(coreTranslate("awb::mesh", "%1: element %2 appears twice"), where,
                           shown(w[1]));
            h.elements.push_back({std::string(w[1]), count, {}});
        } else if (w[0] == "property" && (w.size() == 3 || (w.size() == 5 && w[1] == "list"))) {
            readPlyProperty(w, h.elements, where);
        } else {
            refuse(coreTranslate("awb::mesh", "%1: unknown PLY header line '%2'"), where,
                   shown(line));
        }
    }
    if (!format)
        refuse(coreTranslate("awb::mesh", "%1: the PLY header has no format line"), name);
    h.dataOffset = lines.offset();
    h.dataLine = lines.number() + 1;
    for (std::size_t e = 0; e < h.elements.size(); ++e) {
        const PlyElement &element = h.elements[e];
        const bool vertex = element.name == "vertex";
        if ((!vertex && element.name != "face") || element.count == 0)
            continue; // no mesh, or refused below
        (vertex ? h.vertex : h.face) = int(e);
        for (std::size_t k = 0; k < element.properties.size(); ++k) {
            const PlyProperty &p = element.properties[k];
            const std::size_t axis = std::string_view("xyz").find(p.name);
            if (vertex && p.name.size() == 1 && axis != npos)
                h.axis[axis] = p.list ? -2 : int(k);
            if (!vertex && (p.name == "vertex_indices" || p.name == "vertex_index"))
                h.list = h.list == -1 && p.list && isWhole(p.type) ? int(k) : -2;
        }
        if (vertex && std::min({h.axis[0], h.axis[1], h.axis[2]}) < 0)
            refuse(coreTranslate("awb::mesh", "%1: the vertex element needs the scalar "
                                              "properties x, y and z"),
                   name);
        if (!vertex && h.list < 0)
            refuse(coreTranslate("awb::mesh", "%1: the face element needs one list property "
                                              "vertex_indices (or vertex_index) of whole numbers"),
                   name);
    }
    requireMesh(h.vertex < 0 ? 0 : 1, h.face < 0 ? 0 : 1, name);
    return h;
}

// The data of a PLY file after its header, value by value. Binary: in the file's byte order,
// a value's size its type's. ASCII: words apart by white space, so that a value takes at least
// 2 bytes (a digit and a separator). claim() and need() refuse what a count claims beyond the
// rest of the file before anything is allocated or looped over for it.
class PlyData {
public:
    PlyData(std::string_view text, const PlyHeader &h, const std::string &name)
        : m_text(text), m_pos(h.dataOffset), m_line(h.dataLine), m_wordLine(m_line), m_name(name),
          m_ascii(h.format == h.Ascii),
          m_swap((h.format == h.Big) != (std::endian::native == std::endian::big))
    {
    }
    // The item that messages name: `index` of `element`, starting here.
    void at(const std::string &element, long long index)
    {
        m_element = &element, m_index = index, m_start = m_pos;
    }
    std::string where() const
    {
        return m_ascii ? formatMessage(coreTranslate("awb::mesh", "%1, line %2 (%3 %4)"), m_name,
                                       m_wordLine, shown(*m_element), m_index)
                       : formatMessage(coreTranslate("awb::mesh", "%1, %2 %3 (byte %4)"), m_name,
                                       shown(*m_element), m_index, m_start);
    }
    // Bytes (binary) or words (ASCII) of a value of type t.
    std::size_t least(Type t) const { return m_ascii ? 1 : sizeOf(t); }
    void claim(const PlyElement &e, std::size_t least) const
    {
        if (least > 0 && std::size_t(e.count) > room() / least)
            refuse(coreTranslate("awb::mesh", "%1: element %2 claims %3 items, more than the "
                                              "rest of the file can hold"),
                   m_name, shown(e.name), e.count);
    }
    void need(long long count, Type t) const
    {
        if (std::size_t(count) > room() / least(t))
            refuse(coreTranslate("awb::mesh", "%1: the data ends early (truncated)"), where());
    }
    double number(Type t)
    {
        if (m_ascii) {
            double x = 0;
            const std::string_view w = word();
            if (!parse(w, x))
                refuse(coreTranslate("awb::mesh", "%1: '%2' is not a number"), where(), shown(w));
            return x;
        }
        need(1, t);
        switch (t) {
        case Type::Int8: return get<std::int8_t>();
        case Type::UInt8: return get<std::uint8_t>();
        case Type::Int16: return get<std::int16_t>();
        case Type::UInt16: return get<std::uint16_t>();
        case Type::Int32: return get<std::int32_t>();
        case Type::UInt32: return get<std::uint32_t>();
        case Type::Float32: return get<float>();
        case Type::Float64: break;
        }
        return get<double>();
    }
    // A value of a whole-number type (at most 32 bits: exact as a double).
    long long whole(Type t)
    {
        return m_ascii ? wholeNumber(word(), [this] { return where(); })
                       : static_cast<long long>(number(t));
    }
    void skip(Type t, long long count)
    {
        need(count, t);
        if (!m_ascii)
            m_pos += std::size_t(count) * sizeOf(t);
        for (long long k = 0; m_ascii && k < count; ++k)
            number(t);
    }
    void finish()
    {
        if (m_ascii)
            space();
        if (m_pos < m_text.size())
            refuse(coreTranslate("awb::mesh", "%1: data after the last element (the header's "
                                              "counts do not match the data)"),
                   m_ascii ? atLine(m_name, m_line)
                           : formatMessage(coreTranslate("awb::mesh", "%1, byte %2"), m_name,
                                           m_pos));
    }

private:
    std::size_t room() const
    {
        return m_ascii ? (m_text.size() - m_pos + 1) / 2 : m_text.size() - m_pos;
    }
    template<class T>
    T get()
    {
        char b[sizeof(T)];
        std::memcpy(b, m_text.data() + m_pos, sizeof b);
        if (m_swap)
            std::reverse(b, b + sizeof b);
        m_pos += sizeof b;
        T v;
        std::memcpy(&v, b, sizeof v);
        return v;
    }
    static bool isSpace(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }
    void space()
    {
        for (; m_pos < m_text.size() && isSpace(m_text[m_pos]); ++m_pos)
            m_line += m_text[m_pos] == '\n'
                      || (m_text[m_pos] == '\r' && m_text.compare(m_pos + 1, 1, "\n") != 0);
    }
    std::string_view word()
    {
        space();
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && !isSpace(m_text[m_pos]))
            ++m_pos;
        if (m_pos == start)
            refuse(coreTranslate("awb::mesh", "%1: the data ends early (truncated)"), where());
        m_wordLine = m_line;
        return m_text.substr(start, m_pos - start);
    }

    std::string_view m_text;
    std::size_t m_pos, m_line, m_wordLine; // m_wordLine: of the last word read
    const std::string &m_name;
    bool m_ascii, m_swap;
    const std::string *m_element = nullptr;
    long long m_index = 0;
    std::size_t m_start = 0;
};

Mesh readPly(std::string_view text, const std::string &name)
{
    const PlyHeader h = readPlyHeader(text, name);
    const long long vertexCount = h.elements[std::size_t(h.vertex)].count;
    PlyData data(text, h, name);
    const auto where = [&] { return data.where(); };
    Mesh mesh;
    for (std::size_t e = 0; e < h.elements.size(); ++e) {
        const PlyElement &element = h.elements[e];
        const bool vertex = int(e) == h.vertex, face = int(e) == h.face;
        if (element.properties.empty())
            continue; // nothing to read, whatever its count
        // The least an item takes: its scalars, its lists' lengths, a face's 3 indices.
        std::size_t least = face ? 3 * data.least(element.properties[std::size_t(h.list)].type) : 0;
        for (const PlyProperty &p : element.properties)
            least += data.least(p.list ? p.count : p.type);
        data.claim(element, least);
        if (vertex)
            mesh.vertices.resize(Eigen::Index(element.count), 3);
        if (face)
            mesh.faces.reserve(std::size_t(element.count));
        for (long long i = 0; i < element.count; ++i) {
            data.at(element.name, i);
            for (std::size_t k = 0; k < element.properties.size(); ++k) {
                const PlyProperty &p = element.properties[k];
                if (!p.list) {
                    const double x = data.number(p.type);
                    const int axis = int(std::find(h.axis, h.axis + 3, int(k)) - h.axis);
                    if (vertex && axis < 3 && !std::isfinite(x))
                        refuse(coreTranslate("awb::mesh", "%1: '%2' is not a finite number"),
                               data.where(), x > 0 ? "inf" : x < 0 ? "-inf" : "nan");
                    if (vertex && axis < 3)
                        mesh.vertices(Eigen::Index(i), axis) = x;
                    continue;
                }
                const long long n = data.whole(p.count);
                if (n < 0)
                    refuse(coreTranslate("awb::mesh", "%1: list length %2 is negative"),
                           data.where(), n);
                if (!face || int(k) != h.list) {
                    data.skip(p.type, n);
                    continue;
                }
                requireFaceSize(n, where);
                data.need(n, p.type);
                std::vector<int> loop(static_cast<std::size_t>(n));
                for (int &v : loop) {
                    const long long index = data.whole(p.type);
                    requireIndex(index, 0, vertexCount, where);
                    v = int(index);
                }
                mesh.faces.push_back(std::move(loop));
            }
        }
    }
    data.finish();
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

Mesh readMesh(const std::string &path)
{
    const MeshFormat format = meshFormatForPath(path);
    std::ifstream in(path, std::ios::binary);
    if (!in)
        refuse(coreTranslate("awb::mesh", "cannot open %1"), path);
    return readMesh(in, format, path);
}

Mesh readMesh(std::istream &in, MeshFormat format, const std::string &name)
{
    const std::string bytes((std::istreambuf_iterator<char>(in)),
                            std::istreambuf_iterator<char>());
    if (in.bad())
        refuse(coreTranslate("awb::mesh", "cannot read %1"), name);
    if (bytes.find_first_not_of(" \t\r\n\f\v") == std::string::npos)
        refuse(coreTranslate("awb::mesh", "%1 is empty"), name);
    if (format == MeshFormat::Ply)
        return readPly(bytes, name);
    if (const std::size_t nul = bytes.find('\0'); nul != std::string::npos) {
        Lines lines(std::string_view(bytes).substr(0, nul + 1));
        for (std::string_view line; lines.next(line);) {
        }
        refuse(coreTranslate("awb::mesh", "%1: a NUL byte: not a text file"),
               atLine(name, lines.number()));
    }
    return format == MeshFormat::Obj ? readObj(bytes, name) : readOff(bytes, name);
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
    flush(0);
}

} // namespace awb
