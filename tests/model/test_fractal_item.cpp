// The "fractal" item (model/FractalItem.h): fractals with control points (000 §4), its file
// form, its parameters through the undo stack and its derived IFS against the core.

#include "ItemKindTests.h"

#include "core/schemes/ControlPointFractal.h"
#include "model/FractalItem.h"
#include "TestMain.h"

using namespace awb;

namespace {

const QByteArray kochJson = R"({"type": "fractal", "name": "Koch", "preset": "koch",
    "control_points": [[0, 0], [0.3333333333333333, 0], [0.5, 0.28867513459481287],
                       [0.6666666666666666, 0], [1, 0]]})";
const QByteArray sierpinskiJson = R"({"type": "fractal", "name": "Sierpinski",
    "preset": "sierpinski", "control_points": [[0, 0], [0.5, 0], [1, 0], [0.75, 0.5],
                                              [0.5, 1], [0.25, 0.5]]})";
const QByteArray customJson = R"({"type": "fractal", "name": "Own", "preset": "custom",
    "weights": "least-norm", "control_points": [[0, 0], [1, 0], [1, 1], [0, 1]],
    "maps": [{"A": [[0.5, 0], [0, 0.5]], "b": [0, 0]},
             {"A": [[0.5, 0], [0, 0.5]], "b": [0.5, 0]},
             {"A": [[0.5, 0], [0, 0.5]], "b": [0.25, 0.5]}]})";

FractalItem *fractal(Project &p, const QString &name)
{
    return dynamic_cast<FractalItem *>(p.findItem(name));
}

bool sameMatrices(const std::vector<Mat> &a, const std::vector<Mat> &b, double tol = 0.0)
{
    if (a.size() != b.size())
        return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].rows() != b[i].rows() || a[i].cols() != b[i].cols()
            || (a[i] - b[i]).cwiseAbs().maxCoeff() > tol)
            return false;
    return true;
}

} // namespace

class TestFractalItem : public QObject {
    Q_OBJECT
private slots:
    void issueShapesLoadExactly();
    void saveLoadSaveIsByteIdentical();
    void derivedMatchesCore();
    void parameterEditsUndo();
    void refusedParameterValues();
    void badFilesNameTheField_data();
    void badFilesNameTheField();
};

void TestFractalItem::issueShapesLoadExactly()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, kochJson + "," + sierpinskiJson + "," + customJson, &error),
             qPrintable(error));
    FractalItem *koch = fractal(p, "Koch");
    QVERIFY(koch);
    QCOMPARE(koch->fractal().preset, FractalSpec::Preset::Koch);
    QCOMPARE(koch->controlPoints().size(), size_t(5));
    QCOMPARE(koch->controlPoints()[2], (Point{0.5, 0.28867513459481287}));
    QCOMPARE(koch->mapCount(), 4);
    FractalItem *sierpinski = fractal(p, "Sierpinski");
    QCOMPARE(sierpinski->fractal().preset, FractalSpec::Preset::Sierpinski);
    QCOMPARE(sierpinski->controlPoints()[3], (Point{0.75, 0.5}));
    QCOMPARE(sierpinski->mapCount(), 3);
    FractalItem *own = fractal(p, "Own");
    QCOMPARE(own->fractal().preset, FractalSpec::Preset::Custom);
    QCOMPARE(own->fractal().weights, FractalSpec::Weights::LeastNorm);
    QCOMPARE(own->fractal().maps.size(), size_t(3));
    QCOMPARE(own->fractal().maps[2].b(0), 0.25);
    QCOMPARE(own->fractal().maps[1].A(1, 1), 0.5);
    QVERIFY(own->fractal().reference.empty());
    for (FractalItem *f : {koch, sierpinski, own})
        QVERIFY2(f->derivedIfs(), qPrintable(f->derivedError()));
    // Weights default to "nearest".
    Project q;
    QByteArray noWeights = customJson;
    noWeights.replace("\"weights\": \"least-norm\",", "");
    QVERIFY(test::load(q, noWeights));
    QCOMPARE(fractal(q, "Own")->fractal().weights, FractalSpec::Weights::Nearest);
}

void TestFractalItem::saveLoadSaveIsByteIdentical()
{
    Project p;
    QVERIFY(test::load(p, kochJson + "," + sierpinskiJson + "," + customJson));
    FractalItem *own = fractal(p, "Own");
    FractalSpec s = own->fractal();
    s.reference = {{0, 0}, {1.0 / 3, 0}, {1, 1e-17}, {0.1, 0.7}};
    QVERIFY(own->setFractal(s));
    QVERIFY(test::reloadsIdentically(p));
    const QByteArray text = p.serialize();
    QVERIFY(text.contains("\"reference_points\""));
    QVERIFY(text.contains("\"preset\": \"sierpinski\""));
}

