// The "cifs" item (model/CifsItem.h): a general controlled IFS -- states with their own control
// points, arcs with their matrices -- its file form (the arc's four ways, the files of the one
// preset before it), its edits through the undo stack and its drawing through the core's CIFS
// iteration, of one state or of all.

#include "ItemKindTests.h"

#include "core/ifs/Cifs.h"
#include "core/schemes/ControlPointFractal.h"
#include "core/schemes/Scheme.h"
#include "model/CifsItem.h"
#include "TestMain.h"

using namespace awb;

namespace {

// The files of the one preset (before the general automaton).
const QByteArray fernJson = R"({"type": "cifs", "name": "Fern", "preset": "fern-sierpinski",
    "redirected": 2, "state": "Fern"})";
const QByteArray gasketJson = R"({"type": "cifs", "name": "Gasket",
    "preset": "fern-sierpinski", "redirected": 1, "state": "Sierpinski",
    "control_points": [[-3, 0], [3, 0], [0, 8]]})";

// A user's automaton: a triangle state whose one arc leads into a segment state (a cubic
// B-spline's pieces would not fit: the segment has 2 points, so its arcs are 2 x 2), the
// arcs given in each of the four ways.
const QByteArray ownJson = R"({"type": "cifs", "name": "Own", "state": "all",
    "states": [{"name": "Tri", "control_points": [[0, 0], [1, 0], [0, 1]]},
               {"name": "Seg", "control_points": [[0, 0], [1, 1]]}],
    "arcs": [{"name": "a", "from": "Tri", "to": "Tri",
              "affine": {"A": [[0.5, 0], [0, 0.5]], "b": [0, 0]}},
             {"name": "b", "from": "Tri", "to": "Tri",
              "columns": [[0.5, 0, 0], [0.5, 1, 0.5], [0, 0, 0.5]]},
             {"name": "c", "from": "Tri", "to": "Seg", "matrix": [[0.5, 0, 0.5], [0, 0, 1]],
              "weight": 2},
             {"name": "d", "from": "Seg", "to": "Seg", "matrix": [["1/2", "1/2"], [0, 1]]},
             {"name": "e", "from": "Seg", "to": "Seg",
              "scheme": {"kind": "bezier", "degree": 1}, "piece": 1}]})";

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
    void presetFilesLoadAsTheirAutomaton();
    void ownAutomatonReadsEveryArcForm();
    void saveLoadSaveIsByteIdentical();
    void iterateIsTheCoresAutomaton();
    void allStatesDrawTheUnion();
    void randomIterationLandsOnTheAttractor();
    void editsAreOneUndoStepEach();
    void refusedEditsNameTheProblem();
    void theFirstStateIsDrawnByDefault();
    void badFilesNameTheField_data();
    void badFilesNameTheField();
};

void TestCifsItem::presetFilesLoadAsTheirAutomaton()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, fernJson + "," + gasketJson, &error), qPrintable(error));
    CifsItem *fern = cifsItem(p, "Fern");
    QVERIFY(fern->spec() == CifsSpec::fernOfGaskets(2));
    QCOMPARE(fern->spec().drawn, QString("Fern"));
    QVERIFY(fern->controlPoints(0) == (PointList{{-3, 0}, {3, 0}, {0, 10}})); // fernFrame()
    CifsItem *gasket = cifsItem(p, "Gasket");
    QCOMPARE(gasket->spec().drawn, QString("Sierpinski"));
    QCOMPARE(gasket->controlPointSetCount(), 2);
    QCOMPARE(gasket->controlPoints(1)[2], (Point{0, 8}));
    // The matrices are those of the fern redirected at its main frond.
    QCOMPARE(gasket->spec().arcs.size(), size_t(7));
    QVERIFY(gasket->spec().arcs == CifsSpec::fernOfGaskets(1).arcs);
    for (CifsItem *c : {fern, gasket}) {
        QVERIFY2(c->derivedIfs(), qPrintable(c->derivedError()));
        QVERIFY(c->derivedIfs()->iterate);
        QVERIFY(c->derivedIfs()->ifs.maps.empty());
        QVERIFY(c->unknownFields().isEmpty());
    }
    // Saved in the general form.
    QVERIFY(!p.serialize().contains("preset"));
    QVERIFY(p.serialize().contains("\"arcs\""));
}

