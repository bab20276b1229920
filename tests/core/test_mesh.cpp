// Meshes of any topology (issue 30, the core): connectivity and its refusals, one step of
// Catmull-Clark and Loop with OpenSubdiv's rules (VTX_BOUNDARY_EDGE_ONLY), limit positions,
// and the eigenvalues of the local subdivision matrix against their closed forms.

#include "core/BigAllocator.h"
#include "core/mesh/Mesh.h"
#include "core/mesh/MeshExamples.h"
#include "core/mesh/MeshRefine.h"
#include "core/mesh/VertexSpectrum.h"

#include <QtTest>

#include "TestMain.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

using namespace awb;

namespace {

double diagonal(const Mesh &m)
{
    return (m.vertices.colwise().maxCoeff() - m.vertices.colwise().minCoeff()).norm();
}

QString refusal(const Mesh &m, MeshScheme scheme)
{
    try {
        checkMesh(m, scheme);
    } catch (const InputError &e) {
        return QString::fromStdString(e.what());
    }
    return QString();
}

} // namespace

class TestMesh : public QObject {
    Q_OBJECT
private slots:
    void cubeAfterOneCatmullClarkStep();
    void loopCounts();
    void limitPositionsAreTheLimitOfRefinement_data();
    void limitPositionsAreTheLimitOfRefinement();
    void boundaryIsTheCubicBSplineOfThePolygon();
    void extraordinaryVertices();
    void subdominantEigenvalueClosedForms();
    void characteristicMapWindsOnce();
    void characteristicMapIsKeptForDrawing();
    void badMeshesAreRefusedByName();
    void flatRelationsKeepTheRows();
    void refinedTopologyFromTheParent();
};

void TestMesh::cubeAfterOneCatmullClarkStep()
{
    // The cube [-1, 1]^3: a corner goes to (Q + 2R + (n - 3) V) / n with n = 3, Q the mean of
    // its three face centres (1/3 each coordinate), R of its three edge midpoints (2/3): 5/9.
    const Mesh once = refineMesh(cubeMesh(), MeshScheme::CatmullClark);
    QCOMPARE(once.vertices.rows(), Eigen::Index(8 + 12 + 6));
    QCOMPARE(once.faces.size(), std::size_t(24));
    for (int v = 0; v < 8; ++v) // vertex points keep their numbers
        for (int c = 0; c < 3; ++c)
            QVERIFY(std::abs(std::abs(once.vertices(v, c)) - 5.0 / 9.0) < 1e-15);
    QVERIFY((once.vertices.row(7) - Eigen::RowVector3d(5.0 / 9, 5.0 / 9, 5.0 / 9)).norm() < 1e-15);
    // Edge points: (v0 + v1 + two face centres) / 4, e.g. (1, 1, +-1) -> (3/4, 3/4, 0).
    const MeshTopology t(8, cubeMesh().faces);
    const int e = t.findEdge(3, 7);
    QVERIFY(e >= 0);
    QVERIFY((once.vertices.row(8 + e) - Eigen::RowVector3d(0.75, 0.75, 0)).norm() < 1e-15);
    // Face points: the face centres (one coordinate +-1, the others 0).
    for (int f = 0; f < 6; ++f)
        QVERIFY(std::abs(once.vertices.row(20 + f).cwiseAbs().sum() - 1.0) < 1e-15);
    // The refined mesh is closed, oriented, all quads, valence 3 at the corners.
    const MeshTopology t1(26, once.faces);
    QCOMPARE(t1.edgeCount(), 48);
    for (int v = 0; v < 26; ++v)
        QVERIFY(!t1.onBoundary(v));
    QCOMPARE(t1.valence(0), 3);
    QCOMPARE(t1.valence(20), 4);
}

