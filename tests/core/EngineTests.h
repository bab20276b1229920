#pragma once
// Shared fixtures of the raster engine's tests (test_engine.cpp, test_engine_storage.cpp): small
// IFS, engine jobs and comparisons of density images.

#include "core/ifs/Random.h"
#include "core/render/Engine.h"

#include <cmath>
#include <initializer_list>

namespace awb::test {

inline Mat pts(std::initializer_list<std::pair<double, double>> p)
{
    Mat m(Eigen::Index(p.size()), 2);
    int i = 0;
    for (auto [x, y] : p)
        m.row(i++) << x, y;
    return m;
}

// The Sierpinski gasket in the plane: f_i(z) = z/2 + v_i/2, v = (0,0), (1,0), (0.5,1).
inline Ifs sierpinski(std::vector<double> probabilities = {})
{
    Ifs ifs;
    const double v[3][2] = {{0, 0}, {1, 0}, {0.5, 1}};
    for (auto &p : v) {
        AffineMap f;
        f.A = Mat::Identity(2, 2) * 0.5;
        f.b = RowVec(2);
        f.b << p[0] / 2, p[1] / 2;
        ifs.maps.push_back(f);
    }
    ifs.views.push_back({Mat::Identity(2, 2), RowVec::Zero(2)});
    ifs.probabilities = std::move(probabilities);
    return ifs;
}

// side^2 maps z -> z R / side + (i, j) / side on the unit square, R a rotation by `angle` (a
// carpet-like IFS; with side 3 and `skipCentre`, Sierpinski's carpet of 8 maps).
inline Ifs gridIfs(int side, bool skipCentre, double angle)
{
    Ifs ifs;
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j) {
            if (skipCentre && i == side / 2 && j == side / 2)
                continue;
            AffineMap f;
            f.A = Mat(2, 2);
            f.A << std::cos(angle), std::sin(angle), -std::sin(angle), std::cos(angle);
            f.A /= side;
            f.b = RowVec(2);
            f.b << double(i) / side, double(j) / side;
            ifs.maps.push_back(f);
        }
    ifs.views.push_back({Mat::Identity(2, 2), RowVec::Zero(2)});
    return ifs;
}

inline EngineJob job(const Ifs &ifs, const StartSet &start, int size, double x0, double y0, double x1,
              double y1)
{
    EngineJob j;
    j.ifs = &ifs;
    j.start = start;
    j.frame.width = j.frame.height = size;
    j.frame.x0 = x0, j.frame.y0 = y0, j.frame.x1 = x1, j.frame.y1 = y1;
    j.colours.prefix = 1;
    for (int i = 0; i < ifs.size(); ++i)
        j.colours.labelColours.push_back(Rgb8{std::uint8_t(40 * i), 100, std::uint8_t(200 - 40 * i)});
    return j;
}

inline bool sameBuckets(const DensityImage &a, const DensityImage &b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a.cell(i) != b.cell(i))
            return false;
    return true;
}

// Fraction of cells lit in exactly one of the two images.
inline double litMismatch(const DensityImage &a, const DensityImage &b)
{
    std::size_t differ = 0, lit = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const bool la = a.count(i) > 0, lb = b.count(i) > 0;
        differ += la != lb;
        lit += la || lb;
    }
    return lit ? double(differ) / double(lit) : 0.0;
}

} // namespace awb::test
