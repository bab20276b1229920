// Attractors of subdivision IFS drawn from any start set (000 §2, Figs. 2-5; 004 §3.6):
// deterministic and random iteration, unions (000 §2.2), singular control points (NOTES.md).

#include "core/ifs/Attractor.h"
#include "core/render/Engine.h"
#include "core/analysis/Geometry.h"
#include "core/analysis/Spectrum.h"

#include <QtTest>

#include "TestMain.h"
#include "TestTime.h"
#include <algorithm>
#include <map>
#include <string>

using namespace awb;

namespace {

Mat pts(std::initializer_list<std::initializer_list<double>> r) { return matrixFromRows(r); }

// The plane points of F^depth(start).
Mat attractorPoints(const SubdivisionIfs &s, const StartSet &start, int depth)
{
    PointCollector c(s.ifs.views.front());
    iterate(s.ifs, start, depth, c);
    return c.points();
}

// 000 Fig. 2: a cubic B-spline on five control points.
const Mat kFig2 = pts({{0, 0}, {1, 2}, {3, 2.5}, {4.5, 1}, {6, 2}});

} // namespace

class TestAttractors : public QObject {
    Q_OBJECT
private slots:
    void convergesFromAnyStartSetAtEigenvalueRate_data();
    void convergesFromAnyStartSetAtEigenvalueRate();
    void thesisExample362FromItsStartSet();
    void fourPointFromSegment();
    void bezierAnyDegreeAndSplit();
    void liftedStartPoint();
    void chaosGameLiesOnCurveWithAddresses();
    void parallelEqualsSerial();
    void iterateAlongFollowsTheCurve();
    void rasterIsFilledAndDeterministic();
    void unionOfTwoBeziers();
    void singularControlPointsUseBarycentricForm();
    void contractionOnAverage();
    void badInputIsRefused();
    void cancellation();
};

void TestAttractors::convergesFromAnyStartSetAtEigenvalueRate_data()
{
    QTest::addColumn<int>("kind");
    QTest::newRow("point") << 0;
    QTest::newRow("segment") << 1;
    QTest::newRow("triangle") << 2;
}

void TestAttractors::convergesFromAnyStartSetAtEigenvalueRate()
{
    AWB_SKIP_WITHOUT_THREADS();
    // 000 §2: "iteration on any compact set X0 would yield the same fractal". The Hausdorff
    // distance between F^k(X0) and the curve falls by the factor 1/lambda = 2 per level, where
    // lambda = 1/2 is the subdominant eigenvalue of S_1, S_2 (the largest of A_1, A_2).
    QFETCH(int, kind);
    const UniformScheme cubic = bsplineScheme(3);
    const auto s = buildSubdivisionIfs(cubic, kFig2);
    const double lambda = subdominant(spectrum(s.matrices.S[0])).modulus;
    QVERIFY(std::abs(lambda - 0.5) < 1e-12);
    Mat X0;
    StartSet::Kind k = StartSet::Kind::Points;
    if (kind == 0)
        X0 = pts({{7, -3}});
    else if (kind == 1)
        X0 = pts({{7, -3}, {-2, 5}}), k = StartSet::Kind::Polyline;
    else
        X0 = pts({{7, -3}, {-2, 5}, {1, 8}}), k = StartSet::Kind::Polygon;
    const StartSet start{k, s.toIfsSpace(X0)};
    const Mat exact = *cubic.exactCurve(kFig2, 40000);
    std::vector<double> d;
    for (int depth = 8; depth <= 13; ++depth) {
        // Sample the segments/triangles densely enough that their images are covered too.
        PointCollector c(s.ifs.views.front());
        iterate(s.ifs, start, depth, c);
        d.push_back(hausdorffToCurve(c.points(), exact));
    }
    for (size_t i = 1; i < d.size(); ++i) {
        const double ratio = d[i - 1] / d[i];
        // Asymptotically exactly 1/lambda; within 10 % from depth 8 on.
        QVERIFY2(std::abs(ratio - 1.0 / lambda) < 0.2,
                 qPrintable(QString("depth %1: ratio %2").arg(8 + i).arg(ratio)));
    }
    QVERIFY(d.back() < 0.01);
}

