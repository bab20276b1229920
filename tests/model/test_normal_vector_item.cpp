// The "normal-vector" item (model/NormalVectorItem.h): the normal-vector scheme of 001, its file
// form, its parameters through the undo stack, its polygon and its equivalent IFS (when the
// scheme has one) against the core.

#include "ItemKindTests.h"

#include "core/schemes/NormalVectorScheme.h"
#include "model/NormalVectorItem.h"
#include "TestMain.h"

using namespace awb;

namespace {

const QByteArray kochJson = R"({"type": "normal-vector", "name": "Koch", "preset": "koch",
    "steps": 5, "closed": false, "control_points": [[0, 0], [1, 0]]})";
const QByteArray snowflakeJson = R"({"type": "normal-vector", "name": "Snowflake",
    "preset": "snowflake", "steps": 3, "closed": true,
    "control_points": [[0, 0], [1, 0], [0.5, 0.8660254037844386]]})";
const QByteArray dragonJson = R"({"type": "normal-vector", "name": "Dragon", "preset": "dragon",
    "steps": 6, "control_points": [[0, 0], [1, 0]]})";
const QByteArray customJson = R"({"type": "normal-vector", "name": "Own", "preset": "custom",
    "alpha": [0, 0.5], "beta": [0, 0.5], "normal": "negative", "signs": ["constant"],
    "closed": false, "steps": 7, "control_points": [[0, 0], [2, 0], [2, 1]]})";

NormalVectorItem *nv(Project &p, const QString &name)
{
    return dynamic_cast<NormalVectorItem *>(p.findItem(name));
}

} // namespace

class TestNormalVectorItem : public QObject {
    Q_OBJECT
private slots:
    void issueShapesLoadExactly();
    void everyPresetLoadsAndComputes();
    void saveLoadSaveIsByteIdentical();
    void derivedMatchesCore();
    void parameterEditsUndo();
    void refusedParameterValues();
    void badFilesNameTheField_data();
    void badFilesNameTheField();
};

void TestNormalVectorItem::issueShapesLoadExactly()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, kochJson + "," + snowflakeJson + "," + dragonJson + "," + customJson,
                        &error),
             qPrintable(error));
    QCOMPARE(nv(p, "Koch")->spec().preset, QString("koch"));
    QCOMPARE(nv(p, "Koch")->spec().steps, 5);
    QVERIFY(!nv(p, "Koch")->spec().closed);
    QVERIFY(nv(p, "Snowflake")->spec().closed);
    QCOMPARE(nv(p, "Snowflake")->controlPoints()[2], (Point{0.5, 0.8660254037844386}));
    QVERIFY(!nv(p, "Dragon")->spec().closed); // the default
    const NormalVectorSpec &own = nv(p, "Own")->spec();
    QVERIFY(own.isCustom());
    QVERIFY(own.alpha == (std::vector<double>{0, 0.5}));
    QVERIFY(own.beta == (std::vector<double>{0, 0.5}));
    QCOMPARE(own.normal, NormalVectorSpec::Normal::Negative);
    QCOMPARE(own.signs.size(), size_t(1));
    QCOMPARE(own.steps, 7);
    QCOMPARE(nv(p, "Own")->controlPoints().size(), size_t(3));
    QCOMPARE(nv(p, "Koch")->mapCount(), 4);
}

void TestNormalVectorItem::everyPresetLoadsAndComputes()
{
    for (const NormalVectorPreset &preset : normalVectorPresets()) {
        const QByteArray json = R"({"type": "normal-vector", "name": "x", "preset": ")"
                                + QByteArray::fromStdString(preset.key) + R"(", "steps": 2,
            "closed": )" + (preset.polygon.closed ? "true" : "false")
                                + R"(, "control_points": [[0, 0], [1, 0], [0.5, 0.9]]})";
        Project p;
        QString error;
        QVERIFY2(test::load(p, json, &error), qPrintable(error));
        NormalVectorItem *item = nv(p, "x");
        QCOMPARE(item->spec().preset, QString::fromStdString(preset.key));
        // Open polygons need an interpolatory scheme; the approximating one is closed-only.
        if (!preset.polygon.closed && !preset.scheme.interpolatory())
            continue;
        const auto derived = item->derivedIfs();
        QVERIFY2(derived, qPrintable(QString::fromStdString(preset.key) + ": "
                                     + item->derivedError()));
        QVERIFY(derived->polygon);
        QCOMPARE(derived->ifs.maps.empty(), bool(whyNoEquivalentIfs(preset.scheme)));
        QVERIFY(test::reloadsIdentically(p));
    }
}

void TestNormalVectorItem::saveLoadSaveIsByteIdentical()
{
    Project p;
    QVERIFY(test::load(p, kochJson + "," + snowflakeJson + "," + dragonJson + "," + customJson));
    QVERIFY(nv(p, "Own")->setParameter("alpha.1", 1.0 / 3));
    QVERIFY(test::reloadsIdentically(p));
    QVERIFY(p.serialize().contains("\"signs\""));
}

