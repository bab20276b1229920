// The mesh room against OpenSubdiv 3.5 (issue 30; Debian libosd-dev, a test-only dependency):
// the same meshes refined 1, 2, 3 times by both, with Sdc::Options::VTX_BOUNDARY_EDGE_ONLY and
// TRI_SUB_CATMARK; the points of every level and the limit positions of every vertex of the
// last level agree to 1e-9 of the bounding box's diagonal -- closed and open meshes, valences 3
// to 8, polygons that are not quads, random coordinates -- from the stencils, and at levels 1
// and 2 from the mesh's IFS with condensation; and the surface between the vertices: the IFS's
// point at random parameters of each regular face against OpenSubdiv's patch evaluation.

#include "core/mesh/Mesh.h"
#include "core/mesh/MeshIterate.h"
#include "core/mesh/MeshPieces.h"
#include "core/mesh/MeshRefine.h"

#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <QtTest>

#include "OpenSubdivReference.h"
#include "PointSets.h"
#include "TestMain.h"

#include <cmath>
#include <memory>
#include <random>

using namespace awb;
using awb::test::diagonal;
using awb::test::setDistance;
using namespace awb::test;

namespace {

// OpenSubdiv's limit surface at parameter (u, v) of each face `faces[k]` (Catmull-Clark): an
// adaptive refinement, its patch table (double precision) and patch evaluation.
Mat openSubdivSurface(const Mesh &m, const std::vector<int> &faces,
                      const std::vector<std::pair<double, double>> &uv)
{
    auto refiner = openSubdivRefiner(m, MeshScheme::CatmullClark);
    osd::Far::PatchTableFactory::Options options(4);
    options.SetPatchPrecision<double>();
    options.SetEndCapType(osd::Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
    refiner->RefineAdaptive(options.GetRefineAdaptiveOptions());
    std::unique_ptr<osd::Far::PatchTable> table(
        osd::Far::PatchTableFactory::Create(*refiner, options));
    const int refined = refiner->GetNumVerticesTotal();
    std::vector<OsdPoint> points(std::size_t(refined + table->GetNumLocalPoints()));
    for (Eigen::Index v = 0; v < m.vertices.rows(); ++v)
        for (int k = 0; k < 3; ++k)
            points[std::size_t(v)].p[k] = m.vertices(v, k);
    osd::Far::PrimvarRefinerReal<double> primvar(*refiner);
    OsdPoint *src = points.data();
    for (int level = 1; level <= refiner->GetMaxLevel(); ++level) {
        OsdPoint *dst = src + refiner->GetLevel(level - 1).GetNumVertices();
        primvar.Interpolate(level, src, dst);
        src = dst;
    }
    // The end caps' local points, from the table's own (double precision) stencils:
    // ComputeLocalPointValues<T> assumes float stencils.
    if (table->GetNumLocalPoints() > 0)
        table->GetLocalPointStencilTable<double>()->UpdateValues(points.data(),
                                                                 points.data() + refined);
    const osd::Far::PatchMap map(*table);
    Mat out(Eigen::Index(faces.size()), 3);
    for (std::size_t k = 0; k < faces.size(); ++k) {
        const auto [u, v] = uv[k];
        const osd::Far::PatchTable::PatchHandle *h = map.FindPatch(faces[k], u, v);
        double w[20];
        table->EvaluateBasis(*h, u, v, w);
        const osd::Far::ConstIndexArray cvs = table->GetPatchVertices(*h);
        out.row(Eigen::Index(k)).setZero();
        for (int i = 0; i < cvs.size(); ++i)
            for (int c = 0; c < 3; ++c)
                out(Eigen::Index(k), c) += w[i] * points[std::size_t(cvs[i])].p[c];
    }
    return out;
}

// The IFS's point at (u, v) of a face piece: the sub-face that holds (u, v) taken 40 times
// (a sub-face's parameters turn with its first corner: sub-face j starts at corner j), then
// the limit of its first corner -- within 2^-40 of the piece's size of the point.
RowVec piecePoint(const MeshPieces &pieces, const MeshPieceRoot &root, const Mat &level, double u,
                  double v)
{
    const auto rootNet = pieces.net(root);
    Mat net(Eigen::Index(rootNet.size()), 3);
    for (std::size_t i = 0; i < rootNet.size(); ++i)
        net.row(Eigen::Index(i)) = level.row(rootNet[i]);
    int type = root.type;
    for (int step = 0; step < 40; ++step) {
        const int j = u < 0.5 ? (v < 0.5 ? 0 : 3) : (v < 0.5 ? 1 : 2);
        const double uu = 2 * u, vv = 2 * v;
        switch (j) {
        case 0: u = uu; v = vv; break;
        case 1: u = vv; v = 2 - uu; break;
        case 2: u = 2 - uu; v = 2 - vv; break;
        default: u = 2 - vv; v = uu; break;
        }
        const MeshPieceType::Child &child =
            pieces.types[std::size_t(type)].children[std::size_t(j)];
        net = child.S * net;
        type = child.type;
    }
    return pieces.types[std::size_t(type)].limits.row(0) * net;
}

// A closed mesh of valences 3 to 6 with quads, triangles and pentagons: a pentagonal prism
// capped by a pyramid on top.
Mesh cappedPrism(std::mt19937 &random)
{
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    Mesh m;
    m.vertices.resize(11, 3);
    for (int k = 0; k < 5; ++k) {
        const double a = 2 * M_PI * k / 5;
        m.vertices.row(k) << std::cos(a) + jitter(random), std::sin(a) + jitter(random), 1;
        m.vertices.row(k + 5) << std::cos(a), std::sin(a) + jitter(random), -1 + jitter(random);
    }
    m.vertices.row(10) << 0, 0, 2;
    m.faces.push_back({9, 8, 7, 6, 5});  // bottom, seen from below
    for (int k = 0; k < 5; ++k) {
        m.faces.push_back({k + 5, (k + 1) % 5 + 5, (k + 1) % 5, k});
        m.faces.push_back({k, (k + 1) % 5, 10});
    }
    return m;
}


} // namespace

class TestMeshOpenSubdiv : public QObject {
    Q_OBJECT
private slots:
    void sameLevelsAndLimitsAsOpenSubdiv_data();
    void sameLevelsAndLimitsAsOpenSubdiv();
    void sameSurfaceBetweenVerticesAsOpenSubdivPatches();
};

void TestMeshOpenSubdiv::sameLevelsAndLimitsAsOpenSubdiv_data()
{
    QTest::addColumn<int>("valence");
    QTest::addColumn<bool>("loop");
    QTest::addColumn<bool>("closed");
    for (bool loop : {false, true})
        for (int n = 3; n <= 8; ++n)
            QTest::addRow("%s star, valence %d, open", loop ? "Loop" : "Catmull-Clark", n)
                << n << loop << false;
    QTest::addRow("Catmull-Clark, capped pentagonal prism") << 0 << false << true;
}

void TestMeshOpenSubdiv::sameLevelsAndLimitsAsOpenSubdiv()
{
    QFETCH(int, valence);
    QFETCH(bool, loop);
    QFETCH(bool, closed);
    std::mt19937 random(std::uint32_t(1000 + valence + 17 * loop));
    const MeshScheme scheme = loop ? MeshScheme::Loop : MeshScheme::CatmullClark;
    const Mesh mesh = closed ? cappedPrism(random) : star(valence, 3, loop, random);
    const double tol = 1e-9 * diagonal(mesh.vertices);
    double largest = 0;
    for (int levels = 1; levels <= 3; ++levels) {
        const OsdResult reference = openSubdiv(mesh, scheme, levels);
        const Mesh ours = refineMesh(mesh, scheme, levels);
        QCOMPARE(ours.vertices.rows(), reference.points.rows());
        const Mat limits = limitPositions(ours, scheme);
        // Vertex v keeps its number in both (OpenSubdiv lists the vertices' children first).
        const Eigen::Index n = mesh.vertices.rows();
        const double first = (ours.vertices.topRows(n) - reference.points.topRows(n)).norm();
        const double firstLimit = (limits.topRows(n) - reference.limits.topRows(n))
                                      .rowwise()
                                      .norm()
                                      .maxCoeff();
        const double points = setDistance(ours.vertices, reference.points);
        const double limit = setDistance(limits, reference.limits);
        QVERIFY2(first < tol && firstLimit < tol && points < tol && limit < tol,
                 qPrintable(QStringLiteral("level %1: vertices %2, their limits %3, all points "
                                           "%4, all limits %5 (tolerance %6)")
                                .arg(levels)
                                .arg(first)
                                .arg(firstLimit)
                                .arg(points)
                                .arg(limit)
                                .arg(tol)));
        // The same limits from the mesh's IFS with condensation (its vertex-limits start), at
        // levels 1 and 2 (it emits each vertex once per face: the brute-force distance of level
        // 3 would cost a minute under the sanitizers).
        double viaIfs = 0;
        if (levels <= 2) {
            const MeshPieces pieces = buildMeshPieces(mesh, scheme);
            std::vector<RowVec> rows;
            CallbackSink sink([&](const Mat &v, StartSet::Kind, const std::uint8_t *, int) {
                for (Eigen::Index r = 0; r < v.rows(); ++r)
                    rows.push_back(v.row(r));
            });
            iterateMesh(pieces, mesh.vertices, {}, levels, {&sink});
            Mat ifs(Eigen::Index(rows.size()), 3);
            for (std::size_t r = 0; r < rows.size(); ++r)
                ifs.row(Eigen::Index(r)) = rows[r];
            viaIfs = setDistance(ifs, reference.limits);
            QVERIFY2(viaIfs < tol, qPrintable(QStringLiteral("level %1: the IFS's limits %2")
                                                  .arg(levels)
                                                  .arg(viaIfs)));
        }
        largest = std::max({largest, first, firstLimit, points, limit, viaIfs});
    }
    qInfo("largest difference from OpenSubdiv: %.3g (%.3g of the diagonal)", largest,
          largest / diagonal(mesh.vertices));
}

void TestMeshOpenSubdiv::sameSurfaceBetweenVerticesAsOpenSubdivPatches()
{
    // Every face piece of open quad meshes (their boundaries included) at 5 random parameters:
    // the IFS's point against OpenSubdiv's patch evaluation of the same face.
    std::mt19937 random(2026);
    std::uniform_real_distribution<double> parameter(0.0, 1.0);
    int checked = 0;
    double largest = 0;
    for (int n : {3, 5, 6}) {
        const Mesh mesh = star(n, 3, false, random);
        const MeshPieces pieces = buildMeshPieces(mesh, MeshScheme::CatmullClark);
        if (pieces.steps != 0)  // the pieces' faces are then not the mesh's
            continue;
        const Mat level = isolatedPositions(pieces, mesh.vertices);
        std::vector<int> faces;
        std::vector<std::pair<double, double>> uv;
        std::vector<RowVec> ours;
        for (const MeshPieceRoot &root : pieces.roots) {
            if (root.face < 0)
                continue;
            for (int k = 0; k < 5; ++k) {
                const double u = parameter(random), v = parameter(random);
                faces.push_back(root.face);
                uv.emplace_back(u, v);
                ours.push_back(piecePoint(pieces, root, level, u, v));
            }
        }
        const Mat reference = openSubdivSurface(mesh, faces, uv);
        const double tol = 1e-9 * diagonal(mesh.vertices);
        for (std::size_t k = 0; k < ours.size(); ++k) {
            const double d = (ours[k] - reference.row(Eigen::Index(k))).norm();
            QVERIFY2(d < tol, qPrintable(QStringLiteral("valence %1, face %2 at (%3, %4): %5")
                                             .arg(n)
                                             .arg(faces[k])
                                             .arg(uv[k].first)
                                             .arg(uv[k].second)
                                             .arg(d)));
            largest = std::max(largest, d);
            ++checked;
        }
    }
    QVERIFY2(checked >= 100, qPrintable(QString::number(checked)));
    qInfo("%d points between vertices, largest difference from OpenSubdiv's patches: %.3g",
          checked, largest);
}

AWB_TEST_MAIN(TestMeshOpenSubdiv)
#include "test_mesh_opensubdiv.moc"
