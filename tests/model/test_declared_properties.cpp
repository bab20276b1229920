// Declared properties (model/PropertyTable.h) on every bundled example and every item kind:
// the file form a declaration writes reads back to the same bytes; every scalar property can be
// set to its own value without an undo step; every edit of a parameter is one undo step that
// undo and redo take back to the same bytes; describe() shows what the file holds; update()
// and setText() (attractor-cli set) go through the same declaration.

#include "TestPaths.h"
#include "ItemKindTests.h"
#include "TestMain.h"

#include "model/AttractorItem.h"
#include "model/ItemRegistry.h"
#include "model/PropertyPart.h"
#include "model/SubdivisionCurveItem.h"
#include "model/SubdivisionMeshItem.h"

#include <QDir>
#include <QUndoStack>

using namespace awb;

namespace {

QStringList exampleFiles()
{
    QDir dir(awb::test::sourceDir() + "/examples");
    QStringList files;
    for (const QString &f : dir.entryList({"*.awb"}, QDir::Files, QDir::Name))
        files << dir.filePath(f);
    return files;
}

QByteArray itemBytes(const Item &item)
{
    return ProjectIO::toBytes(ProjectIO::itemToJson(item));
}

// A different value of a parameter that its item may accept: the next choice, the other truth
// value, a nudged number.
std::optional<QVariant> otherValue(const ParameterInfo &p, const QVariant &now)
{
    using T = ParameterInfo::Type;
    switch (p.type) {
    case T::Choice:
        if (p.readOnly || p.choices.size() < 2)
            return std::nullopt;
        return (now.toInt() + 1) % int(p.choices.size());
    case T::Bool: return !now.toBool();
    case T::Integer: {
        const int v = now.toInt();
        return v + 1 <= p.maximum ? v + 1 : v - 1;
    }
    case T::Real: {
        const double v = now.toDouble();
        const double step = std::isfinite(p.maximum - p.minimum) ? (p.maximum - p.minimum) / 97
                                                                : 0.01 * (1 + std::abs(v));
        return v + step <= p.maximum ? v + step : v - step;
    }
    case T::Complex: {
        const QPointF z = now.toPointF();
        return QPointF(z.x() * 0.99 + 0.001, z.y() * 0.99);
    }
    case T::Text: return std::nullopt;
    }
    return std::nullopt;
}

} // namespace

class TestDeclaredProperties : public QObject {
    Q_OBJECT
private slots:
    void examplesReadBackToTheirBytes_data();
    void examplesReadBackToTheirBytes();
    void everyParameterEditIsOneUndoStep_data();
    void everyParameterEditIsOneUndoStep();
    void describeShowsTheFile_data();
    void describeShowsTheFile();
    void everyKindDeclaresItsFile();
    void updateGoesThroughTheParts();
    void setTextReadsWhatAUserTypes();
    void structuredValuesAreSetAsJson();
    void refusalsNameTheProblem();
    void unknownFieldsAndUnsavedStateSurvive();
};

void TestDeclaredProperties::examplesReadBackToTheirBytes_data()
{
    QTest::addColumn<QString>("file");
    for (const QString &f : exampleFiles())
        QTest::newRow(qPrintable(QFileInfo(f).fileName())) << f;
}

// Every bundled example is canonical: read through the declarations and written again, the
// same bytes.
void TestDeclaredProperties::examplesReadBackToTheirBytes()
{
    QFETCH(QString, file);
    QFile f(file);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray bytes = f.readAll();
    Project p;
    QString error;
    QVERIFY2(p.open(file, &error), qPrintable(error));
    QCOMPARE(p.serialize(), bytes);
}

void TestDeclaredProperties::everyParameterEditIsOneUndoStep_data()
{
    examplesReadBackToTheirBytes_data();
}

