#include "cli/ProjectCommands.h"

#include "cli/FigureRenderer.h"
#include "core/analysis/Geometry.h"
#include "core/analysis/Spectrum.h"
#include "model/AttractorItem.h"
#include "model/ExactCurve.h"
#include "model/Project.h"
#include "model/SubdivisionCurveItem.h"

#include <QCommandLineParser>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTextStream>

namespace awb::cli {

namespace {

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

// Raised for a user error with its exit code; caught at the command's top.
struct Failure {
    QString message;
    int code = 1;
};

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
        throw Failure{QString("expected %1 project file, got %2 arguments (see --help)")
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
            throw Failure{QString("no item named '%1' in %2").arg(name, project.fileName())};
        auto *a = qobject_cast<AttractorItem *>(item);
        if (!a)
            throw Failure{QString("item '%1' (%2) has no attractor").arg(name, item->typeName())};
        return a;
    }
    for (Item *item : project.items())
        if (auto *a = qobject_cast<AttractorItem *>(item))
            return a;
    throw Failure{QString("%1 has no item with an attractor").arg(project.fileName())};
}

std::shared_ptr<const DerivedIfs> derived(const AttractorItem *item)
{
    auto d = item->derivedIfs();
    if (!d)
        throw Failure{QString("item '%1': %2").arg(item->name(), item->derivedError())};
    return d;
}

int intOption(const QCommandLineParser &parser, const QString &name, int lo, int hi)
{
    bool ok = false;
    const int v = parser.value(name).toInt(&ok);
    if (!ok || v < lo || v > hi)
        throw Failure{QString("--%1 must be a whole number from %2 to %3, got '%4'")
                          .arg(name)
                          .arg(lo)
                          .arg(hi)
                          .arg(parser.value(name))};
    return v;
}

// "point:x,y", "segment:x1,y1,x2,y2", "triangle:...", "polygon:...", "points:..."
StartSet::Kind parseStart(const QString &text, Mat *points)
{
    const int colon = text.indexOf(':');
    const QString kind = text.left(colon);
    const QStringList numbers = text.mid(colon + 1).split(',', Qt::SkipEmptyParts);
    QList<double> v;
    for (const QString &n : numbers) {
        bool ok = false;
        v << n.trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(v.back()))
            throw Failure{QString("--start: '%1' is not a finite number").arg(n)};
    }
    const QMap<QString, int> count = {{"point", 1}, {"segment", 2}, {"triangle", 3}};
    if (colon < 0 || !(count.contains(kind) || kind == "polygon" || kind == "points"))
        throw Failure{QString("--start must be point:x,y | segment:x1,y1,x2,y2 | "
                              "triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:..., got '%1'")
                          .arg(text),
                      2};
    if (v.size() % 2 || v.isEmpty() || (count.contains(kind) && v.size() != 2 * count[kind])
        || (kind == "polygon" && v.size() < 6))
        throw Failure{QString("--start %1 needs %2 coordinates, got %3")
                          .arg(kind)
                          .arg(count.contains(kind) ? QString::number(2 * count[kind])
                                                    : QString("an even number of"))
                          .arg(v.size())};
    *points = Mat(v.size() / 2, 2);
    for (int i = 0; i < v.size() / 2; ++i)
        (*points)(i, 0) = v[2 * i], (*points)(i, 1) = v[2 * i + 1];
    if (kind == "segment")
        return StartSet::Kind::Polyline;
    if (kind == "triangle" || kind == "polygon")
        return StartSet::Kind::Polygon;
    return StartSet::Kind::Points;
}

QJsonArray complexJson(Complex z) { return {z.real(), z.imag()}; }

