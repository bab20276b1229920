// Meshes in the main window (issues 30 and 31): File > Import Mesh adds a mesh item in one undo
// step and the 3D view draws its limit surface; a refused file leaves the project as it was,
// with the reader's message; Item > Add > Mesh surface offers the starting meshes. A click on
// an extraordinary vertex shows its spectrum, Reif's verdict and its characteristic map (the
// "done when" of issue 31, driven as a user would), File > Export Mesh writes the limit mesh.
#include "core/mesh/MeshAnalysis.h"
#include "core/mesh/MeshExamples.h"
#include "core/mesh/MeshFiles.h"
#include "core/mesh/MeshPieces.h"
#include "core/mesh/VertexSpectrum.h"
#include "gui/app/ItemController.h"
#include "gui/views/AnalysisCharts.h"
#include "gui/views/MatrixView.h"
#include "gui/views/SpectrumView.h"
#include "gui/views/VertexPanel.h"
#include "model/EigenvaluePlotItem.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Messages.h"
#include "gui/views/SurfaceView.h"
#include "model/Project.h"
#include "model/SubdivisionMeshItem.h"

#include <QAction>
#include <QApplication>
#include <QInputDialog>
#include <QMessageBox>
#include <QTimer>
#include <QFile>
#include <QPainter>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <sstream>

#include "ImageCompare.h"
#include "TestFiles.h"
#include "TestMain.h"
#include "TestTime.h"

using namespace awb;

class TestMeshWindow : public QObject {
    Q_OBJECT
private slots:
    void importAddsOneUndoableItem();
    void refusedFileChangesNothing();
    void refusedMeshIsRepairedOnRequest();
    void startingMeshes();
    void extraordinaryVertexInTheWindow_data();
    void extraordinaryVertexInTheWindow();
    void exportMeshWritesTheLimitMesh();
    void creaseAnEdgeByClickingIt();
    void aClickedFaceBecomesAHole();

private:
    QString write(const QString &name, const QByteArray &text)
    {
        return awb::test::writeFile(m_dir, name, text);
    }
    // The window shown with an imported cube (Catmull-Clark) current and drawn.
    void showCube(MainWindow &w, SubdivisionMeshItem **item)
    {
        w.resize(1200, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        std::ostringstream obj;
        writeObj(obj, cubeMesh(), "a cube");
        QString error;
        QVERIFY2(w.importMesh(write("cube.obj", QByteArray::fromStdString(obj.str())),
                              MeshScheme::CatmullClark, &error),
                 qPrintable(error));
        *item = qobject_cast<SubdivisionMeshItem *>(w.project()->findItem("cube"));
        QVERIFY(*item);
        w.setCurrentItem(*item);
        SurfaceView *view = w.surfaceView();
        QTRY_VERIFY_WITH_TIMEOUT(view->isVisible() && !view->isRendering()
                                     && view->mesh().size() > 0,
                                 awb::test::ms(30000));
    }
    QTemporaryDir m_dir;
};

void TestMeshWindow::importAddsOneUndoableItem()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    const int before = w.project()->childCount();
    // An octahedron written as OFF: under Loop its six vertices have valence 4.
    const QString file = write("octahedron.off", "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n"
                                                 "0 0 1\n0 0 -1\n3 0 2 4\n3 2 1 4\n3 1 3 4\n"
                                                 "3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n");
    QString error;
    QVERIFY2(w.importMesh(file, MeshScheme::Loop, &error), qPrintable(error));
    QCOMPARE(w.project()->childCount(), before + 1);
    QCOMPARE(w.project()->undoStack()->count(), 1);
    auto *mesh = qobject_cast<SubdivisionMeshItem *>(w.project()->findItem("octahedron"));
    QVERIFY(mesh);
    QVERIFY(mesh->scheme() == MeshScheme::Loop);
    const auto e = *mesh->extraordinary();
    QCOMPARE(int(e.size()), 6);
    QVERIFY(std::abs(e.front().subdominant - 0.375) < 1e-12);  // Loop, n = 4: 3/8
    // Shown and drawn by the 3D view.
    w.setCurrentItem(mesh);
    SurfaceView *view = w.surfaceView();
    QVERIFY(QTest::qWaitFor([view] { return !view->isRendering() && view->mesh().size() > 0; },
                            awb::test::ms(30000)));
    QCOMPARE(view->controlPointCount(), 6);
    // A second import of the same file gets a name of its own.
    QVERIFY(w.importMesh(file, MeshScheme::CatmullClark));
    QVERIFY(w.project()->findItem("octahedron (2)"));
    w.project()->undoStack()->undo();
    w.project()->undoStack()->undo();
    QCOMPARE(w.project()->childCount(), before);
}

