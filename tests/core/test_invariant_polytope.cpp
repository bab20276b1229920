// Exact joint spectral radius by the invariant polytope algorithm (InvariantPolytope.h) and
// the exact Hölder regularity it gives (Regularity.h), against the literature:
//  * B-splines of degree d: regularity exactly d.
//  * Daubechies' orthonormal scaling functions (Daubechies, "Ten Lectures on Wavelets", 1992,
//    Table 6.1; the masks by spectral factorisation, §6.1): D4 has Hölder exponent
//    2 - log2(1 + sqrt 3) = 0.5500156 (Daubechies & Lagarias, SIAM J. Math. Anal. 23 (1992)),
//    D6 1.0878, D8 1.6179 (Daubechies & Lagarias 1992, Table; Guglielmi & Protasov 2016).
//  * Dubuc-Deslauriers interpolatory schemes: 4-point 2 (not attained), 6-point 2.830,
//    8-point 3.551 (Rioul, SIAM J. Math. Anal. 23 (1992), Table 1).
//  * Random families: every closed certificate passes the independent verifier, tampered
//    ones do not.

#include "core/analysis/InvariantPolytope.h"
#include "core/analysis/LinearProgram.h"
#include "core/analysis/Regularity.h"
#include "core/schemes/Scheme.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include "TestMain.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <map>
#include <random>

using namespace awb;

