#include "core/schemes/Curves.h"

#include "core/Messages.h"

#include <algorithm>
#include <cmath>

namespace awb {

namespace {
double binomial(int n, int k)
{
    if (k < 0 || k > n)
        return 0.0;
    double r = 1.0;
    for (int i = 1; i <= k; ++i)
        r = r * (n - k + i) / i;
    return r;
}

template<class T>
T bernsteinT(int n, int i, T t)
{
    if (i < 0 || i > n)
        return T(0);
    return T(binomial(n, i)) * std::pow(t, i) * std::pow(T(1) - t, n - i);
}

template<class M, class T>
M deCasteljauLT(int n, T t)
{
    if (n < 1)
        throw InputError(coreTranslate("awb::schemes", "Bézier degree must be at least 1"));
    M L = M::Zero(n + 1, n + 1);
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= k; ++j)
            L(k, j) = bernsteinT<T>(k, j, t);
    return L;
}

template<class M, class T>
M deCasteljauRT(int n, T t)
{
    if (n < 1)
        throw InputError(coreTranslate("awb::schemes", "Bézier degree must be at least 1"));
    // r_k = sum_{j=k}^{n} B_{j-k}^{n-k}(t) p_j : the points on the right edge of the triangle.
    M R = M::Zero(n + 1, n + 1);
    for (int k = 0; k <= n; ++k)
        for (int j = k; j <= n; ++j)
            R(k, j) = bernsteinT<T>(n - k, j - k, t);
    return R;
}
} // namespace

double bernstein(int n, int i, double t) { return bernsteinT<double>(n, i, t); }
Complex bernstein(int n, int i, Complex t) { return bernsteinT<Complex>(n, i, t); }

Mat deCasteljauL(int n, double t) { return deCasteljauLT<Mat, double>(n, t); }
Mat deCasteljauR(int n, double t) { return deCasteljauRT<Mat, double>(n, t); }
CMat deCasteljauL(int n, Complex t) { return deCasteljauLT<CMat, Complex>(n, t); }
CMat deCasteljauR(int n, Complex t) { return deCasteljauRT<CMat, Complex>(n, t); }

Mat bezierPoints(const Mat &P, const std::vector<double> &params)
{
    const int n = int(P.rows()) - 1;
    Mat out(params.size(), P.cols());
    Mat work;
    for (size_t s = 0; s < params.size(); ++s) {
        const double t = params[s];
        work = P;
        for (int r = 1; r <= n; ++r)
            for (int i = 0; i <= n - r; ++i)
                work.row(i) = (1.0 - t) * work.row(i) + t * work.row(i + 1);
        out.row(s) = work.row(0);
    }
    return out;
}

CVec bezierPoints(const CVec &P, const std::vector<Complex> &params)
{
    const int n = int(P.size()) - 1;
    CVec out(params.size());
    std::vector<Complex> work(P.size());
    for (size_t s = 0; s < params.size(); ++s) {
        const Complex t = params[s];
        for (int i = 0; i <= n; ++i)
            work[i] = P(i);
        for (int r = 1; r <= n; ++r)
            for (int i = 0; i <= n - r; ++i)
                work[i] = (1.0 - t) * work[i] + t * work[i + 1];
        out(s) = work[0];
    }
    return out;
}

BSplineBasis::BSplineBasis(int degree, std::vector<double> knots)
    : m_degree(degree), m_knots(std::move(knots))
{
    if (degree < 1)
        throw InputError(coreTranslate("awb::schemes", "B-spline degree must be at least 1"));
    if (controlPointCount() < degree + 1)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "a B-spline of degree %1 needs at least %2 control "
                                          "points (%3 knots), got %4 knots"),
            degree, degree + 1, 2 * degree, m_knots.size()));
    for (size_t i = 0; i < m_knots.size(); ++i) {
        if (!std::isfinite(m_knots[i]))
            throw InputError(formatMessage(
                coreTranslate("awb::schemes", "B-spline knot %1 is not a finite number"), i));
        if (i > 0 && m_knots[i] < m_knots[i - 1])
            throw InputError(formatMessage(
                coreTranslate("awb::schemes", "B-spline knots must be nondecreasing (knot %1)"),
                i));
    }
    if (!(domainEnd() > domainStart()))
        throw InputError(
            coreTranslate("awb::schemes", "B-spline knot vector has an empty domain"));
}

BSplineBasis BSplineBasis::uniform(int degree, int m)
{
    std::vector<double> t(m + degree - 1);
    for (size_t i = 0; i < t.size(); ++i)
        t[i] = double(i);
    return BSplineBasis(degree, t);
}

