// Bézier curves as attractors of {w1, w2}, checked against the equations and figures of
// 002 = C. T. John, "All Bézier curves are attractors of iterated function systems" (NYJM 2007),
// with the block union of 000 §2.2 (Schaefer, Levin, Goldman, SGP 2005).

#include "core/ifs/Attractor.h"
#include "core/ifs/BezierAttractor.h"
#include "core/schemes/Curves.h"
#include "core/analysis/Geometry.h"

#include <QtTest>

#include "TestMain.h"

#include <cmath>
#include <limits>

using namespace awb;

namespace {

Mat rows(std::initializer_list<std::initializer_list<double>> r) { return matrixFromRows(r); }

std::string str(const Mat &m)
{
    std::ostringstream os;
    os << m;
    return os.str();
}

bool near(const Mat &a, const Mat &b, double tol)
{
    return a.rows() == b.rows() && a.cols() == b.cols() && (a - b).cwiseAbs().maxCoeff() <= tol;
}

#define COMPARE_MAT(a, b, tol)                                                                   \
    QVERIFY2(near((a), (b), (tol)), (str(a) + "\n vs \n" + str(b)).c_str())

// The maps' coefficients are products of u and 1 - u of size <= 1 and the points have size
// <= 10: a handful of roundings, so 1e-13 separates "the same map" from any real difference.
constexpr double kSame = 1e-13;

// Message of the InputError f throws; "" when it throws nothing; a marker for anything else.
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

Mat collect(const Ifs &ifs, const RowVec &start, int depth, int view = 0)
{
    PointCollector sink(ifs.views.at(view));
    iterate(ifs, StartSet::points(start), depth, sink);
    return sink.points();
}

Mat exactCurve(const Mat &P, int samples)
{
    std::vector<double> t(samples);
    for (int i = 0; i < samples; ++i)
        t[i] = double(i) / (samples - 1);
    return bezierPoints(P, t);
}

// Hodograph bound: |c'(t)| <= n max |P_{i+1} - P_i|.
double maxSpeed(const Mat &P)
{
    const int n = int(P.rows()) - 1;
    double s = 0;
    for (int i = 0; i < n; ++i)
        s = std::max(s, (P.row(i + 1) - P.row(i)).norm());
    return n * s;
}

// Chord error of a polyline through `samples` even parameter steps: |c''| h^2 / 8 with
// |c''| <= n (n-1) max |second difference of P|.
double chordError(const Mat &P, int samples)
{
    const int n = int(P.rows()) - 1;
    double a = 0;
    for (int i = 0; i + 2 <= n; ++i)
        a = std::max(a, (P.row(i + 2) - 2 * P.row(i + 1) + P.row(i)).norm());
    const double h = 1.0 / (samples - 1);
    return n * (n - 1) * a * h * h / 8.0;
}

// The control points of 002 §6 / Fig. 3.
Mat fig3Curve1(double p) { return rows({{-5, 5}, {p, 0}, {5, -5}}); }
Mat fig3Curve2(double p) { return rows({{-5, -5}, {-p, 0}, {5, 5}}); }

} // namespace

class TestBezierAttractor : public QObject {
    Q_OBJECT
private slots:
    void parabolaMapsFollowEqs9to12();
    void barnsleyFormEqualsEqs11and12();
    void homogeneousForm();
    void conjugationEqualsDirectSolve();
    void attractorIsTheCurve();
    void higherDegreeLivesInLiftedSpace();
    void contractivityReport();
    void combinedIfsOfSection6();
    void blockUnionIsUnionOfCurves();
    void badInput();
};

