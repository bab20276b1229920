// Sobolev exponent s_2 of the basic limit function from the transition operator of the mask's
// autocorrelation (Eirola 1992, Villemoes 1994, Jia 1999), against the literature:
// - B-splines of degree d (binary (1 + z)^{d+1} / 2^d and ternary (1 + z + z^2)^{d+1} / 3^d):
//   phi^ = sinc^{d+1}, so s_2 = d + 1/2 exactly;
// - Daubechies' orthonormal scaling functions with 2, 3, 4 vanishing moments (D4, D6, D8):
//   s_2 = 1 exactly for D4 (Eirola 1992), 1.4150 and 1.7756 for D6 and D8 (Villemoes 1992,
//   Cohen & Daubechies 1996; quoted to four digits). Independent corroboration: Phi, the
//   autocorrelation of D_{2p}, is the Dubuc-Deslauriers interpolatory function of 2p points
//   and, as Phi^ = |phi^|^2 >= 0, its Hölder exponent is 2 s_2: 2, 2.830, 3.551 (Daubechies &
//   Lagarias 1992). The tests check this with the JSR (maskRegularity) of the autocorrelation;
// - the four-point scheme (omega = 1/16): its Phi's Hölder exponent (JSR) brackets 2 s_2;
// - for every mask, s_2 - 1/2 <= Hölder exponent <= s_2 (Sobolev embedding in 1D; a compactly
//   supported C^alpha function is in H^s for s < alpha) against maskRegularity's interval;
// - rho itself against a power method on sequences (the cascade of the autocorrelation's
//   2n-th difference scheme), with no matrix, eigen-solver or basis of V.

#include "core/Decompositions.h"
#include "core/analysis/Regularity.h"
#include "core/analysis/Sobolev.h"

#include <QtTest>

#include "TestMain.h"

#include <cmath>

using namespace awb;

namespace {

RegularityOptions budget(double seconds)
{
    RegularityOptions o;
    o.timeBudget = seconds;
    return o;
}

std::vector<double> power(const std::vector<double> &base, int k)
{
    std::vector<double> p{1.0};
    for (int i = 0; i < k; ++i) {
        std::vector<double> q(p.size() + base.size() - 1, 0.0);
        for (size_t a = 0; a < p.size(); ++a)
            for (size_t b = 0; b < base.size(); ++b)
                q[a + b] += p[a] * base[b];
        p.swap(q);
    }
    return p;
}

// sigma(z)^{d+1} / N^d, sigma = 1 + z + .. + z^{N-1}: the B-spline of degree d, arity N.
std::vector<double> bsplineMask(int degree, int N)
{
    std::vector<double> m = power(std::vector<double>(size_t(N), 1.0), degree + 1);
    for (double &v : m)
        v /= std::pow(double(N), degree);
    return m;
}

// Daubechies' minimum-phase mask with p vanishing moments, normalised to sum 2, by spectral
// factorisation: |m(xi)|^2 = cos^{2p}(xi/2) P(sin^2(xi/2)), P(y) = sum_{k<p} C(p-1+k, k) y^k
// (Daubechies 1992, Ten Lectures §6.1); each root y of P gives z + 1/z = 2 - 4y, and the
// factor 1 - z_0 z with |z_0| < 1 (the orientation of the closed forms below).
std::vector<double> daubechiesMask(int p)
{
    std::vector<Complex> poly{1.0};
    auto multiply = [&](Complex c0, Complex c1) {
        std::vector<Complex> q(poly.size() + 1, 0.0);
        for (size_t i = 0; i < poly.size(); ++i) {
            q[i] += c0 * poly[i];
            q[i + 1] += c1 * poly[i];
        }
        poly.swap(q);
    };
    for (int k = 0; k < p; ++k)
        multiply(1.0, 1.0);
    if (p > 1) {
        // Companion matrix of P divided by its leading coefficient C(2p-2, p-1).
        std::vector<double> c(size_t(p), 1.0);
        for (int k = 1; k < p; ++k)
            c[size_t(k)] = c[size_t(k - 1)] * double(p - 1 + k) / double(k);
        Mat C = Mat::Zero(p - 1, p - 1);
        for (int i = 0; i + 1 < p - 1; ++i)
            C(i + 1, i) = 1.0;
        for (int i = 0; i < p - 1; ++i)
            C(i, p - 2) = -c[size_t(i)] / c[size_t(p - 1)];
        Eigen::EigenSolver<Mat> es(C);
        for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) {
            const Complex y = es.eigenvalues()(i);
            const Complex h = (2.0 - 4.0 * y) / 2.0;
            Complex z0 = h + std::sqrt(h * h - 1.0);
            if (std::abs(z0) > 1)
                z0 = 1.0 / z0;
            multiply(1.0, -z0);
        }
    }
    std::vector<double> a;
    double sum = 0.0;
    for (const Complex &v : poly) {
        a.push_back(v.real());
        sum += v.real();
    }
    for (double &v : a)
        v *= 2.0 / sum;
    return a;
}

