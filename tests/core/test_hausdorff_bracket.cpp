// Certified Hausdorff brackets between a finite point set and an exact curve (issue: the fixed
// 4000-sample polyline measured the sampling, not the attractor): the enclosures hold, the
// brackets contain independently computed distances (Newton projection onto each polynomial
// piece), B-spline distances fall by 4 per level where sampling failed, and the Takagi image
// of 004 Conj. 3.7.1 is O(y^2) away from the complex de Casteljau attractor.

#include "core/analysis/Geometry.h"
#include "core/analysis/HausdorffBracket.h"
#include "core/ifs/Attractor.h"
#include "core/schemes/ComplexBezier.h"
#include "core/schemes/Curves.h"
#include "core/schemes/Scheme.h"

#include <QtTest>

#include "TestMain.h"
#include <random>

using namespace awb;

class TestHausdorffBracket : public QObject {
    Q_OBJECT
private slots:
    void enclosuresHoldTheCurve();
    void exactOnASegment();
    void bezierPiecesOfBSplines();
    void cubicBSplineDepth14();
    void endInterpolatingCubic();
    void bsplineDistancesFallByFour();
    void takagiImage();
    void takagiErrorWithinYSquared();
};

namespace {

Mat pts(std::initializer_list<std::initializer_list<double>> r) { return matrixFromRows(r); }

const Mat kFig2 = pts({{0, 0}, {1, 2}, {3, 2.5}, {4.5, 1}, {6, 2}});
// examples/000-fig02-cubic-bspline-from-point.awb: its control points and start point.
const Mat kFig2Example = pts({{0, 0}, {1.2, 2.6}, {3.2, 3}, {4.6, 0.6}, {6.2, 1.8}});
const Mat kFig2Start = pts({{5.5, 3.4}});

// The plane points of F^depth(start) for the subdivision IFS of `scheme` on P (000 §2).
Mat attractorFrom(const CurveScheme &scheme, const Mat &P, const Mat &start, int depth)
{
    const SubdivisionIfs s = buildSubdivisionIfs(scheme, P);
    PointCollector c(s.ifs.views.front());
    iterate(s.ifs, StartSet::points(s.toIfsSpace(start)), depth, c);
    return c.points();
}

Eigen::Vector2d bezierAt(const Mat &Q, double u, Eigen::Vector2d *d1 = nullptr,
                         Eigen::Vector2d *d2 = nullptr)
{
    const Eigen::Index n = Q.rows() - 1;
    auto eval = [](Mat w, double v) {
        for (Eigen::Index r = 1; r < w.rows(); ++r)
            for (Eigen::Index k = 0; k + r < w.rows(); ++k)
                w.row(k) = (1 - v) * w.row(k) + v * w.row(k + 1);
        return Eigen::Vector2d(w.row(0).transpose());
    };
    if (d1 && n >= 1)
        *d1 = double(n) * eval(Q.bottomRows(n) - Q.topRows(n), u);
    if (d2) {
        *d2 = Eigen::Vector2d::Zero();
        if (n >= 2) {
            const Mat D = Q.bottomRows(n) - Q.topRows(n);
            *d2 = double(n * (n - 1)) * eval(D.bottomRows(n - 1) - D.topRows(n - 1), u);
        }
    }
    return eval(Q, u);
}

// dist(a, piece) by a dense start and Newton on (c(u) - a) . c'(u) = 0, ends included.
double newtonDistance(const Mat &Q, const Eigen::Vector2d &a)
{
    double bestU = 0, best = 1e300;
    for (int s = 0; s <= 64; ++s) {
        const double d = (bezierAt(Q, s / 64.0) - a).norm();
        if (d < best)
            best = d, bestU = s / 64.0;
    }
    double u = bestU;
    for (int it = 0; it < 30; ++it) {
        Eigen::Vector2d d1, d2;
        const Eigen::Vector2d c = bezierAt(Q, u, &d1, &d2);
        const double g = (c - a).dot(d1), dg = d1.squaredNorm() + (c - a).dot(d2);
        if (dg <= 0)
            break;
        u = std::clamp(u - g / dg, 0.0, 1.0);
    }
    return std::min({best, (bezierAt(Q, u) - a).norm(), (bezierAt(Q, 0) - a).norm(),
                     (bezierAt(Q, 1) - a).norm()});
}

// sup_a dist(a, curve of the pieces), computed independently of the bracket.
double newtonOneSided(const Mat &A, const std::vector<Mat> &pieces)
{
    double worst = 0;
    for (Eigen::Index i = 0; i < A.rows(); ++i) {
        double d = 1e300;
        for (const Mat &Q : pieces)
            d = std::min(d, newtonDistance(Q, A.row(i).transpose()));
        worst = std::max(worst, d);
    }
    return worst;
}

Mat toPlane(const std::vector<Complex> &z)
{
    Mat m(Eigen::Index(z.size()), 2);
    for (std::size_t i = 0; i < z.size(); ++i)
        m.row(Eigen::Index(i)) << z[i].real(), z[i].imag();
    return m;
}

// The complex de Casteljau attractor of P at t = 1/2 + i y, 2^depth points.
Mat takagiAttractor(const CVec &P, double y, int depth)
{
    return toPlane(attractorPoints(complexBezierIfs(P, Complex(0.5, y)), depth));
}

CVec segment01()
{
    CVec P(2);
    P << 0.0, 1.0;
    return P;
}

bool contains(const DistanceBracket &b, double v) { return b.lower <= v && v <= b.upper; }

QString show(const DistanceBracket &b)
{
    return QString("[%1, %2]").arg(b.lower, 0, 'g', 10).arg(b.upper, 0, 'g', 10);
}

} // namespace

