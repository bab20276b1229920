// Derived data: each item's IFS equals the core's for the same inputs, is cached until an edit
// and recomputed after it, explains why it cannot be computed, and draws the right curve
// (including a complex Bézier parameter). Eigenvalue plots follow their source.

#include "TestProjects.h"
#include "model/ProjectIO.h"

#include <QJsonDocument>

#include "core/ifs/Attractor.h"
#include "core/schemes/Curves.h"
#include "core/analysis/Geometry.h"
#include "core/schemes/Scheme.h"

#include <QSignalSpy>
#include <QtTest>

#include "TestMain.h"

using namespace awb;
using awb::test::curve;
using awb::test::scheme;
using K = SchemeSpec::Kind;

namespace {

bool sameMatrix(const Mat &a, const Mat &b)
{
    return a.rows() == b.rows() && a.cols() == b.cols() && (a.array() == b.array()).all();
}

// Projected points of F^depth(start) for view 0.
Mat attractorPoints(const DerivedIfs &d, const StartSet &start, int depth)
{
    PointCollector sink(d.ifs.views.front());
    iterate(d.ifs, start, depth, sink);
    return sink.points();
}

// The points B(s) of the complex Bézier curve with control points z for the parameters of the
// parameter IFS {s -> t s, s -> t + (1 - t) s} at `depth`, started from s = s0.
Mat complexCurvePoints(const CVec &z, Complex t, int depth, Complex s0 = 1.0)
{
    std::vector<Complex> params{s0};
    for (int k = 0; k < depth; ++k) {
        std::vector<Complex> next;
        for (Complex s : params) {
            next.push_back(t * s);
            next.push_back(t + (1.0 - t) * s);
        }
        params.swap(next);
    }
    const CVec b = bezierPoints(z, params);
    Mat out(b.size(), 2);
    out.col(0) = b.real();
    out.col(1) = b.imag();
    return out;
}

} // namespace

