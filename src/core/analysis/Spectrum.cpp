#include "core/analysis/Spectrum.h"

#include "core/Decompositions.h"
#include "core/Messages.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <sstream>

namespace awb {

namespace {

Spectrum fromSolver(const CVec &vals, const CMat &vecs, double tol)
{
    const Eigen::Index n = vals.size();
    std::vector<Eigen::Index> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
        const double ma = std::abs(vals(a)), mb = std::abs(vals(b));
        if (std::abs(ma - mb) > 1e-12 * std::max(1.0, ma))
            return ma > mb;
        if (std::abs(vals(a).real() - vals(b).real()) > 1e-12)
            return vals(a).real() > vals(b).real();
        return vals(a).imag() > vals(b).imag();
    });
    Spectrum s;
    for (Eigen::Index k : order) {
        s.values.push_back(vals(k));
        CVec v = vecs.col(k);
        const double nv = v.norm();
        if (nv > 0)
            v /= nv;
        s.vectors.push_back(v);
    }
    // Cluster: values within tol (relative) of each other are one eigenvalue with multiplicity.
    s.multiplicity.assign(s.values.size(), 1);
    for (size_t i = 0; i < s.values.size(); ++i) {
        int count = 0;
        Complex mean = 0;
        for (size_t j = 0; j < s.values.size(); ++j)
            if (std::abs(s.values[i] - s.values[j]) <= tol * std::max(1.0, std::abs(s.values[i]))) {
                ++count;
                mean += s.values[j];
            }
        s.multiplicity[i] = count;
    }
    // Replace each cluster's members by the cluster mean: a defective eigenvalue's perturbed
    // copies (error ~ sqrt(eps)) average back to full accuracy.
    std::vector<Complex> snapped = s.values;
    for (size_t i = 0; i < s.values.size(); ++i) {
        if (s.multiplicity[i] < 2)
            continue;
        Complex mean = 0;
        int count = 0;
        for (size_t j = 0; j < s.values.size(); ++j)
            if (std::abs(s.values[i] - s.values[j]) <= tol * std::max(1.0, std::abs(s.values[i]))) {
                mean += s.values[j];
                ++count;
            }
        snapped[i] = mean / double(count);
    }
    s.values = snapped;
    for (auto &v : s.values) {
        // Real eigenvalues of real matrices come with +-1e-17 imaginary noise.
        if (std::abs(v.imag()) < 1e-13 * std::max(1.0, std::abs(v)))
            v = Complex(v.real(), 0.0);
    }
    s.spectralRadius = s.values.empty() ? 0.0 : std::abs(s.values.front());
    return s;
}

} // namespace

Spectrum spectrum(const Mat &M, double tol)
{
    if (M.rows() != M.cols())
        throw InputError(coreTranslate("awb::analysis", "eigenvalues need a square matrix"));
    requireFinite(M, coreTranslate("awb::analysis", "matrix"));
    if (M.rows() == 0)
        return {};
    Eigen::EigenSolver<Mat> es(M, true);
    if (es.info() != Eigen::Success)
        throw InputError(coreTranslate("awb::analysis", "the eigenvalue computation did not "
                                                        "converge"));
    return fromSolver(es.eigenvalues(), es.eigenvectors(), tol);
}

Spectrum spectrum(const CMat &M, double tol)
{
    if (M.rows() != M.cols())
        throw InputError(coreTranslate("awb::analysis", "eigenvalues need a square matrix"));
    requireFinite(M, coreTranslate("awb::analysis", "matrix"));
    if (M.rows() == 0)
        return {};
    Eigen::ComplexEigenSolver<CMat> es(M, true);
    if (es.info() != Eigen::Success)
        throw InputError(coreTranslate("awb::analysis", "the eigenvalue computation did not "
                                                        "converge"));
    return fromSolver(es.eigenvalues(), es.eigenvectors(), tol);
}