namespace {

// (1 + z)^(d+1) / 2^d: the B-spline of degree d (sum 2).
std::vector<double> bsplineMask(int d)
{
    std::vector<double> c{1.0};
    for (int k = 0; k <= d; ++k) {
        std::vector<double> n(c.size() + 1, 0.0);
        for (size_t i = 0; i < c.size(); ++i) {
            n[i] += c[i];
            n[i + 1] += c[i];
        }
        c.swap(n);
    }
    for (double &v : c)
        v /= std::pow(2.0, d);
    return c;
}

// Closed forms (Daubechies 1992, §6.4), normalised to sum 2.
std::vector<double> daubechies4Mask()
{
    const double s = std::sqrt(3.0);
    return {(1 + s) / 4, (3 + s) / 4, (3 - s) / 4, (1 - s) / 4};
}

std::vector<double> daubechies6Mask()
{
    const double r = std::sqrt(10.0), q = std::sqrt(5.0 + 2.0 * std::sqrt(10.0));
    return {(1 + r + q) / 16, (5 + r + 3 * q) / 16, (10 - 2 * r + 2 * q) / 16,
            (10 - 2 * r - 2 * q) / 16, (5 + r - 3 * q) / 16, (1 + r - q) / 16};
}

// Daubechies' D_{2N} by spectral factorisation: |m0|^2 = cos^{2N}(x/2) P(sin^2(x/2)) with
// P(y) = sum_{k<N} C(N-1+k, k) y^k; z^{N-1} P((2 - z - 1/z) / 4) has the roots r, 1/r; the
// mask is (1 + z)^N prod (z - r) over the roots outside the unit circle (the orientation of
// the closed forms above), normalised to sum 2.
std::vector<double> daubechiesBySpectralFactorisation(int N)
{
    using Poly = std::vector<Complex>;   // coefficients, lowest degree first
    auto mul = [](const Poly &a, const Poly &b) {
        Poly c(a.size() + b.size() - 1, 0.0);
        for (size_t i = 0; i < a.size(); ++i)
            for (size_t j = 0; j < b.size(); ++j)
                c[i + j] += a[i] * b[j];
        return c;
    };
    Poly Q(size_t(2 * N - 1), 0.0);
    const Poly t{-0.25, 0.5, -0.25};   // z * y = -(z - 1)^2 / 4
    for (int k = 0; k < N; ++k) {
        double binom = 1.0;
        for (int j = 1; j <= k; ++j)
            binom = binom * (N - 1 + j) / j;
        Poly term{binom};
        for (int j = 0; j < k; ++j)
            term = mul(term, t);
        for (size_t i = 0; i < term.size(); ++i)
            Q[i + size_t(N - 1 - k)] += term[i];
    }
    const int deg = 2 * N - 2;
    std::vector<Complex> outside;
    if (deg > 0) {
        Mat C = Mat::Zero(deg, deg);
        for (int i = 1; i < deg; ++i)
            C(i, i - 1) = 1.0;
        for (int i = 0; i < deg; ++i)
            C(i, deg - 1) = -Q[size_t(i)].real() / Q[size_t(deg)].real();
        const CVec roots = Eigen::EigenSolver<Mat>(C, false).eigenvalues();
        for (Complex r : roots) {
            for (int it = 0; it < 5; ++it) {   // Newton polish
                Complex p = 0.0, dp = 0.0;
                for (int i = deg; i >= 0; --i) {
                    dp = dp * r + p;
                    p = p * r + Q[size_t(i)];
                }
                if (std::abs(dp) > 0)
                    r -= p / dp;
            }
            if (std::abs(r) > 1.0)
                outside.push_back(r);
        }
    }
    Poly h{1.0};
    for (int k = 0; k < N; ++k)
        h = mul(h, Poly{1.0, 1.0});
    for (Complex r : outside)
        h = mul(h, Poly{-r, 1.0});
    std::vector<double> c;
    double sum = 0.0;
    for (Complex v : h)
        sum += v.real();
    for (Complex v : h)
        c.push_back(2.0 * v.real() / sum);
    return c;
}

// Dubuc-Deslauriers 2m-point masks, exact dyadic coefficients.
std::vector<double> ddMask(int points)
{
    std::vector<double> c;
    double scale = 1.0;
    if (points == 4) {
        c = {-1, 0, 9, 16, 9, 0, -1};
        scale = 16;
    } else if (points == 6) {
        c = {3, 0, -25, 0, 150, 256, 150, 0, -25, 0, 3};
        scale = 256;
    } else {
        c = {-5, 0, 49, 0, -245, 0, 1225, 2048, 1225, 0, -245, 0, 49, 0, -5};
        scale = 2048;
    }
    for (double &v : c)
        v /= scale;
    return c;
}

// Portable pseudo-random numbers in [-1, 1] (the raw mt19937 stream is specified).
Mat randomMatrix(std::mt19937 &g, int L)
{
    Mat M(L, L);
    for (int i = 0; i < L; ++i)
        for (int j = 0; j < L; ++j)
            M(i, j) = double(g()) / 4294967296.0 * 2.0 - 1.0;
    return M;
}

Vec v2(double a, double b)
{
    return Vec(Eigen::Vector2d(a, b));
}

RegularityOptions budget(double jsr, double polytope)
{
    RegularityOptions o;
    o.timeBudget = jsr;
    o.polytopeBudget = polytope;
    return o;
}

// The literature's masks are analysed once: the table and the value tests share the results.
struct Analysed {
    Regularity r;
    double seconds = 0.0;
};

const Analysed &analysed(const QString &name, const std::vector<double> &mask)
{
    static std::map<QString, Analysed> cache;
    auto it = cache.find(name);
    if (it == cache.end()) {
        QElapsedTimer t;
        t.start();
        Analysed a{maskRegularity(mask, 2, budget(1.0, 5.0)), 0.0};
        a.seconds = double(t.elapsed()) / 1000.0;
        it = cache.emplace(name, std::move(a)).first;
    }
    return it->second;
}

QString word(const std::vector<int> &w)
{
    QStringList s;
    for (int i : w)
        s << QString("T%1").arg(i);
    return s.join(' ');
}

} // namespace

class TestInvariantPolytope : public QObject {
    Q_OBJECT
private slots:
    void linearProgram();
    void trivialCases();
    void bsplines_data();
    void bsplines();
    void daubechiesMasks();
    void daubechies4();
    void daubechies6And8();
    void dubucDeslauriers();
    void matrixRegularityIsExact();
    void randomFamilies();
    void tamperedCertificates();
    void reducibleFamily();
    void complexLeadingEigenvalue();
    void table();
};

