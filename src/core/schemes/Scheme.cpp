#include "core/schemes/Scheme.h"

#include "core/Messages.h"

#include <cmath>
#include <sstream>

namespace awb {

namespace {

std::vector<double> linspace(double a, double b, int n)
{
    std::vector<double> v(n);
    for (int i = 0; i < n; ++i)
        v[i] = a + (b - a) * i / std::max(1, n - 1);
    return v;
}
} // namespace

Mat SubdivisionMatrices::refinement() const
{
    const Eigen::Index m = S.front().rows();
    const Eigen::Index rows = m + Eigen::Index(S.size() - 1) * (m - overlap);
    Mat R(rows, S.front().cols());
    R.topRows(m) = S.front();
    for (size_t j = 1; j < S.size(); ++j)
        R.middleRows(m + Eigen::Index(j - 1) * (m - overlap), m - overlap) = S[j].bottomRows(m - overlap);
    return R;
}

std::optional<Mat> CurveScheme::exactCurve(const Mat &, int) const { return std::nullopt; }

std::optional<std::vector<Mat>> CurveScheme::bezierPieces(const Mat &) const
{
    return std::nullopt;
}

void CurveScheme::requireControlPointCount(int m) const
{
    if (m < minControlPoints() || m > maxControlPoints())
        throw InputError(formatMessage(
            minControlPoints() == maxControlPoints()
                ? coreTranslate("awb::schemes", "%1 needs exactly %2 control points, got %3")
                : coreTranslate("awb::schemes", "%1 needs at least %2 control points, got %3"),
            name(), minControlPoints(), m));
}

// ---------------------------------------------------------------------------------------------

UniformScheme::UniformScheme(std::string name, int arity, std::vector<SchemeRule> rules)
    : m_name(std::move(name)), m_arity(arity), m_rules(std::move(rules))
{
    if (arity < 2)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "%1: the arity of a scheme must be at least 2, got %2"),
            m_name, arity));
    if (int(m_rules.size()) != arity)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "%1: a scheme of arity %2 needs %2 rules, got %3"),
            m_name, arity, m_rules.size()));
    int kmin = INT_MAX, kmax = INT_MIN;
    for (int r = 0; r < arity; ++r) {
        const auto &rule = m_rules[r];
        if (rule.weights.empty())
            throw InputError(formatMessage(
                coreTranslate("awb::schemes", "%1: rule %2 has no weights"), m_name, r + 1));
        double sum = 0.0, abssum = 0.0;
        for (size_t j = 0; j < rule.weights.size(); ++j) {
            const double w = rule.weights[j];
            if (!std::isfinite(w))
                throw InputError(formatMessage(
                    coreTranslate("awb::schemes", "%1: weight %2 of rule %3 is not a finite "
                                                  "number"),
                    m_name, j + 1, r + 1));
            sum += w;
            abssum += std::abs(w);
        }
        if (std::abs(sum - 1.0) > 1e-9 * std::max(1.0, abssum))
            throw InputError(formatMessage(
                coreTranslate("awb::schemes", "%1: the weights of rule %2 sum to %3, not 1 (an "
                                              "affine rule must reproduce constants)"),
                m_name, r + 1, streamedNumber(sum, 12)));
        for (size_t j = 0; j < rule.weights.size(); ++j) {
            const int k = r - arity * (rule.offset + int(j));
            kmin = std::min(kmin, k);
            kmax = std::max(kmax, k);
        }
    }
    // Pad the support on the right so that (p - 1) divides its length: the IFS split below
    // needs an integral basis-function support [k0/(p-1), k1/(p-1)].
    while ((kmax - kmin) % (arity - 1) != 0)
        ++kmax;
    m_k0 = kmin;
    m_mask.assign(kmax - kmin + 1, 0.0);
    for (int r = 0; r < arity; ++r)
        for (size_t j = 0; j < m_rules[r].weights.size(); ++j)
            m_mask[r - arity * (m_rules[r].offset + int(j)) - m_k0] += m_rules[r].weights[j];
}

int UniformScheme::minControlPoints() const
{
    const int span = int(m_mask.size()) - 1;
    return std::max(2, span / (m_arity - 1));
}

int UniformScheme::firstRow() const
{
    const int k1 = m_k0 + int(m_mask.size()) - 1;
    return k1 - m_arity + 1;
}

int UniformScheme::pieceShift(int m) const
{
    const int span = int(m_mask.size()) - 1;
    return m + 1 - span / (m_arity - 1);
}