void TestFractalItem::derivedMatchesCore()
{
    Project p;
    QVERIFY(test::load(p, kochJson + "," + sierpinskiJson + "," + customJson));
    // The presets use the printed S_i exactly.
    QVERIFY(sameMatrices(fractal(p, "Koch")->derivedIfs()->S.real,
                         kochControlPointFractal().S));
    QVERIFY(sameMatrices(fractal(p, "Sierpinski")->derivedIfs()->S.real,
                         sierpinskiControlPointFractal().S));
    // Moving a control point changes the IFS but not the S_i (it deforms the fractal).
    FractalItem *koch = fractal(p, "Koch");
    const Ifs before = koch->derivedIfs()->ifs;
    QVERIFY(koch->moveControlPoint(2, {0.5, 0.5}));
    QVERIFY(sameMatrices(koch->derivedIfs()->S.real, kochControlPointFractal().S));
    QVERIFY((koch->derivedIfs()->ifs.maps[1].A - before.maps[1].A).norm() > 1e-3);
    // Custom: the core's matrices for the maps on the control points, S_i P = f_i(P).
    FractalItem *own = fractal(p, "Own");
    const Mat P = toMatrix(own->controlPoints());
    const ControlPointMatrices cpm =
        controlPointMatrices(own->fractal().maps, P, AffineWeights::LeastNorm);
    const auto derived = own->derivedIfs();
    QVERIFY(sameMatrices(derived->S.real, cpm.S));
    for (size_t i = 0; i < cpm.S.size(); ++i)
        QVERIFY((derived->S.real[i] * P - applyMap(own->fractal().maps[i], P)).norm() < 1e-12);
    // A preset's S_i fix the number of points: no point is removed or inserted...
    QVERIFY(!koch->pointCountEditable(0));
    QVERIFY(!koch->removeControlPoint(4));
    QVERIFY(!koch->insertControlPoint(1, {0.1, 0}));
    QCOMPARE(koch->controlPoints().size(), size_t(5));
    // ...while a custom IFS on its own points takes any number.
    QVERIFY(own->pointCountEditable(0));
    // A file with the wrong number of points for a preset: the core's reason, not a crash.
    Project wrong;
    QVERIFY(test::load(wrong, R"({"type": "fractal", "name": "Koch", "preset": "koch",
        "control_points": [[0, 0], [0.3, 0], [0.5, 0.3], [1, 0]]})"));
    FractalItem *four = fractal(wrong, "Koch");
    QVERIFY(!four->derivedIfs());
    QVERIFY2(four->derivedError().contains("5 control points"), qPrintable(four->derivedError()));
}

void TestFractalItem::parameterEditsUndo()
{
    Project p;
    QVERIFY(test::load(p, kochJson + "," + customJson));
    FractalItem *koch = fractal(p, "Koch");
    QCOMPARE(test::ownParameters(*koch).size(), 1);
    QCOMPARE(koch->parameter("preset").toInt(), 0);
    test::roundTrip(
        p, [&] { QVERIFY(koch->setParameter("preset", 1)); },
        [&] { QCOMPARE(koch->fractal().preset, FractalSpec::Preset::Sierpinski); },
        [&] { QCOMPARE(koch->fractal().preset, FractalSpec::Preset::Koch); });
    p.undoStack()->undo(); // back to Koch
    // To custom: the preset's classic maps and canonical points, the same S_i as printed for
    // Koch (nearest weights reproduce them, 000 §4.1).
    test::roundTrip(
        p, [&] { QVERIFY(koch->setParameter("preset", 2)); },
        [&] {
            QCOMPARE(koch->fractal().maps.size(), size_t(4));
            QCOMPARE(test::ownParameters(*koch).size(), 2);
            QVERIFY(sameMatrices(koch->derivedIfs()->S.real, kochControlPointFractal().S,
                                 1e-12));
        },
        [&] {
            QCOMPARE(koch->fractal().preset, FractalSpec::Preset::Koch);
            QVERIFY(koch->fractal().maps.empty());
        });
    FractalItem *own = fractal(p, "Own");
    QCOMPARE(own->parameter("weights").toInt(), 1);
    test::roundTrip(
        p, [&] { QVERIFY(own->setParameter("weights", 0)); },
        [&] { QCOMPARE(own->fractal().weights, FractalSpec::Weights::Nearest); },
        [&] { QCOMPARE(own->fractal().weights, FractalSpec::Weights::LeastNorm); });
}