void TestNormalVectorItem::derivedMatchesCore()
{
    Project p;
    QVERIFY(test::load(p, kochJson + "," + dragonJson + "," + customJson));
    // Koch: the polygon at 5 steps is the core's, and the IFS its equivalentIfs.
    const auto koch = nv(p, "Koch")->derivedIfs();
    QVERIFY2(koch, qPrintable(nv(p, "Koch")->derivedError()));
    const NormalVectorScheme scheme = normalVectorPreset(NormalVectorPresetId::Koch).scheme;
    const ControlPolygon poly{(Mat(2, 2) << 0, 0, 1, 0).finished(), false};
    QVERIFY(*koch->polygon == scheme.subdivide(poly, 5).points);
    QCOMPARE(koch->polygon->rows(), Eigen::Index(4 * 4 * 4 * 4 * 4 + 1));
    QVERIFY(!koch->polygonClosed);
    const Ifs ifs = equivalentIfs(scheme, poly);
    QCOMPARE(koch->ifs.maps.size(), ifs.maps.size());
    for (size_t i = 0; i < ifs.maps.size(); ++i)
        QVERIFY(koch->ifs.maps[i].A == ifs.maps[i].A && koch->ifs.maps[i].b == ifs.maps[i].b);
    QVERIFY(!koch->iterate);
    // Dragon: edge-alternating signs; its IFS takes the second new edge reversed.
    const auto dragon = nv(p, "Dragon")->derivedIfs();
    QVERIFY2(dragon, qPrintable(nv(p, "Dragon")->derivedError()));
    QCOMPARE(dragon->ifs.maps.size(), size_t(2));
    QVERIFY(!dragon->iterate);
    QCOMPARE(dragon->polygon->rows(), Eigen::Index(64 + 1));
    QVERIFY2(!dragon->note.contains("No equivalent IFS"), qPrintable(dragon->note));
    // Custom (Lévy rules, clockwise normal) on a two-edge polygon: one view per edge.
    const auto own = nv(p, "Own")->derivedIfs();
    QVERIFY2(own, qPrintable(nv(p, "Own")->derivedError()));
    const NormalVectorScheme levy({0, 0.5}, {0, 0.5}, NormalDirection::Negative,
                                  {BetaSign::Constant});
    const ControlPolygon two{toMatrix(nv(p, "Own")->controlPoints()), false};
    QVERIFY(*own->polygon == levy.subdivide(two, 7).points);
    QCOMPARE(own->ifs.views.size(), size_t(2));
    // Closing a 2-point polygon is refused by the core: reported, not thrown.
    QVERIFY(nv(p, "Koch")->setParameter("closed", true));
    QVERIFY(!nv(p, "Koch")->derivedIfs());
    QVERIFY(!nv(p, "Koch")->derivedError().isEmpty());
}

void TestNormalVectorItem::parameterEditsUndo()
{
    Project p;
    QVERIFY(test::load(p, kochJson + "," + customJson));
    NormalVectorItem *koch = nv(p, "Koch");
    QStringList keys;
    for (const ParameterInfo &info : test::ownParameters(*koch))
        keys << info.key;
    QCOMPARE(keys, (QStringList{"preset", "steps", "normal", "closed", "alpha.0", "alpha.1",
                                "alpha.2", "alpha.3", "beta.0", "beta.1", "beta.2",
                                "beta.3"}));
    QCOMPARE(koch->parameter("steps").toInt(), 5);
    QCOMPARE(koch->parameter("alpha.2").toDouble(), 0.5);
    test::roundTrip(
        p, [&] { QVERIFY(koch->setParameter("steps", 3)); },
        [&] { QCOMPARE(koch->derivedIfs()->polygon->rows(), Eigen::Index(65)); },
        [&] { QCOMPARE(koch->spec().steps, 5); });
    test::roundTrip(
        p, [&] { QVERIFY(koch->setParameter("closed", true)); },
        [&] { QVERIFY(koch->spec().closed); }, [&] { QVERIFY(!koch->spec().closed); });
    test::roundTrip(
        p, [&] { QVERIFY(koch->setParameter("preset", 0)); },
        [&] { QCOMPARE(koch->spec().preset, QString("levy")); },
        [&] { QCOMPARE(koch->spec().preset, QString("koch")); });
    p.undoStack()->undo(); // back to Koch
    // Editing a rule of a preset: a custom scheme starting from the preset's rules.
    test::roundTrip(
        p,
        [&] {
            const int drag = p.beginGesture();
            for (double b : {0.25, 0.3, 0.2})
                QVERIFY(koch->setParameter("beta.2", b, drag));
        },
        [&] {
            QVERIFY(koch->spec().isCustom());
            QCOMPARE(koch->spec().beta[2], 0.2);
            QCOMPARE(koch->spec().alpha.size(), size_t(4));
        },
        [&] { QCOMPARE(koch->spec().preset, QString("koch")); });
    NormalVectorItem *own = nv(p, "Own");
    test::roundTrip(
        p, [&] { QVERIFY(own->setParameter("normal", 0)); },
        [&] { QCOMPARE(own->spec().normal, NormalVectorSpec::Normal::Positive); },
        [&] { QCOMPARE(own->spec().normal, NormalVectorSpec::Normal::Negative); });
    test::roundTrip(
        p, [&] { QVERIFY(own->setParameter("alpha.1", 0.4)); },
        [&] { QCOMPARE(own->spec().alpha[1], 0.4); },
        [&] { QCOMPARE(own->spec().alpha[1], 0.5); });
}