void TestCifsItem::ownAutomatonReadsEveryArcForm()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, ownJson, &error), qPrintable(error));
    CifsItem *own = cifsItem(p, "Own");
    const CifsSpec &s = own->spec();
    QCOMPARE(s.states.size(), size_t(2));
    QCOMPARE(s.arcs.size(), size_t(5));
    QCOMPARE(s.drawn, CifsSpec::allStates);
    // a: x |-> x/2 on the frame (0,0), (1,0), (0,1) is (lambda + e_0)/2 in barycentric form.
    Mat half(3, 3);
    half << 1, 0, 0, 0.5, 0.5, 0, 0.5, 0, 0.5;
    QVERIFY((s.arcs[0].S - half).norm() < 1e-15);
    // b: 003's column form, stored transposed: (lambda + e_1)/2.
    Mat b(3, 3);
    b << 0.5, 0.5, 0, 0, 1, 0, 0, 0.5, 0.5;
    QVERIFY(s.arcs[1].S == b);
    QCOMPARE(s.arcs[2].S.rows(), 2);
    QCOMPARE(s.arcs[2].S.cols(), 3);
    QCOMPARE(s.arcs[2].weight, 2.0);
    QCOMPARE(s.arcs[3].S(0, 0), 0.5);
    // e: the linear Bézier's first half (de Casteljau at 1/2) for the 2-point state.
    const SubdivisionMatrices m = BezierScheme(1).matrices(2);
    QVERIFY(s.arcs[4].S == m.S[0]);
    QCOMPARE(own->mapCount(), 5);
    QCOMPARE(own->branching(), 3);
    // Rectangular arcs: no square S for the spectra, said why.
    const auto d = own->derivedIfs();
    QVERIFY2(d, qPrintable(own->derivedError()));
    QCOMPARE(d->S.count(), 0);
    QVERIFY(!d->S.unavailable.isEmpty());
}

void TestCifsItem::saveLoadSaveIsByteIdentical()
{
    Project p;
    QVERIFY(test::load(p, fernJson + "," + gasketJson + "," + ownJson));
    QVERIFY(cifsItem(p, "Fern")->moveControlPoint(2, {0.1, 10.0 / 3}, 0, 1));
    QVERIFY(test::reloadsIdentically(p));
    QVERIFY(p.serialize().contains("\"state\": \"Sierpinski\""));
    QVERIFY(p.serialize().contains("\"state\": \"all\""));
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
    // The start point (0, 0) in each state's own coordinates.
    std::vector<StartSet> starts(2, StartSet::points(leastNormWeightsOfRows(
                                        fernFrame(), Mat::Zero(1, 2))));
    Collect core;
    core.view = cifs.view(0);
    iterate(cifs, 0, starts, depth, core);
    QCOMPARE(sink.images.size(), core.images.size());
    for (size_t i = 0; i < core.images.size(); ++i)
        QVERIFY((sink.images[i] - core.images[i]).cwiseAbs().maxCoeff() < 1e-12);
    // The arcs' matrices are what an eigenvalue plot analyses (4 fern + 3 gasket arcs).
    QCOMPARE(derived->S.count(), 7);
}

void TestCifsItem::allStatesDrawTheUnion()
{
    Project p;
    QVERIFY(test::load(p, fernJson));
    CifsItem *fern = cifsItem(p, "Fern");
    QVERIFY(fern->setParameter("state", CifsSpec::allStates));
    const auto d = fern->derivedIfs();
    QVERIFY2(d, qPrintable(fern->derivedError()));
    Collect sink;
    sink.view = d->ifs.views.at(0);
    const int depth = 3;
    const IterationStats stats = d->iterate(fern->coreStartSet(*d), depth, {&sink}, {});
    const Cifs cifs = fernSierpinskiCifs(2);
    QCOMPARE(double(stats.images), pathCount(cifs, 0, depth) + pathCount(cifs, 1, depth));
    QCOMPARE(d->pointCount(fern->coreStartSet(*d), depth), double(stats.images));
    // The Sierpinski state's points lie in the frame triangle.
    for (const Mat &m : sink.images)
        for (Eigen::Index r = 0; r < m.rows(); ++r)
            QVERIFY(m(r, 1) >= -1e-9 && m(r, 1) <= 10 + 1e-9);
}

