#include "core/analysis/Sobolev.h"

#include "core/Decompositions.h"
#include "core/Messages.h"
#include "core/analysis/Regularity.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

namespace awb {

namespace {

// An orthonormal basis (columns) of V = {(1 - z)^{2n} w(z)} inside the sequences on M indices.
Mat complementOfPolynomials(int M, int twoN)
{
    std::vector<double> d{1.0};   // coefficients of (1 - z)^{2n}
    for (int k = 0; k < twoN; ++k) {
        std::vector<double> next(d.size() + 1, 0.0);
        for (size_t i = 0; i < d.size(); ++i) {
            next[i] += d[i];
            next[i + 1] -= d[i];
        }
        d.swap(next);
    }
    const int dim = M - twoN;
    Mat W = Mat::Zero(M, dim);
    for (int m = 0; m < dim; ++m)
        for (size_t i = 0; i < d.size(); ++i)
            W(m + Eigen::Index(i), m) = d[i];
    Eigen::HouseholderQR<Mat> qr(W);
    return qr.householderQ() * Mat::Identity(M, dim);
}

} // namespace

SobolevRegularity sobolevRegularity(const std::vector<double> &mask, int arity)
{
    const auto start = std::chrono::steady_clock::now();
    requireMask(mask, arity);
    SobolevRegularity r;
    r.arity = arity;
    const int N = arity;
    const std::vector<double> a = trimmedMask(mask);
    if (a.empty()) {
        r.message = coreTranslate("awb::analysis", "no Sobolev exponent: the mask is zero");
        return r;
    }
    double sum = 0.0, abssum = 0.0;
    for (double v : a) {
        sum += v;
        abssum += std::abs(v);
    }
    const int n = dividedDifferenceMask(a, N).order;
    r.sumRules = n;
    if (n == 0) {
        r.message = coreTranslate("awb::analysis", "no Sobolev exponent: the symbol has no sum "
                                                   "rule (the rules' weights do not each sum "
                                                   "to 1), so the scheme does not converge");
        return r;
    }
    if (std::abs(sum - N) > 1e-12 * std::max(1.0, abssum)) {
        r.message = formatMessage(
            coreTranslate("awb::analysis", "no Sobolev exponent: the mask sums to %1, not the "
                                           "arity %2 (the refinement equation has no "
                                           "integrable solution with nonzero mean)"),
            streamedNumber(sum), N);
        return r;
    }
    // Autocorrelation b_k = (1/N) sum_j a_j a_{j+k}, k = -s..s.
    const int s = int(a.size()) - 1;
    r.autocorrelation.assign(size_t(2 * s + 1), 0.0);
    for (int k = -s; k <= s; ++k) {
        double c = 0.0;
        for (int j = std::max(0, -k); j <= std::min(s, s - k); ++j)
            c += a[size_t(j)] * a[size_t(j + k)];
        r.autocorrelation[size_t(k + s)] = c / N;
    }
    auto b = [&](int k) { return k < -s || k > s ? 0.0 : r.autocorrelation[size_t(k + s)]; };
    // Transition operator on [-L, L]; L >= n since s >= n (N - 1), so V is not empty.
    const int L = (s + N - 2) / (N - 1);
    const int M = 2 * L + 1;
    r.transition = Mat::Zero(M, M);
    for (int i = -L; i <= L; ++i)
        for (int j = -L; j <= L; ++j)
            r.transition(i + L, j + L) = b(N * i - j);
    const Mat U = complementOfPolynomials(M, 2 * n);
    const Mat TU = r.transition * U;
    const Mat R = U.transpose() * TU;
    const double residual = (TU - U * R).norm();
    Eigen::EigenSolver<Mat> right(R);
    const Mat Rt = R.transpose();
    Eigen::EigenSolver<Mat> left(Rt);
    const CVec lambda = right.eigenvalues();
    Eigen::Index top = 0;
    for (Eigen::Index i = 0; i < lambda.size(); ++i) {
        r.values.push_back(lambda(i));
        if (std::abs(lambda(i)) > std::abs(lambda(top)))
            top = i;
    }
    std::sort(r.values.begin(), r.values.end(), [](const Complex &x, const Complex &y) {
        if (std::abs(x) != std::abs(y))
            return std::abs(x) > std::abs(y);
        return x.real() != y.real() ? x.real() > y.real() : x.imag() > y.imag();
    });
    r.rho = std::abs(lambda(top));
    // Rounding margin: condition number of the top eigenvalue, 1 / |y^T x| for unit x, y.
    const CVec x = right.eigenvectors().col(top).normalized();
    const CVec lambdaLeft = left.eigenvalues();
    Eigen::Index match = 0;
    for (Eigen::Index i = 0; i < lambdaLeft.size(); ++i)
        if (std::abs(lambdaLeft(i) - lambda(top)) < std::abs(lambdaLeft(match) - lambda(top)))
            match = i;
    const CVec y = left.eigenvectors().col(match).normalized();
    const double overlap = std::abs((y.transpose() * x).value());
    const double eps = std::numeric_limits<double>::epsilon();
    const double delta = 64 * eps * r.transition.norm() + residual;
    const double drho = overlap > 1e-6 ? delta / overlap
                                       : std::sqrt(delta * std::max(R.norm(), eps));
    const double logN = std::log(double(N));
    r.applies = true;
    const double raw = r.rho > 0 ? -std::log(r.rho) / (2 * logN)
                                 : std::numeric_limits<double>::infinity();
    r.capped = raw > n;
    r.exponent = std::min(raw, double(n));
    r.margin = r.rho > drho ? std::log(r.rho / (r.rho - drho)) / (2 * logN)
                            : std::numeric_limits<double>::infinity();
    if (r.exponent <= r.margin)
        r.message = formatMessage(
            coreTranslate("awb::analysis", "no positive Sobolev smoothness: rho = %1 >= 1 (to "
                                           "rounding), so s_2 = %2 <= 0: with stable shifts the "
                                           "basic limit function is in no H^s with s > 0, if "
                                           "it is a function at all"),
            streamedNumber(r.rho), streamedNumber(r.exponent));
    else
        r.message = formatMessage(
            coreTranslate("awb::analysis", "Sobolev exponent s_2 = %1: in H^s for every s < %1"),
            streamedNumber(r.exponent));
    if (r.capped)
        r.message += formatMessage(coreTranslate("awb::analysis", " (capped at the %1 sum rules; "
                                                                  "-log_N(rho) / 2 = %2)"),
                                   n, streamedNumber(raw));
    r.method = formatMessage(
        coreTranslate("awb::analysis",
                      "s_2 = -log_%1(rho) / 2 with rho the spectral radius of the transition "
                      "operator (T v)_i = sum_j b_{%1i - j} v_j of the autocorrelation b_k = "
                      "(1/%1) sum_j a_j a_{j+k} on [-%2, %2], restricted to the %3-dimensional "
                      "invariant subspace orthogonal to the polynomials of degree < %4 (Eirola "
                      "1992, Villemoes 1994, Jia 1999); exact for stable integer shifts, a lower "
                      "bound otherwise (Ron & Shen 2000); rounding margin %5"),
        N, L, M - 2 * n, 2 * n, streamedNumber(r.margin));
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

} // namespace awb
