// attractor-cli import: the IFS files of other tools as a project (issue 34) -- every entry of
// a Fractint .ifs file (2D and 3D), every flame of a flam3 file (.flame, .flam3), as a custom
// fractal with control points. Entries that are malformed are named with their line and
// column on stderr (exit 1), the others are kept; what was kept with a loss (a flame's
// non-linear variation) is a warning on stderr.

#include "cli/CommandSupport.h"
#include "cli/ProjectCommands.h"

#include "model/FlameExchange.h"
#include "model/IfsExchange.h"
#include "model/Item.h"
#include "model/Project.h"
#include "model/ProjectIO.h"

#include <QCommandLineParser>
#include <QFileInfo>
#include <QSet>

namespace awb::cli {

int importFile(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(CliTr::tr(
            "Make a project of another tool's IFS file: every entry of a Fractint .ifs file (2D "
            "and 3D, the format of Fractint, xfractint and the IFS Construction Kit), or every "
            "flame of a flam3 genome (.flame, .flam3: flam3, Apophysis, JWildfire): a flame of "
            "affine maps as a fractal with control points, any other as a fractal flame item "
            "drawn by flam3's chaos game (a variation this program does not know is named in "
            "a warning)."));
        parser.addPositionalArgument("file",
                                     CliTr::tr("The file to import (.ifs, .flame, .flam3)."));
        parser.addOptions({{"out", CliTr::tr("The project file to write (.awb)."), "file"}});
        parseOrFail(parser, args, 1);
        if (!parser.isSet("out"))
            throw Failure{CliTr::tr("--out FILE (the project to write) is required"), 2};
        const QString file = parser.positionalArguments().first();
        const QString suffix = QFileInfo(file).suffix().toLower();
        const bool flame = suffix == "flame" || suffix == "flam3";
        if (suffix != "ifs" && !flame)
            throw Failure{
                CliTr::tr("%1: import reads Fractint .ifs and flam3 .flame (.flam3) files")
                    .arg(file),
                2};
        ImportedItems imported;
        try {
            imported = flame ? importFlame(file) : importFractint(file);
        } catch (const InputError &e) {
            throw Failure{QString::fromStdString(e.what())};
        }
        for (const QString &p : imported.problems)
            err() << "attractor-cli: " << p << "\n";
        for (const QString &w : imported.warnings)
            err() << "attractor-cli: " << CliTr::tr("warning: %1").arg(w) << "\n";
        if (imported.items.empty())
            throw Failure{CliTr::tr("%1: no entry could be imported").arg(file)};
        Project project;
        QStringList names;
        QSet<QString> taken;
        for (auto &item : imported.items) {
            // Entries of one file may share a name: the project's names are unique (a set of
            // the names so far, so that a file of many entries of one name imports in linear
            // time).
            const QString base = item->name();
            QString name = base;
            for (int k = 2; taken.contains(name); ++k)
                name = QStringLiteral("%1 (%2)").arg(base).arg(k);
            taken.insert(name);
            item->setName(name);
            names << project.addItem(std::move(item))->name();
        }
        // What the import writes, the program must load: a project larger than a project file
        // may be is refused before it is written.
        const QByteArray bytes = project.serialize();
        if (bytes.size() > ProjectIO::maxFileBytes)
            throw Failure{CliTr::tr("%1: its %2 entries make a project of %3 MB, more than the "
                                    "%4 MB a project file may be")
                              .arg(file)
                              .arg(names.size())
                              .arg(bytes.size() / (1024 * 1024))
                              .arg(ProjectIO::maxFileBytes / (1024 * 1024))};
        QString error;
        if (!ProjectIO::writeFile(parser.value("out"), bytes, &error))
            throw Failure{error};
        out() << CliTr::tr("%1: %n item(s): %2\n", nullptr, int(names.size()))
                     .arg(parser.value("out"), names.join(QStringLiteral(", ")));
        return imported.problems.isEmpty() ? 0 : 1;
    });
}

} // namespace awb::cli
