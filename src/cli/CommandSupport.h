#pragma once
// What every attractor-cli command shares (the commands: one file each, ProjectCommands.h):
// its streams, the user error it raises with an exit code, option parsing, loading a project
// and finding its items. Exit codes: 0 success, 1 bad input, 2 usage error.

#include "core/Types.h"
#include "core/ifs/Attractor.h"
#include "core/mesh/Mesh.h"
#include "model/ItemAnalysisJson.h"
#include "render/FigureFile.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QTextStream>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

namespace awb {
class AttractorItem;
class Item;
class Project;
struct DerivedIfs;
} // namespace awb

namespace awb::cli {

// The translation context of every command's messages (lupdate reads it from the macro).
struct CliTr {
    Q_DECLARE_TR_FUNCTIONS(awb::cli)
};

QTextStream &out();
QTextStream &err();

// Prints `document` on stdout as QJsonDocument::Indented writes it, byte for byte, without
// ever holding the whole text: large arrays and objects are written member by member (a mesh's
// analysis lists hundreds of thousands of vertices; its text as one QByteArray, then through
// QTextStream's QString, took five times the text's size).
void printJson(const QJsonObject &document);
// The document {"key": [ ... ]}, its members printed as `next` gives them (none ends the list):
// each is printed and released before the next is made, its lists (ItemAnalysisJson.h) member
// by member in their keys' places.
void printJsonList(const QString &key, const std::function<std::optional<ItemAnalysis>()> &next);

// Raised for a user error with its exit code; caught at the command's top by guarded().
struct Failure {
    QString message;
    int code = 1;
};

// Adds --help, parses, and checks the number of positional arguments (Failure otherwise).
void parseOrFail(QCommandLineParser &parser, const QStringList &args, int positional);
void load(Project &project, const QString &file);
// Saves `project` atomically to --out, or over the file it was opened from; prints the file.
void save(Project &project, const QCommandLineParser &parser);
// The item named `name` (the first item with an attractor when empty).
AttractorItem *attractorItem(const Project &project, const QString &name);
// The item `name`, or without a name the project's only item with an attractor; a project of
// several such items needs --item, and the message lists their names (exit 2).
AttractorItem *namedOrOnlyAttractorItem(const Project &project, const QString &name);
std::shared_ptr<const DerivedIfs> derived(const AttractorItem *item);
int intOption(const QCommandLineParser &parser, const QString &name, int lo, int hi);
// --scheme of the mesh commands: catmull-clark or loop (exit 2 otherwise).
MeshScheme meshSchemeOption(const QCommandLineParser &parser);
// A progress line on stderr for a long computation (`render`): the returned function takes
// the fraction done, from any thread. On a terminal it is one line rewritten in place, from
// the first second on; with `always` (--progress) it is also written to a file or a pipe, one
// line per report, from the start. Nothing otherwise.
std::function<void(double)> progressLine(const QString &what, bool always);
// A count written as digits or in exponent form ("1e9"), whole, from lo to hi.
std::uint64_t countOption(const QCommandLineParser &parser, const QString &name, double lo,
                          double hi);
double realOption(const QCommandLineParser &parser, const QString &name, double lo, double hi);
// The start set of `--start TEXT` (model/StartSetText.h: point:x,y | segment:... | ... |
// lifted:... | vertex-limits); Failure naming the option otherwise (exit 2 for a text that is
// none of the forms).
StartSet startOption(const AttractorItem &item, const DerivedIfs &d, const QString &text);
// The points F^depth(start) makes (Failure when more than maxPoints).
double requirePointBudget(const DerivedIfs &d, const StartSet &start, int depth,
                          double maxPoints);

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
