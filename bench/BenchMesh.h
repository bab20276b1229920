#pragma once
// What the routes of attractor-bench-mesh share (bench_mesh.cpp: the IFS and plain routes and
// the table; bench_mesh_osd.cpp: OpenSubdiv's two routes): timing, the reference's nearest-
// vertex check, the figures a route passes from its forked child, and the cases.

#include "core/mesh/MeshExamples.h"
#include "core/mesh/MeshIterate.h"
#include "core/mesh/MeshPieces.h"
#include "core/mesh/MeshRefine.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace awb::benchmesh {


inline volatile double g_sink = 0;  // keeps results alive

inline double seconds(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

inline double timed(const std::function<void()> &fn)
{
    const auto t0 = std::chrono::steady_clock::now();
    fn();
    return seconds(t0);
}

// A field of /proc/self/status in kB (VmRSS, VmHWM), -1 if absent.
inline long statusKb(const char *field)
{
    std::ifstream in("/proc/self/status");
    std::string line;
    const std::size_t n = std::strlen(field);
    while (std::getline(in, line))
        if (line.compare(0, n, field) == 0 && line.size() > n && line[n] == ':')
            return std::stol(line.substr(n + 1));
    return -1;
}

// ---- checks -----------------------------------------------------------------------------------

// Nearest-vertex queries on the reference positions: a uniform grid of cells about two vertex
// spacings wide, hashed. A query looks in its own cell, and in the 26 around only when the
// best point found is farther than the cell's nearest wall (rare: the routes agree to 1e-12).
class PointGrid {
public:
    explicit PointGrid(const Mat &points) : m_points(points)
    {
        const Eigen::Index n = points.rows();
        const Eigen::RowVector3d lo = points.colwise().minCoeff(),
                                 hi = points.colwise().maxCoeff();
        // 1.7 (not 2): cell walls on no plane of symmetry of the meshes.
        m_h = std::max((hi - lo).norm(), 1e-300) * 1.7 /
              std::sqrt(double(std::max<Eigen::Index>(n, 1)));
        for (int k = 0; k < 3; ++k)
            m_lo[k] = lo(k) - m_h;
        std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(static_cast<std::size_t>(n));
        for (Eigen::Index i = 0; i < n; ++i) {
            const double x[3] = {points(i, 0), points(i, 1), points(i, 2)};
            int c[3];
            cellOf(x, c);
            keyed[std::size_t(i)] = {key(c[0], c[1], c[2]), std::uint32_t(i)};
        }
        std::sort(keyed.begin(), keyed.end());
        m_order.resize(keyed.size());
        std::size_t cells = 0;
        for (std::size_t i = 0; i < keyed.size(); ++i) {
            m_order[i] = keyed[i].second;
            cells += i == 0 || keyed[i].first != keyed[i - 1].first;
        }
        std::size_t size = 16;
        while (size < 2 * cells)
            size *= 2;
        m_mask = size - 1;
        m_slots.assign(size, Slot{});
        for (std::size_t i = 0; i < keyed.size();) {
            std::size_t j = i;
            while (j < keyed.size() && keyed[j].first == keyed[i].first)
                ++j;
            std::size_t s = hash(keyed[i].first);
            while (m_slots[s].key != kEmpty)
                s = (s + 1) & m_mask;
            m_slots[s] = {keyed[i].first, std::uint32_t(i), std::uint32_t(j)};
            i = j;
        }
    }

    // The row of the nearest reference vertex to x and its distance; (-1, inf) when none is
    // within a cell.
    std::pair<Eigen::Index, double> nearest(const double x[3]) const
    {
        int c[3];
        cellOf(x, c);
        Eigen::Index best = -1;
        double d2 = std::numeric_limits<double>::infinity();
        scan(x, c[0], c[1], c[2], best, d2);
        double wall = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 3; ++k) {
            const double lo = m_lo[k] + c[k] * m_h;
            wall = std::min({wall, x[k] - lo, lo + m_h - x[k]});
        }
        if (!(best >= 0 && std::sqrt(d2) <= wall))
            for (int a = -1; a <= 1; ++a)
                for (int b = -1; b <= 1; ++b)
                    for (int e = -1; e <= 1; ++e)
                        if (a || b || e)
                            scan(x, c[0] + a, c[1] + b, c[2] + e, best, d2);
        return {best, std::sqrt(d2)};
    }

    Eigen::Index size() const { return m_points.rows(); }

private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);
    static constexpr int kBits = 21;
    struct Slot {
        std::uint64_t key = kEmpty;
        std::uint32_t begin = 0, end = 0;
    };

    void cellOf(const double x[3], int c[3]) const
    {
        for (int k = 0; k < 3; ++k)
            c[k] = int(std::clamp(std::floor((x[k] - m_lo[k]) / m_h), 0.0,
                                  double((1 << kBits) - 1)));
    }
    static std::uint64_t key(int a, int b, int c)
    {
        return std::uint64_t(a) << (2 * kBits) | std::uint64_t(b) << kBits | std::uint64_t(c);
    }
    std::size_t hash(std::uint64_t k) const
    {
        return std::size_t((k * 0x9E3779B97F4A7C15ull) >> 20) & m_mask;
    }
    void scan(const double x[3], int a, int b, int c, Eigen::Index &best, double &d2) const
    {
        if (a < 0 || b < 0 || c < 0 || a >= (1 << kBits) || b >= (1 << kBits) || c >= (1 << kBits))
            return;
        const std::uint64_t k = key(a, b, c);
        for (std::size_t s = hash(k); m_slots[s].key != kEmpty; s = (s + 1) & m_mask) {
            if (m_slots[s].key != k)
                continue;
            for (std::uint32_t i = m_slots[s].begin; i < m_slots[s].end; ++i) {
                const Eigen::Index r = m_order[i];
                const double dx = m_points(r, 0) - x[0], dy = m_points(r, 1) - x[1],
                             dz = m_points(r, 2) - x[2];
                const double d = dx * dx + dy * dy + dz * dz;
                if (d < d2)
                    d2 = d, best = r;
            }
            return;
        }
    }

    const Mat &m_points;
    double m_lo[3] = {0, 0, 0}, m_h = 1;
    std::vector<std::uint32_t> m_order;
    std::vector<Slot> m_slots;
    std::size_t m_mask = 0;
};