void TestAttractors::thesisExample362FromItsStartSet()
{
    AWB_SKIP_WITHOUT_THREADS();
    // 004 Example 3.6.2, Fig. 3.2: X0 = {[0,0],[1,4],[2,4],[4,0],[5,0]} converges to the
    // quadratic B-spline, which interpolates the fixed points (1/2, 2) and (6, -1/2).
    const Mat P = pts({{0, 0}, {1, 4}, {4, 4}, {5, -1}, {7, 0}});
    const auto s = buildSubdivisionIfs(chaikinScheme(), P);
    const Mat X = attractorPoints(s, StartSet::points(s.toIfsSpace(
                                         pts({{0, 0}, {1, 4}, {2, 4}, {4, 0}, {5, 0}}))), 14);
    const Mat exact = *chaikinScheme().exactCurve(P, 20000);
    QVERIFY(hausdorffToCurve(X, exact) < 1e-3);
    QVERIFY((exact.row(0) - pts({{0.5, 2}})).norm() < 1e-12);
    QVERIFY((exact.row(exact.rows() - 1) - pts({{6, -0.5}})).norm() < 1e-12);
}

void TestAttractors::fourPointFromSegment()
{
    AWB_SKIP_WITHOUT_THREADS();
    // 000 Fig. 5: the four-point IFS from a line segment converges to the curve of classic
    // subdivision (no closed form: compare with 12 levels of classic subdivision, whose vertices
    // lie on the limit curve because the scheme interpolates).
    const Mat P = pts({{0, 0}, {1, 1.5}, {2, 0.2}, {3, 2}, {4, 0.5}, {5, 1.8}, {6, 0}});
    const UniformScheme four = fourPointScheme(1.0 / 16);
    const auto s = buildSubdivisionIfs(four, P);
    QVERIFY(checkIfs(s.ifs).contractive);
    const Mat ref = subdivide(four, P, 12);
    // The interpolating scheme's level-k polygon starts at P_1 and ends at P_5: the IFS curve
    // is the part between (rows 2^k .. ) -- compare against the vertices inside the domain.
    const Mat X = attractorPoints(
        s, StartSet::polyline(s.toIfsSpace(pts({{-3, 4}, {9, -2}}))), 14);
    const double d = directedDistance(X, ref);
    QVERIFY2(d < 2e-3, qPrintable(QString::number(d)));
    // The curve passes through control points 3, 4, 5 (the domain of 7 points is [p_2, p_4]
    // in 0-based indices) and, being interpolatory, the fixed points of f_1, f_2 are p_2, p_4.
    const auto x1 = fixedPoint(s.lifted[0].A, s.lifted[0].b);
    const auto x2 = fixedPoint(s.lifted[1].A, s.lifted[1].b);
    QVERIFY(x1 && x2);
    QVERIFY((x1->head(2) - P.row(2)).norm() < 1e-10);
    QVERIFY((x2->head(2) - P.row(4)).norm() < 1e-10);
}

void TestAttractors::bezierAnyDegreeAndSplit()
{
    AWB_SKIP_WITHOUT_THREADS();
    for (int n : {2, 3, 5}) {
        for (double t : {0.5, 0.3}) {
            Mat P(n + 1, 2);
            for (int i = 0; i <= n; ++i)
                P.row(i) << i, (i % 2 ? 2.0 : -1.0) + 0.2 * i;
            const BezierScheme bez(n, t);
            const auto s = buildSubdivisionIfs(bez, P);
            const Mat exact = *bez.exactCurve(P, 40000);
            const StartSet start = StartSet::points(s.toIfsSpace(pts({{3, 3}})));
            const double d12 = hausdorffToCurve(attractorPoints(s, start, 12), exact);
            const double d15 = hausdorffToCurve(attractorPoints(s, start, 15), exact);
            // The slower piece contracts by max(t, 1-t) per level (the subdominant eigenvalue
            // of R(t) is 1-t): over three levels the distance falls by max(t, 1-t)^-3, to 15 %.
            const double expected = std::pow(std::max(t, 1 - t), -3);
            QVERIFY2(std::abs(d12 / d15 / expected - 1.0) < 0.15,
                     qPrintable(QString("n=%1 t=%2 ratio=%3 expected %4")
                                    .arg(n).arg(t).arg(d12 / d15).arg(expected)));
            // The curves are about 5 units across: 5 * 0.7^15 = 0.024.
            QVERIFY(d15 < 0.05 * std::pow(std::max(t, 1 - t) / 0.7, 15));
        }
    }
}