class TestDerived : public QObject {
    Q_OBJECT

private slots:
    void realSchemesMatchTheCore_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<int>("degree");
        QTest::newRow("bspline 3") << int(K::BSpline) << 3;
        QTest::newRow("bspline 2") << int(K::BSpline) << 2;
        QTest::newRow("end-interpolating 3") << int(K::EndInterpolatingBSpline) << 3;
        QTest::newRow("chaikin") << int(K::Chaikin) << 0;
        QTest::newRow("corner cutting") << int(K::CornerCutting) << 0;
        QTest::newRow("four-point") << int(K::FourPoint) << 0;
        QTest::newRow("bezier 5") << int(K::Bezier) << 5;
        QTest::newRow("matrices") << int(K::Matrices) << 0;
    }

    void realSchemesMatchTheCore()
    {
        QFETCH(int, kind);
        QFETCH(int, degree);
        SchemeSpec s = scheme(K(kind));
        s.degree = degree;
        s.a = 0.2;
        s.b = 0.65;
        s.matrices = test::chaikinMatrices();
        PointList points{{0, 0}, {1, 2}, {2.5, 2.25}, {4, 1}, {5, -0.5}, {6.5, 0.75}};
        if (s.kind == K::Matrices)
            points.resize(3);
        const auto item = curve("c", s, points);
        const auto d = item->derivedIfs();
        QVERIFY2(d, qPrintable(item->derivedError()));
        const SubdivisionIfs core = buildSubdivisionIfs(*s.makeScheme(), toMatrix(points));
        QCOMPARE(d->ifs.size(), core.ifs.size());
        QCOMPARE(item->mapCount(), core.ifs.size());
        for (int i = 0; i < core.ifs.size(); ++i) {
            QVERIFY(sameMatrix(d->ifs.maps[i].A, core.ifs.maps[i].A));
            QVERIFY(sameMatrix(d->ifs.maps[i].b, core.ifs.maps[i].b));
            QVERIFY(sameMatrix(d->S.real[i], core.matrices.S[i]));
            QVERIFY(sameMatrix(d->A.real[i], core.lifted[i].A));
        }
        QCOMPARE(d->ifs.space, std::string("lifted"));
        QVERIFY(d->subdivision);
        QVERIFY(d->note.isEmpty());
    }

    void attractorLiesOnTheCurve_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<bool>("collinear"); // the last three points: barycentric form
        QTest::newRow("bezier") << int(K::Bezier) << false;
        QTest::newRow("bezier, singular P") << int(K::Bezier) << true;
        QTest::newRow("bspline") << int(K::BSpline) << false;
        QTest::newRow("bspline, singular P") << int(K::BSpline) << true;
    }

    void attractorLiesOnTheCurve()
    {
        QFETCH(int, kind);
        QFETCH(bool, collinear);
        PointList points{{0, 0}, {1, 2}, {3, 2}, {4, collinear ? 2.0 : 0.5}};
        if (collinear)
            points.back().x = 5;
        auto item = curve("c", scheme(K(kind)), points);
        QVERIFY(item->setStartSet({StartSetSpec::Kind::Segment, {{-1, 3}, {6, -2}}}));
        const auto d = item->derivedIfs();
        QVERIFY2(d, qPrintable(item->derivedError()));
        QCOMPARE(d->ifs.space == "barycentric", collinear);
        QCOMPARE(d->note.contains("collinear"), collinear);
        QCOMPARE(d->A.unavailable.isEmpty(), !collinear);
        const StartSet start = item->coreStartSet(*d);
        QVERIFY(start.kind == StartSet::Kind::Polyline); // (the core's toString defeats QCOMPARE)
        const Mat pts = attractorPoints(*d, start, 14);
        const Mat exact = *item->scheme().makeScheme()->exactCurve(toMatrix(points), 20001);
        // 2^14 images of a segment: their size shrinks like 2^-14 (times the start's size).
        QVERIFY2(distanceToPolyline(pts, exact) < 1e-2,
                 qPrintable(QString::number(distanceToPolyline(pts, exact))));
        QVERIFY(directedDistance(exact, pts) < 1e-2);
    }

    void cacheAndInvalidation()
    {
        Project p;
        auto *c = static_cast<SubdivisionCurveItem *>(
            p.addItem(curve("c", scheme(K::BSpline), test::fivePoints())));
        const auto first = c->derivedIfs();
        QVERIFY(first);
        QCOMPARE(c->derivedIfs(), first); // cached: the same object
        QSignalSpy spy(c, &Item::derivedChanged);
        const quint64 generation = c->generation();
        c->moveControlPoint(4, {6, 6});
        QCOMPARE(spy.count(), 1);
        QCOMPARE(c->generation(), generation + 1);
        const auto second = c->derivedIfs();
        QVERIFY(second && second != first);
        QVERIFY(!sameMatrix(second->ifs.maps[0].b, first->ifs.maps[0].b));
        p.undoStack()->undo();
        QCOMPARE(spy.count(), 2);
        QCOMPARE(c->generation(), generation + 2);
        const auto third = c->derivedIfs();
        QVERIFY(third != second);
        for (int i = 0; i < 2; ++i) {
            QVERIFY(sameMatrix(third->ifs.maps[i].A, first->ifs.maps[i].A));
            QVERIFY(sameMatrix(third->ifs.maps[i].b, first->ifs.maps[i].b));
        }
    }

    void errorsExplainWhy()
    {
        Project p;
        auto *few = p.addItem(curve("few", scheme(K::BSpline), {{0, 0}, {1, 1}, {2, 0}}));
        QCOMPARE(few->derivedError(),
                 QString("uniform B-spline of degree 3 needs at least 4 control points, got 3"));
        SchemeSpec bezier = scheme(K::Bezier);
        auto *many = p.addItem(curve("many", bezier, test::fivePoints()));
        QVERIFY(many->derivedError().contains("needs exactly 4 control points, got 5"));
        auto *random = static_cast<AttractorItem *>(
            p.addItem(curve("random", scheme(K::Chaikin), test::fivePoints())));
        AlgorithmSpec a;
        a.mode = AlgorithmSpec::Mode::Random;
        a.probabilities = {1, 2, 3};
        QVERIFY(random->setAlgorithm(a));
        QCOMPARE(random->derivedError(), QString("the IFS has 2 maps but 3 probabilities"));
        QVERIFY(!random->derivedIfs());
        a.probabilities = {1, 3};
        QVERIFY(random->setAlgorithm(a));
        QVERIFY(random->derivedIfs());
        QCOMPARE(random->derivedIfs()->ifs.probabilities, (std::vector<double>{1, 3}));
        a.mode = AlgorithmSpec::Mode::Deterministic; // probabilities only count when random
        a.probabilities = {1, 2, 3};
        QVERIFY(random->setAlgorithm(a));
        QVERIFY(random->derivedIfs());
        QCOMPARE(p.problems(),
                 (QStringList{"few: " + few->derivedError(), "many: " + many->derivedError()}));
    }

    void complexBezierLifted()
    {
        // Degree 1, P = 0 and 1, t = (1 + i)/2: f_1(z) = t z, f_2(z) = t + (1 - t) z (Lévy C).
        const Complex t(0.5, 0.5);
        SchemeSpec s = scheme(K::Bezier);
        s.degree = 1;
        s.t = t;
        auto item = curve("levy", s, {{0, 0}, {1, 0}});
        const auto d = item->derivedIfs();
        QVERIFY2(d, qPrintable(item->derivedError()));
        QCOMPARE(d->ifs.dim(), 2);
        QVERIFY(d->S.isComplex() && d->A.isComplex());
        for (Complex z : {Complex(0.3, -0.7), Complex(2, 1), Complex(-1, 0.25)}) {
            Mat plane(1, 2);
            plane << z.real(), z.imag();
            const Mat x = d->toIfsSpace(plane);
            const Complex expected[2] = {t * z, t + (1.0 - t) * z};
            for (int i = 0; i < 2; ++i) {
                const Mat y = project(d->ifs.views[0], applyMap(d->ifs.maps[i], x));
                QVERIFY(std::abs(Complex(y(0, 0), y(0, 1)) - expected[i]) < 1e-14);
            }
        }
        // Degree 2: the attractor from the last control point is the complex curve B(sigma).
        s.degree = 2;
        s.t = Complex(0.5, 0.3);
        const PointList points{{0, 0}, {0.5, 1.0}, {1, 0.25}};
        item = curve("quadratic", s, points);
        const auto q = item->derivedIfs();
        QVERIFY2(q, qPrintable(item->derivedError()));
        QCOMPARE(q->ifs.space, std::string("complex lifted"));
        CVec z(3);
        for (int k = 0; k < 3; ++k)
            z(k) = Complex(points[k].x, points[k].y);
        Mat last(1, 2);
        last << points[2].x, points[2].y;
        const Mat pts = attractorPoints(*q, StartSet::points(q->toIfsSpace(last)), 9);
        const Mat expected = complexCurvePoints(z, s.t, 9);
        QCOMPARE(pts.rows(), expected.rows());
        QVERIFY(hausdorffDistance(pts, expected) < 1e-12);
    }

    void complexBezierCoincidingPoints()
    {
        // The last two control points coincide: 000's lifting would be singular, so the core
        // frees another pair of distinct points and the IFS stays lifted (A_i available).
        SchemeSpec s = scheme(K::Bezier);
        s.degree = 2;
        s.t = Complex(0.4, -0.3);
        const PointList points{{0, 0}, {1, 1}, {1, 1}};
        auto item = curve("coincide", s, points);
        const auto d = item->derivedIfs();
        QVERIFY2(d, qPrintable(item->derivedError()));
        QCOMPARE(d->ifs.space, std::string("complex lifted"));
        QVERIFY(d->A.unavailable.isEmpty());
        QCOMPARE(d->A.complex.size(), std::size_t(2));
        QCOMPARE(d->ifs.dim(), 4);
        CVec z(3);
        for (int k = 0; k < 3; ++k)
            z(k) = Complex(points[k].x, points[k].y);
        // p_0 is in a free row (the farthest pair), so its lifted point is (z_0, 0): the
        // images of depth 8 are the curve points of the parameters reached from s = 0.
        Mat first(1, 2);
        first << points[0].x, points[0].y;
        const Mat pts = attractorPoints(*d, StartSet::points(d->toIfsSpace(first)), 8);
        QVERIFY(hausdorffDistance(pts, complexCurvePoints(z, s.t, 8, 0.0)) < 1e-12);
        const IfsCheck check = checkIfs(d->ifs);
        QVERIFY2(check.contractive, check.message.c_str());
        // All points equal: a single point, no lifting; the item says why.
        auto point = curve("point", s, {{1, 1}, {1, 1}, {1, 1}});
        QVERIFY(!point->derivedIfs());
        QVERIFY2(point->derivedError().contains("coincide"), qPrintable(point->derivedError()));
    }

    // Issue 45: a Fractint map x -> 1.5 x imported as a fractal with control points is not
    // contractive; the message names the plane map's spectral radius 1.5, not only the
    // lifted space's (where the lifting's own coordinate scales by 2).
    void notContractiveNamesThePlaneMap()
    {
        QString why;
        std::unique_ptr<Item> item = ProjectIO::itemFromJson(
            QJsonDocument::fromJson(R"({"type": "fractal", "name": "expand", "preset": "custom",
                "maps": [{"A": [[1.5, 0], [0, 1.5]], "b": [0, 0]},
                         {"A": [[0.5, 0], [0, 0.5]], "b": [0.5, 0]}],
                "control_points": [[0, -20], [380, -20], [380, 20], [0, 20]],
                "weights": "nearest"})")
                .object(),
            &why);
        QVERIFY2(item, qPrintable(why));
        const auto d = static_cast<AttractorItem *>(item.get())->derivedIfs();
        QVERIFY(d);
        QCOMPARE(d->ifs.space, std::string("lifted"));
        const IfsCheck check = checkIfs(d->ifs);
        QVERIFY(!check.contractive);
        QVERIFY2(QString::fromStdString(check.message)
                     .startsWith("map 1 is not contractive: its map of the plane has spectral "
                                 "radius 1.5 >= 1 (2 in the lifted space of its control points)"),
                 check.message.c_str());
        QCOMPARE(check.maps[0].spectralRadius, 2.0);
    }

    void eigenvaluePlots()
    {
        Project p;
        auto *c = static_cast<SubdivisionCurveItem *>(p.addItem(
            curve("cubic", scheme(K::Bezier), {{0, 0}, {1, 2}, {3, 2}, {4, 0}})));
        auto plotOwner = std::make_unique<EigenvaluePlotItem>();
        auto *plot = static_cast<EigenvaluePlotItem *>(p.addItem(std::move(plotOwner)));
        QCOMPARE(plot->derivedError(), QString("no item is chosen to analyse"));
        plot->setSource("cubic");
        auto e = plot->eigenvalues();
        QVERIFY2(e, qPrintable(plot->derivedError()));
        QCOMPARE(e->symbol, QString("S"));
        QCOMPARE(e->spectra.size(), size_t(2));
        // L(1/2) and R(1/2) have the eigenvalues 1, 1/2, 1/4, 1/8 (004 §2.1).
        for (const Spectrum &s : e->spectra) {
            QCOMPARE(s.values.size(), size_t(4));
            for (int k = 0; k < 4; ++k)
                QVERIFY(std::abs(s.values[k] - std::pow(0.5, k)) < 1e-12);
        }
        QVERIFY(e->subdominants[0].kind == SubdominantKind::RealPositive);
        QVERIFY(std::abs(e->subdominants[0].modulus - 0.5) < 1e-12);
        plot->setMatrixKind(EigenvaluePlotItem::MatrixKind::A);
        e = plot->eigenvalues();
        QVERIFY2(e, qPrintable(plot->derivedError()));
        for (const Spectrum &s : e->spectra) { // M_i is similar to S_i: A_i drops the 1
            QCOMPARE(s.values.size(), size_t(3));
            for (int k = 0; k < 3; ++k)
                QVERIFY(std::abs(s.values[k] - std::pow(0.5, k + 1)) < 1e-12);
        }
        QVERIFY(std::abs(e->subdominants[1].modulus - 0.5) < 1e-12);

        // A complex t: L(t) has the eigenvalues 1, t, t^2, R(t) 1, 1 - t, (1 - t)^2.
        SchemeSpec s = c->scheme();
        s.degree = 2;
        s.t = Complex(0.5, 0.25);
        c->setScheme(s);
        c->removeControlPoint(3);
        plot->setMatrixKind(EigenvaluePlotItem::MatrixKind::S);
        e = plot->eigenvalues();
        QVERIFY2(e, qPrintable(plot->derivedError()));
        QVERIFY(e->complexMatrices);
        for (int i = 0; i < 2; ++i) {
            const Complex r = i == 0 ? s.t : 1.0 - s.t;
            std::vector<Complex> expected{1.0, r, r * r};
            for (const Complex &v : e->spectra[i].values) {
                auto near = [&](Complex x) { return std::abs(x - v) < 1e-12; };
                QVERIFY(std::any_of(expected.begin(), expected.end(), near));
            }
        }
        QCOMPARE(e->spectra[0].values.size(), size_t(3));
    }

    void plotsFollowTheirSource()
    {
        Project p;
        auto *c = static_cast<SubdivisionCurveItem *>(
            p.addItem(curve("c", scheme(K::BSpline), test::fivePoints())));
        auto *other = static_cast<SubdivisionCurveItem *>(
            p.addItem(curve("other", scheme(K::Chaikin), test::fivePoints())));
        auto *plot = static_cast<EigenvaluePlotItem *>(
            p.addItem(std::make_unique<EigenvaluePlotItem>()));
        plot->setSource("c");
        const auto first = plot->eigenvalues();
        QVERIFY(first);
        QSignalSpy spy(plot, &Item::derivedChanged);
        other->moveControlPoint(0, {9, 9}); // unrelated: kept
        QCOMPARE(spy.count(), 0);
        QCOMPARE(plot->eigenvalues(), first);
        c->moveControlPoint(0, {9, 9}); // the source (A_i change with P; S_i do not)
        QCOMPARE(spy.count(), 1);
        QVERIFY(plot->eigenvalues() != first);

        p.removeItem(c);
        QCOMPARE(plot->derivedError(), QString("there is no item called \"c\""));
        p.undoStack()->undo();
        QVERIFY(plot->eigenvalues());

        c->removeControlPoints({0, 1, 2});
        QCOMPARE(plot->derivedError(),
                 QString("\"c\" cannot be computed: uniform B-spline of degree 3 needs at "
                         "least 4 control points, got 2"));
        p.undoStack()->undo();
        QVERIFY(plot->eigenvalues());

        plot->setSource(plot->name());
        QCOMPARE(plot->derivedError(),
                 QString("\"%1\" (Eigenvalue plot) has no matrices to analyse")
                     .arg(plot->name()));
        plot->setSource("c");
        plot->setMatrixKind(EigenvaluePlotItem::MatrixKind::A);
        c->moveControlPoints({{2, {0, 0}}, {3, {1, 0}}, {4, {2, 0}}}); // last three collinear
        QVERIFY(plot->derivedError().startsWith("\"c\" has no matrices A: control points "));
        QVERIFY(plot->derivedError().contains("collinear"));
    }

    void startSetKinds()
    {
        auto item = curve("c", scheme(K::BSpline), test::fivePoints());
        const auto d = item->derivedIfs();
        QVERIFY(d);
        const struct {
            StartSetSpec spec;
            StartSet::Kind kind;
        } cases[] = {
            {{StartSetSpec::Kind::Point, {{1, 2}}}, StartSet::Kind::Points},
            {{StartSetSpec::Kind::Segment, {{1, 2}, {3, 4}}}, StartSet::Kind::Polyline},
            {{StartSetSpec::Kind::Triangle, {{0, 0}, {1, 0}, {0, 1}}}, StartSet::Kind::Polygon},
            {{StartSetSpec::Kind::Polygon, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}},
             StartSet::Kind::Polygon},
            {{StartSetSpec::Kind::Points, {{0, 0}, {5, 5}}}, StartSet::Kind::Points},
        };
        for (const auto &c : cases) {
            QVERIFY(item->setStartSet(c.spec));
            const StartSet s = item->coreStartSet(*d);
            QVERIFY(s.kind == c.kind);
            QCOMPARE(s.vertices.rows(), Eigen::Index(c.spec.points.size()));
            QCOMPARE(s.vertices.cols(), Eigen::Index(d->ifs.dim()));
            const Mat shown = project(d->ifs.views[0], s.vertices);
            QVERIFY(sameMatrix(shown, toMatrix(c.spec.points)));
        }
    }
};

AWB_TEST_GUILESS_MAIN(TestDerived)
#include "test_derived.moc"
