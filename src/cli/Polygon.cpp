// attractor-cli polygon: the control polygon after K subdivision steps (001), as JSON.

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

int polygon(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            CliTr::tr("Print the control polygon after K subdivision steps as JSON {\"closed\", "
                   "\"points\"}: the figures of 001 for a normal-vector item (eq. (1) applied K "
                   "times), classic subdivision S_w P for a subdivision curve."));
        parser.addPositionalArgument("project", CliTr::tr("The .awb project file."));
        parser.addOptions({{"item", CliTr::tr("The item (needed when the project has several)."), "name"},
                           {"level", CliTr::tr("Subdivision steps K (0: the control "
                                            "polygon)."), "k", "0"},
                           {"json", CliTr::tr("Print JSON (the only format).")}});
        parseOrFail(parser, args, 1);
        if (!parser.isSet("json"))
            throw Failure{CliTr::tr("--json is required (the only output format)"), 2};
        Project project;
        load(project, parser.positionalArguments().first());
        AttractorItem *item = namedOrOnlyAttractorItem(project, parser.value("item"));
        const int level = intOption(parser, "level", 0, 30);
        Mat points;
        bool closed = false;
        if (const auto *nv = qobject_cast<const NormalVectorItem *>(item)) {
            const ControlPolygon poly{toMatrix(nv->controlPoints()), nv->spec().closed};
            points = nv->spec().makeScheme().subdivide(poly, level).points;
            closed = poly.closed;
        } else if (const auto *curve = qobject_cast<const SubdivisionCurveItem *>(item)) {
            if (curve->scheme().isComplex())
                throw Failure{CliTr::tr("item '%1' has a complex split parameter: its control "
                                     "polygon has complex points").arg(item->name())};
            const Mat P = toMatrix(curve->controlPoints());
            const auto scheme = curve->scheme().makeScheme();
            if (std::pow(double(scheme->arity()), level) * double(P.rows()) > 5e7)
                throw Failure{CliTr::tr("level %1 gives more than 5e7 points").arg(level)};
            points = subdivide(*scheme, P, level);
        } else {
            throw Failure{CliTr::tr("item '%1' (%2) is not polygon-based: the polygon command "
                                 "takes normal-vector items and subdivision curves")
                              .arg(item->name(), item->typeName())};
        }
        QJsonArray list;
        for (Eigen::Index r = 0; r < points.rows(); ++r)
            list.append(QJsonArray{points(r, 0), points(r, 1)});
        out() << QJsonDocument(QJsonObject{{"closed", closed}, {"level", level}, {"points", list}})
                     .toJson(QJsonDocument::Compact)
              << "\n";
        return 0;
    });
}

} // namespace awb::cli