Mat UniformScheme::refinementMatrix(int m) const
{
    requireControlPointCount(m);
    const int p = m_arity;
    const int first = firstRow();
    const int last = p * m + m_k0 - 1;
    Mat R = Mat::Zero(last - first + 1, m);
    const int k1 = m_k0 + int(m_mask.size()) - 1;
    for (int n = first; n <= last; ++n) {
        for (int l = 0; l < m; ++l) {
            const int k = n - p * l;
            if (k >= m_k0 && k <= k1)
                R(n - first, l) = m_mask[k - m_k0];
        }
    }
    return R;
}

SubdivisionMatrices UniformScheme::matrices(int m) const
{
    const Mat R = refinementMatrix(m);
    const int L = pieceShift(m);
    SubdivisionMatrices out;
    out.overlap = m - L;
    for (int j = 0; j < m_arity; ++j)
        out.S.push_back(R.middleRows(j * L, m));
    return out;
}

std::optional<Mat> UniformScheme::exactCurve(const Mat &P, int samples) const
{
    if (m_bsplineDegree < 1)
        return std::nullopt;
    requireControlPointCount(int(P.rows()));
    return BSplineBasis::uniform(m_bsplineDegree, int(P.rows())).curve(P, samples);
}

std::optional<std::vector<Mat>> UniformScheme::bezierPieces(const Mat &P) const
{
    if (m_bsplineDegree < 1)
        return std::nullopt;
    requireControlPointCount(int(P.rows()));
    return BSplineBasis::uniform(m_bsplineDegree, int(P.rows())).bezierPieces(P);
}

UniformScheme bsplineScheme(int degree)
{
    if (degree < 1 || degree > 15)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "B-spline degree must be between 1 and 15, got %1"),
            degree));
    // 004 (2.7): p_{2i} = 2^-n sum_j C(n+1, 2j) p_{i-1+j}, p_{2i+1} = 2^-n sum_j C(n+1, 2j+1) p_{i+j}
    auto binom = [](int n, int k) {
        double r = 1;
        for (int i = 1; i <= k; ++i)
            r = r * (n - k + i) / i;
        return r;
    };
    const double scale = std::ldexp(1.0, -degree);
    SchemeRule even{-1, {}}, odd{0, {}};
    for (int j = 0; 2 * j <= degree + 1; ++j)
        even.weights.push_back(binom(degree + 1, 2 * j) * scale);
    for (int j = 0; 2 * j + 1 <= degree + 1; ++j)
        odd.weights.push_back(binom(degree + 1, 2 * j + 1) * scale);
    UniformScheme s(formatMessage(coreTranslate("awb::schemes", "uniform B-spline of degree %1"),
                                  degree),
                    2, {even, odd});
    s.setBSplineDegree(degree);
    return s;
}

UniformScheme cornerCuttingScheme(double a, double b)
{
    if (!std::isfinite(a) || !std::isfinite(b) || !(0.0 < a && a < b && b < 1.0))
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "corner cutting needs 0 < a < b < 1, got a = %1, b = %2"),
            streamedNumber(a, 12), streamedNumber(b, 12)));
    // Even point 2i: parameter b on edge (p_{i-1}, p_i); odd point 2i+1: parameter a on (p_i, p_{i+1}).
    return UniformScheme(formatMessage(coreTranslate("awb::schemes", "corner cutting (%1, %2)"),
                                       streamedNumber(a, 12), streamedNumber(b, 12)),
                         2,
                         {SchemeRule{-1, {1.0 - b, b}}, SchemeRule{0, {1.0 - a, a}}});
}

UniformScheme chaikinScheme()
{
    UniformScheme s("Chaikin", 2, {SchemeRule{-1, {0.25, 0.75}}, SchemeRule{0, {0.75, 0.25}}});
    s.setBSplineDegree(2);
    return s;
}

UniformScheme fourPointScheme(double omega)
{
    if (!std::isfinite(omega))
        throw InputError(
            coreTranslate("awb::schemes", "four-point tension omega is not a finite number"));
    return UniformScheme(formatMessage(coreTranslate("awb::schemes", "four-point (omega = %1)"),
                                       streamedNumber(omega, 12)),
                         2,
                         {SchemeRule{0, {1.0}},
                          SchemeRule{-1, {-omega, 0.5 + omega, 0.5 + omega, -omega}}});
}