void TestMesh::loopCounts()
{
    const Mesh ico = icosahedronMesh();
    QCOMPARE(ico.faces.size(), std::size_t(20));
    const Mesh once = refineMesh(ico, MeshScheme::Loop);
    QCOMPARE(once.vertices.rows(), Eigen::Index(12 + 30));
    QCOMPARE(once.faces.size(), std::size_t(80));
    // A vertex of valence 5: (1 - 5 beta) v + beta (sum of its 5 neighbours), beta = 3/80 ... as
    // Loop's formula gives: (5/8 - (3/8 + cos(72 deg)/4)^2) / 5.
    const double c = 3.0 / 8 + std::cos(2 * M_PI / 5) / 4;
    const double beta = (5.0 / 8 - c * c) / 5;
    const MeshTopology t(12, ico.faces);
    Eigen::RowVector3d expect = (1 - 5 * beta) * ico.vertices.row(0);
    for (int e : t.ring(0).edges)
        expect += beta * ico.vertices.row(t.otherEnd(e, 0));
    QVERIFY((once.vertices.row(0) - expect).norm() < 1e-15);
}

void TestMesh::limitPositionsAreTheLimitOfRefinement_data()
{
    QTest::addColumn<int>("which");
    QTest::newRow("cube, Catmull-Clark") << 0;
    QTest::newRow("pentagonal prism, Catmull-Clark (pentagons)") << 1;
    QTest::newRow("tetrahedron, Catmull-Clark (triangles)") << 2;
    QTest::newRow("icosahedron, Loop") << 3;
    QTest::newRow("open grid, Catmull-Clark") << 4;
    QTest::newRow("open triangulated grid, Loop") << 5;
}

void TestMesh::limitPositionsAreTheLimitOfRefinement()
{
    // The limit of vertex v is the limit of its point after k steps (same number): the limit
    // masks are the left eigenvectors of the rules, at extraordinary vertices, next to
    // non-quads and on the boundary. And the points of the steps converge to it.
    QFETCH(int, which);
    const std::vector<std::pair<Mesh, MeshScheme>> meshes{
        {cubeMesh(), MeshScheme::CatmullClark},
        {pentagonalPrismMesh(), MeshScheme::CatmullClark},
        {tetrahedronMesh(), MeshScheme::CatmullClark},
        {icosahedronMesh(), MeshScheme::Loop},
        {gridMesh(4, 3, false), MeshScheme::CatmullClark},
        {gridMesh(4, 3, true), MeshScheme::Loop}};
    const auto &[mesh, scheme] = meshes[std::size_t(which)];
    const Eigen::Index n = mesh.vertices.rows();
    const Mat limit = limitPositions(mesh, scheme);
    const double tol = 1e-12 * diagonal(mesh);
    double previous = 1e300;
    for (int k = 1; k <= 6; ++k) {
        const Mesh refined = refineMesh(mesh, scheme, k);
        const Mat again = limitPositions(refined, scheme).topRows(n);
        const double gap = (again - limit).rowwise().norm().maxCoeff();
        QVERIFY2(gap < tol, qPrintable(QStringLiteral("step %1: %2").arg(k).arg(gap)));
        const double distance = (refined.vertices.topRows(n) - limit).rowwise().norm().maxCoeff();
        QVERIFY2(distance < previous, qPrintable(QStringLiteral("step %1").arg(k)));
        previous = distance;
    }
    QVERIFY(previous < 0.02 * diagonal(mesh));
}

void TestMesh::boundaryIsTheCubicBSplineOfThePolygon()
{
    // VTX_BOUNDARY_EDGE_ONLY: every boundary vertex, the grid's corners too, has the limit
    // (b0 + 4 v + b1) / 6 of its boundary neighbours, in both schemes.
    for (bool triangles : {false, true}) {
        const Mesh m = gridMesh(3, 2, triangles);
        const Mat limit =
            limitPositions(m, triangles ? MeshScheme::Loop : MeshScheme::CatmullClark);
        // Vertex 1 = (1, 0): neighbours (0, 0) and (2, 0) along the boundary.
        const Eigen::RowVector3d expect =
            (m.vertices.row(0) + 4 * m.vertices.row(1) + m.vertices.row(2)) / 6;
        QVERIFY((limit.row(1) - expect).norm() < 1e-15);
        // The corner (0, 0): neighbours (1, 0) and (0, 1) = vertex 4.
        const Eigen::RowVector3d corner =
            (m.vertices.row(1) + 4 * m.vertices.row(0) + m.vertices.row(4)) / 6;
        QVERIFY((limit.row(0) - corner).norm() < 1e-15);
    }
}

