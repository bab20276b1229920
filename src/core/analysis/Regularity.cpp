#include "core/analysis/Regularity.h"

#include "core/Decompositions.h"
#include "core/Messages.h"
#include "core/analysis/Sobolev.h"
#include "core/analysis/Spectrum.h"
#include "core/schemes/Scheme.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

namespace awb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

JsrOptions jsrOptions(const RegularityOptions &o, int arity, int order, bool quotientOnly)
{
    JsrOptions j;
    j.timeBudget = o.timeBudget;
    j.maxNodes = o.maxProducts;
    j.cancel = o.cancel;
    if (o.progress) {
        // rho -> r = n - log_N rho (masks) or -log_N rho (quotient maps).
        j.progress = [=](const JsrBounds &b, double fraction) {
            const double shift = quotientOnly ? 0.0 : double(order);
            const double lo = b.upper > 0 ? shift - std::log(b.upper) / std::log(double(arity))
                                          : double(order);
            const double hi = b.lower > 0 ? shift - std::log(b.lower) / std::log(double(arity))
                                          : double(order);
            o.progress(std::min(lo, double(order)), std::min(hi, double(order)), fraction);
        };
    }
    return j;
}

// Bounds on r from the bounds on rho: r = shift - log_N rho, both capped at `cap`.
void fillBounds(Regularity &r, double shift, double cap)
{
    const double logN = std::log(double(r.arity));
    r.lower = r.jsr.upper > 0 ? shift - std::log(r.jsr.upper) / logN : cap;
    r.upper = r.jsr.lower > 0 ? shift - std::log(r.jsr.lower) / logN : cap;
    r.lower = std::min(r.lower, cap);
    r.upper = std::min(r.upper, cap);
    r.convergent = r.lower > 0;
    r.divergent = r.upper <= 0;
    r.smoothness = r.convergent ? int(std::ceil(r.lower)) - 1 : -1;
    r.seconds = r.jsr.seconds;
    if (r.divergent)
        r.message = coreTranslate("awb::analysis", "not convergent: the first difference scheme "
                                                   "does not contract (JSR >= 1)");
    else if (!r.convergent)
        r.message = coreTranslate("awb::analysis", "convergence not certified within the time "
                                                   "budget");
    else
        r.message = formatMessage(
            coreTranslate("awb::analysis", "C^%1, Hölder regularity in [%2, %3]"), r.smoothness,
            streamedNumber(r.lower), streamedNumber(r.upper));
    std::string notes;
    // The budget notes concern the branch and bound: an exact value supersedes them.
    if (r.exact)
        notes += "";
    else if (r.jsr.cancelled)
        notes += coreTranslate("awb::analysis", "cancelled; the bounds are those reached. ");
    else if (r.jsr.timedOut)
        notes += coreTranslate("awb::analysis", "time budget spent; the bounds are those "
                                                "reached. ");
    else if (r.jsr.workSpent)
        notes += coreTranslate("awb::analysis", "work budget spent; the bounds are those "
                                                "reached. ");
    r.notes = notes + r.notes;
}

