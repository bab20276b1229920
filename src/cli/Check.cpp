// attractor-cli check: does a project load, and can every item be computed.

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

int check(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            CliTr::tr("Validate a project file: it must load, and every item's IFS must be computable "
                   "(exit 1: the file is refused; exit 3: it loads but items cannot be "
                   "computed)."));
        parser.addPositionalArgument("project", CliTr::tr("The .awb project file."));
        parseOrFail(parser, args, 1);
        Project project;
        load(project, parser.positionalArguments().first());
        // A figure PNG opens as an untitled project: name the file that was given.
        const QString name = project.fileName().isEmpty() ? parser.positionalArguments().first()
                                                          : project.fileName();
        const QStringList problems = project.problems();
        for (const QString &p : problems)
            err() << name << ": " << p << "\n";
        if (!problems.isEmpty())
            return 3;
        // What the items say about themselves: a singular lifting drawn in barycentric form,
        // a nearly singular one, maps that are not (eventually) contractive.
        for (Item *item : project.items()) {
            auto *a = qobject_cast<AttractorItem *>(item);
            const auto d = a ? a->derivedIfs() : nullptr;
            if (!d)
                continue;
            if (!d->note.isEmpty())
                err() << CliTr::tr("%1: %2: note: %3").arg(name, a->name(), d->note)
                      << "\n";
            // A flame: its affine parts say nothing of how it contracts; its orbit does.
            const std::optional<double> lyapunov = d->chaos.lyapunovExponent();
            if (d->chaos && lyapunov && !(*lyapunov < -1e-3))
                err() << CliTr::tr("%1: %2: note: its chaos game does not contract on average "
                                   "(the Lyapunov exponent along its orbit is %3): flam3 draws "
                                   "it by discarding the points that escape")
                             .arg(name, a->name())
                             .arg(*lyapunov, 0, 'g', 3)
                      << "\n";
            if (!d->iterate && !d->chaos && d->ifs.size() > 0)
                if (const IfsCheck c = checkIfs(d->ifs); !c.contractive)
                    err() << CliTr::tr("%1: %2: note: %3")
                                 .arg(name, a->name(),
                                      QString::fromStdString(c.message))
                          << "\n";
        }
        const auto n = project.items().size();
        out() << name << ": OK, " << n << (n == 1 ? " item\n" : " items\n");
        return 0;
    });
}

} // namespace awb::cli
