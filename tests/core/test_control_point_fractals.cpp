// Tests of fractals with control points (000 §4): the printed Koch and Sierpinski matrices, the
// agreement of their subdivision attractors with the classic IFS, dimensions, locality of a
// control point, and the general recipe in both weight modes.
#include "core/ifs/Attractor.h"
#include "core/schemes/ControlPointFractal.h"
#include "core/analysis/Geometry.h"
#include "core/analysis/Spectrum.h"

#include <QtTest>

#include "TestMain.h"
#include <cmath>

using namespace awb;

namespace {

Mat collect(const Ifs &ifs, const Mat &start, int depth,
            std::vector<std::uint8_t> *pieces = nullptr)
{
    PointCollector sink(ifs.views.front());
    iterate(ifs, StartSet::points(start), depth, sink);
    if (pieces)
        *pieces = sink.firstSymbols();
    return sink.points();
}

// Rows of X whose piece (map applied last) is `piece`.
Mat piece(const Mat &X, const std::vector<std::uint8_t> &pieces, int which)
{
    std::vector<Eigen::Index> rows;
    for (size_t r = 0; r < pieces.size(); ++r)
        if (pieces[r] == which)
            rows.push_back(Eigen::Index(r));
    Mat out(rows.size(), X.cols());
    for (size_t r = 0; r < rows.size(); ++r)
        out.row(r) = X.row(rows[r]);
    return out;
}

template<class F>
QString inputError(F f)
{
    try {
        f();
    } catch (const InputError &e) {
        return QString::fromUtf8(e.what());
    }
    return QStringLiteral("<no InputError>");
}

// Printed matrices as (numerator, denominator) pairs, typed from 000 §4 independently of the
// implementation; entry (r, c) is num[r][c] / den.
Mat printed(std::initializer_list<std::initializer_list<int>> num, double den)
{
    Mat S(num.size(), num.begin()->size());
    int r = 0;
    for (const auto &row : num) {
        int c = 0;
        for (int v : row)
            S(r, c++) = v / den;
        ++r;
    }
    return S;
}

std::vector<Mat> printedKoch()
{
    // 000 §4.1, in thirds.
    return {printed({{3, 0, 0, 0, 0}, {2, 1, 0, 0, 0}, {2, 0, 1, 0, 0}, {1, 2, 0, 0, 0},
                     {0, 3, 0, 0, 0}}, 3),
            printed({{0, 3, 0, 0, 0}, {0, 2, 1, 0, 0}, {1, 0, 2, 0, 0}, {0, 1, 2, 0, 0},
                     {0, 0, 3, 0, 0}}, 3),
            printed({{0, 0, 3, 0, 0}, {0, 0, 2, 1, 0}, {0, 0, 2, 0, 1}, {0, 0, 1, 2, 0},
                     {0, 0, 0, 3, 0}}, 3),
            printed({{0, 0, 0, 3, 0}, {0, 0, 0, 2, 1}, {0, 0, 1, 0, 2}, {0, 0, 0, 1, 2},
                     {0, 0, 0, 0, 3}}, 3)};
}

std::vector<Mat> printedSierpinski()
{
    // 000 §4.2, in eighths.
    return {printed({{8, 0, 0, 0, 0, 0}, {3, 6, -1, 0, 0, 0}, {0, 8, 0, 0, 0, 0},
                     {0, 4, 0, 0, 0, 4}, {0, 0, 0, 0, 0, 8}, {3, 0, 0, 0, -1, 6}}, 8),
            printed({{0, 8, 0, 0, 0, 0}, {-1, 6, 3, 0, 0, 0}, {0, 0, 8, 0, 0, 0},
                     {0, 0, 3, 6, -1, 0}, {0, 0, 0, 8, 0, 0}, {0, 4, 0, 4, 0, 0}}, 8),
            printed({{0, 0, 0, 0, 0, 8}, {0, 0, 0, 4, 0, 4}, {0, 0, 0, 8, 0, 0},
                     {0, 0, -1, 6, 3, 0}, {0, 0, 0, 0, 8, 0}, {-1, 0, 0, 0, 3, 6}}, 8)};
}

ControlPointFractal presetByName(const QString &name)
{
    return name == "koch" ? kochControlPointFractal() : sierpinskiControlPointFractal();
}

} // namespace