// After the bounds: the invariant polytope algorithm on the same matrices. Its certified
// bracket replaces the bounds when it closes (both are certified: the intersection is kept,
// and a disjoint pair, which would mean a bug, is refused).
void applyPolytope(Regularity &r, const RegularityOptions &o)
{
    const double budget = o.polytopeBudget < 0 ? 0.5 * o.timeBudget : o.polytopeBudget;
    if (budget <= 0 || r.jsr.cancelled || (o.cancel && o.cancel->load()))
        return;
    if (o.maxProducts > 0)
        return;  // by work: polytopeFirst already ran it to its vertex limit
    PolytopeOptions p;
    p.timeBudget = budget;
    p.maxVertices = o.maxPolytopeVertices;
    p.cancel = o.cancel;
    const PolytopeResult pr = invariantPolytope(r.transition, p);
    r.polytopeNote = pr.message;
    const double tol = 1e-9;
    if (!pr.closed || pr.lower > r.jsr.upper * (1 + tol) || pr.upper < r.jsr.lower * (1 - tol)) {
        if (pr.closed)
            r.polytopeNote = coreTranslate("awb::analysis", "the invariant polytope's bracket "
                                                            "contradicts the bounds; ignored");
        r.notes += r.polytopeNote + ". ";
        return;
    }
    r.exact = true;
    r.smp = pr.smp;
    r.certificate = pr.certificate;
    r.jsr.lower = std::max(r.jsr.lower, pr.lower);
    r.jsr.upper = std::max(r.jsr.lower, std::min(r.jsr.upper, pr.upper));
    r.jsr.product = pr.smp;
    r.jsr.converged = true;
    r.jsr.seconds += pr.seconds;
}

// The invariant polytope first, for a moment (it closes in milliseconds for the schemes of the
// literature): when it does, rho_n is exact and the branch and bound is not needed. Otherwise
// the bounds run, and the polytope gets the rest of its budget after them (applyPolytope).
bool polytopeFirst(Regularity &r, const RegularityOptions &o, int arity, double shift)
{
    const double budget = o.polytopeBudget < 0 ? 0.5 * o.timeBudget : o.polytopeBudget;
    if (budget <= 0 || (o.cancel && o.cancel->load()))
        return false;
    PolytopeOptions p;
    // By time: a moment first, the rest after the bounds. By work: once, to the vertex limit.
    p.timeBudget = o.maxProducts > 0 ? budget : std::min(0.2, budget);
    p.maxVertices = o.maxPolytopeVertices;
    p.cancel = o.cancel;
    const PolytopeResult pr = invariantPolytope(r.transition, p);
    if (!pr.closed)
        return false;
    r.polytopeNote = pr.message;
    r.exact = true;
    r.smp = pr.smp;
    r.certificate = pr.certificate;
    r.jsr = JsrBounds{};
    r.jsr.lower = pr.lower;
    r.jsr.upper = pr.upper;
    r.jsr.product = pr.smp;
    r.jsr.norm = "invariant polytope";
    r.jsr.converged = true;
    r.jsr.seconds = pr.seconds;
    if (o.progress && pr.upper > 0 && pr.lower > 0) {
        const double logN = std::log(double(arity));
        o.progress(shift - std::log(pr.upper) / logN, shift - std::log(pr.lower) / logN, 1.0);
    }
    return true;
}

std::string polytopeSummary(const Regularity &r)
{
    if (!r.exact)
        return {};
    std::string smp;
    for (size_t k = 0; k < r.smp.size(); ++k)
        smp += (k ? " T_" : "T_") + std::to_string(r.smp[k]);
    return formatMessage(coreTranslate("awb::analysis",
                                       "; exact by the invariant polytope algorithm (Guglielmi & "
                                       "Protasov 2013): s.m.p. (%1), %2 vertices"),
                         smp, r.certificate->vertices.size());
}

std::string jsrSummary(const JsrBounds &b, int count, Eigen::Index size)
{
    std::string s = formatMessage(coreTranslate("awb::analysis", "JSR of %1 matrices %2 x %2"),
                                  count, size);
    if (b.norm == "invariant polytope")
        return s;  // polytopeSummary says how
    s += formatMessage(coreTranslate("awb::analysis", ": lower bound max rho(product)^(1/k) "
                                                      "over all products up to length %1"),
                       b.enumerated);
    if (b.depth > b.enumerated)
        s += formatMessage(
            coreTranslate("awb::analysis", " and the branch's products up to length %1"),
            b.depth);
    s += formatMessage(b.depth > 0
                           ? coreTranslate("awb::analysis", ", upper bound by Gripenberg's "
                                                            "branch and bound (1996) in the %1")
                           : coreTranslate("awb::analysis", ", upper bound in the %1"),
                       b.norm);
    if (b.converged)
        s += coreTranslate("awb::analysis", " (equal to the lower bound)");
    s += formatMessage(coreTranslate("awb::analysis", ", %1 products"), b.nodes);
    return s;
}

} // namespace

