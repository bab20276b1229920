#include "cli/CommandSupport.h"

#include "model/AttractorItem.h"
#include "model/Project.h"

#include <QCoreApplication>

namespace awb::cli {

namespace {

// lupdate takes the context of CommandSupportTr::tr() from the macro (the context of every
// command's messages).
struct CommandSupportTr {
    Q_DECLARE_TR_FUNCTIONS(awb::cli)
};

} // namespace

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

void parseOrFail(QCommandLineParser &parser, const QStringList &args, int positional)
{
    parser.addHelpOption();
    if (!parser.parse(args))
        throw Failure{parser.errorText(), 2};
    if (parser.isSet("help")) {
        out() << parser.helpText();
        throw Failure{{}, 0};
    }
    if (parser.positionalArguments().size() != positional)
        throw Failure{CommandSupportTr::tr("expected %1 project file, got %2 arguments (see --help)")
                          .arg(positional)
                          .arg(parser.positionalArguments().size()),
                      2};
}

void load(Project &project, const QString &file)
{
    QString error;
    if (!project.open(file, &error))
        throw Failure{error, 1};
}

AttractorItem *attractorItem(const Project &project, const QString &name)
{
    if (!name.isEmpty()) {
        Item *item = project.findItem(name);
        if (!item)
            throw Failure{CommandSupportTr::tr("no item named '%1' in %2")
                              .arg(name, project.fileName().isEmpty() ? CommandSupportTr::tr("the figure's "
                                                                               "project")
                                                                      : project.fileName())};
        auto *a = qobject_cast<AttractorItem *>(item);
        if (!a)
            throw Failure{CommandSupportTr::tr("item '%1' (%2) has no attractor").arg(name, item->typeName())};
        return a;
    }
    for (Item *item : project.items())
        if (auto *a = qobject_cast<AttractorItem *>(item))
            return a;
    throw Failure{CommandSupportTr::tr("%1 has no item with an attractor").arg(project.fileName())};
}

std::shared_ptr<const DerivedIfs> derived(const AttractorItem *item)
{
    auto d = item->derivedIfs();
    if (!d)
        throw Failure{CommandSupportTr::tr("item '%1': %2").arg(item->name(), item->derivedError())};
    return d;
}

int intOption(const QCommandLineParser &parser, const QString &name, int lo, int hi)
{
    bool ok = false;
    const int v = parser.value(name).toInt(&ok);
    if (!ok || v < lo || v > hi)
        throw Failure{CommandSupportTr::tr("--%1 must be a whole number from %2 to %3, got '%4'")
                          .arg(name)
                          .arg(lo)
                          .arg(hi)
                          .arg(parser.value(name))};
    return v;
}

} // namespace awb::cli
