// Subdivision matrices and their spectra against the numbers printed in the papers:
// 000 = Schaefer, Levin, Goldman, "Subdivision Schemes and Attractors" (SGP 2005);
// 004 = Ptáčková, "Fractals and Splines" (thesis, 2012).

#include "core/analysis/Geometry.h"
#include "core/ifs/Ifs.h"
#include "core/schemes/Scheme.h"
#include "core/analysis/Spectrum.h"

#include <QtTest>

#include "TestMain.h"

using namespace awb;

namespace {

Mat rows(std::initializer_list<std::initializer_list<double>> r) { return matrixFromRows(r); }

// Exact dyadic fractions: the printed matrices must come out to rounding error.
constexpr double kExact = 1e-14;

bool near(const Mat &a, const Mat &b, double tol)
{
    return a.rows() == b.rows() && a.cols() == b.cols() && (a - b).cwiseAbs().maxCoeff() <= tol;
}

std::string str(const Mat &m)
{
    std::ostringstream os;
    os << m;
    return os.str();
}

#define COMPARE_MAT(a, b, tol) QVERIFY2(near((a), (b), (tol)), (str(a) + "\n vs \n" + str(b)).c_str())

// Control points with an invertible lifting (last three points not collinear).
Mat samplePoints(int m)
{
    Mat P(m, 2);
    for (int i = 0; i < m; ++i)
        P.row(i) << i + 0.3 * std::sin(1.7 * i), 1.5 * std::cos(0.9 * i) + 0.1 * i * i;
    return P;
}

} // namespace

class TestSchemes : public QObject {
    Q_OBJECT
private slots:
    void cubicBSplineMatches000();
    void endInterpolatingCubicMatches000();
    void fourPointMatches000();
    void quadraticBezierMatches000();
    void thesisExample361();
    void thesisExample362ChaikinAndFixedPoints();
    void liftedMatricesHaveLastColumnEm();
    void localCubicMatrixEigenvalues();
    void deCasteljauEigenvalues();
    void thesisExample221();
    void bsplineRulesAllDegrees();
    void classicSubdivisionMatchesRefinement();
    void endInterpolatingAnyDegreeInterpolatesEnds();
    void masksMustSumToOne();
    void badParametersAreNamed();
    void userMatricesValidated();
    void subdominantKinds();
    void nonContractiveMapReported();
};

void TestSchemes::cubicBSplineMatches000()
{
    // 000 §2.1: the 5-point uniform cubic B-spline, S_1 and S_2 as printed.
    const auto sm = bsplineScheme(3).matrices(5);
    QCOMPARE(int(sm.S.size()), 2);
    const Mat S1 = rows({{.5, .5, 0, 0, 0}, {.125, .75, .125, 0, 0}, {0, .5, .5, 0, 0},
                         {0, .125, .75, .125, 0}, {0, 0, .5, .5, 0}});
    const Mat S2 = rows({{0, .5, .5, 0, 0}, {0, .125, .75, .125, 0}, {0, 0, .5, .5, 0},
                         {0, 0, .125, .75, .125}, {0, 0, 0, .5, .5}});
    COMPARE_MAT(sm.S[0], S1, kExact);
    COMPARE_MAT(sm.S[1], S2, kExact);
    // "the last 3 rows of S_1 are identical to the first 3 rows of S_2"
    QCOMPARE(sm.overlap, 3);
    QCOMPARE(int(sm.refinement().rows()), 7);
}

void TestSchemes::endInterpolatingCubicMatches000()
{
    // 000 §2.1: knots {0,0,0,1,2,2,2} refined to {0,0,0,1/2,1,1,1,3/2,2,2,2} by blossoming.
    const auto sm = EndInterpolatingBSplineScheme(3).matrices(5);
    const Mat S1 = rows({{1, 0, 0, 0, 0}, {.5, .5, 0, 0, 0}, {0, .75, .25, 0, 0},
                         {0, .375, .5, .125, 0}, {0, .25, .5, .25, 0}});
    const Mat S2 = rows({{0, .25, .5, .25, 0}, {0, .125, .5, .375, 0}, {0, 0, .25, .75, 0},
                         {0, 0, 0, .5, .5}, {0, 0, 0, 0, 1}});
    COMPARE_MAT(sm.S[0], S1, kExact);
    COMPARE_MAT(sm.S[1], S2, kExact);
    QCOMPARE(sm.overlap, 1);
}

