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
#include "model/SchemeRegularity.h"
#include "model/SubdivisionCurveItem.h"

#include <QCommandLineParser>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

#include <cmath>

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
        const SchemeSpec base = curve->scheme();
        double SchemeSpec::*field = nullptr;
        if (name == "omega" && base.kind == SchemeSpec::Kind::FourPoint)
            field = &SchemeSpec::omega;
        else if (name == "a" && base.kind == SchemeSpec::Kind::CornerCutting)
            field = &SchemeSpec::a;
        else if (name == "b" && base.kind == SchemeSpec::Kind::CornerCutting)
            field = &SchemeSpec::b;
        // A mask with a free coefficient: --mask "-w, 0, 1/2 + w, 1, 1/2 + w, 0, -w" on a mask
        // item (its arity and first index), the parameter's name standing for its value.
        const QString pattern = parser.value("mask");
        const QRegularExpression variable(
            QStringLiteral("\\b%1\\b").arg(QRegularExpression::escape(parser.value("parameter"))));
        if (parser.isSet("mask")) {
            if (base.kind != SchemeSpec::Kind::Mask)
                throw Failure{CliTr::tr("--mask needs a mask item; '%1' is %2")
                                  .arg(curve->name(),
                                       SchemeSpec::kindNames().at(int(base.kind))),
                              2};
            static const QRegularExpression identifier(QStringLiteral("^[A-Za-z_]\\w*$"));
            static const QStringList reserved{"pi", "e", "sqrt", "cbrt", "sin", "cos",
                                              "tan", "exp", "ln"};
            const QString p = parser.value("parameter");
            if (!identifier.match(p).hasMatch() || reserved.contains(p))
                throw Failure{CliTr::tr("the parameter of --mask must be a name that is not a "
                                        "function or constant (pi, e, sqrt, ...), got '%1'")
                                  .arg(p),
                              2};
            if (!pattern.contains(variable))
                throw Failure{CliTr::tr("the mask '%1' does not contain the parameter '%2'")
                                  .arg(pattern, p),
                              2};
        } else if (!field) {
            throw Failure{CliTr::tr("item '%1' (%2) has no parameter '%3': omega belongs to the "
                                    "four-point scheme, a and b to corner cutting; a mask item "
                                    "takes --mask with the parameter in its coefficients")
                              .arg(curve->name(), SchemeSpec::kindNames().at(int(base.kind)),
                                   parser.value("parameter")),
                          2};
        }
        if (!parser.isSet("from") || !parser.isSet("to"))
            throw Failure{CliTr::tr("--from and --to are required"), 2};
        const double from = realOption(parser, "from", -1e6, 1e6);
        const double to = realOption(parser, "to", -1e6, 1e6);
        const int k = intOption(parser, "smoothness", 0, 30);
        FamilyOptions options;
        options.grid = intOption(parser, "grid", 2, 10000);
        options.tolerance = realOption(parser, "tolerance", 1e-15, 1e6);
        options.budgetPerValue = realOption(parser, "budget", 1e-3, 600);
        const int m = int(curve->controlPoints(0).size());
        // Each member: the item's scheme with the parameter set; the item's own regularity
        // (model/SchemeRegularity) on a copy of the item, so nothing is computed another way.
        // Each member: the item's scheme with the parameter moved, analysed as the item's own
        // (model/SchemeRegularity); a member that does not exist (a >= b) is not C^k.
        const auto member = [&](double t, const RegularityOptions &o) {
            SchemeSpec s = base;
            if (field) {
                s.*field = t;
            } else {
                QString line = pattern;
                line.replace(variable, QStringLiteral("(%1)").arg(t, 0, 'g', 17));
                QString why;
                if (!s.setMaskLine(line, &why)) {
                    Regularity none;
                    none.message = why.toStdString();
                    return none;  // not a member: not C^k
                }
            }
            return specRegularity(s, m, o);
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
            out() << QJsonDocument(QJsonObject{{"item", curve->name()},
                                               {"parameter", name},
                                               {"smoothness", k},
                                               {"range", QJsonArray{from, to}},
                                               {"intervals", runs},
                                               {"evaluations", int(result.samples.size())},
                                               {"seconds", result.seconds},
                                               {"samples", samples}})
                         .toJson(QJsonDocument::Indented);
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
