// attractor-cli export: attractor points (PLY), a subdivided net or a mesh at its limit
// positions (OBJ).

#include "cli/CommandSupport.h"
#include "cli/ProjectCommands.h"

#include "render/FigureRenderer.h"
#include "core/analysis/Geometry.h"
#include "core/analysis/Spectrum.h"
#include "model/Animation.h"
#include "model/FigureMetadata.h"
#include "model/AttractorItem.h"
#include "model/ExactCurve.h"
#include "model/FileWriting.h"
#include "model/ItemAddress.h"
#include "model/IfsExchange.h"
#include "model/FlameExchange.h"
#include "model/FlameFile.h"
#include "model/FlameItem.h"
#include "cli/FigureOptions.h"
#include "model/NamedMatrix.h"
#include "model/NumberFormat.h"
#include "model/PointExport.h"
#include "model/Project.h"
#include "model/SchemeRegularity.h"
#include "model/NormalVectorItem.h"
#include "model/SubdivisionCurveItem.h"
#include "core/schemes/NormalVectorScheme.h"
#include "core/schemes/Scheme.h"
#include "model/SubdivisionSurfaceItem.h"
#include "model/SubdivisionMeshItem.h"
#include "model/MeshAnalysisJson.h"
#include "core/mesh/MeshFiles.h"
#include "core/mesh/MeshRefine.h"
#include "core/ifs/SurfaceIfs.h"
#include "render/SurfaceFigure.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTextStream>

#include <sstream>