std::vector<double> d4Mask()
{
    const double r3 = std::sqrt(3.0);
    return {(1 + r3) / 4, (3 + r3) / 4, (3 - r3) / 4, (1 - r3) / 4};
}

// Daubechies (1988), Table 1 in closed form: h_k * sqrt(2) for N = 3.
std::vector<double> d6Mask()
{
    const double r = std::sqrt(10.0), q = std::sqrt(5 + 2 * std::sqrt(10.0));
    return {(1 + r + q) / 16,         (5 + r + 3 * q) / 16,     (10 - 2 * r + 2 * q) / 16,
            (10 - 2 * r - 2 * q) / 16, (5 + r - 3 * q) / 16, (1 + r - q) / 16};
}

std::vector<double> autocorrelation(const std::vector<double> &a, int N)
{
    const int s = int(a.size()) - 1;
    std::vector<double> b(size_t(2 * s + 1), 0.0);
    for (int i = 0; i <= s; ++i)
        for (int j = 0; j <= s; ++j)
            b[size_t(j - i + s)] += a[size_t(i)] * a[size_t(j)] / N;
    return b;
}

double maxDifference(const std::vector<double> &x, const std::vector<double> &y)
{
    if (x.size() != y.size())
        return 1e300;
    double d = 0.0;
    for (size_t i = 0; i < x.size(); ++i)
        d = std::max(d, std::abs(x[i] - y[i]));
    return d;
}

// rho by brute force, without matrices, eigen-solvers or a basis of V: the cascade c_k(z) =
// b(z) b(z^N) .. b(z^{N^{k-1}}) of the autocorrelation and its centred differences e_k(z) =
// z^-n (1 - z)^{2n} c_k(z), which obey e_{k+1}(z) = q(z) e_k(z^N) with q = b / (z^{-(N-1)}
// sigma^2)^n (the 2n-th difference scheme of b). On the unit circle c_k = N^k prod |m|^2 >= 0,
// so |e_k| is largest at 0 and e_k[0] = <delta, T^k Delta^{2n} delta> (subdivision with b is
// T's adjoint) is the power method for T on V: e_{k+1}[0] / e_k[0] -> rho. The window [-W, W]
// determines itself (W >= the half-length of q).
double cascadeRho(const std::vector<double> &b, int N, int n, int steps)
{
    std::vector<double> q = b;   // z^s b(z), coefficients 0..2s
    for (int k = 0; k < 2 * n; ++k) {
        std::vector<double> r = q, quotient(q.size() - size_t(N - 1), 0.0);
        for (int t = int(q.size()) - 1; t >= N - 1; --t) {
            const double c = r[size_t(t)];
            quotient[size_t(t - N + 1)] = c;
            for (int j = 0; j < N; ++j)
                r[size_t(t - j)] -= c;
        }
        for (int t = 0; t < N - 1; ++t)
            if (std::abs(r[size_t(t)]) > 1e-12)
                return std::nan("");
        q.swap(quotient);
    }
    const int h = int(q.size()) / 2;   // q lives on [-h, h]
    const int W = std::max(h, n) + 1;
    std::vector<double> e(size_t(2 * W + 1), 0.0);
    double binom = 1.0;   // e_0 = z^-n (1 - z)^{2n}
    for (int t = 0; t <= 2 * n; ++t) {
        e[size_t(W + t - n)] = (t % 2 ? -1.0 : 1.0) * binom;
        binom = binom * (2 * n - t) / (t + 1);
    }
    double ratio = 0.0;
    for (int k = 0; k < steps; ++k) {
        std::vector<double> next(e.size(), 0.0);
        for (int m = -W; m <= W; ++m)
            for (int j = -h; j <= h; ++j)
                if ((m - j) % N == 0 && std::abs((m - j) / N) <= W)
                    next[size_t(m + W)] += q[size_t(j + h)] * e[size_t((m - j) / N + W)];
        ratio = next[size_t(W)] / e[size_t(W)];
        const double scale = std::abs(next[size_t(W)]);
        for (double &v : next)
            v /= scale;
        e.swap(next);
    }
    return ratio;
}

QString text(double v)
{
    return QString::number(v, 'g', 17);
}

