// The "subdivision-surface" item (model/SubdivisionSurfaceItem.h): subdivision surface patches
// as attractors (000 §3), their file form, the messages for bad nets, undo of every edit, and
// the derived IFS against the core.

#include "TestPaths.h"
#include "ItemKindTests.h"

#include "core/analysis/Geometry.h"
#include "core/ifs/SurfaceIfs.h"
#include "model/SubdivisionSurfaceItem.h"
#include "TestMain.h"

#include <QJsonArray>
#include <QJsonDocument>

using namespace awb;

namespace {

// The item's JSON as the default item of the scheme writes it, with edits applied by `edit`.
QByteArray surfaceJson(SurfaceSchemeSpec::Kind kind, const QString &layout,
                       const std::function<void(QJsonObject &)> &edit = {})
{
    SubdivisionSurfaceItem item;
    item.setScheme({kind, layout});
    item.setName("S");
    QJsonObject json = ProjectIO::itemToJson(item);
    if (edit)
        edit(json);
    return QJsonDocument(json).toJson(QJsonDocument::Compact);
}

SubdivisionSurfaceItem *surface(Project &p, const QString &name = "S")
{
    return dynamic_cast<SubdivisionSurfaceItem *>(p.findItem(name));
}

const std::vector<std::tuple<SurfaceSchemeSpec::Kind, QString, int, int>> kSchemes = {
    {SurfaceSchemeSpec::Kind::Bicubic, "square", 16, 4},
    {SurfaceSchemeSpec::Kind::Loop, "triangle", 12, 4},
    {SurfaceSchemeSpec::Kind::Loop, "hexagon", 19, 6},
    {SurfaceSchemeSpec::Kind::Sqrt3, "triangle", 27, 9},
    {SurfaceSchemeSpec::Kind::Sqrt3, "hexagon", 37, 18},
};

} // namespace

class TestSurfaceItem : public QObject {
    Q_OBJECT
private slots:
    void everySchemeLoadsAndDerives();
    void fileFormat();
    void saveLoadSaveIsByteIdentical();
    void badNetsNameTheField_data();
    void badNetsNameTheField();
    void editsUndo();
    void mapsOnAndOff();
    void netCountIsFixed();
    void refinedMesh();
    void examplesLieOnTheirLimitSurface_data();
    void examplesLieOnTheirLimitSurface();
};

void TestSurfaceItem::everySchemeLoadsAndDerives()
{
    for (const auto &[kind, layout, points, maps] : kSchemes) {
        Project p;
        QString error;
        QVERIFY2(test::load(p, surfaceJson(kind, layout), &error), qPrintable(error));
        SubdivisionSurfaceItem *s = surface(p);
        QCOMPARE(int(s->controlPoints().size()), points);
        QCOMPARE(s->mapCount(), maps);
        const auto d = s->derivedIfs();
        QVERIFY2(d, qPrintable(s->derivedError()));
        QCOMPARE(d->ifs.size(), maps);
        QCOMPARE(d->ifs.dim(), points - 1);  // lifted: the paraboloid net is not flat
        QCOMPARE(int(d->ifs.views.front().V.cols()), 3);
        QCOMPARE(int(d->S.real.size()), maps);
        QCOMPARE(int(d->A.real.size()), maps);
        QVERIFY(d->surface);
        // The start set is a triangle in R^3, mapped into the lifted space.
        const StartSet start = s->coreStartSet(*d);
        QCOMPARE(int(start.vertices.cols()), points - 1);
        QVERIFY(start.kind == StartSet::Kind::Polygon);
    }
}