std::string toString(SubdominantKind kind)
{
    switch (kind) {
    case SubdominantKind::None: return "none";
    case SubdominantKind::RealPositive: return "real positive";
    case SubdominantKind::RealNegative: return "real negative";
    case SubdominantKind::ComplexPair: return "complex pair";
    case SubdominantKind::Complex: return "complex";
    case SubdominantKind::Mixed: return "mixed";
    }
    return "none";
}

std::string Subdominant::meaning() const
{
    switch (kind) {
    case SubdominantKind::None:
        return coreTranslate("awb::analysis", "no subdominant eigenvalue (the map is constant)");
    case SubdominantKind::RealPositive:
        return multiplicity == 1
                   ? coreTranslate("awb::analysis", "real positive: the curve has a half-tangent "
                                                    "at the fixed point, along the eigenvector "
                                                    "(G1 where the two sides' eigenvectors "
                                                    "align)")
                   : coreTranslate("awb::analysis", "real positive but repeated: the tangent "
                                                    "direction at the fixed point depends on the "
                                                    "control points");
    case SubdominantKind::RealNegative:
        return coreTranslate("awb::analysis", "real negative: the curve oscillates at the fixed "
                                              "point and has no tangent there");
    case SubdominantKind::ComplexPair:
        return coreTranslate("awb::analysis", "complex pair: the curve spirals around the fixed "
                                              "point (no tangent)");
    case SubdominantKind::Complex:
        return coreTranslate("awb::analysis", "complex: near the fixed point the map acts as the "
                                              "spiral similarity z -> lambda z, so the curve "
                                              "spirals around the fixed point (no tangent)");
    case SubdominantKind::Mixed:
        return coreTranslate("awb::analysis", "several eigenvalues of the same modulus with "
                                              "different signs or phases: no single tangent "
                                              "behaviour");
    }
    return {};
}

Subdominant subdominant(const Spectrum &s, bool dominantIsOne, double tol)
{
    Subdominant out;
    std::vector<size_t> rest(s.values.size());
    std::iota(rest.begin(), rest.end(), 0);
    if (dominantIsOne && !rest.empty()) {
        // Remove one eigenvalue closest to 1.
        auto it = std::min_element(rest.begin(), rest.end(), [&](size_t a, size_t b) {
            return std::abs(s.values[a] - 1.0) < std::abs(s.values[b] - 1.0);
        });
        rest.erase(it);
    }
    if (rest.empty())
        return out;
    double top = 0;
    for (size_t i : rest)
        top = std::max(top, std::abs(s.values[i]));
    if (top < 1e-14)
        return out;
    for (size_t i : rest)
        if (std::abs(std::abs(s.values[i]) - top) <= tol * std::max(1.0, top)) {
            out.values.push_back(s.values[i]);
            out.vectors.push_back(s.vectors[i]);
        }
    out.modulus = top;
    out.multiplicity = int(out.values.size());
    bool allPos = true, allNeg = true, anyComplex = false;
    for (const Complex &v : out.values) {
        const bool real = std::abs(v.imag()) <= tol * std::max(1.0, std::abs(v));
        anyComplex = anyComplex || !real;
        allPos = allPos && real && v.real() > 0;
        allNeg = allNeg && real && v.real() < 0;
    }
    if (allPos)
        out.kind = SubdominantKind::RealPositive;
    else if (allNeg)
        out.kind = SubdominantKind::RealNegative;
    else if (anyComplex && out.values.size() == 2
             && std::abs(out.values[0] - std::conj(out.values[1])) <= tol * std::max(1.0, top))
        out.kind = SubdominantKind::ComplexPair;
    else if (anyComplex
             && std::all_of(out.values.begin(), out.values.end(), [&](const Complex &v) {
                    return std::abs(v - out.values.front()) <= tol * std::max(1.0, top);
                }))
        out.kind = SubdominantKind::Complex;
    else
        out.kind = SubdominantKind::Mixed;
    return out;
}

