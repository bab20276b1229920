// The "complex-bezier" item (model/ComplexBezierItem.h): a Bézier curve split at a complex t
// (004 §3.7), its file form, its parameter t through the undo stack and its derived IFS against
// the core's complexBezierIfs().

#include "ItemKindTests.h"

#include "core/schemes/ComplexBezier.h"
#include "model/ComplexBezierItem.h"
#include "model/ExactCurve.h"
#include "TestPaths.h"
#include "TestMain.h"

using namespace awb;

namespace {

const QByteArray levyJson = R"({"type": "complex-bezier", "name": "Lévy",
    "control_points": [[0, 0], [1, 0]], "t": [0.5, 0.5]})";
const QByteArray takagiJson = R"({"type": "complex-bezier", "name": "Takagi-like",
    "control_points": [[0, 0], [0.5, 2], [0.5, 0]], "t": [0.5, 0.01]})";

ComplexBezierItem *item(Project &p, const QString &name)
{
    return dynamic_cast<ComplexBezierItem *>(p.findItem(name));
}

} // namespace

class TestComplexBezierItem : public QObject {
    Q_OBJECT
private slots:
    void issueShapesLoadExactly();
    void saveLoadSaveIsByteIdentical();
    void derivedMatchesCore();
    void notHyperbolicIsReported();
    void parameterEditsUndo();
    void refusedParameterValues();
    void scaledCoordinatesApproachTakagi();
    void badFilesNameTheField_data();
    void badFilesNameTheField();
};

void TestComplexBezierItem::issueShapesLoadExactly()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, levyJson + "," + takagiJson, &error), qPrintable(error));
    QCOMPARE(item(p, "Lévy")->t(), std::complex<double>(0.5, 0.5));
    QVERIFY(item(p, "Lévy")->controlPoints() == (PointList{{0, 0}, {1, 0}}));
    QCOMPARE(item(p, "Takagi-like")->t(), std::complex<double>(0.5, 0.01));
    QCOMPARE(item(p, "Takagi-like")->controlPoints()[1], (Point{0.5, 2}));
    QCOMPARE(item(p, "Lévy")->mapCount(), 2);
}

void TestComplexBezierItem::saveLoadSaveIsByteIdentical()
{
    Project p;
    QVERIFY(test::load(p, levyJson + "," + takagiJson));
    QVERIFY(item(p, "Lévy")->setT({1.0 / 3, -0.1 - 1e-17}));
    QVERIFY(test::reloadsIdentically(p));
    QVERIFY(p.serialize().contains("\"t\": ["));
}

void TestComplexBezierItem::derivedMatchesCore()
{
    Project p;
    QVERIFY(test::load(p, levyJson + "," + takagiJson));
    for (const QString name : {"Lévy", "Takagi-like"}) {
        ComplexBezierItem *c = item(p, name);
        const auto derived = c->derivedIfs();
        QVERIFY2(derived, qPrintable(c->derivedError()));
        const Mat P = toMatrix(c->controlPoints());
        const CVec z = P.col(0).cast<Complex>() + Complex(0, 1) * P.col(1).cast<Complex>();
        const ComplexBezierIfs core = complexBezierIfs(z, c->t());
        QCOMPARE(derived->ifs.maps.size(), size_t(2));
        for (size_t i = 0; i < 2; ++i) {
            QVERIFY(derived->ifs.maps[i].A == core.ifs.maps[i].A);
            QVERIFY(derived->ifs.maps[i].b == core.ifs.maps[i].b);
            QVERIFY(derived->S.complex[i] == core.S[i]);
            QVERIFY(derived->liftedComplex.at(i) == core.M[i]);
        }
        QVERIFY(derived->S.isComplex());
        QCOMPARE(derived->A.complex[0].rows(), Eigen::Index(core.degree()));
        QVERIFY(!derived->note.isEmpty());
        QCOMPARE(derived->toIfsSpace(Mat::Zero(1, 2)).cols(), Eigen::Index(2 * core.degree()));
    }
    // Lévy: f_1(z) = t z, so A_1 = [[t]] (the subdominant eigenvalue t, 004 §3.7).
    const Complex a = item(p, "Lévy")->derivedIfs()->A.complex[0](0, 0);
    QVERIFY2(std::abs(a - Complex(0.5, 0.5)) < 1e-12, qPrintable(QString::number(a.real())));
}