void TestCifsItem::randomIterationLandsOnTheAttractor()
{
    Project p;
    QVERIFY(test::load(p, ownJson));
    CifsItem *own = cifsItem(p, "Own");
    AlgorithmSpec a = own->algorithm();
    a.mode = AlgorithmSpec::Mode::Random;
    a.samples = 20000;
    QVERIFY(own->setAlgorithm(a));
    const auto d = own->derivedIfs();
    QVERIFY2(d, qPrintable(own->derivedError()));
    Collect sink;
    sink.view = d->ifs.views.at(0);
    const IterationStats stats = d->iterate(own->coreStartSet(*d), a.depth, {&sink}, {});
    QVERIFY(stats.images >= 20000);
    // Every state's attractor lies in the convex hull of its control points here: the
    // triangle x, y >= 0, x + y <= 1 (the segment's diagonal is inside too).
    for (const Mat &m : sink.images)
        for (Eigen::Index r = 0; r < m.rows(); ++r)
            QVERIFY(m(r, 0) >= -1e-9 && m(r, 1) >= -1e-9 && m(r, 0) + m(r, 1) <= 2 + 1e-9);
    // The arcs carry the weights: the algorithm's probabilities are refused.
    a.probabilities = {0.2, 0.2, 0.2, 0.2, 0.2};
    QVERIFY(own->setAlgorithm(a));
    QVERIFY(!own->derivedIfs());
    QVERIFY2(own->derivedError().contains("weights"), qPrintable(own->derivedError()));
}

void TestCifsItem::editsAreOneUndoStepEach()
{
    Project p;
    QVERIFY(test::load(p, fernJson));
    CifsItem *fern = cifsItem(p, "Fern");
    // Add a state and an arc into it: one step each.
    CifsSpec s = fern->spec();
    s.states.push_back({s.freshStateName(), {{0, 0}, {1, 0}}});
    QCOMPARE(s.states.back().name, QString("S1"));
    test::roundTrip(
        p, [&] { QVERIFY(fern->setSpec(s)); },
        [&] { QCOMPARE(fern->controlPointSetCount(), 3); },
        [&] { QCOMPARE(fern->controlPointSetCount(), 2); });
    QVERIFY(fern->setSpec(s));
    // The new state has no arc yet: the fern, which does not reach it, is still drawn; drawn
    // itself (all states), the item says why it cannot be.
    QVERIFY2(fern->derivedIfs(), qPrintable(fern->derivedError()));
    QCOMPARE(fern->derivedIfs()->S.count(), 7);
    QVERIFY(fern->setParameter("state", CifsSpec::allStates));
    QVERIFY(!fern->derivedIfs());
    QVERIFY2(fern->derivedError().contains("'S1' has no outgoing arc"),
             qPrintable(fern->derivedError()));
    CifsSpec t = fern->spec();
    t.arcs.push_back({t.freshArcName(), 2, 2, CifsSpec::defaultArcMatrix(2, 2, 0), 1.0});
    test::roundTrip(
        p, [&] { QVERIFY(fern->setSpec(t)); },
        [&] { QVERIFY2(fern->derivedIfs(), qPrintable(fern->derivedError())); },
        [&] { QVERIFY(!fern->derivedIfs()); });
    QVERIFY(fern->setParameter("state", "Fern"));
    // The drawn state through the declared choice; a state's control point by the point set.
    test::roundTrip(
        p, [&] { QVERIFY(fern->setParameter("state", "Sierpinski")); },
        [&] { QCOMPARE(fern->spec().drawn, QString("Sierpinski")); },
        [&] { QCOMPARE(fern->spec().drawn, QString("Fern")); });
    test::roundTrip(
        p, [&] { QVERIFY(fern->moveControlPoint(0, {-2, 1}, 0, 1)); },
        [&] { QCOMPARE(fern->spec().states[1].points[0], (Point{-2, 1})); },
        [&] { QCOMPARE(fern->spec().states[1].points[0], (Point{-3, 0})); });
    // The scalar one: the drawn state (states and arcs are structured, edited as JSON).
    QCOMPARE(test::ownParameters(*fern).size(), 1);
    QCOMPARE(test::ownParameters(*fern).at(0).choices,
             (QStringList{"Fern", "Sierpinski", "S1", "All states"}));
}