struct Row {
    QString name;
    double s2;
    double seconds;
    QString holder;   // phi's Hölder interval from maskRegularity
    QString phi;      // Phi's Hölder interval (JSR), which should hold 2 s_2
};
std::vector<Row> table;

QString interval(const Regularity &r)
{
    return QString("[%1, %2]").arg(r.lower, 0, 'f', 4).arg(r.upper, 0, 'f', 4);
}

// s_2 - 1/2 <= alpha <= s_2 against maskRegularity's certified lower bound and its upper bound
// (exact for stable shifts, as all masks here have); also Regularity::sobolev.
void checkHolderSandwich(const std::vector<double> &mask, int N, double s2, double tol)
{
    const Regularity r = maskRegularity(mask, N, budget(1.0));
    QVERIFY(r.applies);
    table.back().holder = interval(r);
    QVERIFY2(r.lower <= s2 + tol, qPrintable(text(r.lower) + " > s_2 = " + text(s2)));
    QVERIFY2(s2 - 0.5 <= r.upper + tol, qPrintable(text(r.upper) + " < s_2 - 1/2"));
    QVERIFY(r.sobolev.has_value());
    QCOMPARE(*r.sobolev, s2);
}

void record(const QString &name, const SobolevRegularity &s)
{
    table.push_back({name, s.exponent, s.seconds, "-", "-"});
}

} // namespace

class TestSobolev : public QObject {
    Q_OBJECT
private slots:
    void bsplines_data();
    void bsplines();
    void ternaryBSplines();
    void daubechiesCoefficients();
    void daubechies_data();
    void daubechies();
    void fourPoint();
    void cascadeAgrees();
    void notApplicable();
    void noPositiveSmoothness();
    void unstableShifts();
    void printTable();
};

void TestSobolev::bsplines_data()
{
    QTest::addColumn<int>("degree");
    for (int d = 0; d <= 5; ++d)
        QTest::addRow("degree %d", d) << d;
}

void TestSobolev::bsplines()
{
    QFETCH(int, degree);
    const std::vector<double> a = bsplineMask(degree, 2);
    const SobolevRegularity s = sobolevRegularity(a, 2);
    QVERIFY2(s.applies, s.message.c_str());
    QCOMPARE(s.sumRules, degree + 1);
    QVERIFY(!s.capped);
    // V is one-dimensional: T on V is the number 2^-(2d+1), also a polynomial eigenvalue.
    QCOMPARE(int(s.values.size()), 1);
    QVERIFY2(std::abs(s.rho - std::pow(2.0, -(2 * degree + 1))) < 1e-15, qPrintable(text(s.rho)));
    QVERIFY2(std::abs(s.exponent - (degree + 0.5)) < 1e-9, qPrintable(text(s.exponent)));
    QVERIFY(s.margin < 1e-9);
    record(QString("B-spline degree %1").arg(degree), s);
    checkHolderSandwich(a, 2, s.exponent, 1e-9);
}

void TestSobolev::ternaryBSplines()
{
    // (1 + z + z^2)^3 / 9: the ternary quadratic B-spline (phi^ = sinc^3), s_2 = 5/2.
    const std::vector<double> quadratic{1. / 9, 3. / 9, 6. / 9, 7. / 9, 6. / 9, 3. / 9, 1. / 9};
    QVERIFY(maxDifference(quadratic, bsplineMask(2, 3)) < 1e-16);
    for (int d = 0; d <= 3; ++d) {
        const std::vector<double> a = bsplineMask(d, 3);
        const SobolevRegularity s = sobolevRegularity(a, 3);
        QVERIFY2(s.applies, s.message.c_str());
        QCOMPARE(s.arity, 3);
        QCOMPARE(s.sumRules, d + 1);
        QVERIFY2(std::abs(s.exponent - (d + 0.5)) < 1e-9, qPrintable(text(s.exponent)));
        record(QString("ternary B-spline degree %1").arg(d), s);
        checkHolderSandwich(a, 3, s.exponent, 1e-9);
    }
}

void TestSobolev::daubechiesCoefficients()
{
    // The spectral factorisation reproduces the closed forms, and the masks are orthonormal:
    // sum_k a_k a_{k+2m} = 2 delta_m, i.e. b_{2m} = delta_m.
    QVERIFY(maxDifference(daubechiesMask(2), d4Mask()) < 1e-14);
    QVERIFY(maxDifference(daubechiesMask(3), d6Mask()) < 1e-14);
    for (int p = 1; p <= 4; ++p) {
        const std::vector<double> a = daubechiesMask(p);
        QCOMPARE(int(a.size()), 2 * p);
        const std::vector<double> b = autocorrelation(a, 2);
        const int s = int(a.size()) - 1;
        for (int m = -s / 2; m <= s / 2; ++m)
            QVERIFY2(std::abs(b[size_t(2 * m + s)] - (m == 0 ? 1.0 : 0.0)) < 1e-14,
                     qPrintable(QString("p=%1 m=%2").arg(p).arg(m)));
    }
    // Phi of D4 is the four-point scheme's phi: b = (-1, 0, 9, 16, 9, 0, -1) / 16.
    const std::vector<double> four{-1. / 16, 0, 9. / 16, 1, 9. / 16, 0, -1. / 16};
    QVERIFY(maxDifference(autocorrelation(d4Mask(), 2), four) < 1e-15);
}