void TestDeclaredProperties::everyParameterEditIsOneUndoStep()
{
    QFETCH(QString, file);
    Project p;
    QString error;
    QVERIFY2(p.open(file, &error), qPrintable(error));
    int edits = 0;
    for (Item *item : p.items()) {
        const QList<ParameterInfo> params = item->parameters();
        for (const ParameterInfo &info : params) {
            // Its own value: no edit.
            const int steps = p.undoStack()->index();
            const QVariant now = item->parameter(info.key);
            QVERIFY2(now.isValid(), qPrintable(item->name() + ": " + info.key));
            QVERIFY(!info.label.isEmpty());
            if (!info.readOnly) {
                QVERIFY2(item->setParameter(info.key, now, 0, &error),
                         qPrintable(item->name() + ": " + info.key + ": " + error));
                QCOMPARE(p.undoStack()->index(), steps);
            }
            if (info.key == QLatin1String("name"))
                continue;
            const auto other = otherValue(info, now);
            if (!other)
                continue;
            const QByteArray before = itemBytes(*item);
            if (!item->setParameter(info.key, *other, 0, &error)) {
                // Refused: with a reason, and nothing changed.
                QVERIFY2(!error.isEmpty(), qPrintable(info.key));
                QCOMPARE(p.undoStack()->index(), steps);
                QCOMPARE(itemBytes(*item), before);
                continue;
            }
            ++edits;
            if (itemBytes(*item) == before)
                continue;  // a value the file does not hold (the start set's text form)
            QCOMPARE(p.undoStack()->index(), steps + 1);
            // The undo step names the field edited, not the part that holds it.
            QCOMPARE(p.undoStack()->text(steps),
                     QStringLiteral("Change %1 of %2").arg(info.label, item->name()));
            const QByteArray after = itemBytes(*item);
            p.undoStack()->undo();
            QVERIFY2(itemBytes(*item) == before, qPrintable(item->name() + ": " + info.key));
            p.undoStack()->redo();
            QVERIFY2(itemBytes(*item) == after, qPrintable(item->name() + ": " + info.key));
            p.undoStack()->undo();
        }
    }
    QVERIFY(edits > 0);
}

void TestDeclaredProperties::describeShowsTheFile_data()
{
    examplesReadBackToTheirBytes_data();
}

// What describe() (attractor-cli set --list) shows of a saved property is what the file holds,
// and setting it to that value through its file form is no edit.
void TestDeclaredProperties::describeShowsTheFile()
{
    QFETCH(QString, file);
    Project p;
    QString error;
    QVERIFY2(p.open(file, &error), qPrintable(error));
    for (Item *item : p.items()) {
        const QJsonObject json = ProjectIO::itemToJson(*item);
        const PropertyTable &table = item->properties();
        for (const PropertyDescription &d : table.describe(*item)) {
            if (d.json.isEmpty())
                continue;
            const QJsonValue inFile = property::jsonAt(json, d.json);
            if (inFile.isUndefined())
                continue;  // written only when not the default
            QVERIFY2(inFile == d.value, qPrintable(item->name() + ": " + d.info.key));
            if (d.info.readOnly)
                continue;
            const int steps = p.undoStack()->index();
            QVERIFY2(table.setJson(*item, d.info.key, d.value, &error),
                     qPrintable(item->name() + ": " + d.info.key + ": " + error));
            QCOMPARE(p.undoStack()->index(), steps);
        }
    }
}

// Every registered kind writes only declared fields ("type" and "children" are the loader's).
void TestDeclaredProperties::everyKindDeclaresItsFile()
{
    for (const QString &type : ItemRegistry::instance().types()) {
        std::unique_ptr<Item> item = ItemRegistry::instance().create(type);
        QJsonObject json;
        item->write(json);
        QStringList declared;
        for (const auto &part : item->properties().parts())
            declared << part->jsonKeys();
        for (auto it = json.begin(); it != json.end(); ++it)
            QVERIFY2(declared.contains(it.key()), qPrintable(type + ": " + it.key()));
        // And the parameters come with labels and groups.
        for (const ParameterInfo &info : item->parameters()) {
            QVERIFY2(!info.label.isEmpty(), qPrintable(type + ": " + info.key));
            QVERIFY2(!info.group.isEmpty(), qPrintable(type + ": " + info.key));
        }
    }
}

