// attractor-cli import-mesh: a mesh file (OBJ, OFF, PLY) as a project with one
// "subdivision-mesh" item, the file's vertex numbering and polygons kept.

#include "cli/CommandSupport.h"
#include "cli/ProjectCommands.h"

#include "core/mesh/MeshAnalysis.h"
#include "core/mesh/MeshFiles.h"
#include "core/mesh/MeshRepair.h"
#include "core/mesh/MeshSheets.h"
#include "model/Project.h"
#include "model/SubdivisionMeshItem.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace awb::cli {

int importMesh(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(CliTr::tr(
            "Make a project of a mesh file (OBJ, OFF, PLY ASCII or binary): one subdivision-mesh "
            "item with the file's vertices, in its numbering, and its polygons. A non-manifold "
            "mesh (edges of three or more faces, faces of opposite orientations, vertices whose "
            "faces form several fans) is drawn as OpenSubdiv draws it, with a note."));
        parser.addPositionalArgument("mesh", CliTr::tr("The mesh file."));
        parser.addOptions(
            {{"scheme", CliTr::tr("catmull-clark (any polygons, the default) or loop "
                                         "(triangles)."),
              "scheme", "catmull-clark"},
             {"out", CliTr::tr("The project file to write (.awb)."), "file"},
             {"name", CliTr::tr("The item's name (default: the file's base name)."),
              "name"},
             {"repair", CliTr::tr("Repair what is well defined before the checks: weld "
                                  "boundary vertices at the same position, turn flipped faces "
                                  "over, split vertices whose faces form several fans, name "
                                  "repeated vertices once; say each change (the mesh is then drawn as the repaired "
                                  "surface, not as OpenSubdiv draws the original).")}});
        parseOrFail(parser, args, 1);
        if (!parser.isSet("out"))
            throw Failure{CliTr::tr("--out FILE (the project to write) is required"), 2};
        const MeshScheme scheme = meshSchemeOption(parser);
        const QString file = parser.positionalArguments().first();
        Mesh mesh;
        std::vector<std::string> notes;  // what the file holds that the mesh does not keep
        try {
            mesh = readMesh(QFile::encodeName(file).toStdString(), &notes);
        } catch (const InputError &e) {  // the message names the file and the place
            throw Failure{QString::fromStdString(e.what())};
        }
        for (const std::string &n : notes)
            err() << CliTr::tr("attractor-cli: warning: %1").arg(QString::fromStdString(n))
                  << "\n";
        if (parser.isSet("repair")) {
            MeshRepairReport report;
            mesh = repairMesh(mesh, &report);
            for (const std::string &c : report.changes)
                out() << CliTr::tr("repaired: %1").arg(QString::fromStdString(c)) << "\n";
            for (const std::string &c : report.unrepaired)
                err() << CliTr::tr("attractor-cli: not repaired: %1")
                             .arg(QString::fromStdString(c))
                      << "\n";
            if (!report.changed())
                out() << CliTr::tr("repaired: nothing needed repair") << "\n";
        }
        // What --repair would change, as " (--repair would ...)", or nothing.
        const auto wouldRepair = [&] {
            if (parser.isSet("repair"))
                return QString();
            MeshRepairReport report;
            repairMesh(mesh, &report);
            QStringList would;
            if (report.collapsedFaces + report.removedFaces > 0)
                would << CliTr::tr("name repeated vertices once in %1 faces")
                             .arg(report.collapsedFaces + report.removedFaces);
            if (report.weldedVertices > 0)
                would << CliTr::tr("weld %1 vertices").arg(report.weldedVertices);
            if (report.turnedFaces > 0)
                would << CliTr::tr("turn %1 faces over").arg(report.turnedFaces);
            if (report.splitVertices > 0)
                would << CliTr::tr("split %1 vertices").arg(report.splitVertices);
            return would.isEmpty()
                       ? QString()
                       : CliTr::tr(" (--repair would %1)").arg(would.join(QStringLiteral(", ")));
        };
        Project project;
        auto item = std::make_unique<SubdivisionMeshItem>();
        QString error;
        if (!item->setMesh(mesh, scheme, &error))
            throw Failure{QStringLiteral("%1: %2%3").arg(file, error, wouldRepair())};
        // A non-manifold mesh is drawn as OpenSubdiv draws it (MeshSheets.h): said.
        if (const auto sheets = manifoldSheets(mesh))
            err() << CliTr::tr("attractor-cli: note: the mesh is %1%2")
                         .arg(QString::fromStdString(describe(*sheets)), wouldRepair())
                  << "\n";
        const QString name =
            parser.isSet("name") ? parser.value("name") : QFileInfo(file).completeBaseName();
        if (!name.isEmpty() && !item->setName(name))
            throw Failure{CliTr::tr("'%1' cannot be an item's name").arg(name), 2};
        SubdivisionMeshItem *added = static_cast<SubdivisionMeshItem *>(
            project.addItem(std::move(item)));
        // What check and every command would refuse (a valence above the pieces' limit, a
        // prelude too long) is refused here, before a project is written.
        if (!added->derivedError().isEmpty())
            throw Failure{QStringLiteral("%1: %2").arg(file, added->derivedError())};
        if (!project.saveAs(parser.value("out"), &error))
            throw Failure{error};
        out() << CliTr::tr("%1: item '%2', %3 vertices, %4 faces, %5 extraordinary "
                                  "vertices (%6)\n")
                     .arg(parser.value("out"), added->name())
                     .arg(mesh.vertices.rows())
                     .arg(mesh.faces.size())
                     .arg(added->extraordinaryCount())
                     .arg(MeshInputs::schemeNames().at(int(scheme)));
        if (!mesh.tags.empty())
            out() << CliTr::tr("  sharp features: %1 creases, %2 corners, %3 holes; boundary "
                               "%4, crease method %5, triangles %6\n")
                         .arg(mesh.tags.edges.size())
                         .arg(mesh.tags.vertices.size())
                         .arg(mesh.tags.holes.size())
                         .arg(QString::fromStdString(toString(mesh.tags.options.boundary)),
                              QString::fromStdString(toString(mesh.tags.options.creaseMethod)),
                              QString::fromStdString(toString(mesh.tags.options.triangles)));
        if (!parser.isSet("scheme") && suggestedScheme(mesh) != scheme)
            err() << CliTr::tr("attractor-cli: note: all %1 faces are triangles; --scheme loop "
                               "keeps them triangles (Catmull-Clark makes each one three quads "
                               "around a new valence-3 vertex)")
                         .arg(mesh.faces.size())
                  << "\n";
        return 0;
    });
}

} // namespace awb::cli