std::string Regularity::smoothnessLabel() const
{
    if (!applies)
        return "n/a";
    if (infinite)
        return "C^infinity";
    if (divergent)
        return coreTranslate("awb::analysis", "not convergent");
    if (smoothness < 0)
        return coreTranslate("awb::analysis", "C^0 not certified");
    return "C^" + std::to_string(smoothness);
}

int smoothnessVerdict(bool applies, double lower, double upper, int k)
{
    if (!applies || upper < k)
        return -1;
    return lower > k ? 1 : 0;
}

std::vector<double> trimmedMask(std::vector<double> c)
{
    const double scale = std::accumulate(c.begin(), c.end(), 0.0,
                                         [](double s, double v) { return s + std::abs(v); });
    auto tiny = [&](double v) { return std::abs(v) <= 1e-15 * scale; };
    while (!c.empty() && tiny(c.back()))
        c.pop_back();
    auto first = std::find_if_not(c.begin(), c.end(), tiny);
    c.erase(c.begin(), first);
    return c;
}

DifferenceMask dividedDifferenceMask(const std::vector<double> &mask, int arity, int maxOrder)
{
    DifferenceMask out{0, trimmedMask(mask)};
    const int N = arity;
    while (out.order < maxOrder && int(out.mask.size()) >= N) {
        const std::vector<double> &p = out.mask;
        const int s = int(p.size()) - 1;
        double scale = 0.0;
        for (double v : p)
            scale += std::abs(v);
        // Long division by sigma(z) = 1 + z + .. + z^{N-1}, from the top coefficient.
        std::vector<double> r = p, q(size_t(s - N + 2), 0.0);
        for (int k = s; k >= N - 1; --k) {
            const double c = r[size_t(k)];
            q[size_t(k - N + 1)] = c;
            for (int j = 0; j < N; ++j)
                r[size_t(k - j)] -= c;
        }
        double rem = 0.0;
        for (int k = 0; k < N - 1; ++k)
            rem = std::max(rem, std::abs(r[size_t(k)]));
        if (rem > 1e-12 * scale)
            break;
        for (double &v : q)
            v *= N;
        out.mask = trimmedMask(q);
        ++out.order;
        if (out.mask.empty())
            break;
    }
    return out;
}

std::vector<Mat> transitionMatrices(const std::vector<double> &mask, int arity)
{
    const int N = arity;
    const int s = int(mask.size()) - 1;
    const int L = std::max(1, (s + N - 2) / (N - 1));
    std::vector<Mat> T;
    for (int e = 0; e < N; ++e) {
        Mat M = Mat::Zero(L, L);
        for (int i = 0; i < L; ++i)
            for (int j = 0; j < L; ++j) {
                const int k = N * i + e - j;
                if (k >= 0 && k <= s)
                    M(i, j) = mask[size_t(k)];
            }
        T.push_back(M);
    }
    return T;
}

void requireMask(const std::vector<double> &mask, int arity)
{
    if (arity < 2)
        throw InputError(formatMessage(
            coreTranslate("awb::analysis", "the arity of a scheme must be at least 2, got %1"),
            arity));
    for (double v : mask)
        if (!std::isfinite(v))
            throw InputError(coreTranslate("awb::analysis", "the mask has a coefficient that is "
                                                            "not a finite number"));
}

