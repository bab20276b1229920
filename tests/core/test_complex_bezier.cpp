// The complex de Casteljau IFS and the Takagi curve, checked against 004 = L. Ptáčková,
// "Fractals and Splines" (diploma thesis, Plzeň 2012), §3.7: eqs. (3.29)-(3.44), Figs. 3.4-3.9,
// Lemma 3.7.1, Lemma 3.7.2, Theorem 3.7.3 and Conjecture 3.7.1 (Example 3.7.3).

#include "core/ifs/Attractor.h"
#include "core/schemes/ComplexBezier.h"
#include "core/schemes/Curves.h"
#include "core/analysis/Geometry.h"
#include "core/analysis/Spectrum.h"

#include <QtTest>

#include "TestMain.h"

#include <cmath>
#include <limits>

using namespace awb;

namespace {

// The maps have coefficients of modulus <= 1 and the points modulus <= 3; a depth-14 word is
// 14 multiply-adds, each adding ~1e-16: 1e-12 separates "the same point" from a real difference.
constexpr double kSamePoint = 1e-12;

template<class F>
std::string thrown(F f)
{
    try {
        f();
    } catch (const InputError &e) {
        return e.what();
    } catch (...) {
        return "<an exception that is not awb::InputError>";
    }
    return {};
}

#define VERIFY_INPUT_ERROR(expr, fragment)                                                       \
    do {                                                                                         \
        const std::string msg_ = thrown([&] { (void)(expr); });                                  \
        QVERIFY2(!msg_.empty(), "no InputError from " #expr);                                    \
        QVERIFY2(msg_.find(fragment) != std::string::npos, msg_.c_str());                        \
    } while (false)

// f_w(start) for all words of length depth, row j = the word whose maps, outermost first,
// are the binary digits of j (the order attractorPoints() promises).
Mat byCode(const Ifs &ifs, const RowVec &start, int depth)
{
    Mat out(Eigen::Index(1) << depth, 2);
    CallbackSink sink([&](const Mat &v, StartSet::Kind, const std::uint8_t *a, int n) {
        Eigen::Index j = 0;
        for (int k = 0; k < n; ++k)
            j = 2 * j + a[k];
        out.row(j) = project(ifs.views.at(0), v);
    });
    iterate(ifs, StartSet::points(start), depth, sink);
    return out;
}

Mat toPlane(const std::vector<Complex> &z)
{
    Mat out(z.size(), 2);
    for (std::size_t i = 0; i < z.size(); ++i)
        out.row(Eigen::Index(i)) << z[i].real(), z[i].imag();
    return out;
}

CVec segment()
{
    CVec P(2);
    P << 0.0, 1.0;
    return P;
}

std::vector<int> code(std::size_t j, int n)
{
    std::vector<int> d(n);
    for (int k = 0; k < n; ++k)
        d[k] = int((j >> (n - 1 - k)) & 1u);
    return d;
}

} // namespace

class TestComplexBezier : public QObject {
    Q_OBJECT
private slots:
    void segmentMapsAreEq330();
    void levyCurveAndFig34();
    void hyperbolicityReport();
    void anyDegreeIsTheCurveOfTheSegmentAttractor();
    void lemma372PointsLieOnAttractor();
    void takagiFunction();
    void theorem373ErrorShrinksLikeYSquared();
    void conjecture371Example373();
    void takagiImageIsTheOverlay();
    void badInput();
};

void TestComplexBezier::segmentMapsAreEq330()
{
    // eq. (3.30): f1(z) = t z, f2(z) = (1 - t) z + t; realified, on sample points.
    const Complex t(0.3, 0.45);
    const Ifs seg = deCasteljauSegmentIfs(t);
    const std::vector<Complex> zs = {0.0, 1.0, Complex(0.2, -0.7), Complex(-1.5, 2.0)};
    for (const Complex z : zs) {
        const RowVec x = (RowVec(2) << z.real(), z.imag()).finished();
        const Complex f1 = t * z, f2 = (1.0 - t) * z + t;
        const RowVec y1 = applyMap(seg.maps[0], x), y2 = applyMap(seg.maps[1], x);
        QVERIFY(std::abs(Complex(y1(0), y1(1)) - f1) < 1e-15);
        QVERIFY(std::abs(Complex(y2(0), y2(1)) - f2) < 1e-15);
    }
    // The general lifted construction on control points 0, 1 reproduces eq. (3.29): row
    // convention M_1 = [[t, 0], [0, 1]], M_2 = [[1-t, 0], [t, 1]] (transposes of the thesis).
    const ComplexBezierIfs cb = complexBezierIfs(segment(), t);
    CMat M1(2, 2), M2(2, 2);
    M1 << t, 0.0, 0.0, 1.0;
    M2 << 1.0 - t, 0.0, t, 1.0;
    QVERIFY((cb.M[0] - M1).cwiseAbs().maxCoeff() < 1e-15);
    QVERIFY((cb.M[1] - M2).cwiseAbs().maxCoeff() < 1e-15);
    for (int i = 0; i < 2; ++i) {
        QVERIFY((cb.ifs.maps[i].A - seg.maps[i].A).cwiseAbs().maxCoeff() < 1e-15);
        QVERIFY((cb.ifs.maps[i].b - seg.maps[i].b).cwiseAbs().maxCoeff() < 1e-15);
    }
    // Fixed points z1* = 0, z2* = 1 and f1(z2*) = f2(z1*) = t (proof of Theorem 3.7.2).
    QVERIFY(fixedPoint(seg.maps[0])->norm() < 1e-15);
    QVERIFY((*fixedPoint(seg.maps[1]) - RowVec::Unit(2, 0)).norm() < 1e-15);
}

void TestComplexBezier::levyCurveAndFig34()
{
    // The classic Lévy C curve IFS (Barnsley's table, column form):
    //   w1(x, y) = (x/2 - y/2, x/2 + y/2),  w2(x, y) = (x/2 + y/2 + 1/2, -x/2 + y/2 + 1/2),
    // written out by hand, in row form A = transpose. NOTES.md: t = 1/2 + i/2 is exactly Lévy.
    Ifs levy;
    levy.maps.push_back({(Mat(2, 2) << 0.5, 0.5, -0.5, 0.5).finished(), RowVec::Zero(2)});
    levy.maps.push_back(
        {(Mat(2, 2) << 0.5, -0.5, 0.5, 0.5).finished(), (RowVec(2) << 0.5, 0.5).finished()});
    levy.views.push_back({Mat::Identity(2, 2), RowVec::Zero(2)});
    const int depth = 14;
    const Mat classic = byCode(levy, RowVec::Zero(2), depth);
    const ComplexBezierIfs cb = complexBezierIfs(segment(), Complex(0.5, 0.5));
    const Mat ours = toPlane(attractorPoints(cb, depth));
    // Same words in the same order: point by point.
    QCOMPARE(ours.rows(), classic.rows());
    QVERIFY((ours - classic).cwiseAbs().maxCoeff() < kSamePoint);

    // Fig. 3.4: t = 1/2 + i sqrt(3)/3 "resembles the Lévy C curve" but is not it.
    const ComplexBezierIfs fig34 = complexBezierIfs(segment(), Complex(0.5, std::sqrt(3.0) / 3));
    QVERIFY(fig34.parameter.hyperbolic);
    QVERIFY(std::abs(fig34.parameter.modT - std::sqrt(7.0 / 12.0)) < 1e-15);
    const double d = hausdorffDistance(toPlane(attractorPoints(fig34, depth)), classic);
    qInfo("Fig. 3.4 (t = 1/2 + i sqrt(3)/3) vs the Lévy C curve: d_H = %.4f", d);
    QVERIFY2(d > 0.05 && d < 0.5, std::to_string(d).c_str());
}

void TestComplexBezier::hyperbolicityReport()
{
    // Fig. 3.3: hyperbolic iff |t| < 1 and |1 - t| < 1.
    const ParameterReport in = classifyParameter(Complex(0.5, 0.5));
    QVERIFY(in.hyperbolic && in.insideT && in.insideOneMinusT);
    QVERIFY2(in.message.find("inside both discs") != std::string::npos, in.message.c_str());

    const ParameterReport big = classifyParameter(Complex(1.2, 0.0));  // |1 - t| = 0.2
    QVERIFY(!big.hyperbolic && !big.insideT && big.insideOneMinusT);
    QVERIFY2(big.message.find("outside the disc |t| < 1") != std::string::npos,
             big.message.c_str());
    QVERIFY2(big.message.find("f1(z) = t z expands") != std::string::npos, big.message.c_str());

    const ParameterReport neg = classifyParameter(Complex(-0.3, 0.0));  // |1 - t| = 1.3
    QVERIFY(!neg.hyperbolic && neg.insideT && !neg.insideOneMinusT);
    QVERIFY2(neg.message.find("outside the disc |1 - t| < 1") != std::string::npos,
             neg.message.c_str());

    const ParameterReport far = classifyParameter(Complex(0.0, 3.0));
    QVERIFY(!far.insideT && !far.insideOneMinusT);
    QVERIFY2(far.message.find("outside both discs") != std::string::npos, far.message.c_str());

    // On both circles: t = 1/2 + i sqrt(3)/2, |t| = |1 - t| = 1 (to rounding).
    const ParameterReport rim = classifyParameter(Complex(0.5, std::sqrt(3.0) / 2));
    QVERIFY(!rim.hyperbolic);
    QVERIFY2(rim.message.find("on the circle |t| = 1") != std::string::npos, rim.message.c_str());
    QVERIFY2(rim.message.find("isometry") != std::string::npos, rim.message.c_str());

    // Not a crash: the IFS is built, and asking for its attractor names the failing condition.
    const ComplexBezierIfs outside = complexBezierIfs(segment(), Complex(1.2, 0.0));
    QCOMPARE(outside.ifs.size(), 2);
    VERIFY_INPUT_ERROR(attractorPoints(outside, 5), "not hyperbolic");

    // Fig. 3.5: t = 1/4 + i sqrt(3)/4, |t| = 1/2, |1 - t| = sqrt(3)/2: nearer the rim than
    // Fig. 3.4 (sqrt(7/12) = 0.764). After the caption's 15 iterations pieces may still be
    // 0.866^15 = 0.116 of the curve: "not quite the limiting curve"; Fig. 3.4 is at 0.018.
    const ParameterReport fig35 = classifyParameter(Complex(0.25, std::sqrt(3.0) / 4));
    QVERIFY(fig35.hyperbolic);
    QVERIFY(std::abs(fig35.modT - 0.5) < 1e-15);
    QVERIFY(std::abs(fig35.modOneMinusT - std::sqrt(3.0) / 2) < 1e-15);
    QVERIFY(std::pow(fig35.slowestFactor, 15) > 0.1);
    const ParameterReport fig34 = classifyParameter(Complex(0.5, std::sqrt(3.0) / 3));
    QVERIFY(std::pow(fig34.slowestFactor, 15) < 0.02);
    QVERIFY(fig35.levelsFor(0.01) > 2 * 15);  // 33 levels for 1 % against 18 for Fig. 3.4
    QCOMPARE(fig34.levelsFor(0.01), 18);
}

void TestComplexBezier::anyDegreeIsTheCurveOfTheSegmentAttractor()
{
    // The point of address w is c(phi_w(0)), c the Bézier polynomial, phi_w the word in the
    // segment maps (3.30): L(t) P, R(t) P are the control points of c(t a), c(t + (1-t) a).
    CVec cubic(4);
    cubic << Complex(0, 0), Complex(1, 2), Complex(3, 2.5), Complex(3.5, 0);
    CVec repeated(4);  // the last two coincide: another free pair for the lifting
    repeated << Complex(0, 0), Complex(1, 1), Complex(2, -0.5), Complex(2, -0.5);
    const int depth = 12;
    for (const Complex t : {Complex(0.5, 0.1), Complex(0.4, 0.3), Complex(0.6, -0.2)}) {
        const std::vector<Complex> s = attractorPoints(complexBezierIfs(segment(), t), depth);
        for (const CVec &P : {example373ControlPoints(), cubic, repeated}) {
            const ComplexBezierIfs cb = complexBezierIfs(P, t);
            QCOMPARE(cb.ifs.dim(), 2 * cb.degree());
            const std::vector<Complex> a = attractorPoints(cb, depth);
            const CVec c = bezierPoints(P, s);
            double worst = 0;
            for (std::size_t j = 0; j < a.size(); ++j)
                worst = std::max(worst, std::abs(a[j] - c(Eigen::Index(j))));
            QVERIFY2(worst < kSamePoint, std::to_string(worst).c_str());
        }
        // Eigenvalues of A_1, A_2 (lifted, complex) are t^k and (1-t)^k, k = 1..n: the
        // hyperbolic region is the same for every degree.
        const ComplexBezierIfs cb = complexBezierIfs(cubic, t);
        for (int i = 0; i < 2; ++i) {
            const Spectrum sp = spectrum(CMat(cb.M[i].topLeftCorner(3, 3)));
            const Complex base = i == 0 ? t : 1.0 - t;
            for (int k = 1; k <= 3; ++k) {
                double best = 1;
                for (const Complex v : sp.values)
                    best = std::min(best, std::abs(v - std::pow(base, k)));
                QVERIFY(best < 1e-12);
            }
        }
    }
    QVERIFY(complexBezierIfs(repeated, 0.5).freeRows[1] != 3);
}

void TestComplexBezier::lemma372PointsLieOnAttractor()
{
    // s(d) = first coordinate of M(d_1)..M(d_n) (0,1)^T is f_{d1} o .. o f_{dn}(0): an exact
    // image of the fixed point 0, i.e. the depth-n point of code d.
    const int n = 10;
    for (const Complex t : {Complex(0.5, 0.1), Complex(0.5, -0.03), Complex(0.3, 0.4)}) {
        const std::vector<Complex> pts = attractorPoints(complexBezierIfs(segment(), t), n);
        double worst = 0;
        for (std::size_t j = 0; j < pts.size(); ++j)
            worst = std::max(worst, std::abs(lemmaPoint(code(j, n), t) - pts[j]));
        QVERIFY2(worst < kSamePoint, std::to_string(worst).c_str());
    }
    // Base cases of the proof: s([0]) = 0, s([1]) = 1/2 + i y.
    const double y = 0.1;
    QCOMPARE(lemmaPoint({0}, Complex(0.5, y)), Complex(0, 0));
    QVERIFY(std::abs(lemmaPoint({1}, Complex(0.5, y)) - Complex(0.5, y)) < 1e-16);
    // Eq. (3.36): the scale of M(d) is (1/2 - iy)^u (1/2 + iy)^(n-u); with one more 1 appended,
    // s grows by exactly that scale times t (eq. (3.38)).
    const std::vector<int> d = {1, 0, 1, 1, 0};
    std::vector<int> d1 = d;
    d1.push_back(1);
    const Complex t(0.5, y);
    const int u = onesCount(d);
    const Complex scale = std::pow(1.0 - t, u) * std::pow(t, int(d.size()) - u);
    QVERIFY(std::abs(lemmaPoint(d1, t) - lemmaPoint(d, t) - scale * t) < 1e-15);
    // Re s is even and Im s odd in y: s(d)(-y) = conj(s(d)(y)). This is why the error of the
    // scaled points is O(y^2), not O(y): the next term of Im s is y^3.
    for (std::size_t j = 0; j < 64; ++j) {
        const auto c = code(j, 6);
        QVERIFY(std::abs(lemmaPoint(c, Complex(0.5, -y)) - std::conj(lemmaPoint(c, t))) < 1e-15);
    }
    // eq. (3.34): s(d) = r(d) + 2 i y T(r(d)) + O(y^2). Writing t = (rho/2) e^{i theta},
    // rho^2 = 1 + 4y^2, theta = atan 2y, the term of digit k is (rho/2)^k e^{i theta m_k},
    // |m_k| <= k, so |Re error| <= sum_k 2^-k (2k + 2k^2) y^2 = 16 y^2 and Im error = O(y^3).
    const double ys = 1e-3;
    for (std::size_t j = 0; j < 256; ++j) {
        const auto c = code(j, 8);
        const double r = dyadicValue(c);
        const Complex s = lemmaPoint(c, Complex(0.5, ys));
        QVERIFY(std::abs(s - Complex(r, 2 * ys * takagi(r))) < 16 * ys * ys * 1.01);
    }
}

void TestComplexBezier::takagiFunction()
{
    QCOMPARE(takagi(0.0), 0.0);
    QCOMPARE(takagi(1.0), 0.0);
    QCOMPARE(takagi(0.5), 0.5);
    QCOMPARE(takagi(0.25), 0.5);
    QCOMPARE(takagi(0.75), 0.5);
    QCOMPARE(takagi(0.125), 0.375);
    // σ(2^n / 3) = 1/3 for every n: T(1/3) = 2/3, the maximum of T.
    QVERIFY(std::abs(takagi(1.0 / 3) - 2.0 / 3) < 1e-15);
    // Truncation: the tail after K terms is at most 2^-K (here exactly (2/3) 2^-K).
    for (int K = 1; K <= 30; ++K) {
        QCOMPARE(takagiTruncationBound(K), std::ldexp(1.0, -K));
        for (double x : {1.0 / 3, 0.1, 0.7071067811865476, 0.987654321}) {
            const double err = std::abs(takagi(x, K) - takagi(x, 64));
            QVERIFY(err <= takagiTruncationBound(K) + 1e-16);
        }
        QVERIFY(std::abs(takagi(1.0 / 3, K) - 2.0 / 3) > 0.5 * takagiTruncationBound(K));
    }
    // A dyadic j / 2^N is exact after N terms.
    QCOMPARE(takagi(37.0 / 64, 6), takagi(37.0 / 64, 64));
    // Lemma 3.7.1: T(r(d) + 2^-m) - T(r(d)) = (m - 2 u(d)) / 2^m for n <= m.
    for (int n = 1; n <= 8; ++n)
        for (int m = n; m <= 10; ++m)
            for (std::size_t j = 0; j < (std::size_t(1) << n); ++j) {
                const auto d = code(j, n);
                const double r = dyadicValue(d);
                const double lhs = takagi(r + std::ldexp(1.0, -m)) - takagi(r);
                QCOMPARE(lhs, (m - 2.0 * onesCount(d)) * std::ldexp(1.0, -m));
            }
    // eq. (3.40): g(z, s) = Re z + i s Im z.
    QCOMPARE(takagiScaling(Complex(1, 2), 0.25), Complex(1, 0.5));
}

void TestComplexBezier::theorem373ErrorShrinksLikeYSquared()
{
    // The scaled points g(s(d), 1/(2y)) against the Takagi graph at r(d). Re s - r is even in y
    // and Im s - 2yT(r) odd, so after dividing Im by 2y both errors are C y^2 (1 + O(y^2)):
    // halving y divides them by 4 up to a relative O(y^2) <= 1e-3 here. Tolerance 0.05 on a
    // ratio of 4 is ~1 % and still excludes the O(y) rate (ratio 2) by far.
    const std::vector<double> ys = {0.02, 0.01, 0.005};
    std::vector<TakagiComparison> c;
    for (double y : ys) {
        c.push_back(compareWithTakagi(y, 16));
        qInfo("y = %.3f: scaled error %.3e (= %.4f y^2), real %.3e, imag/2y %.3e, "
              "eq. (3.42) %.3e, point-set d_H %.3e", y, c.back().scaledError,
              c.back().scaledError / (y * y), c.back().realError, c.back().imagScaledError,
              c.back().unscaledError, c.back().hausdorffScaled);
    }
    for (std::size_t k = 1; k < c.size(); ++k) {
        const double ratio = c[k - 1].scaledError / c[k].scaledError;
        QVERIFY2(std::abs(ratio - 4.0) < 0.05, std::to_string(ratio).c_str());
        QVERIFY(std::abs(c[k - 1].realError / c[k].realError - 4.0) < 0.05);
        QVERIFY(std::abs(c[k - 1].imagScaledError / c[k].imagScaledError - 4.0) < 0.05);
        // eq. (3.42): d_H(A*(y), T*(y)) = O(y^2) as well, and "its real part dominates": the
        // imaginary part of the unscaled error is 2y times imagScaledError, O(y^3).
        QVERIFY(std::abs(c[k - 1].unscaledError / c[k].unscaledError - 4.0) < 0.05);
        QVERIFY(2 * ys[k] * c[k].imagScaledError < 0.05 * c[k].realError);
        // The point-set Hausdorff distance is at most the matched error.
        QVERIFY(c[k].hausdorffScaled <= c[k].scaledError);
    }
    // Fig. 3.8: y = 2^-10, "we can only see T": the scaled curve is within 1e-5 of it.
    const TakagiComparison fig38 = compareWithTakagi(std::ldexp(1.0, -10), 16);
    QVERIFY2(fig38.scaledError < 1e-5, std::to_string(fig38.scaledError).c_str());
}

void TestComplexBezier::conjecture371Example373()
{
    // Example 3.7.3: p = {0, 1/2 + 2i, 1/2}, thesis value y = 10^-2. Conjecture 3.7.1 claims
    // d_H(A*(y), c(g(T, 2y))) = O(y). What holds: A*(y) = c(A_1(y)) exactly (identityError),
    // so the distance is at most Lip(c) d_H(A_1(y), T*(y)) = O(y^2), a stronger statement.
    // And O(y) alone says nothing: the plain curve c([0, 1]) is itself O(y) from A*(y).
    const CVec P = example373ControlPoints();
    const std::vector<double> ys = {0.02, 0.01, 0.005};
    std::vector<ConjectureComparison> c;
    for (double y : ys) {
        c.push_back(compareConjecture(P, y, 14));
        qInfo("Example 3.7.3, y = %.3f: |A* - c(T*)| %.3e (= %.3f y^2), point-set d_H %.3e, "
              "d_H(A*, c([0,1])) %.3e (= %.3f y)", y, c.back().toTakagiImage,
              c.back().toTakagiImage / (y * y), c.back().hausdorffToTakagiImage,
              c.back().toPlainCurve, c.back().toPlainCurve / y);
        QVERIFY2(c.back().identityError < kSamePoint,
                 std::to_string(c.back().identityError).c_str());
        // Lipschitz bound: |c'(a)| <= 2 max|p_{i+1} - p_i| (|a| + |1 - a|) <= 2 * 2.0616 (1 + 2h)
        // with h = max |Im a| <= 2y * 2/3 + the degree-1 error (and Re a at most realError
        // outside [0, 1]).
        const TakagiComparison seg = compareWithTakagi(y, 14);
        const double h = 2 * y * 2.0 / 3 + seg.unscaledError;
        const double lip = 2 * std::abs(P(1) - P(0)) * (1 + 2 * h + 2 * seg.realError);
        QVERIFY(c.back().toTakagiImage <= lip * seg.unscaledError);
    }
    for (std::size_t k = 1; k < c.size(); ++k) {
        const double r2 = c[k - 1].toTakagiImage / c[k].toTakagiImage;
        QVERIFY2(std::abs(r2 - 4.0) < 0.1, std::to_string(r2).c_str());
        const double r1 = c[k - 1].toPlainCurve / c[k].toPlainCurve;
        QVERIFY2(std::abs(r1 - 2.0) < 0.1, std::to_string(r1).c_str());
    }
    // Fig. 3.9 "we can not quite see any difference" at y = 10^-2: relative to the curve's size
    // (~1.4) the distance is below 1e-3, under a pixel of the printed figure.
    QVERIFY(c[1].toTakagiImage < 1e-3);
}

void TestComplexBezier::takagiImageIsTheOverlay()
{
    // The subdominant eigenvalue of L(t) is t itself, alone (no conjugate: a complex matrix):
    // the Lévy C curve spirals around its end point 0, as f_1(z) = t z rotates by 45 degrees.
    const Subdominant levy = subdominant(spectrum(deCasteljauL(1, Complex(0.5, 0.5))), true);
    QVERIFY(levy.kind == SubdominantKind::Complex);
    QCOMPARE(levy.multiplicity, 1);
    QVERIFY(std::abs(levy.values.front() - Complex(0.5, 0.5)) < 1e-12);
    QVERIFY(levy.meaning().find("spiral") != std::string::npos);
    // Degree 2: eigenvalues 1, t, t^2; t is subdominant.
    const Subdominant quad = subdominant(spectrum(deCasteljauL(2, Complex(0.5, 0.01))), true);
    QVERIFY(quad.kind == SubdominantKind::Complex);
    QVERIFY(std::abs(quad.values.front() - Complex(0.5, 0.01)) < 1e-12);

    // The polyline the attractor view overlays: for the segment (0, 1) it is the graph
    // x + 2iy T(x) at dyadics, T(1/2) = 1/2, T(1/4) = T(3/4) = 1/2 (sum of 1/4 + 1/4), T(0) = 0.
    const double y = 0.05;
    const std::vector<Complex> g = takagiImage(segment(), y, 2);
    QCOMPARE(int(g.size()), 5);
    const double T[5] = {0.0, 0.5, 0.5, 0.5, 0.0};
    for (int j = 0; j < 5; ++j) {
        QVERIFY(std::abs(g[std::size_t(j)] - Complex(j / 4.0, 2 * y * T[j])) < 1e-15);
    }
    // Example 3.7.3 at y = 10^-2: the overlay is the Takagi image of compareConjecture, so the
    // attractor is as close to it as that comparison says (O(y^2), below a printed pixel).
    const CVec P = example373ControlPoints();
    const std::vector<Complex> image = takagiImage(P, 0.01, 12);
    QCOMPARE(int(image.size()), 4097);
    QVERIFY(std::abs(image.front() - P(0)) < 1e-15);
    QVERIFY(std::abs(image.back() - P(2)) < 1e-15);
    const std::vector<Complex> a = attractorPoints(complexBezierIfs(P, Complex(0.5, 0.01)), 12);
    double pointwise = 0.0;
    for (std::size_t j = 0; j < a.size(); ++j)
        pointwise = std::max(pointwise, std::abs(a[j] - image[j]));
    const double bound = compareConjecture(P, 0.01, 12).toTakagiImage;
    QVERIFY2(std::abs(pointwise - bound) < 1e-12,
             (std::to_string(pointwise) + " vs " + std::to_string(bound)).c_str());
    // Set to set (the overlay also has x = 1, the end point p_2, which the depth-12 points
    // approach to within |1 - t|^12 * diameter): below a printed pixel.
    const double dH = hausdorffDistance(toPlane(a), toPlane(image));
    QVERIFY2(dH < 1e-3, std::to_string(dH).c_str());
    // y = 0: the plain Bézier curve.
    const std::vector<Complex> plain = takagiImage(P, 0.0, 4);
    std::vector<Complex> params;
    for (int j = 0; j <= 16; ++j)
        params.push_back(j / 16.0);
    const CVec expected = bezierPoints(P, params);
    for (int j = 0; j <= 16; ++j)
        QVERIFY(std::abs(plain[std::size_t(j)] - expected(j)) < 1e-15);
    VERIFY_INPUT_ERROR(takagiImage(CVec::Constant(1, 1.0), 0.1), "at least 2");
    VERIFY_INPUT_ERROR(takagiImage(P, std::numeric_limits<double>::quiet_NaN()), "finite");
    VERIFY_INPUT_ERROR(takagiImage(P, 0.1, 0), "depth");
    VERIFY_INPUT_ERROR(takagiImage(P, 0.1, 21), "depth");
}

void TestComplexBezier::badInput()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    VERIFY_INPUT_ERROR(complexBezierIfs(CVec::Constant(1, 1.0), 0.5), "degree >= 1");
    VERIFY_INPUT_ERROR(complexBezierIfs(CVec(0), 0.5), "degree >= 1");
    CVec bad = example373ControlPoints();
    bad(1) = Complex(nan, 0.0);
    VERIFY_INPUT_ERROR(complexBezierIfs(bad, 0.5), "not a finite number");
    bad(1) = Complex(0.0, inf);
    VERIFY_INPUT_ERROR(complexBezierIfs(bad, 0.5), "not a finite number");
    VERIFY_INPUT_ERROR(complexBezierIfs(segment(), Complex(nan, 0.0)), "not a finite number");
    VERIFY_INPUT_ERROR(classifyParameter(Complex(0.5, inf)), "not a finite number");
    VERIFY_INPUT_ERROR(deCasteljauSegmentIfs(Complex(inf, 0.0)), "not a finite number");
    VERIFY_INPUT_ERROR(complexBezierIfs(CVec::Constant(3, Complex(1, 1)), 0.5), "coincide");
    VERIFY_INPUT_ERROR(compareWithTakagi(0.0), "nonzero");
    VERIFY_INPUT_ERROR(compareWithTakagi(nan), "finite");
    VERIFY_INPUT_ERROR(compareWithTakagi(0.9), "not hyperbolic");  // |t|^2 = 1/4 + 0.81 > 1
    VERIFY_INPUT_ERROR(compareWithTakagi(0.1, 0), "depth");
    VERIFY_INPUT_ERROR(compareWithTakagi(0.1, 25), "depth");
    VERIFY_INPUT_ERROR(compareConjecture(example373ControlPoints(), 0.9), "not hyperbolic");
    VERIFY_INPUT_ERROR(takagi(nan), "finite");
    VERIFY_INPUT_ERROR(takagi(0.3, -1), ">= 0");
    VERIFY_INPUT_ERROR(lemmaPoint({0, 2, 1}, 0.5), "digits 0 and 1");
    VERIFY_INPUT_ERROR(attractorPoints(complexBezierIfs(segment(), 0.5), 30), "depth");
}

AWB_TEST_APPLESS_MAIN(TestComplexBezier)
#include "test_complex_bezier.moc"