void TestAttractors::liftedStartPoint()
{
    AWB_SKIP_WITHOUT_THREADS();
    // 000 Fig. 2: "a random homogeneous point in five dimensions".
    const auto s = buildSubdivisionIfs(bsplineScheme(3), kFig2);
    const Mat X = attractorPoints(s, StartSet::points(s.toIfsSpace(pts({{9, -4, 3, 7, 1}}))), 14);
    QVERIFY(hausdorffToCurve(X, *bsplineScheme(3).exactCurve(kFig2, 20000)) < 2e-3);
}

void TestAttractors::chaosGameLiesOnCurveWithAddresses()
{
    AWB_SKIP_WITHOUT_THREADS();
    const UniformScheme cubic = bsplineScheme(3);
    const auto s = buildSubdivisionIfs(cubic, kFig2);
    const Mat exact = *cubic.exactCurve(kFig2, 20000);
    const int half = int(exact.rows()) / 2;
    const PointIndex curveIndex(exact); // one index for all samples (fast under sanitizers too)
    std::vector<RowVec> points;
    int wrongHalf = 0, n = 0;
    CallbackSink sink([&](const Mat &v, StartSet::Kind, const std::uint8_t *a, int len) {
        const Mat p = project(s.ifs.views.front(), v);
        // The latest map decides which half of the curve the point is on.
        Eigen::Index nearest = 0;
        const RowVec q = p.row(0);
        curveIndex.nearest(q.data(), &nearest);
        if (len > 0 && std::abs(nearest - half) > 40 && (a[0] == 0) != (nearest < half))
            ++wrongHalf;
        ++n;
        points.push_back(q);
    });
    ChaosOptions opt;
    opt.samples = 20000;
    opt.skip = 40; // 0.5^40 of the start distance is far below the tolerance
    chaosGame(s.ifs, s.toIfsSpace(pts({{50, 50}})).row(0), opt, sink);
    QCOMPARE(n, 20000);
    QCOMPARE(wrongHalf, 0);
    Mat all(Eigen::Index(points.size()), exact.cols());
    for (std::size_t i = 0; i < points.size(); ++i)
        all.row(Eigen::Index(i)) = points[i];
    QVERIFY(distanceToPolyline(all, exact) < 1e-6);
}

void TestAttractors::parallelEqualsSerial()
{
    const auto s = buildSubdivisionIfs(fourPointScheme(1.0 / 16),
                                       pts({{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}, {5, 1}, {6, 0}}));
    const StartSet start = StartSet::points(s.toIfsSpace(pts({{1, 1}})));
    PointCollector serial(s.ifs.views.front()), a(s.ifs.views.front()), b(s.ifs.views.front());
    iterate(s.ifs, start, 12, serial);
    const auto stats = iterateParallel(s.ifs, start, 12, {&a, &b});
    QCOMPARE(stats.images, std::uint64_t(4096));
    auto sorted = [](Mat m) {
        std::vector<std::pair<double, double>> v;
        for (Eigen::Index i = 0; i < m.rows(); ++i)
            v.emplace_back(m(i, 0), m(i, 1));
        std::sort(v.begin(), v.end());
        return v;
    };
    Mat both(a.points().rows() + b.points().rows(), 2);
    both << a.points(), b.points();
    QVERIFY(sorted(serial.points()) == sorted(both));
}