void TestMesh::extraordinaryVertices()
{
    const MeshTopology c(8, cubeMesh().faces);
    QCOMPARE(c.extraordinaryVertices(MeshScheme::CatmullClark).size(), std::size_t(8));
    const MeshTopology ico(12, icosahedronMesh().faces);
    const auto ev = ico.extraordinaryVertices(MeshScheme::Loop);
    QCOMPARE(ev.size(), std::size_t(12));
    for (int v : ev)
        QCOMPARE(ico.valence(v), 5);
    const Mesh g = gridMesh(4, 4, false);
    const MeshTopology gt(int(g.vertices.rows()), g.faces);
    QVERIFY(gt.extraordinaryVertices(MeshScheme::CatmullClark).empty());
    QCOMPARE(gt.valence(0), 2); // a corner: boundary, regular for the crease rule
    QVERIFY(gt.onBoundary(0));
}

void TestMesh::subdominantEigenvalueClosedForms()
{
    // The local subdivision matrix on the ring of two faces around a vertex of valence n:
    // 1 first, the subdominant pair (Stam 1998 for Catmull-Clark, 3/8 + cos(2 pi/n)/4 for
    // Loop), and the next modulus mu against lambda^2.
    for (MeshScheme scheme : {MeshScheme::CatmullClark, MeshScheme::Loop}) {
        for (int n = 3; n <= 12; ++n) {
            const VertexSpectrum s = interiorVertexSpectrum(scheme, n);
            QCOMPARE(s.S.rows(),
                     Eigen::Index(scheme == MeshScheme::Loop ? 3 * n + 1 : 6 * n + 1));
            QVERIFY((s.S.rowwise().sum().array() - 1.0).abs().maxCoeff() < 1e-14);
            QVERIFY(std::abs(s.eigenvalues[0] - 1.0) < 1e-12);
            const double closed = closedFormSubdominant(scheme, n);
            QVERIFY2(std::abs(s.subdominant - closed) < 1e-12,
                     qPrintable(QStringLiteral("%1 n=%2: %3 vs %4")
                                    .arg(QString::fromStdString(toString(scheme)))
                                    .arg(n)
                                    .arg(s.subdominant, 0, 'g', 17)
                                    .arg(closed, 0, 'g', 17)));
            QVERIFY(s.spectralC1);
            QVERIFY(s.characteristicRegular);
            QVERIFY(s.characteristicInjective);
            QVERIFY(s.c1);
            qInfo("%-13s n=%2d  lambda=%.6f  mu=%.6f  lambda^2=%.6f  curvature %s",
                  toString(scheme).c_str(), n, s.subdominant, s.subsubdominant,
                  s.subdominant * s.subdominant, s.curvature.c_str());
        }
        // The regular vertex: lambda = 1/2, mu = 1/4 = lambda^2 (the splines' bounded curvature).
        const VertexSpectrum regular = interiorVertexSpectrum(scheme, regularValence(scheme));
        QVERIFY(std::abs(regular.subdominant - 0.5) < 1e-12);
        QVERIFY(std::abs(regular.subsubdominant - 0.25) < 1e-12);
        QCOMPARE(regular.curvature, std::string("bounded"));
    }
    // Catmull-Clark's curvature diverges at valences above 4 (mu = 1/4 > lambda^2): Peters &
    // Reif 2008, section 7.
    QCOMPARE(interiorVertexSpectrum(MeshScheme::CatmullClark, 5).curvature,
             std::string("unbounded"));
    QVERIFY_THROWS_EXCEPTION(InputError, interiorVertexSpectrum(MeshScheme::Loop, 2));
}