void TestSchemes::fourPointMatches000()
{
    // 000 §2.3: four-point scheme (omega = 1/16) on 7 control points.
    const auto sm = fourPointScheme(1.0 / 16).matrices(7);
    const double a = -1.0 / 16, b = 9.0 / 16;
    const Mat S1 = rows({{0, 1, 0, 0, 0, 0, 0}, {a, b, b, a, 0, 0, 0}, {0, 0, 1, 0, 0, 0, 0},
                         {0, a, b, b, a, 0, 0}, {0, 0, 0, 1, 0, 0, 0}, {0, 0, a, b, b, a, 0},
                         {0, 0, 0, 0, 1, 0, 0}});
    const Mat S2 = rows({{0, 0, 1, 0, 0, 0, 0}, {0, a, b, b, a, 0, 0}, {0, 0, 0, 1, 0, 0, 0},
                         {0, 0, a, b, b, a, 0}, {0, 0, 0, 0, 1, 0, 0}, {0, 0, 0, a, b, b, a},
                         {0, 0, 0, 0, 0, 1, 0}});
    COMPARE_MAT(sm.S[0], S1, kExact);
    COMPARE_MAT(sm.S[1], S2, kExact);
}

void TestSchemes::quadraticBezierMatches000()
{
    // 000 §2.2: the two matrices of a quadratic Bézier curve.
    const auto sm = BezierScheme(2, 0.5).matrices(3);
    COMPARE_MAT(sm.S[0], rows({{1, 0, 0}, {.5, .5, 0}, {.25, .5, .25}}), kExact);
    COMPARE_MAT(sm.S[1], rows({{.25, .5, .25}, {0, .5, .5}, {0, 0, 1}}), kExact);
}

void TestSchemes::thesisExample361()
{
    // 004 Example 3.6.1: cubic B-spline on 4 control points.
    const auto sm = bsplineScheme(3).matrices(4);
    COMPARE_MAT(sm.S[0], rows({{.5, .5, 0, 0}, {.125, .75, .125, 0}, {0, .5, .5, 0},
                               {0, .125, .75, .125}}), kExact);
    COMPARE_MAT(sm.S[1], rows({{.125, .75, .125, 0}, {0, .5, .5, 0}, {0, .125, .75, .125},
                               {0, 0, .5, .5}}), kExact);
    // The lifted P printed there: [p | e_1 | 1].
    const Mat P = rows({{0, 0}, {1, 2}, {3, 2.5}, {3.5, 0}});
    const Lifting L = liftControlPoints(P);
    QVERIFY(L.invertible);
    COMPARE_MAT(L.lifted, rows({{0, 0, 1, 1}, {1, 2, 0, 1}, {3, 2.5, 0, 1}, {3.5, 0, 0, 1}}), 0.0);
    const auto ifs = buildSubdivisionIfs(bsplineScheme(3), P);
    for (const auto &f : ifs.lifted)
        QVERIFY(contractivity(f.A).eventuallyContractive);
}

void TestSchemes::thesisExample362ChaikinAndFixedPoints()
{
    // 004 Example 3.6.2 (S_2 read as NOTES.md says: the last five rows of the 8x5 matrix).
    const auto sm = chaikinScheme().matrices(5);
    QCOMPARE(int(sm.refinement().rows()), 8);
    COMPARE_MAT(sm.S[0], rows({{.75, .25, 0, 0, 0}, {.25, .75, 0, 0, 0}, {0, .75, .25, 0, 0},
                               {0, .25, .75, 0, 0}, {0, 0, .75, .25, 0}}), kExact);
    COMPARE_MAT(sm.S[1], rows({{0, .25, .75, 0, 0}, {0, 0, .75, .25, 0}, {0, 0, .25, .75, 0},
                               {0, 0, 0, .75, .25}, {0, 0, 0, .25, .75}}), kExact);
    const Mat P = rows({{0, 0}, {1, 4}, {4, 4}, {5, -1}, {7, 0}});
    const auto s = buildSubdivisionIfs(chaikinScheme(), P);
    QVERIFY(!s.barycentric());
    COMPARE_MAT(s.lifting.lifted, rows({{0, 0, 1, 0, 1}, {1, 4, 0, 1, 1}, {4, 4, 0, 0, 1},
                                        {5, -1, 0, 0, 1}, {7, 0, 0, 0, 1}}), 0.0);
    // x*_1 = b_1 (I - A_1)^-1 = (1/2, 2, 1/2, 1/2) and x*_2 = (6, -1/2, 0, 0); tolerance: the
    // inversions of a 5x5 matrix with entries <= 7, 1e-12.
    const auto x1 = fixedPoint(s.lifted[0].A, s.lifted[0].b);
    const auto x2 = fixedPoint(s.lifted[1].A, s.lifted[1].b);
    QVERIFY(x1 && x2);
    COMPARE_MAT(Mat(*x1), rows({{.5, 2, .5, .5}}), 1e-12);
    COMPARE_MAT(Mat(*x2), rows({{6, -.5, 0, 0}}), 1e-12);
}

