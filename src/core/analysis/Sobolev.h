#pragma once
// Sobolev (L^2) regularity of the basic limit function of a uniform curve scheme (layer 1, no
// Qt): s_2 = sup{s : phi in H^s(R)} from the spectral radius of one matrix, the transition
// operator of the mask's autocorrelation restricted to an invariant subspace. Exact linear
// algebra up to rounding (no joint spectral radius, no time budget).
//
// Mask a_k of arity N (refinement equation phi(x) = sum_k a_k phi(N x - k), sum_k a_k = N, each
// of the N cosets summing to 1), n sum rules (sigma^n | a, sigma(z) = 1 + z + .. + z^{N-1}):
// - phi^(xi) = m(xi / N) phi^(xi / N) with m(xi) = (1/N) sum_k a_k e^{-i k xi}, m(0) = 1, so
//   the autocorrelation Phi(x) = int phi(y) phi(y - x) dy (Phi^ = |phi^|^2) is refinable with
//   |m|^2 = (1/N) sum_k b_k e^{-i k xi}:  b_k = (1/N) sum_j a_j a_{j+k}, sum_k b_k = N,
//   b_{-k} = b_k, and sigma^{2n} divides b, exactly (a's cofactor a / sigma^n is nonzero at
//   some root w of sigma, and b's cofactor is its squared modulus there);
// - the transition operator (T v)_i = sum_j b_{N i - j} v_j on i, j in [-L, L], L =
//   ceil(s / (N - 1)) for a mask of length s + 1 (b lives on [-s, s]; T maps the sequences on
//   [-L, L] into themselves and every eigenvector of a nonzero eigenvalue lives there);
// - the sum rules make the moment functionals v -> sum_j j^k v_j, k < 2n, a left-invariant
//   flag of T (eigenvalues N^-k), so V = {v : sum_j p(j) v_j = 0 for deg p < 2n}, i.e. the
//   sequences (1 - z)^{2n} w(z), is invariant; rho = the spectral radius of T on V (computed
//   on V, not by discarding values N^-k from T's spectrum: they can also be V's own, as for
//   every B-spline, where rho = N^-(2n-1));
// - s_2 = -log_N(rho) / 2                (Eirola 1992, Villemoes 1994 for N = 2; Jia 1999,
//   Trans. AMS 351, for dilation N; Cohen & Daubechies 1996). The formula is exact when the
//   integer shifts of phi are stable (B-splines; orthonormal shifts such as Daubechies'
//   scaling functions; interpolatory masks with a continuous phi, whose shifts are linearly
//   independent) and a lower bound otherwise (Ron & Shen 2000, J. Approx. Theory 106: then the
//   exact value needs a larger subspace and the bound may be far off). With stable shifts
//   s_2 <= n (Phi is then C^{2 s_2} and stable, so it cannot be smoother than its 2n sum rules
//   allow), and the value is capped at n (`capped`).
//
// Checks: for the B-spline of degree d (mask (1 + z)^{d+1} / 2^d) V is one-dimensional and
// rho = 2^-(2d+1), s_2 = d + 1/2; Phi of Daubechies' D4 is the four-point scheme's phi, whose
// Hölder exponent 2 = 2 s_2(D4) (tests/core/test_sobolev.cpp).

#include "core/Types.h"

#include <string>
#include <vector>

namespace awb {

struct SobolevRegularity {
    // False when the formula does not apply (no sum rule, a mask not summing to N): `message`
    // says why.
    bool applies = false;
    double exponent = 0.0;    // s_2 = -log_N(rho) / 2, capped at sumRules
    double rho = 0.0;         // spectral radius of T on V
    double margin = 0.0;      // estimated rounding error of `exponent` (see sobolevRegularity)
    bool capped = false;      // -log_N(rho) / 2 exceeded sumRules (or rho == 0)
    int sumRules = 0;         // n: sigma^n divides the symbol
    int arity = 2;            // N
    std::vector<double> autocorrelation;  // b_{-s} .. b_s
    Mat transition;           // T on [-L, L] ((2L + 1) x (2L + 1))
    std::vector<Complex> values;  // the eigenvalues of T on V, largest modulus first
    std::string method;       // the formula and its references
    std::string message;      // why it does not apply, or a short verdict
    double seconds = 0.0;
};

// The mask a_k (k from any start; only the coefficients matter) of arity N >= 2 (InputError for
// N < 2 or a coefficient that is not finite). `margin` is a first-order estimate: the
// eigenvalue's condition number (from its left and right eigenvectors; sqrt of the error for a
// defective one) times 64 eps ||T||_F plus the residual of T U = U (U^T T U) on the orthonormal
// basis U of V, turned into an error on -log_N(rho) / 2.
SobolevRegularity sobolevRegularity(const std::vector<double> &mask, int arity);

} // namespace awb
