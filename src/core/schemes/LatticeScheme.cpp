#include "core/schemes/LatticeScheme.h"

#include "core/Decompositions.h"
#include "core/Messages.h"

#include <cmath>
#include <cstdlib>
#include <functional>

namespace awb {

std::string toString(Lattice lattice)
{
    return lattice == Lattice::Square ? "square" : "triangular";
}

Eigen::Vector2d latticePosition(Lattice lattice, const Eigen::Vector2d &c)
{
    if (lattice == Lattice::Square)
        return c;
    return {c.x() + 0.5 * c.y(), 0.5 * std::sqrt(3.0) * c.y()};
}

int latticeDistance(Lattice lattice, LatticePoint p)
{
    const int m = std::max(std::abs(p.i), std::abs(p.j));
    return lattice == Lattice::Square ? m : std::max(m, std::abs(p.i + p.j));
}

std::vector<LatticePoint> latticeNeighbours(Lattice lattice)
{
    if (lattice == Lattice::Square)
        return {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    return {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
}

namespace {

int floorMod(int a, int n) { return ((a % n) + n) % n; }

} // namespace

LatticeScheme::LatticeScheme(std::string name, Lattice lattice, int dilation,
                             std::map<LatticePoint, double> mask)
    : m_name(std::move(name)), m_lattice(lattice), m_dilation(dilation)
{
    if (dilation < 2)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "scheme %1: the dilation must be at least 2"), m_name));
    for (const auto &[x, w] : mask) {
        if (!std::isfinite(w))
            throw InputError(formatMessage(
                coreTranslate("awb::schemes", "scheme %1: the mask holds a non-finite weight"),
                m_name));
        if (w != 0.0)
            m_mask.emplace(x, w);
    }
    if (m_mask.empty())
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "scheme %1: the mask is empty"), m_name));
    // Each refined point must be an affine combination of old points.
    const int N = dilation;
    for (int r = 0; r < N; ++r)
        for (int s = 0; s < N; ++s) {
            double sum = 0.0;
            for (const auto &[x, w] : m_mask)
                if (floorMod(x.i, N) == r && floorMod(x.j, N) == s)
                    sum += w;
            if (std::abs(sum - 1.0) > 1e-12)
                throw InputError(formatMessage(
                    coreTranslate("awb::schemes", "scheme %1: the mask entries of class (%2, %3) "
                                                  "mod %4 sum to %5, not 1"),
                    m_name, r, s, N, streamedNumber(sum)));
        }
    for (const auto &[x, w] : m_mask)
        m_radius = std::max(m_radius, latticeDistance(lattice, x));
    computeLimitStencil();
}

Stencil LatticeScheme::stencil(LatticePoint rho) const
{
    Stencil out;
    const int N = m_dilation;
    for (const auto &[x, w] : m_mask) {
        const LatticePoint d = rho - x;
        if (floorMod(d.i, N) == 0 && floorMod(d.j, N) == 0)
            out.push_back({{d.i / N, d.j / N}, w});
    }
    std::sort(out.begin(), out.end(),
              [](const auto &a, const auto &b) { return a.first < b.first; });
    return out;
}

bool LatticeScheme::symmetricUnder(const LatticeMatrix &R) const
{
    for (const auto &[x, w] : m_mask) {
        const auto it = m_mask.find(R.apply(x));
        if (it == m_mask.end() || std::abs(it->second - w) > 1e-14)
            return false;
    }
    return true;
}

void LatticeScheme::computeLimitStencil()
{
    // Local subdivision matrix on the ball B_r around a vertex: the refined points of B_r
    // depend only on old points of B_r once r >= R / (N - 1).
    const int N = m_dilation;
    const int r = (m_radius + N - 2) / (N - 1);
    std::vector<LatticePoint> ball;
    for (int j = -r; j <= r; ++j)
        for (int i = -r; i <= r; ++i)
            if (latticeDistance(m_lattice, {i, j}) <= r)
                ball.push_back({i, j});
    std::map<LatticePoint, int> index;
    for (size_t k = 0; k < ball.size(); ++k)
        index[ball[k]] = int(k);
    const int n = int(ball.size());
    Mat L = Mat::Zero(n, n);
    for (int k = 0; k < n; ++k)
        for (const auto &[beta, w] : stencil(ball[size_t(k)])) {
            const auto it = index.find(beta);
            if (it == index.end())
                throw InputError(formatMessage(
                    coreTranslate("awb::schemes", "scheme %1: local subdivision matrix not "
                                                  "closed"),
                    m_name));
            L(k, it->second) = w;
        }
    // Left eigenvector for eigenvalue 1: l L = l, i.e. L^T l^T = l^T.
    Eigen::EigenSolver<Mat> es(Mat(L.transpose()));
    int best = -1;
    double gap = 1e300;
    for (int k = 0; k < n; ++k) {
        const double g = std::abs(es.eigenvalues()(k) - Complex(1.0, 0.0));
        if (g < gap)
            gap = g, best = k;
    }
    if (best < 0 || gap > 1e-8)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "scheme %1: the local subdivision matrix has no "
                                          "eigenvalue 1"),
            m_name));
    Vec l = es.eigenvectors().col(best).real();
    const double sum = l.sum();
    if (std::abs(sum) < 1e-12)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "scheme %1: the limit eigenvector sums to 0"), m_name));
    l /= sum;
    for (int k = 0; k < n; ++k)
        if (std::abs(l(k)) > 1e-13)
            m_limit.push_back({ball[size_t(k)], l(k)});
}

