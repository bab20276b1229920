// The "bcifs-junction" item (model/BcifsJunctionItem.h): the junction curve of 003 §3-§5, its
// file form, its parameters through the undo stack, the automaton it draws and the spectrum it
// hands to eigenvalue plots (003 Fig. 16: subdominant 0.696).

#include "ItemKindTests.h"

#include "core/ifs/Bcifs.h"
#include "core/analysis/Spectrum.h"
#include "model/BcifsJunctionItem.h"
#include "TestMain.h"

using namespace awb;

namespace {

// 003 Fig. 16 (top), written out as in the issue.
const QByteArray cubicQuadraticJson = R"({"type": "bcifs-junction", "name": "Fig. 16",
    "variant": "cubic-quadratic", "a": 0.131, "b": 0.2, "c": 0.38, "d": 0.289,
    "k": 0.11, "l": 0.12, "m": 0.1, "n": 0.12,
    "left_points": [[0, 0], [1, 2], [3, 2.5], [4, 1]],
    "right_points": [[7, 0.5], [8, 2], [10, 1.5]]})";
const QByteArray refinedJson = R"({"type": "bcifs-junction", "name": "Refined",
    "variant": "refined", "j": 0.8, "r": 0.4,
    "left_points": [[0, 0], [1, 2], [3, 2.5], [4, 1]],
    "right_points": [[7, 0.5], [8, 2], [10, 1.5]],
    "handles": [[5, 1], [5.5, 0.75], [6, 0.5]]})";

BcifsJunctionItem *junction(Project &p, const QString &name)
{
    return dynamic_cast<BcifsJunctionItem *>(p.findItem(name));
}

// Collects the drawn points of every image (through the item's single view).
class Collect : public AttractorSink {
public:
    explicit Collect(const Projection &view) : m_view(view) {}
    std::vector<Mat> images;
    void consume(const Mat &vertices, StartSet::Kind, const std::uint8_t *, int) override
    {
        images.push_back(project(m_view, vertices));
    }

private:
    Projection m_view;
};

class CollectCore : public AttractorSink {
public:
    Projection view;
    std::vector<Mat> images;
    void consume(const Mat &vertices, StartSet::Kind, const std::uint8_t *, int) override
    {
        images.push_back(project(view, vertices));
    }
};

} // namespace

class TestBcifsJunctionItem : public QObject {
    Q_OBJECT
private slots:
    void issueShapesLoadExactly();
    void saveLoadSaveIsByteIdentical();
    void spectrumIsThePapers();
    void iterateDrawsTheAutomaton();
    void parameterEditsUndo();
    void refusedParameterValues();
    void badFilesNameTheField_data();
    void badFilesNameTheField();
};

void TestBcifsJunctionItem::issueShapesLoadExactly()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, cubicQuadraticJson + "," + refinedJson, &error), qPrintable(error));
    BcifsJunctionItem *cq = junction(p, "Fig. 16");
    QCOMPARE(cq->spec().variant, JunctionSpec::Variant::CubicQuadratic);
    QCOMPARE(cq->spec().free.a, 0.131);
    QCOMPARE(cq->spec().free.d, 0.289);
    QCOMPARE(cq->spec().free.n, 0.12);
    QCOMPARE(cq->controlPointSetCount(), 2);
    QCOMPARE(cq->controlPoints(0)[2], (Point{3, 2.5}));
    QCOMPARE(cq->controlPoints(1)[2], (Point{10, 1.5}));
    BcifsJunctionItem *refined = junction(p, "Refined");
    QCOMPARE(refined->spec().variant, JunctionSpec::Variant::Refined);
    QCOMPARE(refined->spec().refined.j, 0.8);
    QCOMPARE(refined->spec().refined.r, 0.4);
    QCOMPARE(refined->controlPointSetCount(), 3);
    QCOMPARE(refined->controlPoints(2)[1], (Point{5.5, 0.75}));
    for (BcifsJunctionItem *j : {cq, refined}) {
        QVERIFY2(j->derivedIfs(), qPrintable(j->derivedError()));
        QVERIFY(j->derivedIfs()->iterate);
    }
}

void TestBcifsJunctionItem::saveLoadSaveIsByteIdentical()
{
    Project p;
    QVERIFY(test::load(p, cubicQuadraticJson + "," + refinedJson));
    QVERIFY(junction(p, "Fig. 16")->setParameter("c", 0.38 + 1e-16));
    QVERIFY(junction(p, "Refined")->moveControlPoint(0, {5.0 / 3, 1}, 0, 2));
    QVERIFY(test::reloadsIdentically(p));
    const QByteArray text = p.serialize();
    QVERIFY(text.contains("\"handles\""));
    QVERIFY(text.contains("\"variant\": \"cubic-quadratic\""));
}