// A route's points against the reference: the farthest point from its nearest reference vertex,
// and the reference vertices no point was nearest to.
struct Check {
    explicit Check(const PointGrid &g) : grid(g), hit(std::size_t(g.size()), 0) {}
    void add(const double x[3])
    {
        const auto [row, d] = grid.nearest(x);
        worst = std::max(worst, d);
        if (row >= 0)
            hit[std::size_t(row)] = 1;
    }
    void addRows(const Mat &m)
    {
        for (Eigen::Index i = 0; i < m.rows(); ++i) {
            const double x[3] = {m(i, 0), m(i, 1), m(i, 2)};
            add(x);
        }
    }
    double missing() const { return double(std::count(hit.begin(), hit.end(), 0)); }

    const PointGrid &grid;
    std::vector<char> hit;
    double worst = 0;
};

// ---- routes in child processes ----------------------------------------------------------------

// One line of the table, passed from the child through a pipe (plain data).
struct Figures {
    char route[40] = "";
    int threads = 1;
    double setup = NAN, data = NAN, total = NAN;  // seconds
    double points = NAN;    // points the route produced
    double peakMb = NAN;
    double diff = NAN;      // max distance to the reference over the diagonal; NAN: not checked
    double missing = 0;     // reference vertices no point reached
    char notes[200] = "";
    char error[200] = "";
};

struct Reference {
    const PointGrid *grid = nullptr;
    double diagonal = 1;
};

inline long g_forkRssKb = 0;  // the child's VmRSS at the fork

