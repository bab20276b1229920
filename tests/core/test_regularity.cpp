// Certified Hölder regularity of curve schemes (issue 16) against the literature:
// B-splines of degree d have regularity exactly d (C^(d-1), Lipschitz (d-1)-th derivative);
// the four-point scheme with omega = 1/16 has regularity 2, not attained (Daubechies &
// Lagarias 1992, Rioul 1992: C^1, derivative alpha-Hölder for every alpha < 1); omega = 0 is
// piecewise linear (1); 0 < omega < 1/8 is C^1 (Dyn, Gregory & Levin 1987). The JSR bounds are
// checked independently against Dyn & Levin's norms ||S^k||^(1/k) of the difference scheme.

#include "core/analysis/Regularity.h"
#include "core/schemes/Scheme.h"

#include <QtTest>

#include "TestMain.h"

#include "TestTime.h"

#include <cmath>

using namespace awb;

namespace {

RegularityOptions budget(double seconds)
{
    RegularityOptions o;
    o.timeBudget = seconds;
    return o;
}

// ||S_c^k||_inf for the scheme with mask c (coefficients c_0..c_s) of arity N: the largest
// residue-class l1 sum of the iterated mask c(z) c(z^N) .. c(z^(N^(k-1))).
double iteratedNorm(const std::vector<double> &c, int N, int k)
{
    std::vector<double> ck = c;
    long stride = 1;
    for (int level = 1; level < k; ++level) {
        stride *= N;
        std::vector<double> up((c.size() - 1) * size_t(stride) + 1, 0.0);
        for (size_t i = 0; i < c.size(); ++i)
            up[i * size_t(stride)] = c[i];
        std::vector<double> prod(ck.size() + up.size() - 1, 0.0);
        for (size_t i = 0; i < ck.size(); ++i)
            for (size_t j = 0; j < up.size(); ++j)
                prod[i + j] += ck[i] * up[j];
        ck.swap(prod);
    }
    const long Nk = stride * N;
    double best = 0.0;
    for (long e = 0; e < Nk; ++e) {
        double s = 0.0;
        for (size_t i = size_t(e); i < ck.size(); i += size_t(Nk))
            s += std::abs(ck[i]);
        best = std::max(best, s);
    }
    return best;
}

} // namespace

class TestRegularity : public QObject {
    Q_OBJECT
private slots:
    void bsplinesHaveRegularityDegree_data();
    void bsplinesHaveRegularityDegree();
    void chaikinIsQuadraticBSpline();
    void ternaryQuadraticBSpline();
    void fourPointClassic();
    void fourPointPiecewiseLinear();
    void fourPointIsC1ForSmallPositiveOmega_data();
    void fourPointIsC1ForSmallPositiveOmega();
    void fourPointBeyondC1();
    void noDifferenceScheme();
    void notConvergent();
    void boundsAgreeWithDifferenceNorms_data();
    void boundsAgreeWithDifferenceNorms();
    void matrixFormAgreesWithMask();
    void endInterpolatingAndBezier();
    void jsrOfKnownPair();
    void cancelAndBudget();
};

void TestRegularity::bsplinesHaveRegularityDegree_data()
{
    QTest::addColumn<int>("degree");
    for (int d = 1; d <= 5; ++d)
        QTest::addRow("degree %d", d) << d;
}

void TestRegularity::bsplinesHaveRegularityDegree()
{
    QFETCH(int, degree);
    const Regularity r = schemeRegularity(bsplineScheme(degree), 10, budget(2.0));
    QVERIFY(r.applies);
    QCOMPARE(r.sumRules, degree + 1);
    // The (d+1)-th divided-difference mask is the single coefficient 2: lower = upper = d.
    QVERIFY2(std::abs(r.lower - degree) < 1e-9, qPrintable(QString::number(r.lower, 'g', 17)));
    QVERIFY2(std::abs(r.upper - degree) < 1e-9, qPrintable(QString::number(r.upper, 'g', 17)));
    QVERIFY(r.lower <= r.upper);
    QVERIFY(r.width() < 1e-9);
    QCOMPARE(r.smoothness, degree - 1);
    QCOMPARE(QString::fromStdString(r.smoothnessLabel()), QString("C^%1").arg(degree - 1));
    QVERIFY(r.convergent && !r.divergent);
}

void TestRegularity::chaikinIsQuadraticBSpline()
{
    const Regularity c = schemeRegularity(chaikinScheme(), 6, budget(2.0));
    QVERIFY(std::abs(c.lower - 2.0) < 1e-9 && std::abs(c.upper - 2.0) < 1e-9);
    QCOMPARE(c.smoothnessLabel(), std::string("C^1"));
    // General corner cutting (a, b) with b - a != 1/2 has one sum rule only: C^0 at most
    // reaching regularity < 2; the bounds stay ordered and inside (0, 2).
    const Regularity cc = schemeRegularity(cornerCuttingScheme(0.2, 0.7), 6, budget(1.0));
    QCOMPARE(cc.sumRules, 2);
    QVERIFY(cc.lower > 1.0 && cc.upper < 2.0 && cc.lower <= cc.upper);
}