void TestBezierAttractor::parabolaMapsFollowEqs9to12()
{
    const Mat P = parabolaControlPoints();
    for (double u : {0.1, 0.3, 0.5, 0.7, 0.9}) {
        // de Casteljau by hand, eqs. (2)-(4).
        const RowVec P01 = (1 - u) * P.row(0) + u * P.row(1);
        const RowVec P11 = (1 - u) * P.row(1) + u * P.row(2);
        const RowVec P02 = (1 - u) * P01 + u * P11;
        // "P_0^2(u) = (u, u^2)": the split point lies on y = x^2.
        COMPARE_MAT(Mat(P02), rows({{u, u * u}}), kSame);
        const auto w = parabolaMaps(u);
        // eq. (9): w1 maps P0, P1, P2 to P0, P_0^1(u), P_0^2(u).
        Mat T1(3, 2), T2(3, 2);
        T1 << P.row(0), P01, P02;
        T2 << P02, P11, P.row(2);
        COMPARE_MAT(applyMap(w[0], P), T1, kSame);
        // eq. (10): w2 maps them to P_0^2(u), P_1^1(u), P2.
        COMPARE_MAT(applyMap(w[1], P), T2, kSame);
        // Solving eqs. (9)-(10) as a linear system (what bezierSplit does) gives eqs. (11)-(12).
        const BezierSplit s = bezierSplit(P, u);
        QVERIFY(s.planar);
        QCOMPARE(int(s.planeMaps.size()), 2);
        for (int i = 0; i < 2; ++i) {
            COMPARE_MAT(s.planeMaps[i].map.A, w[i].A, kSame);
            COMPARE_MAT(Mat(s.planeMaps[i].map.b), Mat(w[i].b), kSame);
        }
    }
}

void TestBezierAttractor::barnsleyFormEqualsEqs11and12()
{
    // 002 §4: data (0,0), (u,u^2), (1,1) with d_1 = u^2, d_2 = (1-u)^2 in eqs. (13)-(16)
    // "is {w1, w2} where w1 and w2 are defined as in Equations (11) and (12)".
    for (double u : {0.05, 0.25, 0.5, 0.6, 0.95}) {
        const auto b = barnsleyParabolaMaps(u);
        const auto w = parabolaMaps(u);
        QCOMPARE(int(b.size()), 2);
        for (int i = 0; i < 2; ++i) {
            COMPARE_MAT(b[i].A, w[i].A, kSame);
            COMPARE_MAT(Mat(b[i].b), Mat(w[i].b), kSame);
        }
    }
    // A general fractal interpolation IFS interpolates its data: w_n maps the end points
    // (x_0, y_0), (x_N, y_N) to (x_{n-1}, y_{n-1}), (x_n, y_n) (Barnsley's construction).
    const Mat data = rows({{0, 1}, {1, 3}, {2.5, -1}, {4, 0.5}});
    const auto f = fractalInterpolationMaps(data, {0.3, -0.4, 0.6});
    QCOMPARE(int(f.size()), 3);
    for (int n = 1; n <= 3; ++n) {
        Mat ends(2, 2);
        ends << data.row(0), data.row(3);
        Mat expect(2, 2);
        expect << data.row(n - 1), data.row(n);
        COMPARE_MAT(applyMap(f[n - 1], ends), expect, kSame);
        QCOMPARE(f[n - 1].A(1, 0), 0.0);  // b_n = 0: vertical lines stay vertical
    }
}

void TestBezierAttractor::homogeneousForm()
{
    // u = 1/2: eq. (11) is diag(1/2, 1/4); eq. (12) is [[1/2, 0], [1/2, 1/4]] + (1/2, 1/4).
    // Row convention: [x y 1] H = [w(x, y), 1], so H is the transposed 3 x 3 matrix.
    const BezierSplit s = bezierSplit(parabolaControlPoints(), 0.5);
    COMPARE_MAT(s.planeMaps[0].homogeneous(),
                rows({{0.5, 0, 0}, {0, 0.25, 0}, {0, 0, 1}}), kSame);
    COMPARE_MAT(s.planeMaps[1].homogeneous(),
                rows({{0.5, 0.5, 0}, {0, 0.25, 0}, {0.5, 0.25, 1}}), kSame);
    Mat X(2, 3);
    X << 0.3, 0.7, 1, -2, 5, 1;
    Mat Y = Mat::Ones(2, 3);
    Y.leftCols(2) = applyMap(s.planeMaps[1].map, X.leftCols(2));
    COMPARE_MAT(Mat(X * s.planeMaps[1].homogeneous()), Y, kSame);
}