QJsonObject analyseItem(const AttractorItem *item)
{
    QJsonObject o;
    o["name"] = item->name();
    o["type"] = item->type();
    auto d = item->derivedIfs();
    if (!d) {
        o["error"] = item->derivedError();
        return o;
    }
    if (!d->note.isEmpty())
        o["note"] = d->note;
    // Per map: the eigenvalues of S_i as the item defines them, contractivity of f_i, and
    // its fixed point in the plane.
    QJsonArray maps, subdominants;
    double worstSub = -1;
    const int count = d->S.count();
    for (int i = 0; i < count; ++i) {
        const Spectrum s = d->S.isComplex() ? spectrum(d->S.complex[i]) : spectrum(d->S.real[i]);
        QJsonObject m;
        QJsonArray ev;
        for (const Complex &z : s.values)
            ev.append(complexJson(z));
        m["eigenvalues"] = ev;
        m["spectral_radius"] = s.spectralRadius;
        const Subdominant sub = subdominant(s);
        m["subdominant"] = [&] {
            QJsonArray a;
            for (const Complex &z : sub.values)
                a.append(complexJson(z));
            return a;
        }();
        m["subdominant_kind"] = QString::fromStdString(toString(sub.kind));
        if (i < d->ifs.size()) {
            const Contractivity c = contractivity(d->ifs.effectiveLinearPart(i));
            m["contractive"] = c.eventuallyContractive;
            m["contraction_norm"] = c.normFactor;
            const auto fp = fixedPoint(d->ifs.maps[i]);
            if (fp && !d->ifs.views.empty()) {
                const Mat p = project(d->ifs.views.front(), Mat(*fp));
                m["fixed_point"] = QJsonArray{p(0, 0), p(0, 1)};
            } else {
                m["fixed_point"] = QJsonValue::Null;
            }
        }
        maps.append(m);
        if (sub.modulus > worstSub + 1e-12) {
            worstSub = sub.modulus;
            subdominants = QJsonArray();
            for (const Complex &z : sub.values)
                subdominants.append(complexJson(z));
        }
    }
    o["maps"] = maps;
    o["subdominant"] = subdominants;
    if (d->subdivision) {
        o["lifting_invertible"] = d->subdivision->lifting.invertible;
        if (!d->subdivision->lifting.invertible)
            o["lifting_problem"] = QString::fromStdString(d->subdivision->lifting.reason);
    }
    // Box-counting dimension of the attractor at a depth giving about 2^18 points.
    o["box_dimension"] = QJsonValue::Null;
    try {
        if (d->ifs.size() > 1 && !d->iterate && !d->ifs.views.empty()) {
            const StartSet start = item->coreStartSet(*d);
            int depth = 1;
            while (imageCount(d->ifs, depth + 1) * start.vertices.rows() <= 300000)
                ++depth;
            PointCollector c(d->ifs.views.front());
            iterate(d->ifs, StartSet::points(start.vertices), depth, c);
            const BoxDimension b = boxCountingDimension(c.points());
            if (b.valid) {
                o["box_dimension"] = b.dimension;
                o["box_dimension_fit"] = QJsonObject{{"r2", b.r2},
                                                     {"levels", QJsonArray{b.levelFrom, b.levelTo}},
                                                     {"points", double(c.points().rows())}};
            }
        }
    } catch (const InputError &e) {
        o["box_dimension_error"] = QString::fromStdString(e.what());
    }
    return o;
}

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

} // namespace