void TestRegularity::ternaryQuadraticBSpline()
{
    // (1 + z + z^2)^3 / 9: the ternary quadratic B-spline, regularity 2.
    const Regularity r = maskRegularity({1. / 9, 3. / 9, 6. / 9, 7. / 9, 6. / 9, 3. / 9, 1. / 9},
                                        3, budget(1.0));
    QCOMPARE(r.arity, 3);
    QCOMPARE(r.sumRules, 3);
    QVERIFY(std::abs(r.lower - 2.0) < 1e-9 && std::abs(r.upper - 2.0) < 1e-9);
}

void TestRegularity::fourPointClassic()
{
    const Regularity r = schemeRegularity(fourPointScheme(1.0 / 16), 8, budget(2.0));
    QVERIFY(r.applies);
    QCOMPARE(r.sumRules, 4);   // reproduces cubics
    // Regularity exactly 2, not attained: C^1, and the interval contains 2 (to rounding).
    QVERIFY2(r.lower > 2.0 - 1e-6, qPrintable(QString::number(r.lower, 'g', 17)));
    QVERIFY(r.lower <= 2.0);
    QVERIFY(r.upper >= 2.0 - 1e-12 && r.upper <= 2.0 + 1e-9);
    QCOMPARE(r.smoothness, 1);
}

void TestRegularity::fourPointPiecewiseLinear()
{
    const Regularity r = schemeRegularity(fourPointScheme(0.0), 8, budget(2.0));
    QVERIFY(std::abs(r.lower - 1.0) < 1e-9 && std::abs(r.upper - 1.0) < 1e-9);
    QCOMPARE(r.smoothness, 0);
}

void TestRegularity::fourPointIsC1ForSmallPositiveOmega_data()
{
    QTest::addColumn<double>("omega");
    for (double w : {1.0 / 64, 1.0 / 32, 0.1, 0.12, 1.0 / 8})
        QTest::addRow("omega %g", w) << w;
}

void TestRegularity::fourPointIsC1ForSmallPositiveOmega()
{
    QFETCH(double, omega);
    const Regularity r = schemeRegularity(fourPointScheme(omega), 8, budget(1.0));
    QVERIFY2(r.lower > 1.0, qPrintable(QString::number(r.lower)));
    QVERIFY(r.smoothness >= 1);
    // Only omega = 1/16 reaches 2 (the only omega with four sum rules).
    QCOMPARE(r.sumRules, 2);
    QVERIFY(r.upper < 2.0);
    QVERIFY(r.lower <= r.upper);
    QVERIFY(r.width() < 0.02);
}

void TestRegularity::fourPointBeyondC1()
{
    // Past omega ~ 0.1927 (root of 32 w^3 + 4 w - 1, Hechler, Mößner & Reif 2009) the scheme
    // is no longer C^1; it is still convergent.
    const Regularity r = schemeRegularity(fourPointScheme(0.25), 8, budget(1.0));
    QVERIFY(r.upper < 1.0 && r.lower > 0.0);
    QCOMPARE(r.smoothnessLabel(), std::string("C^0"));
    const Regularity below = schemeRegularity(fourPointScheme(0.18), 8, budget(1.0));
    QVERIFY(below.lower > 1.0);
}

void TestRegularity::noDifferenceScheme()
{
    // 1 + z + z^2 (binary): a(-1) = 1 != 0, so no factor 1 + z.
    const Regularity r = maskRegularity({1.0, 1.0, 1.0}, 2);
    QVERIFY(!r.applies);
    QCOMPARE(r.sumRules, 0);
    QVERIFY(QString::fromStdString(r.message).startsWith("no difference scheme"));
    QCOMPARE(r.smoothnessLabel(), std::string("n/a"));
}

void TestRegularity::notConvergent()
{
    // Four-point with omega = 1: the first difference scheme does not contract.
    const Regularity r = schemeRegularity(fourPointScheme(1.0), 8, budget(1.0));
    QVERIFY(r.applies);
    QVERIFY(r.divergent);
    QVERIFY(r.upper <= 0.0);
    QCOMPARE(r.smoothnessLabel(), std::string("not convergent"));
    QVERIFY(QString::fromStdString(r.message).startsWith("not convergent"));
    // A mask with the factor but summing to 4: it doubles constants.
    const Regularity twice = maskRegularity({1.0, 2.0, 1.0}, 2);
    QVERIFY(twice.divergent);
}

void TestRegularity::boundsAgreeWithDifferenceNorms_data()
{
    QTest::addColumn<double>("omega");
    for (double w : {-0.1, 0.03, 0.1, 0.15, 0.3})
        QTest::addRow("four-point %g", w) << w;
}

