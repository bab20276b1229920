// model/ExactCurve.h: which items have an exact-curve overlay and what it is. Real subdivision
// schemes give their closed-form curve (here a cubic Bézier, compared with de Casteljau at
// t = 1/2); complex Bézier curves give c([0, 1]) for a real t and the Takagi image
// c(x + 2iy T(x)) of 004 Conjecture 3.7.1 for t = 1/2 + iy; other t and other kinds none.

#include "ItemKindTests.h"

#include "core/schemes/ComplexBezier.h"
#include "core/analysis/Geometry.h"
#include "core/analysis/HausdorffBracket.h"
#include "model/ExactCurve.h"
#include "TestMain.h"

using namespace awb;

class TestExactCurve : public QObject {
    Q_OBJECT
private slots:
    void realBezierIsTheCurve();
    void takagiImageForHalfPlusIy();
    void noOverlayWhereNoneIsKnown();
    void certifiedCurveIsTheOverlay();
};

void TestExactCurve::realBezierIsTheCurve()
{
    Project p;
    QVERIFY(test::load(p, R"({"type": "subdivision-curve", "name": "cubic",
        "scheme": {"kind": "bezier", "degree": 3, "t": [0.5, 0]},
        "control_points": [[0, 0], [1, 2], [3, 2], [4, 0]]})"));
    const auto c = exactCurveOf(p.findItem("cubic"), 101);
    QVERIFY(c);
    QVERIFY(c->points.rows() >= 101);
    QVERIFY(c->label.contains("exact curve"));
    // The curve passes through c(1/2) = (P0 + 3P1 + 3P2 + P3) / 8 = (2, 1.5) and its ends.
    Mat mid(1, 2);
    mid << 2.0, 1.5;
    QVERIFY(distanceToPolyline(mid.row(0), c->points) < 1e-3);
    QVERIFY((c->points.row(0) - RowVec::Zero(2)).norm() < 1e-12);
    QVERIFY((c->points.bottomRows(1) - (RowVec(2) << 4.0, 0.0).finished()).norm() < 1e-12);
}

void TestExactCurve::takagiImageForHalfPlusIy()
{
    Project p;
    // Both spellings of a complex Bézier curve: the complex-bezier kind and a subdivision
    // curve whose Bézier scheme has a complex t (004 Figs. 3.4-3.9 use both).
    QVERIFY(test::load(p, R"({"type": "complex-bezier", "name": "Fig. 3.9",
        "control_points": [[0, 0], [0.5, 2], [0.5, 0]], "t": [0.5, 0.01]},
        {"type": "subdivision-curve", "name": "Fig. 3.7",
        "scheme": {"kind": "bezier", "degree": 1, "t": [0.5, 0.25]},
        "control_points": [[0, 0], [1, 0]]},
        {"type": "complex-bezier", "name": "real t",
        "control_points": [[0, 0], [0.5, 2], [0.5, 0]], "t": [0.3, 0]})"));
    const auto fig39 = exactCurveOf(p.findItem("Fig. 3.9"), 600);
    QVERIFY(fig39);
    QVERIFY2(fig39->label.contains("Takagi"), qPrintable(fig39->label));
    QCOMPARE(fig39->points.rows(), Eigen::Index(1025));  // 2^10 + 1 dyadics
    const std::vector<Complex> core = takagiImage(example373ControlPoints(), 0.01, 10);
    for (std::size_t j = 0; j < core.size(); ++j) {
        const auto row = fig39->points.row(Eigen::Index(j));
        QVERIFY(std::abs(Complex(row(0), row(1)) - core[j]) < 1e-15);
    }
    // Fig. 3.7 (left): the graph x + i/2 T(x); T(1/2) = 1/2 puts the middle at (1/2, 1/4).
    const auto fig37 = exactCurveOf(p.findItem("Fig. 3.7"), 64);
    QVERIFY(fig37);
    QCOMPARE(fig37->points.rows(), Eigen::Index(65));
    QVERIFY(std::abs(fig37->points(32, 0) - 0.5) < 1e-15);
    QVERIFY(std::abs(fig37->points(32, 1) - 0.25) < 1e-15);
    const auto real = exactCurveOf(p.findItem("real t"), 64);
    QVERIFY(real);
    QVERIFY(real->label.contains("Bézier"));
    QVERIFY(std::abs(real->points(32, 1) - 1.0) < 1e-15); // c(1/2) = (3/8, 1)
    QVERIFY(std::abs(real->points(32, 0) - 0.375) < 1e-15);
}

