// The "subdivision-mesh" item (model/SubdivisionMeshItem.h, issue 30): a mesh of any topology
// and its limit surface as the attractor of its IFS with condensation; the file form, the
// messages for bad meshes, undo of every edit, and what moving a vertex keeps.

#include "ItemKindTests.h"

#include "core/mesh/MeshAnalysis.h"
#include "core/mesh/MeshExamples.h"
#include "core/mesh/MeshPieces.h"
#include "core/mesh/MeshRefine.h"
#include "core/mesh/MeshSheets.h"
#include "model/EigenvaluePlotItem.h"
#include "model/MeshAnalysisJson.h"
#include "model/PointExport.h"
#include "model/SubdivisionMeshItem.h"
#include "TestMain.h"

#include <QBuffer>
#include <QJsonArray>
#include <QJsonDocument>

using namespace awb;

namespace {

// The item's JSON as the default item writes it (the cube), with edits applied by `edit`.
QByteArray meshJson(const std::function<void(QJsonObject &)> &edit = {})
{
    SubdivisionMeshItem item;
    item.setName("M");
    QJsonObject json = ProjectIO::itemToJson(item);
    if (edit)
        edit(json);
    return QJsonDocument(json).toJson(QJsonDocument::Compact);
}

SubdivisionMeshItem *meshItem(Project &p, const QString &name = "M")
{
    return dynamic_cast<SubdivisionMeshItem *>(p.findItem(name));
}

QJsonArray facesJson(const std::vector<std::vector<int>> &faces)
{
    QJsonArray out;
    for (const auto &f : faces) {
        QJsonArray loop;
        for (int v : f)
            loop.append(v);
        out.append(loop);
    }
    return out;
}

} // namespace

class TestMeshItem : public QObject {
    Q_OBJECT
private slots:
    void theCubeByDefault();
    void fileFormatRoundTrip();
    void badMeshesNameTheProblem_data();
    void badMeshesNameTheProblem();
    void nonManifoldMeshesAreDrawnAsOpenSubdivDrawsThem();
    void movingAVertexIsOneUndoStepAndKeepsThePieces();
    void schemeChangeIsOneUndoStep();
    void vertexLimitsStartIsExact();
    void analysisJson();
    void eigenvaluePlotOfAnExtraordinaryVertex();
    void limitObjRefusesAbsurdSteps();
};

void TestMeshItem::theCubeByDefault()
{
    SubdivisionMeshItem item;
    QVERIFY(item.scheme() == MeshScheme::CatmullClark);
    QCOMPARE(int(item.inputs().vertices.size()), 8);
    QCOMPARE(item.startSet().kind, StartSetSpec::Kind::VertexLimits);
    const auto d = item.derivedIfs();
    QVERIFY2(d, qPrintable(item.derivedError()));
    QVERIFY(d->iterate);
    QVERIFY(d->vertexLimitStart);
    const auto e = *item.extraordinary();
    QCOMPARE(int(e.size()), 8);
    for (const ExtraordinaryVertex &v : e) {
        QCOMPARE(v.valence, 3);
        QVERIFY(std::abs(v.subdominant - 0.410097050800551) < 1e-12);
        QVERIFY(v.c1.value_or(false));
        QCOMPARE(QString::fromStdString(v.curvature), QString("zero"));
        // The limit of a cube's corner: (+-1/2, ...) by symmetry of the stencil (n = 3:
        // (9 v + 4 sum e + sum d) / 24 after one step), the normal along the diagonal.
        QVERIFY((v.limit.cwiseAbs().array() - 0.5).abs().maxCoeff() < 1e-12);
        QVERIFY(std::abs(std::abs(v.normal(0)) - 1 / std::sqrt(3.0)) < 1e-12);
        QVERIFY(v.normal.dot(v.limit) > 0);  // outward
    }
}

void TestMeshItem::fileFormatRoundTrip()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, meshJson([](QJsonObject &j) {
                            const Mesh ico = icosahedronMesh();
                            QJsonArray v;
                            for (Eigen::Index r = 0; r < ico.vertices.rows(); ++r)
                                v.append(QJsonArray{ico.vertices(r, 0), ico.vertices(r, 1),
                                                    ico.vertices(r, 2)});
                            j["vertices"] = v;
                            j["faces"] = facesJson(ico.faces);
                            j["scheme"] = QJsonObject{{"kind", "loop"}};
                            j["colouring"] = "levels";
                        }),
                        &error),
             qPrintable(error));
    SubdivisionMeshItem *m = meshItem(p);
    QVERIFY(m);
    QVERIFY(m->scheme() == MeshScheme::Loop);
    QCOMPARE(int(m->inputs().faces.size()), 20);
    QVERIFY(m->inputs().levelColours);
    QVERIFY(test::reloadsIdentically(p));
    const auto e = *m->extraordinary();
    QCOMPARE(int(e.size()), 12);
    QVERIFY(std::abs(e.front().subdominant - (3.0 / 8 + std::cos(2 * M_PI / 5) / 4)) < 1e-12);
}