namespace {
template<class M>
Contractivity contractivityT(const M &A)
{
    Contractivity c;
    if (A.rows() == 0) {
        c.eventuallyContractive = true;
        c.exponent = 1;
        return c;
    }
    c.spectralRadius = spectrum(A).spectralRadius;
    c.eventuallyContractive = c.spectralRadius < 1.0 - 1e-12;
    Eigen::JacobiSVD<M> svd(A);
    c.normFactor = svd.singularValues()(0);
    M power = A;
    for (int k = 1; k <= 200; ++k) {
        Eigen::JacobiSVD<M> s(power);
        if (s.singularValues()(0) < 1.0) {
            c.exponent = k;
            break;
        }
        power = (power * A).eval();
    }
    return c;
}
} // namespace

Contractivity contractivity(const Mat &A) { return contractivityT(A); }
Contractivity contractivity(const CMat &A) { return contractivityT(A); }

std::string Contractivity::verdict() const
{
    if (!eventuallyContractive)
        return formatMessage(
            coreTranslate("awb::analysis", "not contractive: spectral radius %1 >= 1"),
            streamedNumber(spectralRadius));
    if (normFactor < 1.0)
        return formatMessage(coreTranslate("awb::analysis", "contractive (factor ||A||_2 = %1)"),
                             streamedNumber(normFactor));
    if (exponent > 0)
        return formatMessage(coreTranslate("awb::analysis", "eventually contractive (spectral "
                                                            "radius %1 < 1; ||A^%2||_2 < 1)"),
                             streamedNumber(spectralRadius), exponent);
    return formatMessage(
        coreTranslate("awb::analysis", "eventually contractive (spectral radius %1 < 1)"),
        streamedNumber(spectralRadius));
}

std::optional<RowVec> fixedPoint(const Mat &A, const RowVec &b)
{
    const Eigen::Index n = A.rows();
    if (n == 0)
        return RowVec();
    const Mat IA = Mat::Identity(n, n) - A;
    Eigen::FullPivLU<Mat> lu(IA);
    lu.setThreshold(1e-12);
    if (!lu.isInvertible())
        return std::nullopt;
    // x (I - A) = b  <=>  (I - A)^T x^T = b^T
    const Vec x = IA.transpose().fullPivLu().solve(b.transpose());
    return RowVec(x.transpose());
}

std::optional<RowVec> fixedPoint(const AffineMap &f) { return fixedPoint(f.A, f.b); }

std::optional<RowVec> fixedWeights(const Mat &S)
{
    const Eigen::Index m = S.rows();
    if (m == 0 || S.cols() != m || !S.allFinite())
        return std::nullopt;
    // (S^T - I) l^T = 0 with 1^T l^T = 1: an (m+1) x m system, solved in least squares and
    // accepted when it holds (a repeated eigenvalue 1 leaves it rank deficient).
    Mat E(m + 1, m);
    E.topRows(m) = S.transpose() - Mat::Identity(m, m);
    E.row(m).setOnes();
    Vec rhs = Vec::Zero(m + 1);
    rhs(m) = 1.0;
    Eigen::ColPivHouseholderQR<Mat> qr(E);
    if (qr.rank() < m)
        return std::nullopt;
    const Vec l = qr.solve(rhs);
    if ((E * l - rhs).norm() > 1e-9 * std::max(1.0, S.norm()))
        return std::nullopt;
    return RowVec(l.transpose());
}

namespace {

// The linear part of `A` in the plane of `view`: Q with A V = V Q, when the plane coordinates
// of an image depend on the plane coordinates alone (a fractal with control points: the
// lifted map's plane block is x' = x A + b, decoupled from the lifting's coordinates).
std::optional<Mat> planeLinearPart(const Mat &A, const Projection &view)
{
    const Mat &V = view.V;
    if (V.rows() != A.rows() || V.cols() == 0 || V.cols() >= V.rows())
        return std::nullopt;
    Eigen::ColPivHouseholderQR<Mat> qr(V);
    if (qr.rank() < V.cols())
        return std::nullopt;
    const Mat AV = A * V;
    const Mat Q = qr.solve(AV);
    if ((V * Q - AV).norm() > 1e-9 * std::max(1.0, AV.norm()))
        return std::nullopt;
    return Q;
}

} // namespace

