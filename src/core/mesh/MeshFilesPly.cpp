// The PLY reader of MeshFiles.h: ASCII, binary little and big endian 1.0; the vertex element's
// x, y, z (any numeric type) and the face element's vertex_indices (or vertex_index) list, every
// other property, list and element skipped by its size.

#include "core/mesh/MeshFilesText.h"

#include <algorithm>
#include <bit>
#include <climits>
#include <cstdint>
#include <cstring>
#include <limits>

namespace awb::meshtext {

namespace {

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

PlyHeader readPlyHeader(std::string_view text, const std::string &name,
                        std::vector<std::string> *notes)
{
    Lines lines(text);
    std::string_view line;
    if (!lines.next(line) || line != "ply")
        refuse(coreTranslate("awb::mesh", "%1 is not a PLY file (its first line is not 'ply')"),
               name);
    PlyHeader h;
    bool format = false;
    long long skipped = 0;
    std::string firstSkipped, firstSkippedLine;
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
        } else if (w[0] == "format" || w[0] == "element" || w[0] == "property") {
            refuse(coreTranslate("awb::mesh", "%1: malformed PLY header line '%2'"), where,
                   shown(line));
        } else {
            // Not PLY 1.0's (an exporter's own keyword): other readers skip it, so does this
            // one, and says so below, once.
            if (skipped++ == 0) {
                firstSkipped = where;
                firstSkippedLine = shown(line);
            }
        }
    }
    if (notes && skipped == 1)
        notes->push_back(formatMessage(
            coreTranslate("awb::mesh", "%1: header line '%2' is not PLY 1.0's: skipped"),
            firstSkipped, firstSkippedLine));
    else if (notes && skipped > 1)
        notes->push_back(formatMessage(
            coreTranslate("awb::mesh", "%1: %2 header lines that are not PLY 1.0's, the first "
                                       "'%3', are skipped"),
            firstSkipped, skipped, firstSkippedLine));
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

} // namespace

Mesh readPly(std::string_view text, const std::string &name, std::vector<std::string> *notes)
{
    const PlyHeader h = readPlyHeader(text, name, notes);
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

} // namespace awb::meshtext
