// The main window's mesh actions (issue 30/31): File > Import Mesh… and Item > Add > Mesh
// surface with the starting meshes, each a new subdivision-mesh item in one undo step.

#include "gui/app/MainWindow.h"

#include "core/mesh/MeshExamples.h"
#include "core/mesh/MeshFiles.h"
#include "gui/app/Messages.h"
#include "model/Project.h"
#include "model/SubdivisionMeshItem.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>

namespace awb {

bool MainWindow::importMesh(const QString &fileName, MeshScheme scheme, QString *error)
{
    QString why;
    auto item = std::make_unique<SubdivisionMeshItem>();
    try {
        const Mesh mesh = readMesh(QFile::encodeName(fileName).toStdString());
        if (!item->setMesh(mesh, scheme, &why))
            why = QFileInfo(fileName).fileName() + QStringLiteral(": ") + why;
    } catch (const std::exception &e) {  // the reader's message names the file and the place
        why = QString::fromStdString(e.what());
    }
    if (!why.isEmpty()) {
        if (error)
            *error = why;
        return false;
    }
    QString name = QFileInfo(fileName).completeBaseName();
    for (int k = 2; m_project->findItem(name); ++k)
        name = QStringLiteral("%1 (%2)").arg(QFileInfo(fileName).completeBaseName()).arg(k);
    item->setName(name);
    m_project->addItem(std::move(item), nullptr);
    return true;
}

void MainWindow::importMeshDialog()
{
    const QString file = QFileDialog::getOpenFileName(
        this, tr("Import Mesh"), QString(),
        tr("Meshes (*.obj *.off *.ply);;Wavefront OBJ (*.obj);;OFF (*.off);;PLY (*.ply)"));
    if (file.isEmpty())
        return;
    const QStringList schemes{tr("Catmull–Clark (any polygons)"), tr("Loop (triangles only)")};
    bool ok = false;
    const QString chosen = QInputDialog::getItem(this, tr("Import Mesh"),
                                                 tr("Subdivision scheme:"), schemes, 0, false,
                                                 &ok);
    if (!ok)
        return;
    QString error;
    if (!importMesh(file, chosen == schemes[1] ? MeshScheme::Loop : MeshScheme::CatmullClark,
                    &error))
        m_messages->error(this, tr("Import Mesh"), error);
}

void MainWindow::addMeshMenu(QMenu *add, const QString &title)
{
    // The starting meshes of every subdivision course, each with the scheme it is usually
    // shown with (Properties switches it: Loop takes triangle meshes only).
    QMenu *menu = add->addMenu(title);
    const struct {
        const char *name;
        QString text;
        MeshScheme scheme;
    } meshes[] = {
        {"cube", tr("Cube (Catmull–Clark)"), MeshScheme::CatmullClark},
        {"tetrahedron", tr("Tetrahedron (Loop)"), MeshScheme::Loop},
        {"octahedron", tr("Octahedron (Loop)"), MeshScheme::Loop},
        {"icosahedron", tr("Icosahedron (Loop)"), MeshScheme::Loop},
        {"pentagonal-prism", tr("Pentagonal prism (Catmull–Clark)"), MeshScheme::CatmullClark},
        {"grid", tr("Open grid (Catmull–Clark)"), MeshScheme::CatmullClark},
        {"diagonal-grid", tr("Grid of mixed diagonals (Loop)"), MeshScheme::Loop},
    };
    for (const auto &m : meshes) {
        QAction *a = menu->addAction(m.text);
        a->setObjectName(QStringLiteral("actionAddMesh_") + QString::fromLatin1(m.name));
        const std::string name = m.name;
        const MeshScheme scheme = m.scheme;
        const QString text = m.text;
        connect(a, &QAction::triggered, this, [this, name, scheme, text] {
            auto item = std::make_unique<SubdivisionMeshItem>();
            if (!item->setMesh(exampleMesh(name), scheme))
                return;
            item->setName(text);
            m_project->addItem(std::move(item), nullptr);
        });
    }
}

} // namespace awb