// iterateAlong (vector export of curves): the same images as iterate, address by address, but
// in the order of the addresses read outermost first. For the IFS of a cubic Bézier curve
// (de Casteljau halves) from the segment between its lifted end points, every image is the
// chord of one piece, so consecutive images share their end points: f_w(P_3) = f_{w+1}(P_0).
void TestAttractors::iterateAlongFollowsTheCurve()
{
    AWB_SKIP_WITHOUT_THREADS();
    const auto s = buildSubdivisionIfs(BezierScheme(3), pts({{0, 0}, {1, 3}, {4, 3}, {5, 0}}));
    // The chord between the lifted end points P_0 and P_3: rows of the lifted control points
    // without their last (homogeneous, all ones) column.
    QCOMPARE(s.ifs.dim(), 3);
    Mat ends(2, 3);
    ends << s.lifting.lifted.row(0).head(3), s.lifting.lifted.row(3).head(3);
    const StartSet chord = StartSet::polyline(ends);
    const int depth = 7;
    // Addresses as byte strings (std::string compares its chars as unsigned: the addresses'
    // lexicographic order).
    auto address = [](const std::uint8_t *a, int n) {
        return std::string(reinterpret_cast<const char *>(a), std::size_t(n));
    };
    std::map<std::string, Mat> byIterate;
    CallbackSink collect([&](const Mat &v, StartSet::Kind, const std::uint8_t *a, int n) {
        byIterate[address(a, n)] = v;
    });
    iterate(s.ifs, chord, depth, collect);
    std::vector<std::string> order;
    std::vector<Mat> images;
    CallbackSink along([&](const Mat &v, StartSet::Kind k, const std::uint8_t *a, int n) {
        QVERIFY(k == StartSet::Kind::Polyline);
        order.push_back(address(a, n));
        images.push_back(v);
    });
    const IterationStats stats = iterateAlong(s.ifs, chord, depth, along);
    QCOMPARE(stats.images, std::uint64_t(1) << depth);
    QCOMPARE(order.size(), byIterate.size());
    QVERIFY(std::is_sorted(order.begin(), order.end()));
    double worst = 0, gap = 0;
    for (size_t k = 0; k < order.size(); ++k) {
        worst = std::max(worst, (images[k] - byIterate.at(order[k])).cwiseAbs().maxCoeff());
        if (k > 0) {
            const Mat a = project(s.ifs.views.front(), images[k - 1]);
            const Mat b = project(s.ifs.views.front(), images[k]);
            gap = std::max(gap, (a.row(a.rows() - 1) - b.row(0)).norm());
        }
    }
    QVERIFY2(worst < 1e-12, qPrintable(QString::number(worst)));
    QVERIFY2(gap < 1e-12, qPrintable(QString::number(gap)));
    // The first image starts at P_0 and the last ends at P_3.
    const Mat first = project(s.ifs.views.front(), images.front());
    const Mat last = project(s.ifs.views.front(), images.back());
    QVERIFY(first.row(0).norm() < 1e-12);
    QVERIFY((last.row(last.rows() - 1) - RowVec(Eigen::RowVector2d(5, 0))).norm() < 1e-12);
    // Depth 0 is the start set itself; a bad depth is refused like iterate's.
    int n0 = 0;
    CallbackSink count([&](const Mat &, StartSet::Kind, const std::uint8_t *, int) { ++n0; });
    iterateAlong(s.ifs, chord, 0, count);
    QCOMPARE(n0, 1);
    QVERIFY_THROWS_EXCEPTION(InputError, iterateAlong(s.ifs, chord, 65, count));
}

void TestAttractors::rasterIsFilledAndDeterministic()
{
    const auto s = buildSubdivisionIfs(EndInterpolatingBSplineScheme(3),
                                       pts({{0, 0}, {4, 4}, {2, -1}, {-1, 3}, {5, 0}}));
    // 000 Fig. 3: start with a triangle.
    const StartSet tri = StartSet::polygon(s.toIfsSpace(pts({{0, 5}, {5, 5}, {2, 8}})));
    RasterFrame frame;
    frame.width = 200, frame.height = 150;
    frame.x0 = -2, frame.y0 = -2, frame.x1 = 6, frame.y1 = 6;
    EngineColours colours;
    colours.labelColours = {Rgb8{1, 2, 3}, Rgb8{4, 5, 6}};
    DensitySink one(frame, s.ifs.views, Accumulation::Hits, colours, s.ifs.size());
    iterate(s.ifs, tri, 10, one);
    DensitySink a(frame, s.ifs.views, Accumulation::Hits, colours, s.ifs.size());
    DensitySink b(frame, s.ifs.views, Accumulation::Hits, colours, s.ifs.size());
    iterateParallel(s.ifs, tri, 10, {&a, &b});
    a.image().merge(b.image());
    QVERIFY(one.image().litCells() > 200);
    bool same = true;
    for (std::size_t i = 0; i < one.image().size(); ++i)
        same = same && one.image().cell(i) == a.image().cell(i);
    QVERIFY(same);
}

