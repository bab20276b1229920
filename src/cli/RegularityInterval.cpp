// attractor-cli regularity-interval: where a curve item's scheme is C^k as one of its real
// parameters (the four-point tension omega, a corner cutting's a or b, a free coefficient of a
// mask written in --mask) moves over a range --
// the certified Hölder bounds of each member (model/SchemeRegularity, core Regularity) and
// bisection on them (core RegularityFamily). The same computation as the window's Four-point
// Regularity Chart bands.

#include "cli/CommandSupport.h"
#include "cli/ProjectCommands.h"

#include "core/analysis/RegularityFamily.h"
#include "model/AttractorItem.h"
#include "model/Project.h"
#include "model/SchemeFamily.h"
#include "model/SchemeRegularity.h"
#include "model/SubdivisionCurveItem.h"

#include <QCommandLineParser>
#include <QJsonArray>
#include <QJsonObject>

#include <cmath>
#include <optional>

namespace awb::cli {

namespace {

QJsonObject boundaryJson(const FamilyBoundary &b)
{
    // "certified_not": the outer value is certified not C^k; false at the range's end or where
    // the bounds could not decide.
    return QJsonObject{{"inner", b.inner},
                       {"outer", b.outer},
                       {"width", b.width()},
                       {"range_end", b.rangeEnd},
                       {"certified_not", !b.rangeEnd && !b.undecided}};
}

} // namespace

int regularityInterval(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(CliTr::tr(
            "Where a curve scheme is C^k as one of its parameters moves: the parameter "
            "intervals on which the certified Hölder exponent exceeds k, each end bracketed by "
            "bisection on certified values."));
        parser.addPositionalArgument("project", CliTr::tr("The project file (.awb)."));
        parser.addOptions(
            {{"item", CliTr::tr("The curve item (default: the first item with an attractor)."),
              "name"},
             {"parameter", CliTr::tr("omega (four-point), a or b (corner cutting), or the "
                                     "name used in --mask."),
              "name"},
             {"mask", CliTr::tr("For a mask item: its coefficients with the parameter in "
                                "them, e.g. \"-w, 0, 1/2 + w, 1, 1/2 + w, 0, -w\"."),
              "coefficients"},
             {"from", CliTr::tr("The start of the range."), "value"},
             {"to", CliTr::tr("The end of the range."), "value"},
             {"smoothness", CliTr::tr("k: the class C^k asked for (default 1)."), "k", "1"},
             {"grid", CliTr::tr("Values of the first sweep, 2 to 10000 (default 24)."), "n",
              "24"},
             {"tolerance", CliTr::tr("Bracket width at which bisection stops (default 1e-6)."),
              "width", "1e-6"},
             {"budget", CliTr::tr("Seconds of joint spectral radius per value (default 0.3)."),
              "seconds", "0.3"},
             {"json", CliTr::tr("Print JSON instead of text.")}});
        parseOrFail(parser, args, 1);
        Project project;
        load(project, parser.positionalArguments().at(0));
        auto *curve = qobject_cast<SubdivisionCurveItem *>(
            attractorItem(project, parser.value("item")));
        if (!curve)
            throw Failure{CliTr::tr("item '%1' is not a subdivision curve: its scheme has no "
                                    "parameter to move")
                              .arg(parser.value("item"))};
        const QString name = parser.value("parameter").toLower();
        // The item's scheme with the parameter moved (model/SchemeFamily): the same members
        // as the regularity atlas and the window's chart.
        const std::optional<SchemeFamily> family = [&]() -> std::optional<SchemeFamily> {
            try {
                return SchemeFamily::ofItem(*curve, {parser.value("parameter")},
                                            parser.value("mask"));
            } catch (const InputError &e) {
                throw Failure{QString::fromStdString(e.what()), 2};
            }
        }();
        if (!parser.isSet("from") || !parser.isSet("to"))
            throw Failure{CliTr::tr("--from and --to are required"), 2};
        const double from = realOption(parser, "from", -1e6, 1e6);
        const double to = realOption(parser, "to", -1e6, 1e6);
        const int k = intOption(parser, "smoothness", 0, 30);
        FamilyOptions options;
        options.grid = intOption(parser, "grid", 2, 10000);
        options.tolerance = realOption(parser, "tolerance", 1e-15, 1e6);
        options.budgetPerValue = realOption(parser, "budget", 1e-3, 600);
        const auto member = [&](double t, const RegularityOptions &o) {
            return family->regularity({t}, o);
        };
        const FamilyResult result = regularityInterval(member, from, to, k, options);

        if (parser.isSet("json")) {
            QJsonArray runs;
            for (const FamilyRun &run : result.runs)
                runs.append(QJsonObject{{"from", boundaryJson(run.from)},
                                        {"to", boundaryJson(run.to)}});
            QJsonArray samples;
            for (const FamilySample &s : result.samples)
                samples.append(QJsonObject{{"parameter", s.parameter},
                                           {"lower", s.applies ? QJsonValue(s.lower)
                                                               : QJsonValue::Null},
                                           {"upper", s.applies ? QJsonValue(s.upper)
                                                               : QJsonValue::Null}});
            printJson(QJsonObject{{"item", curve->name()},
                                  {"parameter", name},
                                  {"smoothness", k},
                                  {"range", QJsonArray{from, to}},
                                  {"intervals", runs},
                                  {"evaluations", int(result.samples.size())},
                                  {"seconds", result.seconds},
                                  {"samples", samples}});
            return 0;
        }
        out() << CliTr::tr("%1: C^%2 for %3 in %4 interval(s) of [%5, %6]")
                     .arg(curve->name())
                     .arg(k)
                     .arg(name)
                     .arg(result.runs.size())
                     .arg(from)
                     .arg(to)
              << "\n";
        const auto end = [](const FamilyBoundary &b) {
            if (b.rangeEnd)
                return CliTr::tr("%1 (the range's end)").arg(b.inner, 0, 'g', 10);
            return CliTr::tr("in [%1, %2]%3")
                .arg(std::min(b.inner, b.outer), 0, 'g', 10)
                .arg(std::max(b.inner, b.outer), 0, 'g', 10)
                .arg(b.undecided ? CliTr::tr(" (the bounds cannot decide beyond)") : QString());
        };
        for (const FamilyRun &run : result.runs)
            out() << CliTr::tr("  from %1 to %2").arg(end(run.from), end(run.to)) << "\n";
        out() << CliTr::tr("%1 evaluations, %2 s").arg(result.samples.size())
                     .arg(result.seconds, 0, 'g', 3)
              << "\n";
        return 0;
    });
}

} // namespace awb::cli