void TestMeshItem::badMeshesNameTheProblem_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("words");
    const auto faces = [](std::vector<std::vector<int>> f) {
        return meshJson([f](QJsonObject &j) { j["faces"] = facesJson(f); });
    };
    const std::vector<std::vector<int>> cube = cubeMesh().faces;
    auto outOfRange = cube;
    outOfRange[2][1] = 8;
    QTest::newRow("index out of range") << faces(outOfRange) << "refers to vertex 8";
    QTest::newRow("two vertices") << faces({{0, 1}}) << "needs at least 3";
    QTest::newRow("no faces") << faces({}) << "no faces";
    QTest::newRow("Loop on quads")
        << meshJson([](QJsonObject &j) { j["scheme"] = QJsonObject{{"kind", "loop"}}; })
        << "Loop subdivision takes triangles only";
    QTest::newRow("not a face list")
        << meshJson([](QJsonObject &j) { j["faces"] = "cube"; }) << "expected an array of faces";
    QTest::newRow("fractional index") << meshJson([](QJsonObject &j) {
        // Appended: QJsonArray{QJsonArray{...}} is a copy for some compilers (clang).
        QJsonArray faces;
        faces.append(QJsonArray{0, 1.5, 2});
        j["faces"] = faces;
    }) << "whole numbers";
    QTest::newRow("no vertices") << meshJson([](QJsonObject &j) { j["vertices"] = QJsonArray(); })
                                 << "no vertices";
}

void TestMeshItem::badMeshesNameTheProblem()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, words);
    const QString error = test::loadError(json);
    QVERIFY2(error.contains(words), qPrintable(error));
}

void TestMeshItem::nonManifoldMeshesAreDrawnAsOpenSubdivDrawsThem()
{
    // What the topology alone refuses, drawn as OpenSubdiv draws it (MeshSheets.h): a face
    // turned over (its edges become infinitely sharp, its corners corners), a fin on an edge of
    // the cube (three faces on edge (0, 1)), a face that names a vertex twice. Each loads; its
    // non-manifold vertices are corners, so their limits are the control points themselves.
    const std::vector<std::vector<int>> cube = cubeMesh().faces;
    auto flipped = cube;
    std::reverse(flipped[3].begin(), flipped[3].end());
    auto fins = cube;
    fins.push_back({0, 1, 7, 6});
    auto repeated = cube;
    repeated[1][2] = repeated[1][0];
    for (const auto &faces : {flipped, fins, repeated}) {
        Project p;
        QString error;
        QVERIFY2(test::load(p, meshJson([&](QJsonObject &j) { j["faces"] = facesJson(faces); }),
                            &error),
                 qPrintable(error));
        const SubdivisionMeshItem *item = meshItem(p);
        QVERIFY(item);
        QVERIFY2(item->derivedIfs(), qPrintable(item->derivedError()));
        const Mesh mesh = item->inputs().mesh();
        const auto sheets = manifoldSheets(mesh);
        QVERIFY(sheets);
        const Mat limits = limitPositions(mesh, MeshScheme::CatmullClark);
        for (int v : sheets->vertices)
            if (std::find(sheets->creaseVertices.begin(), sheets->creaseVertices.end(), v)
                == sheets->creaseVertices.end())
                QVERIFY((limits.row(v) - mesh.vertices.row(v)).norm() < 1e-15);
    }
}

void TestMeshItem::movingAVertexIsOneUndoStepAndKeepsThePieces()
{
    Project p;
    QVERIFY(test::load(p, meshJson()));
    SubdivisionMeshItem *m = meshItem(p);
    const auto pieces = m->pieces();
    QVERIFY(pieces);
    const Point before = m->controlPoints()[3];
    const int gesture = p.beginGesture();
    QVERIFY(m->moveControlPoint(3, {1.5, 1.2, -1.1}, gesture));
    QVERIFY(m->moveControlPoint(3, {1.6, 1.3, -1.2}, gesture));
    p.endGesture(gesture);
    QCOMPARE(p.undoStack()->count(), 1);
    QCOMPARE(m->controlPoints()[3], (Point{1.6, 1.3, -1.2}));
    // The faces did not change: the pieces are the same object, the limit moved.
    QCOMPARE(m->pieces().get(), pieces.get());
    p.undoStack()->undo();
    QCOMPARE(m->controlPoints()[3], before);
    // A NaN is refused.
    QVERIFY(!m->moveControlPoint(3, {std::nan(""), 0, 0}));
}

