// MainWindow: the sharp features of a mesh item edited in the window (issue 44). A click on an
// edge of the control net in the 3D view selects it (a click on a control point, the point; a
// click inside a face, the face); Item > Crease Edge… and Item > Sharpen Vertex… ask for the
// sharpness, 0 to take it away, 10 or more for an infinitely sharp crease or corner, and Item >
// Toggle Hole makes the face a hole or fills it; each is one undo step. The same edits as the
// item's "creases", "corners" and "holes" (the file, Python's update(), attractor-cli set).

#include "gui/app/MainWindow.h"

#include "core/mesh/MeshTags.h"
#include "gui/views/SurfaceView.h"
#include "model/SubdivisionMeshItem.h"

#include <QInputDialog>
#include <QStatusBar>

namespace awb {

SubdivisionMeshItem *MainWindow::currentMesh(QString *error) const
{
    auto *mesh = qobject_cast<SubdivisionMeshItem *>(currentItem());
    if (!mesh && error)
        *error = tr("Sharp features belong to mesh surfaces: choose one first");
    return mesh;
}

bool MainWindow::setSelectedEdgeSharpness(double sharpness, QString *error)
{
    SubdivisionMeshItem *mesh = currentMesh(error);
    if (!mesh)
        return false;
    const auto [a, b] = m_surface->selectedNetEdge();
    if (a < 0) {
        if (error)
            *error = tr("Click an edge of the control mesh in the 3D view first");
        return false;
    }
    return mesh->setEdgeSharpness(a, b, float(sharpness), error);
}

bool MainWindow::setSelectedVertexSharpness(double sharpness, QString *error)
{
    SubdivisionMeshItem *mesh = currentMesh(error);
    if (!mesh)
        return false;
    const int v = m_surface->selectedControlPoint();
    if (v < 0) {
        if (error)
            *error = tr("Click a vertex of the control mesh in the 3D view first");
        return false;
    }
    return mesh->setVertexSharpness(v, float(sharpness), error);
}

bool MainWindow::toggleSelectedHole(QString *error)
{
    SubdivisionMeshItem *mesh = currentMesh(error);
    if (!mesh)
        return false;
    const int f = m_surface->selectedNetFace();
    if (f < 0) {
        if (error)
            *error = tr("Click inside a face of the control mesh in the 3D view first");
        return false;
    }
    return mesh->setHole(f, !mesh->isHole(f), error);
}

void MainWindow::toggleHoleAction()
{
    QString error;
    if (!toggleSelectedHole(&error))
        statusBar()->showMessage(error, 8000);
}

namespace {

// The sharpness asked for, from `current`: 0 to 10 in steps of 0.1 (10: for ever).
bool askSharpness(QWidget *parent, const QString &title, const QString &label, float current,
                  double *out)
{
    bool ok = false;
    *out = QInputDialog::getDouble(parent, title, label, std::min(double(current), 10.0), 0.0,
                                   10.0, 2, &ok, Qt::WindowFlags(), 0.5);
    return ok;
}

} // namespace

void MainWindow::creaseEdgeDialog()
{
    QString error;
    SubdivisionMeshItem *mesh = currentMesh(&error);
    const auto [a, b] = m_surface->selectedNetEdge();
    double sharpness = 0;
    if (mesh && a >= 0
        && !askSharpness(this, tr("Crease Edge"),
                         tr("Sharpness of the edge from vertex %1 to vertex %2 (0: smooth; the "
                            "crease rules for that many levels; 10: for ever):")
                             .arg(a)
                             .arg(b),
                         mesh->edgeSharpness(a, b), &sharpness))
        return;
    if (!setSelectedEdgeSharpness(sharpness, &error))
        statusBar()->showMessage(error, 8000);
}

void MainWindow::sharpenVertexDialog()
{
    QString error;
    SubdivisionMeshItem *mesh = currentMesh(&error);
    const int v = m_surface->selectedControlPoint();
    double sharpness = 0;
    if (mesh && v >= 0
        && !askSharpness(this, tr("Sharpen Vertex"),
                         tr("Sharpness of vertex %1 (0: smooth; a corner for that many levels; "
                            "10: for ever):")
                             .arg(v),
                         mesh->vertexSharpness(v), &sharpness))
        return;
    if (!setSelectedVertexSharpness(sharpness, &error))
        statusBar()->showMessage(error, 8000);
}

} // namespace awb