void TestMeshWindow::refusedFileChangesNothing()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    const int before = w.project()->childCount();
    QString error;
    QVERIFY(!w.importMesh(write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"),
                          MeshScheme::CatmullClark, &error));
    QVERIFY2(error.contains("range.obj, line 4") && error.contains("out of range"),
             qPrintable(error));
    QVERIFY(!w.importMesh(write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"),
                          MeshScheme::Loop, &error));
    QVERIFY2(error.contains("triangles only"), qPrintable(error));
    // A fan whose centre has valence 514: refused at import, as the CLI refuses it.
    Mesh fan;
    fan.vertices = Mat::Zero(515, 3);
    for (int k = 0; k <= 513; ++k)
        fan.vertices.row(k + 1) << std::cos(k * 0.012), std::sin(k * 0.012), 0;
    for (int k = 0; k < 513; ++k)
        fan.faces.push_back({0, k + 1, k + 2});
    QVERIFY(!w.importMesh("fan.obj", fan, MeshScheme::Loop, &error));
    QVERIFY2(error.contains("fan.obj: vertex 0 has 514 edges; valences above 512"),
             qPrintable(error));
    QCOMPARE(w.project()->childCount(), before);
    QCOMPARE(w.project()->undoStack()->count(), 0);
}

void TestMeshWindow::refusedMeshIsRepairedOnRequest()
{
    // Two triangles that meet at one vertex only (a bowtie): File > Import Mesh says how the
    // mesh would be drawn (as OpenSubdiv draws it: the vertex a corner) and offers the repair
    // instead; Cancel changes nothing, No imports it as it is and says so, Yes imports the
    // repaired mesh and says what was changed.
    const QString file = write("bowtie.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\n"
                                             "f 1 2 3\nf 1 4 5\n");
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    const int before = w.project()->childCount();
    const auto acceptScheme = [] {
        QTimer::singleShot(0, [] {  // the scheme question is modal: take its default, Loop
            auto *dialog = qobject_cast<QInputDialog *>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            QCOMPARE(dialog->textValue(), QStringLiteral("Loop (triangles only)"));
            dialog->accept();
        });
    };
    messages.answer = QMessageBox::Cancel;
    acceptScheme();
    w.importMeshFile(file);
    QCOMPARE(messages.questions.size(), 1);
    QVERIFY2(messages.questions[0].contains("The mesh is non-manifold: 1 vertices (0), "
                                            "drawn as OpenSubdiv draws them: the vertices "
                                            "as corners")
                 && messages.questions[0].contains("Repair it instead?")
                 && messages.questions[0].contains("split, one vertex per fan (vertices 0;"),
             qPrintable(messages.questions[0]));
    QCOMPARE(w.project()->childCount(), before);
    QVERIFY(messages.errors.isEmpty());
    messages.answer = QMessageBox::No;
    acceptScheme();
    w.importMeshFile(file);
    QCOMPARE(w.project()->childCount(), before + 1);
    const auto *asIs = qobject_cast<const SubdivisionMeshItem *>(
        w.project()->child(w.project()->childCount() - 1));
    QVERIFY(asIs);
    QCOMPARE(asIs->inputs().vertices.size(), std::size_t(5));
    QCoreApplication::processEvents();  // the note comes queued
    QVERIFY2(messages.infos.join('\n').contains("The mesh is non-manifold"),
             qPrintable(messages.infos.join('\n')));
    messages.answer = QMessageBox::Yes;
    acceptScheme();
    w.importMeshFile(file);
    QCOMPARE(w.project()->childCount(), before + 2);
    const auto *item = qobject_cast<const SubdivisionMeshItem *>(
        w.project()->child(w.project()->childCount() - 1));
    QVERIFY(item);
    QCOMPARE(item->inputs().vertices.size(), std::size_t(6));  // vertex 0 and its copy, 5
    QCOMPARE(item->inputs().faces[1][0], 5);
    QCoreApplication::processEvents();
    QVERIFY2(messages.infos.join('\n').contains("Repaired:"), qPrintable(messages.infos.join('\n')));
    QCOMPARE(w.project()->undoStack()->count(), 2);
}