namespace awb::cli {

namespace {

// Wavefront OBJ of the control net after `rounds` rounds of classic subdivision.
void writeObj(QIODevice &file, const SubdivisionSurfaceItem *item, int rounds)
{
    const LatticeMesh mesh = item->refinedMesh(rounds);
    QByteArray text;
    text += QString("# Attractor Workbench: item %1, %2 scheme, net after %3 rounds of "
                    "subdivision\n# %4 vertices, %5 faces\n")
                .arg(item->name(), SurfaceSchemeSpec::kindNames().at(int(item->scheme().kind)))
                .arg(rounds)
                .arg(mesh.points.rows())
                .arg(mesh.faces.size())
                .toUtf8();
    for (Eigen::Index k = 0; k < mesh.points.rows(); ++k)
        text += CliTr::tr("v %1 %2 %3\n")
                    .arg(mesh.points(k, 0), 0, 'g', 17)
                    .arg(mesh.points(k, 1), 0, 'g', 17)
                    .arg(mesh.points(k, 2), 0, 'g', 17)
                    .toUtf8();
    for (const auto &face : mesh.faces) {
        text += "f";
        for (int i : face)
            text += " " + QByteArray::number(i + 1);
        text += "\n";
    }
    file.write(text);
}

} // namespace

int exportData(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            CliTr::tr("Export an item's geometry: the attractor F^k(X0) as a PLY point cloud "
                      "(with the map applied last per point), a surface item's net after k "
                      "rounds of classic subdivision as an OBJ mesh, or a mesh item after k "
                      "steps with every vertex at its limit position (OBJ); its maps as a "
                      "Fractint .ifs entry (ifs) or a flam3 genome that flam3-render draws in "
                      "the frame of render's --size and --bounds (flame); or its matrices S_i, "
                      "M_i, A_i as MATLAB cell arrays for the JSR toolbox (matlab)."));
        parser.addPositionalArgument("project", CliTr::tr("The .awb project file."));
        parser.addOptions({{"item", CliTr::tr("The item (needed when the project has several)."), "name"},
                           {"format", CliTr::tr("ply (attractor points), obj (subdivided "
                                                "mesh), ifs (Fractint), flame (flam3) or "
                                                "matlab (matrices)."),
                            "fmt"},
                           {"out", CliTr::tr("Output file."), "file"},
                           {"depth", CliTr::tr("PLY: iteration depth (default: the item's)."), "k"},
                           {"rounds", CliTr::tr("OBJ: rounds of subdivision (default: the "
                                             "item's; a mesh item: its depth, at most 6)."), "r"},
                           {"max-points", CliTr::tr("PLY: refuse to write more (default "
                                                 "50000000)."), "n",
                            "50000000"}});
        parser.addOptions(frameOptionList());
        parseOrFail(parser, args, 1);
        if (!parser.isSet("out") || !parser.isSet("format"))
            throw Failure{
                CliTr::tr("--format ply|obj|ifs|flame|matlab and --out FILE are required"), 2};
        const QString format = parser.value("format").toLower();
        if (format != "ply" && format != "obj" && format != "ifs" && format != "flame"
            && format != "matlab")
            throw Failure{
                CliTr::tr("--format must be ply, obj, ifs, flame or matlab, got '%1'").arg(format),
                2};
        Project project;
        load(project, parser.positionalArguments().first());
        AttractorItem *item = namedOrOnlyAttractorItem(project, parser.value("item"));
        auto d = derived(item);
        const QString outFile = parser.value("out");
        WholeFileWriter writer;
        QString reason;
        if (!writer.open(outFile, &reason))
            throw Failure{CliTr::tr("cannot write %1: %2").arg(outFile, reason)};
        QIODevice &file = *writer.device();
        if (format == "ifs") {
            QString why;
            const auto entry = fractintEntryOf(*item, &why);
            if (!entry)
                throw Failure{why};
            const QByteArray text = QByteArray::fromStdString(fractintEntryText(*entry));
            if (file.write(text) != text.size())
                throw Failure{CliTr::tr("cannot write %1: %2").arg(outFile, file.errorString())};
        } else if (format == "flame") {
            QString refused;
            // A flame item is written whole (flameOf); other items need a frame first.
            if (!qobject_cast<const FlameItem *>(item) && !flameEntryOf(*item, &refused))
                throw Failure{refused};
            // The frame `render` draws with the same --size and --bounds.
            FigureOptions o;
            readFrameOptions(parser, o);
            QRectF content;
            renderItemFigure(project, item, o, QString(), &content);
            if (content.width() < 0)
                throw Failure{CliTr::tr("'%1' has nothing to frame").arg(item->name())};
            QStringList colours;
            const QStringList own = item->style().colors;
            for (int i = 0; i < std::max(1, d->ifs.size()); ++i)
                colours << (i < own.size() ? own[i] : mapColor(i).name());
            QString why;
            const auto text = flameOf(
                *item, colours, {figureWorld(content, QSizeF(o.width, o.height)),
                                 QSize(o.width, o.height)},
                &why);
            if (!text)
                throw Failure{why};
            if (file.write(*text) != text->size())
                throw Failure{CliTr::tr("cannot write %1: %2").arg(outFile, file.errorString())};
        } else if (format == "matlab") {
            const QByteArray text = matlabMatrices(namedMatrices(*d), item->name()).toUtf8();
            if (file.write(text) != text.size())
                throw Failure{CliTr::tr("cannot write %1: %2").arg(outFile, file.errorString())};
        } else if (format == "ply") {
            const int depth = parser.isSet("depth") ? intOption(parser, "depth", 0, 64)
                                                    : item->algorithm().depth;
            const StartSet start = item->coreStartSet(*d);
            requirePointBudget(*d, start, depth, intOption(parser, "max-points", 1, 2000000000));
            writePointsPly(file, item->name(), *d, start, depth, mapColor);
        } else if (const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(item)) {
            // The mesh after k steps, every vertex at its exact limit position.
            const int most = SubdivisionMeshItem::maxExportRounds;
            const int rounds = parser.isSet("rounds")  ? intOption(parser, "rounds", 0, most)
                               : parser.isSet("depth") ? intOption(parser, "depth", 0, most)
                                                       : std::min(item->algorithm().depth, 6);
            std::string bytes;
            try {
                bytes = mesh->limitObj(rounds);
            } catch (const InputError &e) {
                throw Failure{QString::fromStdString(e.what())};
            }
            if (file.write(bytes.data(), qint64(bytes.size())) != qint64(bytes.size()))
                throw Failure{CliTr::tr("cannot write %1: %2")
                                  .arg(outFile, file.errorString())};
        } else {
            const auto *surface = qobject_cast<const SubdivisionSurfaceItem *>(item);
            if (!surface)
                throw Failure{CliTr::tr("OBJ export writes the subdivided net of a surface item; "
                                     "'%1' is a %2").arg(item->name(), item->typeName())};
            const int rounds = parser.isSet("rounds")
                                   ? intOption(parser, "rounds", 0,
                                               SubdivisionSurfaceItem::maxMeshRounds)
                                   : surface->meshRounds();
            writeObj(file, surface, rounds);
        }
        if (!writer.commit(&reason))
            throw Failure{CliTr::tr("cannot write %1: %2").arg(outFile, reason)};
        out() << parser.value("out") << "\n";
        return 0;
    });
}

} // namespace awb::cli
