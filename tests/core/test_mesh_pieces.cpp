// A mesh of any topology as an IFS with condensation (issue 30): the pieces, their types and
// maps, and the CLI's contract -- started from the corners' limit stencils, depth K gives
// exactly the limit positions of the vertices of the mesh refined K times, at extraordinary
// vertices and on the boundary too.

#include "core/mesh/MeshExamples.h"
#include "core/mesh/MeshIterate.h"
#include "core/mesh/MeshPieces.h"
#include "core/mesh/VertexSpectrum.h"

#include <QtTest>

#include "PointSets.h"
#include "TestMain.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <map>

using namespace awb;
using awb::test::diagonal;
using awb::test::directedDistance;
using awb::test::jittered;

Q_DECLARE_METATYPE(awb::Mesh)
Q_DECLARE_METATYPE(awb::MeshScheme)

namespace {

Mat collect(const MeshPieces &pieces, const Mat &vertices, const MeshStart &start, int depth)
{
    std::vector<RowVec> rows;
    CallbackSink sink([&](const Mat &v, StartSet::Kind, const std::uint8_t *, int) {
        for (Eigen::Index r = 0; r < v.rows(); ++r)
            rows.push_back(v.row(r));
    });
    iterateMesh(pieces, vertices, start, depth, {&sink});
    // The count known in advance is the count sent (PLY headers rely on it).
    if (double(rows.size()) != meshPointCount(pieces, start, depth))
        throw std::logic_error("meshPointCount disagrees with the points sent");
    Mat out(Eigen::Index(rows.size()), 3);
    for (std::size_t i = 0; i < rows.size(); ++i)
        out.row(Eigen::Index(i)) = rows[i];
    return out;
}

std::vector<double> moduli(const Mat &S)
{
    const Eigen::EigenSolver<Mat> es(S, false);
    std::vector<double> out;
    for (Eigen::Index i = 0; i < S.rows(); ++i)
        out.push_back(std::abs(es.eigenvalues()(i)));
    std::sort(out.rbegin(), out.rend());
    return out;
}

} // namespace

class TestMeshPieces : public QObject {
    Q_OBJECT
private slots:
    void vertexLimitsAreExactlyTheRefinedLimits_data();
    void vertexLimitsAreExactlyTheRefinedLimits();
    void controlPointsAreTheRefinedMesh();
    void vertexPiecesSettleOnTheirLocalSubdivisionMatrix();
    void regularFacesHaveTheBicubicSpectrum();
    void anyStartSetConvergesToTheSurface();
    void badInputIsRefusedByName();
};

void TestMeshPieces::vertexLimitsAreExactlyTheRefinedLimits_data()
{
    QTest::addColumn<Mesh>("mesh");
    QTest::addColumn<MeshScheme>("scheme");
    QTest::addColumn<int>("maxDepth");
    const auto cc = MeshScheme::CatmullClark, loop = MeshScheme::Loop;
    QTest::newRow("cube, Catmull-Clark") << cubeMesh() << cc << 4;
    QTest::newRow("pentagonal prism, Catmull-Clark") << jittered(pentagonalPrismMesh(), 1) << cc
                                                     << 3;
    QTest::newRow("tetrahedron, Catmull-Clark") << tetrahedronMesh() << cc << 3;
    QTest::newRow("icosahedron, Loop") << jittered(icosahedronMesh(), 2) << loop << 3;
    QTest::newRow("octahedron, Loop") << octahedronMesh() << loop << 3;
    QTest::newRow("tetrahedron, Loop") << tetrahedronMesh() << loop << 3;
    QTest::newRow("open grid, Catmull-Clark") << gridMesh(4, 3, false) << cc << 3;
    QTest::newRow("open grid, Loop") << gridMesh(4, 3, true) << loop << 3;
    QTest::newRow("one quad, Catmull-Clark") << gridMesh(1, 1, false) << cc << 3;
    QTest::newRow("one triangle, Loop") << Mesh{gridMesh(1, 1, true).vertices, {{0, 1, 3}}, {}}
                                        << loop << 3;
    for (unsigned seed : {1u, 2u, 3u}) {
        const Mesh m = jittered(diagonalGridMesh(5, 4, seed), seed);
        QTest::addRow("mixed diagonals %u, Loop", seed) << m << loop << 3;
        QTest::addRow("mixed diagonals %u, Catmull-Clark", seed) << m << cc << 2;
    }
    // A lone vertex stays where it is.
    Mesh lone = gridMesh(2, 2, false);
    lone.vertices.conservativeResize(lone.vertices.rows() + 1, 3);
    lone.vertices.row(lone.vertices.rows() - 1) << 5, 5, 5;
    QTest::newRow("grid and a lone vertex") << lone << cc << 2;
}