class TestControlPointFractals : public QObject
{
    Q_OBJECT

private slots:
    void printedMatrices_data();
    void printedMatrices();
    void imagesOfControlPoints_data() { presets(); }
    void imagesOfControlPoints();
    void attractorMatchesClassic_data();
    void attractorMatchesClassic();
    void boxDimension_data();
    void boxDimension();
    void liftedSierpinski();
    void movingControlPointIsLocal();
    void singularLifting();
    void recipeReproducesKoch();
    void nearestTieBreak();
    void recipeLeastNorm_data() { presets(); }
    void recipeLeastNorm();
    void recipeSierpinskiNearest();
    void badInput();

private:
    void presets()
    {
        QTest::addColumn<QString>("name");
        QTest::newRow("koch") << "koch";
        QTest::newRow("sierpinski") << "sierpinski";
    }
};

void TestControlPointFractals::printedMatrices_data() { presets(); }

void TestControlPointFractals::printedMatrices()
{
    QFETCH(QString, name);
    const ControlPointFractal f = presetByName(name);
    const std::vector<Mat> expected = name == "koch" ? printedKoch() : printedSierpinski();
    QCOMPARE(f.S.size(), expected.size());
    QCOMPARE(f.classicMaps.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        // Exact: every printed entry is a ratio of small integers, computed the same way.
        QVERIFY2(f.S[i] == expected[i], qPrintable(QString("S_%1 differs").arg(i + 1)));
        QVERIFY((f.S[i].rowwise().sum().array() - 1.0).abs().maxCoeff() < 1e-15);
    }
    // Koch pieces follow the curve (one shared point each); the gasket's do not.
    QCOMPARE(f.overlap, name == "koch" ? 1 : 0);
}

void TestControlPointFractals::imagesOfControlPoints()
{
    QFETCH(QString, name);
    const ControlPointFractal f = presetByName(name);
    for (size_t i = 0; i < f.S.size(); ++i) {
        // 000 §4: row j of S_i holds the affine weights of f_i(P_j). With entries of size <= 1
        // and coordinates <= 1 the round-off is a few ulps: 1e-14.
        const Mat diff = f.S[i] * f.controlPoints - applyMap(f.classicMaps[i], f.controlPoints);
        QVERIFY2(diff.cwiseAbs().maxCoeff() < 1e-14, qPrintable(QString("map %1").arg(i + 1)));
    }
}

void TestControlPointFractals::attractorMatchesClassic_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("depth");
    QTest::newRow("koch") << "koch" << 7;
    QTest::newRow("sierpinski") << "sierpinski" << 8;
}

void TestControlPointFractals::attractorMatchesClassic()
{
    QFETCH(QString, name);
    QFETCH(int, depth);
    const ControlPointFractal f = presetByName(name);
    const SubdivisionIfs sub = controlPointFractalIfs(f);
    QVERIFY(!sub.barycentric()); // the canonical points lift (last three not collinear)
    // Same start points in both: the control points and two points off the fractal.
    Mat start(f.controlPoints.rows() + 2, 2);
    start << f.controlPoints, 0.3, 0.9, -0.2, 0.1;
    const Mat lifted = collect(sub.ifs, sub.toIfsSpace(start), depth);
    const Mat classic = collect(classicIfs(f), start, depth);
    QCOMPARE(lifted.rows(), classic.rows());
    // With S_i P = f_i(P), the projection of x M_i is f_i(projection of x) for every lifted x
    // (x = λ P~, Σλ = 1), so the two sets agree up to round-off of the lifted products.
    const double dH = hausdorffDistance(lifted, classic);
    QVERIFY2(dH < 1e-12, qPrintable(QString::number(dH)));
    QVERIFY((lifted - classic).cwiseAbs().maxCoeff() < 1e-12); // even point by point
}

void TestControlPointFractals::boxDimension_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("depth");
    QTest::addColumn<double>("expected");
    QTest::addColumn<double>("tolerance");
    // Tolerances (the core's box counter, dyadic boxes on the bounding box, >= 8 points per box):
    // * Koch, ratio 1/3 on a dyadic grid: the box counts oscillate with log(1/eps) at a period
    //   incommensurate with the grid (local slopes 1.15..1.49 between levels), so a fit over
    //   the ~11 octaves that 4^10 points allow is off by a few per cent: 0.04 (3 %).
    // * Gasket: N(2^-n) = c 3^n plus a term of order 2^n from boxes crossing the slanted sides,
    //   which biases the slope upwards by an amount decaying like (2/3)^n; the fit from 3^12
    //   points reaches level ~9 and lands near 1.60: 0.03 (2 %).
    QTest::newRow("koch") << "koch" << 10 << std::log(4.0) / std::log(3.0) << 0.04;
    QTest::newRow("sierpinski") << "sierpinski" << 12 << std::log(3.0) / std::log(2.0) << 0.03;
}