void TestBcifsJunctionItem::spectrumIsThePapers()
{
    Project p;
    QVERIFY(test::load(p, cubicQuadraticJson + "," + refinedJson));
    const auto derived = junction(p, "Fig. 16")->derivedIfs();
    QVERIFY(derived);
    // S holds T^i (as S = T^T, row convention): its subdominant eigenvalue is 003's 0.696.
    QCOMPARE(derived->S.count(), 1);
    QVERIFY(derived->S.real[0]
            == cubicQuadraticMatrices(JunctionParameters()).Ti.transpose());
    const Subdominant sub = subdominant(spectrum(derived->S.real[0]));
    QVERIFY(sub.kind == SubdominantKind::RealPositive);
    QVERIFY2(std::abs(sub.values[0].real() - 0.696) < 5e-4,
             qPrintable(QString::number(sub.values[0].real())));
    QVERIFY2(derived->note.contains("G1"), qPrintable(derived->note));
    QVERIFY2(derived->note.contains("p = 0.55"), qPrintable(derived->note));
    // Refined: T^il and T^ir, whose tangent eigenvalues are j and r (003 §5).
    const auto refined = junction(p, "Refined")->derivedIfs();
    QCOMPARE(refined->S.count(), 2);
    QVERIFY(std::abs(subdominant(spectrum(refined->S.real[0])).values[0].real() - 0.8) < 1e-9);
    QVERIFY(std::abs(subdominant(spectrum(refined->S.real[1])).values[0].real() - 0.4) < 1e-9);
    QVERIFY(!refined->note.isEmpty());
}

void TestBcifsJunctionItem::iterateDrawsTheAutomaton()
{
    Project p;
    QVERIFY(test::load(p, cubicQuadraticJson));
    BcifsJunctionItem *item = junction(p, "Fig. 16");
    const auto derived = item->derivedIfs();
    QCOMPARE(derived->ifs.views.size(), size_t(1));
    const StartSet start = item->coreStartSet(*derived);
    Collect sink(derived->ifs.views[0]);
    const int depth = 5;
    const IterationStats stats = derived->iterate(start, depth, {&sink}, {});
    // The same as the core's automaton, state after state, each drawn by its own view.
    const Cifs cifs = toCifs(cubicQuadraticJunction(
        JunctionParameters(), toMatrix(item->controlPoints(0)), toMatrix(item->controlPoints(1))));
    std::vector<StartSet> starts;
    int offset = 0;
    for (const CifsState &s : cifs.states) {
        starts.push_back({start.kind, start.vertices.middleCols(offset, s.dim())});
        offset += s.dim();
    }
    QCOMPARE(offset, int(start.vertices.cols()));
    CollectCore core;
    double paths = 0;
    for (int s = 0; s < int(cifs.states.size()); ++s) {
        core.view = cifs.view(s);
        iterate(cifs, s, starts, depth, core);
        paths += pathCount(cifs, s, depth);
    }
    QCOMPARE(double(stats.images), paths);
    QCOMPARE(sink.images.size(), core.images.size());
    for (size_t i = 0; i < core.images.size(); ++i)
        QVERIFY((sink.images[i] - core.images[i]).cwiseAbs().maxCoeff() < 1e-12);
    // Deep enough, the left state's pieces lie on the cubic B-spline: its ends are the
    // B-spline end points (P_0 + 4 P_1 + P_2) / 6 and (P_1 + 4 P_2 + P_3) / 6 nearby.
    const Mat Pl = toMatrix(item->controlPoints(0));
    const RowVec end = (Pl.row(1) + 4 * Pl.row(2) + Pl.row(3)) / 6;
    double nearest = 1e9;
    for (const Mat &m : sink.images)
        for (Eigen::Index r = 0; r < m.rows(); ++r)
            nearest = std::min(nearest, (m.row(r) - end).norm());
    QVERIFY2(nearest < 0.2, qPrintable(QString::number(nearest)));
}