void TestBezierAttractor::conjugationEqualsDirectSolve()
{
    // 002 §5, eqs. (17)-(18): v_i = omega w_i omega^-1 for arbitrary non-collinear Q.
    const Mat Q = rows({{0, 0}, {2, 3}, {5, 1}});
    for (double u : {0.2, 0.5, 0.8}) {
        const auto v = conjugatedQuadraticMaps(Q, u);
        const BezierSplit s = bezierSplit(Q, u);
        QVERIFY(s.planar);
        for (int i = 0; i < 2; ++i) {
            COMPARE_MAT(v[i].A, s.planeMaps[i].map.A, kSame);
            COMPARE_MAT(Mat(v[i].b), Mat(s.planeMaps[i].map.b), kSame);
            // v_i maps the control polygon to that of the piece: S_i Q (004 eq. (2.5)).
            COMPARE_MAT(applyMap(v[i], Q), Mat(s.S[i] * Q), kSame);
        }
    }
}

void TestBezierAttractor::attractorIsTheCurve()
{
    // Theorem 1: the attractor of {w1, w2} is the curve, for every u. Start at p_0 (fixed point
    // of w1): every image f_w(p_0) is the curve point at the left end of piece w, whose
    // parameter length is at most max(u, 1-u)^k. Hence the Hausdorff distance to the exact curve
    // is at most maxSpeed * max(u,1-u)^k, plus the chord error of the sampled exact curve.
    // The skewed Q has maps with ||A||_2 = 2.56 > 1: 002 §5 says that does not matter.
    const std::vector<Mat> curves = {parabolaControlPoints(), rows({{0, 0}, {2, 3}, {5, 1}}),
                                     rows({{0, 0}, {10, 1}, {0, 2}}), fig3Curve1(3)};
    const int samples = 20001;
    for (const Mat &P : curves) {
        const Mat exact = exactCurve(P, samples);
        for (double u : {0.5, 0.3, 0.7}) {
            const BezierSplit s = bezierSplit(P, u);
            QVERIFY2(s.planar, s.planarReason.c_str());
            const double rho = std::max(u, 1 - u);
            double previous = std::numeric_limits<double>::infinity();
            double ratio = 0;
            for (int k : {8, 12, 16}) {
                const Mat pts = collect(s.ifs, s.start, k);
                const double d = hausdorffToCurve(pts, exact);
                const double bound = maxSpeed(P) * std::pow(rho, k) + chordError(P, samples);
                QVERIFY2(d <= bound, (std::to_string(d) + " > " + std::to_string(bound)).c_str());
                // Every image is exactly on the curve (only the chord error of `exact` remains).
                QVERIFY(distanceToPolyline(pts, exact) <= chordError(P, samples) + 1e-12);
                QVERIFY2(d < previous, std::to_string(d).c_str());
                ratio = d / previous;
                previous = d;
            }
            // The largest gap sits in the end piece of parameter length rho^k, where the curve
            // is smooth: four more levels shrink it by rho^4 up to a curvature term O(rho^k).
            // Levels 12 -> 16 leave that term at a few per cent: allow 5 %.
            QVERIFY2(std::abs(ratio / std::pow(rho, 4) - 1) < 0.05, std::to_string(ratio).c_str());
            if (u == 0.5 && P(1, 0) == 0.5)
                qInfo("parabola, u = 1/2: d_H(attractor level 16, y = x^2) = %.3g", previous);
        }
    }
}

