// The "complex-bezier" item (model/ComplexBezierItem.h): a Bézier curve split at a complex t
// (004 §3.7), its file form, its parameter t through the undo stack and its derived IFS against
// the core's complexBezierIfs().

#include "ItemKindTests.h"

#include "core/schemes/ComplexBezier.h"
#include "model/ComplexBezierItem.h"
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
    QCOMPARE(test::ownParameters(*c).size(), 1);
    QCOMPARE(test::ownParameters(*c).at(0).type, ParameterInfo::Type::Complex);
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