void TestInvariantPolytope::linearProgram()
{
    // min x1 + x2 s.t. x1 + 2 x2 = 4, x1 - x2 = 1 (x >= 0): x = (2, 1), value 3.
    const LpResult lp = solveStandardLp(matrixFromRows({{1, 2}, {1, -1}}),
                                        Vec(Eigen::Vector2d(4, 1)), Vec::Ones(2));
    QCOMPARE(lp.status, LpResult::Optimal);
    QVERIFY(std::abs(lp.value - 3.0) < 1e-12);
    // Infeasible: x1 + x2 = -1.
    QCOMPARE(solveStandardLp(matrixFromRows({{1, 1}}), Vec::Constant(1, -1.0), Vec::Ones(2))
                 .status,
             LpResult::Infeasible);
    // ||y||_V for the square's vertices (1,0), (0,1): the l1 norm; (1,1) adds a shortcut.
    Mat V = matrixFromRows({{1, 0, 1}, {0, 1, 1}});
    const AbsoluteCombination a = absoluteCombination(V.leftCols(2), v2(0.3, -0.5));
    QVERIFY(a.feasible && std::abs(a.norm - 0.8) < 1e-14);
    const AbsoluteCombination b = absoluteCombination(V, v2(0.7, 0.7));
    QVERIFY(b.feasible && std::abs(b.norm - 0.7) < 1e-14);
    // Out of the span.
    QVERIFY(!absoluteCombination(V.leftCols(1), v2(0.0, 1.0)).feasible);
    // Many random columns: the LP optimum is below every feasible guess and reproduces y.
    std::mt19937 g(7);
    Mat W(6, 300);
    for (int k = 0; k < 50; ++k)
        W.middleCols(6 * k, 6) = randomMatrix(g, 6);
    const Vec y = randomMatrix(g, 6).col(0);
    const AbsoluteCombination c = absoluteCombination(W, y);
    QVERIFY(c.feasible);
    Vec lambda = Vec::Zero(W.cols());
    for (const auto &[j, v] : c.lambda)
        lambda(j) = v;
    QVERIFY((W * lambda - y).norm() < 1e-12);
    const Vec ls = W.leftCols(6).colPivHouseholderQr().solve(y);
    QVERIFY(c.norm <= ls.cwiseAbs().sum() + 1e-12);
}

void TestInvariantPolytope::trivialCases()
{
    const PolytopeResult empty = invariantPolytope({Mat(0, 0), Mat(0, 0)});
    QVERIFY(empty.closed && empty.upper == 0.0);
    const PolytopeResult zero = invariantPolytope({Mat::Zero(3, 3), Mat::Zero(3, 3)});
    QVERIFY(zero.closed && zero.lower == 0.0 && zero.upper == 0.0);
    QVERIFY(verifyPolytopeCertificate(*zero.certificate).ok);
    // L = 1: JSR = max |a_i|.
    const PolytopeResult one = invariantPolytope({Mat::Constant(1, 1, -3.0),
                                                  Mat::Constant(1, 1, 2.0)});
    QVERIFY(one.closed);
    QCOMPARE(one.smp, std::vector<int>{0});
    QVERIFY(one.lower <= 3.0 && one.upper >= 3.0 && one.upper - one.lower < 1e-12);
    // Nilpotent pair: every product has spectral radius 0: no s.m.p.
    const PolytopeResult nil = invariantPolytope({matrixFromRows({{0, 1}, {0, 0}}),
                                                  matrixFromRows({{0, 2}, {0, 0}})});
    QVERIFY(!nil.applies && !nil.closed);
    QVERIFY_THROWS_EXCEPTION(InputError, invariantPolytope({Mat::Zero(2, 2), Mat::Zero(3, 3)}));
}

void TestInvariantPolytope::bsplines_data()
{
    QTest::addColumn<int>("degree");
    for (int d = 1; d <= 5; ++d)
        QTest::addRow("degree %d", d) << d;
}