void TestRegularity::boundsAgreeWithDifferenceNorms()
{
    QFETCH(double, omega);
    const UniformScheme s = fourPointScheme(omega);
    const Regularity r = schemeRegularity(s, 8, budget(1.0));
    const DifferenceMask d = dividedDifferenceMask(s.mask(), 2);
    // rho_n <= ||S_{a_n}^k||^(1/k) for every k: the certified lower bound on rho_n must obey it
    // (an independent computation on sequences, not on the transition matrices).
    for (int k = 1; k <= 10; ++k) {
        const double nk = std::pow(iteratedNorm(d.mask, 2, k), 1.0 / k);
        QVERIFY2(r.jsr.lower <= nk * (1 + 1e-9),
                 qPrintable(QString("k=%1: %2 > %3").arg(k).arg(r.jsr.lower).arg(nk)));
    }
    QVERIFY(r.jsr.lower <= r.jsr.upper);
}

void TestRegularity::matrixFormAgreesWithMask()
{
    // The same schemes analysed from their IFS matrices S_i (quotient by the generated
    // polynomials, join conditions): the same regularity.
    const Regularity cubic = matrixRegularity(bsplineScheme(3).matrices(7).S, budget(1.0));
    QVERIFY(std::abs(cubic.lower - 3.0) < 1e-9 && std::abs(cubic.upper - 3.0) < 1e-9);
    const Regularity chaikin = matrixRegularity(chaikinScheme().matrices(6).S, budget(1.0));
    QVERIFY(std::abs(chaikin.lower - 2.0) < 1e-9 && std::abs(chaikin.upper - 2.0) < 1e-9);
    const Regularity four = matrixRegularity(fourPointScheme(1.0 / 16).matrices(8).S, budget(1.0));
    QVERIFY(four.lower > 1.9 && four.lower <= 2.0 && four.upper >= 2.0 - 1e-9);
    QCOMPARE(four.smoothness, 1);
}

void TestRegularity::endInterpolatingAndBezier()
{
    const Regularity e = schemeRegularity(EndInterpolatingBSplineScheme(3), 7, budget(1.0));
    QVERIFY(std::abs(e.lower - 3.0) < 1e-9 && std::abs(e.upper - 3.0) < 1e-9);
    QCOMPARE(e.smoothness, 2);
    // With degree + 1 points the curve is one Bézier piece.
    QVERIFY(schemeRegularity(EndInterpolatingBSplineScheme(3), 4).infinite);
    const Regularity b = schemeRegularity(BezierScheme(3, 0.3), 4);
    QVERIFY(b.applies && b.infinite);
    QCOMPARE(b.smoothnessLabel(), std::string("C^infinity"));
    // User matrices whose pieces do not join: no regularity, said so.
    const Mat S1 = matrixFromRows({{1, 0}, {1, 0}});
    const Mat S2 = matrixFromRows({{0, 1}, {0, 1}});
    const Regularity split = matrixRegularity({S1, S2});
    QVERIFY(!split.applies);
    QVERIFY(QString::fromStdString(split.message).contains("do not join"));
}

void TestRegularity::jsrOfKnownPair()
{
    // JSR{[[1,1],[0,1]], [[1,0],[1,1]]} = golden ratio (rho(AB)^(1/2); Jungers 2009, §1.2).
    const std::vector<Mat> A{matrixFromRows({{1, 1}, {0, 1}}), matrixFromRows({{1, 0}, {1, 1}})};
    JsrOptions o;
    o.timeBudget = 1.0;
    int calls = 0;
    o.progress = [&](const JsrBounds &, double) { ++calls; };
    const JsrBounds b = jointSpectralRadius(A, o);
    const double phi = (1 + std::sqrt(5.0)) / 2;
    QVERIFY(b.lower <= phi && b.lower > phi - 1e-9);
    QVERIFY(b.upper >= phi && b.upper < phi + 0.05);
    QVERIFY(calls > 0);
    // Single matrix: JSR = spectral radius.
    const JsrBounds one = jointSpectralRadius({matrixFromRows({{0.5, 3}, {0, 0.25}})}, o);
    QVERIFY(one.lower <= 0.5 && one.lower > 0.5 - 1e-9 && one.upper >= 0.5);
}

void TestRegularity::cancelAndBudget()
{
    std::atomic<bool> cancel{true};
    RegularityOptions o = budget(30.0);
    o.cancel = &cancel;
    QElapsedTimer t;
    t.start();
    const Regularity r = schemeRegularity(fourPointScheme(0.1), 8, o);
    QVERIFY(t.elapsed() < awb::test::ms(5000));
    QVERIFY(r.jsr.cancelled);
    QVERIFY(r.lower <= r.upper);
    QVERIFY(QString::fromStdString(r.notes).contains("cancelled"));
    t.restart();
    const Regularity timed = schemeRegularity(fourPointScheme(0.1), 8, budget(0.3));
    QVERIFY(t.elapsed() < awb::test::ms(5000));
    QVERIFY(timed.lower > 1.0);
}

AWB_TEST_APPLESS_MAIN(TestRegularity)
#include "test_regularity.moc"