void TestAttractors::unionOfTwoBeziers()
{
    AWB_SKIP_WITHOUT_THREADS();
    // 000 §2.2, Fig. 4: block IFS of two quadratic Bézier curves; start point
    // (2, 3/2, 1, 2, 3/2, 1): each component gets (2, 3/2) with its homogeneous 1.
    const Mat P = pts({{0, 0}, {1, 2}, {2, 0}});
    const Mat Q = pts({{3, 1}, {4, -1}, {5, 1.5}});
    const BezierScheme bez(2, 0.5);
    const auto sp = buildSubdivisionIfs(bez, P), sq = buildSubdivisionIfs(bez, Q);
    const Ifs u = blockUnion({sp.ifs, sq.ifs});
    QCOMPARE(u.dim(), 4);
    QCOMPARE(int(u.views.size()), 2);
    // Two homogeneous components: the lifted maps M_i of the union have eigenvalue 1 twice.
    Mat M1 = Mat::Zero(6, 6);
    M1.topLeftCorner(3, 3) = sp.lifted[0].M;
    M1.bottomRightCorner(3, 3) = sq.lifted[0].M;
    QCOMPARE(spectrum(M1).multiplicity[0], 2);
    QVERIFY(checkIfs(u).contractive);
    RowVec x0(4);
    x0 << 2, 1.5, 2, 1.5;
    Mat all;
    for (int v = 0; v < 2; ++v) {
        PointCollector c(u.views[v]);
        iterate(u, StartSet::points(x0), 14, c);
        const Mat exact = *bez.exactCurve(v == 0 ? P : Q, 20000);
        QVERIFY(hausdorffToCurve(c.points(), exact) < 1e-3);
    }
}

void TestAttractors::singularControlPointsUseBarycentricForm()
{
    AWB_SKIP_WITHOUT_THREADS();
    // The last three control points are collinear: P is singular (NOTES.md), the attractor is
    // computed in barycentric form and is still the B-spline curve.
    const Mat P = pts({{0, 0}, {1, 3}, {2, 1}, {3, 2}, {4, 3}});
    const UniformScheme cubic = bsplineScheme(3);
    const auto s = buildSubdivisionIfs(cubic, P);
    QVERIFY(!s.lifting.invertible);
    QVERIFY(s.barycentric());
    QVERIFY(s.lifted.empty());
    QCOMPARE(s.lifting.culprits, (std::vector<int>{2, 3, 4}));
    QVERIFY2(QString::fromStdString(s.lifting.reason).contains("control points 3, 4 and 5 are collinear"),
             s.lifting.reason.c_str());
    QVERIFY(checkIfs(s.ifs).contractive);
    const Mat X = attractorPoints(s, StartSet::points(s.toIfsSpace(pts({{10, -10}}))), 13);
    QVERIFY(hausdorffToCurve(X, *cubic.exactCurve(P, 20000)) < 3e-3);
    // Asking for the lifted form explicitly names the problem.
    try {
        buildSubdivisionIfs(cubic, P, IfsForm::Lifted);
        QFAIL("singular lifting accepted");
    } catch (const InputError &e) {
        QVERIFY(QString(e.what()).contains("collinear"));
    }
    // All points on one line: still a (straight) curve.
    const Mat line = pts({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}});
    const auto sl = buildSubdivisionIfs(cubic, line);
    QVERIFY(sl.barycentric());
    const Mat Y = attractorPoints(sl, StartSet::points(sl.toIfsSpace(pts({{5, -1}}))), 12);
    QVERIFY((Y.col(0) - Y.col(1)).cwiseAbs().maxCoeff() < 1e-12);
}