void TestMeshPieces::vertexLimitsAreExactlyTheRefinedLimits()
{
    QFETCH(Mesh, mesh);
    QFETCH(MeshScheme, scheme);
    QFETCH(int, maxDepth);
    const MeshPieces pieces = buildMeshPieces(mesh, scheme);
    QVERIFY(pieces.steps <= 2);
    const double tol = 1e-9 * diagonal(mesh.vertices);
    for (int depth = 0; depth <= maxDepth; ++depth) {
        const Mat expected = limitPositions(refineMesh(mesh, scheme, depth), scheme);
        const Mat got = collect(pieces, mesh.vertices, {}, depth);
        const double cell = 1e-6 * diagonal(mesh.vertices);
        // Each limit position at least once, and nothing else.
        const QByteArray at = "depth " + QByteArray::number(depth);
        QVERIFY2(directedDistance(expected, got, cell, 2) < tol, at.constData());
        QVERIFY2(directedDistance(got, expected, cell, 2) < tol, at.constData());
    }
}

void TestMeshPieces::controlPointsAreTheRefinedMesh()
{
    const Mesh m = jittered(diagonalGridMesh(4, 4, 7), 7);
    for (MeshScheme scheme : {MeshScheme::Loop, MeshScheme::CatmullClark}) {
        const MeshPieces pieces = buildMeshPieces(m, scheme);
        MeshStart start;
        start.kind = MeshStart::Kind::ControlPoints;
        for (int depth = 0; depth <= 3; ++depth) {
            const Mat expected = refineMesh(m, scheme, depth).vertices;
            const Mat got = collect(pieces, m.vertices, start, depth);
            const double cell = 1e-6 * diagonal(m.vertices);
            QVERIFY(directedDistance(expected, got, cell, 2) < 1e-9 * diagonal(m.vertices));
            QVERIFY(directedDistance(got, expected, cell, 2) < 1e-9 * diagonal(m.vertices));
        }
    }
}

void TestMeshPieces::vertexPiecesSettleOnTheirLocalSubdivisionMatrix()
{
    // The cube: eight valence-3 vertex pieces, whose type once settled has an S_0 with the
    // spectrum of the vertex's local subdivision matrix: 1, then lambda = 0.410097 (twice).
    // The pentagonal prism: ten valence-3 corners and the two centres of its pentagons.
    const struct {
        Mesh mesh;
        MeshScheme scheme;
        std::map<int, int> valences;  // valence -> vertex pieces
    } cases[] = {{cubeMesh(), MeshScheme::CatmullClark, {{3, 8}}},
                 {pentagonalPrismMesh(), MeshScheme::CatmullClark, {{3, 10}, {5, 2}}},
                 {icosahedronMesh(), MeshScheme::Loop, {{5, 12}}},
                 {octahedronMesh(), MeshScheme::Loop, {{4, 6}}}};
    for (const auto &c : cases) {
        const MeshPieces pieces = buildMeshPieces(c.mesh, c.scheme);
        std::map<int, int> vertexRoots;
        for (const MeshPieceRoot &root : pieces.roots) {
            const MeshPieceType &type = pieces.types[std::size_t(root.type)];
            if (type.kind != MeshPieceType::Kind::Vertex)
                continue;
            ++vertexRoots[type.valence];
            const int n = type.valence;
            const int settled = settledType(pieces, root.type);
            QVERIFY(settled >= 0);
            const MeshPieceType &s = pieces.types[std::size_t(settled)];
            QCOMPARE(s.children.front().type, settled);
            // The annulus: 3n faces, all face pieces.
            QCOMPARE(int(s.children.size()), 1 + 3 * n);
            for (std::size_t k = 1; k < s.children.size(); ++k)
                QCOMPARE(pieces.types[std::size_t(s.children[k].type)].kind,
                         MeshPieceType::Kind::Face);
            const std::vector<double> m = moduli(s.children.front().S);
            const double lambda = interiorVertexSpectrum(c.scheme, n).subdominant;
            QVERIFY(std::abs(m[0] - 1.0) < 1e-12);
            QVERIFY(std::abs(m[1] - lambda) < 1e-9);
            QVERIFY(std::abs(m[2] - lambda) < 1e-9);
            QVERIFY(m[3] < lambda - 1e-6);
            QVERIFY(s.children.front().S.rowwise().sum().isApproxToConstant(1.0, 1e-12));
        }
        QVERIFY(vertexRoots == c.valences);
        QVERIFY(pieces.types.size() < 40);
    }
}