void TestControlPointFractals::boxDimension()
{
    QFETCH(QString, name);
    QFETCH(int, depth);
    QFETCH(double, expected);
    QFETCH(double, tolerance);
    const ControlPointFractal f = presetByName(name);
    const SubdivisionIfs sub = controlPointFractalIfs(f);
    // One start point: 4^10 (Koch) or 3^12 (gasket) points, each within ratio^depth * diameter
    // of the attractor, far below the smallest box used.
    const Mat pts = collect(sub.ifs, sub.toIfsSpace(f.controlPoints.topRows(1)), depth);
    const BoxDimension box = boxCountingDimension(pts);
    QVERIFY2(box.valid, box.note.c_str());
    QVERIFY2(std::abs(box.dimension - expected) < tolerance,
             qPrintable(QString("%1 vs %2 (levels %3..%4)").arg(box.dimension).arg(expected)
                            .arg(box.levelFrom).arg(box.levelTo)));
}

void TestControlPointFractals::liftedSierpinski()
{
    const SubdivisionIfs sub = controlPointFractalIfs(sierpinskiControlPointFractal());
    QCOMPARE(sub.lifted.size(), size_t(3));
    for (const LiftedMap &M : sub.lifted) {
        QCOMPARE(M.M.rows(), 6);
        QCOMPARE(M.M.cols(), 6);
        // 000 eq. (3): the last column of P^-1 S_i P is (0, ..., 0, 1)^T.
        QVERIFY((M.M.col(5) - Vec::Unit(6, 5)).cwiseAbs().maxCoeff() < 1e-13);
    }
    const IfsCheck check = checkIfs(sub.ifs);
    QVERIFY2(check.contractive, check.message.c_str());
}

void TestControlPointFractals::movingControlPointIsLocal()
{
    // 000 Fig. 10 (bottom): moving a control point deforms the Koch curve locally. S_4 has
    // zero columns 1 and 2, so the piece f_4(A) = attractor of the control points S_4 P does not
    // depend on P_1; the piece f_1(A) does.
    const ControlPointFractal f = kochControlPointFractal();
    Mat moved = f.controlPoints;
    moved.row(0) << 0.1, 0.2;
    const int depth = 6;
    for (IfsForm form : {IfsForm::Lifted, IfsForm::Barycentric}) {
        const SubdivisionIfs a = controlPointFractalIfs(f, f.controlPoints, form);
        const SubdivisionIfs b = controlPointFractalIfs(f, moved, form);
        // Start from the control points themselves (homogeneous rows of the lifted P, or the
        // unit vectors in barycentric form): their barycentric coordinates do not depend on P.
        const Mat startA = form == IfsForm::Lifted ? a.toIfsSpace(a.lifting.lifted)
                                                   : Mat(Mat::Identity(5, 5));
        const Mat startB = form == IfsForm::Lifted ? b.toIfsSpace(b.lifting.lifted) : startA;
        std::vector<std::uint8_t> pa, pb;
        const Mat A = collect(a.ifs, startA, depth, &pa);
        const Mat B = collect(b.ifs, startB, depth, &pb);
        QVERIFY(pa == pb);
        const double right = (piece(A, pa, 3) - piece(B, pb, 3)).cwiseAbs().maxCoeff();
        const double left = (piece(A, pa, 0) - piece(B, pb, 0)).cwiseAbs().maxCoeff();
        // Barycentric: λ S_w S_4 P multiplies P_1 by exact zeros, so the piece is bit-identical.
        // Lifted: P~^-1 mixes all points, so only round-off (1e-12) is left.
        if (form == IfsForm::Barycentric)
            QCOMPARE(right, 0.0);
        else
            QVERIFY2(right < 1e-12, qPrintable(QString::number(right)));
        QVERIFY2(left > 0.05, qPrintable(QString::number(left))); // P_1 moved by ~0.22
    }
}

