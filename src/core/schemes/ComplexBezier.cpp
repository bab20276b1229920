#include "core/schemes/ComplexBezier.h"

#include "core/Decompositions.h"
#include "core/Messages.h"
#include "core/ifs/Attractor.h"
#include "core/schemes/Curves.h"
#include "core/analysis/Geometry.h"

#include <cmath>
#include <sstream>

namespace awb {

namespace {

constexpr double kCircleTol = 1e-12;

void requireFiniteComplex(Complex z, const std::string &what)
{
    if (!std::isfinite(z.real()) || !std::isfinite(z.imag()))
        throw InputError(
            formatMessage(coreTranslate("awb::schemes", "%1 is not a finite number"), what));
}

std::string str(Complex z)
{
    std::ostringstream os;
    os.precision(6);
    os << z.real() << (z.imag() < 0 ? " - " : " + ") << std::abs(z.imag()) << "i";
    return os.str();
}

// One condition |z| < 1 in words: "|t| = 0.7 < 1" / "|t| = 1 (on the circle ...)".
std::string discWords(const char *name, double mod, const char *map)
{
    if (mod < 1.0 - kCircleTol)
        return formatMessage(coreTranslate("awb::schemes", "%1 = %2 < 1"), name,
                             streamedNumber(mod));
    if (mod <= 1.0 + kCircleTol)
        return formatMessage(coreTranslate("awb::schemes", "%1 = %2: on the circle %1 = 1, so %3 "
                                                           "is an isometry, not a contraction"),
                             name, streamedNumber(mod), map);
    return formatMessage(coreTranslate("awb::schemes", "%1 = %2 > 1, so %3 expands"), name,
                         streamedNumber(mod), map);
}

Mat toPlane(const std::vector<Complex> &z)
{
    Mat out(z.size(), 2);
    for (std::size_t i = 0; i < z.size(); ++i)
        out.row(Eigen::Index(i)) << z[i].real(), z[i].imag();
    return out;
}

void requireTakagiY(double y, int depth)
{
    if (!std::isfinite(y) || y == 0.0)
        throw InputError(coreTranslate("awb::schemes", "y must be a finite nonzero number (t = "
                                                       "1/2 + i y)"));
    const ParameterReport r = classifyParameter(Complex(0.5, y));
    if (!r.hyperbolic)
        throw InputError(formatMessage(coreTranslate("awb::schemes", "t = 1/2 + i y with y = "
                                                                     "%1: %2"),
                                       std::to_string(y), r.message));
    if (depth < 1 || depth > 24)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "depth must be between 1 and 24, got %1"), depth));
}

} // namespace

int ParameterReport::levelsFor(double factor) const
{
    if (!hyperbolic)
        return -1;
    if (!(factor > 0.0 && factor < 1.0) || slowestFactor <= 0.0)
        return 1;
    return std::max(1, int(std::ceil(std::log(factor) / std::log(slowestFactor))));
}

ParameterReport classifyParameter(Complex t)
{
    requireFiniteComplex(t, coreTranslate("awb::schemes", "the subdivision parameter t"));
    ParameterReport r;
    r.t = t;
    r.modT = std::abs(t);
    r.modOneMinusT = std::abs(1.0 - t);
    r.insideT = r.modT < 1.0 - kCircleTol;
    r.insideOneMinusT = r.modOneMinusT < 1.0 - kCircleTol;
    r.hyperbolic = r.insideT && r.insideOneMinusT;
    r.slowestFactor = std::max(r.modT, r.modOneMinusT);
    const std::string discT = discWords("|t|", r.modT, "f1(z) = t z");
    const std::string discOneMinusT =
        discWords("|1 - t|", r.modOneMinusT, "f2(z) = (1 - t) z + t");
    if (r.hyperbolic)
        r.message = formatMessage(
            coreTranslate("awb::schemes", "t = %1: %2, %3. t lies inside both discs: the IFS is "
                                          "hyperbolic (contraction factor %4) and its attractor "
                                          "is a connected curve (Theorem 3.7.2)"),
            str(t), discT, discOneMinusT, streamedNumber(r.slowestFactor));
    else if (!r.insideT && !r.insideOneMinusT)
        r.message = formatMessage(
            coreTranslate("awb::schemes", "t = %1: %2, %3. t lies outside both discs |t| < 1 and "
                                          "|1 - t| < 1: the IFS is not hyperbolic and has no "
                                          "attractor"),
            str(t), discT, discOneMinusT);
    else
        r.message = formatMessage(
            coreTranslate("awb::schemes", "t = %1: %2, %3. t lies outside the disc %4: the IFS "
                                          "is not hyperbolic and has no attractor"),
            str(t), discT, discOneMinusT, r.insideT ? "|1 - t| < 1" : "|t| < 1");
    return r;
}

