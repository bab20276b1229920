// Meshes in the main window (issues 30 and 31): File > Import Mesh adds a mesh item in one undo
// step and the 3D view draws its limit surface; a refused file leaves the project as it was,
// with the reader's message; Item > Add > Mesh surface offers the starting meshes.
#include "core/mesh/MeshAnalysis.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Messages.h"
#include "gui/views/SurfaceView.h"
#include "model/Project.h"
#include "model/SubdivisionMeshItem.h"

#include <QAction>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"
#include "TestTime.h"

using namespace awb;

class TestMeshWindow : public QObject {
    Q_OBJECT
private slots:
    void importAddsOneUndoableItem();
    void refusedFileChangesNothing();
    void startingMeshes();

private:
    QString write(const QString &name, const QByteArray &text)
    {
        const QString path = m_dir.filePath(name);
        QFile f(path);
        f.open(QIODevice::WriteOnly);
        f.write(text);
        return path;
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
    const auto e = mesh->extraordinary();
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
    QCOMPARE(w.project()->childCount(), before);
    QCOMPARE(w.project()->undoStack()->count(), 0);
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
        const auto e = mesh->extraordinary();
        QCOMPARE(int(e.size()), c.extraordinary);
        QVERIFY(std::abs(e.front().subdominant - c.lambda) < 1e-12);
    }
    QVERIFY(w.findChild<QAction *>("actionImportMesh"));
}

AWB_TEST_MAIN(TestMeshWindow)
#include "test_mesh_window.moc"