void TestSchemes::liftedMatricesHaveLastColumnEm()
{
    // 000 eq. (3) / 004 eq. (3.24): M_i = P^-1 S_i P always ends in the column e_m.
    std::vector<std::pair<const CurveScheme *, int>> cases;
    const UniformScheme cubic = bsplineScheme(3), four = fourPointScheme(1.0 / 16),
                        quintic = bsplineScheme(5), chaikin = chaikinScheme();
    const EndInterpolatingBSplineScheme ei(3);
    const BezierScheme bez(4, 0.3);
    cases = {{&cubic, 5}, {&ei, 5}, {&four, 7}, {&quintic, 9}, {&chaikin, 6}, {&bez, 5}};
    for (auto [scheme, m] : cases) {
        const auto s = buildSubdivisionIfs(*scheme, samplePoints(m));
        QVERIFY2(!s.barycentric(), scheme->name().c_str());
        for (const auto &f : s.lifted) {
            Vec em = Vec::Zero(m);
            em(m - 1) = 1.0;
            QVERIFY2((f.M.col(m - 1) - em).cwiseAbs().maxCoeff() < 1e-11, scheme->name().c_str());
        }
    }
}

void TestSchemes::localCubicMatrixEigenvalues()
{
    // 004 Example 2.3.2: the local subdivision matrix of the cubic B-spline has eigenvalues
    // 1, 1/2, 1/4, 1/8, 1/8. It is the centred 5x5 block of the refinement matrix.
    const Mat local = bsplineScheme(3).refinementMatrix(5).middleRows(1, 5);
    COMPARE_MAT(local, rows({{.125, .75, .125, 0, 0}, {0, .5, .5, 0, 0}, {0, .125, .75, .125, 0},
                             {0, 0, .5, .5, 0}, {0, 0, .125, .75, .125}}), kExact);
    const Spectrum s = spectrum(local);
    const double expect[] = {1, .5, .25, .125, .125};
    for (int i = 0; i < 5; ++i) {
        QVERIFY(std::abs(s.values[i] - Complex(expect[i], 0)) < 1e-10);
    }
    QCOMPARE(s.multiplicity[3], 2);
    const Subdominant sub = subdominant(s);
    QVERIFY(sub.kind == SubdominantKind::RealPositive);
    QVERIFY(std::abs(sub.modulus - 0.5) < 1e-12);
}

void TestSchemes::deCasteljauEigenvalues()
{
    // 004 §2.2: L(1/2), R(1/2) of degree n have eigenvalues (1/2)^i, i = 0..n; the eigenvector of
    // 1 is the vector of ones. Triangular matrices: the values are exact to rounding.
    for (int n = 1; n <= 8; ++n) {
        for (const Mat &M : {deCasteljauL(n, 0.5), deCasteljauR(n, 0.5)}) {
            const Spectrum s = spectrum(M);
            for (int i = 0; i <= n; ++i)
                QVERIFY(std::abs(s.values[i] - std::pow(0.5, i)) < 1e-12);
            const CVec v = s.vectors[0] / s.vectors[0](0);
            QVERIFY((v - CVec::Ones(n + 1)).norm() < 1e-10);
        }
    }
    // Complex t of 004 §3.7: L and R are still row-stochastic.
    const CMat Lc = deCasteljauL(3, Complex(0.5, 0.5));
    QVERIFY((Lc.rowwise().sum() - CVec::Ones(4)).norm() < 1e-14);
}

void TestSchemes::thesisExample221()
{
    // 004 Example 2.2.1 (last row of L(1/2) is (1/8, 3/8, 3/8, 1/8); the text's last 3/8 is a
    // typo, NOTES.md).
    COMPARE_MAT(deCasteljauL(3, 0.5),
                rows({{1, 0, 0, 0}, {.5, .5, 0, 0}, {.25, .5, .25, 0}, {.125, .375, .375, .125}}),
                kExact);
    COMPARE_MAT(deCasteljauR(3, 0.5),
                rows({{.125, .375, .375, .125}, {0, .25, .5, .25}, {0, 0, .5, .5}, {0, 0, 0, 1}}),
                kExact);
}

