// The main window's item actions: Item > Add (every kind; surfaces by scheme and layout; mesh
// surfaces from the starting meshes), Duplicate, Delete, and File > Import Mesh… -- each one
// undo step.

#include "gui/app/MainWindow.h"

#include "core/ifs/SurfaceIfs.h"
#include "core/mesh/MeshExamples.h"
#include "core/mesh/MeshFiles.h"
#include "core/mesh/MeshRepair.h"
#include "core/mesh/MeshSheets.h"
#include "gui/app/ItemController.h"
#include "gui/app/Messages.h"
#include "model/EigenvaluePlotItem.h"
#include "model/FileWriting.h"
#include "model/ItemRegistry.h"
#include "model/Project.h"
#include "model/ProjectIO.h"
#include "model/SubdivisionMeshItem.h"
#include "model/SubdivisionSurfaceItem.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QJsonArray>
#include <QMenu>
#include <QStatusBar>

namespace awb {

void MainWindow::addItem(const QString &type)
{
    std::unique_ptr<Item> item = ItemRegistry::instance().create(type);
    if (!item)
        return;
    if (auto *a = qobject_cast<AttractorItem *>(item.get())) {
        AlgorithmSpec alg = a->algorithm();
        alg.depth = m_preferences.defaultDepth;
        if (!a->checkAlgorithm(alg))
            a->setAlgorithm(alg);
    }
    // A new eigenvalue plot analyses the item drawn now and sits under it in the tree.
    if (auto *plot = qobject_cast<EigenvaluePlotItem *>(item.get())) {
        // Of the extraordinary vertex clicked in a mesh, when there is one (issue 31).
        if (m_controller->focusedVertex() >= 0 && m_controller->addVertexPlot())
            return;
        if (AttractorItem *source = m_controller->drawnItem()) {
            plot->setSource(source->name());
            plot->setName(tr("Spectra of %1").arg(source->name()));
            m_project->addItem(std::move(item), source);
            return;
        }
    }
    m_project->addItem(std::move(item), nullptr);
}

void MainWindow::addSurfaceMenu(QMenu *add, const QString &title)
{
    // One entry per scheme and layout: a surface's net is fixed by both, so they are chosen
    // up front; the user then drags the default net into shape.
    QMenu *menu = add->addMenu(title);
    const QStringList schemes{tr("Bicubic B-spline"), tr("Loop (box spline)"),
                              tr("Kobbelt √3")};
    const SurfaceSchemeSpec::Kind kinds[] = {SurfaceSchemeSpec::Kind::Bicubic,
                                             SurfaceSchemeSpec::Kind::Loop,
                                             SurfaceSchemeSpec::Kind::Sqrt3};
    for (int k = 0; k < 3; ++k)
        for (const QString &layout : SurfaceSchemeSpec::layoutNames(kinds[k])) {
            QAction *a = menu->addAction(tr("%1, %2 layout").arg(schemes[k], layout));
            const SurfaceSchemeSpec spec{kinds[k], layout};
            a->setObjectName(QStringLiteral("actionAddSurface_%1_%2")
                                 .arg(SurfaceSchemeSpec::kindNames().value(k), layout));
            // The first entry is the kind's plain "add" action, as for the other kinds.
            if (menu->actions().size() == 1)
                a->setObjectName(QStringLiteral("actionAdd_")
                                 + SubdivisionSurfaceItem::staticType());
            connect(a, &QAction::triggered, this, [this, spec] { addSurface(spec); });
        }
}

void MainWindow::addSurface(const SurfaceSchemeSpec &scheme)
{
    auto item = std::make_unique<SubdivisionSurfaceItem>();
    if (!item->setScheme(scheme))
        return;
    item->setName(tr("%1 surface").arg(scheme.layout));
    AlgorithmSpec alg = item->algorithm();
    alg.depth = std::min(m_preferences.defaultDepth, 7);
    if (!item->checkAlgorithm(alg))
        item->setAlgorithm(alg);
    // Start from the polygon of limit points at the domain's corners: its images tile the
    // surface from the first level on (a triangle of control points only converges to it).
    if (const auto d = item->derivedIfs(); d && d->surface
                                           && d->surface->cornerLimitPoints.rows() >= 3) {
        const Mat &c = d->surface->cornerLimitPoints;
        StartSetSpec start;
        start.kind = c.rows() == 3 ? StartSetSpec::Kind::Triangle : StartSetSpec::Kind::Polygon;
        start.points.clear(); // not the default set's point
        for (Eigen::Index r = 0; r < c.rows(); ++r)
            start.points.push_back({c(r, 0), c(r, 1), c(r, 2)});
        item->setStartSet(start);
    }
    m_project->addItem(std::move(item), nullptr);
}

void MainWindow::duplicateItem()
{
    if (!m_current)
        return;
    QJsonObject root = ProjectIO::toJson(*m_project);
    root[QStringLiteral("items")] = QJsonArray{ProjectIO::itemToJson(*m_current)};
    ProjectData data;
    QString error;
    if (!ProjectIO::parseRoot(root, tr("duplicate"), &data, &error) || data.items.empty()) {
        m_messages->error(this, tr("Duplicate Item"), error);
        return;
    }
    m_project->addItem(std::move(data.items.front()), m_current->parentItem(),
                       m_project->rowOf(m_current) + 1);
}

void MainWindow::deleteItem()
{
    if (m_current)
        m_project->removeItem(m_current);
}

bool MainWindow::importMesh(const QString &fileName, MeshScheme scheme, QString *error)
{
    Mesh mesh;
    try {
        mesh = readMesh(QFile::encodeName(fileName).toStdString());
    } catch (const std::exception &e) {  // the reader's message names the file and the place
        if (error)
            *error = QString::fromStdString(e.what());
        return false;
    }
    return importMesh(fileName, mesh, scheme, error);
}

bool MainWindow::importMesh(const QString &fileName, const Mesh &mesh, MeshScheme scheme,
                            QString *error)
{
    QString why;
    auto item = std::make_unique<SubdivisionMeshItem>();
    try {
        // What every view and command would refuse (a valence above the pieces' limit, a
        // prelude too long) is refused here, as attractor-cli import-mesh refuses it.
        if (!item->setMesh(mesh, scheme, &why) || !(why = item->derivedError()).isEmpty())
            why = QFileInfo(fileName).fileName() + QStringLiteral(": ") + why;
    } catch (const std::exception &e) {
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
    if (!file.isEmpty())
        importMeshFile(file);
}

void MainWindow::importMeshFile(const QString &file)
{
    // Read first: a file that cannot be read is said before any question, and the question
    // proposes the scheme made for the mesh.
    Mesh mesh;
    std::vector<std::string> notes;  // what the file holds that the mesh does not keep
    try {
        mesh = readMesh(QFile::encodeName(file).toStdString(), &notes);
    } catch (const std::exception &e) {
        m_messages->error(this, tr("Import Mesh"), QString::fromStdString(e.what()));
        return;
    }
    const QStringList schemes{tr("Catmull–Clark (any polygons)"), tr("Loop (triangles only)")};
    const bool triangles = suggestedScheme(mesh) == MeshScheme::Loop;
    const QString label =
        triangles ? tr("All %1 faces are triangles: Loop keeps them triangles (Catmull–Clark "
                       "would make each one three quads around a new valence-3 vertex).\n\n"
                       "Subdivision scheme:")
                        .arg(mesh.faces.size())
                  : tr("Subdivision scheme:");
    bool ok = false;
    const QString chosen = QInputDialog::getItem(this, tr("Import Mesh"), label, schemes,
                                                 triangles ? 1 : 0, false, &ok);
    if (!ok)
        return;
    const MeshScheme scheme = chosen == schemes[1] ? MeshScheme::Loop : MeshScheme::CatmullClark;
    // A non-manifold mesh is drawn as OpenSubdiv draws it (MeshSheets.h); where the repairs
    // would make it manifold instead (flipped faces, bowties, seams), the user chooses.
    std::optional<ManifoldSheets> sheets;
    try {
        sheets = manifoldSheets(mesh);
    } catch (const std::exception &) {  // a bad tag: importMesh names it below
    }
    if (sheets) {
        MeshRepairReport report;
        const Mesh repaired = repairMesh(mesh, &report);
        const QString drawn = QString::fromStdString(describe(*sheets));
        if (report.changed()) {
            QStringList changes;
            for (const std::string &c : report.changes)
                changes << QStringLiteral("• ") + QString::fromStdString(c);
            const auto answer = m_messages->question(
                this, tr("Import Mesh"),
                tr("The mesh is %1.\n\nRepair it instead? These changes are well defined:\n\n"
                   "%2\n\nNo imports it as it is.")
                    .arg(drawn, changes.join(QLatin1Char('\n'))),
                QMessageBox::Yes | QMessageBox::No | QMessageBox::Cancel, QMessageBox::Yes);
            if (answer == QMessageBox::Cancel)
                return;
            if (answer == QMessageBox::Yes) {
                mesh = repaired;
                for (const std::string &c : report.changes)
                    notes.push_back(
                        tr("Repaired: %1").arg(QString::fromStdString(c)).toStdString());
                sheets = std::nullopt;
                try {
                    sheets = manifoldSheets(mesh);
                } catch (const std::exception &) {
                }
            }
        }
        if (sheets)
            notes.push_back(tr("The mesh is %1.")
                                .arg(QString::fromStdString(describe(*sheets)))
                                .toStdString());
    }
    QString error;
    if (!importMesh(file, mesh, scheme, &error)) {
        // Refused: offer the repairs that are well defined (MeshRepair.h), saying what they
        // would change, and import the repaired mesh on Yes.
        MeshRepairReport report;
        const Mesh repaired = repairMesh(mesh, &report);
        if (!report.changed()) {
            m_messages->error(this, tr("Import Mesh"), error);
            return;
        }
        QStringList changes;
        for (const std::string &c : report.changes)
            changes << QStringLiteral("• ") + QString::fromStdString(c);
        for (const std::string &c : report.unrepaired)
            changes << QStringLiteral("• ") + tr("Not repaired: %1").arg(QString::fromStdString(c));
        const auto answer = m_messages->question(
            this, tr("Import Mesh"),
            tr("%1\n\nRepair the mesh? These changes are well defined:\n\n%2")
                .arg(error, changes.join(QLatin1Char('\n'))),
            QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
        if (answer != QMessageBox::Yes)
            return;
        if (!importMesh(file, repaired, scheme, &error)) {
            m_messages->error(this, tr("Import Mesh"), tr("Even repaired: %1").arg(error));
            return;
        }
        for (const std::string &c : report.changes)
            notes.push_back(tr("Repaired: %1").arg(QString::fromStdString(c)).toStdString());
    }
    if (!notes.empty()) {
        // Said once the window shows the new item, as the other imports' losses are.
        QStringList list;
        for (const std::string &n : notes)
            list << QString::fromStdString(n);
        const QString text = tr("Imported with these losses and changes:") + QStringLiteral("\n\n")
                             + list.join(QLatin1Char('\n'));
        QMetaObject::invokeMethod(
            this, [this, text] { m_messages->information(this, tr("Import Mesh"), text); },
            Qt::QueuedConnection);
    }
}

bool MainWindow::exportMesh(const QString &fileName, int rounds, QString *error)
{
    const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(m_controller->drawnItem());
    QString why;
    if (!mesh) {
        why = m_current ? tr("Export Mesh writes a mesh surface; %1 is a %2")
                              .arg(m_current->name(), m_current->typeName())
                        : tr("Export Mesh writes a mesh surface: choose one first");
    } else {
        try {
            const std::string text = mesh->limitObj(rounds);
            if (QString reason; !writeWholeFile(fileName, QByteArray::fromStdString(text),
                                                &reason))
                why = tr("cannot write %1: %2").arg(fileName, reason);
        } catch (const std::exception &e) {
            why = QString::fromStdString(e.what());
        }
    }
    if (!why.isEmpty() && error)
        *error = why;
    return why.isEmpty();
}

void MainWindow::exportMeshDialog()
{
    const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(m_controller->drawnItem());
    if (!mesh) {
        QString error;
        exportMesh(QString(), 0, &error);
        m_messages->error(this, tr("Export Mesh"), error);
        return;
    }
    bool ok = false;
    const int rounds = QInputDialog::getInt(
        this, tr("Export Mesh"),
        tr("Steps of %1 before every vertex is moved to its limit position:")
            .arg(MeshInputs::schemeNames().at(int(mesh->scheme()))),
        std::min(3, SubdivisionMeshItem::maxExportRounds), 0, SubdivisionMeshItem::maxExportRounds,
        1, &ok);
    if (!ok)
        return;
    const QString file = QFileDialog::getSaveFileName(this, tr("Export Mesh"),
                                                      outputPath(QStringLiteral("obj")),
                                                      tr("Wavefront OBJ (*.obj)"));
    if (file.isEmpty())
        return;
    QString error;
    if (!exportMesh(file, rounds, &error))
        m_messages->error(this, tr("Export Mesh"), error);
    else
        statusBar()->showMessage(tr("Wrote %1").arg(QDir::toNativeSeparators(file)), 5000);
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