void TestMeshWindow::startingMeshes()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    const struct {
        const char *action;
        int extraordinary;
        double lambda;
    } cases[] = {{"actionAddMesh_cube", 8, 0.410097050800551},
                 {"actionAddMesh_icosahedron", 12, 0.452254248593737},
                 {"actionAddMesh_pentagonal-prism", 12, 0.410097050800551}};
    for (const auto &c : cases) {
        auto *action = w.findChild<QAction *>(QString::fromLatin1(c.action));
        QVERIFY2(action, c.action);
        const int before = w.project()->childCount();
        action->trigger();
        QCOMPARE(w.project()->childCount(), before + 1);
        auto *mesh = qobject_cast<SubdivisionMeshItem *>(w.project()->child(before));
        QVERIFY(mesh);
        const auto e = *mesh->extraordinary();
        QCOMPARE(int(e.size()), c.extraordinary);
        QVERIFY(std::abs(e.front().subdominant - c.lambda) < 1e-12);
    }
    QVERIFY(w.findChild<QAction *>("actionImportMesh"));
}

void TestMeshWindow::extraordinaryVertexInTheWindow_data()
{
    QTest::addColumn<QString>("mesh");
    QTest::addColumn<int>("scheme");
    QTest::addColumn<int>("valence");
    QTest::addColumn<double>("lambda");
    QTest::addColumn<int>("ring");
    // Stam 1998: (5 + cos(2 pi/3) + cos(pi/3) sqrt(2 (9 + cos(2 pi/3)))) / 16 at valence 3;
    // Loop: 3/8 + cos(2 pi/5) / 4 at valence 5.
    QTest::newRow("Catmull-Clark cube") << "cube" << int(MeshScheme::CatmullClark) << 3
                                        << 0.410097050800551 << 19;
    QTest::newRow("Loop icosahedron") << "icosahedron" << int(MeshScheme::Loop) << 5
                                      << 0.452254248593737 << 16;
}

