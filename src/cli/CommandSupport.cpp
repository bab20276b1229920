#include "cli/CommandSupport.h"

#include "model/SubdivisionMeshItem.h"

#include "model/AttractorItem.h"
#include "model/FigureMetadata.h"
#include "model/PointExport.h"
#include "model/Project.h"

#include <QCoreApplication>

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

// The item's project in the figure file (PNG text chunk, SVG metadata): it reopens as is.
FigureMetadata figureMetadata(const Project &project, const Item &item)
{
    const QByteArray bytes = figureProjectBytes(project, item);
    return {figurePngTexts(bytes), svgMetadataElement(bytes)};
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

// "point:x,y", "segment:x1,y1,x2,y2", "triangle:...", "polygon:...", "points:..."
StartSet::Kind parseStart(const QString &text, Mat *points, int dim)
{
    const int colon = text.indexOf(':');
    const QString kind = text.left(colon);
    const QStringList numbers = text.mid(colon + 1).split(',', Qt::SkipEmptyParts);
    QList<double> v;
    for (const QString &n : numbers) {
        bool ok = false;
        v << n.trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(v.back()))
            throw Failure{
                QCoreApplication::translate("awb::cli", "--start: '%1' is not a finite number")
                    .arg(n)};
    }
    const QMap<QString, int> count = {{"point", 1}, {"segment", 2}, {"triangle", 3}};
    if (colon < 0 || !(count.contains(kind) || kind == "polygon" || kind == "points"))
        throw Failure{QCoreApplication::translate("awb::cli",
                                                  "--start must be point:x,y | "
                                                  "segment:x1,y1,x2,y2 | "
                                                  "triangle:x1,y1,x2,y2,x3,y3 | polygon:... | "
                                                  "points:... | lifted:x,y,c1,...;..., got '%1'")
                          .arg(text),
                      2};
    if (v.size() % dim || v.isEmpty()
        || (count.contains(kind) && v.size() != dim * count[kind])
        || (kind == "polygon" && v.size() < 3 * dim))
        throw Failure{QCoreApplication::translate(
                          "awb::cli", "--start %1 needs %2 coordinates (%3 per point), got %4")
                          .arg(kind)
                          .arg(count.contains(kind)
                                   ? QString::number(dim * count[kind])
                                   : QCoreApplication::translate("awb::cli", "a multiple of %1")
                                         .arg(dim))
                          .arg(dim)
                          .arg(v.size())};
    *points = Mat(v.size() / dim, dim);
    for (int i = 0; i < v.size() / dim; ++i)
        for (int c = 0; c < dim; ++c)
            (*points)(i, c) = v[dim * i + c];
    if (kind == "segment")
        return StartSet::Kind::Polyline;
    if (kind == "triangle" || kind == "polygon")
        return StartSet::Kind::Polygon;
    return StartSet::Kind::Points;
}

// The number of points F^depth(start) makes (over every view); refuses more than maxPoints.
StartSet startOption(const AttractorItem &item, const DerivedIfs &d, const QString &text)
{
    if (text.startsWith("lifted:")) {
        // Points of the lifted space, ';' between points: lifted:x,y,c1,..;x,y,c1,..
        std::vector<std::vector<double>> lifted;
        for (const QString &point : text.mid(7).split(';', Qt::SkipEmptyParts)) {
            std::vector<double> p;
            for (const QString &n : point.split(',', Qt::SkipEmptyParts)) {
                bool ok = false;
                p.push_back(n.trimmed().toDouble(&ok));
                if (!ok || !std::isfinite(p.back()))
                    throw Failure{CliTr::tr("--start: '%1' is not a finite number").arg(n)};
            }
            lifted.push_back(std::move(p));
        }
        if (lifted.empty())
            throw Failure{CliTr::tr("--start lifted: needs at least one point")};
        return StartSet::points(liftedStartPoints(d, lifted));
    }
    if (text == "vertex-limits") {
        // The limit positions of the vertices of the mesh refined `depth` times (exact).
        if (!d.vertexLimitStart)
            throw Failure{CliTr::tr("--start vertex-limits needs a mesh item; '%1' "
                                    "is a %2")
                              .arg(item.name(), item.typeName())};
        return StartSet::points(Mat(0, 3));
    }
    Mat pts;
    const StartSet::Kind kind = parseStart(text, &pts, item.pointDimension());
    return {kind, d.toIfsSpace(pts)};
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