void TestSobolev::daubechies_data()
{
    QTest::addColumn<int>("moments");
    QTest::addColumn<double>("expected");
    QTest::addColumn<double>("tolerance");
    QTest::addRow("D4") << 2 << 1.0 << 1e-9;
    QTest::addRow("D6") << 3 << 1.4150 << 1e-3;
    QTest::addRow("D8") << 4 << 1.7756 << 1e-3;
}

void TestSobolev::daubechies()
{
    QFETCH(int, moments);
    QFETCH(double, expected);
    QFETCH(double, tolerance);
    const std::vector<double> a = moments == 2 ? d4Mask() : moments == 3 ? d6Mask()
                                                                      : daubechiesMask(moments);
    const SobolevRegularity s = sobolevRegularity(a, 2);
    QVERIFY2(s.applies, s.message.c_str());
    QCOMPARE(s.sumRules, moments);
    QVERIFY2(std::abs(s.exponent - expected) < tolerance, qPrintable(text(s.exponent)));
    QVERIFY2(s.margin < 1e-9, qPrintable(text(s.margin)));
    record(QString("Daubechies D%1").arg(2 * moments), s);
    checkHolderSandwich(a, 2, s.exponent, 1e-6);
    // Independent: the Hölder exponent of Phi (the Dubuc-Deslauriers 2p-point function) by the
    // JSR of its difference scheme is 2 s_2.
    const Regularity phi = maskRegularity(autocorrelation(a, 2), 2, budget(2.0));
    QCOMPARE(phi.sumRules, 2 * moments);
    QVERIFY2(phi.lower <= 2 * s.exponent + 1e-6 && 2 * s.exponent <= phi.upper + 1e-6,
             qPrintable(QString("[%1, %2] vs 2 s_2 = %3")
                            .arg(text(phi.lower), text(phi.upper), text(2 * s.exponent))));
    QVERIFY2(phi.width() < 0.01, qPrintable(text(phi.width())));
    table.back().phi = interval(phi);
}

void TestSobolev::fourPoint()
{
    const std::vector<double> a{-1. / 16, 0, 9. / 16, 1, 9. / 16, 0, -1. / 16};
    const SobolevRegularity s = sobolevRegularity(a, 2);
    QVERIFY2(s.applies, s.message.c_str());
    QCOMPARE(s.sumRules, 4);
    // Hölder exponent 2 (not attained): 2 <= s_2 <= 5/2.
    QVERIFY2(s.exponent >= 2.0 - 1e-6 && s.exponent <= 2.5 + 1e-9, qPrintable(text(s.exponent)));
    record("four-point 1/16", s);
    checkHolderSandwich(a, 2, s.exponent, 1e-6);
    // Independent: Phi^ = |phi^|^2 >= 0 and phi has stable shifts, so Phi's Hölder exponent,
    // from the JSR of the difference scheme of the autocorrelation mask, is 2 s_2.
    const Regularity phi = maskRegularity(autocorrelation(a, 2), 2, budget(2.0));
    QCOMPARE(phi.sumRules, 8);
    QVERIFY2(phi.lower <= 2 * s.exponent + 1e-6 && 2 * s.exponent <= phi.upper + 1e-6,
             qPrintable(QString("[%1, %2] vs 2 s_2 = %3")
                            .arg(text(phi.lower), text(phi.upper), text(2 * s.exponent))));
    QVERIFY2(phi.width() < 0.01, qPrintable(text(phi.width())));
    table.back().phi = interval(phi);
}