void TestMeshItem::schemeChangeIsOneUndoStep()
{
    Project p;
    QVERIFY(test::load(p, meshJson()));
    SubdivisionMeshItem *m = meshItem(p);
    QString error;
    QVERIFY(!m->setScheme(MeshScheme::Loop, &error));
    QVERIFY2(error.contains("face 0 has 4 vertices"), qPrintable(error));
    QVERIFY(!m->setParameter("scheme.kind", 1, 0, &error));
    QCOMPARE(p.undoStack()->count(), 0);
    QVERIFY(m->setMesh(octahedronMesh(), MeshScheme::CatmullClark));
    QVERIFY(m->setParameter("scheme.kind", 1));
    QVERIFY(m->scheme() == MeshScheme::Loop);
    QCOMPARE(p.undoStack()->count(), 2);
    QCOMPARE(int(m->extraordinary()->size()), 6);  // Loop: six valence-4 vertices
    p.undoStack()->undo();
    QVERIFY(m->scheme() == MeshScheme::CatmullClark);
    QCOMPARE(int(m->extraordinary()->size()), 8);  // CC: valence 4 is regular; 8 triangle centres
    p.undoStack()->undo();
    QCOMPARE(int(m->inputs().vertices.size()), 8);
}

void TestMeshItem::vertexLimitsStartIsExact()
{
    // The item's own start set: the points written are the limit positions of the mesh
    // refined K times, each at least once.
    Project p;
    QVERIFY(test::load(p, meshJson()));
    SubdivisionMeshItem *m = meshItem(p);
    const auto d = m->derivedIfs();
    const StartSet start = m->coreStartSet(*d);
    QCOMPARE(start.vertices.rows(), 0);
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    const int depth = 2;
    const std::uint64_t n = writePointsCsv(buffer, *d, start, depth, {});
    QCOMPARE(double(n), exportPointCount(*d, start, depth));
    const Mat expected = limitPositions(refineMesh(m->mesh(), MeshScheme::CatmullClark, depth),
                                        MeshScheme::CatmullClark);
    const QList<QByteArray> lines = buffer.data().split('\n');
    QCOMPARE(lines.front(), QByteArray("x,y,z,map,view"));
    std::vector<bool> seen(std::size_t(expected.rows()), false);
    for (qsizetype l = 1; l < lines.size(); ++l) {
        if (lines[l].isEmpty())
            continue;
        const QList<QByteArray> c = lines[l].split(',');
        const RowVec x = (RowVec(3) << c[0].toDouble(), c[1].toDouble(), c[2].toDouble())
                             .finished();
        Eigen::Index best = 0;
        const double dist = (expected.rowwise() - x).rowwise().norm().minCoeff(&best);
        QVERIFY2(dist < 1e-12, qPrintable(QString::fromUtf8(lines[l])));
        seen[std::size_t(best)] = true;
    }
    QVERIFY(std::all_of(seen.begin(), seen.end(), [](bool b) { return b; }));
}

void TestMeshItem::analysisJson()
{
    SubdivisionMeshItem item;
    QVERIFY(item.setMesh(pentagonalPrismMesh(), MeshScheme::CatmullClark));
    const QJsonObject o = meshAnalysisJson(item);
    QCOMPARE(o["kind"].toString(), QString("subdivision-mesh"));
    QCOMPARE(o["vertex_count"].toInt(), 10);
    QCOMPARE(o["face_count"].toInt(), 7);
    const QJsonArray e = o["extraordinary"].toArray();
    QCOMPARE(e.size(), 12);  // ten valence-3 corners, two pentagon centres
    QCOMPARE(e[0].toObject()["vertex"].toInt(), 0);
    const QJsonObject centre = e[11].toObject();
    QCOMPARE(centre["face"].toInt(), 1);
    QVERIFY(!centre.contains("vertex"));
    QCOMPARE(centre["valence"].toInt(), 5);
    // Its kind (the matrix and what it says, once for every vertex that shares it).
    const QJsonArray kinds = o["vertex_kinds"].toArray();
    QCOMPARE(kinds.size(), 2);  // valence 3, valence 5
    const QJsonObject five = kinds[centre["kind"].toInt()].toObject();
    QCOMPARE(five["valence"].toInt(), 5);
    QCOMPARE(five["vertices"].toInt(), 2);
    QVERIFY(std::abs(five["subdominant"].toDouble() - 0.549988) < 1e-6);
    QCOMPARE(five["eigenvalues"].toArray().size(), 31);  // the ring: 6n + 1
    QCOMPARE(five["curvature"].toString(), QString("unbounded"));
    QVERIFY(five["c1"].toBool());
    QCOMPARE(kinds[e[0].toObject()["kind"].toInt()].toObject()["vertices"].toInt(), 10);
    // One step makes the pentagons' centres vertices, next to the valence-3 corners; a second
    // separates them.
    QCOMPARE(o["pieces"].toObject()["isolation_steps"].toInt(), 2);
}

