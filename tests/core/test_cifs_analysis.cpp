// Tests of what a controlled IFS contracts by (core/analysis/CifsAnalysis.h): the constrained
// joint spectral radius over admissible products, against cases whose value is known in closed
// form and against the unconstrained JSR of the maps a cycle can repeat; the cycles' spectra;
// the Lyapunov exponent of random iteration against its closed form for scalar arcs.

#include "core/analysis/CifsAnalysis.h"
#include "core/analysis/JointSpectralRadius.h"
#include "core/ifs/Cifs.h"

#include <QtTest>

#include "TestMain.h"

#include <QElapsedTimer>

#include <cmath>
#include <string>

using namespace awb;

namespace {

// A row-stochastic 2 x 2 matrix whose part on the segment's direction is the scalar r.
Mat segmentMap(double r)
{
    Mat S(2, 2);
    S << r, 1 - r, 0, 1;
    return S;
}

// Two segment states: A -> A (r = c), A -> B (a), B -> A (b). Admissible products are words
// of c and (ab), so rho_G = max(|c|, sqrt|ab|), although a alone may expand.
Cifs twoSegments(double a, double b, double c)
{
    Cifs cifs;
    Mat P(2, 2);
    P << 0, 0, 1, 0;
    cifs.addState("A", P);
    cifs.addState("B", P);
    cifs.addTransition("c", 0, 0, segmentMap(c));
    cifs.addTransition("a", 0, 1, segmentMap(a));
    cifs.addTransition("b", 1, 0, segmentMap(b));
    return cifs;
}

} // namespace

class TestCifsAnalysis : public QObject {
    Q_OBJECT
private slots:
    void arcLinearPartOfSquareMatricesIsTheBarycentricPart();
    void constrainedRadiusFollowsThePaths();
    void fernOfGasketsIsTheLargerOfItsLoops();
    void cyclesCarryTheirSpectra();
    void lyapunovMatchesItsClosedForm();
    void exponentiallyManyPathsStayBounded();
};

void TestCifsAnalysis::arcLinearPartOfSquareMatricesIsTheBarycentricPart()
{
    const Cifs c = fernSierpinskiCifs();
    for (const CifsTransition &t : c.transitions)
        QVERIFY((arcLinearPart(t.S) - barycentricPart(t.S)).norm() < 1e-15);
    // A rectangular arc: a segment (2 points) into a triangle (3 points): S is 2 x 3.
    Mat S(2, 3);
    S << 0.5, 0.5, 0, 0, 0.25, 0.75;
    const Mat R = arcLinearPart(S);
    QCOMPARE(R.rows(), 1);
    QCOMPARE(R.cols(), 2);
    // e_0 - e_1 of the segment goes to (0.5, 0.25, -0.75): coordinates (0.5, 0.25).
    QCOMPARE(R(0, 0), 0.5);
    QCOMPARE(R(0, 1), 0.25);
}

void TestCifsAnalysis::constrainedRadiusFollowsThePaths()
{
    // a = 1.6 expands, but every return to A through B multiplies by ab = 0.64: rho_G = 0.8.
    const CifsAnalysis r = analyseCifs(twoSegments(1.6, 0.4, 0.5));
    QVERIFY2(r.lower() <= 0.8 + 1e-12 && r.upper() >= 0.8 - 1e-12,
             qPrintable(QStringLiteral("[%1, %2]").arg(r.lower()).arg(r.upper())));
    QVERIFY(r.upper() - r.lower() < 1e-6);
    QVERIFY(r.contractive());
    // The unconstrained JSR of the three maps is 1.6: the graph is what makes it contract.
    QVERIFY(jointSpectralRadius({Mat::Constant(1, 1, 1.6), Mat::Constant(1, 1, 0.4),
                                 Mat::Constant(1, 1, 0.5)})
                .lower > 1.59);
    // The self-loop dominates when |c| > sqrt(ab): 0.9.
    const CifsAnalysis s = analyseCifs(twoSegments(1.6, 0.4, 0.9));
    QVERIFY(std::abs(s.lower() - 0.9) < 1e-9 && std::abs(s.upper() - 0.9) < 1e-6);
    // ab = 1.21: some path does not contract.
    const CifsAnalysis e = analyseCifs(twoSegments(2.2, 0.55, 0.5));
    QVERIFY(!e.contractive());
    QVERIFY(e.lower() > 1.09);
}

void TestCifsAnalysis::fernOfGasketsIsTheLargerOfItsLoops()
{
    // 003 Fig. 4: the fern state loops on its three other maps, the Sierpinski state on
    // (lambda + e_k)/2; the redirected arc lies on no cycle. So rho_G is the larger of the
    // JSR of those fern maps' linear parts (the plane maps' A, similar to the barycentric
    // parts) and 1/2.
    for (int redirected = 0; redirected < 4; ++redirected) {
        const CifsAnalysis r = analyseCifs(fernSierpinskiCifs(redirected));
        std::vector<Mat> plane;
        const auto maps = barnsleyFernMaps();
        for (int k = 0; k < 4; ++k)
            if (k != redirected)
                plane.push_back(maps[size_t(k)].A);
        JsrOptions o;
        o.timeBudget = 1.0;
        const JsrBounds fern = jointSpectralRadius(plane, o);
        const double lo = std::max(fern.lower, 0.5), hi = std::max(fern.upper, 0.5);
        QVERIFY2(r.lower() <= hi + 1e-9 && r.upper() >= lo - 1e-9,
                 qPrintable(QStringLiteral("redirected %1: [%2, %3] against [%4, %5]")
                                .arg(redirected)
                                .arg(r.lower())
                                .arg(r.upper())
                                .arg(lo)
                                .arg(hi)));
        QVERIFY(r.contractive());
        QVERIFY(r.lyapunov && *r.lyapunov < 0);
    }
}