void TestControlPointFractals::singularLifting()
{
    // NOTES.md: the lifted P is singular when the last three control points are collinear.
    // Moving Koch's P_3 onto the base line does that; the IFS falls back to barycentric form
    // and still draws the deformed curve (here: a flat one, all S_i P on the x-axis).
    const ControlPointFractal f = kochControlPointFractal();
    Mat flat = f.controlPoints;
    flat(2, 1) = 0;
    const SubdivisionIfs sub = controlPointFractalIfs(f, flat);
    QVERIFY(sub.barycentric());
    QVERIFY(sub.lifting.reason.find("collinear") != std::string::npos);
    const Mat pts = collect(sub.ifs, Mat(Mat::Identity(5, 5)), 4);
    QVERIFY(pts.col(1).cwiseAbs().maxCoeff() < 1e-15);
    QVERIFY(inputError([&] { controlPointFractalIfs(f, flat, IfsForm::Lifted); })
                .contains("collinear"));
}

void TestControlPointFractals::recipeReproducesKoch()
{
    // 000 §4.1: "barycentric coordinates with respect to the three closest control points".
    const ControlPointFractal f = kochControlPointFractal();
    const ControlPointMatrices r = controlPointMatrices(f.classicMaps, f.controlPoints);
    QVERIFY(r.mode == AffineWeights::NearestBarycentric);
    const std::vector<Mat> expected = printedKoch();
    for (size_t i = 0; i < expected.size(); ++i) {
        // 3 x 3 solves with entries <= 1: 1e-14 covers their round-off.
        const double err = (r.S[i] - expected[i]).cwiseAbs().maxCoeff();
        QVERIFY2(err < 1e-14, qPrintable(QString("S_%1: %2").arg(i + 1).arg(err)));
    }
    QVERIFY(r.maxResidual < 1e-14);
    QCOMPARE(r.overlap, 1);

    // Affine weights do not change under a similarity T(x) = x s + t applied to the points and
    // conjugating the maps (f' = T f T^-1: A' = A, b' = b s + t - t A). Far from the origin and
    // small (s = 1e-2 at 1e3) the coordinates keep ~11 digits of the shape: 1e-9.
    const double scale = 1e-2;
    const RowVec t = RowVec::Constant(2, 1e3);
    Mat Q = scale * f.controlPoints;
    Q.rowwise() += t;
    std::vector<AffineMap> conj = f.classicMaps;
    for (AffineMap &g : conj)
        g.b = g.b * scale + t - t * g.A;
    const ControlPointMatrices moved = controlPointMatrices(conj, Q);
    for (size_t i = 0; i < expected.size(); ++i)
        QVERIFY((moved.S[i] - expected[i]).cwiseAbs().maxCoeff() < 1e-9);
}

void TestControlPointFractals::nearestTieBreak()
{
    // y = (1, 1) is √2 from A = (0,0) and B = (2,0), and √5 from both D = (0,-1) and C = (3,2)
    // (squared distances 2 and 5 are exact in floating point, so the tie is exact). D comes
    // first, but in A, B, D the weights are (3/2, 1/2, -1) (sum |w| = 3) while in A, B, C they
    // are (3/4, -1/4, 1/2) (sum |w| = 3/2): the smaller sum wins, as for Koch's f_3(P_3).
    Mat P(4, 2);
    P << 0, 0, 2, 0, 0, -1, 3, 2;
    const RowVec w = nearestBarycentricWeights(P, RowVec(RowVec::Ones(2)));
    RowVec expected(4);
    expected << 0.75, -0.25, 0, 0.5;
    QVERIFY2((w - expected).cwiseAbs().maxCoeff() < 1e-15,
             qPrintable(QString("%1 %2 %3 %4").arg(w(0)).arg(w(1)).arg(w(2)).arg(w(3))));
    // Least norm uses all four points and still reproduces y.
    const RowVec l = leastNormWeights(P, RowVec(RowVec::Ones(2)));
    QVERIFY((l * P - RowVec::Ones(2)).cwiseAbs().maxCoeff() < 1e-15);
    QVERIFY(std::abs(l.sum() - 1) < 1e-15);
    QVERIFY(l.norm() < w.norm());
}

