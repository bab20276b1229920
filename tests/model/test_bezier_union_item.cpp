// The "bezier-union" item (model/BezierUnionItem.h): several Bézier curves as one attractor
// (002 §6, 000 §2.2), its file form, parameters, point sets and derived IFS against the core.

#include "ItemKindTests.h"

#include "core/ifs/BezierAttractor.h"
#include "model/BezierUnionItem.h"
#include "TestMain.h"

using namespace awb;

namespace {

const QByteArray blockJson = R"({"type": "bezier-union", "name": "Block", "mode": "block",
    "curves": [{"control_points": [[0, 0], [0.5, 1], [1, 0]], "u": 0.5},
               {"control_points": [[1, 0], [2, 1], [2.5, -1], [3, 0]], "u": 0.25}]})";
const QByteArray combinedJson = R"({"type": "bezier-union", "name": "Dusty",
    "mode": "combined",
    "curves": [{"control_points": [[0, 0], [0.5, 1], [1, 0]], "u": 0.5},
               {"control_points": [[0, 0], [0.5, -1], [1, 0]], "u": 0.4}]})";

BezierUnionItem *unionItem(Project &p, const QString &name)
{
    return dynamic_cast<BezierUnionItem *>(p.findItem(name));
}

std::vector<BezierCurveSpec> specs(const BezierUnionItem &item)
{
    std::vector<BezierCurveSpec> out;
    for (int k = 0; k < item.controlPointSetCount(); ++k)
        out.push_back({toMatrix(item.controlPoints(k)), item.spec().u[size_t(k)]});
    return out;
}

bool sameIfs(const Ifs &a, const Ifs &b)
{
    if (a.maps.size() != b.maps.size())
        return false;
    for (size_t i = 0; i < a.maps.size(); ++i)
        if (a.maps[i].A != b.maps[i].A || a.maps[i].b != b.maps[i].b)
            return false;
    return true;
}

} // namespace

class TestBezierUnionItem : public QObject {
    Q_OBJECT
private slots:
    void issueShapesLoadExactly();
    void saveLoadSaveIsByteIdentical();
    void derivedMatchesCore();
    void parameterEditsUndo();
    void pointSetsAreCurves();
    void refusedParameterValues();
    void badFilesNameTheField_data();
    void badFilesNameTheField();
};

void TestBezierUnionItem::issueShapesLoadExactly()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, blockJson + "," + combinedJson, &error), qPrintable(error));
    BezierUnionItem *block = unionItem(p, "Block");
    QVERIFY(block);
    QCOMPARE(block->spec().mode, BezierUnionSpec::Mode::Block);
    QCOMPARE(block->controlPointSetCount(), 2);
    QVERIFY(block->controlPoints(0) == (PointList{{0, 0}, {0.5, 1}, {1, 0}}));
    QVERIFY(block->controlPoints(1) == (PointList{{1, 0}, {2, 1}, {2.5, -1}, {3, 0}}));
    QVERIFY(block->spec().u == (std::vector<double>{0.5, 0.25}));
    QCOMPARE(block->mapCount(), 2);
    BezierUnionItem *dusty = unionItem(p, "Dusty");
    QCOMPARE(dusty->spec().mode, BezierUnionSpec::Mode::Combined);
    QCOMPARE(dusty->mapCount(), 4);
    QVERIFY2(block->derivedIfs(), qPrintable(block->derivedError()));
    QVERIFY2(dusty->derivedIfs(), qPrintable(dusty->derivedError()));
    // Defaults: mode block, u = 1/2.
    Project q;
    QVERIFY(test::load(q, R"({"type": "bezier-union", "name": "d",
                              "curves": [{"control_points": [[0, 0], [1, 1], [2, 0]]}]})"));
    QCOMPARE(unionItem(q, "d")->spec().mode, BezierUnionSpec::Mode::Block);
    QCOMPARE(unionItem(q, "d")->spec().u, std::vector<double>{0.5});
}

void TestBezierUnionItem::saveLoadSaveIsByteIdentical()
{
    Project p;
    QVERIFY(test::load(p, blockJson + "," + combinedJson));
    QVERIFY(unionItem(p, "Block")->setParameter("curves.1.u", 1.0 / 3));
    QVERIFY(unionItem(p, "Dusty")->moveControlPoint(1, {0.1 + 1e-17, 1.0 / 7}, 0, 1));
    QVERIFY(test::reloadsIdentically(p));
    QVERIFY(p.serialize().contains("\"mode\": \"combined\""));
}

void TestBezierUnionItem::derivedMatchesCore()
{
    Project p;
    QVERIFY(test::load(p, blockJson + "," + combinedJson));
    BezierUnionItem *block = unionItem(p, "Block");
    const BezierUnion core = bezierUnion(specs(*block));
    const auto derived = block->derivedIfs();
    QVERIFY(sameIfs(derived->ifs, core.ifs));
    // S_i is block-diagonal in the curves' de Casteljau matrices (3 + 4 rows).
    QCOMPARE(derived->S.count(), 2);
    QCOMPARE(derived->S.real[1].rows(), Eigen::Index(7));
    QVERIFY(derived->S.real[1].topLeftCorner(3, 3) == core.curves[0].S[1]);
    QVERIFY(derived->S.real[1].bottomRightCorner(4, 4) == core.curves[1].S[1]);
    QVERIFY(derived->S.real[1].topRightCorner(3, 4).isZero());
    // The start set reaches both blocks: its image lies on both curves' spaces.
    const Mat start = derived->toIfsSpace(Mat::Zero(1, 2));
    QCOMPARE(start.cols(), Eigen::Index(derived->ifs.dim()));
    QVERIFY2(derived->note.contains("curve 2"), qPrintable(derived->note)); // the cubic lifts

    BezierUnionItem *dusty = unionItem(p, "Dusty");
    const CombinedBezierIfs combined = combinedBezierIfs(specs(*dusty));
    QVERIFY(sameIfs(dusty->derivedIfs()->ifs, combined.ifs));
    QCOMPARE(dusty->derivedIfs()->S.count(), 4);
    QCOMPARE(dusty->derivedIfs()->ifs.dim(), 2);
    // A cubic has no plane maps: the combined mode says which curve.
    QVERIFY(block->setParameter("mode", 1));
    QVERIFY(!block->derivedIfs());
    QVERIFY2(block->derivedError().contains("curve 2"), qPrintable(block->derivedError()));
}

