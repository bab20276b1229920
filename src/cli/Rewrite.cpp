// attractor-cli rewrite: a project saved again in canonical form.

#include "cli/CommandSupport.h"
#include "cli/ProjectCommands.h"

#include "model/Project.h"

#include <QCommandLineParser>

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
        save(project, parser);
        return 0;
    });
}

} // namespace awb::cli