void TestFractalItem::refusedParameterValues()
{
    Project p;
    QVERIFY(test::load(p, kochJson));
    FractalItem *koch = fractal(p, "Koch");
    const int steps = p.undoStack()->count();
    QString error;
    QVERIFY(!koch->setParameter("preset", 3, 0, &error));
    QVERIFY2(error.contains("not a valid value"), qPrintable(error));
    // A choice by its file spelling is the same choice; an unknown word is refused.
    QVERIFY(koch->setParameter("preset", QString("koch"), 0, &error));
    QVERIFY(!koch->setParameter("preset", QString("kock"), 0, &error));
    QVERIFY(!koch->setParameter("omega", 0.1, 0, &error));
    QVERIFY2(error.contains("no parameter"), qPrintable(error));
    // The depth bound follows the number of maps of the new spec.
    AlgorithmSpec a = koch->algorithm();
    a.depth = 15; // 4^15 = 2^30 images: allowed
    QVERIFY(koch->setAlgorithm(a));
    QVERIFY(koch->setParameter("preset", 1)); // 3 maps: fewer images, fine
    FractalSpec big = koch->fractal();
    big.preset = FractalSpec::Preset::Custom;
    big.maps.assign(6, AffineMap{Mat::Identity(2, 2) * 0.3, RowVec::Zero(2)});
    QVERIFY(koch->checkFractal(big)); // 6^15 images exceed the bound
    QVERIFY(!koch->setFractal(big));
    QCOMPARE(p.undoStack()->count(), steps + 2);
}

void TestFractalItem::badFilesNameTheField_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    const QByteArray points = R"("control_points": [[0, 0], [1, 0], [1, 1]])";
    auto item = [&](const QByteArray &fields) {
        return R"({"type": "fractal", "name": "x", )" + fields + "}";
    };
    QTest::newRow("preset missing") << item(points) << R"(field "preset": missing)";
    QTest::newRow("preset unknown")
        << item(R"("preset": "dragon", )" + points)
        << R"(field "preset": expected one of "koch", "sierpinski", "custom", got "dragon")";
    QTest::newRow("points missing") << item(R"("preset": "koch")")
                                    << R"(field "control_points": missing)";
    QTest::newRow("point not finite")
        << item(R"("preset": "koch", "control_points": [[0, 0], [1, 1e400]])")
        << R"(field "control_points[2][2]": 1e400 is not a finite number)";
    QTest::newRow("maps missing") << item(R"("preset": "custom", )" + points)
                                  << R"(field "maps": missing)";
    QTest::newRow("maps empty") << item(R"("preset": "custom", "maps": [], )" + points)
                                << R"(field "maps": expected a non-empty array)";
    QTest::newRow("map not object") << item(R"("preset": "custom", "maps": [1], )" + points)
                                    << R"(field "maps[1]": expected an object)";
    QTest::newRow("A missing")
        << item(R"("preset": "custom", "maps": [{"b": [0, 0]}], )" + points)
        << R"(field "maps[1].A": missing)";
    QTest::newRow("A wrong size")
        << item(R"("preset": "custom", "maps": [{"A": [[1, 0]], "b": [0, 0]}], )" + points)
        << R"(field "maps[1].A": expected a 2 x 2 matrix)";
    QTest::newRow("A row wrong size")
        << item(R"("preset": "custom", "maps": [{"A": [[1, 0], [0]], "b": [0, 0]}], )"
                + points)
        << R"(field "maps[1].A[2]": expected an array of 2 numbers)";
    QTest::newRow("A entry not finite")
        << item(R"("preset": "custom", "maps": [{"A": [[1, 0], [0, NaN]], "b": [0, 0]}], )"
                + points)
        << R"(field "maps[1].A[2][2]": NaN is not a finite number)";
    QTest::newRow("b missing")
        << item(R"("preset": "custom", "maps": [{"A": [[1, 0], [0, 1]]}], )" + points)
        << R"(field "maps[1].b": missing)";
    QTest::newRow("b mistyped")
        << item(R"("preset": "custom", "maps": [{"A": [[1, 0], [0, 1]], "b": "0"}], )"
                + points)
        << R"(field "maps[1].b": expected an array of 2 numbers)";
    const QByteArray oneMap = R"("maps": [{"A": [[0.5, 0], [0, 0.5]], "b": [0, 0]}], )";
    QTest::newRow("weights unknown")
        << item(R"("preset": "custom", "weights": "far", )" + oneMap + points)
        << R"(field "weights": expected one of "nearest", "least-norm", got "far")";
    QTest::newRow("reference too few")
        << item(R"("preset": "custom", "reference_points": [[0, 0]], )" + oneMap + points)
        << R"(field "reference_points": need at least 3 reference points)";
    QTest::newRow("depth for the maps")
        << item(R"("preset": "koch", "algorithm": {"depth": 16}, )" + points)
        << R"(field "algorithm.depth")";
}

void TestFractalItem::badFilesNameTheField()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const QString error = test::loadError(json);
    QVERIFY2(error.startsWith(R"(t.awb: item 1 ("x"): )"), qPrintable(error));
    QVERIFY2(error.contains(message), qPrintable(error));
}

AWB_TEST_GUILESS_MAIN(TestFractalItem)
#include "test_fractal_item.moc"