void TestMeshPieces::regularFacesHaveTheBicubicSpectrum()
{
    // A face of a large open grid away from the boundary: its four maps are the bicubic
    // patch's (the 16 points of 000 §3), eigenvalues 1, 1/2, 1/2, 1/4, 1/4, 1/4, ...
    const MeshPieces pieces = buildMeshPieces(gridMesh(6, 6, false), MeshScheme::CatmullClark);
    bool found = false;
    for (const MeshPieceType &t : pieces.types) {
        if (t.kind != MeshPieceType::Kind::Face || t.boundary || t.netSize != 16)
            continue;
        found = true;
        QCOMPARE(int(t.children.size()), 4);
        for (const auto &child : t.children) {
            const std::vector<double> m = moduli(child.S);
            const double expected[] = {1, 0.5, 0.5, 0.25, 0.25, 0.25};
            for (int i = 0; i < 6; ++i)
                QVERIFY(std::abs(m[std::size_t(i)] - expected[i]) < 1e-12);
        }
    }
    QVERIFY(found);
}

void TestMeshPieces::anyStartSetConvergesToTheSurface()
{
    // One start point far from the surface: its images approach the limit surface (here
    // sampled densely by the vertex limits at depth 6) at least like 0.7^K (measured: 1.30,
    // 0.45, 0.13, 0.036 at depths 3 to 6).
    const Mesh m = jittered(cubeMesh(), 3);
    const MeshPieces pieces = buildMeshPieces(m, MeshScheme::CatmullClark);
    const Mat surface = collect(pieces, m.vertices, {}, 6);
    MeshStart start;
    start.kind = MeshStart::Kind::Points;
    start.points = StartSet::points((Mat(1, 3) << 3.0, -2.0, 0.5).finished());
    const double cell = 0.05;
    double previous = 1e9;
    for (int depth : {3, 4, 5, 6}) {
        const double d = directedDistance(collect(pieces, m.vertices, start, depth), surface,
                                          cell);
        QVERIFY2(d < 0.7 * previous, qPrintable(QString("depth %1: %2").arg(depth).arg(d)));
        previous = d;
    }
    QVERIFY(previous < 0.05);
}

void TestMeshPieces::badInputIsRefusedByName()
{
    const Mesh m = cubeMesh();
    const MeshPieces pieces = buildMeshPieces(m, MeshScheme::CatmullClark);
    const auto refusal = [&](const Mat &v, const MeshStart &start, int depth) {
        try {
            collect(pieces, v, start, depth);
        } catch (const InputError &e) {
            return QString::fromStdString(e.what());
        }
        return QString();
    };
    QVERIFY(refusal(m.vertices, {}, 65).contains("between 0 and 64"));
    QVERIFY(refusal(m.vertices, {}, 30).contains("at most 2^31"));
    QVERIFY(refusal(m.vertices.topRows(5), {}, 2).contains("8 vertices"));
    Mat bad = m.vertices;
    bad(2, 1) = std::nan("");
    QVERIFY(!refusal(bad, {}, 2).isEmpty());
    MeshStart flat;
    flat.kind = MeshStart::Kind::Points;
    flat.points = StartSet::points(Mat::Zero(1, 2));
    QVERIFY(refusal(m.vertices, flat, 2).contains("coordinates"));
    // A fan whose centre has valence 514 (513 triangles, open): above the pieces' limit.
    Mesh fan;
    const int count = 513;
    fan.vertices = Mat::Zero(count + 2, 3);
    for (int k = 0; k <= count; ++k)
        fan.vertices.row(k + 1) << std::cos(k * 0.012), std::sin(k * 0.012), 0;
    for (int k = 0; k < count; ++k)
        fan.faces.push_back({0, k + 1, k + 2});
    try {
        buildMeshPieces(fan, MeshScheme::Loop);
        QFAIL("a vertex of valence 514 was taken");
    } catch (const InputError &e) {
        QVERIFY2(QString(e.what()).contains("vertex 0 has 514 edges; valences above 512 are not "
                                            "supported"),
                 e.what());
    }
}

AWB_TEST_MAIN(TestMeshPieces)
#include "test_mesh_pieces.moc"
