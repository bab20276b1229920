#pragma once
// What the mesh readers share (MeshFiles.cpp: OBJ, OFF; MeshFilesPly.cpp: PLY): the words and
// lines of a text, numbers read exactly, and the refusals that name the place. Internal to the
// mesh room.

#include "core/Messages.h"
#include "core/mesh/Mesh.h"

#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace awb::meshtext {

inline constexpr std::size_t npos = std::string_view::npos;
using Words = std::vector<std::string_view>;

template<class... Args>
[[noreturn]] void refuse(std::string_view pattern, const Args &...args)
{
    throw InputError(formatMessage(pattern, args...));
}

// The words of a line, split at spaces and tabs.
inline Words words(std::string_view line)
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
inline std::string shown(std::string_view w)
{
    std::string s(w.substr(0, 40));
    for (char &c : s)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            c = '?';
    return w.size() > 40 ? s + "..." : s;
}

inline std::string atLine(const std::string &name, std::size_t line)
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

inline void requireMesh(long long vertices, std::size_t faces, const std::string &name)
{
    if (vertices == 0)
        refuse(coreTranslate("awb::mesh", "%1 holds no vertices"), name);
    if (faces == 0)
        refuse(coreTranslate("awb::mesh", "%1 holds no faces: not a polygon mesh"), name);
}

// The PLY reader (MeshFilesPly.cpp).
// `notes` (may be null) receives the header lines it skips.
Mesh readPly(std::string_view text, const std::string &name, std::vector<std::string> *notes);

} // namespace awb::meshtext