void TestControlPointFractals::recipeLeastNorm()
{
    QFETCH(QString, name);
    const ControlPointFractal f = presetByName(name);
    const ControlPointMatrices r =
        controlPointMatrices(f.classicMaps, f.controlPoints, AffineWeights::LeastNorm);
    QVERIFY(r.mode == AffineWeights::LeastNorm);
    QCOMPARE(r.S.size(), f.classicMaps.size());
    for (size_t i = 0; i < r.S.size(); ++i) {
        const Mat diff = r.S[i] * f.controlPoints - applyMap(f.classicMaps[i], f.controlPoints);
        QVERIFY(diff.cwiseAbs().maxCoeff() < 1e-14); // a least-squares solve: a few ulps
        QVERIFY((r.S[i].rowwise().sum().array() - 1.0).abs().maxCoeff() < 1e-14);
        QVERIFY(r.residuals[i] < 1e-14);
        // Least norm uses every control point, unlike the printed three-point rules.
        QVERIFY(r.S[i] != f.S[i]);
    }
    // Different weights, same attractor on the canonical points (S_i P = f_i(P) again).
    const SubdivisionIfs sub = buildSubdivisionIfs(r.S, r.overlap, f.controlPoints);
    const Mat start = f.controlPoints.topRows(2);
    const double dH = hausdorffDistance(collect(sub.ifs, sub.toIfsSpace(start), 6),
                                        collect(classicIfs(f), start, 6));
    QVERIFY2(dH < 1e-12, qPrintable(QString::number(dH)));
}

void TestControlPointFractals::recipeSierpinskiNearest()
{
    // The recipe does not reproduce the printed Lagrange rules of 000 §4.2 (they are a choice),
    // but its matrices must still satisfy S_i P = f_i(P) with weights on 3 points per row.
    const ControlPointFractal f = sierpinskiControlPointFractal();
    const ControlPointMatrices r = controlPointMatrices(f.classicMaps, f.controlPoints);
    QVERIFY(r.maxResidual < 1e-14);
    for (const Mat &S : r.S)
        for (Eigen::Index j = 0; j < S.rows(); ++j)
            QVERIFY((S.row(j).array().abs() > 1e-15).count() <= 3);
    // f_1 scales about C_1 = P_1: f_1(P_1) = P_1 has the single weight 1.
    QCOMPARE(r.S[0](0, 0), 1.0);
}

void TestControlPointFractals::badInput()
{
    const ControlPointFractal koch = kochControlPointFractal();
    Mat collinear(4, 2);
    collinear << 0, 0, 1, 0, 2, 0, 3, 0;
    QVERIFY(inputError([&] { controlPointMatrices(koch.classicMaps, collinear); })
                .contains("collinear"));
    const Mat two = koch.controlPoints.topRows(2);
    QVERIFY(inputError([&] { controlPointMatrices(koch.classicMaps, two); }).contains("too few"));
    Mat nan = koch.controlPoints;
    nan(2, 1) = std::nan("");
    QVERIFY(inputError([&] { controlPointMatrices(koch.classicMaps, nan); })
                .contains("control points: entry (row 3, column 2) is not a finite number"));
    std::vector<AffineMap> badMaps = koch.classicMaps;
    badMaps[1].A(0, 0) = INFINITY;
    QVERIFY(inputError([&] { controlPointMatrices(badMaps, koch.controlPoints); })
                .contains("map f_2 (linear part)"));
    badMaps = koch.classicMaps;
    badMaps[2] = {Mat::Identity(3, 3), RowVec::Zero(3)};
    QVERIFY(inputError([&] { controlPointMatrices(badMaps, koch.controlPoints); })
                .contains("map f_3 is not a map of 2D points"));
    QVERIFY(inputError([&] { controlPointMatrices({}, koch.controlPoints); })
                .contains("no maps"));
    QVERIFY(inputError([&] { controlPointMatrices(koch.classicMaps, Mat::Zero(5, 1)); })
                .contains("2 or 3 coordinates"));
    RowVec y(3);
    y << 0, 0, 0;
    QVERIFY(inputError([&] { nearestBarycentricWeights(koch.controlPoints, y); })
                .contains("the point has 3 coordinates"));
    QVERIFY(inputError([&] { controlPointFractalIfs(koch, koch.controlPoints.topRows(4)); })
                .contains("needs 5 control points"));
}

AWB_TEST_APPLESS_MAIN(TestControlPointFractals)
#include "test_control_point_fractals.moc"