void TestInvariantPolytope::bsplines()
{
    QFETCH(int, degree);
    const Regularity r = maskRegularity(bsplineMask(degree), 2, budget(1.0, 1.0));
    QVERIFY(r.exact);
    QVERIFY(r.lower <= degree && r.upper >= degree);
    QVERIFY(r.upper - r.lower < 1e-10);
    QCOMPARE(r.smp, std::vector<int>{0});   // T_0 = (2), T_1 = (0)
    QVERIFY(verifyPolytopeCertificate(*r.certificate).ok);
}

void TestInvariantPolytope::daubechiesMasks()
{
    // The spectral factorisation reproduces the closed forms.
    const auto d4 = daubechiesBySpectralFactorisation(2), d6 = daubechiesBySpectralFactorisation(3);
    const auto c4 = daubechies4Mask(), c6 = daubechies6Mask();
    QCOMPARE(d4.size(), size_t(4));
    QCOMPARE(d6.size(), size_t(6));
    for (size_t k = 0; k < 4; ++k)
        QVERIFY2(std::abs(d4[k] - c4[k]) < 1e-14, qPrintable(QString::number(d4[k], 'g', 17)));
    for (size_t k = 0; k < 6; ++k)
        QVERIFY2(std::abs(d6[k] - c6[k]) < 1e-14, qPrintable(QString::number(d6[k], 'g', 17)));
    // D8: the standard coefficients (Daubechies 1992, Table 6.1) times sqrt 2.
    const std::vector<double> table{0.2303778133088964, 0.7148465705529154, 0.6308807679298587,
                                    -0.0279837694168599, -0.1870348117190931,
                                    0.0308413818355607, 0.0328830116668852, -0.0105974017850690};
    const auto d8 = daubechiesBySpectralFactorisation(4);
    QCOMPARE(d8.size(), size_t(8));
    for (size_t k = 0; k < 8; ++k)
        QVERIFY2(std::abs(d8[k] - table[k] * std::sqrt(2.0)) < 1e-13,
                 qPrintable(QString::number(d8[k], 'g', 17)));
}

void TestInvariantPolytope::daubechies4()
{
    const Regularity r = maskRegularity(daubechies4Mask(), 2, budget(1.0, 2.0));
    const double expected = 2.0 - std::log2(1.0 + std::sqrt(3.0));
    QCOMPARE(r.sumRules, 2);
    QVERIFY(r.exact);
    QVERIFY2(r.lower <= expected + 1e-14 && r.upper >= expected - 1e-14,
             qPrintable(QString("[%1, %2]").arg(r.lower, 0, 'g', 17).arg(r.upper, 0, 'g', 17)));
    QVERIFY(r.upper - r.lower < 1e-10);
    QCOMPARE(r.smp, std::vector<int>{0});   // T_0 = (1 + sqrt 3)
    QVERIFY(std::abs(r.lower - 0.5500156) < 1e-7);
}

void TestInvariantPolytope::daubechies6And8()
{
    struct Case {
        int N;
        double literature;
    };
    for (const Case c : {Case{3, 1.0878}, Case{4, 1.6179}}) {
        const Regularity &r = analysed(QString("Daubechies D%1").arg(2 * c.N),
                                       daubechiesBySpectralFactorisation(c.N)).r;
        QVERIFY(r.applies);
        QCOMPARE(r.sumRules, c.N);
        const QString info = QString("D%1: [%2, %3] exact %4 smp (%5): %6")
                                 .arg(2 * c.N)
                                 .arg(r.lower, 0, 'g', 12)
                                 .arg(r.upper, 0, 'g', 12)
                                 .arg(r.exact)
                                 .arg(word(r.smp))
                                 .arg(QString::fromStdString(r.polytopeNote));
        // The bounds contain the literature value (4 digits) in any case.
        QVERIFY2(r.lower <= c.literature + 1e-4 && r.upper >= c.literature - 1e-4,
                 qPrintable(info));
        if (r.exact) {
            QVERIFY2(std::abs(r.lower - c.literature) < 1e-4, qPrintable(info));
            QVERIFY(r.upper - r.lower < 1e-10);
            QVERIFY(verifyPolytopeCertificate(*r.certificate).ok);
        }
        qInfo("%s", qPrintable(info));
    }
}

