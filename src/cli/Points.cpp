// attractor-cli points: the points of F^k(X0) as CSV.

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

int points(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            CliTr::tr("Print the points of F^k(X0) as CSV: x, y (and z for a surface), the map "
                   "applied last (1-based), and the view. --address w limits them to the sub-copy "
                   "f_w(A): the points f_w(F^k(X0))."));
        parser.addPositionalArgument("project", CliTr::tr("The .awb project file."));
        parser.addOptions({{"item", CliTr::tr("The item (needed when the project has several)."), "name"},
                           {"depth", CliTr::tr("Iteration depth (default: the item's)."), "k"},
                           {"start", CliTr::tr("Start set: point:x,y | segment:x1,y1,x2,y2 | "
                                            "triangle:... | polygon:... | points:... (plane "
                                            "coordinates; x,y,z for a surface) | "
                                            "lifted:x,y,c1,...;x,y,c1,... (points of the lifted "
                                            "space of 000 §2) | net:i,j,... (control points by "
                                            "index, from 0: the rows of the lifted P) | "
                                            "vertex-limits (a mesh item: the "
                                            "limit positions of the vertices of the mesh refined "
                                            "k times; default: the item's)."),
                            "set"},
                           {"csv", CliTr::tr("Print CSV (the only format so far).")},
                           {"address", CliTr::tr("Only the sub-copy f_w(A) of this address: 0-based "
                                              "map numbers, w_1 (the outermost map) first, e.g. "
                                              "0,1,1."),
                            "w"},
                           {"max-points", CliTr::tr("Refuse to print more (default 10000000)."), "n",
                            "10000000"}});
        parseOrFail(parser, args, 1);
        if (!parser.isSet("csv"))
            throw Failure{CliTr::tr("--csv is required (the only output format)"), 2};
        Project project;
        load(project, parser.positionalArguments().first());
        AttractorItem *item = namedOrOnlyAttractorItem(project, parser.value("item"));
        auto d = derived(item);
        const int depth = parser.isSet("depth") ? intOption(parser, "depth", 0, 64)
                                                : item->algorithm().depth;
        Address address;
        if (parser.isSet("address")) {
            try {
                address = parseItemAddress(parser.value("address"), *d);
            } catch (const InputError &e) {
                throw Failure{CliTr::tr("--address %1: %2")
                                  .arg(parser.value("address"), QString::fromStdString(e.what())),
                              2};
            }
        }
        const StartSet start = parser.isSet("start")
                                   ? startOption(*item, *d, parser.value("start"))
                                   : item->coreStartSet(*d);
        const double maxPoints = intOption(parser, "max-points", 1, 2000000000);
        requirePointBudget(*d, start, depth, maxPoints);
        out().flush();
        QFile stdoutFile;
        if (!stdoutFile.open(stdout, QIODevice::WriteOnly))
            throw Failure{CliTr::tr("cannot write to the standard output")};
        std::atomic<bool> cancel{false};
        IterationControl control;
        control.cancel = &cancel;
        writePointsCsv(stdoutFile, *d, start, depth, control, address);
        stdoutFile.flush();
        return 0;
    });
}

} // namespace awb::cli
