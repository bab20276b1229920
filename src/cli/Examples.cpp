// attractor-cli examples: the built-in paper figures (000 Figs. 2, 3, 5) rendered to PNG files.

#include "cli/CommandSupport.h"
#include "render/FigureRenderer.h"
#include "cli/Gallery.h"
#include "cli/ProjectCommands.h"
#include "core/analysis/Spectrum.h"
#include "render/FigureFile.h"

#include <QCommandLineParser>
#include <QDir>

namespace awb::cli {

int examples(const QStringList &args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        CliTr::tr("Render the bundled paper figures to PNG files (one row of panels per figure: the "
               "start set, a few iterates of the Hutchinson operator, and the attractor, over the "
               "control polygon)."));
    parser.addHelpOption();
    parser.addOption({"out", CliTr::tr("Directory for the PNG files (created if missing)."), "dir",
                      "gallery"});
    parser.addOption({"list", CliTr::tr("List the examples and exit.")});
    parser.process(args);
    const auto gallery = builtinGallery();
    if (parser.isSet("list")) {
        for (const auto &ex : gallery)
            out() << ex.id << "\t" << ex.title << "\n";
        return 0;
    }
    QDir dir(parser.value("out"));
    if (!dir.mkpath(".")) {
        err() << CliTr::tr("attractor-cli: cannot create directory %1").arg(dir.path()) << "\n";
        return 1;
    }
    for (const auto &ex : gallery) {
        const SubdivisionIfs s = buildSubdivisionIfs(*ex.scheme, ex.controlPoints);
        const IfsCheck check = checkIfs(s.ifs);
        if (!check.contractive) {
            err() << ex.id << ": " << QString::fromStdString(check.message) << "\n";
            return 1;
        }
        FigureSpec spec;
        spec.title = ex.title;
        spec.ifs = &s.ifs;
        spec.start = {ex.startKind, s.toIfsSpace(ex.start)};
        spec.controlPolygons = {ex.controlPoints};
        if (auto exact = ex.scheme->exactCurve(ex.controlPoints, 600))
            spec.overlays.push_back(*exact);
        spec.panels = {{"X0", 0}, {"F(X0)", 1}, {"F^3(X0)", 3}, {"F^6(X0)", 6},
                       {QString("F^%1(X0)").arg(ex.depth), ex.depth}};
        const QImage img = renderFigure(spec);
        const QString file = dir.filePath(ex.id + ".png");
        QString error;
        if (!writeFigureFile(
                file, [&](QIODevice &png, QString *) { return writePng(img, png); },
                &error)) {
            err() << "attractor-cli: " << error << "\n";
            return 1;
        }
        out() << file << "\n";
    }
    return 0;
}

} // namespace awb::cli