void TestSurfaceItem::fileFormat()
{
    const QByteArray text = R"({"type": "subdivision-surface", "name": "S",
        "scheme": {"kind": "bicubic", "layout": "square"},
        "control_points": [[0,0,0],[1,0,0],[2,0,0],[3,0,0],[0,1,0],[1,1,1],[2,1,1],[3,1,0],
                           [0,2,0],[1,2,1],[2,2,1],[3,2,0],[0,3,0],[1,3,0],[2,3,0],[3,3,0.5]],
        "lattice": [[-1,-1],[0,-1],[1,-1],[2,-1],[-1,0],[0,0],[1,0],[2,0],
                    [-1,1],[0,1],[1,1],[2,1],[-1,2],[0,2],[1,2],[2,2]],
        "maps_used": [0, 3],
        "start_set": {"kind": "point", "points": [[1, 1, 1]]},
        "algorithm": {"mode": "deterministic", "depth": 5}})";
    Project p;
    QString error;
    QVERIFY2(test::load(p, text, &error), qPrintable(error));
    SubdivisionSurfaceItem *s = surface(p);
    QCOMPARE(s->scheme().kind, SurfaceSchemeSpec::Kind::Bicubic);
    QCOMPARE(s->controlPoints()[5], (Point{1, 1, 1}));
    QCOMPARE(s->lattice()[5], (LatticePoint{0, 0}));
    QCOMPARE(s->mapsUsed(), (std::vector<int>{0, 3}));
    QCOMPARE(s->mapCount(), 2);
    QCOMPARE(s->startSet().points.front(), (Point{1, 1, 1}));
    QCOMPARE(s->meshRounds(), 3);
    const auto d = s->derivedIfs();
    QVERIFY2(d, qPrintable(s->derivedError()));
    QCOMPARE(d->ifs.size(), 2);
    QCOMPARE(d->mapIndex, (std::vector<int>{0, 3}));
    QCOMPARE(d->analysisIndex(1), 3);
    // Written back: 3D points, the lattice, the subset.
    const QByteArray out = p.serialize();
    QVERIFY(out.contains("\"maps_used\""));
    QVERIFY(out.contains("\"lattice\""));
    QVERIFY(test::reloadsIdentically(p));
}

void TestSurfaceItem::saveLoadSaveIsByteIdentical()
{
    QByteArray all;
    for (const auto &[kind, layout, points, maps] : kSchemes) {
        // Named copies: clang 14 cannot capture a structured binding.
        const auto k = kind;
        const auto l = layout;
        all += (all.isEmpty() ? "" : ",")
               + surfaceJson(kind, layout, [&](QJsonObject &o) {
                     o["name"] = QString("%1 %2").arg(int(k)).arg(l);
                 });
    }
    Project p;
    QString error;
    QVERIFY2(test::load(p, all, &error), qPrintable(error));
    QCOMPARE(p.items().size(), qsizetype(kSchemes.size()));
    QVERIFY(test::reloadsIdentically(p));
}

void TestSurfaceItem::badNetsNameTheField_data()
{
    using K = SurfaceSchemeSpec::Kind;
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("words");
    QTest::newRow("missing lattice point")
        << surfaceJson(K::Loop, "hexagon", [](QJsonObject &o) {
               QJsonArray l = o["lattice"].toArray(), c = o["control_points"].toArray();
               l.removeLast();
               c.removeLast();
               o["lattice"] = l;
               o["control_points"] = c;
           })
        << "lattice" << "needs 19 control points";
    QTest::newRow("duplicated lattice point")
        << surfaceJson(K::Loop, "hexagon", [](QJsonObject &o) {
               QJsonArray l = o["lattice"].toArray();
               l[4] = l[3];
               o["lattice"] = l;
           })
        << "lattice" << "given twice";
    QTest::newRow("net of another layout")
        << surfaceJson(K::Loop, "hexagon", [](QJsonObject &o) {
               o["scheme"] = QJsonObject{{"kind", "loop"}, {"layout", "triangle"}};
           })
        << "lattice" << "needs 12 control points";
    QTest::newRow("point off the net")
        << surfaceJson(K::Bicubic, "square", [](QJsonObject &o) {
               QJsonArray l = o["lattice"].toArray();
               l[15] = QJsonArray{9, 9};
               o["lattice"] = l;
           })
        << "lattice" << "(9, 9)";
    QTest::newRow("fewer lattice coordinates")
        << surfaceJson(K::Bicubic, "square", [](QJsonObject &o) {
               QJsonArray l = o["lattice"].toArray();
               l.removeLast();
               o["lattice"] = l;
           })
        << "lattice" << "15 lattice coordinates for 16 control points";
    QTest::newRow("fractional lattice coordinate")
        << surfaceJson(K::Bicubic, "square", [](QJsonObject &o) {
               QJsonArray l = o["lattice"].toArray();
               l[0] = QJsonArray{0.5, 0};
               o["lattice"] = l;
           })
        << "lattice[1]" << "whole numbers";
    QTest::newRow("plane point")
        << surfaceJson(K::Bicubic, "square", [](QJsonObject &o) {
               QJsonArray c = o["control_points"].toArray();
               c[2] = QJsonArray{1, 2};
               o["control_points"] = c;
           })
        << "control_points[3]" << "[x, y, z]";
    QTest::newRow("maps_used out of range")
        << surfaceJson(K::Loop, "hexagon",
                       [](QJsonObject &o) { o["maps_used"] = QJsonArray{0, 6}; })
        << "maps_used" << "map 6 does not exist";
    QTest::newRow("maps_used empty")
        << surfaceJson(K::Loop, "hexagon", [](QJsonObject &o) { o["maps_used"] = QJsonArray{}; })
        << "maps_used" << "at least one map";
    QTest::newRow("unknown layout")
        << surfaceJson(K::Bicubic, "square", [](QJsonObject &o) {
               o["scheme"] = QJsonObject{{"kind", "bicubic"}, {"layout", "hexagon"}};
           })
        << "scheme.layout" << "expected one of \"square\"";
    QTest::newRow("unknown scheme")
        << surfaceJson(K::Bicubic, "square", [](QJsonObject &o) {
               o["scheme"] = QJsonObject{{"kind", "butterfly"}, {"layout", "square"}};
           })
        << "scheme.kind" << "\"bicubic\", \"loop\", \"sqrt3\"";
    QByteArray nan = surfaceJson(K::Bicubic, "square");
    const int at = nan.indexOf("\"control_points\":[[") + 19;
    nan.insert(at, "NaN,");
    nan.remove(at + 4, nan.indexOf(',', at + 4) - (at + 4) + 1);
    QTest::newRow("NaN coordinate") << nan << "control_points[1][1]" << "finite";
}