int render(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            "Render an item's attractor (with its control polygons) to PNG, SVG or PDF.");
        parser.addPositionalArgument("project", "The .awb project file.");
        parser.addOptions({{"item", "The item to render (default: the first with an attractor).",
                            "name"},
                           {"out", "Output file: .png, .svg or .pdf.", "file"},
                           {"size", "Image size in pixels (default 900x700).", "WxH", "900x700"},
                           {"depth", "Deterministic iteration depth (default: the item's).", "k"},
                           {"samples", "Random iteration with this many points.", "n"}});
        parseOrFail(parser, args, 1);
        if (!parser.isSet("out"))
            throw Failure{"--out FILE is required", 2};
        if (parser.isSet("depth") && parser.isSet("samples"))
            throw Failure{"--depth and --samples exclude each other", 2};
        const QRegularExpression sizeRe("^(\\d+)x(\\d+)$");
        const auto sm = sizeRe.match(parser.value("size"));
        if (!sm.hasMatch() || sm.captured(1).toInt() < 64 || sm.captured(2).toInt() < 64
            || sm.captured(1).toInt() > 16384 || sm.captured(2).toInt() > 16384)
            throw Failure{QString("--size must be WxH with 64..16384 pixels each, got '%1'")
                              .arg(parser.value("size"))};
        Project project;
        load(project, parser.positionalArguments().first());
        AttractorItem *item = attractorItem(project, parser.value("item"));
        auto d = derived(item);
        const AlgorithmSpec &alg = item->algorithm();
        FigureSpec spec;
        spec.ifs = &d->ifs;
        spec.iterate = d->iterate;
        spec.random = parser.isSet("samples")
                      || (alg.mode == AlgorithmSpec::Mode::Random && !parser.isSet("depth"));
        spec.samples = parser.isSet("samples")
                           ? std::uint64_t(intOption(parser, "samples", 1, 2000000000))
                           : std::uint64_t(alg.samples);
        spec.seed = std::uint64_t(alg.seed);
        const int depth = parser.isSet("depth") ? intOption(parser, "depth", 0, 64) : alg.depth;
        if (d->ifs.size() > 0 && !spec.random && !d->iterate) {
            const IfsCheck check = checkIfs(d->ifs);
            if (!check.contractive)
                throw Failure{QString("item '%1': %2").arg(item->name(),
                                                           QString::fromStdString(check.message))};
            const double images = imageCount(d->ifs, depth);
            if (images > 4e9)
                throw Failure{QString("depth %1 makes %2 images; at most 4e9 are rendered")
                                  .arg(depth)
                                  .arg(images, 0, 'g', 3)};
        }
        if (d->ifs.size() > 0 || d->iterate)
            spec.start = item->coreStartSet(*d);
        for (int s = 0; s < item->controlPointSetCount(); ++s)
            if (!item->controlPoints(s).empty())
                spec.controlPolygons.push_back(toMatrix(item->controlPoints(s)));
        if (d->polygon)
            spec.polygons.push_back(*d->polygon);
        if (const auto exact = exactCurveOf(item, 800))
            spec.overlays.push_back(exact->points);
        spec.panelWidth = sm.captured(1).toInt();
        spec.panelHeight = sm.captured(2).toInt() - 26;
        QString caption = spec.random
                              ? QString("%1: %2 random points").arg(item->name()).arg(spec.samples)
                              : QString("%1: F^%2(X0)").arg(item->name()).arg(depth);
        if (d->polygon) // a normal-vector curve: the polygon after `steps` is the figure
            caption = QString("%1: polygon after %2 steps")
                          .arg(item->name())
                          .arg(item->parameter("steps").toInt());
        spec.panels = {{caption, depth}};
        QString error;
        if (!writeFigure(spec, parser.value("out"), &error))
            throw Failure{error};
        out() << parser.value("out") << "\n";
        return 0;
    });
}

int analyse(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            "Analyse the items of a project: eigenvalues of each S_i, spectral radius, "
            "contractivity and fixed point of each map, subdominant eigenvalues, box-counting "
            "dimension of the attractor.");
        parser.addPositionalArgument("project", "The .awb project file.");
        parser.addOptions({{"item", "Only this item.", "name"},
                           {"json", "Print JSON (the only format so far)."}});
        parseOrFail(parser, args, 1);
        if (!parser.isSet("json"))
            throw Failure{"--json is required (the only output format)", 2};
        Project project;
        load(project, parser.positionalArguments().first());
        QJsonArray items;
        if (parser.isSet("item")) {
            items.append(analyseItem(attractorItem(project, parser.value("item"))));
        } else {
            for (Item *item : project.items())
                if (auto *a = qobject_cast<AttractorItem *>(item))
                    items.append(analyseItem(a));
        }
        out() << QJsonDocument(QJsonObject{{"items", items}}).toJson(QJsonDocument::Indented);
        return 0;
    });
}