void TestAttractors::contractionOnAverage()
{
    AWB_SKIP_WITHOUT_THREADS();
    // x -> 1.2 x (probability p) and x -> 0.3 x + 1 (1 - p): the first map does not contract,
    // but random iteration does when p log 1.2 + (1 - p) log 0.3 < 0 (Barnsley-Elton 1988):
    // the Lyapunov exponent along the orbit is that mean, within its sampling error.
    for (const double p : {0.3, 0.5, 0.9}) {
        Ifs ifs;
        Mat grow(2, 2), shrink(2, 2);
        grow << 1.2, 0, 0, 1.2;
        shrink << 0.3, 0, 0, 0.3;
        RowVec b(2);
        b << 1, 1;
        ifs.maps = {{grow, RowVec::Zero(2)}, {shrink, b}};
        ifs.views = {{Mat::Identity(2, 2), RowVec::Zero(2)}};
        ifs.probabilities = {p, 1 - p};
        const IfsCheck check = checkIfs(ifs);
        QVERIFY(!check.contractive);
        QVERIFY(check.lyapunov.has_value());
        const double mean = p * std::log(1.2) + (1 - p) * std::log(0.3);
        QVERIFY2(std::abs(*check.lyapunov - mean) < 0.03,
                 qPrintable(QString("p %1: %2 vs %3").arg(p).arg(*check.lyapunov).arg(mean)));
        QCOMPARE(check.contractsOnAverage(), mean < 0);
        QCOMPARE(check.message.find("contracts on average") != std::string::npos, mean < 0);
    }
    // A contractive IFS needs no estimate.
    Ifs half;
    half.maps = {{0.5 * Mat::Identity(2, 2), RowVec::Zero(2)}};
    half.views = {{Mat::Identity(2, 2), RowVec::Zero(2)}};
    QVERIFY(checkIfs(half).contractive && !checkIfs(half).lyapunov);
}

void TestAttractors::badInputIsRefused()
{
    AWB_SKIP_WITHOUT_THREADS();
    const auto s = buildSubdivisionIfs(bsplineScheme(3), kFig2);
    const StartSet p = StartSet::points(s.toIfsSpace(pts({{0, 0}})));
    PointCollector c(s.ifs.views.front());
    QVERIFY_THROWS_EXCEPTION(InputError, iterate(s.ifs, p, 65, c));
    QVERIFY_THROWS_EXCEPTION(InputError, iterate(s.ifs, p, -1, c));
    QVERIFY_THROWS_EXCEPTION(InputError, iterate(s.ifs, StartSet::points(pts({{0, 0}})), 3, c));
    Mat nan = s.toIfsSpace(pts({{0, 0}}));
    nan(0, 1) = std::nan("");
    QVERIFY_THROWS_EXCEPTION(InputError, iterate(s.ifs, StartSet::points(nan), 3, c));
    Ifs badProb = s.ifs;
    badProb.probabilities = {0.5, -0.1};
    ChaosOptions opt;
    QVERIFY_THROWS_EXCEPTION(InputError, chaosGame(badProb, p.vertices.row(0), opt, c));
}

void TestAttractors::cancellation()
{
    const auto s = buildSubdivisionIfs(bsplineScheme(3), kFig2);
    std::atomic<bool> cancel{false};
    IterationControl control;
    control.cancel = &cancel;
    std::uint64_t seen = 0;
    CallbackSink sink([&](const Mat &, StartSet::Kind, const std::uint8_t *, int) {
        if (++seen == 10000)
            cancel = true;
    });
    const auto stats = iterate(s.ifs, StartSet::points(s.toIfsSpace(pts({{0, 0}}))), 30, sink,
                               control);
    QVERIFY(stats.cancelled);
    QVERIFY(stats.images < 20000);
}

AWB_TEST_APPLESS_MAIN(TestAttractors)
#include "test_attractors.moc"