void TestInvariantPolytope::dubucDeslauriers()
{
    struct Case {
        int points;
        double literature;
    };
    for (const Case c : {Case{4, 2.0}, Case{6, 2.830}, Case{8, 3.551}}) {
        const Regularity &r = analysed(QString("Dubuc-Deslauriers %1-point").arg(c.points),
                                       ddMask(c.points)).r;
        QVERIFY(r.applies);
        const QString info = QString("DD %1-point: [%2, %3] exact %4 smp (%5): %6")
                                 .arg(c.points)
                                 .arg(r.lower, 0, 'g', 12)
                                 .arg(r.upper, 0, 'g', 12)
                                 .arg(r.exact)
                                 .arg(word(r.smp))
                                 .arg(QString::fromStdString(r.polytopeNote));
        QVERIFY2(r.lower <= c.literature + 1e-3 && r.upper >= c.literature - 1e-3,
                 qPrintable(info));
        // Never an exact claim with a wrong value.
        if (r.exact) {
            QVERIFY2(std::abs(r.lower - c.literature) < 1e-3, qPrintable(info));
            QVERIFY(verifyPolytopeCertificate(*r.certificate).ok);
        }
        qInfo("%s", qPrintable(info));
    }
}

void TestInvariantPolytope::matrixRegularityIsExact()
{
    // The IFS matrices' quotient maps (matrixRegularity) give the same exact values.
    const Regularity cubic = matrixRegularity(bsplineScheme(3).matrices(7).S, budget(1.0, 2.0));
    // The cubic B-spline's quotient maps are nilpotent (the pieces are cubics; the joins cap
    // the regularity at 3): the JSR is 0 up to rounding, and no polytope is claimed.
    QVERIFY(!cubic.exact);
    QVERIFY2(QString::fromStdString(cubic.polytopeNote).contains("nilpotent"),
             cubic.polytopeNote.c_str());
    QVERIFY(std::abs(cubic.lower - 3.0) < 1e-9 && std::abs(cubic.upper - 3.0) < 1e-9);
    const Regularity four = matrixRegularity(fourPointScheme(1.0 / 16).matrices(8).S,
                                             budget(1.0, 2.0));
    qInfo("four-point from its matrices: [%.12f, %.12f] exact %d: %s", four.lower, four.upper,
          int(four.exact), four.polytopeNote.c_str());
    QVERIFY(four.lower <= 2.0 + 1e-9 && four.upper >= 2.0 - 1e-9);
    if (four.exact) {
        QVERIFY(four.width() < 1e-9);
        QVERIFY(verifyPolytopeCertificate(*four.certificate).ok);
        QVERIFY(QString::fromStdString(four.method).contains("invariant polytope"));
    }
}