void TestBezierAttractor::higherDegreeLivesInLiftedSpace()
{
    const int samples = 20001;
    // A genuine cubic (the curve (t, t^3) up to an affine map): no plane maps exist.
    const Mat cubic = rows({{0, 0}, {1, 2}, {3, 2.5}, {3.5, 0}});
    const BezierSplit s = bezierSplit(cubic, 0.4);
    QVERIFY(!s.planar);
    QVERIFY2(s.planarReason.find("lifted space R^3") != std::string::npos,
             s.planarReason.c_str());
    QCOMPARE(s.ifs.dim(), 3);
    QCOMPARE(s.ifs.space, std::string("lifted"));
    // The view of the lifted start is p_0, and the attractor is still the curve.
    COMPARE_MAT(project(s.ifs.views[0], s.start), Mat(cubic.row(0)), kSame);
    const Mat pts = collect(s.ifs, s.start, 16);
    const double bound = maxSpeed(cubic) * std::pow(0.6, 16) + chordError(cubic, samples);
    QVERIFY(hausdorffToCurve(pts, exactCurve(cubic, samples)) <= bound);
    // Both maps of every degree contract at rate max(u, 1-u) (eigenvalues u^k, (1-u)^k).
    QVERIFY(std::abs(s.slowestRadius - 0.6) < 1e-12);

    // The same quadratic written as a cubic (degree elevation): the plane maps exist and are
    // the quadratic's own maps, because the curve and its pieces are the same sets.
    const Mat Q = rows({{0, 0}, {2, 3}, {5, 1}});
    Mat E(4, 2);
    E << Q.row(0), (Q.row(0) + 2 * Q.row(1)) / 3, (2 * Q.row(1) + Q.row(2)) / 3, Q.row(2);
    const BezierSplit e = bezierSplit(E, 0.35), q = bezierSplit(Q, 0.35);
    QVERIFY2(e.planar, e.planarReason.c_str());
    for (int i = 0; i < 2; ++i)
        COMPARE_MAT(e.planeMaps[i].map.A, q.planeMaps[i].map.A, 1e-12);

    // Last three control points collinear: the 000 §2 lifting is singular, the barycentric
    // form takes over and still draws the curve.
    const Mat flat = rows({{0, 3}, {0, 0}, {1, 0}, {2, 0}});
    const BezierSplit b = bezierSplit(flat, 0.5);
    QVERIFY(!b.planar);
    QVERIFY(b.lifted.barycentric());
    QVERIFY2(b.planarReason.find("barycentric") != std::string::npos, b.planarReason.c_str());
    const Mat bp = collect(b.ifs, b.start, 14);
    QVERIFY(hausdorffToCurve(bp, exactCurve(flat, samples))
            <= maxSpeed(flat) * std::pow(0.5, 14) + chordError(flat, samples));

    // Degree 1 in the plane: the two points do not fix an affine map of the plane.
    const BezierSplit seg = bezierSplit(rows({{0, 0}, {2, 1}}), 0.5);
    QVERIFY(!seg.planar);
    QVERIFY2(seg.planarReason.find("not unique") != std::string::npos,
             seg.planarReason.c_str());
}

void TestBezierAttractor::contractivityReport()
{
    const Mat Q = rows({{0, 0}, {2, 3}, {5, 1}});
    const BezierSplit mid = bezierSplit(Q, 0.5);
    // Eigenvalues of eq. (11) are u, u^2 and of eq. (12) 1-u, (1-u)^2; conjugation keeps them.
    QVERIFY(std::abs(mid.check.maps[0].spectralRadius - 0.5) < 1e-12);
    QVERIFY(std::abs(mid.check.maps[1].spectralRadius - 0.5) < 1e-12);
    QVERIFY(!mid.nearlyNonContractive);
    QCOMPARE(mid.levelsFor(1e-3), 10);  // 2^-10 < 1e-3 < 2^-9

    for (double u : {0.02, 0.98}) {
        const BezierSplit s = bezierSplit(Q, u);
        QVERIFY(s.check.contractive);  // still eventually contractive...
        QVERIFY(s.nearlyNonContractive);  // ...but only just
        QVERIFY(std::abs(s.slowestRadius - 0.98) < 1e-12);
        // ceil(log(1e-3) / log(0.98)) = 342 levels: a deterministic picture is hopeless.
        QCOMPARE(s.levelsFor(1e-3), 342);
        const std::string close = u < 0.5 ? "close to 0" : "close to 1";
        QVERIFY2(s.contractionNote.find(close) != std::string::npos, s.contractionNote.c_str());
        QVERIFY2(s.contractionNote.find(u < 0.5 ? "map 2" : "map 1") != std::string::npos,
                 s.contractionNote.c_str());
    }
    // 002 §5: "even if v1 and v2 are not contraction mappings in a conventional sense".
    const BezierSplit skew = bezierSplit(rows({{0, 0}, {10, 1}, {0, 2}}), 0.5);
    QVERIFY(skew.check.maps[0].normFactor > 1.0);
    QVERIFY(skew.check.maps[0].spectralRadius < 1.0);
    QVERIFY2(skew.contractionNote.find("not a Euclidean contraction") != std::string::npos,
             skew.contractionNote.c_str());
}

