// attractor-cli rewrite: a project saved again in canonical form.

#include "cli/CommandSupport.h"
#include "cli/ProjectCommands.h"

#include "cli/FigureRenderer.h"
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

int rewrite(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            CliTr::tr("Load a project and save it again in the canonical form of this version (sorted "
                   "keys, every field written): to upgrade or normalise a hand-written file."));
        parser.addPositionalArgument("project", CliTr::tr("The .awb project file."));
        parser.addOption({"out", CliTr::tr("Write here instead of over the input."), "file"});
        parseOrFail(parser, args, 1);
        Project project;
        load(project, parser.positionalArguments().first());
        QString error;
        const QString target = parser.isSet("out") ? parser.value("out") : project.fileName();
        if (!project.saveAs(target, &error))
            throw Failure{error};
        out() << target << "\n";
        return 0;
    });
}

} // namespace awb::cli