void TestComplexBezierItem::notHyperbolicIsReported()
{
    Project p;
    QVERIFY(test::load(p, levyJson));
    ComplexBezierItem *c = item(p, "Lévy");
    QVERIFY(c->setT({1.2, 0.3}));
    QVERIFY(!c->derivedIfs());
    const ParameterReport report = classifyParameter({1.2, 0.3});
    QVERIFY(!report.hyperbolic);
    QCOMPARE(c->derivedError(), QString::fromStdString(report.message));
}

void TestComplexBezierItem::parameterEditsUndo()
{
    Project p;
    QVERIFY(test::load(p, levyJson));
    ComplexBezierItem *c = item(p, "Lévy");
    QCOMPARE(test::ownParameters(*c).size(), 2);  // t and the scaled coordinates
    QCOMPARE(test::ownParameters(*c).at(0).type, ParameterInfo::Type::Complex);
    QCOMPARE(test::ownParameters(*c).at(1).type, ParameterInfo::Type::Bool);
    QCOMPARE(c->parameter("t").toPointF(), QPointF(0.5, 0.5));
    test::roundTrip(
        p,
        [&] {
            const int drag = p.beginGesture();
            for (double y : {0.4, 0.3, 0.25})
                QVERIFY(c->setParameter("t", QPointF(0.5, y), drag));
        },
        [&] { QCOMPARE(c->t(), std::complex<double>(0.5, 0.25)); },
        [&] { QCOMPARE(c->t(), std::complex<double>(0.5, 0.5)); });
}

// Takagi's function T(x) = sum over n of dist(2^n x, Z) / 2^n (to 2^-40), recomputed here.
double takagiSum(double x)
{
    double sum = 0, scale = 1;
    for (int n = 0; n < 40; ++n, scale *= 0.5) {
        const double u = x / scale;
        sum += std::abs(u - std::round(u)) * scale;
    }
    return sum;
}

// 004 Thm 3.7.3 and Figs. 3.6-3.8 (examples/004-fig3.6-3.8-takagi-scaled.awb): in the scaled
// coordinates g(z, 1/(2y)) the curve of t = 1/2 + iy with control points 0, 1 approaches the
// Takagi graph x + i T(x) as y -> 0; at y = 2^-10 it is incident with it (Fig. 3.8).
void TestComplexBezierItem::scaledCoordinatesApproachTakagi()
{
    Project p;
    QString error;
    QVERIFY2(p.open(awb::test::sourceDir() + "/examples/004-fig3.6-3.8-takagi-scaled.awb", &error),
             qPrintable(error));
    QCOMPARE(p.childCount(), 4);
    std::vector<double> gaps;
    for (int k = 0; k < 4; ++k) {
        auto *c = qobject_cast<ComplexBezierItem *>(p.child(k));
        QVERIFY(c && c->scaled() && c->scaledApplies());
        const auto d = c->derivedIfs();
        QVERIFY2(d, qPrintable(c->derivedError()));
        QVERIFY(d->note.startsWith("Scaled coordinates"));
        PointCollector points(d->ifs.views.front());
        iterate(d->ifs, c->coreStartSet(*d), 12, points);
        const Mat X = points.points();
        double gap = 0;  // the largest vertical distance to the graph
        for (Eigen::Index r = 0; r < X.rows(); ++r)
            if (X(r, 0) >= 0 && X(r, 0) <= 1)
                gap = std::max(gap, std::abs(X(r, 1) - takagiSum(X(r, 0))));
        gaps.push_back(gap);
        // The exact curve the view overlays is the graph itself, scaled.
        const auto exact = exactCurveOf(c, 257);
        QVERIFY(exact);
        for (Eigen::Index r = 0; r < exact->points.rows(); ++r)
            QVERIFY(std::abs(exact->points(r, 1) - takagiSum(exact->points(r, 0))) < 1e-9);
        // Not an isometry: no certified distance in these coordinates.
        QVERIFY(!certifiedExactCurveOf(c));
    }
    qInfo("largest vertical gap to the Takagi graph: y = 1/2 %g, 1/4 %g, 1/8 %g, 2^-10 %g",
          gaps[0], gaps[1], gaps[2], gaps[3]);
    QVERIFY(gaps[0] > gaps[1] && gaps[1] > gaps[2] && gaps[2] > gaps[3]);
    QVERIFY(gaps[3] < 0.01);  // Fig. 3.8: "we can only see T"
    QVERIFY(gaps[1] > 0.05);  // Fig. 3.7: y = 1/4 still makes crunodes
    // Off the Takagi family the option is kept but does nothing, and the note says why.
    auto *c = qobject_cast<ComplexBezierItem *>(p.child(1));
    QVERIFY(c->setParameter("t", QPointF(0.4, 0.25)));
    QVERIFY(!c->scaledApplies());
    QVERIFY2(c->derivedIfs()->note.contains("drawn unscaled"), qPrintable(c->derivedIfs()->note));
}