void TestCifsItem::refusedEditsNameTheProblem()
{
    Project p;
    QVERIFY(test::load(p, fernJson));
    CifsItem *fern = cifsItem(p, "Fern");
    const int steps = p.undoStack()->count();
    QString error;
    CifsSpec s = fern->spec();
    s.arcs[0].S = Mat::Identity(2, 2);
    QVERIFY(!fern->setSpec(s, 0, &error));
    QVERIFY2(error.contains("must be 3 x 3"), qPrintable(error));
    s = fern->spec();
    s.arcs[0].S(0, 0) += 0.25;
    QVERIFY(!fern->setSpec(s, 0, &error));
    QVERIFY2(error.contains("sums to 1.25"), qPrintable(error));
    s = fern->spec();
    s.states[1].name = "Fern";
    QVERIFY(!fern->setSpec(s, 0, &error));
    QVERIFY2(error.contains("two states are called \"Fern\""), qPrintable(error));
    QVERIFY(!fern->setParameter("state", "Leaf", 0, &error));
    QVERIFY(!fern->properties().setJson(
        *fern, "arcs",
        QJsonArray{QJsonObject{{"from", "Fern"}, {"to", "Leaf"}, {"matrix", QJsonArray{}}}},
        &error));
    QVERIFY2(error.contains("no state \"Leaf\""), qPrintable(error));
    QCOMPARE(p.undoStack()->count(), steps);
}

void TestCifsItem::badFilesNameTheField_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    auto x = [](const QByteArray &fields) {
        return R"({"type": "cifs", "name": "x", )" + fields + "}";
    };
    const QByteArray tri = R"("states": [{"name": "T", "control_points": [[0,0],[1,0],[0,1]]}])";
    QTest::newRow("states missing") << x(R"("state": "Fern")") << R"(field "states": missing)";
    QTest::newRow("arc into the void")
        << x(tri + R"(, "arcs": [{"from": "T", "to": "T", "matrix": [[1, 0], [0, 1]]}])")
        << R"(field "arcs[1].matrix": arc "t1" has a 2 x 2 matrix)";
    QTest::newRow("old preset unknown")
        << x(R"("preset": "fern")") << R"(field "states": missing)";
    QTest::newRow("state unknown")
        << x(tri + R"(, "arcs": [], "state": "Leaf")")
        << R"(field "state": expected one of "T", "all", got "Leaf")";
    QTest::newRow("arc to nowhere")
        << x(tri + R"(, "arcs": [{"from": "T", "to": "U", "matrix": [[1]]}], "state": "T")")
        << R"(field "arcs[1].to": no state "U"; the states are "T")";
    QTest::newRow("arc two ways")
        << x(tri + R"(, "arcs": [{"from": "T", "to": "T", "matrix": [[1]], "columns": [[1]]}])")
        << R"(field "arcs[1].": give the arc's map one way)";
    QTest::newRow("arc row sum")
        << x(tri + R"(, "arcs": [{"from": "T", "to": "T",
               "matrix": [[1,0,0],[0,1,0],[0,0,2]]}], "state": "T")")
        << R"(field "arcs[1].matrix": row 3 of arc "t1" sums to 2)";
    QTest::newRow("arc misspelt")
        << x(tri + R"(, "arcs": [{"from": "T", "to": "T", "wieght": 2,
               "matrix": [[1,0,0],[0,1,0],[0,0,1]]}], "state": "T")")
        << R"(field "arcs[1].wieght": unknown field of an arc)";
    QTest::newRow("frame not finite")
        << x(R"("preset": "fern-sierpinski", "control_points": [[0, 0], [1, NaN], [0, 1]])")
        << R"(NaN)";
}

void TestCifsItem::theFirstStateIsDrawnByDefault()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, R"({"type": "cifs", "name": "x",
        "states": [{"name": "T", "control_points": [[0, 0], [1, 0], [0, 1]]}],
        "arcs": [{"from": "T", "to": "T", "matrix": [[1, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5]]},
                 {"from": "T", "to": "T", "matrix": [[0.5, 0.5, 0], [0, 1, 0], [0, 0.5, 0.5]]}]})",
                        &error),
             qPrintable(error));
    CifsItem *c = cifsItem(p, "x");
    QCOMPARE(c->spec().drawn, QString("T"));
    QVERIFY2(c->derivedIfs(), qPrintable(c->derivedError()));
    // New states without the drawn one: the first is drawn.
    QVERIFY(c->properties().setJson(
        *c, "states",
        QJsonArray{QJsonObject{{"name", "U"},
                               {"control_points", QJsonArray{QJsonArray{0, 0}, QJsonArray{1, 0},
                                                             QJsonArray{0, 1}}}}},
        &error));
    QCOMPARE(c->spec().drawn, QString("U"));
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