int points(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            "Print the points of F^k(X0) as CSV: x, y, the map applied last, and the view.");
        parser.addPositionalArgument("project", "The .awb project file.");
        parser.addOptions({{"item", "The item.", "name"},
                           {"depth", "Iteration depth (default: the item's).", "k"},
                           {"start", "Start set: point:x,y | segment:x1,y1,x2,y2 | "
                                     "triangle:... | polygon:... | points:... (plane coordinates;"
                                     " default: the item's).",
                            "set"},
                           {"csv", "Print CSV (the only format so far)."},
                           {"max-points", "Refuse to print more (default 10000000).", "n",
                            "10000000"}});
        parseOrFail(parser, args, 1);
        if (!parser.isSet("item"))
            throw Failure{"--item NAME is required", 2};
        if (!parser.isSet("csv"))
            throw Failure{"--csv is required (the only output format)", 2};
        Project project;
        load(project, parser.positionalArguments().first());
        AttractorItem *item = attractorItem(project, parser.value("item"));
        auto d = derived(item);
        const int depth = parser.isSet("depth") ? intOption(parser, "depth", 0, 64)
                                                : item->algorithm().depth;
        StartSet start = item->coreStartSet(*d);
        if (parser.isSet("start")) {
            Mat pts;
            const StartSet::Kind kind = parseStart(parser.value("start"), &pts);
            start = {kind, d->toIfsSpace(pts)};
        }
        const double maxPoints = intOption(parser, "max-points", 1, 2000000000);
        if (!d->iterate) {
            const double n = imageCount(d->ifs, depth) * double(start.vertices.rows())
                             * double(d->ifs.views.size());
            if (n > maxPoints)
                throw Failure{QString("depth %1 gives %2 points, more than --max-points %3")
                                  .arg(depth)
                                  .arg(n, 0, 'g', 4)
                                  .arg(maxPoints, 0, 'g', 4)};
        }
        QTextStream &o = out();
        o.setRealNumberPrecision(17);
        o << "x,y,map,view\n";
        std::uint64_t printed = 0;
        CallbackSink sink([&](const Mat &v, StartSet::Kind, const std::uint8_t *a, int n) {
            for (size_t k = 0; k < d->ifs.views.size(); ++k) {
                const Mat p = awb::project(d->ifs.views[k], v);
                for (Eigen::Index r = 0; r < p.rows(); ++r)
                    o << p(r, 0) << ',' << p(r, 1) << ',' << (n > 0 ? a[0] + 1 : 0) << ','
                      << k + 1 << '\n';
                printed += std::uint64_t(p.rows());
            }
        });
        std::atomic<bool> cancel{false};
        IterationControl control;
        control.cancel = &cancel;
        if (d->iterate)
            d->iterate(start, depth, {&sink}, control);
        else
            iterate(d->ifs, start, depth, sink, control);
        o.flush();
        return 0;
    });
}

int check(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            "Validate a project file: it must load, and every item's IFS must be computable "
            "(exit 1: the file is refused; exit 3: it loads but items cannot be computed).");
        parser.addPositionalArgument("project", "The .awb project file.");
        parseOrFail(parser, args, 1);
        Project project;
        load(project, parser.positionalArguments().first());
        const QStringList problems = project.problems();
        for (const QString &p : problems)
            err() << project.fileName() << ": " << p << "\n";
        if (!problems.isEmpty())
            return 3;
        const auto n = project.items().size();
        out() << project.fileName() << ": OK, " << n << (n == 1 ? " item\n" : " items\n");
        return 0;
    });
}

int rewrite(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            "Load a project and save it again in the canonical form of this version (sorted "
            "keys, every field written): to upgrade or normalise a hand-written file.");
        parser.addPositionalArgument("project", "The .awb project file.");
        parser.addOption({"out", "Write here instead of over the input.", "file"});
        parseOrFail(parser, args, 1);
        Project project;
        load(project, parser.positionalArguments().first());
        QString error;
        const QString target = parser.isSet("out") ? parser.value("out") : project.fileName();
        if (!project.saveAs(target, &error))
            throw Failure{error};
        out() << target << "\n";
        return 0;
    });
}

} // namespace awb::cli