void TestInvariantPolytope::randomFamilies()
{
    int closed = 0, tried = 0;
    for (unsigned seed = 1; seed <= 12; ++seed) {
        std::mt19937 g(seed);
        const int K = 2 + int(seed % 2);
        std::vector<Mat> A;
        for (int i = 0; i < K; ++i)
            A.push_back(randomMatrix(g, 3));
        PolytopeOptions o;
        o.timeBudget = 2.0;
        const PolytopeResult p = invariantPolytope(A, o);
        ++tried;
        JsrOptions jo;
        jo.timeBudget = 0.3;
        const JsrBounds b = jointSpectralRadius(A, jo);
        // Both are certified: the brackets intersect.
        QVERIFY(p.lower <= b.upper * (1 + 1e-12));
        if (!p.closed)
            continue;
        ++closed;
        QVERIFY(p.upper >= b.lower * (1 - 1e-12));
        QVERIFY(p.upper - p.lower < 1e-10 * p.upper);
        const PolytopeVerdict v = verifyPolytopeCertificate(*p.certificate);
        QVERIFY2(v.ok, v.message.c_str());
        QCOMPARE(v.upper, p.upper);
        // The JSON text parses, and its numbers read back to the same doubles.
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson(
            QByteArray::fromStdString(certificateJson(*p.certificate)), &error);
        QCOMPARE(error.error, QJsonParseError::NoError);
        const QJsonObject json = doc.object();
        QCOMPARE(json["rhoHat"].toDouble(), p.certificate->rhoHat);
        const QJsonArray vertices = json["vertices"].toArray();
        QCOMPARE(vertices.size(), qsizetype(p.certificate->vertices.size()));
        for (qsizetype j = 0; j < vertices.size(); ++j)
            for (int k = 0; k < 3; ++k)
                QCOMPARE(vertices[j].toArray()[k].toDouble(),
                         p.certificate->vertices[size_t(j)](k));
        QCOMPARE(json["lambda"].toArray().size(), vertices.size());
        QCOMPARE(json["matrices"].toArray()[0].toArray()[1].toArray()[2].toDouble(), A[0](1, 2));
    }
    qInfo("random 3 x 3 families: %d of %d closed", closed, tried);
    QVERIFY(closed >= tried / 2);
}

void TestInvariantPolytope::tamperedCertificates()
{
    // A random family whose s.m.p. has length >= 2 (so that a shorter word differs).
    std::shared_ptr<const PolytopeCertificate> cert;
    for (unsigned seed = 1; seed <= 60 && !cert; ++seed) {
        std::mt19937 g(1000 + seed);
        const std::vector<Mat> A{randomMatrix(g, 3), randomMatrix(g, 3)};
        const PolytopeResult p = invariantPolytope(A);
        if (p.closed && p.smp.size() >= 2)
            cert = p.certificate;
    }
    QVERIFY(cert);
    QVERIFY(verifyPolytopeCertificate(*cert).ok);
    {
        PolytopeCertificate c = *cert;
        c.matrices[0](1, 2) += 1e-3;
        const PolytopeVerdict v = verifyPolytopeCertificate(c);
        QVERIFY(!v.ok);
        qInfo("changed matrix entry: %s", v.message.c_str());
    }
    {
        // The same change with rhoHat made consistent again: the polytope is no longer
        // invariant, and a (vertex, map) is named.
        PolytopeCertificate c = *cert;
        c.matrices[0](1, 2) += 1e-3;
        Mat P = Mat::Identity(3, 3);
        for (int i : c.smp)
            P = P * c.matrices[size_t(i)];
        c.rhoHat = std::pow(spectralRadiusOf(P), 1.0 / double(c.smp.size()));
        const PolytopeVerdict v = verifyPolytopeCertificate(c);
        QVERIFY(!v.ok);
        QVERIFY(v.failingVertex >= 0 && v.failingMap >= 0);
        qInfo("changed matrix entry, consistent rhoHat: %s", v.message.c_str());
    }
    {
        PolytopeCertificate c = *cert;
        c.vertices[0](0) += 1e-3;   // the s.m.p.'s leading eigenvector: on the boundary
        const PolytopeVerdict v = verifyPolytopeCertificate(c);
        QVERIFY(!v.ok);
        QVERIFY(v.failingVertex >= 0 && v.failingMap >= 0);
        qInfo("changed vertex: %s", v.message.c_str());
    }
    {
        PolytopeCertificate c = *cert;
        c.smp.pop_back();
        const PolytopeVerdict v = verifyPolytopeCertificate(c);
        QVERIFY(!v.ok);
        QVERIFY(QString::fromStdString(v.message).contains("s.m.p. word"));
    }
    {
        PolytopeCertificate c = *cert;
        bool scaled = false;
        for (auto &row : c.lambda)
            for (auto &l : row)
                if (!scaled && !l.empty()) {
                    for (auto &e : l)
                        e.second *= 1.01;
                    scaled = true;
                }
        const PolytopeVerdict v = verifyPolytopeCertificate(c);
        QVERIFY(!v.ok);
        QCOMPARE(v.failingVertex, 0);
        qInfo("scaled lambda: %s", v.message.c_str());
    }
    {
        PolytopeCertificate c = *cert;
        c.rhoHat *= 1.0 + 1e-6;
        QVERIFY(!verifyPolytopeCertificate(c).ok);
        c = *cert;
        c.vertices.resize(1);
        c.lambda.resize(1);
        QVERIFY(!verifyPolytopeCertificate(c).ok);
    }
}