Ifs deCasteljauSegmentIfs(Complex t)
{
    requireFiniteComplex(t, coreTranslate("awb::schemes", "the subdivision parameter t"));
    Ifs ifs;
    ifs.space = "complex plane";
    CMat a(1, 1);
    Eigen::RowVectorXcd b(1);
    a(0, 0) = t;
    b(0) = 0.0;
    ifs.maps.push_back(realify(a, b));  // f1(z) = t z
    a(0, 0) = 1.0 - t;
    b(0) = t;
    ifs.maps.push_back(realify(a, b));  // f2(z) = (1 - t) z + t
    ifs.views.push_back({Mat::Identity(2, 2), RowVec::Zero(2)});
    return ifs;
}

ComplexBezierIfs complexBezierIfs(const CVec &P, Complex t)
{
    if (P.size() < 2)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "a Bézier curve needs at least 2 control points "
                                          "(degree >= 1), got %1"),
            P.size()));
    requireFinite(CMat(P), coreTranslate("awb::schemes", "control points"));
    ComplexBezierIfs out;
    out.controlPoints = P;
    out.t = t;
    out.parameter = classifyParameter(t);  // throws for a non-finite t
    const int n = int(P.size()) - 1;

    // The free pair: 000's last two points unless they (nearly) coincide, else the farthest.
    double diameter = 0.0;
    int fa = 0, fb = 1;
    for (int i = 0; i <= n; ++i)
        for (int j = i + 1; j <= n; ++j)
            if (std::abs(P(i) - P(j)) > diameter) {
                diameter = std::abs(P(i) - P(j));
                fa = i;
                fb = j;
            }
    if (diameter == 0.0)
        throw InputError(coreTranslate("awb::schemes", "all control points coincide: the curve "
                                                       "is a single point and the lifted matrix "
                                                       "of 000 §2 is singular"));
    if (std::abs(P(n - 1) - P(n)) > 1e-8 * diameter) {
        fa = n - 1;
        fb = n;
    }
    out.freeRows = {fa, fb};

    out.lifted = CMat::Zero(n + 1, n + 1);
    out.lifted.col(0) = P;
    out.lifted.col(n).setOnes();
    for (int row = 0, k = 1; row <= n; ++row)
        if (row != fa && row != fb)
            out.lifted(row, k++) = 1.0;
    const CMat inv = out.lifted.fullPivLu().inverse();

    out.S = {deCasteljauL(n, t), deCasteljauR(n, t)};
    out.ifs.space = "complex lifted";
    for (int i = 0; i < 2; ++i) {
        out.M[i] = inv * out.S[i] * out.lifted;
        const CMat A = out.M[i].topLeftCorner(n, n);
        const Eigen::RowVectorXcd b = out.M[i].bottomLeftCorner(1, n);
        out.ifs.maps.push_back(realify(A, b));
    }
    Mat V = Mat::Zero(2 * n, 2);
    V(0, 0) = 1.0;
    V(1, 1) = 1.0;
    out.ifs.views.push_back({V, RowVec::Zero(2)});
    out.start = RowVec(2 * n);
    for (int k = 0; k < n; ++k) {
        out.start(2 * k) = out.lifted(0, k).real();
        out.start(2 * k + 1) = out.lifted(0, k).imag();
    }
    return out;
}

std::vector<Complex> attractorPoints(const ComplexBezierIfs &cb, int depth)
{
    if (!cb.parameter.hyperbolic)
        throw InputError(cb.parameter.message);
    if (depth < 0 || depth > 24)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "depth must be between 0 and 24, got %1"), depth));
    std::vector<Complex> out(std::size_t(1) << depth);
    const Projection &view = cb.ifs.views.front();
    CallbackSink sink([&](const Mat &v, StartSet::Kind, const std::uint8_t *a, int len) {
        std::size_t j = 0;
        for (int k = 0; k < len; ++k)
            j = (j << 1) | a[k];
        const Mat p = project(view, v);
        out[j] = Complex(p(0, 0), p(0, 1));
    });
    iterate(cb.ifs, StartSet::points(cb.start), depth, sink);
    return out;
}

double takagiTruncationBound(int terms) { return std::ldexp(1.0, -terms); }

double takagi(double x, int terms)
{
    if (!std::isfinite(x))
        throw InputError(coreTranslate("awb::schemes", "the Takagi function needs a finite x"));
    if (terms < 0)
        throw InputError(
            coreTranslate("awb::schemes", "the number of Takagi terms must be >= 0"));
    double sum = 0.0, weight = 1.0, v = x;  // v = 2^n x, exact in binary
    for (int n = 0; n < terms; ++n) {
        const double frac = v - std::floor(v);
        if (frac == 0.0)
            break;  // 2^n x is an integer: every later term vanishes too
        sum += weight * std::min(frac, 1.0 - frac);
        v *= 2.0;
        weight *= 0.5;
    }
    return sum;
}

Complex takagiScaling(Complex z, double s) { return Complex(z.real(), s * z.imag()); }

double dyadicValue(const std::vector<int> &d)
{
    if (d.size() > 60)
        throw InputError(
            coreTranslate("awb::schemes", "binary codes longer than 60 digits are not supported"));
    double r = 0.0;
    for (std::size_t k = 0; k < d.size(); ++k) {
        if (d[k] != 0 && d[k] != 1)
            throw InputError(formatMessage(
                coreTranslate("awb::schemes", "a binary code has digits 0 and 1 only (digit %1 "
                                              "is %2)"),
                k + 1, d[k]));
        r += d[k] * std::ldexp(1.0, -int(k + 1));
    }
    return r;
}

