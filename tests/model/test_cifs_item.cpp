// The "cifs" item (model/CifsItem.h): the fern built of Sierpiński gaskets (003 §2.2, Figs.
// 4-5), its file form, its parameters through the undo stack and its drawing through the core's
// CIFS iteration.

#include "ItemKindTests.h"

#include "core/ifs/Cifs.h"
#include "model/CifsItem.h"
#include "TestMain.h"

using namespace awb;

namespace {

const QByteArray fernJson = R"({"type": "cifs", "name": "Fern", "preset": "fern-sierpinski",
    "redirected": 2, "state": "Fern"})";
const QByteArray gasketJson = R"({"type": "cifs", "name": "Gasket",
    "preset": "fern-sierpinski", "redirected": 1, "state": "Sierpinski",
    "control_points": [[-3, 0], [3, 0], [0, 8]]})";

CifsItem *cifsItem(Project &p, const QString &name)
{
    return dynamic_cast<CifsItem *>(p.findItem(name));
}

class Collect : public AttractorSink {
public:
    Projection view;
    std::vector<Mat> images;
    void consume(const Mat &vertices, StartSet::Kind, const std::uint8_t *, int) override
    {
        images.push_back(project(view, vertices));
    }
};

} // namespace

class TestCifsItem : public QObject {
    Q_OBJECT
private slots:
    void issueShapesLoadExactly();
    void saveLoadSaveIsByteIdentical();
    void iterateIsTheCoresAutomaton();
    void parameterEditsUndo();
    void refusedParameterValues();
    void badFilesNameTheField_data();
    void badFilesNameTheField();
};

void TestCifsItem::issueShapesLoadExactly()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, fernJson + "," + gasketJson, &error), qPrintable(error));
    CifsItem *fern = cifsItem(p, "Fern");
    QCOMPARE(fern->spec().redirected, 2);
    QCOMPARE(fern->spec().state, QString("Fern"));
    QVERIFY(fern->controlPoints() == (PointList{{-3, 0}, {3, 0}, {0, 10}})); // fernFrame()
    CifsItem *gasket = cifsItem(p, "Gasket");
    QCOMPARE(gasket->spec().redirected, 1);
    QCOMPARE(gasket->spec().state, QString("Sierpinski"));
    QCOMPARE(gasket->controlPoints()[2], (Point{0, 8}));
    for (CifsItem *c : {fern, gasket}) {
        QVERIFY2(c->derivedIfs(), qPrintable(c->derivedError()));
        QVERIFY(c->derivedIfs()->iterate);
        QVERIFY(c->derivedIfs()->ifs.maps.empty());
    }
}

void TestCifsItem::saveLoadSaveIsByteIdentical()
{
    Project p;
    QVERIFY(test::load(p, fernJson + "," + gasketJson));
    QVERIFY(cifsItem(p, "Fern")->moveControlPoint(2, {0.1, 10.0 / 3}));
    QVERIFY(test::reloadsIdentically(p));
    QVERIFY(p.serialize().contains("\"state\": \"Sierpinski\""));
}

void TestCifsItem::iterateIsTheCoresAutomaton()
{
    Project p;
    QVERIFY(test::load(p, fernJson));
    CifsItem *fern = cifsItem(p, "Fern");
    const auto derived = fern->derivedIfs();
    const StartSet start = fern->coreStartSet(*derived);
    Collect sink;
    sink.view = derived->ifs.views.at(0);
    const int depth = 4;
    const IterationStats stats = derived->iterate(start, depth, {&sink}, {});
    const Cifs cifs = fernSierpinskiCifs(2);
    QCOMPARE(double(stats.images), pathCount(cifs, 0, depth));
    std::vector<StartSet> starts(2, start);
    Collect core;
    core.view = cifs.view(0);
    iterate(cifs, 0, starts, depth, core);
    QCOMPARE(sink.images.size(), core.images.size());
    for (size_t i = 0; i < core.images.size(); ++i)
        QVERIFY((sink.images[i] - core.images[i]).cwiseAbs().maxCoeff() < 1e-12);
    // The transitions' matrices are what an eigenvalue plot analyses (4 fern + 3 gasket arcs).
    QCOMPARE(derived->S.count(), 7);
}

void TestCifsItem::parameterEditsUndo()
{
    Project p;
    QVERIFY(test::load(p, fernJson));
    CifsItem *fern = cifsItem(p, "Fern");
    // The preset is shown, not edited; then the arc and the state.
    QCOMPARE(test::ownParameters(*fern).size(), 3);
    QVERIFY(test::ownParameters(*fern).at(0).readOnly);
    QCOMPARE(test::ownParameters(*fern).at(2).choices, (QStringList{"Fern", "Sierpinski"}));
    test::roundTrip(
        p, [&] { QVERIFY(fern->setParameter("redirected", 1)); },
        [&] { QCOMPARE(fern->parameter("redirected").toInt(), 1); },
        [&] { QCOMPARE(fern->parameter("redirected").toInt(), 2); });
    test::roundTrip(
        p, [&] { QVERIFY(fern->setParameter("state", 1)); },
        [&] {
            QCOMPARE(fern->spec().state, QString("Sierpinski"));
            QVERIFY(fern->derivedIfs());
        },
        [&] { QCOMPARE(fern->spec().state, QString("Fern")); });
}

void TestCifsItem::refusedParameterValues()
{
    Project p;
    QVERIFY(test::load(p, fernJson));
    CifsItem *fern = cifsItem(p, "Fern");
    const int steps = p.undoStack()->count();
    QString error;
    QVERIFY(!fern->setParameter("redirected", 4, 0, &error));
    QVERIFY2(error.contains("must be 0"), qPrintable(error));
    QVERIFY(!fern->setParameter("state", 2, 0, &error));
    QVERIFY2(error.contains("not a valid value"), qPrintable(error));
    QVERIFY(!fern->setParameter("depth", 2, 0, &error));
    QVERIFY2(error.contains("no parameter"), qPrintable(error));
    QCOMPARE(p.undoStack()->count(), steps);
}

void TestCifsItem::badFilesNameTheField_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    auto x = [](const QByteArray &fields) {
        return R"({"type": "cifs", "name": "x", )" + fields + "}";
    };
    QTest::newRow("preset missing") << x(R"("state": "Fern")") << R"(field "preset": missing)";
    QTest::newRow("preset unknown")
        << x(R"("preset": "fern")")
        << R"(field "preset": expected one of "fern-sierpinski", got "fern")";
    QTest::newRow("redirected range")
        << x(R"("preset": "fern-sierpinski", "redirected": 4)")
        << R"(field "redirected": expected an integer between 0 and 3)";
    QTest::newRow("redirected mistyped")
        << x(R"("preset": "fern-sierpinski", "redirected": "T1")")
        << R"(field "redirected": expected an integer)";
    QTest::newRow("state unknown")
        << x(R"("preset": "fern-sierpinski", "state": "Leaf")")
        << R"(field "state": expected one of "Fern", "Sierpinski", got "Leaf")";
    QTest::newRow("frame not finite")
        << x(R"("preset": "fern-sierpinski", "control_points": [[0, 0], [1, NaN], [0, 1]])")
        << R"(field "control_points[2][2]": NaN is not a finite number)";
}

void TestCifsItem::badFilesNameTheField()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const QString error = test::loadError(json);
    QVERIFY2(error.startsWith(R"(t.awb: item 1 ("x"): )"), qPrintable(error));
    QVERIFY2(error.contains(message), qPrintable(error));
}

AWB_TEST_GUILESS_MAIN(TestCifsItem)
#include "test_cifs_item.moc"
