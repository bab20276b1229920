#include "core/analysis/RegularityAtlas.h"

#include "core/Messages.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

namespace awb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void require(bool ok, const std::string &message)
{
    if (!ok)
        throw InputError(message);
}

} // namespace

int atlasVerdict(const AtlasRow &row, int k)
{
    return smoothnessVerdict(row.applies, row.lower, row.upper, k);
}

RegularityOptions atlasRegularityOptions(const AtlasOptions &options)
{
    RegularityOptions o;
    o.timeBudget = options.safetySeconds;
    o.polytopeBudget = options.safetySeconds;
    o.maxProducts = std::max<long long>(1, options.work);
    o.maxPolytopeVertices = options.polytopeVertices;
    return o;
}

AtlasRow evaluateAtlasPoint(const AtlasMember &member, const std::vector<double> &params,
                            const AtlasOptions &options)
{
    const auto start = std::chrono::steady_clock::now();
    AtlasRow row;
    row.params = params;
    try {
        const Regularity r = member(params, atlasRegularityOptions(options));
        row.applies = r.applies;
        row.message = r.message;
        if (r.applies) {
            row.lower = r.infinite ? kInf : r.lower;
            row.upper = r.infinite ? kInf : r.upper;
            row.exact = r.exact || r.infinite;
            row.smoothness = r.infinite ? std::numeric_limits<int>::max() : r.smoothness;
            row.sobolev = r.sobolev ? *r.sobolev : -1.0;
            row.timedOut = r.jsr.timedOut;
        }
    } catch (const std::exception &e) {
        row = AtlasRow{};
        row.params = params;
        row.message = e.what();
    }
    row.verdict = atlasVerdict(row, options.smoothness);
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return row;
}

AtlasPlan::AtlasPlan(std::vector<AtlasAxis> axes, AtlasOptions options)
    : m_axes(std::move(axes)), m_options(options)
{
    require(m_axes.size() == 1 || m_axes.size() == 2,
            formatMessage(coreTranslate("awb::analysis", "an atlas has one or two parameters, "
                                                         "got %1"),
                          int(m_axes.size())));
    const int maxCount = m_axes.size() == 1 ? 100000 : 2000;
    for (const AtlasAxis &a : m_axes) {
        require(!a.name.empty(), coreTranslate("awb::analysis", "a parameter of the atlas has "
                                                                "no name"));
        require(std::isfinite(a.from) && std::isfinite(a.to) && a.from < a.to,
                formatMessage(coreTranslate("awb::analysis", "the range of %1, [%2, %3], must "
                                                             "be finite with from < to"),
                              a.name, streamedNumber(a.from), streamedNumber(a.to)));
        require(a.count >= 2 && a.count <= maxCount,
                formatMessage(coreTranslate("awb::analysis", "the grid of %1 must have 2 to %2 "
                                                             "values, got %3"),
                              a.name, maxCount, a.count));
    }
    if (m_axes.size() == 2)
        require(m_axes[0].name != m_axes[1].name,
                formatMessage(coreTranslate("awb::analysis", "the two parameters of the atlas "
                                                             "have the same name %1"),
                              m_axes[0].name));
    require(m_options.smoothness >= 0 && m_options.smoothness <= 30,
            formatMessage(coreTranslate("awb::analysis", "the smoothness k must be between 0 "
                                                         "and 30, got %1"),
                          m_options.smoothness));
    require(m_options.tolerance > 0 && std::isfinite(m_options.tolerance),
            coreTranslate("awb::analysis", "the tolerance must be a positive number"));
    require(m_options.sections >= 1 && m_options.sections <= 64,
            coreTranslate("awb::analysis", "the sections per round must be 1 to 64"));
    require(m_options.maxRounds >= 0 && m_options.maxRounds <= 64,
            coreTranslate("awb::analysis", "the rounds must be 0 to 64"));
    require(m_options.refineLevels >= 0 && m_options.refineLevels <= 10,
            formatMessage(coreTranslate("awb::analysis", "the refinement levels must be 0 to "
                                                         "10, got %1"),
                          m_options.refineLevels));
    require(m_options.work >= 1000 && m_options.work <= 100000000000LL,
            coreTranslate("awb::analysis", "the work per point must be 1000 to 1e11 products"));
    require(m_options.polytopeVertices >= 0 && m_options.polytopeVertices <= 100000,
            coreTranslate("awb::analysis", "the polytope vertices must be 0 to 100000"));
    require(m_options.safetySeconds > 0 && m_options.safetySeconds <= 86400,
            coreTranslate("awb::analysis", "the safety time must be 0 to 86400 s"));
    if (m_axes.size() == 2) {
        const double points = double(m_axes[0].count) * double(m_axes[1].count);
        require(points <= 1e6,
                formatMessage(coreTranslate("awb::analysis", "a grid of %1 x %2 points is more "
                                                             "than the atlas's 1e6"),
                              m_axes[0].count, m_axes[1].count));
    }
    // The first batch: the grid.
    if (m_axes.size() == 1) {
        const AtlasAxis &a = m_axes[0];
        for (int i = 0; i < a.count; ++i)
            m_pending.push_back(
                {i + 1 == a.count ? a.to : a.from + (a.to - a.from) * double(i) / (a.count - 1)});
    } else {
        const std::int64_t S = std::int64_t(1) << m_options.refineLevels;
        for (int j = 0; j < m_axes[1].count; ++j)
            for (int i = 0; i < m_axes[0].count; ++i) {
                m_pendingLattice.push_back({i * S, j * S});
                m_level[{i * S, j * S}] = S;
                if (i + 1 < m_axes[0].count && j + 1 < m_axes[1].count)
                    m_cells.push_back({i * S, j * S, S});
            }
        for (const auto &[i, j] : m_pendingLattice)
            m_pending.push_back({value(0, i), value(1, j)});
    }
}

