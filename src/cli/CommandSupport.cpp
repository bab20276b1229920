#include "cli/CommandSupport.h"

#include "model/StartSetText.h"

#include "model/SubdivisionMeshItem.h"

#include "model/AttractorItem.h"
#include "model/FigureMetadata.h"
#include "model/PointExport.h"
#include "model/Project.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <mutex>

#include <unistd.h>

namespace awb::cli {

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

namespace {

void put(QByteArrayView bytes)
{
    std::fwrite(bytes.data(), 1, std::size_t(bytes.size()), stdout);
}

// Qt's own text of `value` as a document's top (4 spaces a level), without a final line break.
QByteArray qtText(const QJsonValue &value)
{
    QByteArray text;
    if (value.isObject())
        text = QJsonDocument(value.toObject()).toJson(QJsonDocument::Indented);
    else if (value.isArray())
        text = QJsonDocument(value.toArray()).toJson(QJsonDocument::Indented);
    else  // a scalar, as the one member of a compact array: "[v]"
        return QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact).chopped(1).sliced(1);
    text.chop(1);
    return text;
}

// `text` moved `depth` levels in: 4 * depth spaces after each line break.
void putIndented(const QByteArray &text, int depth)
{
    const QByteArray pad(4 * depth, ' ');
    qsizetype from = 0;
    for (qsizetype nl; (nl = text.indexOf('\n', from)) >= 0; from = nl + 1) {
        put(QByteArrayView(text).sliced(from, nl + 1 - from));
        put(pad);
    }
    put(QByteArrayView(text).sliced(from));
}

// Containers up to this size, below the first levels, are printed by Qt at once.
constexpr qsizetype kWhole = 64;

void printValue(const QJsonValue &value, int depth);

// n members at nesting `depth` + 1, as Qt's writer nests them (QJsonPrivate::Writer: the
// opening bracket and a line break, the members joined by ",\n", a line break after the last,
// the closing bracket at `depth`); member(i) prints member i.
template <class Member>
void printBracketed(const char *open, const char *close, qsizetype n, int depth, Member member)
{
    const QByteArray pad(4 * (depth + 1), ' ');
    put(open);
    put("\n");
    for (qsizetype i = 0; i < n; ++i) {
        put(i ? ",\n" : "");
        put(pad);
        member(i);
    }
    put(n ? "\n" : "");
    put(QByteArray(4 * depth, ' '));
    put(close);
}

// An object at `depth`, its `lists` (ItemAnalysisJson.h) printed member by member in their
// keys' places: the object's keys and the lists' merged in Qt's order (QString's, as
// std::map's).
void printObject(const QJsonObject &o, const std::map<QString, JsonList> &lists, int depth)
{
    auto it = o.begin();
    auto list = lists.begin();
    printBracketed("{", "}", o.size() + qsizetype(lists.size()), depth, [&](qsizetype) {
        if (list == lists.end() || (it != o.end() && it.key() < list->first)) {
            put(qtText(it.key()));
            put(": ");
            printValue(it.value(), depth + 1);
            ++it;
            return;
        }
        const JsonList &l = list->second;
        put(qtText(list->first));
        put(": ");
        printBracketed("[", "]", l.size, depth + 1,
                       [&](qsizetype i) { printValue(l.at(i), depth + 2); });
        ++list;
    });
}

// `value` at nesting `depth`: large arrays and the first levels' objects member by member, the
// rest by Qt's writer at once.
void printValue(const QJsonValue &value, int depth)
{
    if (value.isArray() && value.toArray().size() > kWhole) {
        const QJsonArray a = value.toArray();
        printBracketed("[", "]", a.size(), depth,
                       [&](qsizetype i) { printValue(a.at(i), depth + 1); });
    } else if (value.isObject() && !value.toObject().isEmpty()
               && (depth < 4 || value.toObject().size() > kWhole)) {
        printObject(value.toObject(), {}, depth);
    } else {
        putIndented(qtText(value), depth);
    }
}

} // namespace