void TestSchemes::bsplineRulesAllDegrees()
{
    // 004 eq. (2.7); degree 2 is Chaikin (2.8), degree 3 is (2.9).
    for (int n = 1; n <= 7; ++n) {
        const UniformScheme s = bsplineScheme(n);
        QCOMPARE(s.minControlPoints(), std::max(2, n + 1));
        const auto sm = s.matrices(n + 4);
        for (const Mat &S : sm.S)
            QVERIFY((S.rowwise().sum() - Vec::Ones(S.rows())).cwiseAbs().maxCoeff() < 1e-14);
        // The attractor is the uniform B-spline on the same control points: the shared rows of
        // the split carry the C^{n-1} join.
        QCOMPARE(sm.overlap, n);
    }
    const auto quad = bsplineScheme(2).matrices(5);
    const auto chaikin = chaikinScheme().matrices(5);
    COMPARE_MAT(quad.S[0], chaikin.S[0], kExact);
    COMPARE_MAT(quad.S[1], chaikin.S[1], kExact);
}

void TestSchemes::classicSubdivisionMatchesRefinement()
{
    const UniformScheme cubic = bsplineScheme(3);
    const Mat P = samplePoints(6);
    // One step of classic subdivision is the refinement matrix applied to P.
    COMPARE_MAT(subdivide(cubic, P, 1), cubic.refinementMatrix(6) * P, 1e-13);
    // Two steps: the refinement of the refined polygon.
    const Mat P1 = cubic.refinementMatrix(6) * P;
    COMPARE_MAT(subdivide(cubic, P, 2), cubic.refinementMatrix(int(P1.rows())) * P1, 1e-12);
    // Point count: m + (2^k - 1)(m - overlap) for a binary scheme.
    QCOMPARE(int(subdivide(cubic, P, 5).rows()), 6 + 31 * 3);
    // The polygon converges to the exact curve. Its end vertices lie one control-point spacing
    // outside the curve's domain, so the Hausdorff distance halves per step (ratio 4 over two
    // steps, within 10 %).
    const Mat exact = *cubic.exactCurve(P, 20000);
    const double d6 = hausdorffToCurve(subdivide(cubic, P, 6), exact);
    const double d8 = hausdorffToCurve(subdivide(cubic, P, 8), exact);
    QVERIFY2(std::abs(d6 / d8 - 4.0) < 0.4, qPrintable(QString::number(d6 / d8)));
}

void TestSchemes::endInterpolatingAnyDegreeInterpolatesEnds()
{
    for (int n = 2; n <= 5; ++n) {
        for (int m = n + 1; m <= n + 4; ++m) {
            const EndInterpolatingBSplineScheme s(n);
            const auto sm = s.matrices(m);
            // First row of S_1 is e_1 and last row of S_2 is e_m: the end points are fixed
            // points of f_1, f_2, so the curve interpolates them.
            QVERIFY(std::abs(sm.S[0](0, 0) - 1.0) < 1e-14);
            QVERIFY(std::abs(sm.S[1](m - 1, m - 1) - 1.0) < 1e-14);
            for (const Mat &S : sm.S)
                QVERIFY((S.rowwise().sum() - Vec::Ones(m)).cwiseAbs().maxCoeff() < 1e-13);
            QCOMPARE(sm.overlap, 1);
        }
    }
    // With m = n + 1 the curve is the Bézier curve: S_1, S_2 are L(1/2), R(1/2).
    const auto b = EndInterpolatingBSplineScheme(3).matrices(4);
    COMPARE_MAT(b.S[0], deCasteljauL(3, 0.5), 1e-14);
    COMPARE_MAT(b.S[1], deCasteljauR(3, 0.5), 1e-14);
}

void TestSchemes::masksMustSumToOne()
{
    try {
        UniformScheme("bad", 2, {SchemeRule{0, {0.5, 0.5}}, SchemeRule{0, {0.5, 0.25}}});
        QFAIL("a rule summing to 0.75 was accepted");
    } catch (const InputError &e) {
        QVERIFY2(QString(e.what()).contains("rule 2") && QString(e.what()).contains("0.75"),
                 e.what());
    }
    // Ternary scheme with arity 3 needs 3 rules.
    QVERIFY_THROWS_EXCEPTION(InputError, UniformScheme("t", 3, {SchemeRule{0, {1}}}));
    // A user mask of arity 3 (ternary quadratic B-spline) builds three matrices.
    const UniformScheme ternary("ternary", 3,
                                {SchemeRule{-1, {1.0 / 3, 2.0 / 3}}, SchemeRule{0, {1.0}},
                                 SchemeRule{0, {2.0 / 3, 1.0 / 3}}});
    const auto sm = ternary.matrices(5);
    QCOMPARE(int(sm.S.size()), 3);
    for (const Mat &S : sm.S)
        QVERIFY((S.rowwise().sum() - Vec::Ones(5)).cwiseAbs().maxCoeff() < 1e-14);
}

