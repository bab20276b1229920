#pragma once
// Point sets in the tests of the mesh room: the distance from a set to another through a grid
// of cells searched in growing shells (linear, so that sets of 10^5 points compare in
// milliseconds, also under the sanitizers), and meshes with their vertices moved at random.

#include "core/mesh/Mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <unordered_map>
#include <vector>

namespace awb::test {

// The length of the bounding box's diagonal of the rows of v.
inline double diagonal(const Mat &v)
{
    return (v.colwise().maxCoeff() - v.colwise().minCoeff()).norm();
}

// The largest distance from a row of `a` to the nearest row of `b`, through a grid of cells of
// size `cell` searched in growing shells, at most `shells` of them (infinity beyond).
inline double directedDistance(const Mat &a, const Mat &b, double cell, long shells = 64)
{
    struct Hash {
        std::size_t operator()(const std::array<long, 3> &k) const
        {
            return std::size_t(k[0] * 73856093L ^ k[1] * 19349663L ^ k[2] * 83492791L);
        }
    };
    std::unordered_map<std::array<long, 3>, std::vector<Eigen::Index>, Hash> grid;
    const auto keyOf = [cell](const RowVec &p) {
        return std::array<long, 3>{long(std::floor(p(0) / cell)), long(std::floor(p(1) / cell)),
                                   long(std::floor(p(2) / cell))};
    };
    for (Eigen::Index j = 0; j < b.rows(); ++j)
        grid[keyOf(b.row(j))].push_back(j);
    double worst = 0.0;
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
        const auto k = keyOf(a.row(i));
        double best = std::numeric_limits<double>::infinity();
        // Shell r holds the cells at Chebyshev distance r; every point beyond it is farther
        // than r cells.
        for (long r = 0; r <= shells && !(best <= double(r) * cell); ++r)
            for (long dx = -r; dx <= r; ++dx)
                for (long dy = -r; dy <= r; ++dy)
                    for (long dz = -r; dz <= r; ++dz) {
                        if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != r)
                            continue;
                        const auto it = grid.find({k[0] + dx, k[1] + dy, k[2] + dz});
                        if (it == grid.end())
                            continue;
                        for (Eigen::Index j : it->second)
                            best = std::min(best, (a.row(i) - b.row(j)).norm());
                    }
        worst = std::max(worst, best);
    }
    return worst;
}

// Both ways: each row of `a` near a row of `b` and each of `b` near one of `a`. For sets that
// should coincide: cells of 1e-6 of their size, two shells.
inline double setDistance(const Mat &a, const Mat &b)
{
    const double cell = 1e-6 * std::max(diagonal(a), diagonal(b));
    return std::max(directedDistance(a, b, cell, 2), directedDistance(b, a, cell, 2));
}

// The mesh with every coordinate moved by up to `amount`, the same on every machine for a seed.
inline Mesh jittered(Mesh m, unsigned seed, double amount = 0.2)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> jitter(-amount, amount);
    for (Eigen::Index v = 0; v < m.vertices.rows(); ++v)
        for (int c = 0; c < 3; ++c)
            m.vertices(v, c) += jitter(random);
    return m;
}

} // namespace awb::test