void TestComplexBezierItem::refusedParameterValues()
{
    Project p;
    QVERIFY(test::load(p, levyJson));
    ComplexBezierItem *c = item(p, "Lévy");
    const int steps = p.undoStack()->count();
    QString error;
    QVERIFY(!c->setParameter("t", QPointF(std::nan(""), 0), 0, &error));
    QVERIFY2(error.contains("finite"), qPrintable(error));
    QVERIFY(!c->setParameter("t", 0.5, 0, &error));
    QVERIFY2(error.contains("not a valid value"), qPrintable(error));
    QVERIFY(!c->setParameter("u", 0.5, 0, &error));
    QVERIFY2(error.contains("no parameter"), qPrintable(error));
    QCOMPARE(p.undoStack()->count(), steps);
}

void TestComplexBezierItem::badFilesNameTheField_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    auto x = [](const QByteArray &fields) {
        return R"({"type": "complex-bezier", "name": "x", )" + fields + "}";
    };
    const QByteArray pts = R"("control_points": [[0, 0], [1, 0]])";
    QTest::newRow("t missing") << x(pts) << R"(field "t": missing)";
    QTest::newRow("t real") << x(pts + R"(, "t": 0.5)") << R"(field "t": expected [re, im])";
    QTest::newRow("t three") << x(pts + R"(, "t": [0.5, 0.5, 0])")
                             << R"(field "t": expected [re, im])";
    QTest::newRow("t not finite") << x(pts + R"(, "t": [0.5, Infinity])")
                                  << R"(field "t[2]": Infinity is not a finite number)";
    QTest::newRow("t mistyped") << x(pts + R"(, "t": ["a", 0.5])")
                                << R"(field "t[1]": expected a number)";
    QTest::newRow("points missing") << x(R"("t": [0.5, 0.5])")
                                    << R"(field "control_points": missing)";
    QTest::newRow("point mistyped") << x(R"("t": [0.5, 0.5], "control_points": [[0, 0], 1])")
                                    << R"(field "control_points[2]")";
}

void TestComplexBezierItem::badFilesNameTheField()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const QString error = test::loadError(json);
    QVERIFY2(error.startsWith(R"(t.awb: item 1 ("x"): )"), qPrintable(error));
    QVERIFY2(error.contains(message), qPrintable(error));
}

AWB_TEST_GUILESS_MAIN(TestComplexBezierItem)
#include "test_complex_bezier_item.moc"
