#pragma once
// Pictures compared by blocks (the flame tests: ours against flam3-render's): the correlation
// of two block means, and how much of one's lit blocks the other lights.

#include <cmath>
#include <vector>

namespace awb::test {

inline double correlation(const std::vector<double> &a, const std::vector<double> &b)
{
    const double n = double(a.size());
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        ma += a[i] / n, mb += b[i] / n;
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return sab / std::sqrt(saa * sbb);
}

// The share of the blocks of `a` above litA whose block of `b` is above litB.
inline double litCovered(const std::vector<double> &a, const std::vector<double> &b, double litA,
                         double litB)
{
    double lit = 0, both = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i] > litA) {
            lit += 1;
            both += b[i] > litB;
        }
    return lit > 0 ? both / lit : 0;
}

} // namespace awb::test