void TestInvariantPolytope::reducibleFamily()
{
    // Block upper triangular: W = span(e1, e2) invariant; the diagonal blocks have JSR 2
    // (on W) and 1.5 (the quotient). The polytope is first found on W, then extended.
    const Mat A0 = matrixFromRows({{2, 0, 1}, {0, 1, 1}, {0, 0, 1.5}});
    const Mat A1 = matrixFromRows({{0, 1, 0}, {1, 0, -1}, {0, 0, -1}});
    const PolytopeResult p = invariantPolytope({A0, A1});
    QVERIFY2(p.closed, p.message.c_str());
    QVERIFY(p.extended);
    QVERIFY(p.lower <= 2.0 && p.upper >= 2.0 && p.upper - p.lower < 1e-10);
    QVERIFY(verifyPolytopeCertificate(*p.certificate).ok);
}

void TestInvariantPolytope::complexLeadingEigenvalue()
{
    // A rotation by 90 degrees dominates: the real polytope algorithm does not apply.
    const PolytopeResult p = invariantPolytope({matrixFromRows({{0, -1}, {1, 0}}),
                                                matrixFromRows({{0.5, 0}, {0, 0.2}})});
    QVERIFY(!p.applies && !p.closed);
    QVERIFY(QString::fromStdString(p.message).contains("complex"));
}

void TestInvariantPolytope::table()
{
    struct Row {
        QString name;
        std::vector<double> mask;
    };
    std::vector<Row> rows;
    for (int d = 1; d <= 5; ++d)
        rows.push_back({QString("B-spline degree %1").arg(d), bsplineMask(d)});
    rows.push_back({"Daubechies D4", daubechies4Mask()});
    rows.push_back({"Daubechies D6", daubechiesBySpectralFactorisation(3)});
    rows.push_back({"Daubechies D8", daubechiesBySpectralFactorisation(4)});
    for (int pts : {4, 6, 8})
        rows.push_back({QString("Dubuc-Deslauriers %1-point").arg(pts), ddMask(pts)});
    qInfo("%-28s %-7s %-34s %-8s %-11s %s", "scheme", "closed", "Hoelder regularity",
          "s.m.p.", "polytope s", "all s (with the branch and bound)");
    for (const Row &row : rows) {
        const Analysed &a = analysed(row.name, row.mask);
        const Regularity &r = a.r;
        const QString value = r.exact ? QString::number(r.lower, 'f', 12)
                                      : QString("[%1, %2]").arg(r.lower, 0, 'f', 6)
                                            .arg(r.upper, 0, 'f', 6);
        QElapsedTimer t;
        t.start();
        const PolytopeResult p = invariantPolytope(r.transition);
        const double polytopeSeconds = double(t.nsecsElapsed()) * 1e-9;
        QCOMPARE(p.closed, r.exact);
        qInfo("%-28s %-7s %-34s %-8s %-11.3f %.2f", qPrintable(row.name), r.exact ? "yes" : "no",
              qPrintable(value), qPrintable(word(r.exact ? r.smp : r.jsr.product)),
              polytopeSeconds, a.seconds);
        QVERIFY(r.lower <= r.upper);
    }
}

AWB_TEST_APPLESS_MAIN(TestInvariantPolytope)
#include "test_invariant_polytope.moc"