UniformScheme maskScheme(int arity, const std::vector<double> &mask, int offset)
{
    if (arity < 2 || arity > 64)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "the arity of a mask must be between 2 and 64, got %1"),
            arity));
    if (mask.empty() || mask.size() > 4096)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "a mask needs between 1 and 4096 coefficients, got %1"),
            mask.size()));
    if (std::abs(double(offset)) > 1e6)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "the mask's offset %1 is absurd"), offset));
    for (size_t i = 0; i < mask.size(); ++i)
        if (!std::isfinite(mask[i]))
            throw InputError(formatMessage(
                coreTranslate("awb::schemes", "mask coefficient %1 is not a finite number"),
                i + 1));
    // Rule r (refined points N i + r) holds the coefficients a_k with k = r mod N, from the
    // largest k down: new point N i + r = sum_j a_{r - N (o_r + j)} p_{i + o_r + j}.
    auto mod = [arity](int k) { return ((k % arity) + arity) % arity; };
    const int first = offset, last = offset + int(mask.size()) - 1;
    std::vector<SchemeRule> rules;
    for (int r = 0; r < arity; ++r) {
        int top = last;
        while (top >= first && mod(top) != r)
            --top;
        double sum = 0.0, scale = 0.0;
        SchemeRule rule;
        if (top >= first) {
            rule.offset = (r - top) / arity;
            for (int k = top; k >= first; k -= arity) {
                rule.weights.push_back(mask[size_t(k - first)]);
                sum += mask[size_t(k - first)];
                scale += std::abs(mask[size_t(k - first)]);
            }
        }
        if (std::abs(sum - 1.0) > 1e-9 * std::max(1.0, scale))
            throw InputError(formatMessage(
                coreTranslate("awb::schemes",
                              "the coefficients a_k with k = %1 mod %2 sum to %3, not 1: every "
                              "coset of the mask must sum to 1 (the scheme must reproduce "
                              "constants; the whole mask sums to the arity %2)"),
                r, arity, streamedNumber(sum, 12)));
        rules.push_back(std::move(rule));
    }
    return UniformScheme(
        formatMessage(coreTranslate("awb::schemes", "mask of arity %1"), arity), arity,
        std::move(rules));
}

// ---------------------------------------------------------------------------------------------

BezierScheme::BezierScheme(int degree, double t) : m_degree(degree), m_t(t)
{
    if (degree < 1 || degree > 30)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "Bézier degree must be between 1 and 30, got %1"),
            degree));
    if (!std::isfinite(t) || !(t > 0.0 && t < 1.0))
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "the de Casteljau split parameter t must lie strictly "
                                          "between 0 and 1, got %1"),
            streamedNumber(t, 12)));
}

std::string BezierScheme::name() const
{
    return formatMessage(
        coreTranslate("awb::schemes", "Bézier of degree %1 (de Casteljau at t = %2)"), m_degree,
        streamedNumber(m_t, 12));
}

SubdivisionMatrices BezierScheme::matrices(int m) const
{
    requireControlPointCount(m);
    return {{deCasteljauL(m_degree, m_t), deCasteljauR(m_degree, m_t)}, 1};
}

std::optional<Mat> BezierScheme::exactCurve(const Mat &P, int samples) const
{
    requireControlPointCount(int(P.rows()));
    return bezierPoints(P, linspace(0.0, 1.0, samples));
}

std::optional<std::vector<Mat>> BezierScheme::bezierPieces(const Mat &P) const
{
    requireControlPointCount(int(P.rows()));
    return std::vector<Mat>{P};
}

// ---------------------------------------------------------------------------------------------

EndInterpolatingBSplineScheme::EndInterpolatingBSplineScheme(int degree) : m_degree(degree)
{
    if (degree < 1 || degree > 15)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "B-spline degree must be between 1 and 15, got %1"),
            degree));
}

std::string EndInterpolatingBSplineScheme::name() const
{
    return formatMessage(
        coreTranslate("awb::schemes", "end-interpolating B-spline of degree %1"), m_degree);
}

SubdivisionMatrices EndInterpolatingBSplineScheme::matrices(int m) const
{
    requireControlPointCount(m);
    const BSplineBasis basis = BSplineBasis::endInterpolating(m_degree, m);
    const double N = basis.domainEnd();
    // Each half has the knots of the whole, scaled by 1/2: the middle knot becomes n-fold.
    std::vector<double> finer;
    for (double t : basis.knots())
        finer.push_back(0.5 * t);
    for (size_t i = m_degree; i < basis.knots().size(); ++i)
        finer.push_back(0.5 * N + 0.5 * basis.knots()[i]);
    const Mat K = basis.insertionMatrix(finer);
    SubdivisionMatrices out;
    out.S = {K.topRows(m), K.bottomRows(m)};
    out.overlap = 2 * m - int(K.rows());
    return out;
}