void TestMesh::characteristicMapWindsOnce()
{
    // The star's own layout as planar control points is a regular, injective map (winding
    // number 1); the same points at twice their angle wind twice around the centre: not
    // injective, as the second Fourier frequency's eigenvectors (mu for Catmull-Clark n > 4).
    for (MeshScheme scheme : {MeshScheme::CatmullClark, MeshScheme::Loop}) {
        const std::vector<std::pair<int, int>> sector =
            scheme == MeshScheme::CatmullClark
                ? std::vector<std::pair<int, int>>{{1, 0}, {1, 1}, {2, 0}, {2, 1}, {2, 2}, {1, 2}}
                : std::vector<std::pair<int, int>>{{1, 0}, {2, 0}, {1, 1}};
        const int n = 7;
        Mat layout(1 + n * Eigen::Index(sector.size()), 2), doubled(layout.rows(), 2);
        layout.row(0).setZero();
        doubled.row(0).setZero();
        Eigen::Index r = 1;
        for (int k = 0; k < n; ++k) {
            const double a0 = 2 * M_PI * k / n, a1 = 2 * M_PI * (k + 1) / n;
            for (const auto &[i, j] : sector) {
                const double x = i * std::cos(a0) + j * std::cos(a1);
                const double y = i * std::sin(a0) + j * std::sin(a1);
                layout.row(r) << x, y;
                const double radius = std::hypot(x, y), angle = 2 * std::atan2(y, x);
                doubled.row(r++) << radius * std::cos(angle), radius * std::sin(angle);
            }
        }
        const CharacteristicMap plain = checkCharacteristicMap(scheme, n, layout);
        QVERIFY(plain.regular());
        QCOMPARE(plain.winding, 1);
        QVERIFY(plain.injective());
        const CharacteristicMap twice = checkCharacteristicMap(scheme, n, doubled);
        QCOMPARE(twice.winding, 2);
        QVERIFY(!twice.injective());
    }
}

void TestMesh::characteristicMapIsKeptForDrawing()
{
    // The map the view draws is the one checked: the n faces around the vertex refined three
    // times (64 cells each), each cell's signed area of one sign away from the centre, every
    // sector present, and an outline once around. The Catmull-Clark valence 3 of the issue:
    // lambda = 0.4101 (Stam 1998).
    for (MeshScheme scheme : {MeshScheme::CatmullClark, MeshScheme::Loop}) {
        for (int n : {3, 5, 7}) {
            const auto s = sharedVertexSpectrum(scheme, n);
            QCOMPARE(sharedVertexSpectrum(scheme, n).get(), s.get());  // computed once
            const CharacteristicMap &m = s->characteristic;
            QCOMPARE(int(m.cells.size()), 64 * n);
            QCOMPARE(m.cellAreas.size(), m.cells.size());
            QCOMPARE(m.cellSectors.size(), m.cells.size());
            int centre = 0, positive = 0, negative = 0;
            std::vector<int> perSector(std::size_t(n), 0);
            for (std::size_t c = 0; c < m.cells.size(); ++c) {
                const double a = m.cellAreas[c];
                (a == 0 ? centre : a > 0 ? positive : negative)++;
                QVERIFY(m.cellSectors[c] >= 0 && m.cellSectors[c] < n);
                ++perSector[std::size_t(m.cellSectors[c])];
            }
            QCOMPARE(centre, n);  // one cell per face touches the centre
            QVERIFY(positive == 0 || negative == 0);
            for (int k : perSector)
                QCOMPARE(k, 64);
            QVERIFY(m.outline.size() >= std::size_t(8 * n));
            QVERIFY(std::abs(s->subdominant - closedFormSubdominant(scheme, n)) < 1e-12);
        }
    }
    QVERIFY(std::abs(sharedVertexSpectrum(MeshScheme::CatmullClark, 3)->subdominant - 0.4101)
            < 5e-5);
    QVERIFY(std::abs(sharedVertexSpectrum(MeshScheme::Loop, 5)->subdominant - 0.4523) < 5e-5);
    const std::vector<VertexSpectrum> table = valenceSpectra(MeshScheme::Loop, 3, 16);
    QCOMPARE(int(table.size()), 14);
    for (std::size_t k = 0; k < table.size(); ++k)
        QCOMPARE(table[k].valence, int(k) + 3);
}

