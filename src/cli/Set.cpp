// attractor-cli set: an item's declared properties changed from the command line and the file
// saved atomically, or listed with their types, ranges and values. The same declaration as the
// Properties dock, Python's item.parameters and the file format (model/PropertyTable.h).

#include "cli/CommandSupport.h"
#include "cli/ProjectCommands.h"

#include "model/Item.h"
#include "model/Project.h"
#include "model/PropertyTable.h"

#include <QCommandLineParser>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>

#include <cmath>

namespace awb::cli {

namespace {

Item *findItem(const Project &project, const QString &name)
{
    if (name.isEmpty()) {
        if (project.childCount() == 0)
            throw Failure{CliTr::tr("the project has no items")};
        return project.child(0);
    }
    if (Item *item = project.findItem(name))
        return item;
    QStringList names;
    for (Item *i : project.items())
        names << QStringLiteral("\"%1\"").arg(i->name());
    throw Failure{CliTr::tr("no item called \"%1\"; the items: %2")
                      .arg(name, names.join(QStringLiteral(", ")))};
}

QString compact(const QJsonValue &v)
{
    if (v.isString())
        return v.toString();
    if (v.isDouble())  // the shortest text that reads back to the same number
        return QString::number(v.toDouble(), 'g', QLocale::FloatingPointShortest);
    if (v.isBool())
        return v.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    if (v.isNull() || v.isUndefined())
        return QString();
    const QByteArray json = v.isArray() ? QJsonDocument(v.toArray()).toJson(QJsonDocument::Compact)
                                        : QJsonDocument(v.toObject()).toJson(QJsonDocument::Compact);
    return QString::fromUtf8(json);
}

QString rangeText(const ParameterInfo &i)
{
    if (!std::isfinite(i.minimum) && !std::isfinite(i.maximum))
        return QString();
    const auto n = [](double x) {
        return std::isfinite(x) ? QString::number(x, 'g', QLocale::FloatingPointShortest)
                                : QStringLiteral("…");
    };
    return QStringLiteral("[%1, %2]").arg(n(i.minimum), n(i.maximum));
}

QJsonObject describeJson(const PropertyDescription &d)
{
    QJsonObject o{{"key", d.info.key},
                  {"type", d.typeName},
                  {"label", d.info.label},
                  {"value", d.value},
                  {"parameter", d.scalar},
                  {"read_only", d.info.readOnly}};
    if (!d.json.isEmpty())
        o["json"] = d.json;
    if (!d.info.group.isEmpty())
        o["group"] = d.info.group;
    if (!d.info.toolTip.isEmpty())
        o["help"] = d.info.toolTip;
    if (std::isfinite(d.info.minimum))
        o["minimum"] = d.info.minimum;
    if (std::isfinite(d.info.maximum))
        o["maximum"] = d.info.maximum;
    if (!d.spellings.isEmpty())
        o["spellings"] = QJsonArray::fromStringList(d.spellings);
    if (!d.info.choices.isEmpty())
        o["choices"] = QJsonArray::fromStringList(d.info.choices);
    return o;
}

} // namespace

int set(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            CliTr::tr("Set properties of an item and save the project (atomically: all of them "
                      "or none), or list them. A value is typed as in the Properties dock: a "
                      "number (3/8 and sqrt(3) too), a choice by its number, its word in the "
                      "file or its text, true or false, a complex number as 0.5,0.3 or "
                      "0.5+0.3i; a structured value (points, matrices, a list) as JSON."));
        parser.addPositionalArgument("project", CliTr::tr("The .awb project file."));
        parser.addPositionalArgument("key=value", CliTr::tr("Properties to set, in order."),
                                     "[key=value...]");
        parser.addOption({"item", CliTr::tr("The item (default: the first)."), "name"});
        parser.addOption({"list", CliTr::tr("List the item's properties: key, type, value, "
                                            "range and choices.")});
        parser.addOption({"json", CliTr::tr("With --list: as JSON.")});
        parser.addOption({"out", CliTr::tr("Write here instead of over the input."), "file"});
        parser.addHelpOption();
        if (!parser.parse(args))
            throw Failure{parser.errorText(), 2};
        if (parser.isSet("help")) {
            out() << parser.helpText();
            return 0;
        }
        const QStringList positional = parser.positionalArguments();
        if (positional.isEmpty())
            throw Failure{CliTr::tr("expected a project file; see --help"), 2};
        Project project;
        load(project, positional.first());
        Item *item = findItem(project, parser.value("item"));
        const PropertyTable &table = item->properties();
        if (parser.isSet("list")) {
            if (positional.size() > 1)
                throw Failure{CliTr::tr("--list takes no key=value"), 2};
            const QList<PropertyDescription> all = table.describe(*item);
            if (parser.isSet("json")) {
                QJsonArray list;
                for (const PropertyDescription &d : all)
                    list.append(describeJson(d));
                printJson(QJsonObject{{"item", item->name()},
                                      {"type", item->type()},
                                      {"properties", list}});
                return 0;
            }
            out() << CliTr::tr("%1 (%2)").arg(item->name(), item->type()) << "\n";
            for (const PropertyDescription &d : all) {
                QString value = compact(d.value);
                if (value.size() > 60)
                    value = value.left(57) + QStringLiteral("...");
                QString line = QStringLiteral("  %1  %2  %3").arg(d.info.key, -24).arg(
                    d.typeName, -10).arg(value);
                if (const QString range = rangeText(d.info); !range.isEmpty())
                    line += QStringLiteral("  ") + range;
                if (!d.spellings.isEmpty())
                    line += QStringLiteral("  {%1}").arg(d.spellings.join(QLatin1Char('|')));
                if (d.info.readOnly)
                    line += QStringLiteral("  ") + CliTr::tr("(shown, not set)");
                out() << line.trimmed().prepend(QStringLiteral("  ")) << "\n";
            }
            return 0;
        }
        if (positional.size() < 2)
            throw Failure{CliTr::tr("nothing to set: give key=value (or --list)"), 2};
        for (const QString &assignment : positional.mid(1)) {
            const qsizetype eq = assignment.indexOf(QLatin1Char('='));
            if (eq <= 0)
                throw Failure{CliTr::tr("\"%1\" is not key=value").arg(assignment), 2};
            const QString key = assignment.left(eq).trimmed();
            QString why;
            if (!table.setText(*item, key, assignment.mid(eq + 1), &why))
                throw Failure{why.startsWith(key) ? why
                                                  : QStringLiteral("%1: %2").arg(key, why)};
        }
        save(project, parser);
        return 0;
    });
}

} // namespace awb::cli
