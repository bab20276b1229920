#pragma once
// Certified Hölder regularity of a curve subdivision scheme (layer 1, no Qt): an interval
// [lower, upper] for r = n + alpha (the limit curves are C^n with an alpha-Hölder n-th
// derivative) from certified bounds on a joint spectral radius (JointSpectralRadius.h).
//
// Masks (uniform schemes of arity N, symbol a(z) = sum_k a_k z^k, a(1) = N): let
// sigma(z) = 1 + z + .. + z^{N-1} and n the largest power with sigma^n | a (n sum rules; none
// means no difference scheme: the scheme cannot converge). The n-th divided-difference scheme
// has the mask a_n(z) = N^n a(z) / sigma(z)^n; with T_0..T_{N-1} its transition matrices on
// the invariant support (Daubechies & Lagarias 1992: (T_e)_{ij} = a_n[N i + e - j],
// i, j = 0..L-1, L = ceil(s / (N-1)) for a mask of length s + 1), and rho_n their JSR,
//     r = n - log_N rho_n                                       (Rioul 1992, Thm. 5.1;
// Daubechies & Lagarias 1992; Jungers 2009, Ch. 4; Dyn & Levin 2002, §4 for the difference
// schemes). A lower bound on r needs an upper bound on rho_n and holds for every scheme: the
// n-th differences of the refined polygons decay like rho_n^k / N^{nk}. The upper bound on r
// (from a lower bound on rho_n, and r <= n) is the exact Hölder exponent when the integer
// shifts of the basic limit function are stable (B-splines, interpolatory schemes such as the
// four-point scheme); `notes` says so when that is not known for the mask.
//
// IFS matrices S_1..S_p (user matrices, end-interpolating B-splines): in the p-adic
// parametrisation of the attractor, the S_i act on the control vectors of the polynomials of
// degree < n that the scheme generates; the quotient maps on the complement play the role of
// the T_e (Micchelli & Prautzsch 1989). Bézier curves are polynomials: C^infinity.

#include "core/analysis/InvariantPolytope.h"
#include "core/analysis/JointSpectralRadius.h"

#include <memory>
#include <optional>

namespace awb {

class CurveScheme;

struct RegularityOptions {
    double timeBudget = 2.0;                    // seconds of wall time for the JSR
    // Seconds for the invariant polytope algorithm (InvariantPolytope.h), run after the bounds
    // on the same matrices; 0 skips it, negative means half of timeBudget (so a caller's time
    // grows by at most half). When it closes, rho_n is exact (a certificate).
    double polytopeBudget = -1.0;
    // A budget of work instead of time (0: time only): the branch and bound stops after this
    // many products and the polytope at `maxPolytopeVertices`, both run once, so the bounds are
    // the same on every machine. timeBudget then only guards against a runaway evaluation
    // (jsr.timedOut says it fired, and the result is no longer reproducible).
    long long maxProducts = 0;
    int maxPolytopeVertices = 2000;
    const std::atomic<bool> *cancel = nullptr;  // set from another thread to stop early
    // The current bounds (regularity and JSR) and the fraction of the budget spent.
    std::function<void(double lower, double upper, double fraction)> progress;
};

struct Regularity {
    // False when the analysis does not apply (no difference scheme, a complex parameter, no
    // joined pieces, ...): `message` says why.
    bool applies = false;
    bool infinite = false;     // C^infinity (a single polynomial piece); lower = upper = inf
    bool convergent = false;   // certified: lower > 0
    bool divergent = false;    // certified: the first difference scheme does not contract
    double lower = 0.0;        // certified lower bound on r
    double upper = 0.0;        // upper bound on r (see `notes`)
    int sumRules = 0;          // n: sigma^n divides the symbol (masks); polynomial degree + 1
    int arity = 2;             // N
    int smoothness = -1;       // the certified class C^smoothness; -1 when none
    std::string method;        // how the bounds were obtained, with references
    std::string message;       // why it does not apply, or a short verdict
    std::string notes;         // caveats (stability assumption, budget spent, ...)
    JsrBounds jsr;             // the bounds on rho_n (the polytope's when exact)
    // rho_n is exact: an invariant polytope closed, lower/upper are its certified values
    // (width ~1e-12 relative), `smp` the spectrum maximizing product (indices into
    // `transition`), `certificate` re-checkable by verifyPolytopeCertificate.
    bool exact = false;
    std::vector<int> smp;
    std::shared_ptr<const PolytopeCertificate> certificate;
    std::string polytopeNote;  // the polytope algorithm's verdict (closed, did not close, n/a)
    std::vector<Mat> transition;  // T_0..T_{N-1} (or the quotient maps) whose JSR was bounded
    // Masks: the Sobolev exponent s_2 of the basic limit function (sobolevRegularity in
    // Sobolev.h: exact for stable shifts, a lower bound otherwise), when that applies. The
    // exact exponents obey s_2 - 1/2 <= Hölder exponent <= s_2.
    std::optional<double> sobolev;
    double seconds = 0.0;

    double width() const { return upper - lower; }
    // "C^2", "C^infinity", "not convergent", "C^0 not certified", or "n/a".
    std::string smoothnessLabel() const;
};

// The mask without its leading and trailing zeros (below 1e-15 of its l1 norm).
// The verdict on "C^k" from certified bounds [lower, upper] on the Hölder exponent: +1
// certified (lower > k), -1 certified not (upper < k, or no member: applies false), 0 the
// bounds cannot tell (r = k, or too close within the budget). regularity-interval and the
// regularity atlas decide with it.
int smoothnessVerdict(bool applies, double lower, double upper, int k);

std::vector<double> trimmedMask(std::vector<double> mask);
// InputError unless arity >= 2 and every coefficient is finite (the mask analyses' input).
void requireMask(const std::vector<double> &mask, int arity);

// Largest n with sigma^n | a and the quotient mask a_n = N^n a / sigma^n (coefficients from
// the same start index as a; remainders below 1e-12 of the mask's size count as zero).
struct DifferenceMask {
    int order = 0;
    std::vector<double> mask;
};
DifferenceMask dividedDifferenceMask(const std::vector<double> &mask, int arity, int maxOrder = 64);

// Daubechies-Lagarias transition matrices T_0..T_{N-1} (L x L) of a mask c_0..c_s.
std::vector<Mat> transitionMatrices(const std::vector<double> &mask, int arity);

// The mask a_k (k from any start; only the coefficients matter) of arity N >= 2.
Regularity maskRegularity(const std::vector<double> &mask, int arity,
                          const RegularityOptions &options = {});
// S_1..S_p, all m x m with rows summing to 1, in curve order.
Regularity matrixRegularity(const std::vector<Mat> &S, const RegularityOptions &options = {});
// Dispatches on the scheme: UniformScheme -> its mask, BezierScheme -> C^infinity, other
// schemes -> their matrices for m control points.
Regularity schemeRegularity(const CurveScheme &scheme, int controlPoints,
                            const RegularityOptions &options = {});

} // namespace awb