void TestCifsAnalysis::cyclesCarryTheirSpectra()
{
    const CifsAnalysis r = analyseCifs(fernSierpinskiCifs(2));
    // Fern: loops T0, T1, T3; Sierpinski: S0, S1, S2; the arc T2 is on no cycle.
    QCOMPARE(int(r.cycles.size()), 6);
    QVERIFY(r.cyclesComplete);
    int halves = 0;
    for (const CifsCycle &c : r.cycles) {
        QCOMPARE(int(c.arcs.size()), 1);
        QCOMPARE(int(c.eigenvalues.size()), 2);
        if (c.state == 1) {
            ++halves;
            for (const Complex &z : c.eigenvalues)
                QVERIFY(std::abs(z - Complex(0.5)) < 1e-12);
        }
    }
    QCOMPARE(halves, 3);
    // The two-state case: the cycle A -a-> B -b-> A has the eigenvalue ab = 0.64.
    const CifsAnalysis s = analyseCifs(twoSegments(1.6, 0.4, 0.5));
    QCOMPARE(int(s.cycles.size()), 2);
    bool found = false;
    for (const CifsCycle &c : s.cycles)
        if (c.arcs.size() == 2) {
            found = true;
            QVERIFY(std::abs(c.spectralRadius - 0.64) < 1e-12);
            QVERIFY(std::abs(c.perArc - 0.8) < 1e-12);
        }
    QVERIFY(found);
}

void TestCifsAnalysis::lyapunovMatchesItsClosedForm()
{
    // From A: c or a, each 1/2; from B: b. Stationary: A 2/3, B 1/3, so the exponent is
    // 2/3 (log c + log a)/2 + 1/3 log b = log(a b c) / 3.
    const CifsAnalysis r = analyseCifs(twoSegments(1.6, 0.4, 0.5));
    QVERIFY(r.lyapunov);
    const double exact = std::log(1.6 * 0.4 * 0.5) / 3.0;
    QVERIFY2(std::abs(*r.lyapunov - exact) < 0.01,
             qPrintable(QStringLiteral("%1 against %2").arg(*r.lyapunov).arg(exact)));
    // Weights move it: a twice as likely as c (from A: c 1/3, a 2/3) makes the stationary
    // law A 3/5, B 2/5, and the exponent (log c + 2 log a + 2 log b) / 5.
    Cifs w = twoSegments(1.6, 0.4, 0.5);
    w.transitions[1].weight = 2.0;
    const CifsAnalysis q = analyseCifs(w);
    const double weighted = (std::log(0.5) + 2 * std::log(1.6) + 2 * std::log(0.4)) / 5.0;
    QVERIFY2(std::abs(*q.lyapunov - weighted) < 0.01,
             qPrintable(QStringLiteral("%1 against %2").arg(*q.lyapunov).arg(weighted)));
}

void TestCifsAnalysis::exponentiallyManyPathsStayBounded()
{
    // 31 layers of 2 states, each joined to both of the next (2^31 simple paths), the last
    // layer into a state 0 that only loops: one cycle, but a walk over all paths would take
    // hours. The analysis ends, says its list may be incomplete, and still bounds rho_G.
    Cifs c;
    Mat P(2, 2);
    P << 0, 0, 1, 0;
    // Names appended, not concatenated: GCC 12 warns falsely on "x" + std::to_string at -O3.
    const auto name = [](const char *prefix, int k) {
        std::string n(prefix);
        n += std::to_string(k);
        return n;
    };
    for (int q = 0; q < 63; ++q)
        c.addState(name("q", q), P);
    c.addTransition("loop", 0, 0, segmentMap(0.5));
    for (int layer = 0; layer < 31; ++layer)
        for (int a = 0; a < 2; ++a) {
            const int from = 1 + 2 * layer + a;
            if (layer == 30) {
                c.addTransition(name("back", a), from, 0, segmentMap(0.5));
                continue;
            }
            for (int b = 0; b < 2; ++b)
                c.addTransition(name("t", 2 * from + b), from, 1 + 2 * (layer + 1) + b,
                                segmentMap(0.5));
        }
    QElapsedTimer timer;
    timer.start();
    const CifsAnalysis r = analyseCifs(c);
    QVERIFY(timer.elapsed() < 60000);
    QVERIFY(!r.cyclesComplete);
    QVERIFY(r.upper() <= 0.5 + 1e-6 && r.lower() >= 0.5 - 1e-9);
}

AWB_TEST_APPLESS_MAIN(TestCifsAnalysis)
#include "test_cifs_analysis.moc"