std::optional<Mat> EndInterpolatingBSplineScheme::exactCurve(const Mat &P, int samples) const
{
    requireControlPointCount(int(P.rows()));
    return BSplineBasis::endInterpolating(m_degree, int(P.rows())).curve(P, samples);
}

std::optional<std::vector<Mat>> EndInterpolatingBSplineScheme::bezierPieces(const Mat &P) const
{
    requireControlPointCount(int(P.rows()));
    return BSplineBasis::endInterpolating(m_degree, int(P.rows())).bezierPieces(P);
}

// ---------------------------------------------------------------------------------------------

MatrixScheme::MatrixScheme(std::vector<Mat> S, std::string name)
    : m_S(std::move(S)), m_name(std::move(name))
{
    if (m_S.size() < 2)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "%1: an IFS needs at least two matrices, got %2"),
            m_name, m_S.size()));
    const Eigen::Index m = m_S.front().rows();
    if (m < 1)
        throw InputError(
            formatMessage(coreTranslate("awb::schemes", "%1: matrix S_1 is empty"), m_name));
    for (size_t i = 0; i < m_S.size(); ++i) {
        if (m_S[i].rows() != m || m_S[i].cols() != m)
            throw InputError(formatMessage(
                coreTranslate("awb::schemes", "%1: matrix S_%2 is %3 x %4, expected %5 x %5 like "
                                              "S_1"),
                m_name, i + 1, m_S[i].rows(), m_S[i].cols(), m));
        requireFinite(m_S[i], formatMessage(coreTranslate("awb::schemes", "%1: matrix S_%2"),
                                            m_name, i + 1));
        for (Eigen::Index r = 0; r < m; ++r) {
            const double sum = m_S[i].row(r).sum();
            if (std::abs(sum - 1.0) > 1e-9 * std::max(1.0, m_S[i].row(r).cwiseAbs().sum()))
                throw InputError(formatMessage(
                    coreTranslate("awb::schemes", "%1: matrix S_%2, row %3 sums to %4, not 1 "
                                                  "(subdivision rows are affine combinations)"),
                    m_name, i + 1, r + 1, streamedNumber(sum, 12)));
        }
    }
    m_overlap = int(m);
    for (size_t i = 1; i < m_S.size(); ++i)
        m_overlap = std::min(m_overlap, sharedRows(m_S[i - 1], m_S[i]));
}

SubdivisionMatrices MatrixScheme::matrices(int m) const
{
    requireControlPointCount(m);
    return {m_S, m_overlap};
}

// ---------------------------------------------------------------------------------------------

int sharedRows(const Mat &prev, const Mat &next)
{
    const Eigen::Index m = std::min(prev.rows(), next.rows());
    for (Eigen::Index o = m; o > 0; --o) {
        if ((prev.bottomRows(o) - next.topRows(o)).cwiseAbs().maxCoeff() < 1e-12)
            return int(o);
    }
    return 0;
}

Mat subdivide(const CurveScheme &scheme, const Mat &P, int steps)
{
    requireFinite(P, coreTranslate("awb::schemes", "control points"));
    if (steps < 0)
        throw InputError(
            coreTranslate("awb::schemes", "the number of subdivision steps cannot be negative"));
    const SubdivisionMatrices sm = scheme.matrices(int(P.rows()));
    const double rows = double(P.rows()) * std::pow(double(sm.S.size()), steps);
    if (rows > 5e7)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "classic subdivision with %1 steps would make %2 "
                                          "points; use fewer steps"),
            steps, streamedNumber(rows, 12)));
    std::vector<Mat> pieces{P};
    for (int k = 0; k < steps; ++k) {
        std::vector<Mat> next;
        next.reserve(pieces.size() * sm.S.size());
        for (const Mat &Q : pieces)
            for (const Mat &S : sm.S)
                next.push_back(S * Q);
        pieces.swap(next);
    }
    if (steps == 0)
        return P;
    const Eigen::Index m = P.rows();
    const Eigen::Index keep = m - sm.overlap;
    Mat out(m + Eigen::Index(pieces.size() - 1) * keep, P.cols());
    out.topRows(m) = pieces.front();
    for (size_t i = 1; i < pieces.size(); ++i)
        out.middleRows(m + Eigen::Index(i - 1) * keep, keep) = pieces[i].bottomRows(keep);
    return out;
}

} // namespace awb