Regularity maskRegularity(const std::vector<double> &mask, int arity,
                          const RegularityOptions &options)
{
    requireMask(mask, arity);
    Regularity r;
    r.arity = arity;
    const std::vector<double> a = trimmedMask(mask);
    double sum = 0.0, abssum = 0.0;
    for (double v : a) {
        sum += v;
        abssum += std::abs(v);
    }
    if (a.empty()) {
        r.message = coreTranslate("awb::analysis", "no difference scheme: the mask is zero");
        return r;
    }
    // A mask typed in may be long; the transition matrices are about (length / (N - 1))
    // square, the Sobolev operator twice that. Past 48 the analysis would take minutes (and
    // the division by sigma loses its accuracy): say so instead.
    const size_t longest = 48 * size_t(arity - 1) + 1;
    if (a.size() > longest) {
        r.message = formatMessage(
            coreTranslate("awb::analysis", "not analysed: the mask has %1 coefficients, the "
                                           "regularity analysis takes at most %2 for arity %3 "
                                           "(transition matrices up to 48 x 48)"),
            a.size(), longest, arity);
        return r;
    }
    const DifferenceMask d = dividedDifferenceMask(a, arity);
    r.sumRules = d.order;
    if (d.order == 0) {
        r.message = formatMessage(
            coreTranslate("awb::analysis", "no difference scheme: the symbol a(z) has no factor "
                                           "1 + z%1 (the rules' weights do not each sum to 1), "
                                           "so the scheme does not reproduce constants and is "
                                           "not convergent"),
            arity > 2 ? " + .. + z^" + std::to_string(arity - 1) : std::string());
        return r;
    }
    if (std::abs(sum - arity) > 1e-12 * std::max(1.0, abssum)) {
        r.message = formatMessage(
            coreTranslate("awb::analysis", "not convergent: the mask sums to %1, not the arity "
                                           "%2 (the scheme does not reproduce constants)"),
            streamedNumber(sum), arity);
        r.applies = true;
        r.divergent = true;
        return r;
    }
    r.applies = true;
    r.transition = transitionMatrices(d.mask, arity);
    if (!polytopeFirst(r, options, arity, double(d.order))) {
        r.jsr = jointSpectralRadius(r.transition, jsrOptions(options, arity, d.order, false));
        applyPolytope(r, options);
    }
    // Stable integer shifts are known for interpolatory masks (phi(k) = delta_k) and for
    // B-spline-like masks a = N sigma^n / N^n (a_n has one coefficient).
    bool interpolatory = false;
    for (int e = 0; e < arity && !interpolatory; ++e) {
        int ones = 0, others = 0;
        for (size_t k = size_t(e); k < a.size(); k += size_t(arity)) {
            if (std::abs(a[k] - 1.0) < 1e-14)
                ++ones;
            else if (std::abs(a[k]) >= 1e-14)
                ++others;
        }
        interpolatory = ones == 1 && others == 0;
    }
    if (!interpolatory && d.mask.size() > 1)
        r.notes += coreTranslate("awb::analysis", "the upper bound is the exact Hölder "
                                                  "exponent only if the integer shifts of the "
                                                  "basic limit function are stable (not checked "
                                                  "for this mask). ");
    fillBounds(r, double(d.order), double(d.order));
    const std::string factor =
        arity == 2 ? std::string("1 + z") : "1 + .. + z^" + std::to_string(arity - 1);
    r.method = formatMessage(coreTranslate("awb::analysis",
                                           "r = n - log_%1 rho_n with n = %2 (a(z) has the "
                                           "factor (%3)^%2), rho_n the joint spectral radius of "
                                           "the transition matrices of the divided-difference "
                                           "mask of order %2 (Daubechies & Lagarias 1992, Rioul "
                                           "1992); %4%5"),
                             arity, d.order, factor,
                             jsrSummary(r.jsr, arity, r.transition.front().rows()),
                             polytopeSummary(r));
    if (const SobolevRegularity sob = sobolevRegularity(a, arity); sob.applies)
        r.sobolev = sob.exponent;
    return r;
}