void TestBezierAttractor::combinedIfsOfSection6()
{
    // 002 §6, Fig. 3: the two curves for p = 1, 3, 5, u = 1/2 (and Fig. 4: p = 1, u varies).
    struct Case {
        double p, u;
    };
    std::vector<Case> cases = {{1, 0.5}, {3, 0.5}, {5, 0.5}};
    for (double u : {0.1, 0.3, 0.7, 0.9})
        cases.push_back({1, u});
    for (const Case &c : cases) {
        const CombinedBezierIfs comb
            = combinedBezierIfs({{fig3Curve1(c.p), c.u}, {fig3Curve2(c.p), c.u}});
        QCOMPARE(comb.ifs.size(), 4);
        QCOMPARE(comb.ifs.dim(), 2);
        QVERIFY(comb.check.contractive);
        // Each map is a Euclidean contraction here, so the joint bound is < 1 already at L = 1.
        QVERIFY2(comb.joint.contractive, std::to_string(comb.joint.factor).c_str());
        for (int i = 0; i < 4; ++i)
            QVERIFY(comb.check.maps[i].normFactor < 1.0);
        // Maps 1, 2 are curve 1's {w1, w2}, maps 3, 4 curve 2's.
        const BezierSplit s1 = bezierSplit(fig3Curve1(c.p), c.u);
        COMPARE_MAT(comb.ifs.maps[1].A, s1.planeMaps[1].map.A, kSame);
        // The curves are mirror images under x -> -x (with their order reversed, u -> 1-u).
        // For u = 1/2 the combined IFS commutes with the mirror, so its attractor is symmetric.
        const Mat pts = collect(comb.ifs, RowVec::Zero(2), 7);
        if (c.u == 0.5) {
            Mat mirrored = pts;
            mirrored.col(0) *= -1;
            QVERIFY(hausdorffDistance(pts, mirrored) < 1e-9);
        }
        // "Dusty": the attractor is not the union of the curves; it reaches well off both.
        Mat curves(8002, 2);
        curves << exactCurve(fig3Curve1(c.p), 4001), exactCurve(fig3Curve2(c.p), 4001);
        const double offUnion = directedDistance(pts, curves);
        QVERIFY2(offUnion > 0.5, std::to_string(offUnion).c_str());
        if (c.u == 0.5)
            qInfo("002 Fig. 3, p = %g: joint factor %.4f (L = %d), attractor up to %.2f off "
                  "the curves", c.p, comb.joint.factor, comb.joint.length, offUnion);
    }
    // p = 0 makes curve 1 a straight segment: its maps are not unique, no dusty IFS.
    VERIFY_INPUT_ERROR(combinedBezierIfs({{fig3Curve1(0), 0.5}, {fig3Curve2(2), 0.5}}),
                       "curve 1");
    // A genuine cubic has no plane maps to combine.
    const Mat cubic = rows({{0, 0}, {1, 2}, {3, 2.5}, {3.5, 0}});
    VERIFY_INPUT_ERROR(combinedBezierIfs({{fig3Curve1(1), 0.5}, {cubic, 0.5}}),
                       "curve 2: its maps do not act on the plane");
}

