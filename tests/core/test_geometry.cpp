// Measures of point sets: Hausdorff distance (004 eq. (3.11)), box-counting dimension
// (004 eq. (3.15)), lengths and areas, and exact curve evaluation (004 §1).

#include "core/schemes/Curves.h"
#include "core/analysis/Geometry.h"

#include <QtTest>

#include "TestMain.h"
#include <random>

using namespace awb;

class TestGeometry : public QObject {
    Q_OBJECT
private slots:
    void hausdorffOfKnownSets();
    void nearestAgreesWithBruteForce();
    void nearestOnCurvesAndDegenerateSets();
    void boxDimensionOfLineAndSquare();
    void lengthAndArea();
    void bezierExample111();
    void bsplineBasisExample121();
};

void TestGeometry::hausdorffOfKnownSets()
{
    Mat A(2, 2), B(3, 2);
    A << 0, 0, 1, 0;
    B << 0, 0, 1, 0, 1, 3;
    QCOMPARE(directedDistance(A, B), 0.0);
    QCOMPARE(directedDistance(B, A), 3.0);      // d(A,B) != d(B,A) in general (004 §3.2)
    QCOMPARE(hausdorffDistance(A, B), 3.0);
    // A point above the middle of a segment: 0.5 from the polyline, not sqrt(0.5^2+0.5^2).
    Mat p(1, 2), seg(2, 2);
    p << 0.5, 0.5;
    seg << 0, 0, 1, 0;
    QVERIFY(std::abs(distanceToPolyline(p, seg) - 0.5) < 1e-15);
}

void TestGeometry::nearestAgreesWithBruteForce()
{
    std::mt19937 rng(7);
    std::normal_distribution<double> g(0, 1);
    for (int dim : {2, 3}) {
        Mat A(3000, dim), B(2000, dim);
        for (Eigen::Index i = 0; i < A.size(); ++i)
            A.data()[i] = g(rng) * 3;
        for (Eigen::Index i = 0; i < B.size(); ++i)
            B.data()[i] = g(rng) * (i % 2 ? 1.0 : 0.1);
        double brute = 0;
        for (Eigen::Index i = 0; i < A.rows(); ++i)
            brute = std::max(brute, std::sqrt((B.rowwise() - A.row(i)).rowwise().squaredNorm().minCoeff()));
        QVERIFY(std::abs(directedDistance(A, B) - brute) < 1e-12);
    }
}

// The sets attractors are made of: points on a curve (a spiral and a Koch-like zigzag in the
// plane, a helix in space), many copies of one point, 1D sets; every query's distance and index
// against brute force, and within() against the distance.
void TestGeometry::nearestOnCurvesAndDegenerateSets()
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-2, 2);
    auto check = [&](const Mat &B, const char *what) {
        const PointIndex index(B);
        Mat q(1, B.cols());
        for (int k = 0; k < 600; ++k) {
            for (Eigen::Index a = 0; a < B.cols(); ++a)
                q(0, a) = k % 3 == 0 ? B(k % B.rows(), a) + 1e-3 * u(rng) : u(rng) * (k % 5 ? 1 : 40);
            Eigen::Index best;
            const double brute = std::sqrt((B.rowwise() - q.row(0)).rowwise().squaredNorm().minCoeff(&best));
            Eigen::Index got = -1;
            const double d = index.nearest(q.data(), &got);
            if (std::abs(d - brute) > 1e-14 || std::abs((B.row(got) - q.row(0)).norm() - brute) > 1e-14)
                QFAIL(qPrintable(QString("%1: query %2 found %3, brute force %4").arg(what).arg(k).arg(d).arg(brute)));
            QCOMPARE(index.within(q.data(), brute * 1.001 + 1e-300), true);
            QCOMPARE(index.within(q.data(), brute * 0.999), false);
        }
    };
    const int n = 6000;  // a curve's cells held sqrt(n) points each in the old grid
    Mat spiral(n, 2), zigzag(n, 2), helix(n, 3), same(500, 2), line1(n, 1);
    for (int i = 0; i < n; ++i) {
        const double t = 12.0 * i / n;
        spiral.row(i) << t * std::cos(t), t * std::sin(t);
        zigzag.row(i) << double(i) / n, (i / 37) % 2 ? double(i % 37) / 37 : 1 - double(i % 37) / 37;
        helix.row(i) << std::cos(3 * t), std::sin(3 * t), t / 12;
        line1(i, 0) = std::sin(t) * t;
    }
    same.rowwise() = RowVec::Constant(2, 0.25);
    check(spiral, "spiral");
    check(zigzag, "zigzag");
    check(helix, "helix");
    check(same, "one point 500 times");
    check(line1, "points of a line (1 coordinate)");
    // Directed distance on a curve equals brute force (the early break changes nothing).
    Mat A(1000, 2);
    for (Eigen::Index i = 0; i < A.size(); ++i)
        A.data()[i] = u(rng) * 5;
    double brute = 0;
    for (Eigen::Index i = 0; i < A.rows(); ++i)
        brute = std::max(brute, std::sqrt((spiral.rowwise() - A.row(i)).rowwise().squaredNorm().minCoeff()));
    QCOMPARE(directedDistance(A, spiral), brute);
}