inline double peakMbSinceFork()
{
    const long hwm = statusKb("VmHWM");
    return hwm < 0 ? NAN : double(hwm - g_forkRssKb) / 1024.0;
}

inline void fillDiff(Figures &f, const Check &c, const Reference &ref)
{
    f.diff = c.worst / ref.diagonal;
    f.missing = c.missing();
}

inline bool writeAll(int fd, const void *p, std::size_t n)
{
    const char *c = static_cast<const char *>(p);
    while (n > 0) {
        const ssize_t w = write(fd, c, n);
        if (w <= 0)
            return false;
        c += w, n -= std::size_t(w);
    }
    return true;
}

inline bool readAll(int fd, void *p, std::size_t n)
{
    char *c = static_cast<char *>(p);
    while (n > 0) {
        const ssize_t r = read(fd, c, n);
        if (r <= 0)
            return false;
        c += r, n -= std::size_t(r);
    }
    return true;
}

// Runs fn(figures, positions) in a forked child; returns its figures, and its positions (n x 3)
// in *positions when given. A child that dies gives one line with the error.
template <typename Fn>
std::vector<Figures> inChild(const char *route, Fn fn, Mat *positions = nullptr)
{
    std::fflush(stdout);
    int fd[2];
    if (pipe(fd) != 0) {
        Figures f;
        std::snprintf(f.route, sizeof f.route, "%s", route);
        std::snprintf(f.error, sizeof f.error, "pipe() failed");
        return {f};
    }
    const pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        g_forkRssKb = statusKb("VmRSS");
        std::vector<Figures> out;
        Mat pos;
        try {
            fn(out, pos);
        } catch (const std::exception &e) {
            Figures f;
            std::snprintf(f.route, sizeof f.route, "%s", route);
            std::snprintf(f.error, sizeof f.error, "%s", e.what());
            out.assign(1, f);
        }
        const std::uint64_t count = out.size(), rows = std::uint64_t(pos.rows());
        const bool ok = writeAll(fd[1], &count, sizeof count) &&
                        writeAll(fd[1], out.data(), count * sizeof(Figures)) &&
                        writeAll(fd[1], &rows, sizeof rows) &&
                        writeAll(fd[1], pos.data(), rows * 3 * sizeof(double));
        _exit(ok ? 0 : 1);
    }
    close(fd[1]);
    std::vector<Figures> out;
    std::uint64_t count = 0, rows = 0;
    bool ok = pid > 0 && readAll(fd[0], &count, sizeof count) && count < 100;
    if (ok) {
        out.resize(count);
        ok = readAll(fd[0], out.data(), count * sizeof(Figures)) &&
             readAll(fd[0], &rows, sizeof rows);
    }
    if (ok && positions) {
        positions->resize(Eigen::Index(rows), 3);
        ok = readAll(fd[0], positions->data(), rows * 3 * sizeof(double));
    }
    close(fd[0]);
    int status = 0;
    if (pid > 0)
        waitpid(pid, &status, 0);
    if (!ok) {
        Figures f;
        std::snprintf(f.route, sizeof f.route, "%s", route);
        if (WIFSIGNALED(status))
            std::snprintf(f.error, sizeof f.error, "the child died of signal %d (%s)",
                          WTERMSIG(status), strsignal(WTERMSIG(status)));
        else
            std::snprintf(f.error, sizeof f.error, "the child failed (status %d)", status);
        out.assign(1, f);
    }
    return out;
}

struct Case {
    std::string name;  // mesh-scheme
    Mesh mesh;
    MeshScheme scheme;
    int depth;
    bool checkIfs;  // match the IFS's emitted points to the reference too
};

// OpenSubdiv 3.5's routes (bench_mesh_osd.cpp): Interpolate level by level then Limit, and its
// stencil table of level K over the input then Limit.
std::vector<Figures> osdRoute(const Case &c, int rounds, const Reference &ref);
std::vector<Figures> osdTableRoute(const Case &c, int rounds, const Reference &ref);

} // namespace awb::benchmesh