void TestBezierAttractor::blockUnionIsUnionOfCurves()
{
    // 000 §2.2: the block-diagonal IFS draws exactly the union, each curve with its own u; a
    // lifted cubic mixes with plane quadratics.
    const Mat cubic = rows({{0, 0}, {1, 2}, {3, 2.5}, {3.5, 0}});
    const std::vector<BezierCurveSpec> specs = {
        {fig3Curve1(3), 0.5}, {fig3Curve2(3), 0.3}, {cubic, 0.6}};
    const BezierUnion un = bezierUnion(specs);
    QCOMPARE(un.ifs.size(), 2);
    QCOMPARE(un.ifs.dim(), 2 + 2 + 3);
    QCOMPARE(int(un.ifs.views.size()), 3);
    QVERIFY(checkIfs(un.ifs).contractive);
    const int samples = 20001, depth = 16;
    Mat all(0, 2), exactAll(0, 2);
    double worstBound = 0;
    for (int k = 0; k < 3; ++k) {
        const Mat &P = specs[k].controlPoints;
        const Mat pts = collect(un.ifs, un.start, depth, k);
        const Mat exact = exactCurve(P, samples);
        const double rho = std::max(specs[k].u, 1 - specs[k].u);
        const double bound = maxSpeed(P) * std::pow(rho, depth) + chordError(P, samples);
        const double d = hausdorffToCurve(pts, exact);
        QVERIFY2(d <= bound, (std::to_string(d) + " > " + std::to_string(bound)).c_str());
        worstBound = std::max(worstBound, bound + maxSpeed(P) / (samples - 1));
        all.conservativeResize(all.rows() + pts.rows(), 2);
        all.bottomRows(pts.rows()) = pts;
        exactAll.conservativeResize(exactAll.rows() + exact.rows(), 2);
        exactAll.bottomRows(exact.rows()) = exact;
    }
    // The union of the views against the union of the curves (as point sets: the sampled
    // curves add at most one sample spacing, maxSpeed / (samples - 1)).
    const double d = hausdorffDistance(all, exactAll);
    QVERIFY2(d <= worstBound, (std::to_string(d) + " > " + std::to_string(worstBound)).c_str());
}

void TestBezierAttractor::badInput()
{
    const Mat Q = rows({{0, 0}, {2, 3}, {5, 1}});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (double u : {0.0, 1.0, -0.1, 1.5})
        VERIFY_INPUT_ERROR(bezierSplit(Q, u), "strictly between 0 and 1");
    for (double u : {nan, inf})
        VERIFY_INPUT_ERROR(bezierSplit(Q, u), "not a finite number");
    VERIFY_INPUT_ERROR(parabolaMaps(0.0), "strictly between 0 and 1");
    VERIFY_INPUT_ERROR(barnsleyParabolaMaps(1.0), "strictly between 0 and 1");
    VERIFY_INPUT_ERROR(conjugatedQuadraticMaps(Q, nan), "not a finite number");
    VERIFY_INPUT_ERROR(combinedBezierIfs({{Q, 1.2}}), "curve 1");

    Mat bad = Q;
    bad(1, 1) = nan;
    VERIFY_INPUT_ERROR(bezierSplit(bad, 0.5), "not a finite number");
    bad(1, 1) = inf;
    VERIFY_INPUT_ERROR(bezierSplit(bad, 0.5), "not a finite number");
    // Degree < 1.
    VERIFY_INPUT_ERROR(bezierSplit(rows({{1, 2}}), 0.5), "degree >= 1");
    VERIFY_INPUT_ERROR(bezierSplit(Mat(0, 2), 0.5), "degree >= 1");
    // Collinear quadratic: no omega (002 §5 needs non-collinear points).
    VERIFY_INPUT_ERROR(conjugatedQuadraticMaps(rows({{0, 0}, {1, 1}, {3, 3}}), 0.5), "collinear");
    // Fractal interpolation data.
    VERIFY_INPUT_ERROR(fractalInterpolationMaps(rows({{0, 0}, {0, 1}, {1, 1}}), {0.1, 0.1}),
                       "must increase");
    VERIFY_INPUT_ERROR(fractalInterpolationMaps(rows({{0, 0}, {1, 1}, {2, 0}}), {0.1, 1.0}),
                       "|d_n| < 1");
    VERIFY_INPUT_ERROR(fractalInterpolationMaps(rows({{0, 0}, {1, 1}, {2, 0}}), {0.1}),
                       "needs 2 vertical scalings");
    VERIFY_INPUT_ERROR(affineMapThrough(rows({{0, 0}, {1, 1}, {2, 2}}), Q), "collinear");
    VERIFY_INPUT_ERROR(bezierUnion({}), "at least one curve");
}

AWB_TEST_APPLESS_MAIN(TestBezierAttractor)
#include "test_bezier_attractor.moc"
