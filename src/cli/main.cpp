// attractor-cli: the command-line face of Attractor Workbench.

#include "cli/ProjectCommands.h"
#include "core/Messages.h"
#include "core/Types.h"
#include "i18n/Translations.h"

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

// The commands, one file each (ProjectCommands.h), as git's builtin table: name, body, what it
// does, and whether its output is for programs (JSON: the core's notes stay in English).
struct Command {
    const char *name;
    int (*run)(const QStringList &);
    const char *summary;
    bool machineOutput = false;
};

const Command commands[] = {
    {"render", cli::render, QT_TRANSLATE_NOOP("awb::cli", "render an item of a project to PNG, SVG or PDF")},
    {"animate", cli::animate, QT_TRANSLATE_NOOP("awb::cli", "render the frames of an item's animation (PNG files, MP4/GIF)")},
    {"analyse", cli::analyse, QT_TRANSLATE_NOOP("awb::cli", "eigenvalues, contractivity, fixed points, dimension (JSON)"), true},
    {"points", cli::points, QT_TRANSLATE_NOOP("awb::cli", "the points of F^k(X0) as CSV")},
    {"set", cli::set, QT_TRANSLATE_NOOP("awb::cli", "set an item's properties and save, or list them")},
    {"check", cli::check, QT_TRANSLATE_NOOP("awb::cli", "validate a project file")},
    {"rewrite", cli::rewrite, QT_TRANSLATE_NOOP("awb::cli", "load and save a project in canonical form")},
    {"export", cli::exportData, QT_TRANSLATE_NOOP("awb::cli", "points (PLY), a net or mesh (OBJ), maps (.ifs), matrices (MATLAB)")},
    {"polygon", cli::polygon, QT_TRANSLATE_NOOP("awb::cli", "the control polygon after K subdivision steps (JSON)"), true},
    {"import", cli::importFile, QT_TRANSLATE_NOOP("awb::cli", "another tool's IFS file (Fractint .ifs) as a project")},
    {"import-mesh", cli::importMesh, QT_TRANSLATE_NOOP("awb::cli", "a mesh file (OBJ, OFF, PLY) as a project with a mesh item")},
    {"valences", cli::valences, QT_TRANSLATE_NOOP("awb::cli", "lambda, mu, Reif's C1 verdict per valence (Catmull-Clark, Loop)"), true},
    {"regularity-interval", cli::regularityInterval, QT_TRANSLATE_NOOP("awb::cli", "where a scheme is C^k as a parameter moves"), true},
    {"verify-regularity", cli::verifyRegularity, QT_TRANSLATE_NOOP("awb::cli", "re-check the certificate of an exact Hölder exponent"), true},
    {"examples", cli::examples, QT_TRANSLATE_NOOP("awb::cli", "render the built-in paper figures (000 Figs. 2, 3, 5) to PNG")},
};

const Command *findCommand(const QString &name)
{
    const QString canonical = name == QLatin1String("analyze") ? QStringLiteral("analyse") : name;
    for (const Command &c : commands)
        if (canonical == QLatin1String(c.name))
            return &c;
    return nullptr;
}

void usage()
{
    out() << Tr::tr("Usage: attractor-cli <command> [options]") << "\n\n"
          << Tr::tr("Commands:") << "\n";
    for (const Command &c : commands)
        out() << QStringLiteral("  %1  %2").arg(QString::fromLatin1(c.name), -10)
                     .arg(QCoreApplication::translate("awb::cli", c.summary))
              << "\n";
    out() << "\n" << Tr::tr("Run 'attractor-cli <command> --help' for the options of a command.")
          << "\n";
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
    const Command *c = findCommand(command);
    if (!c) {
        err() << Tr::tr("attractor-cli: unknown command '%1'").arg(command) << "\n";
        usage();
        return 2;
    }
    if (c->machineOutput)
        setMessageTranslator(nullptr);
    args.removeAt(1);
    args[0] = "attractor-cli " + command;
    try {
        return c->run(args);
    } catch (const InputError &e) {
        err() << "attractor-cli " << command << ": " << e.what() << "\n";
        return 1;
    }
}