int onesCount(const std::vector<int> &d)
{
    dyadicValue(d);  // validates
    int u = 0;
    for (int v : d)
        u += v;
    return u;
}

Complex lemmaPoint(const std::vector<int> &d, Complex t)
{
    requireFiniteComplex(t, coreTranslate("awb::schemes", "the subdivision parameter t"));
    dyadicValue(d);  // validates the digits
    Eigen::Matrix2cd L, R, M = Eigen::Matrix2cd::Identity();
    L << t, 0.0, 0.0, 1.0;
    R << 1.0 - t, t, 0.0, 1.0;
    for (int dk : d)
        M = (M * (dk ? R : L)).eval();
    return (M * Eigen::Vector2cd(0.0, 1.0))(0);
}

TakagiComparison compareWithTakagi(double y, int depth)
{
    requireTakagiY(y, depth);
    CVec seg(2);
    seg << 0.0, 1.0;
    const std::vector<Complex> s = attractorPoints(complexBezierIfs(seg, Complex(0.5, y)), depth);
    TakagiComparison c;
    c.y = y;
    c.depth = depth;
    std::vector<Complex> scaled(s.size()), graph(s.size());
    for (std::size_t j = 0; j < s.size(); ++j) {
        const double r = std::ldexp(double(j), -depth);
        const double T = takagi(r, depth);  // exact at this dyadic
        scaled[j] = takagiScaling(s[j], 1.0 / (2.0 * y));
        graph[j] = Complex(r, T);
        c.scaledError = std::max(c.scaledError, std::abs(scaled[j] - graph[j]));
        c.realError = std::max(c.realError, std::abs(s[j].real() - r));
        c.imagScaledError = std::max(c.imagScaledError, std::abs(scaled[j].imag() - T));
        c.unscaledError = std::max(c.unscaledError, std::abs(s[j] - Complex(r, 2.0 * y * T)));
    }
    c.hausdorffScaled = hausdorffDistance(toPlane(scaled), toPlane(graph));
    return c;
}

ConjectureComparison compareConjecture(const CVec &P, double y, int depth)
{
    requireTakagiY(y, depth);
    const Complex t(0.5, y);
    const ComplexBezierIfs curve = complexBezierIfs(P, t);
    CVec seg(2);
    seg << 0.0, 1.0;
    const std::vector<Complex> a = attractorPoints(curve, depth);
    const std::vector<Complex> s = attractorPoints(complexBezierIfs(seg, t), depth);
    std::vector<Complex> takagiParams(s.size());
    for (std::size_t j = 0; j < s.size(); ++j) {
        const double r = std::ldexp(double(j), -depth);
        takagiParams[j] = Complex(r, 2.0 * y * takagi(r, depth));
    }
    const CVec cs = bezierPoints(P, s);
    const CVec ct = bezierPoints(P, takagiParams);  // = takagiImage(P, y, depth) without x = 1
    ConjectureComparison c;
    c.y = y;
    c.depth = depth;
    std::vector<Complex> image(s.size());
    for (std::size_t j = 0; j < s.size(); ++j) {
        const Eigen::Index i = Eigen::Index(j);
        c.identityError = std::max(c.identityError, std::abs(a[j] - cs(i)));
        c.toTakagiImage = std::max(c.toTakagiImage, std::abs(a[j] - ct(i)));
        image[j] = ct(i);
    }
    const Mat pts = toPlane(a);
    c.hausdorffToTakagiImage = hausdorffDistance(pts, toPlane(image));
    std::vector<Complex> real(4097);
    for (std::size_t k = 0; k < real.size(); ++k)
        real[k] = double(k) / double(real.size() - 1);
    const CVec plain = bezierPoints(P, real);
    c.toPlainCurve = hausdorffToCurve(
        pts, toPlane(std::vector<Complex>(plain.data(), plain.data() + plain.size())));
    return c;
}

std::vector<Complex> takagiImage(const CVec &P, double y, int depth)
{
    if (P.size() < 2)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "Takagi image: needs at least 2 control points, got %1"),
            P.size()));
    if (!P.allFinite() || !std::isfinite(y))
        throw InputError(
            coreTranslate("awb::schemes", "Takagi image: control points and y must be finite"));
    if (depth < 1 || depth > 20)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "Takagi image: depth %1 is outside 1..20"), depth));
    const std::size_t n = (std::size_t(1) << depth) + 1;
    std::vector<Complex> params(n);
    for (std::size_t j = 0; j < n; ++j) {
        const double x = std::ldexp(double(j), -depth);
        params[j] = Complex(x, 2.0 * y * takagi(x, depth));
    }
    const CVec c = bezierPoints(P, params);
    return std::vector<Complex>(c.data(), c.data() + c.size());
}

CVec example373ControlPoints()
{
    CVec P(3);
    P << Complex(0.0, 0.0), Complex(0.5, 2.0), Complex(0.5, 0.0);
    return P;
}

} // namespace awb