BSplineBasis BSplineBasis::endInterpolating(int degree, int m)
{
    const int N = m - degree;
    if (N < 1)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "an end-interpolating B-spline of degree %1 needs at "
                                          "least %2 control points"),
            degree, degree + 1));
    std::vector<double> t;
    for (int i = 0; i < degree; ++i)
        t.push_back(0.0);
    for (int i = 1; i < N; ++i)
        t.push_back(double(i));
    for (int i = 0; i < degree; ++i)
        t.push_back(double(N));
    return BSplineBasis(degree, t);
}

RowVec BSplineBasis::blossomWeights(const std::vector<double> &u, int J) const
{
    const int n = m_degree;
    const int m = controlPointCount();
    // Control points P_{J-n+1} .. P_{J+1} carry the piece on [t_J, t_{J+1}].
    // d[i] holds weights (over all m points) of f(u_1..u_r, t_i, .., t_{i+n-1-r}).
    std::vector<RowVec> d(n + 1);
    for (int k = 0; k <= n; ++k) {
        d[k] = RowVec::Zero(m);
        d[k](J - n + 1 + k) = 1.0;
    }
    const auto &t = m_knots;
    for (int r = 1; r <= n; ++r) {
        for (int k = n; k >= r; --k) {
            const int i = J - n + 1 + k;
            const double lo = t[i - 1], hi = t[i + n - r];
            const double a = (u[r - 1] - lo) / (hi - lo);
            d[k] = (1.0 - a) * d[k - 1] + a * d[k];
        }
    }
    return d[n];
}

int BSplineBasis::spanOf(double x) const
{
    const int n = m_degree;
    const int m = controlPointCount();
    for (int J = n - 1; J <= m - 2; ++J)
        if (m_knots[J] < m_knots[J + 1] && x < m_knots[J + 1])
            return J;
    for (int J = m - 2; J >= n - 1; --J)
        if (m_knots[J] < m_knots[J + 1])
            return J;
    return n - 1;
}

RowVec BSplineBasis::pointWeights(double x) const
{
    return blossomWeights(std::vector<double>(m_degree, x), spanOf(x));
}

Mat BSplineBasis::insertionMatrix(const std::vector<double> &finer) const
{
    const int n = m_degree;
    const int mFine = int(finer.size()) - n + 1;
    Mat K(mFine, controlPointCount());
    for (int i = 0; i < mFine; ++i) {
        std::vector<double> u(finer.begin() + i, finer.begin() + i + n);
        // Any nondegenerate fine span touched by the window [tau_{i-1}, tau_{i+n}] gives the
        // same blossom value; take the one nearest the middle of the window and map it to the
        // coarse span that contains it.
        const double mid = 0.5 * (u.front() + u.back());
        double a = mid, b = mid;
        if (u.front() == u.back()) {
            const double lo = i > 0 ? finer[i - 1] : u.front();
            const double hi = i + n < int(finer.size()) ? finer[i + n] : u.back();
            a = std::max(lo, domainStart());
            b = std::min(hi, domainEnd());
        }
        double x = 0.5 * (a + b);
        x = std::clamp(x, domainStart(), domainEnd());
        K.row(i) = blossomWeights(u, spanOf(x));
    }
    return K;
}

std::vector<Mat> BSplineBasis::bezierPieces(const Mat &P) const
{
    if (P.rows() != controlPointCount())
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "B-spline needs %1 control points, got %2"),
            controlPointCount(), P.rows()));
    const int n = m_degree;
    std::vector<Mat> pieces;
    for (int J = n - 1; J + 1 <= controlPointCount() - 1; ++J) {
        const double a = m_knots[std::size_t(J)], b = m_knots[std::size_t(J + 1)];
        if (!(b > a))
            continue;
        Mat Q(n + 1, P.cols());
        for (int k = 0; k <= n; ++k) {
            std::vector<double> u(std::size_t(n), a);
            std::fill(u.begin() + (n - k), u.end(), b);
            Q.row(k) = blossomWeights(u, J) * P;
        }
        pieces.push_back(Q);
    }
    return pieces;
}

Mat BSplineBasis::curve(const Mat &P, int samples) const
{
    if (P.rows() != controlPointCount())
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "B-spline needs %1 control points, got %2"),
            controlPointCount(), P.rows()));
    Mat out(samples, P.cols());
    for (int s = 0; s < samples; ++s) {
        const double x = domainStart()
                         + (domainEnd() - domainStart()) * s / std::max(1, samples - 1);
        out.row(s) = pointWeights(x) * P;
    }
    return out;
}

} // namespace awb