void TestMeshWindow::extraordinaryVertexInTheWindow()
{
    QFETCH(QString, mesh);
    QFETCH(int, scheme);
    QFETCH(int, valence);
    QFETCH(double, lambda);
    QFETCH(int, ring);
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    w.resize(1400, 900);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    // The user's OBJ file (the starting mesh written as any modeller would).
    std::ostringstream obj;
    writeObj(obj, exampleMesh(mesh.toStdString()), "a test mesh");
    const QString file = write(mesh + ".obj", QByteArray::fromStdString(obj.str()));
    QString error;
    QVERIFY2(w.importMesh(file, MeshScheme(scheme), &error), qPrintable(error));
    auto *item = qobject_cast<SubdivisionMeshItem *>(w.project()->findItem(mesh));
    QVERIFY(item);
    w.setCurrentItem(item);
    SurfaceView *view = w.surfaceView();
    QTRY_VERIFY_WITH_TIMEOUT(view->isVisible() && !view->isRendering() && view->mesh().size() > 0,
                             awb::test::ms(30000));
    const auto list = item->extraordinary();
    QCOMPARE(view->markerCount(), int(list->size()));

    // Drag a vertex: one undo step, undone.
    const int steps = w.project()->undoStack()->count();
    const Point original = item->controlPoints(0)[0];
    const QPoint grab = view->controlPointScreen(0).toPoint();
    QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, grab);
    QTest::mouseMove(view, grab + QPoint(0, -12));
    QTest::mouseMove(view, grab + QPoint(0, -30));
    QTest::qWait(30);
    QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, grab + QPoint(0, -30));
    QVERIFY(!(item->controlPoints(0)[0] == original));
    QCOMPARE(w.project()->undoStack()->count(), steps + 1);
    w.project()->undoStack()->undo();
    QCOMPARE(item->controlPoints(0)[0], original);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isRendering() && view->isFullDetail(), awb::test::ms(30000));
    // The limit surface as the attractor, compared with its reference (tolerant: the CPU
    // renderer's rasterisation and shading may change a little, the figure must not).
    const QImage surface = view->renderImage(QSize(400, 300), false);
    QVERIFY(test::drawnPixels(surface) > 400 * 300 / 10);
    const QImage surfaceRef =
        test::reference(QStringLiteral("mesh-surface-%1.png").arg(mesh), surface);
    QVERIFY2(!surfaceRef.isNull(), "reference image missing: run with AWB_REGENERATE_REFERENCES=1");
    const test::ImageDiff sd = test::compare(surfaceRef, surface);
    QVERIFY2(sd.coverageMismatch < 0.05 && sd.meanColour < 30,
             qPrintable(QStringLiteral("surface: coverage %1, colour %2")
                            .arg(sd.coverageMismatch)
                            .arg(sd.meanColour)));

    // Click an extraordinary vertex's marker (one away from every handle: a handle under the
    // mouse is grabbed instead).
    int chosen = -1;
    for (int k = 0; k < view->markerCount() && chosen < 0; ++k) {
        bool free = (*list)[std::size_t(k)].valence == valence;
        for (int i = 0; i < view->controlPointCount(); ++i) {
            const QPointF d = view->controlPointScreen(i) - view->markerScreen(k);
            free = free && QPointF::dotProduct(d, d) > 14.0 * 14.0;
        }
        const QPointF at = view->markerScreen(k);
        free = free && view->rect().contains(at.toPoint()) && view->markerFacing(k);
        if (free)
            chosen = k;
    }
    QVERIFY2(chosen >= 0, "every marker sits under a handle");
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, view->markerScreen(chosen).toPoint());
    QCOMPARE(w.controller()->focusedVertex(), chosen);
    QCOMPARE(view->selectedMarker(), chosen);
    // Issue 47: markers on the far side of the closed surface are hidden (not clickable
    // through it); the seen ones are exactly those whose outward normal faces the viewer.
    int hiddenCount = 0;
    for (int k = 0; k < view->markerCount(); ++k) {
        const ExtraordinaryVertex &e = (*list)[std::size_t(k)];
        const Eigen::Vector3d centre = e.limit.transpose() / std::max(1e-12, e.limit.norm());
        // Starting meshes are centred at the origin: the outward normal points away from it.
        QVERIFY2(e.normal.dot(centre) > 0.5, qPrintable(QString::number(k)));
        hiddenCount += view->markerFacing(k) ? 0 : 1;
    }
    QVERIFY2(hiddenCount >= 1 && hiddenCount < view->markerCount(),
             qPrintable(QString::number(hiddenCount)));
    // A click on a marker selects its vertex even where a control point lies under it (the
    // view zoomed far out: every handle and marker within a few pixels); the point stays.
    view->zoomBy(0.08);
    int other = -1;
    for (int k = 0; k < view->markerCount() && other < 0; ++k)
        if (k != chosen && view->markerFacing(k)
            && (*list)[std::size_t(k)].valence == valence)
            other = k;
    QVERIFY(other >= 0);
    const std::vector<Point> before = item->controlPoints(0);
    const int stepsBefore = w.project()->undoStack()->count();
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, view->markerScreen(other).toPoint());
    QCOMPARE(w.controller()->focusedVertex(), other);
    QVERIFY(item->controlPoints(0) == before);
    QCOMPARE(w.project()->undoStack()->count(), stepsBefore);
    view->zoomBy(1 / 0.08);
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, view->markerScreen(chosen).toPoint());
    QCOMPARE(w.controller()->focusedVertex(), chosen);
    w.controller()->refreshNow();
    // Spectrum dock: the eigenvalues of the vertex's local subdivision matrix, lambda marked.
    const QList<MapSpectrum> maps = w.spectrumView()->maps();
    QCOMPARE(maps.size(), 1);
    QVERIFY2(std::abs(maps.front().subdominant.modulus - lambda) < 1e-9,
             qPrintable(QString::number(maps.front().subdominant.modulus, 'g', 17)));
    QCOMPARE(maps.front().spectrum.values.size(), std::size_t(ring));
    // Matrices dock: that matrix, ring x ring.
    QCOMPARE(w.matrixView()->matrixCount(), 1);
    QCOMPARE(w.matrixView()->matrices().front().rows(), Eigen::Index(ring));
    // Analysis dock, Vertex tab: Reif's verdict with the numbers, the characteristic map.
    VertexPanel *panel = w.vertexPanel();
    QCOMPARE(w.analysisCharts()->tabs()->currentWidget(), panel);
    QVERIFY(panel->hasVertex());
    const QString verdict = panel->verdictText();
    QVERIFY2(verdict.contains(QStringLiteral("λ = %1").arg(lambda, 0, 'g', 6))
                 && verdict.contains(QStringLiteral("C¹ at the vertex"))
                 && verdict.contains(QStringLiteral("valence %1").arg(valence)),
             qPrintable(verdict));
    const CharacteristicMapView *map = panel->mapView();
    QCOMPARE(map->valence(), valence);
    QCOMPARE(int(map->map().cells.size()), 64 * valence);
    QCOMPARE(map->foldedCells(), 0);
    QVERIFY(map->map().injective());
    // The picture: the n-fold star, compared with its reference (tolerant).
    QImage picture(300, 300, QImage::Format_RGB32);
    {
        QPainter p(&picture);
        map->paintMap(p, QRectF(0, 0, 300, 300));
    }
    const QString name = QStringLiteral("characteristic-map-%1.png").arg(mesh);
    const QImage ref = test::reference(name, picture);
    QVERIFY2(!ref.isNull(), "reference image missing: run with AWB_REGENERATE_REFERENCES=1");
    const test::ImageDiff d = test::compare(ref, picture);
    QVERIFY2(d.coverageMismatch < 0.03 && d.meanColour < 20,
             qPrintable(QStringLiteral("coverage %1, colour %2")
                            .arg(d.coverageMismatch)
                            .arg(d.meanColour)));
    // The valence explorer marks this mesh's valence.
    const std::vector<int> marked = w.valenceChart()->markedValences();
    QVERIFY(std::find(marked.begin(), marked.end(), valence) != marked.end());
    // An eigenvalue plot item of the vertex: kept in the project, one undo step.
    const int at = w.project()->undoStack()->index();
    Item *plot = w.controller()->addVertexPlot();
    QVERIFY(plot);
    QCOMPARE(w.project()->undoStack()->index(), at + 1);
    QCOMPARE(plot->parentItem(), item);
    const auto data = qobject_cast<EigenvaluePlotItem *>(plot)->eigenvalues();
    QVERIFY(data);
    QVERIFY(std::abs(data->subdominants.front().modulus - lambda) < 1e-9);
    // Another item: the focus goes, the docks show that item again.
    w.setCurrentItem(plot);
    QCOMPARE(w.controller()->focusedVertex(), -1);
}

