#pragma once
// What every attractor-cli command shares (the commands: ProjectCommands.cpp, ImportMesh.cpp):
// its streams, the user error it raises with an exit code, option parsing, loading a project
// and finding its items. Exit codes: 0 success, 1 bad input, 2 usage error.

#include "core/Types.h"

#include <QCommandLineParser>
#include <QString>
#include <QTextStream>

#include <memory>

namespace awb {
class AttractorItem;
class Project;
struct DerivedIfs;
} // namespace awb

namespace awb::cli {

QTextStream &out();
QTextStream &err();

// Raised for a user error with its exit code; caught at the command's top by guarded().
struct Failure {
    QString message;
    int code = 1;
};

// Adds --help, parses, and checks the number of positional arguments (Failure otherwise).
void parseOrFail(QCommandLineParser &parser, const QStringList &args, int positional);
void load(Project &project, const QString &file);
// The item named `name` (the first item with an attractor when empty).
AttractorItem *attractorItem(const Project &project, const QString &name);
std::shared_ptr<const DerivedIfs> derived(const AttractorItem *item);
int intOption(const QCommandLineParser &parser, const QString &name, int lo, int hi);

// Runs a command's body: a Failure or an InputError becomes its message on stderr and the exit
// code.
template<class F>
int guarded(F &&body)
{
    try {
        return body();
    } catch (const Failure &f) {
        if (!f.message.isEmpty())
            err() << "attractor-cli: " << f.message << "\n";
        return f.code;
    } catch (const InputError &e) {
        err() << "attractor-cli: " << e.what() << "\n";
        return 1;
    }
}

} // namespace awb::cli