void TestBcifsJunctionItem::parameterEditsUndo()
{
    Project p;
    QVERIFY(test::load(p, cubicQuadraticJson + "," + refinedJson));
    BcifsJunctionItem *cq = junction(p, "Fig. 16");
    QStringList keys;
    for (const ParameterInfo &info : test::ownParameters(*cq))
        keys << info.key;
    QCOMPARE(keys, (QStringList{"variant", "a", "b", "c", "d", "k", "l", "m", "n"}));
    for (const QString &key : keys.mid(1)) {
        const double before = cq->parameter(key).toDouble();
        test::roundTrip(
            p, [&] { QVERIFY(cq->setParameter(key, before + 0.01)); },
            [&] { QCOMPARE(cq->parameter(key).toDouble(), before + 0.01); },
            [&] { QCOMPARE(cq->parameter(key).toDouble(), before); });
    }
    test::roundTrip(
        p, [&] { QVERIFY(cq->setParameter("variant", 1)); },
        [&] { QCOMPARE(cq->controlPointSetCount(), 3); },
        [&] { QCOMPARE(cq->controlPointSetCount(), 2); });
    BcifsJunctionItem *refined = junction(p, "Refined");
    QCOMPARE(test::ownParameters(*refined).size(), 3);
    QVERIFY(test::ownParameters(*refined).at(1).hasSlider());
    for (const QString key : {"j", "r"}) {
        const double before = refined->parameter(key).toDouble();
        test::roundTrip(
            p,
            [&] {
                const int drag = p.beginGesture();
                for (double dv : {0.01, 0.02, 0.05})
                    QVERIFY(refined->setParameter(key, before + dv, drag));
            },
            [&] { QCOMPARE(refined->parameter(key).toDouble(), before + 0.05); },
            [&] { QCOMPARE(refined->parameter(key).toDouble(), before); });
    }
}

void TestBcifsJunctionItem::refusedParameterValues()
{
    Project p;
    QVERIFY(test::load(p, cubicQuadraticJson + "," + refinedJson));
    BcifsJunctionItem *refined = junction(p, "Refined");
    const int steps = p.undoStack()->count();
    QString error;
    QVERIFY(!refined->setParameter("j", 0.3, 0, &error));
    QVERIFY2(error.contains("j = 0.3 is outside"), qPrintable(error));
    QVERIFY(!refined->setParameter("r", 1.2, 0, &error));
    QVERIFY2(error.contains("r = 1.2 is outside"), qPrintable(error));
    QVERIFY(!junction(p, "Fig. 16")->setParameter("a", std::nan(""), 0, &error));
    QVERIFY2(error.contains("finite"), qPrintable(error));
    QVERIFY(!refined->setParameter("q", 0.1, 0, &error));
    QVERIFY2(error.contains("no parameter"), qPrintable(error));
    QCOMPARE(p.undoStack()->count(), steps);
}

void TestBcifsJunctionItem::badFilesNameTheField_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    auto x = [](const QByteArray &fields) {
        return R"({"type": "bcifs-junction", "name": "x", )" + fields + "}";
    };
    const QByteArray pts = R"("left_points": [[0, 0], [1, 2], [3, 2.5], [4, 1]],
                              "right_points": [[7, 0.5], [8, 2], [10, 1.5]])";
    QTest::newRow("variant missing") << x(pts) << R"(field "variant": missing)";
    QTest::newRow("variant unknown")
        << x(R"("variant": "quartic", )" + pts)
        << R"(field "variant": expected one of "cubic-quadratic", "refined", got "quartic")";
    QTest::newRow("a mistyped") << x(R"("variant": "cubic-quadratic", "a": "x", )" + pts)
                                << R"(field "a": expected a number)";
    QTest::newRow("n not finite") << x(R"("variant": "cubic-quadratic", "n": 1e500, )" + pts)
                                  << R"(field "n": 1e500 is not a finite number)";
    QTest::newRow("j out of range") << x(R"("variant": "refined", "j": 0.2, )" + pts
                                         + R"(, "handles": [[5, 1], [5.5, 0.75], [6, 0.5]])")
                                    << R"(field "j": j = 0.2 is outside)";
    QTest::newRow("r out of range") << x(R"("variant": "refined", "r": 1, )" + pts
                                         + R"(, "handles": [[5, 1], [5.5, 0.75], [6, 0.5]])")
                                    << R"(field "r": r = 1 is outside)";
    QTest::newRow("left missing")
        << x(R"("variant": "cubic-quadratic", "right_points": [[7, 0.5]])")
        << R"(field "left_points": missing)";
    QTest::newRow("right mistyped")
        << x(R"("variant": "cubic-quadratic", "left_points": [], "right_points": 3)")
        << R"(field "right_points": expected an array of points)";
    QTest::newRow("handles missing") << x(R"("variant": "refined", )" + pts)
                                     << R"(field "handles": missing)";
}

void TestBcifsJunctionItem::badFilesNameTheField()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const QString error = test::loadError(json);
    QVERIFY2(error.startsWith(R"(t.awb: item 1 ("x"): )"), qPrintable(error));
    QVERIFY2(error.contains(message), qPrintable(error));
}

AWB_TEST_GUILESS_MAIN(TestBcifsJunctionItem)
#include "test_bcifs_junction_item.moc"