void TestDeclaredProperties::updateGoesThroughTheParts()
{
    Project p;
    QString error;
    QVERIFY(p.open(awb::test::sourceDir()
                       + "/examples/000-fig05-four-point-from-segment.awb",
                   &error));
    Item *curve = p.items().front();
    const QByteArray before = p.serialize();
    const int steps = p.undoStack()->index();
    // Its own JSON: no edit.
    QJsonObject own = ProjectIO::itemToJson(*curve);
    own.remove("children");
    QVERIFY2(curve->properties().update(*curve, own, &error), qPrintable(error));
    QCOMPARE(p.undoStack()->index(), steps);
    QCOMPARE(p.serialize(), before);
    // A scheme and a style in one step; the item stays the same object.
    QVERIFY2(curve->properties().update(
                 *curve,
                 QJsonObject{{"scheme", QJsonObject{{"kind", "four-point"}, {"omega", 0.07}}},
                             {"style", QJsonObject{{"point_size", 3}}}},
                 &error),
             qPrintable(error));
    QCOMPARE(p.undoStack()->index(), steps + 1);
    QCOMPARE(p.items().front(), curve);
    QCOMPARE(curve->parameter("scheme.omega").toDouble(), 0.07);
    QCOMPARE(curve->parameter("style.point_size").toDouble(), 3.0);
    p.undoStack()->undo();
    QCOMPARE(p.serialize(), before);
    // A merged item that does not read: refused, with the field, nothing changed.
    QVERIFY(!curve->properties().update(*curve, {{"scheme", 5}}, &error));
    QVERIFY2(error.contains("field \"scheme\": expected an object"), qPrintable(error));
    QVERIFY(!curve->properties().update(*curve, {{"type", "fractal"}}, &error));
    QVERIFY2(error.contains("type cannot change"), qPrintable(error));
    QCOMPARE(p.undoStack()->index(), steps);
    QCOMPARE(p.serialize(), before);
}

void TestDeclaredProperties::setTextReadsWhatAUserTypes()
{
    Project p;
    QString error;
    QVERIFY(p.open(awb::test::sourceDir() + "/examples/004-fig2.2-decasteljau-cubic.awb",
                   &error));
    Item *item = p.items().front();
    const PropertyTable &t = item->properties();
    // A choice by its file spelling, then a parameter that applies only now.
    QVERIFY2(t.setText(*item, "scheme.kind", "four-point", &error), qPrintable(error));
    QVERIFY2(t.setText(*item, "scheme.omega", "1/16", &error), qPrintable(error));
    QCOMPARE(item->parameter("scheme.omega").toDouble(), 0.0625);
    QVERIFY2(t.setText(*item, "scheme.kind", "Bézier (de Casteljau)", &error), qPrintable(error));
    QVERIFY2(t.setText(*item, "scheme.t", "0.5+0.3i", &error), qPrintable(error));
    QCOMPARE(item->parameter("scheme.t").toPointF(), QPointF(0.5, 0.3));
    QVERIFY2(t.setText(*item, "scheme.t", "0.4, -0.2", &error), qPrintable(error));
    QCOMPARE(item->parameter("scheme.t").toPointF(), QPointF(0.4, -0.2));
    QVERIFY2(t.setText(*item, "algorithm.mode", "random", &error), qPrintable(error));
    QVERIFY2(t.setText(*item, "algorithm.samples", "1e5", &error), qPrintable(error));
    QCOMPARE(item->parameter("algorithm.samples").toLongLong(), 100000);
    QVERIFY2(t.setText(*item, "style.point_size", "2.5", &error), qPrintable(error));
    // Refusals name the key and what was expected.
    QVERIFY(!t.setText(*item, "scheme.omega", "0.1", &error));
    QVERIFY2(error.contains("no parameter"), qPrintable(error));
    QVERIFY(!t.setText(*item, "style.point_size", "big", &error));
    QVERIFY2(error.contains("style.point_size") && error.contains("a number"), qPrintable(error));
    QVERIFY(!t.setText(*item, "scheme.kind", "spline", &error));
    QVERIFY2(error.contains("four-point"), qPrintable(error));
    QVERIFY(!t.setText(*item, "algorithm.samples", "0", &error));
    QVERIFY2(error.contains("between 1 and 2^31"), qPrintable(error));
}