void TestNormalVectorItem::refusedParameterValues()
{
    Project p;
    QVERIFY(test::load(p, kochJson));
    NormalVectorItem *koch = nv(p, "Koch");
    const int steps = p.undoStack()->count();
    QString error;
    QVERIFY(!koch->setParameter("steps", 31, 0, &error));
    QVERIFY2(error.contains("at most 30"), qPrintable(error));
    QVERIFY(!koch->setParameter("alpha.1", std::nan(""), 0, &error));
    QVERIFY2(error.contains("not a finite number"), qPrintable(error));
    QVERIFY(!koch->setParameter("closed", QString("yes"), 0, &error));
    QVERIFY2(error.contains("not a valid value"), qPrintable(error));
    QVERIFY(!koch->setParameter("alpha.4", 0.5, 0, &error));
    QVERIFY2(error.contains("no parameter"), qPrintable(error));
    QCOMPARE(p.undoStack()->count(), steps);
}

void TestNormalVectorItem::badFilesNameTheField_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    auto x = [](const QByteArray &fields) {
        return R"({"type": "normal-vector", "name": "x", )" + fields + "}";
    };
    const QByteArray pts = R"("control_points": [[0, 0], [1, 0]])";
    QTest::newRow("preset missing") << x(pts) << R"(field "preset": missing)";
    QTest::newRow("preset unknown") << x(R"("preset": "fern", )" + pts)
                                    << R"(field "preset": expected one of "levy")";
    QTest::newRow("steps fraction") << x(R"("preset": "koch", "steps": 2.5, )" + pts)
                                    << R"(field "steps": expected an integer)";
    QTest::newRow("steps range") << x(R"("preset": "koch", "steps": 40, )" + pts)
                                 << R"(field "steps": expected an integer between 0 and 30)";
    QTest::newRow("closed mistyped") << x(R"("preset": "koch", "closed": 1, )" + pts)
                                     << R"(field "closed": expected true or false)";
    QTest::newRow("points missing") << x(R"("preset": "koch")")
                                    << R"(field "control_points": missing)";
    QTest::newRow("alpha missing") << x(R"("preset": "custom", "beta": [0, 1], )" + pts)
                                   << R"(field "alpha": missing)";
    QTest::newRow("alpha not finite")
        << x(R"("preset": "custom", "alpha": [0, 1e400], "beta": [0, 1], )" + pts)
        << R"(field "alpha[2]": 1e400 is not a finite number)";
    QTest::newRow("alpha too short")
        << x(R"("preset": "custom", "alpha": [0], "beta": [0], )" + pts)
        << R"(field "alpha": need at least 2 rules)";
    QTest::newRow("beta count")
        << x(R"("preset": "custom", "alpha": [0, 0.5], "beta": [0], )" + pts)
        << R"(field "beta": 1 values of beta for 2 of alpha)";
    QTest::newRow("normal unknown")
        << x(R"("preset": "custom", "alpha": [0, 0.5], "beta": [0, 0.5], "normal": "up", )"
             + pts)
        << R"(field "normal": expected one of "positive", "negative", got "up")";
    QTest::newRow("sign unknown")
        << x(R"("preset": "custom", "alpha": [0, 0.5], "beta": [0, 0.5], "signs": ["odd"], )"
             + pts)
        << R"(field "signs[1]": expected one of "constant")";
    QTest::newRow("sign count")
        << x(R"("preset": "custom", "alpha": [0, 0.5, 1], "beta": [0, 0.5, 0],
                "signs": ["constant", "constant"], )" + pts)
        << R"(field "signs": 2 signs for 3 rules)";
}

void TestNormalVectorItem::badFilesNameTheField()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const QString error = test::loadError(json);
    QVERIFY2(error.startsWith(R"(t.awb: item 1 ("x"): )"), qPrintable(error));
    QVERIFY2(error.contains(message), qPrintable(error));
}

AWB_TEST_GUILESS_MAIN(TestNormalVectorItem)
#include "test_normal_vector_item.moc"