IfsCheck checkIfs(const Ifs &ifs)
{
    ifs.validate();
    IfsCheck out;
    for (int i = 0; i < ifs.size(); ++i) {
        out.maps.push_back(contractivity(ifs.effectiveLinearPart(i)));
        if (!out.contractive || out.maps.back().eventuallyContractive)
            continue;
        out.contractive = false;
        const double rho = out.maps.back().spectralRadius;
        // In a lifted space the user's map is the plane's: name its spectral radius when it
        // differs from the lifted one (x -> 1.5 x whose lifting scales by 2).
        const std::optional<Mat> plane =
            ifs.views.empty() ? std::nullopt : planeLinearPart(ifs.maps[size_t(i)].A,
                                                               ifs.views.front());
        const double planeRho = plane ? contractivity(*plane).spectralRadius : rho;
        if (plane && std::abs(planeRho - rho) > 1e-9 * std::max(1.0, rho)) {
            out.message = formatMessage(
                planeRho >= 1
                    ? coreTranslate("awb::analysis", "map %1 is not contractive: its map of the "
                                                     "plane has spectral radius %2 >= 1 (%3 in "
                                                     "the lifted space of its control points), "
                                                     "so the IFS has no attractor (the iteration "
                                                     "does not converge)")
                    : coreTranslate("awb::analysis", "map %1 is not contractive in the lifted "
                                                     "space of its control points (spectral "
                                                     "radius %3 >= 1), although its map of the "
                                                     "plane contracts (spectral radius %2): the "
                                                     "lifted iteration does not converge"),
                i + 1, streamedNumber(planeRho), streamedNumber(rho));
        } else {
            out.message = formatMessage(
                coreTranslate("awb::analysis", "map %1 is not contractive: the spectral radius "
                                               "of its linear part is %2 >= 1, so the IFS has no "
                                               "attractor (the iteration does not converge)"),
                i + 1, streamedNumber(rho));
        }
    }
    if (!out.contractive && ifs.size() > 0) {
        std::vector<Mat> linear;
        for (int i = 0; i < ifs.size(); ++i)
            linear.push_back(ifs.effectiveLinearPart(i));
        std::vector<double> cumulative;
        double total = 0;
        for (int i = 0; i < ifs.size(); ++i) {
            const double p = std::size_t(i) < ifs.probabilities.size() ? ifs.probabilities[i]
                             : ifs.probabilities.empty()                ? 1.0
                                                                        : 0.0;
            total += std::max(0.0, p);
            cumulative.push_back(total);
        }
        if (total > 0 && linear.front().rows() > 0) {
            RowVec v = RowVec::Ones(linear.front().rows()).normalized();
            std::uint64_t state = 0x2545f4914f6cdd1dull;
            double sum = 0;
            const int steps = 20000;
            for (int n = 0; n < steps; ++n) {
                state = state * 6364136223846793005ull + 1442695040888963407ull;
                const double u = double(state >> 11) * 0x1.0p-53 * total;
                std::size_t i = 0;
                while (i + 1 < cumulative.size() && u >= cumulative[i])
                    ++i;
                v = v * linear[i];
                const double norm = v.norm();
                if (!(norm > 0) || !std::isfinite(norm)) {  // a singular map: contracts
                    sum = -std::numeric_limits<double>::infinity();
                    break;
                }
                sum += std::log(norm);
                v /= norm;
            }
            out.lyapunov = std::isfinite(sum) ? sum / steps : -std::numeric_limits<double>::max();
            if (out.contractsOnAverage())
                out.message += formatMessage(
                    coreTranslate("awb::analysis", "; but the IFS contracts on average (Lyapunov "
                                                   "exponent %1 along the orbit): random "
                                                   "iteration draws its attractor"),
                    streamedNumber(*out.lyapunov));
        }
    }
    return out;
}

} // namespace awb