void TestMeshWindow::exportMeshWritesTheLimitMesh()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    QString error;
    // Not a mesh: refused by name.
    QVERIFY(!w.exportMesh(m_dir.filePath("x.obj"), 1, &error));
    QVERIFY2(error.contains("mesh surface"), qPrintable(error));
    w.findChild<QAction *>("actionAddMesh_cube")->trigger();
    auto *cube = qobject_cast<SubdivisionMeshItem *>(
        w.project()->child(w.project()->childCount() - 1));
    QVERIFY(cube);
    w.setCurrentItem(cube);
    const QString out = m_dir.filePath("cube-limit.obj");
    QVERIFY2(w.exportMesh(out, 2, &error), qPrintable(error));
    const Mesh back = readMesh(QFile::encodeName(out).toStdString());
    // Two Catmull-Clark steps of the cube: 98 vertices, 96 quads, all at their limit positions
    // (inside the cube, on the sphere-like surface: none at a corner of the net).
    QCOMPARE(back.vertices.rows(), Eigen::Index(98));
    QCOMPARE(int(back.faces.size()), 96);
    QVERIFY(back.vertices.cwiseAbs().maxCoeff() < 1.0 - 1e-3);
    QVERIFY(!w.exportMesh(out, 9, &error));
    QVERIFY2(error.contains("0 to 8"), qPrintable(error));
    QVERIFY(w.findChild<QAction *>("actionExportMesh"));
}

