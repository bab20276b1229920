// attractor-cli render: an item to PNG, SVG or PDF.

#include "cli/FigureOptions.h"
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
#include "model/ComplexBezierItem.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTextStream>

#include <sstream>

namespace awb::cli {

int render(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            CliTr::tr("Render an item's attractor (with its control polygons) to PNG, SVG or PDF; "
                      "or its raw density (hits per pixel) to OpenEXR (.exr, float32 "
                      "counts) or a 16-bit PNG (--bits 16), to tone-map elsewhere."));
        parser.addPositionalArgument("project", CliTr::tr("The .awb project file."));
        parser.addOptions({{"item", CliTr::tr("The item to render (default: the first with an "
                                           "attractor)."),
                            "name"},
                           {"out", CliTr::tr("Output file: .png, .svg, .pdf or .exr."), "file"},
                           {"progress", CliTr::tr("Report the iteration's progress on stderr, "
                                                  "one line per report (default: on a "
                                                  "terminal only, after a second).")},
                           {"scaled", CliTr::tr("A complex Bézier curve of t = 1/2 + iy in the "
                                                "scaled coordinates g(z, 1/(2y)) of 004 Thm "
                                                "3.7.3, where it approaches the Takagi graph "
                                                "(the item's \"scaled\", for this figure)")}});
        parser.addOptions(figureOptionList());
        parseOrFail(parser, args, 1);
        if (!parser.isSet("out"))
            throw Failure{CliTr::tr("--out FILE is required"), 2};
        FigureOptions options = figureOptions(parser);
        options.progress = progressLine(QStringLiteral("render"), parser.isSet("progress"));
        Project project;
        load(project, parser.positionalArguments().first());
        AttractorItem *item = attractorItem(project, parser.value("item"));
        if (parser.isSet("scaled")) {
            auto *curve = qobject_cast<ComplexBezierItem *>(item);
            if (!curve || !curve->scaledApplies())
                throw Failure{CliTr::tr("--scaled draws a complex Bézier curve of t = 1/2 + iy "
                                        "(y ≠ 0) with control points on the real axis; '%1' is "
                                        "not one")
                                  .arg(item->name()),
                              2};
            curve->setScaled(true);
        }
        renderItemFigure(project, item, options, parser.value("out"));
        out() << parser.value("out") << "\n";
        return 0;
    });
}

} // namespace awb::cli