double AtlasPlan::value(int axis, std::int64_t lattice) const
{
    const AtlasAxis &a = m_axes[size_t(axis)];
    const std::int64_t last = std::int64_t(a.count - 1) << m_options.refineLevels;
    if (lattice >= last)
        return a.to;
    return a.from + (a.to - a.from) * double(lattice) / double(last);
}

std::vector<std::vector<double>> AtlasPlan::nextBatch()
{
    if (m_finished)
        return {};
    require(!m_awaiting, coreTranslate("awb::analysis", "the atlas's previous batch has no rows "
                                                        "yet"));
    if (m_pending.empty()) {
        m_finished = true;
        return {};
    }
    m_awaiting = true;
    ++m_round;
    return m_pending;
}

void AtlasPlan::accept(const std::vector<AtlasRow> &rows)
{
    require(m_awaiting && rows.size() == m_pending.size(),
            formatMessage(coreTranslate("awb::analysis", "the atlas expected %1 rows, got %2"),
                          int(m_awaiting ? m_pending.size() : 0), int(rows.size())));
    for (size_t n = 0; n < rows.size(); ++n) {
        require(rows[n].params == m_pending[n],
                coreTranslate("awb::analysis", "a row of the atlas does not belong to its "
                                               "batch"));
    }
    m_awaiting = false;
    if (m_axes.size() == 1) {
        for (AtlasRow row : rows) {
            row.verdict = atlasVerdict(row, m_options.smoothness);
            m_line[row.params[0]] = row;
        }
        m_pending.clear();
        plan1D();
    } else {
        for (size_t n = 0; n < rows.size(); ++n) {
            AtlasRow row = rows[n];
            row.verdict = atlasVerdict(row, m_options.smoothness);
            m_plane[m_pendingLattice[n]] = row;
        }
        m_pending.clear();
        m_pendingLattice.clear();
        plan2D();
    }
    if (m_pending.empty())
        m_finished = true;
}

void AtlasPlan::plan1D()
{
    // After the grid: the brackets between neighbours on both sides of a C^k verdict.
    if (m_round == 1) {
        for (auto it = m_line.begin(); std::next(it) != m_line.end(); ++it) {
            const auto next = std::next(it);
            const bool a = it->second.verdict > 0, b = next->second.verdict > 0;
            if (a != b)
                m_brackets.push_back(a ? std::pair{it->first, next->first}
                                       : std::pair{next->first, it->first});
        }
    } else {
        // Narrow each bracket to the last C^k row seen from its inner end and the row after it.
        for (auto &[inner, outer] : m_brackets) {
            const bool up = outer > inner;
            auto it = m_line.find(inner);
            while (true) {
                auto next = up ? std::next(it) : std::prev(it);
                if (next->first == outer || next->second.verdict <= 0) {
                    inner = it->first;
                    outer = next->first;
                    break;
                }
                it = next;
            }
        }
    }
    if (m_round > m_options.maxRounds)
        return;
    for (const auto &[inner, outer] : m_brackets) {
        if (std::abs(outer - inner) <= m_options.tolerance)
            continue;
        for (int j = 1; j <= m_options.sections; ++j) {
            const double t = inner + (outer - inner) * double(j) / (m_options.sections + 1);
            if (t != inner && t != outer && !m_line.count(t))
                m_pending.push_back({t});
        }
    }
    std::sort(m_pending.begin(), m_pending.end());
    m_pending.erase(std::unique(m_pending.begin(), m_pending.end()), m_pending.end());
}

