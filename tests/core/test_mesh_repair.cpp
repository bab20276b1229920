// The repairs of a refused mesh (core/mesh/MeshRepair.h, issue 44): each one on a mesh that
// needs exactly it, the repaired mesh passing the checks and subdividing as the mesh it stands
// for; what is not well defined (an edge of three faces, a Möbius band) left and said; a
// mesh that needs nothing unchanged.

#include "core/mesh/Mesh.h"
#include "core/mesh/MeshExamples.h"
#include "core/mesh/MeshRefine.h"
#include "core/mesh/MeshRepair.h"

#include <QtTest>

#include "TestMain.h"

#include <algorithm>

using namespace awb;

namespace {

bool accepted(const Mesh &mesh, MeshScheme scheme = MeshScheme::CatmullClark)
{
    try {
        checkMesh(mesh, scheme);
        return true;
    } catch (const InputError &) {
        return false;
    }
}

std::string joined(const std::vector<std::string> &lines)
{
    std::string s;
    for (const std::string &l : lines)
        s += l + "\n";
    return s;
}

} // namespace

class TestMeshRepair : public QObject {
    Q_OBJECT
private slots:
    void aSoundMeshIsLeftAlone();
    void flippedFacesAreTurnedToTheMajority();
    void seamsAreWelded();
    void bowtieVerticesAreSplitWithTheirTags();
    void repeatedVerticesAreNamedOnce();
    void whatIsNotWellDefinedIsSaid();
};

void TestMeshRepair::aSoundMeshIsLeftAlone()
{
    for (const Mesh &mesh : {cubeMesh(), gridMesh(4, 3, true), pentagonalPrismMesh()}) {
        MeshRepairReport report;
        const Mesh out = repairMesh(mesh, &report);
        QVERIFY(!report.changed());
        QVERIFY(report.changes.empty() && report.unrepaired.empty());
        QCOMPARE(out.faces, mesh.faces);
        QCOMPARE(out.vertices, mesh.vertices);
    }
}

void TestMeshRepair::flippedFacesAreTurnedToTheMajority()
{
    const Mesh grid = gridMesh(4, 4, false);
    Mesh flipped = grid;
    for (int f : {5, 10})
        std::reverse(flipped.faces[std::size_t(f)].begin(), flipped.faces[std::size_t(f)].end());
    QVERIFY(!accepted(flipped));
    MeshRepairReport report;
    const Mesh out = repairMesh(flipped, &report);
    QCOMPARE(report.turnedFaces, 2);
    QVERIFY2(joined(report.changes).find("faces 5, 10") != std::string::npos,
             joined(report.changes).c_str());
    QVERIFY(accepted(out));
    // The same loops up to where they start: the same surface.
    QVERIFY((limitPositions(out, MeshScheme::CatmullClark)
             - limitPositions(grid, MeshScheme::CatmullClark))
                .cwiseAbs()
                .maxCoeff()
            < 1e-14);
    // When most faces are flipped, the few others turn.
    Mesh most = grid;
    for (std::size_t f = 1; f < most.faces.size(); ++f)
        std::reverse(most.faces[f].begin(), most.faces[f].end());
    repairMesh(most, &report);
    QCOMPARE(report.turnedFaces, 1);
}

void TestMeshRepair::seamsAreWelded()
{
    // A 4 x 2 grid whose right half has its own copies of the middle column (as exporters split
    // vertices along texture seams), with a crease on a seam edge and a corner on a seam vertex.
    const Mesh grid = gridMesh(4, 2, false);
    Mesh split = grid;
    const int columns = 5;  // (w + 1) vertices per row
    std::vector<int> copyOf(std::size_t(grid.vertices.rows()), -1);
    for (int row = 0; row < 3; ++row) {
        const int v = row * columns + 2;
        copyOf[std::size_t(v)] = int(split.vertices.rows());
        split.vertices.conservativeResize(split.vertices.rows() + 1, 3);
        split.vertices.row(split.vertices.rows() - 1) = grid.vertices.row(v);
    }
    for (auto &face : split.faces) {
        double x = 0;
        for (int v : face)
            x += grid.vertices(v, 0) / double(face.size());
        if (x > grid.vertices(2, 0))
            for (int &v : face)
                if (copyOf[std::size_t(v)] >= 0)
                    v = copyOf[std::size_t(v)];
    }
    split.tags.vertices.push_back({copyOf[2], 10.0f});
    split.tags.edges.push_back({2, columns + 2, 3.0f});
    QVERIFY(accepted(split));  // two sheets side by side: sound, but not what was meant
    MeshRepairReport report;
    const Mesh out = repairMesh(split, &report);
    QCOMPARE(report.weldedVertices, 3);
    QVERIFY(accepted(out));
    for (std::size_t f = 0; f < out.faces.size(); ++f)
        QCOMPARE(out.faces[f], grid.faces[f]);
    QCOMPARE(out.tags.vertices.size(), std::size_t(1));
    QCOMPARE(out.tags.vertices[0].vertex, 2);
    QCOMPARE(out.tags.edges.size(), std::size_t(1));
    // The welded copies stay, used by no face: the limits of the grid's own vertices are the
    // welded grid's.
    Mesh tagged = grid;
    tagged.tags = out.tags;
    const Mat a = limitPositions(out, MeshScheme::CatmullClark);
    const Mat b = limitPositions(tagged, MeshScheme::CatmullClark);
    QVERIFY((a.topRows(b.rows()) - b).cwiseAbs().maxCoeff() < 1e-15);
    // Coincident boundary vertices whose weld would join three faces on an edge stay apart:
    // two fins standing on the grid's boundary edge (0, 1), each with its own copies of 0 and 1.
    Mesh fins = grid;
    for (int k = 0; k < 2; ++k) {
        const Eigen::Index base = fins.vertices.rows();
        fins.vertices.conservativeResize(base + 3, 3);
        fins.vertices.row(base) = grid.vertices.row(0);
        fins.vertices.row(base + 1) = grid.vertices.row(1);
        fins.vertices.row(base + 2) = grid.vertices.row(0) + Eigen::RowVector3d(0.5, k - 0.5, 1);
        fins.faces.push_back({int(base + 1), int(base), int(base + 2)});
    }
    QVERIFY(accepted(fins));
    repairMesh(fins, &report);
    QCOMPARE(report.weldedVertices, 0);
}

