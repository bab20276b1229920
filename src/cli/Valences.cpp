// attractor-cli valences: the valence explorer's table (issue 31) -- the subdominant
// eigenvalue lambda, the next modulus mu and lambda^2 of the local subdivision matrix at an
// interior vertex of every valence, with Reif's C1 verdict and the curvature, for Catmull-Clark
// or Loop. The same table as the window's Analysis > Valences (model/MeshAnalysisJson.h).

#include "cli/CommandSupport.h"
#include "cli/ProjectCommands.h"

#include "model/MeshAnalysisJson.h"
#include "model/SubdivisionMeshItem.h"

#include <QCommandLineParser>

namespace awb::cli {

int valences(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(CliTr::tr(
            "The spectrum of the local subdivision matrix at an interior vertex of each valence: "
            "lambda (with its closed form), mu, lambda^2, Reif's C1 verdict and the curvature."));
        parser.addOptions(
            {{"scheme", CliTr::tr("catmull-clark (the default) or loop."), "scheme",
              "catmull-clark"},
             {"from", CliTr::tr("The smallest valence (3 to 64, default 3)."), "n", "3"},
             {"to", CliTr::tr("The largest valence (3 to 64, default 16)."), "n", "16"},
             {"json", CliTr::tr("Print JSON instead of a table.")}});
        parseOrFail(parser, args, 0);
        const MeshScheme scheme = meshSchemeOption(parser);
        const int from = intOption(parser, "from", 3, 64);
        const int to = intOption(parser, "to", from, 64);
        const QJsonArray rows = valenceTableJson(scheme, from, to);
        if (parser.isSet("json")) {
            printJson(QJsonObject{{"scheme", parser.value("scheme").toLower()},
                                  {"valences", rows}});
            return 0;
        }
        out() << QStringLiteral("%1 %2 %3 %4  %5  %6\n")
                     .arg(QStringLiteral("n"), 3)
                     .arg(QStringLiteral("lambda"), 10)
                     .arg(QStringLiteral("mu"), 10)
                     .arg(QStringLiteral("lambda^2"), 10)
                     .arg(QStringLiteral("C1"), 3)
                     .arg(QStringLiteral("curvature"));
        for (const QJsonValue &v : rows) {
            const QJsonObject r = v.toObject();
            out() << QStringLiteral("%1 %2 %3 %4  %5  %6\n")
                         .arg(r["valence"].toInt(), 3)
                         .arg(r["subdominant"].toDouble(), 10, 'f', 6)
                         .arg(r["subsubdominant"].toDouble(), 10, 'f', 6)
                         .arg(r["lambda_squared"].toDouble(), 10, 'f', 6)
                         .arg(r["c1"].toBool() ? QStringLiteral("yes") : QStringLiteral("no"), 3)
                         .arg(r["curvature"].toString());
        }
        return 0;
    });
}

} // namespace awb::cli
