// attractor-cli analyse: eigenvalues, contractivity, fixed points, dimension, regularity and,
// for meshes, the extraordinary vertices, as JSON.

#include "cli/CommandSupport.h"
#include "cli/ProjectCommands.h"

#include "render/FigureRenderer.h"
#include "core/analysis/Geometry.h"
#include "core/analysis/HausdorffBracket.h"
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
#include "model/RegularityCertificate.h"
#include "model/SchemeRegularity.h"
#include "model/NormalVectorItem.h"
#include "model/SubdivisionCurveItem.h"
#include "core/schemes/NormalVectorScheme.h"
#include "core/schemes/Scheme.h"
#include "model/SubdivisionSurfaceItem.h"
#include "model/SubdivisionMeshItem.h"
#include "model/MeshAnalysisJson.h"
#include "model/ItemAnalysisJson.h"
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
#include <QJsonObject>
#include <QRegularExpression>
#include <QTextStream>

#include <sstream>
#include <utility>

namespace awb::cli {

int analyse(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            CliTr::tr("Analyse the items of a project: per map S_i (exact fractions), M_i = P^-1 S_i "
                   "P with its blocks A_i, b_i, the eigenvalues of S_i and A_i, spectral radius, "
                   "contractivity and fixed point; per item the subdominant eigenvalues, the "
                   "Hausdorff distance to the exact curve and the box-counting dimension; per "
                   "subdivision curve the certified Hölder regularity of its scheme."));
        parser.addPositionalArgument("project", CliTr::tr("The .awb project file."));
        parser.addOptions({{"item", CliTr::tr("Only this item."), "name"},
                           {"json", CliTr::tr("Print JSON (the only format so far).")},
                           {"certificate",
                            CliTr::tr("With --item: write the certificate of the curve's exact "
                                      "Hölder exponent (verify-regularity checks it)."),
                            "file"}});
        parseOrFail(parser, args, 1);
        if (!parser.isSet("json"))
            throw Failure{CliTr::tr("--json is required (the only output format)"), 2};
        if (parser.isSet("certificate") && !parser.isSet("item"))
            throw Failure{CliTr::tr("--certificate needs --item: the certificate is one "
                                    "curve's"),
                          2};
        Project project;
        load(project, parser.positionalArguments().first());
        if (parser.isSet("item")) {
            const AttractorItem *item = attractorItem(project, parser.value("item"));
            Regularity regularity;
            std::optional<ItemAnalysis> analysis = analyseItem(item, &regularity);
            if (parser.isSet("certificate")) {
                const auto *curve = qobject_cast<const SubdivisionCurveItem *>(item);
                if (!curve)
                    throw Failure{CliTr::tr("item '%1' is not a subdivision curve: no "
                                            "regularity to certify")
                                      .arg(item->name())};
                QString why;
                const QByteArray cert = regularityCertificate(curve->scheme(), regularity, &why);
                if (cert.isEmpty())
                    throw Failure{CliTr::tr("item '%1': %2").arg(item->name(), why)};
                if (!writeWholeFile(parser.value("certificate"), cert, &why))
                    throw Failure{why};
            }
            printJsonList("items", [&] { return std::exchange(analysis, std::nullopt); });
        } else {
            // Item by item: each analysis printed and released before the next is made.
            const QList<Item *> all = project.items();
            qsizetype next = 0;
            printJsonList("items", [&]() -> std::optional<ItemAnalysis> {
                while (next < all.size())
                    if (auto *a = qobject_cast<AttractorItem *>(all[next++]))
                        return analyseItem(a);
                return std::nullopt;
            });
        }
        return 0;
    });
}

} // namespace awb::cli