void TestMeshRepair::bowtieVerticesAreSplitWithTheirTags()
{
    // Two fans of two triangles meeting at vertex 0, tagged there.
    Mesh bowtie;
    bowtie.vertices.resize(7, 3);
    bowtie.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 0, 0, -1, -1, 0, 0, -1, 0;
    bowtie.faces = {{0, 1, 2}, {0, 2, 3}, {0, 4, 5}, {0, 5, 6}};
    bowtie.tags.vertices.push_back({0, 2.0f});
    bowtie.tags.edges.push_back({0, 5, 1.5f});
    bowtie.tags.edges.push_back({0, 2, 4.0f});
    QVERIFY(!accepted(bowtie));
    MeshRepairReport report;
    const Mesh out = repairMesh(bowtie, &report);
    QCOMPARE(report.splitVertices, 1);
    QCOMPARE(report.addedVertices, 1);
    QVERIFY2(joined(report.changes).find("vertices 0;") != std::string::npos,
             joined(report.changes).c_str());
    QVERIFY(accepted(out));
    QCOMPARE(out.vertices.rows(), Eigen::Index(8));
    QCOMPARE(out.vertices.row(7), bowtie.vertices.row(0));
    QCOMPARE(out.faces[0][0], 0);  // the first fan keeps the number
    QCOMPARE(out.faces[2][0], 7);
    QCOMPARE(out.faces[3][0], 7);
    // The corner on both copies, each crease on the copy whose edge it names.
    QCOMPARE(out.tags.vertices.size(), std::size_t(2));
    bool onFirst = false, onCopy = false;
    for (const SharpEdge &e : out.tags.edges) {
        onFirst = onFirst || (std::min(e.a, e.b) == 0 && std::max(e.a, e.b) == 2);
        onCopy = onCopy || (std::min(e.a, e.b) == 5 && std::max(e.a, e.b) == 7);
    }
    QVERIFY(onFirst && onCopy);
    QCOMPARE(out.tags.edges.size(), std::size_t(2));
    // Each fan subdivides as it would alone.
    Mesh alone;
    alone.vertices = bowtie.vertices.topRows(4);
    alone.faces = {{0, 1, 2}, {0, 2, 3}};
    alone.tags.vertices.push_back({0, 2.0f});
    alone.tags.edges.push_back({0, 2, 4.0f});
    const Mat a = limitPositions(out, MeshScheme::Loop);
    const Mat b = limitPositions(alone, MeshScheme::Loop);
    QVERIFY((a.topRows(4) - b).cwiseAbs().maxCoeff() < 1e-15);
}

void TestMeshRepair::repeatedVerticesAreNamedOnce()
{
    Mesh mesh = gridMesh(2, 1, false);  // two quads: 0 1 4 3, 1 2 5 4
    mesh.faces[0] = {0, 1, 1, 4, 3, 0};
    mesh.faces.push_back({2, 2, 5});  // nothing left of it
    mesh.tags.holes = {1, 2};
    QVERIFY(!accepted(mesh));
    MeshRepairReport report;
    const Mesh out = repairMesh(mesh, &report);
    QCOMPARE(report.collapsedFaces, 1);
    QCOMPARE(report.removedFaces, 1);
    QVERIFY(accepted(out));
    QCOMPARE(out.faces.size(), std::size_t(2));
    QCOMPARE(out.faces[0], (std::vector<int>{0, 1, 4, 3}));
    QCOMPARE(out.tags.holes, std::vector<int>{1});  // the removed face's hole went with it
}

void TestMeshRepair::whatIsNotWellDefinedIsSaid()
{
    // Three quads on one edge.
    Mesh book;
    book.vertices.resize(8, 3);
    book.vertices << 0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, 1, 0, 0, 0, 1, 0, 1, 1;
    book.faces = {{0, 2, 3, 1}, {1, 5, 4, 0}, {0, 6, 7, 1}};
    MeshRepairReport report;
    repairMesh(book, &report);
    QVERIFY2(joined(report.unrepaired).find("1 edges join three or more faces ((0, 1))")
                 != std::string::npos,
             joined(report.unrepaired).c_str());
    // A Möbius band of three quads: no orientation to turn it to.
    Mesh band;
    band.vertices.resize(6, 3);
    for (int k = 0; k < 3; ++k) {
        const double t = 2 * M_PI * k / 3;
        band.vertices.row(k) << std::cos(t), std::sin(t), -0.2;
        band.vertices.row(k + 3) << std::cos(t), std::sin(t), 0.2;
    }
    band.faces = {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 3, 0, 5}};
    repairMesh(band, &report);
    QCOMPARE(report.turnedFaces, 0);
    QVERIFY2(joined(report.unrepaired).find("cannot be oriented") != std::string::npos,
             joined(report.unrepaired).c_str());
}

AWB_TEST_MAIN(TestMeshRepair)
#include "test_mesh_repair.moc"