void TestBezierUnionItem::parameterEditsUndo()
{
    Project p;
    QVERIFY(test::load(p, blockJson));
    BezierUnionItem *item = unionItem(p, "Block");
    QStringList keys;
    for (const ParameterInfo &info : test::ownParameters(*item))
        keys << info.key;
    QCOMPARE(keys, (QStringList{"mode", "curves.0.u", "curves.1.u"}));
    QVERIFY(test::ownParameters(*item).at(2).hasSlider());
    QCOMPARE(item->parameter("curves.1.u").toDouble(), 0.25);
    test::roundTrip(
        p, [&] { QVERIFY(item->setParameter("mode", 1)); },
        [&] { QCOMPARE(item->mapCount(), 4); },
        [&] { QCOMPARE(item->mapCount(), 2); });
    test::roundTrip(
        p,
        [&] {
            const int drag = p.beginGesture();
            for (double u : {0.3, 0.35, 0.6})
                QVERIFY(item->setParameter("curves.1.u", u, drag));
        },
        [&] { QCOMPARE(item->spec().u[1], 0.6); },
        [&] { QCOMPARE(item->spec().u[1], 0.25); });
}

void TestBezierUnionItem::pointSetsAreCurves()
{
    Project p;
    QVERIFY(test::load(p, blockJson));
    BezierUnionItem *item = unionItem(p, "Block");
    test::roundTrip(
        p, [&] { QVERIFY(item->moveControlPoint(3, {3, 0.5}, 0, 1)); },
        [&] { QCOMPARE(item->controlPoints(1)[3], (Point{3, 0.5})); },
        [&] { QCOMPARE(item->controlPoints(1)[3], (Point{3, 0})); });
    QVERIFY(!item->moveControlPoint(0, {1, 1}, 0, 2)); // no third curve
}

void TestBezierUnionItem::refusedParameterValues()
{
    Project p;
    QVERIFY(test::load(p, blockJson));
    BezierUnionItem *item = unionItem(p, "Block");
    const int steps = p.undoStack()->count();
    QString error;
    for (double u : {0.0, 1.0, -0.5, std::nan("")}) {
        QVERIFY(!item->setParameter("curves.0.u", u, 0, &error));
        QVERIFY2(error.contains("0 < u < 1"), qPrintable(error));
    }
    QVERIFY(!item->setParameter("curves.2.u", 0.5, 0, &error));
    QVERIFY2(error.contains("no parameter"), qPrintable(error));
    QVERIFY(!item->setParameter("mode", 2, 0, &error));
    QVERIFY(error.contains("not a valid value"));
    QCOMPARE(p.undoStack()->count(), steps);
}

void TestBezierUnionItem::badFilesNameTheField_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    auto item = [](const QByteArray &fields) {
        return R"({"type": "bezier-union", "name": "x", )" + fields + "}";
    };
    const QByteArray pts = R"("control_points": [[0, 0], [1, 1], [2, 0]])";
    QTest::newRow("curves missing") << item(R"("mode": "block")") << R"(field "curves": missing)";
    QTest::newRow("curves empty") << item(R"("curves": [])")
                                  << R"(field "curves": expected a non-empty array)";
    QTest::newRow("curve mistyped") << item(R"("curves": [3])")
                                    << R"(field "curves[1]": expected an object)";
    QTest::newRow("mode unknown")
        << item(R"("mode": "dust", "curves": [{)" + pts + "}]")
        << R"(field "mode": expected one of "block", "combined", got "dust")";
    QTest::newRow("points missing") << item(R"("curves": [{"u": 0.5}])")
                                    << R"(field "curves[1].control_points": missing)";
    QTest::newRow("point not finite")
        << item(R"("curves": [{)" + pts + R"(}, {"control_points": [[0, 1e999]]}])")
        << R"(field "curves[2].control_points[1][2]": 1e999 is not a finite number)";
    QTest::newRow("u mistyped") << item(R"("curves": [{)" + pts + R"(, "u": "half"}])")
                                << R"(field "curves[1].u": expected a number)";
    QTest::newRow("u out of range")
        << item(R"("curves": [{)" + pts + R"(}, {)" + pts + R"(, "u": 1}])")
        << R"(field "curves[2].u": the split parameter u = 1 must satisfy 0 < u < 1)";
    QTest::newRow("depth for the maps")
        << item(R"("mode": "combined", "algorithm": {"depth": 16}, "curves": [{)" + pts
                + "}, {" + pts + "}]")
        << R"(field "algorithm.depth")";
}

void TestBezierUnionItem::badFilesNameTheField()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const QString error = test::loadError(json);
    QVERIFY2(error.startsWith(R"(t.awb: item 1 ("x"): )"), qPrintable(error));
    QVERIFY2(error.contains(message), qPrintable(error));
}

AWB_TEST_GUILESS_MAIN(TestBezierUnionItem)
#include "test_bezier_union_item.moc"