void TestSurfaceItem::badNetsNameTheField()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, field);
    QFETCH(QString, words);
    const QString error = test::loadError(json);
    QVERIFY2(error.contains(QString("field \"%1\"").arg(field)), qPrintable(error));
    QVERIFY2(error.contains(words), qPrintable(error));
}

void TestSurfaceItem::editsUndo()
{
    Project p;
    QVERIFY(test::load(p, surfaceJson(SurfaceSchemeSpec::Kind::Bicubic, "square")));
    SubdivisionSurfaceItem *s = surface(p);
    const QByteArray original = p.serialize();
    // A 3D move of a control point, one undo step.
    const Point before = s->controlPoints()[5];
    QVERIFY(s->moveControlPoint(5, {before.x, before.y, before.z + 2.0}));
    QCOMPARE(s->controlPoints()[5].z, before.z + 2.0);
    const auto moved = s->derivedIfs();
    QVERIFY(moved);
    p.undoStack()->undo();
    QCOMPARE(s->controlPoints()[5], before);
    QCOMPARE(p.serialize(), original);
    // A new scheme brings its own net: one step, undone exactly.
    QVERIFY(s->setParameter("scheme.kind", int(SurfaceSchemeSpec::Kind::Loop)));
    QCOMPARE(s->scheme().layout, QString("triangle"));
    QCOMPARE(int(s->controlPoints().size()), 12);
    QVERIFY(s->setParameter("scheme.layout", 1));
    QCOMPARE(int(s->controlPoints().size()), 19);
    QVERIFY(s->derivedIfs());
    p.undoStack()->undo();
    p.undoStack()->undo();
    QCOMPARE(p.serialize(), original);
    p.undoStack()->redo();
    p.undoStack()->redo();
    QCOMPARE(s->mapCount(), 6);
    // Mesh rounds.
    QVERIFY(s->setParameter("mesh_rounds", 5));
    QCOMPARE(s->meshRounds(), 5);
    QString error;
    QVERIFY(!s->setParameter("mesh_rounds", 9, 0, &error));
    QVERIFY(!error.isEmpty());
    p.undoStack()->undo();
    QCOMPARE(s->meshRounds(), 3);
}

void TestSurfaceItem::mapsOnAndOff()
{
    Project p;
    QVERIFY(test::load(p, surfaceJson(SurfaceSchemeSpec::Kind::Loop, "hexagon")));
    SubdivisionSurfaceItem *s = surface(p);
    const QByteArray original = p.serialize();
    int bools = 0;
    for (const ParameterInfo &info : test::ownParameters(*s))
        bools += info.type == ParameterInfo::Type::Bool;
    QCOMPARE(bools, 6);
    // 000 Fig. 9: two of the six maps off.
    QVERIFY(s->setParameter("maps.2", false));
    QVERIFY(s->setParameter("maps.5", false));
    QCOMPARE(s->mapsUsed(), (std::vector<int>{0, 1, 3, 4}));
    QCOMPARE(s->derivedIfs()->ifs.size(), 4);
    QCOMPARE(s->parameter("maps.2").toBool(), false);
    QCOMPARE(s->parameter("maps.3").toBool(), true);
    QVERIFY(p.serialize().contains("\"maps_used\""));
    QVERIFY(test::reloadsIdentically(p));
    // The last map cannot go.
    for (int i : {0, 1, 3})
        QVERIFY(s->setParameter(QString("maps.%1").arg(i), false));
    QString error;
    QVERIFY(!s->setParameter("maps.4", false, 0, &error));
    QVERIFY2(error.contains("at least one map"), qPrintable(error));
    for (int k = 0; k < 5; ++k)
        p.undoStack()->undo();
    QCOMPARE(p.serialize(), original);
}