void TestDeclaredProperties::structuredValuesAreSetAsJson()
{
    Project p;
    auto *mesh = static_cast<SubdivisionMeshItem *>(
        p.addItem(ItemRegistry::instance().create("subdivision-mesh")));
    const PropertyTable &t = mesh->properties();
    QString error;
    // A tetrahedron, as JSON: vertices and faces change together (update), one undo step.
    const int steps = p.undoStack()->index();
    QVERIFY2(t.update(*mesh,
                      {{"vertices", QJsonArray{QJsonArray{0, 0, 0}, QJsonArray{1, 0, 0},
                                               QJsonArray{0, 1, 0}, QJsonArray{0, 0, 1}}},
                       {"faces", QJsonArray{QJsonArray{0, 2, 1}, QJsonArray{0, 1, 3},
                                            QJsonArray{1, 2, 3}, QJsonArray{0, 3, 2}}},
                       {"scheme", QJsonObject{{"kind", "loop"}}}},
                      &error),
             qPrintable(error));
    QCOMPARE(p.undoStack()->index(), steps + 1);
    QCOMPARE(int(mesh->controlPoints().size()), 4);
    QVERIFY(mesh->scheme() == MeshScheme::Loop);
    // A vertex moved through the file form of "vertices" (setText, as attractor-cli set).
    QVERIFY2(t.setText(*mesh, "vertices", "[[0,0,0],[1,0,0],[0,1,0],[0,0,2]]", &error),
             qPrintable(error));
    QCOMPARE(mesh->controlPoints()[3].z, 2.0);
    // Faces that index no vertex: the core's words.
    QVERIFY(!t.setText(*mesh, "faces", "[[0,1,7]]", &error));
    QVERIFY2(!error.isEmpty(), qPrintable(error));
    QVERIFY(!t.setText(*mesh, "faces", "[[0,1", &error));
    QVERIFY2(error.contains("JSON"), qPrintable(error));
}

void TestDeclaredProperties::refusalsNameTheProblem()
{
    Project p;
    auto *curve = static_cast<SubdivisionCurveItem *>(
        p.addItem(ItemRegistry::instance().create("subdivision-curve")));
    QString error;
    const int steps = p.undoStack()->index();
    QVERIFY(!curve->setParameter("style.point_size", -1, 0, &error));
    QVERIFY2(error.contains("point size"), qPrintable(error));
    QVERIFY(!curve->setParameter("style.gamma", 50.0, 0, &error));
    QVERIFY2(error.contains("gamma"), qPrintable(error));
    QVERIFY(!curve->setParameter("algorithm.depth", 65, 0, &error));
    QVERIFY2(error.contains("depth 65"), qPrintable(error));
    QVERIFY(!curve->setParameter("scheme.degree", 16, 0, &error));
    QVERIFY(!error.isEmpty());
    QVERIFY(!curve->setParameter("scheme.symbol", "x", 0, &error));  // not a mask now
    QVERIFY2(error.contains("no parameter"), qPrintable(error));
    QVERIFY(!curve->setParameter("name", "", 0, &error));
    QVERIFY2(!error.isEmpty(), qPrintable(error));
    QCOMPARE(p.undoStack()->index(), steps);
    // A slider drag: one undo step.
    curve->setParameter("scheme.kind", 4);  // four-point
    const int before = p.undoStack()->index();
    const int drag = p.beginGesture();
    for (double w : {0.01, 0.02, 0.03})
        QVERIFY(curve->setParameter("scheme.omega", w, drag));
    p.endGesture(drag);
    QCOMPARE(p.undoStack()->index(), before + 1);
}

// A field not saved in the item's state stays an unknown field of the file, written back as
// it was (a preset's "normal" is not the preset's).
void TestDeclaredProperties::unknownFieldsAndUnsavedStateSurvive()
{
    const QByteArray json = R"({"name": "K", "type": "normal-vector", "preset": "koch",
        "steps": 2, "closed": false, "normal": "negative", "future": {"x": 1},
        "control_points": [[0, 0], [1, 0]]})";
    Project p;
    QVERIFY(test::load(p, json));
    const QJsonObject back = ProjectIO::itemToJson(*p.items().front());
    QCOMPARE(back.value("normal").toString(), QString("negative"));
    QCOMPARE(back.value("future").toObject().value("x").toInt(), 1);
    QVERIFY(test::reloadsIdentically(p));
}

AWB_TEST_GUILESS_MAIN(TestDeclaredProperties)
#include "test_declared_properties.moc"