void TestSchemes::badParametersAreNamed()
{
    auto message = [](auto fn) {
        try {
            fn();
        } catch (const InputError &e) {
            return QString(e.what());
        }
        return QString();
    };
    QVERIFY(message([] { bsplineScheme(0); }).contains("degree"));
    QVERIFY(message([] { BezierScheme(3, 1.5); }).contains("strictly between 0 and 1"));
    QVERIFY(message([] { BezierScheme(3, std::nan("")); }).contains("t"));
    QVERIFY(message([] { cornerCuttingScheme(0.8, 0.2); }).contains("0 < a < b < 1"));
    QVERIFY(message([] { fourPointScheme(std::numeric_limits<double>::infinity()); })
                .contains("omega"));
    QVERIFY(message([] { bsplineScheme(3).matrices(3); }).contains("at least 4 control points"));
    QVERIFY(message([] { BezierScheme(2).matrices(4); }).contains("exactly 3 control points"));
    Mat P = samplePoints(5);
    P(1, 0) = std::nan("");
    const QString nanMsg = message([&] { buildSubdivisionIfs(bsplineScheme(3), P); });
    QVERIFY2(nanMsg.contains("control points") && nanMsg.contains("row 2")
                 && nanMsg.contains("not a finite number"),
             qPrintable(nanMsg));
}

void TestSchemes::userMatricesValidated()
{
    const auto cubic = bsplineScheme(3).matrices(5);
    const MatrixScheme user(cubic.S);
    QCOMPARE(user.matrices(5).overlap, 3);
    try {
        Mat bad = cubic.S[1];
        bad(2, 2) += 0.1;
        MatrixScheme({cubic.S[0], bad});
        QFAIL("accepted a row not summing to 1");
    } catch (const InputError &e) {
        QVERIFY2(QString(e.what()).contains("S_2, row 3 sums to 1.1"), e.what());
    }
    QVERIFY_THROWS_EXCEPTION(InputError, MatrixScheme({cubic.S[0], Mat::Identity(4, 4)}));
    QVERIFY_THROWS_EXCEPTION(InputError, MatrixScheme({cubic.S[0]}));
}

void TestSchemes::subdominantKinds()
{
    // Real negative (oscillation) and complex pair (spiral), 003 §4.
    Mat neg = Mat::Identity(3, 3);
    neg(1, 1) = -0.5;
    neg(2, 2) = 0.25;
    QVERIFY(subdominant(spectrum(neg)).kind == SubdominantKind::RealNegative);
    Mat rot = Mat::Zero(3, 3);
    rot(0, 0) = 1;
    rot.block(1, 1, 2, 2) << 0.3, -0.4, 0.4, 0.3;
    const Subdominant s = subdominant(spectrum(rot));
    QVERIFY(s.kind == SubdominantKind::ComplexPair);
    QVERIFY(std::abs(s.modulus - 0.5) < 1e-12);
    QVERIFY(QString::fromStdString(s.meaning()).contains("spiral"));
}

void TestSchemes::nonContractiveMapReported()
{
    // Rows sum to 1, but the map doubles distances: S_1 has eigenvalue 2.
    Mat S1(3, 3), S2(3, 3);
    S1 << 1, 0, 0, -1, 2, 0, 0, 0, 1;
    S2 << 0.5, 0.5, 0, 0, 0.5, 0.5, 0, 0, 1;
    const Mat P = rows({{0, 0}, {1, 1}, {2, 0}});
    const auto s = buildSubdivisionIfs({S1, S2}, 1, P);
    const IfsCheck check = checkIfs(s.ifs);
    QVERIFY(!check.contractive);
    QVERIFY2(QString::fromStdString(check.message).contains("map 1 is not contractive"),
             check.message.c_str());
    QVERIFY(QString::fromStdString(check.message).contains("2"));
    // The same maps in barycentric form: the eigenvalue 1 of the affine constraint does not
    // count, the eigenvalue 2 does.
    const IfsCheck bary = checkIfs(barycentricIfs({S1, S2}, P));
    QVERIFY(!bary.contractive);
    QVERIFY(checkIfs(barycentricIfs(bsplineScheme(3).matrices(5).S, samplePoints(5))).contractive);
}

AWB_TEST_APPLESS_MAIN(TestSchemes)
#include "test_schemes.moc"