void printJson(const QJsonObject &document)
{
    out().flush();
    printValue(document, 0);
    put("\n");
    std::fflush(stdout);
}

void printJsonList(const QString &key, const std::function<std::optional<ItemAnalysis>()> &next)
{
    out().flush();
    put("{\n    ");
    put(qtText(key));
    put(": [");
    bool first = true;
    for (std::optional<ItemAnalysis> v = next(); v; v = next()) {
        put(first ? "\n        " : ",\n        ");
        first = false;
        printObject(v->json, v->lists, 2);
    }
    put("\n    ]\n}\n");
    std::fflush(stdout);
}

std::function<void(double)> progressLine(const QString &what, bool always)
{
    const bool terminal = isatty(fileno(stderr)) != 0;
    if (!terminal && !always)
        return {};
    struct State {
        std::mutex mutex;
        QElapsedTimer clock;
        qint64 shownAt = -1;
        int percent = -1;
    };
    auto state = std::make_shared<State>();
    state->clock.start();
    const QByteArray name = what.toLocal8Bit();
    return [state, terminal, name](double fraction) {
        const std::lock_guard<std::mutex> lock(state->mutex);
        const qint64 ms = state->clock.elapsed();
        const int percent = int(std::clamp(fraction, 0.0, 1.0) * 100.0);
        const bool last = percent == 100;
        if (percent == state->percent || (terminal && ms < 1000 && !last)
            || (!last && state->shownAt >= 0 && ms - state->shownAt < 200))
            return;
        if (last && state->percent < 0 && terminal && ms < 1000)
            return;  // done before a line was worth showing
        state->percent = percent;
        state->shownAt = ms;
        QString line = CliTr::tr("%1: %2 % (%3 s").arg(QString::fromLocal8Bit(name))
                           .arg(percent)
                           .arg(double(ms) / 1000.0, 0, 'f', 1);
        if (percent > 0 && !last) {
            const double left = double(ms) / 1000.0 * (100.0 - percent) / percent;
            line += CliTr::tr(", about %1 s left").arg(left, 0, 'f', left < 10 ? 1 : 0);
        }
        line += QStringLiteral(")");
        const QByteArray text = line.toLocal8Bit();
        if (terminal)
            std::fprintf(stderr, "\r%s\033[K%s", text.constData(), last ? "\n" : "");
        else
            std::fprintf(stderr, "%s\n", text.constData());
        std::fflush(stderr);
    };
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
        throw Failure{CliTr::tr("expected %1 project file, got %2 arguments (see --help)")
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

void save(Project &project, const QCommandLineParser &parser)
{
    QString error;
    const QString target = parser.isSet("out") ? parser.value("out") : project.fileName();
    if (!project.saveAs(target, &error))
        throw Failure{error};
    out() << target << "\n";
}

AttractorItem *attractorItem(const Project &project, const QString &name)
{
    if (!name.isEmpty()) {
        Item *item = project.findItem(name);
        if (!item)
            throw Failure{CliTr::tr("no item named '%1' in %2")
                              .arg(name, project.fileName().isEmpty() ? CliTr::tr("the figure's "
                                                                               "project")
                                                                      : project.fileName())};
        auto *a = qobject_cast<AttractorItem *>(item);
        if (!a)
            throw Failure{CliTr::tr("item '%1' (%2) has no attractor").arg(name, item->typeName())};
        return a;
    }
    for (Item *item : project.items())
        if (auto *a = qobject_cast<AttractorItem *>(item))
            return a;
    throw Failure{CliTr::tr("%1 has no item with an attractor").arg(project.fileName())};
}

AttractorItem *namedOrOnlyAttractorItem(const Project &project, const QString &name)
{
    if (!name.isEmpty())
        return attractorItem(project, name);
    QList<AttractorItem *> items;
    for (Item *item : project.items())
        if (auto *a = qobject_cast<AttractorItem *>(item))
            items << a;
    if (items.size() == 1)
        return items.front();
    if (items.isEmpty())
        throw Failure{CliTr::tr("%1 has no item with an attractor").arg(project.fileName())};
    QStringList names;
    for (int i = 0; i < items.size() && i < 8; ++i)
        names << QLatin1Char('\'') + items[i]->name() + QLatin1Char('\'');
    if (items.size() > 8)
        names << CliTr::tr("… (%1 in all)").arg(items.size());
    throw Failure{CliTr::tr("--item NAME is required: %1 has %2 items with an attractor: %3")
                      .arg(project.fileName())
                      .arg(items.size())
                      .arg(names.join(QStringLiteral(", "))),
                  2};
}

std::shared_ptr<const DerivedIfs> derived(const AttractorItem *item)
{
    auto d = item->derivedIfs();
    if (!d)
        throw Failure{CliTr::tr("item '%1': %2").arg(item->name(), item->derivedError())};
    return d;
}

MeshScheme meshSchemeOption(const QCommandLineParser &parser)
{
    const int scheme = MeshInputs::schemeNames().indexOf(parser.value("scheme").toLower());
    if (scheme < 0)
        throw Failure{CliTr::tr("--scheme must be catmull-clark or loop, got '%1'")
                          .arg(parser.value("scheme")),
                      2};
    return MeshScheme(scheme);
}

int intOption(const QCommandLineParser &parser, const QString &name, int lo, int hi)
{
    bool ok = false;
    const int v = parser.value(name).toInt(&ok);
    if (!ok || v < lo || v > hi)
        throw Failure{CliTr::tr("--%1 must be a whole number from %2 to %3, got '%4'")
                          .arg(name)
                          .arg(lo)
                          .arg(hi)
                          .arg(parser.value(name))};
    return v;
}

// A count written as digits or in exponent form ("1e9"), whole, from lo to hi.
std::uint64_t countOption(const QCommandLineParser &parser, const QString &name, double lo,
                          double hi)
{
    bool ok = false;
    const double v = parser.value(name).toDouble(&ok);
    if (!ok || !std::isfinite(v) || v < lo || v > hi || v != std::floor(v))
        throw Failure{QCoreApplication::translate(
                          "awb::cli", "--%1 must be a whole number from %2 to %3, got '%4'")
                          .arg(name)
                          .arg(lo, 0, 'g', 12)
                          .arg(hi, 0, 'g', 12)
                          .arg(parser.value(name))};
    return std::uint64_t(v);
}

double realOption(const QCommandLineParser &parser, const QString &name, double lo, double hi)
{
    bool ok = false;
    const double v = parser.value(name).toDouble(&ok);
    if (!ok || !std::isfinite(v) || v < lo || v > hi)
        throw Failure{CliTr::tr("--%1 must be a number from %2 to %3, got '%4'")
                          .arg(name)
                          .arg(lo)
                          .arg(hi)
                          .arg(parser.value(name))};
    return v;
}

// The start set of --start TEXT: model/StartSetText's reading, its refusals as the option's.
StartSet startOption(const AttractorItem &item, const DerivedIfs &d, const QString &text)
{
    try {
        return startSetFromText(item, d, text);
    } catch (const StartSetTextError &e) {
        throw Failure{QStringLiteral("--start: ") + e.message, e.malformed ? 2 : 1};
    }
}

double requirePointBudget(const DerivedIfs &d, const StartSet &start, int depth, double maxPoints)
{
    // Items drawn by their own iteration (automata, meshes) say their count when they know it.
    const double n = exportPointCount(d, start, depth);
    if (n > maxPoints)
        throw Failure{CliTr::tr("depth %1 gives %2 points, more than --max-points %3")
                          .arg(depth)
                          .arg(n, 0, 'g', 4)
                          .arg(maxPoints, 0, 'g', 4)};
    return n;
}

} // namespace awb::cli