void TestHausdorffBracket::enclosuresHoldTheCurve()
{
    // Dense samples of random dyadic sub-intervals lie in the capsule of the interval.
    const auto pieces = *bsplineScheme(3).bezierPieces(kFig2);
    CVec P(3);
    P << 0.0, Complex(0.5, 2.0), 0.5;
    const BezierPiecesCurve bezier(pieces);
    const TakagiImageCurve takagi(P, 0.01);
    std::mt19937 rng(7);
    for (const CertifiedCurve *c : {static_cast<const CertifiedCurve *>(&bezier),
                                    static_cast<const CertifiedCurve *>(&takagi)}) {
        const std::vector<double> br = c->breaks();
        for (int trial = 0; trial < 40; ++trial) {
            const std::size_t k = rng() % (br.size() - 1);
            const int level = int(rng() % 12);
            const double len = (br[k + 1] - br[k]) * std::ldexp(1.0, -level);
            const double t0 = br[k] + len * double(rng() % (1u << level));
            const CurvePiece p = c->enclose(t0, t0 + len);
            QVERIFY((p.a - c->point(t0)).norm() <= 4 * c->allowance() + 1e-15);
            const int samples = 2048;  // dyadic parameters: T exact there
            for (int s = 0; s <= samples; ++s) {
                const Eigen::Vector2d q = c->point(t0 + len * s / samples);
                const Eigen::Vector2d ab = p.b - p.a;
                const double u = std::clamp((q - p.a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
                QVERIFY((q - (p.a + u * ab)).norm() <= p.radius);
            }
        }
    }
}

void TestHausdorffBracket::exactOnASegment()
{
    // The segment from (0, 0) to (1, 0) and A = {(0.5, 0.3)}: sup_a dist = 0.3 exactly, and the
    // farthest curve point from a is an end, at sqrt(0.25 + 0.09).
    const BezierPiecesCurve seg({pts({{0, 0}, {0.5, 0}, {1, 0}})});
    const HausdorffBracket h = hausdorffBracket(pts({{0.5, 0.3}}), seg);
    QVERIFY2(contains(h.oneSided, 0.3), qPrintable(show(h.oneSided)));
    QVERIFY2(contains(h.curveToPoints, std::sqrt(0.34)), qPrintable(show(h.curveToPoints)));
    QVERIFY2(contains(h.value, std::sqrt(0.34)), qPrintable(show(h.value)));
    QVERIFY(h.converged && h.width <= 1e-3);
    // Points on the curve: the bracket is at rounding level, not sampling level.
    Mat on(3, 2);
    on << 0.0, 0.0, 1.0 / 3.0, 0.0, 1.0, 0.0;
    const HausdorffBracket z = hausdorffBracket(on, seg);
    QVERIFY(z.oneSided.upper < 1e-13);
    QVERIFY(contains(z.curveToPoints, 1.0 / 3.0));
}

void TestHausdorffBracket::bezierPiecesOfBSplines()
{
    // The Bézier pieces are the B-spline exactly: same points as de Boor's evaluation.
    const auto pieces = *bsplineScheme(3).bezierPieces(kFig2);
    QCOMPARE(int(pieces.size()), 2);
    const Mat dense = *bsplineScheme(3).exactCurve(kFig2, 9);
    const BezierPiecesCurve c(pieces);
    for (int s = 0; s < 9; ++s)
        QVERIFY((c.point(s / 8.0) - dense.row(s).transpose()).norm() < 1e-14);
    EndInterpolatingBSplineScheme end(3);
    const auto ep = *end.bezierPieces(kFig2);
    QCOMPARE(int(ep.size()), 2);
    QVERIFY((ep.front().row(0) - kFig2.row(0)).norm() < 1e-15);
    QVERIFY((ep.back().row(3) - kFig2.row(4)).norm() < 1e-15);
    const Mat edense = *end.exactCurve(kFig2, 9);
    const BezierPiecesCurve ec(ep);
    for (int s = 0; s < 9; ++s)
        QVERIFY((ec.point(s / 8.0) - edense.row(s).transpose()).norm() < 1e-14);
    QVERIFY(!fourPointScheme(1.0 / 16).bezierPieces(kFig2));
}

void TestHausdorffBracket::cubicBSplineDepth14()
{
    // 000 Fig. 2 from its start point at depth 14: the ends overhang (the eigenvalue 1/2 moves
    // the points along the end tangents), 4.79e-5.
    const UniformScheme cubic = bsplineScheme(3);
    const auto pieces = *cubic.bezierPieces(kFig2Example);
    const BezierPiecesCurve curve(pieces);
    const Mat A = attractorFrom(cubic, kFig2Example, kFig2Start, 14);
    const double truth = newtonOneSided(A, pieces);
    const HausdorffBracket h = hausdorffBracket(A, curve);
    QVERIFY2(contains(h.oneSided, truth),
             qPrintable(QString("%1 not in %2").arg(truth, 0, 'g', 12).arg(show(h.oneSided))));
    QVERIFY(h.converged && h.oneSided.relativeWidth() <= 1e-3);
    QVERIFY(std::abs(truth - 4.787e-5) < 0.001e-5);
    // The curve's farthest point from the points: about half their spacing near the ends.
    QVERIFY(contains(h.value, h.curveToPoints.mid()));
    QVERIFY(h.curveToPoints.lower > 5 * h.oneSided.upper);
    // The interior of the level-14 control polygon is ~1e-8 from the curve, below what 4000
    // samples resolve (their chords are ~1e-7 off the curve).
    const Mat level = subdivide(cubic, kFig2Example, 14);
    const Mat inner = level.middleRows(2, level.rows() - 4);
    const double innerTruth = newtonOneSided(inner, pieces);
    const HausdorffBracket hi = hausdorffBracket(inner, curve);
    QVERIFY2(contains(hi.oneSided, innerTruth),
             qPrintable(QString("%1 not in %2").arg(innerTruth).arg(show(hi.oneSided))));
    QVERIFY(hi.converged && innerTruth > 1e-9 && innerTruth < 1e-7);
    const double sampled = distanceToPolyline(inner, *cubic.exactCurve(kFig2Example, 4000));
    QVERIFY2(sampled > 3 * hi.oneSided.upper, qPrintable(QString::number(sampled)));
}

void TestHausdorffBracket::endInterpolatingCubic()
{
    // 000 Fig. 3 (knots {0,0,0,1,2,2,2}) from its triangle's corners, and kFig2 from its
    // control points. The curve of Fig. 3 crosses itself: the polyline measure (nearest sample
    // and its neighbours) took a point near the crossing to the wrong branch.
    const EndInterpolatingBSplineScheme end(3);
    const Mat fig3 = pts({{0, 0}, {5, 4.5}, {5.5, -0.5}, {0.5, 3.5}, {5, 3}});
    const Mat triangle = pts({{1, -1.2}, {3.5, -1.5}, {2, 0.8}});
    for (const auto &[P, start] : {std::pair{fig3, triangle}, std::pair{kFig2, kFig2}}) {
        const auto pieces = *end.bezierPieces(P);
        const Mat A = attractorFrom(end, P, start, 12);
        const double truth = newtonOneSided(A, pieces);
        const HausdorffBracket h = hausdorffBracket(A, BezierPiecesCurve(pieces));
        QVERIFY2(contains(h.oneSided, truth),
                 qPrintable(QString("%1 not in %2").arg(truth, 0, 'g', 12).arg(show(h.oneSided))));
        QVERIFY(h.converged && h.width <= 1e-3);
    }
}

void TestHausdorffBracket::bsplineDistancesFallByFour()
{
    // The end-interpolating cubic of 000 Fig. 3 from its triangle: the points approach the
    // curve as 4^-k (no overhang at interpolated ends) and the curve's farthest point from
    // them as 2^-k (their spacing). Depths 10..15, where 4000 samples stop resolving it.
    const EndInterpolatingBSplineScheme end(3);
    const Mat fig3 = pts({{0, 0}, {5, 4.5}, {5.5, -0.5}, {0.5, 3.5}, {5, 3}});
    const Mat triangle = pts({{1, -1.2}, {3.5, -1.5}, {2, 0.8}});
    const BezierPiecesCurve curve(*end.bezierPieces(fig3));
    double previous = 0, previousCurveSide = 0;
    for (int k = 10; k <= 15; ++k) {
        const HausdorffBracket h = hausdorffBracket(attractorFrom(end, fig3, triangle, k), curve);
        QVERIFY(h.converged);
        if (k > 10) {
            const double ratio = previous / h.oneSided.mid();
            QVERIFY2(std::abs(ratio - 4.0) < 0.05,
                     qPrintable(QString("depth %1: ratio %2").arg(k).arg(ratio)));
            const double curveRatio = previousCurveSide / h.curveToPoints.mid();
            QVERIFY2(std::abs(curveRatio - 2.0) < 0.05,
                     qPrintable(QString("depth %1: ratio %2").arg(k).arg(curveRatio)));
        }
        previous = h.oneSided.mid();
        previousCurveSide = h.curveToPoints.mid();
    }
    // The uniform cubic from a point: its ends overhang, so 2^-k on both sides.
    const UniformScheme cubic = bsplineScheme(3);
    const BezierPiecesCurve uniform(*cubic.bezierPieces(kFig2Example));
    auto oneSided = [&](int k) {
        return hausdorffBracket(attractorFrom(cubic, kFig2Example, kFig2Start, k), uniform)
            .oneSided.mid();
    };
    QVERIFY(std::abs(oneSided(12) / oneSided(13) - 2.0) < 0.05);
}

void TestHausdorffBracket::takagiImage()
{
    // P = (0, 1): A*(y) against T*(y) = {x + 2iy T(x)} (004 Remark, eq. (3.42)), from the
    // 2^15 points f_w(0) of depth 15 (the thesis iterates 15 times). d_H is then the curve's
    // farthest point from those points: its end 1, 2^-15 = 3.05e-5 from the nearest point
    // f_2^15(0), for y = 2^-8 and 2^-10, where the 4097-sample polyline saw 2.9e-5 and 1.8e-6.
    for (int e : {8, 10}) {
        const double y = std::ldexp(1.0, -e);
        const Mat A = takagiAttractor(segment01(), y, 15);
        const HausdorffBracket h = hausdorffBracket(A, TakagiImageCurve(segment01(), y));
        QVERIFY(h.converged && h.width <= 1e-3);
        QVERIFY2(h.value.lower >= 3.05e-5, qPrintable(show(h.value)));
        // The points' side, checked against a polyline of 2^20 + 1 points of T*(y), whose
        // chords are within (4/3) y 2^-20 |c'| of the curve.
        const double dense = distanceToPolyline(A, toPlane(awb::takagiImage(segment01(), y, 20)));
        const double chord = (4.0 / 3.0) * y * std::ldexp(1.0, -20);
        QVERIFY2(dense >= h.oneSided.lower - chord && dense <= h.oneSided.upper + chord,
                 qPrintable(QString("%1 vs %2").arg(dense).arg(show(h.oneSided))));
    }
}

void TestHausdorffBracket::takagiErrorWithinYSquared()
{
    // sup over the points of depth 17 (points of A*(y)) of their distance to c(x + 2iy T(x)),
    // for P = (0, 1) and the P of Example 3.7.3, y = 2^-6 .. 2^-10: a lower bound for the
    // attractor's (depth 21 raises it by 1 % at y = 2^-8, by 24 % at y = 2^-10). Within y^2
    // (eq. (3.42)'s O(y^2); Conj. 3.7.1 claims O(y)), and falling faster than y^2: the ratio
    // to y^2 shrinks with y.
    for (const CVec &P : {segment01(), example373ControlPoints()}) {
        double previous = 1e300;
        for (int e = 6; e <= 10; ++e) {
            const double y = std::ldexp(1.0, -e);
            const HausdorffBracket h =
                hausdorffBracket(takagiAttractor(P, y, 17), TakagiImageCurve(P, y));
            QVERIFY(h.converged);
            const double ratio = h.oneSided.upper / (y * y);
            QVERIFY2(ratio < 1.5 && ratio < previous,
                     qPrintable(QString("y = 2^-%1: %2 y^2").arg(e).arg(ratio)));
            previous = ratio;
        }
    }
}

AWB_TEST_APPLESS_MAIN(TestHausdorffBracket)
#include "test_hausdorff_bracket.moc"