void AtlasPlan::plan2D()
{
    std::vector<Cell> children;
    std::set<std::pair<std::int64_t, std::int64_t>> added;
    const auto add = [&](std::int64_t i, std::int64_t j, std::int64_t size) {
        if (m_plane.count({i, j}) || !added.insert({i, j}).second)
            return;
        m_pendingLattice.push_back({i, j});
        m_level[{i, j}] = size;
    };
    for (const Cell &c : m_cells) {
        if (c.size < 2)
            continue;
        const int v00 = m_plane.at({c.i, c.j}).verdict;
        const int v10 = m_plane.at({c.i + c.size, c.j}).verdict;
        const int v01 = m_plane.at({c.i, c.j + c.size}).verdict;
        const int v11 = m_plane.at({c.i + c.size, c.j + c.size}).verdict;
        if (v00 == v10 && v00 == v01 && v00 == v11)
            continue;
        const std::int64_t h = c.size / 2;
        for (const auto &[di, dj] : {std::pair{h, 0}, {0, h}, {h, h}, {2 * h, h}, {h, 2 * h}})
            add(c.i + di, c.j + dj, h);
        for (const auto &[di, dj] : {std::pair{0, 0}, {h, 0}, {0, h}, {h, h}})
            children.push_back({c.i + di, c.j + dj, h});
    }
    m_cells = std::move(children);
    std::sort(m_pendingLattice.begin(), m_pendingLattice.end(),
              [](const auto &a, const auto &b) {
                  return std::pair{a.second, a.first} < std::pair{b.second, b.first};
              });
    for (const auto &[i, j] : m_pendingLattice)
        m_pending.push_back({value(0, i), value(1, j)});
}

std::vector<AtlasRow> AtlasPlan::rows() const
{
    std::vector<AtlasRow> out;
    for (const auto &[t, row] : m_line)
        out.push_back(row);
    for (const auto &[ij, row] : m_plane)
        out.push_back(row);
    std::sort(out.begin(), out.end(),
              [](const AtlasRow &a, const AtlasRow &b) { return a.params < b.params; });
    return out;
}

std::vector<AtlasRun> AtlasPlan::runs() const
{
    std::vector<AtlasRun> out;
    if (m_axes.size() != 1)
        return out;
    std::vector<const AtlasRow *> rows;
    for (const auto &[t, row] : m_line)
        rows.push_back(&row);
    for (size_t i = 0; i < rows.size();) {
        if (rows[i]->verdict <= 0) {
            ++i;
            continue;
        }
        size_t j = i;
        while (j + 1 < rows.size() && rows[j + 1]->verdict > 0)
            ++j;
        AtlasRun run;
        const double a = rows[i]->params[0], b = rows[j]->params[0];
        run.from = i == 0 ? AtlasBoundary{a, a, true, false}
                          : AtlasBoundary{a, rows[i - 1]->params[0], false,
                                          rows[i - 1]->verdict == 0};
        run.to = j + 1 == rows.size() ? AtlasBoundary{b, b, true, false}
                                      : AtlasBoundary{b, rows[j + 1]->params[0], false,
                                                      rows[j + 1]->verdict == 0};
        out.push_back(run);
        i = j + 1;
    }
    return out;
}

std::vector<double> AtlasPlan::cellSize(const AtlasRow &row) const
{
    std::vector<double> out;
    for (size_t a = 0; a < m_axes.size(); ++a)
        out.push_back((m_axes[a].to - m_axes[a].from) / (m_axes[a].count - 1));
    if (m_axes.size() != 2 || row.params.size() != 2)
        return out;
    const std::int64_t S = std::int64_t(1) << m_options.refineLevels;
    std::pair<std::int64_t, std::int64_t> ij;
    for (int a = 0; a < 2; ++a) {
        const AtlasAxis &ax = m_axes[size_t(a)];
        const double l = (row.params[size_t(a)] - ax.from) / (ax.to - ax.from) *
                         double(std::int64_t(ax.count - 1) * S);
        (a == 0 ? ij.first : ij.second) = std::llround(l);
    }
    const auto it = m_level.find(ij);
    const double f = it == m_level.end() ? 1.0 : double(it->second) / double(S);
    for (double &v : out)
        v *= f;
    return out;
}

} // namespace awb