// ---- the schemes ------------------------------------------------------------------------------

LatticeScheme boxSplineScheme(std::string name, Lattice lattice,
                              const std::vector<LatticePoint> &directions)
{
    // a(z) = 4 prod (1 + z^xi) / 2, as a map from exponent to coefficient.
    std::map<LatticePoint, double> poly{{{0, 0}, 4.0}};
    LatticePoint sum;
    for (const LatticePoint &xi : directions) {
        std::map<LatticePoint, double> next;
        for (const auto &[e, c] : poly) {
            next[e] += 0.5 * c;
            next[e + xi] += 0.5 * c;
        }
        poly = std::move(next);
        sum = sum + xi;
    }
    if (sum.i % 2 || sum.j % 2)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "box spline %1: its directions sum to an odd vector, so "
                                          "the mask has no lattice-point centre"),
            name));
    const LatticePoint centre{sum.i / 2, sum.j / 2};
    std::map<LatticePoint, double> mask;
    for (const auto &[e, c] : poly)
        mask[e - centre] = c;
    return LatticeScheme(std::move(name), lattice, 2, std::move(mask));
}

LatticeScheme bicubicScheme()
{
    const LatticePoint e1{1, 0}, e2{0, 1};
    return boxSplineScheme(coreTranslate("awb::schemes", "bicubic B-spline"), Lattice::Square,
                           {e1, e1, e1, e1, e2, e2, e2, e2});
}

LatticeScheme loopScheme()
{
    const LatticePoint e1{1, 0}, e2{0, 1}, e3{-1, 1};
    return boxSplineScheme(coreTranslate("awb::schemes", "Loop (three-direction quartic box "
                                                         "spline)"),
                           Lattice::Triangular,
                           {e1, e1, e2, e2, e3, e3});
}

LatticeScheme sqrt3Scheme()
{
    // Coordinates in thirds of the original lattice: original vertices at (3i, 3j), the first
    // round's centroids at (3i+1, 3j+1) (up triangles) and (3i+2, 3j+2) (down triangles); the
    // first round's lattice is {x = y mod 3}, with neighbours ±(1,1), ±(2,-1), ±(-1,2).
    // The second round fills in the rest of the thirds lattice.
    const auto p = [](int i, int j) { return i == 0 && j == 0 ? 1.0 : 0.0; };  // impulse
    const auto mod3 = [](int a) { return floorMod(a, 3); };
    const std::vector<LatticePoint> unit = latticeNeighbours(Lattice::Triangular);
    const std::function<double(int, int)> round1 = [&](int x, int y) -> double {
        if (mod3(x) == 0 && mod3(y) == 0) {  // old vertex, relaxed
            const int i = x / 3, j = y / 3;
            double s = 2.0 / 3.0 * p(i, j);
            for (const LatticePoint &n : unit)
                s += p(i + n.i, j + n.j) / 18.0;
            return s;
        }
        // Centroid of an up (class 1) or down (class 2) triangle: its three vertices.
        const int sgn = mod3(x) == 1 ? 1 : -1;
        double s = 0.0;
        for (const LatticePoint off : {LatticePoint{-1, -1}, LatticePoint{2, -1},
                                       LatticePoint{-1, 2}})
            s += p((x + sgn * off.i) / 3, (y + sgn * off.j) / 3) / 3.0;
        return s;
    };
    const std::vector<LatticePoint> round1Neighbours{{1, 1},  {2, -1},  {-1, 2},
                                                     {-1, -1}, {-2, 1}, {1, -2}};
    std::map<LatticePoint, double> mask;
    for (int y = -12; y <= 12; ++y)
        for (int x = -12; x <= 12; ++x) {
            double s = 0.0;
            if (mod3(x - y) == 0) {  // a point of the first round's lattice, relaxed
                s = 2.0 / 3.0 * round1(x, y);
                for (const LatticePoint &u : round1Neighbours)
                    s += round1(x + u.i, y + u.j) / 18.0;
            } else {  // centroid of a first-round triangle: its three first-round vertices
                for (const LatticePoint &u : unit)
                    if (mod3(x + u.i - y - u.j) == 0)
                        s += round1(x + u.i, y + u.j) / 3.0;
            }
            if (std::abs(s) > 1e-15)
                mask[{x, y}] = s;
        }
    return LatticeScheme(coreTranslate("awb::schemes", "Kobbelt √3 (two rounds)"),
                         Lattice::Triangular, 3, std::move(mask));
}

} // namespace awb