void TestMeshWindow::creaseAnEdgeByClickingIt()
{
    // Issue 44: a click on an edge of the control mesh selects it, Item > Crease Edge… (its
    // function here, without the dialog) makes it infinitely sharp in one undo step, the view
    // draws the crease, and the analysis sees the darts at its ends; a click on a vertex and
    // Sharpen Vertex… make a corner.
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    SubdivisionMeshItem *item = nullptr;
    showCube(w, &item);
    QVERIFY(item);
    SurfaceView *view = w.surfaceView();
    QString error;
    // Nothing selected: the action says what to do.
    QVERIFY(!w.setSelectedEdgeSharpness(10, &error));
    QVERIFY2(error.contains("Click an edge"), qPrintable(error));
    // The midpoint of the first face's first edge, on screen; a click there (no drag).
    const int a = item->inputs().faces[0][0], b = item->inputs().faces[0][1];
    const QPoint mid = ((view->controlPointScreen(a) + view->controlPointScreen(b)) / 2).toPoint();
    QSignalSpy clicked(view, &SurfaceView::netEdgeClicked);
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, mid);
    QCOMPARE(clicked.count(), 1);
    QCOMPARE(view->selectedNetEdge(), (std::pair<int, int>{std::min(a, b), std::max(a, b)}));
    const int steps = w.project()->undoStack()->count();
    QVERIFY2(w.setSelectedEdgeSharpness(10, &error), qPrintable(error));
    QCOMPARE(w.project()->undoStack()->count(), steps + 1);
    QCOMPARE(item->edgeSharpness(a, b), 10.0f);
    QCOMPARE(int(item->inputs().tags.edges.size()), 1);
    int darts = 0;
    for (const ExtraordinaryVertex &e : *item->extraordinary())
        darts += e.rule == "dart" ? 1 : 0;
    QCOMPARE(darts, 2);
    // The crease is drawn (once the views refresh): the pixels along the edge turn the crease
    // colour.
    const auto creaseDrawn = [&] {
        const QImage shot = view->grab().toImage();
        for (int dx = -3; dx <= 3; ++dx)
            for (int dy = -3; dy <= 3; ++dy) {
                const QColor c = shot.pixelColor(mid + QPoint(dx, dy));
                if (c.red() > 150 && c.green() < 140 && c.blue() < 90)
                    return true;
            }
        return false;
    };
    QTRY_VERIFY_WITH_TIMEOUT(creaseDrawn(), awb::test::ms(10000));
    // Smooth again (0 removes it), and undone back to the crease.
    QVERIFY(w.setSelectedEdgeSharpness(0, &error));
    QVERIFY(item->inputs().tags.edges.empty());
    w.project()->undoStack()->undo();
    QCOMPARE(item->edgeSharpness(a, b), 10.0f);
    // A vertex: pressed and released on it (no move), then a corner of sharpness 2.
    const QPoint at = view->controlPointScreen(a).toPoint();
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, at);
    QCOMPARE(view->selectedControlPoint(), a);
    QCOMPARE(view->selectedNetEdge().first, -1);
    QVERIFY2(w.setSelectedVertexSharpness(2, &error), qPrintable(error));
    QCOMPARE(item->vertexSharpness(a), 2.0f);
    QVERIFY(!w.setSelectedVertexSharpness(-1, &error));
    QVERIFY2(error.contains("0 or more"), qPrintable(error));
}

void TestMeshWindow::aClickedFaceBecomesAHole()
{
    // Issue 44: a click inside a face of the control mesh (away from its edges and points)
    // selects the front face there; Item > Toggle Hole (its function here) makes it a hole in
    // one undo step, and fills it again; the hole leaves the surface (fewer pieces drawn).
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    SubdivisionMeshItem *item = nullptr;
    showCube(w, &item);
    QVERIFY(item);
    SurfaceView *view = w.surfaceView();
    QString error;
    QVERIFY(!w.toggleSelectedHole(&error));
    QVERIFY2(error.contains("Click inside a face"), qPrintable(error));
    // The centre on screen of each face in turn: the first click that selects that very face
    // (a face seen from the front).
    QSignalSpy clicked(view, &SurfaceView::netFaceClicked);
    int face = -1;
    for (int f = 0; f < int(item->inputs().faces.size()) && face < 0; ++f) {
        QPointF centre;
        for (int v : item->inputs().faces[std::size_t(f)])
            centre += view->controlPointScreen(v) / double(item->inputs().faces[std::size_t(f)].size());
        QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, centre.toPoint());
        if (view->selectedNetFace() == f)
            face = f;
    }
    QVERIFY(face >= 0);
    QVERIFY(clicked.count() >= 1);
    QCOMPARE(clicked.last().at(0).toInt(), face);
    const int steps = w.project()->undoStack()->count();
    const auto points = [&] {
        const auto d = item->derivedIfs();
        return d ? d->pointCount(item->coreStartSet(*d), 3) : 0.0;
    };
    const double before = points();
    QVERIFY2(w.toggleSelectedHole(&error), qPrintable(error));
    QCOMPARE(w.project()->undoStack()->count(), steps + 1);
    QVERIFY(item->isHole(face));
    QCOMPARE(item->inputs().tags.holes, std::vector<int>{face});
    QVERIFY2(points() < before, qPrintable(QString("%1 of %2").arg(points()).arg(before)));
    QVERIFY(w.toggleSelectedHole(&error));
    QVERIFY(!item->isHole(face));
    w.project()->undoStack()->undo();
    QVERIFY(item->isHole(face));
    QVERIFY(!item->setHole(99, true, &error));
    QVERIFY2(error.contains("face 99: the mesh has 6 faces"), qPrintable(error));
}

AWB_TEST_MAIN(TestMeshWindow)
#include "test_mesh_window.moc"
