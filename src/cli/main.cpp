// attractor-cli: the command-line face of Attractor Workbench.

#include "cli/FigureRenderer.h"
#include "cli/Gallery.h"
#include "cli/ProjectCommands.h"
#include "core/Messages.h"
#include "core/analysis/Spectrum.h"
#include "i18n/Translations.h"
#include "render/FigureFile.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QGuiApplication>
#include <QTextStream>

#include <csignal>

using namespace awb;

namespace {

// lupdate takes the context of Tr::tr() from the macro.
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(awb::cli)
};

QTextStream &out()
{
    static QTextStream s(stdout);
    return s;
}
QTextStream &err()
{
    static QTextStream s(stderr);
    return s;
}

int runExamples(const QStringList &args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        Tr::tr("Render the bundled paper figures to PNG files (one row of panels per figure: the "
               "start set, a few iterates of the Hutchinson operator, and the attractor, over the "
               "control polygon)."));
    parser.addHelpOption();
    parser.addOption({"out", Tr::tr("Directory for the PNG files (created if missing)."), "dir",
                      "gallery"});
    parser.addOption({"list", Tr::tr("List the examples and exit.")});
    parser.process(args);
    const auto gallery = builtinGallery();
    if (parser.isSet("list")) {
        for (const auto &ex : gallery)
            out() << ex.id << "\t" << ex.title << "\n";
        return 0;
    }
    QDir dir(parser.value("out"));
    if (!dir.mkpath(".")) {
        err() << Tr::tr("attractor-cli: cannot create directory %1").arg(dir.path()) << "\n";
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

void usage()
{
    out() << Tr::tr("Usage: attractor-cli <command> [options]\n\n"
                    "Commands:\n"
                    "  render     render an item of a project to PNG, SVG or PDF\n"
                    "  animate    render the frames of an item's animation (PNG files, MP4/GIF)\n"
                    "  analyse    eigenvalues, contractivity, fixed points, dimension (JSON)\n"
                    "  points     the points of F^k(X0) as CSV\n"
                    "  check      validate a project file\n"
                    "  rewrite    load and save a project in canonical form\n"
                    "  export     points (PLY), a net or mesh (OBJ), maps (.ifs), matrices (MATLAB)\n"
                    "  polygon    the control polygon after K subdivision steps (JSON)\n"
                    "  import     another tool's IFS file (Fractint .ifs) as a project\n"
                    "  import-mesh  a mesh file (OBJ, OFF, PLY) as a project with a mesh item\n"
                    "  valences   lambda, mu, Reif's C1 verdict per valence (Catmull-Clark, Loop)\n"
                    "  regularity-interval  where a scheme is C^k as a parameter moves\n"
                    "  verify-regularity  re-check the certificate of an exact Hölder exponent\n"
                    "  examples   render the built-in paper figures (000 Figs. 2, 3, 5) to PNG\n\n"
                    "Run 'attractor-cli <command> --help' for the options of a command.\n");
}

} // namespace

int main(int argc, char **argv)
{
    // A file size limit (ulimit -f) makes a too-large write fail with EFBIG, reported as a
    // message, instead of killing the process.
    std::signal(SIGXFSZ, SIG_IGN);
    // Text in images needs a QGuiApplication; without a display, render off screen.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    // Without a session (CI, ssh) Qt warns on every run that XDG_RUNTIME_DIR is unset.
    if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
        const QString dir = QDir::tempPath() + "/attractor-cli-runtime-" + qgetenv("USER");
        QDir().mkpath(dir);
        QFile::setPermissions(dir, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        qputenv("XDG_RUNTIME_DIR", dir.toLocal8Bit());
    }
    QGuiApplication app(argc, argv);
    QGuiApplication::setApplicationName("attractor-cli");
    QGuiApplication::setApplicationVersion(PROJECT_VERSION);
    // The GUI's settings hold the chosen language (View > Language): read them.
    QGuiApplication::setOrganizationName(QStringLiteral("attractor-workbench"));
    i18n::installTranslations(app);
    QStringList args = app.arguments();
    if (args.size() < 2 || args[1] == "--help" || args[1] == "-h" || args[1] == "help") {
        usage();
        return args.size() < 2 ? 2 : 0;
    }
    if (args[1] == "--version") {
        out() << "attractor-cli " << PROJECT_VERSION << "\n";
        return 0;
    }
    const QString command = args[1];
    // JSON output is for programs: the core's notes, verdicts and errors in it stay in English.
    if (command == "analyse" || command == "analyze" || command == "polygon"
        || command == "valences" || command == "regularity-interval"
        || command == "verify-regularity")
        setMessageTranslator(nullptr);
    args.removeAt(1);
    args[0] = "attractor-cli " + command;
    try {
        if (command == "examples")
            return runExamples(args);
        if (command == "render")
            return cli::render(args);
        if (command == "animate")
            return cli::animate(args);
        if (command == "analyse" || command == "analyze")
            return cli::analyse(args);
        if (command == "points")
            return cli::points(args);
        if (command == "check")
            return cli::check(args);
        if (command == "rewrite")
            return cli::rewrite(args);
        if (command == "export")
            return cli::exportData(args);
        if (command == "polygon")
            return cli::polygon(args);
        if (command == "import-mesh")
            return cli::importMesh(args);
        if (command == "valences")
            return cli::valences(args);
        if (command == "import")
            return cli::importFile(args);
        if (command == "regularity-interval")
            return cli::regularityInterval(args);
        if (command == "verify-regularity")
            return cli::verifyRegularity(args);
    } catch (const InputError &e) {
        err() << "attractor-cli " << command << ": " << e.what() << "\n";
        return 1;
    }
    err() << Tr::tr("attractor-cli: unknown command '%1'").arg(command) << "\n";
    usage();
    return 2;
}