void TestSobolev::cascadeAgrees()
{
    // An independent computation of rho (sequences only, no eigen-solver, no basis of V).
    struct Case {
        const char *name;
        std::vector<double> mask;
        int N;
    };
    const std::vector<Case> cases{
        {"four-point", {-1. / 16, 0, 9. / 16, 1, 9. / 16, 0, -1. / 16}, 2},
        {"D4", d4Mask(), 2},
        {"D6", d6Mask(), 2},
        {"D8", daubechiesMask(4), 2},
        {"cubic B-spline", bsplineMask(3, 2), 2},
        {"ternary quadratic", bsplineMask(2, 3), 3},
        {"four-point omega = 1", {-1.0, 0, 1.5, 1, 1.5, 0, -1.0}, 2},
    };
    for (const Case &c : cases) {
        const SobolevRegularity s = sobolevRegularity(c.mask, c.N);
        QVERIFY(s.applies);
        QVERIFY(maxDifference(s.autocorrelation, autocorrelation(c.mask, c.N)) < 1e-15);
        const double rho = cascadeRho(autocorrelation(c.mask, c.N), c.N, s.sumRules, 200);
        QVERIFY2(std::abs(rho - s.rho) < 1e-9 * s.rho,
                 qPrintable(QString("%1: cascade %2, eigenvalue %3")
                                .arg(c.name, text(rho), text(s.rho))));
    }
}

void TestSobolev::notApplicable()
{
    // 1 + z + z^2 (binary): no factor 1 + z.
    const SobolevRegularity none = sobolevRegularity({1.0, 1.0, 1.0}, 2);
    QVERIFY(!none.applies);
    QCOMPARE(none.sumRules, 0);
    QVERIFY(QString::fromStdString(none.message).startsWith("no Sobolev exponent"));
    QVERIFY(!maskRegularity({1.0, 1.0, 1.0}, 2).sobolev.has_value());
    // The factor, but summing to 4.
    const SobolevRegularity twice = sobolevRegularity({1.0, 2.0, 1.0}, 2);
    QVERIFY(!twice.applies);
    QVERIFY(QString::fromStdString(twice.message).contains("sums to 4"));
    QVERIFY_THROWS_EXCEPTION(InputError, sobolevRegularity({0.5, 1.0, 0.5}, 1));
    QVERIFY_THROWS_EXCEPTION(InputError, sobolevRegularity({0.5, NAN, 0.5}, 2));
}

void TestSobolev::noPositiveSmoothness()
{
    // The four-point scheme with omega = 1 does not converge (test_regularity); its phi has no
    // positive L^2 smoothness either.
    const std::vector<double> a{-1.0, 0, 1.5, 1, 1.5, 0, -1.0};
    const SobolevRegularity s = sobolevRegularity(a, 2);
    QVERIFY(s.applies);
    QVERIFY2(s.exponent <= 0.0, qPrintable(text(s.exponent)));
    QVERIFY(s.rho >= 1.0);
    QVERIFY2(QString::fromStdString(s.message).startsWith("no positive Sobolev smoothness"),
             s.message.c_str());
    record("four-point omega = 1", s);
    table.back().holder = interval(maskRegularity(a, 2, budget(0.5)));
}

void TestSobolev::unstableShifts()
{
    // 1 + z^3: phi = chi_[0,3] / 3, whose shifts are not stable. The subdivision scheme does
    // not converge (its first difference scheme does not contract), yet phi is in H^s for
    // s < 1/2. The formula is only a lower bound here (Ron & Shen 2000), and a poor one: T
    // has the eigenvalues 1 and -1 on V (the shifts' dependence), so it says s_2 >= 0.
    const std::vector<double> a{1.0, 0.0, 0.0, 1.0};
    const SobolevRegularity s = sobolevRegularity(a, 2);
    QVERIFY(s.applies);
    QCOMPARE(s.sumRules, 1);
    QVERIFY2(s.exponent <= 0.5 + 1e-9, qPrintable(text(s.exponent)));
    QVERIFY2(std::abs(s.rho - 1.0) < 1e-12, qPrintable(text(s.rho)));
    QVERIFY2(QString::fromStdString(s.message).startsWith("no positive Sobolev smoothness"),
             s.message.c_str());
    const Regularity r = maskRegularity(a, 2, budget(0.5));
    QVERIFY(r.upper <= 0.0 + 1e-9);
    record("1 + z^3 (unstable)", s);
    table.back().holder = interval(r);
}

void TestSobolev::printTable()
{
    // phi's Hölder interval (maskRegularity), and that of Phi, which should hold 2 s_2.
    qInfo("%-26s %10s %9s %18s %18s", "mask", "s_2", "seconds", "Hölder(phi)", "Hölder(Phi)");
    for (const Row &r : table)
        qInfo("%-26s %10.6f %9.6f %18s %18s", qPrintable(r.name), r.s2, r.seconds,
              qPrintable(r.holder), qPrintable(r.phi));
    QVERIFY(!table.empty());
}

AWB_TEST_APPLESS_MAIN(TestSobolev)
#include "test_sobolev.moc"