void TestMesh::badMeshesAreRefusedByName()
{
    const auto cc = MeshScheme::CatmullClark;
    Mesh m = cubeMesh();
    m.faces[2][1] = 8;
    QCOMPARE(refusal(m, cc),
             QStringLiteral("face 2 refers to vertex 8, but the mesh has 8 vertices (0 to 7)"));
    m = cubeMesh();
    m.faces[3] = {2, 6, 2, 3};
    QCOMPARE(refusal(m, cc), QStringLiteral("face 3 lists vertex 2 twice"));
    m = cubeMesh();
    m.faces[0] = {0, 2};
    QCOMPARE(refusal(m, cc), QStringLiteral("face 0 has 2 vertices; a face needs at least 3"));
    m = cubeMesh();
    std::reverse(m.faces[4].begin(), m.faces[4].end());
    QVERIFY2(refusal(m, cc).contains(QStringLiteral("oriented inconsistently")),
             qPrintable(refusal(m, cc)));
    QVERIFY(refusal(m, cc).contains(QStringLiteral(" 4 ")));
    m = cubeMesh();
    m.faces.push_back(m.faces[0]); // a second copy of a face on the same edges
    std::reverse(m.faces.back().begin(), m.faces.back().end());
    QVERIFY2(refusal(m, cc).contains(QStringLiteral("non-manifold: faces")),
             qPrintable(refusal(m, cc)));
    m = cubeMesh();
    m.vertices(5, 1) = std::nan("");
    QCOMPARE(refusal(m, cc),
             QStringLiteral("vertex 5 has a coordinate that is not a finite number"));
    QCOMPARE(refusal(cubeMesh(), MeshScheme::Loop),
             QStringLiteral("face 0 has 4 vertices; Loop subdivision takes triangles only"));
    QCOMPARE(refusal(Mesh{}, cc), QStringLiteral("the mesh has no vertices"));
    m = cubeMesh();
    m.faces.clear();
    QCOMPARE(refusal(m, cc), QStringLiteral("the mesh has no faces"));
    // Two tetrahedra sharing one vertex only: a bowtie, two fans at vertex 0.
    Mesh bow;
    bow.vertices.resize(7, 3);
    bow.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1;
    bow.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},
                 {0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}};
    QVERIFY2(refusal(bow, cc).startsWith(QStringLiteral("vertex 0 is non-manifold")),
             qPrintable(refusal(bow, cc)));
    QVERIFY(refusal(cubeMesh(), cc).isEmpty());
    QVERIFY(refusal(icosahedronMesh(), MeshScheme::Loop).isEmpty());
    // Every fault of a kind at once (issue 44: a real file's six bowties were one per run).
    m = cubeMesh();
    m.faces[1] = {1, 9, 2, 5};
    m.faces[3] = {2, 6, 11, 3};
    QCOMPARE(refusal(m, cc),
             QStringLiteral("2 problems: face 1 refers to vertex 9, but the mesh has 8 vertices "
                            "(0 to 7); face 3 refers to vertex 11, but the mesh has 8 vertices "
                            "(0 to 7)"));
    m = cubeMesh();
    for (int f : {0, 2, 4})  // half the faces turned over: many edges run twice one way
        std::reverse(m.faces[std::size_t(f)].begin(), m.faces[std::size_t(f)].end());
    const QString many = refusal(m, cc);
    QVERIFY2(many.contains(QRegularExpression("^\\d+ problems(, the first 5)?: faces ")),
             qPrintable(many));
    QVERIFY(many.count(QStringLiteral("oriented inconsistently")) >= 2);
}

AWB_TEST_MAIN(TestMesh)
// The mesh room's flat relations (IndexRows, StencilTable) and the allocator of their large
// arrays: the rows read back as given, a large block is whole and, mapped, on 2 MB boundaries.
void TestMesh::flatRelationsKeepTheRows()
{
    const std::vector<std::vector<int>> rows{{0, 1, 2}, {}, {3, 4, 5, 6}, {7}};
    const IndexRows flat(rows);
    QCOMPARE(flat.size(), rows.size());
    QCOMPARE(flat.toVectors(), rows);
    QCOMPARE(int(flat[2].size()), 4);
    QCOMPARE(flat[2][3], 6);
    std::size_t visited = 0;
    for (const auto row : flat)
        visited += row.size();
    QCOMPARE(visited, std::size_t(8));
    IndexRows faces = IndexRows::shapedLike(flat, -1);
    QCOMPARE(faces.starts(), flat.starts());
    QCOMPARE(faces[3][0], -1);

    StencilTable table;
    table.push_back({{0, 0.5}, {1, 0.5}});
    table.push_back({{2, 1.0}});
    table.push_back({{0, 0.25}, {1, 0.25}, {2, 0.5}});
    QCOMPARE(table.size(), std::size_t(3));
    QCOMPARE(table.entryCount(), std::size_t(6));
    const Mat data = (Mat(3, 1) << 1.0, 3.0, 8.0).finished();
    const Mat applied = applyStencils(table, data);
    QCOMPARE(applied(0, 0), 2.0);
    QCOMPARE(applied(1, 0), 8.0);
    QCOMPARE(applied(2, 0), 5.0);
    // Stencil 0 over the table itself: (s0 + s1) / 2 = p0 / 4 + p1 / 4 + p2 / 2.
    StencilTable composed;
    const MeshStencil first(table[0].begin(), table[0].end());
    appendComposed(composed, first, table);
    const MeshStencil expected{{0, 0.25}, {1, 0.25}, {2, 0.5}};
    QVERIFY(std::ranges::equal(composed[0], expected));
    table.truncate(1);
    QCOMPARE(table.size(), std::size_t(1));
    QCOMPARE(table.entryCount(), std::size_t(2));

    // 24 MB: past the threshold of the mapped blocks; every element kept through a growth.
    BigVector<int> big(6 << 20);
    for (std::size_t i = 0; i < big.size(); ++i)
        big[i] = int(i);
    big.push_back(-1);
    long long sum = 0;
    for (std::size_t i = 0; i + 1 < big.size(); ++i)
        sum += big[i] == int(i) ? 1 : 0;
    QCOMPARE(sum, (long long)(6 << 20));
#if defined(__linux__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
    QCOMPARE(reinterpret_cast<std::uintptr_t>(big.data()) % (std::uintptr_t(2) << 20),
             std::uintptr_t(0));
#endif
}