void TestGeometry::boxDimensionOfLineAndSquare()
{
    Mat line(200000, 2), square(400000, 2);
    for (int i = 0; i < line.rows(); ++i)
        line.row(i) << i / 200000.0, 0.5 * i / 200000.0;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < square.rows(); ++i)
        square.row(i) << u(rng), u(rng);
    const BoxDimension l = boxCountingDimension(line);
    const BoxDimension s = boxCountingDimension(square);
    QVERIFY(l.valid && s.valid);
    // A segment is exactly 1-dimensional; the random square saturates only at the fine end.
    QVERIFY2(std::abs(l.dimension - 1.0) < 0.01, qPrintable(QString::number(l.dimension)));
    QVERIFY2(std::abs(s.dimension - 2.0) < 0.03, qPrintable(QString::number(s.dimension)));
    QVERIFY(l.r2 > 0.999);
    QVERIFY(!boxCountingDimension(Mat::Zero(5, 2)).valid);
}

void TestGeometry::lengthAndArea()
{
    Mat sq(4, 2);
    sq << 0, 0, 2, 0, 2, 2, 0, 2;
    QCOMPARE(polygonLength(sq), 6.0);
    QCOMPARE(polygonLength(sq, true), 8.0);
    QCOMPARE(polygonArea(sq), 4.0);
}

void TestGeometry::bezierExample111()
{
    // 004 Example 1.1.1: c(t) = (3/2 t - 1/2 t^3, 3t - 3t^2).
    Mat P(4, 2);
    P << 0, 0, 0.5, 1, 1, 1, 1, 0;
    const std::vector<double> ts = {0, 0.2, 0.5, 0.9, 1};
    const Mat c = bezierPoints(P, ts);
    for (size_t i = 0; i < ts.size(); ++i) {
        const double t = ts[i];
        QVERIFY(std::abs(c(i, 0) - (1.5 * t - 0.5 * t * t * t)) < 1e-15);
        QVERIFY(std::abs(c(i, 1) - (3 * t - 3 * t * t)) < 1e-15);
    }
}

void TestGeometry::bsplineBasisExample121()
{
    // 004 Example 1.2.1: knots (0, 1, 2, 3), N_0^2(t) = t^2/2 on [0,1), -3/2 + 3t - t^2 on
    // [1,2), (3-t)^2/2 on [2,3]. In Ramshaw's labelling (control point P_i = f(u_i, u_{i+1}))
    // the function supported on [0, 3] belongs to f(1, 2): with knots u = (0, 1, 2, 3, 4, 5)
    // that is P_1, and the curve's domain [u_1, u_4] = [1, 4] holds its last two pieces.
    const BSplineBasis b(2, {0, 1, 2, 3, 4, 5});
    for (double t : {1.0, 1.25, 1.5, 1.99})
        QVERIFY(std::abs(b.pointWeights(t)(1) - (-1.5 + 3 * t - t * t)) < 1e-14);
    for (double t : {2.0, 2.5, 2.9})
        QVERIFY(std::abs(b.pointWeights(t)(1) - 0.5 * (3 - t) * (3 - t)) < 1e-14);
    QVERIFY(std::abs(b.pointWeights(1.0).sum() - 1.0) < 1e-15);
}

AWB_TEST_APPLESS_MAIN(TestGeometry)
#include "test_geometry.moc"