Regularity matrixRegularity(const std::vector<Mat> &S, const RegularityOptions &options)
{
    if (S.size() < 2)
        throw InputError(coreTranslate("awb::analysis", "regularity needs at least two subdivision "
                                                        "matrices"));
    const Eigen::Index m = S.front().rows();
    for (size_t i = 0; i < S.size(); ++i) {
        if (S[i].rows() != m || S[i].cols() != m)
            throw InputError(coreTranslate("awb::analysis", "the subdivision matrices must all be "
                                                            "square and of one size"));
        requireFinite(S[i], formatMessage(coreTranslate("awb::analysis", "matrix S_%1"), i + 1));
    }
    Regularity r;
    const int N = int(S.size());
    r.arity = N;
    const Vec ones = Vec::Ones(m);
    for (size_t i = 0; i < S.size(); ++i)
        if ((S[i] * ones - ones).cwiseAbs().maxCoeff() > 1e-9) {
            r.message = formatMessage(coreTranslate("awb::analysis", "no difference scheme: the "
                                                                     "rows of S_%1 do not all "
                                                                     "sum to 1"),
                                      i + 1);
            return r;
        }
    // The curve is continuous only if piece i ends where piece i+1 starts.
    const auto first = fixedWeights(S.front());
    const auto last = fixedWeights(S.back());
    if (!first || !last) {
        r.message = coreTranslate("awb::analysis", "no regularity: S_1 or S_p has no simple "
                                                   "eigenvalue 1, so the curve's end points are "
                                                   "not defined");
        return r;
    }
    for (size_t i = 0; i + 1 < S.size(); ++i)
        if ((*last * S[i] - *first * S[i + 1]).cwiseAbs().maxCoeff() > 1e-9) {
            r.message = formatMessage(
                coreTranslate("awb::analysis", "no regularity: the pieces S_%1 and S_%2 do not "
                                               "join (the attractor is not a continuous curve in "
                                               "its %3-adic parameter)"),
                i + 1, i + 2, N);
            return r;
        }
    // Control vectors v_k of t^k: S_i v_k = N^-k sum_j C(k, j) i^(k-j) v_j (piece i is
    // t -> (t + i) / N).
    std::vector<Vec> v{ones};
    for (int k = 1; k < m; ++k) {
        Mat E(N * m, m);
        Vec rhs = Vec::Zero(N * m);
        for (int i = 0; i < N; ++i) {
            E.middleRows(i * m, m) = std::pow(double(N), k) * S[size_t(i)] - Mat::Identity(m, m);
            double binom = 1.0;
            for (int j = 0; j < k; ++j) {
                rhs.segment(i * m, m) += binom * std::pow(double(i), k - j) * v[size_t(j)];
                binom = binom * (k - j) / (j + 1);
            }
        }
        const Vec x = E.completeOrthogonalDecomposition().solve(rhs);
        if ((E * x - rhs).norm() > 1e-9 * std::max(1.0, rhs.norm()))
            break;
        v.push_back(x);
    }
    const int generated = int(v.size());
    // The pieces join C^(k) only if the k-th derivative at t = 1 of piece i equals that at
    // t = 0 of piece i+1: l1_k S_i = l0_k S_{i+1}, where l0_k (l1_k) is the functional with
    // l S_1 = N^-k l (l S_p = N^-k l) and l v_j = d^k/dt^k t^j at t = 0 (t = 1).
    int joined = generated;
    for (int k = 1; k < generated && joined == generated; ++k) {
        auto functional = [&](const Mat &Send, double t) -> std::optional<RowVec> {
            Mat E(m + generated, m);
            Vec rhs = Vec::Zero(m + generated);
            E.topRows(m) = (std::pow(double(N), k) * Send - Mat::Identity(m, m)).transpose();
            for (int j = 0; j < generated; ++j) {
                E.row(m + j) = v[size_t(j)].transpose();
                double d = j < k ? 0.0 : 1.0;
                for (int q = 0; q < k && j >= k; ++q)
                    d *= double(j - q);
                rhs(m + j) = d * (j >= k ? std::pow(t, j - k) : 0.0);
            }
            const Vec l = E.completeOrthogonalDecomposition().solve(rhs);
            if ((E * l - rhs).norm() > 1e-9 * std::max(1.0, rhs.norm()))
                return std::nullopt;
            return RowVec(l.transpose());
        };
        const auto l0 = functional(S.front(), 0.0), l1 = functional(S.back(), 1.0);
        if (!l0 || !l1) {
            joined = k;
            break;
        }
        for (size_t i = 0; i + 1 < S.size(); ++i)
            if ((*l1 * S[i] - *l0 * S[i + 1]).cwiseAbs().maxCoeff()
                > 1e-9 * std::max(1.0, l1->cwiseAbs().maxCoeff()))
                joined = k;
    }
    const int n = generated;
    r.sumRules = generated;
    r.applies = true;
    Mat V(m, n);
    for (int k = 0; k < n; ++k)
        V.col(k) = v[size_t(k)];
    Eigen::HouseholderQR<Mat> qr(V);
    const Mat Qfull = qr.householderQ() * Mat::Identity(m, m);
    const Mat U = Qfull.rightCols(m - n);
    if (m == n) {
        r.infinite = true;
        r.convergent = true;
        r.lower = r.upper = kInf;
        r.message = formatMessage(coreTranslate("awb::analysis", "C^infinity: the curve is one "
                                                                 "polynomial piece of degree %1"),
                                  n - 1);
        r.method = formatMessage(
            coreTranslate("awb::analysis", "the matrices reproduce every polynomial of degree < "
                                           "%1 in the %2-adic parameter and leave no complement"),
            n, N);
        return r;
    }
    for (const Mat &Si : S)
        r.transition.push_back(U.transpose() * Si * U);
    if (!polytopeFirst(r, options, N, 0.0)) {
        r.jsr = jointSpectralRadius(r.transition, jsrOptions(options, N, n, true));
        applyPolytope(r, options);
    }
    r.notes += coreTranslate("awb::analysis", "the upper bound assumes the curve's basis "
                                              "functions are stable. ");
    if (joined < generated)
        r.notes += formatMessage(coreTranslate("awb::analysis", "the pieces join only C^%1 "
                                                                "(derivative %2 differs across a "
                                                                "join). "),
                                 joined - 1, joined);
    fillBounds(r, 0.0, double(joined));
    r.method = formatMessage(coreTranslate("awb::analysis",
                                           "r = -log_%1 rho with rho the joint spectral radius "
                                           "of S_1..S_%1 on the quotient by the control vectors "
                                           "of the polynomials of degree < %2 that they "
                                           "generate (Micchelli & Prautzsch 1989); %3%4"),
                             N, n, jsrSummary(r.jsr, N, m - n), polytopeSummary(r));
    return r;
}

Regularity schemeRegularity(const CurveScheme &scheme, int controlPoints,
                            const RegularityOptions &options)
{
    if (const auto *u = dynamic_cast<const UniformScheme *>(&scheme))
        return maskRegularity(u->mask(), u->arity(), options);
    if (const auto *b = dynamic_cast<const BezierScheme *>(&scheme)) {
        Regularity r;
        r.applies = true;
        r.infinite = true;
        r.convergent = true;
        r.lower = r.upper = kInf;
        r.sumRules = b->degree() + 1;
        r.message = formatMessage(coreTranslate("awb::analysis", "C^infinity: a Bézier curve is "
                                                                 "a polynomial of degree %1"),
                                  b->degree());
        r.method = coreTranslate("awb::analysis", "de Casteljau subdivision reproduces the Bézier "
                                                  "polynomial exactly");
        return r;
    }
    return matrixRegularity(scheme.matrices(controlPoints).S, options);
}

} // namespace awb