void TestMeshItem::eigenvaluePlotOfAnExtraordinaryVertex()
{
    // An eigenvalue plot whose source is an extraordinary vertex (issue 31): the eigenvalues of
    // its local subdivision matrix, saved with the project, undoable, refused with a message
    // that names the vertex when there is no such extraordinary vertex.
    Project p;
    QString error;
    QVERIFY2(test::load(p, meshJson(), &error), qPrintable(error));
    auto plot = std::make_unique<EigenvaluePlotItem>();
    plot->setName("E");
    plot->setSource("M");
    auto *e = static_cast<EigenvaluePlotItem *>(p.addItem(std::move(plot)));
    const int before = p.undoStack()->count();
    QVERIFY(e->setExtraordinary(3));
    QCOMPARE(p.undoStack()->count(), before + 1);
    auto data = e->eigenvalues();
    QVERIFY2(data, qPrintable(e->derivedError()));
    QCOMPARE(int(data->spectra.size()), 1);
    QCOMPARE(data->matrices.real.front().rows(), Eigen::Index(19));  // 6n + 1 at valence 3
    QVERIFY(std::abs(data->subdominants.front().modulus - 0.410097050800551)
            < 1e-9);
    QVERIFY(test::reloadsIdentically(p));
    QVERIFY(ProjectIO::itemToJson(*e)["vertex"].toInt() == 3);
    p.undoStack()->undo();
    QCOMPARE(e->vertex(), -1);
    QVERIFY(e->setExtraordinary(42));
    QVERIFY(!e->eigenvalues());
    QVERIFY2(e->derivedError().contains("vertex 42"), qPrintable(e->derivedError()));
    QVERIFY(e->setMatrixKind(EigenvaluePlotItem::MatrixKind::A));
    QVERIFY(e->setExtraordinary(0));
    QVERIFY(!e->eigenvalues());
    QVERIFY2(e->derivedError().contains("local subdivision matrix"),
             qPrintable(e->derivedError()));

    // The Loop icosahedron: lambda = 3/8 + cos(2 pi/5)/4 = 0.4523 at every vertex (valence 5).
    auto *m = meshItem(p);
    QVERIFY(m->setMesh(icosahedronMesh(), MeshScheme::Loop));
    QVERIFY(e->setMatrixKind(EigenvaluePlotItem::MatrixKind::S));
    data = e->eigenvalues();
    QVERIFY2(data, qPrintable(e->derivedError()));
    QCOMPARE(data->matrices.real.front().rows(), Eigen::Index(16));  // 3n + 1
    QVERIFY(std::abs(data->subdominants.front().modulus - 0.4523) < 5e-5);
}

void TestMeshItem::limitObjRefusesAbsurdSteps()
{
    SubdivisionMeshItem item;
    const std::string obj = item.limitObj(1);
    // The cube after one Catmull-Clark step: 26 vertices, 24 quads.
    QCOMPARE(int(std::count(obj.begin(), obj.end(), '\n')) > 50, true);
    QVERIFY(obj.find("\nv ") != std::string::npos);
    try {
        item.limitObj(SubdivisionMeshItem::maxExportRounds + 1);
        QFAIL("nine steps accepted");
    } catch (const InputError &e) {
        QVERIFY2(QString(e.what()).contains("0 to 8"), e.what());
    }
    QVERIFY(item.setMesh(gridMesh(200, 200, false), MeshScheme::CatmullClark));
    try {
        item.limitObj(8);
        QFAIL("billions of vertices accepted");
    } catch (const InputError &e) {
        QVERIFY2(QString(e.what()).contains("vertices"), e.what());
    }
}

AWB_TEST_MAIN(TestMeshItem)
#include "test_mesh_item.moc"