void TestExactCurve::noOverlayWhereNoneIsKnown()
{
    Project p;
    QVERIFY(test::load(p, R"({"type": "complex-bezier", "name": "Fig. 3.5",
        "control_points": [[0, 0], [1, 0]], "t": [0.25, 0.4330127018922193]},
        {"type": "fractal", "name": "Koch", "preset": "koch",
         "control_points": [[0, 0], [1, 0], [0.5, 0.8660254037844386]]},
        {"type": "complex-bezier", "name": "outside",
        "control_points": [[0, 0], [1, 0]], "t": [0.5, 2]})"));
    QVERIFY(!exactCurveOf(p.findItem("Fig. 3.5")));  // Re t != 1/2: c(A_1), no closed form
    QVERIFY(!exactCurveOf(p.findItem("Koch")));
    // t outside the discs: the overlay is still the Takagi image (any finite y); the item's
    // derived error says there is no attractor.
    QVERIFY(exactCurveOf(p.findItem("outside")));
    QVERIFY(!exactCurveOf(nullptr));
}

void TestExactCurve::certifiedCurveIsTheOverlay()
{
    // The exact data the distances are measured with (certifiedExactCurveOf) is the curve the
    // overlay samples: same label, same points at the overlay's parameters.
    Project p;
    QVERIFY(test::load(p, R"({"type": "complex-bezier", "name": "Fig. 3.9",
        "control_points": [[0, 0], [0.5, 2], [0.5, 0]], "t": [0.5, 0.01]},
        {"type": "complex-bezier", "name": "real t",
        "control_points": [[0, 0], [0.5, 2], [0.5, 0]], "t": [0.3, 0]},
        {"type": "subdivision-curve", "name": "uniform",
         "scheme": {"kind": "bspline", "degree": 3},
         "control_points": [[0, 0], [1, 2], [3, 2.5], [4.5, 1], [6, 2]]},
        {"type": "subdivision-curve", "name": "end",
         "scheme": {"kind": "bspline-end-interpolating", "degree": 3},
         "control_points": [[0, 0], [5, 4.5], [5.5, -0.5], [0.5, 3.5], [5, 3]]},
        {"type": "complex-bezier", "name": "Fig. 3.5",
        "control_points": [[0, 0], [1, 0]], "t": [0.25, 0.4330127018922193]})"));
    for (const char *name : {"Fig. 3.9", "real t", "uniform", "end"}) {
        const Item *item = p.findItem(name);
        const auto sampled = exactCurveOf(item, 65);
        const auto certified = certifiedExactCurveOf(item);
        QVERIFY(sampled && certified && certified->curve);
        QCOMPARE(certified->label, sampled->label);
        const Eigen::Index n = sampled->points.rows() - 1;
        for (Eigen::Index j = 0; j <= n; j += 8) {
            const Eigen::Vector2d q = certified->curve->point(double(j) / double(n));
            QVERIFY2((q - sampled->points.row(j).transpose()).norm() < 1e-12, name);
        }
    }
    QVERIFY(!certifiedExactCurveOf(p.findItem("Fig. 3.5")));
    QVERIFY(!certifiedExactCurveOf(nullptr));
}

AWB_TEST_GUILESS_MAIN(TestExactCurve)
#include "test_exact_curve.moc"