void TestSurfaceItem::netCountIsFixed()
{
    Project p;
    QVERIFY(test::load(p, surfaceJson(SurfaceSchemeSpec::Kind::Loop, "triangle")));
    SubdivisionSurfaceItem *s = surface(p);
    QVERIFY(!s->insertControlPoint(0, {0, 0, 0}));
    QVERIFY(!s->removeControlPoint(0));
    QCOMPARE(int(s->controlPoints().size()), 12);
    QVERIFY(!s->moveControlPoint(0, {0, 0, std::nan("")}));
}

void TestSurfaceItem::refinedMesh()
{
    Project p;
    QVERIFY(test::load(p, surfaceJson(SurfaceSchemeSpec::Kind::Bicubic, "square")));
    SubdivisionSurfaceItem *s = surface(p);
    const LatticeMesh net = s->refinedMesh(0);
    QCOMPARE(int(net.faces.size()), 9);  // 3 x 3 quads
    const LatticeMesh fine = s->refinedMesh(2);
    // Each round keeps the points whose stencil is complete: 4 -> 5 -> 7 per side.
    QCOMPARE(int(fine.points.rows()), 7 * 7);
    QCOMPARE(int(fine.faces.size()), 36);
}

void TestSurfaceItem::examplesLieOnTheirLimitSurface_data()
{
    // Tolerances relative to the net's size: F^k(X0) of the examples' start triangles (not on
    // the surface) approaches it by the subdominant eigenvalue per level; the limit samples
    // (5 rounds of refinement, then limit positions) are 1/32 (√3: 1/243) of a lattice step
    // apart, which bounds the measured distances from below.
    QTest::addColumn<QString>("file");
    QTest::addColumn<double>("onSurface");
    QTest::addColumn<double>("covers");
    QTest::newRow("fig 6") << "000-fig06-bicubic-patch.awb" << 0.008 << 0.005;
    QTest::newRow("fig 7") << "000-fig07-box-spline-hexagon.awb" << 0.008 << 0.005;
    QTest::newRow("fig 8") << "000-fig08-sqrt3-surface.awb" << 0.008 << 0.005;
    QTest::newRow("fig 9") << "000-fig09-box-spline-subset.awb" << 0.008 << -1.0;
}

void TestSurfaceItem::examplesLieOnTheirLimitSurface()
{
    QFETCH(QString, file);
    QFETCH(double, onSurface);
    QFETCH(double, covers);
    Project p;
    QString error;
    const QString path =
        awb::test::sourceDir() + "/examples/" + file;
    QVERIFY2(p.open(path, &error), qPrintable(error));
    for (Item *item : p.items()) {
        auto *s = dynamic_cast<SubdivisionSurfaceItem *>(item);
        QVERIFY(s);
        const auto d = s->derivedIfs();
        QVERIFY2(d, qPrintable(s->derivedError()));
        QVERIFY(!d->ifs.views.empty());
        const Mat P = toMatrix(s->controlPoints(), 3);
        const double size = (P.colwise().maxCoeff() - P.colwise().minCoeff()).norm();
        PointCollector c(d->ifs.views.front());
        iterate(d->ifs, s->coreStartSet(*d), s->algorithm().depth, c);
        const LatticeScheme scheme = s->scheme().makeScheme();
        const int rounds = scheme.dilation() == 3 ? 4 : 5;
        const Mat L = limitSurfaceSamples(scheme, s->scheme().makeLayout(), s->lattice(), P,
                                          rounds);
        const double on = directedDistance(c.points(), L) / size;
        qInfo("%s: %lld points, max distance to the limit surface %.2e of the net's size",
              qPrintable(s->name()), qint64(c.points().rows()), on);
        QVERIFY2(on < onSurface, qPrintable(QString::number(on)));
        if (covers > 0 && int(s->mapsUsed().size()) == s->net().layoutMapCount()) {
            const double gap = directedDistance(L, c.points()) / size;
            qInfo("  largest gap: %.2e of the net's size", gap);
            QVERIFY2(gap < covers, qPrintable(QString::number(gap)));
        }
    }
}

AWB_TEST_MAIN(TestSurfaceItem)
#include "test_surface_item.moc"