// A refinement's child topology is derived from the parent's relations (MeshChildTopology.cpp,
// no search, no walk): it must be the topology that the checked construction finds from the
// child's faces alone -- the same edges in the same order, faces' edges and vertex rings with
// their first face, boundary flags -- closed and open, quads, triangles and pentagons, a vertex
// of no face, both schemes, two levels down.
void TestMesh::refinedTopologyFromTheParent()
{
    Mesh lone = gridMesh(2, 2, true);
    lone.vertices.conservativeResize(lone.vertices.rows() + 1, 3);
    lone.vertices.row(lone.vertices.rows() - 1) << 5.0, 5.0, 5.0;
    const std::vector<std::pair<Mesh, MeshScheme>> cases{
        {lone, MeshScheme::CatmullClark},
        {lone, MeshScheme::Loop},
        {cubeMesh(), MeshScheme::CatmullClark},
        {pentagonalPrismMesh(), MeshScheme::CatmullClark},
        {gridMesh(3, 2, false), MeshScheme::CatmullClark},
        {gridMesh(3, 2, true), MeshScheme::CatmullClark},
        {torusMesh(5, 4, true), MeshScheme::CatmullClark},
        {icosahedronMesh(), MeshScheme::Loop},
        {gridMesh(3, 3, true), MeshScheme::Loop},
        {diagonalGridMesh(4, 3, 7), MeshScheme::Loop},
    };
    int compared = 0;
    for (const auto &[mesh, scheme] : cases) {
        MeshTopology t = checkMesh(mesh, scheme);
        for (int level = 0; level < 2; ++level) {
            const Refinement r = refineTopology(t, scheme);
            const MeshTopology linked = refinedTopology(t, r);
            const MeshTopology searched(r.pointCount, r.faces);
            QCOMPARE(linked.edgeCount(), searched.edgeCount());
            for (int e = 0; e < linked.edgeCount(); ++e) {
                const auto &a = linked.edge(e), &b = searched.edge(e);
                QVERIFY(a.v[0] == b.v[0] && a.v[1] == b.v[1]);
                QVERIFY(a.face[0] == b.face[0] && a.face[1] == b.face[1]);
            }
            QCOMPARE(linked.faces().values(), searched.faces().values());
            for (int f = 0; f < linked.faceCount(); ++f)
                QVERIFY(std::ranges::equal(linked.faceEdges(f), searched.faceEdges(f)));
            for (int v = 0; v < linked.vertexCount(); ++v) {
                QVERIFY(std::ranges::equal(linked.ring(v).edges, searched.ring(v).edges));
                QVERIFY(std::ranges::equal(linked.ring(v).faces, searched.ring(v).faces));
                QCOMPARE(linked.onBoundary(v), searched.onBoundary(v));
            }
            t = linked;
            ++compared;
        }
    }
    QCOMPARE(compared, 20);
}

#include "test_mesh.moc"
