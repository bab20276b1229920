#include "cli/ProjectCommands.h"

#include "cli/CommandSupport.h"

#include "cli/FigureRenderer.h"
#include "core/analysis/Geometry.h"
#include "core/analysis/Spectrum.h"
#include "model/Animation.h"
#include "model/FigureMetadata.h"
#include "model/AttractorItem.h"
#include "model/ExactCurve.h"
#include "model/FileWriting.h"
#include "model/ItemAddress.h"
#include "model/NumberFormat.h"
#include "model/PointExport.h"
#include "model/Project.h"
#include "model/SchemeRegularity.h"
#include "model/NormalVectorItem.h"
#include "model/SubdivisionCurveItem.h"
#include "core/schemes/NormalVectorScheme.h"
#include "core/schemes/Scheme.h"
#include "model/SubdivisionSurfaceItem.h"
#include "model/SubdivisionMeshItem.h"
#include "model/MeshAnalysisJson.h"
#include "core/mesh/MeshFiles.h"
#include "core/mesh/MeshRefine.h"
#include "core/ifs/SurfaceIfs.h"
#include "render/SurfaceFigure.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTextStream>

#include <sstream>

namespace awb::cli {

namespace {

// lupdate takes the context of ProjectCommandsTr::tr() from the macro.
struct ProjectCommandsTr {
    Q_DECLARE_TR_FUNCTIONS(awb::cli)
};

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
        throw Failure{ProjectCommandsTr::tr("--%1 must be a number from %2 to %3, got '%4'")
                          .arg(name)
                          .arg(lo)
                          .arg(hi)
                          .arg(parser.value(name))};
    return v;
}

// "point:x,y", "segment:x1,y1,x2,y2", "triangle:...", "polygon:...", "points:..."
StartSet::Kind parseStart(const QString &text, Mat *points, int dim = 2)
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
double requirePointBudget(const DerivedIfs &d, const StartSet &start, int depth, double maxPoints)
{
    // Items drawn by their own iteration (automata, meshes) say their count when they know it.
    const double n = exportPointCount(d, start, depth);
    if (n > maxPoints)
        throw Failure{ProjectCommandsTr::tr("depth %1 gives %2 points, more than --max-points %3")
                          .arg(depth)
                          .arg(n, 0, 'g', 4)
                          .arg(maxPoints, 0, 'g', 4)};
    return n;
}

QJsonArray complexJson(Complex z) { return {z.real(), z.imag()}; }

// A real matrix as numbers and as exact text ("3/8" where rational): {"values", "exact"}.
QJsonObject matrixJson(const Mat &m)
{
    QJsonArray values, exact;
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
        QJsonArray v, e;
        for (Eigen::Index c = 0; c < m.cols(); ++c) {
            v.append(m(r, c));
            e.append(exactText(m(r, c)));
        }
        values.append(v);
        exact.append(e);
    }
    return {{"values", values}, {"exact", exact}};
}

// A complex matrix as [re, im] pairs: {"values"}.
QJsonObject matrixJson(const CMat &m)
{
    QJsonArray values;
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
        QJsonArray v;
        for (Eigen::Index c = 0; c < m.cols(); ++c)
            v.append(complexJson(m(r, c)));
        values.append(v);
    }
    return {{"values", values}};
}

QJsonArray eigenvaluesJson(const Spectrum &s)
{
    QJsonArray ev;
    for (const Complex &z : s.values)
        ev.append(complexJson(z));
    return ev;
}

// The map matrices of analysis map i, as the Matrices dock shows them: M_i = P^-1 S_i P with
// its blocks A_i, b_i for a lifted subdivision IFS (000 §2), the complex M_i of a complex
// Bézier split, or the IFS map itself (A, b) where there is no S_i.
void addMapMatrices(QJsonObject &m, const DerivedIfs &d, int i, int k)
{
    if (i < int(d.S.real.size()))
        m["S"] = matrixJson(d.S.real[size_t(i)]);
    else if (i < int(d.S.complex.size()))
        m["S"] = matrixJson(d.S.complex[size_t(i)]);
    if (d.subdivision && d.subdivision->lifting.invertible && i < int(d.S.real.size())) {
        const LiftedMap l = liftMatrix(d.subdivision->lifting, d.S.real[size_t(i)]);
        m["M"] = matrixJson(l.M);
        m["A"] = matrixJson(l.A);
        m["b"] = matrixJson(Mat(l.b));
        m["eigenvalues_A"] = eigenvaluesJson(spectrum(l.A));
    } else if (i < int(d.liftedComplex.size())) {
        const CMat &M = d.liftedComplex[size_t(i)];
        const Eigen::Index n = M.rows() - 1;
        m["M"] = matrixJson(M);
        m["A"] = matrixJson(CMat(M.topLeftCorner(n, n)));
        m["b"] = matrixJson(CMat(M.bottomLeftCorner(1, n)));
        m["eigenvalues_A"] = eigenvaluesJson(spectrum(CMat(M.topLeftCorner(n, n))));
    } else if (k >= 0) {
        m["A"] = matrixJson(d.ifs.maps[size_t(k)].A);
        m["b"] = matrixJson(Mat(d.ifs.maps[size_t(k)].b));
        m["eigenvalues_A"] = eigenvaluesJson(spectrum(d.ifs.effectiveLinearPart(k)));
    }
}

// d_H(F^depth(X0), exact curve) at the item's depth (or the deepest depth under 2e6 points),
// with the one-sided distance from the attractor points to the curve.
QJsonValue hausdorffToExact(const AttractorItem *item, const DerivedIfs &d)
{
    const auto exact = exactCurveOf(item, 4000);
    if (!exact || d.iterate || d.ifs.views.empty() || d.ifs.size() == 0)
        return QJsonValue::Null;
    const StartSet start = item->coreStartSet(d);
    int depth = item->algorithm().depth;
    while (depth > 0 && imageCount(d.ifs, depth) * double(start.vertices.rows()) > 2e6)
        --depth;
    PointCollector c(d.ifs.views.front());
    iterate(d.ifs, StartSet::points(start.vertices), depth, c);
    const Mat pts = c.points();
    return QJsonObject{{"depth", depth},
                       {"value", hausdorffToCurve(pts, exact->points)},
                       {"one_sided", distanceToPolyline(pts, exact->points)},
                       {"curve", exact->label}};
}

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
    // Items without subdivision matrices (an equivalent IFS of a normal-vector scheme) list
    // the IFS's maps: "eigenvalues" are then those of the linear parts A_i.
    const bool hasS = d->S.count() > 0;
    const int count = hasS ? d->S.count() : d->ifs.size();
    for (int i = 0; i < count; ++i) {
        const Spectrum s = !hasS            ? spectrum(d->ifs.effectiveLinearPart(i))
                           : d->S.isComplex() ? spectrum(d->S.complex[i])
                                              : spectrum(d->S.real[i]);
        QJsonObject m;
        QJsonArray ev;
        for (const Complex &z : s.values)
            ev.append(complexJson(z));
        m["eigenvalues"] = ev;
        m["spectral_radius"] = s.spectralRadius;
        const Subdominant sub = subdominant(s, hasS);
        m["subdominant"] = [&] {
            QJsonArray a;
            for (const Complex &z : sub.values)
                a.append(complexJson(z));
            return a;
        }();
        m["subdominant_kind"] = QString::fromStdString(toString(sub.kind));
        // The IFS map that is analysis map i (the IFS may use a subset of the maps).
        int k = -1;
        for (int j = 0; j < d->ifs.size(); ++j)
            if (d->analysisIndex(j) == i)
                k = j;
        if (d->surface)
            m["used"] = k >= 0;
        addMapMatrices(m, *d, i, k);
        if (k >= 0) {
            const Contractivity c = contractivity(d->ifs.effectiveLinearPart(k));
            m["contractive"] = c.eventuallyContractive;
            m["contraction_norm"] = c.normFactor;
            const auto fp = fixedPoint(d->ifs.maps[k]);
            Mat p;
            if (fp && !d->ifs.views.empty()) {
                p = project(d->ifs.views.front(), Mat(*fp));
            } else if (d->subdivision && i < int(d->S.real.size())) {
                // No lifted fixed point (barycentric form of a singular P): the fixed weights
                // of S_i (eigenvalue 1) applied to the control points give the same point.
                if (const auto l = fixedWeights(d->S.real[size_t(i)]))
                    p = *l * d->subdivision->controlPoints;
            }
            if (p.size() > 0) {
                QJsonArray xy;
                for (Eigen::Index c2 = 0; c2 < p.cols(); ++c2)
                    xy.append(p(0, c2));
                m["fixed_point"] = xy;
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
    // A mesh: its extraordinary vertices and the pieces of its IFS with condensation.
    if (const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(item)) {
        const QJsonObject m = meshAnalysisJson(*mesh);
        for (auto it = m.begin(); it != m.end(); ++it)
            o[it.key()] = it.value();
    }
    // The scheme's certified Hölder regularity (issue 16): an interval, its class C^n, how.
    if (const auto *curve = qobject_cast<const SubdivisionCurveItem *>(item))
        o["regularity"] = regularityJson(itemRegularity(*curve));
    if (const auto *s = qobject_cast<const SubdivisionSurfaceItem *>(item)) {
        o["kind"] = item->type();
        o["scheme"] = SurfaceSchemeSpec::kindNames().at(int(s->scheme().kind));
        o["layout"] = s->scheme().layout;
        o["map_count"] = int(d->S.real.size());
        QJsonArray used, points, lattice;
        for (int i : s->mapsUsed())
            used.append(i);
        o["maps_used"] = used;
        for (const Point &q : s->controlPoints())
            points.append(QJsonArray{q.x, q.y, q.z});
        o["control_points"] = points;
        for (const LatticePoint &q : s->lattice())
            lattice.append(QJsonArray{q.i, q.j});
        o["lattice"] = lattice;
        o["lifted_dimension"] = d->ifs.dim();
    }
    if (d->subdivision) {
        o["lifting_invertible"] = d->subdivision->lifting.invertible;
        if (!d->subdivision->lifting.invertible)
            o["lifting_problem"] = QString::fromStdString(d->subdivision->lifting.reason);
    }
    try {
        o["hausdorff_to_exact"] = hausdorffToExact(item, *d);
    } catch (const InputError &e) {
        o["hausdorff_to_exact"] = QJsonValue::Null;
        o["hausdorff_error"] = QString::fromStdString(e.what());
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
            if (d->surface) {
                // The images of a surface's overlapping pieces coincide at lattice points:
                // random iteration gives distinct points for the count.
                ChaosOptions options;
                options.samples = 300000;
                chaosGame(d->ifs, start.vertices.row(0), options, c);
            } else {
                iterate(d->ifs, StartSet::points(start.vertices), depth, c);
            }
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

// The options of `render` that `animate` shares: how a figure of an item is drawn.
QList<QCommandLineOption> figureOptionList()
{
    return {{"size", ProjectCommandsTr::tr("Image size in pixels (default 900x700)."), "WxH", "900x700"},
            {"depth", ProjectCommandsTr::tr("Deterministic iteration depth (default: the item's)."), "k"},
            {"samples", ProjectCommandsTr::tr("Random iteration with this many points (up to 1e12; "
                               "memory stays that of the raster)."), "n"},
            {"tone", ProjectCommandsTr::tr("Raster tone: 'hits' (every lit pixel opaque, the papers' "
                            "look) or 'density' (log density of the invariant measure, "
                            "gamma and vibrancy as flame renderers). Default: the item's "
                            "style (auto: hits for deterministic, density for random "
                            "iteration)."),
             "hits|density"},
            {"gamma", ProjectCommandsTr::tr("Density tone: display gamma (default: the item's, 2.2)."), "g"},
            {"vibrancy", ProjectCommandsTr::tr("Density tone: 1 saturated colours, 0 per-channel "
                                "gamma (default 1)."), "v", "1"},
            {"supersample", ProjectCommandsTr::tr("Histogram cells per pixel side, 1..4 (default 1; "
                                   "2 or 3 anti-alias edges)."), "s", "1"},
            {"threads", ProjectCommandsTr::tr("Threads of the raster engine (default: all cores)."), "n"},
            {"view", ProjectCommandsTr::tr("Surfaces: the camera's azimuth and elevation in degrees "
                            "(orthographic; default: the item's camera)."),
             "az,el"},
            {"bounds", ProjectCommandsTr::tr("Plane figures: the world rectangle to frame (padded by 6%), e.g. to "
                              "compare figures at one scale (default: fit the content)."),
             "x0,y0,x1,y1"},
            {"format", ProjectCommandsTr::tr("The output's format when its name has no suffix (e.g. /dev/stdout): "
                              "png, svg or pdf (default: the suffix)."),
             "png|svg|pdf"}};
}

struct FigureOptions {
    int width = 900, height = 700;
    std::optional<int> depth;
    std::optional<std::uint64_t> samples;
    QString tone;  // "", "hits" or "density"
    std::optional<double> gamma;
    double vibrancy = 1.0;
    int supersample = 1;
    int threads = 0;
    QString view;  // "az,el" or empty
    QRectF bounds;  // the world rectangle to frame; invalid: fit the content
    QString captionSuffix;  // e.g. an animation frame's time and values
    QString format;  // "", "png", "svg" or "pdf"
};

FigureOptions figureOptions(const QCommandLineParser &parser)
{
    FigureOptions o;
    if (parser.isSet("depth") && parser.isSet("samples"))
        throw Failure{ProjectCommandsTr::tr("--depth and --samples exclude each other"), 2};
    const QRegularExpression sizeRe("^(\\d+)x(\\d+)$");
    const auto sm = sizeRe.match(parser.value("size"));
    if (!sm.hasMatch() || sm.captured(1).toInt() < 64 || sm.captured(2).toInt() < 64
        || sm.captured(1).toInt() > 16384 || sm.captured(2).toInt() > 16384)
        throw Failure{ProjectCommandsTr::tr("--size must be WxH with 64..16384 pixels each, got '%1'")
                          .arg(parser.value("size"))};
    o.width = sm.captured(1).toInt();
    o.height = sm.captured(2).toInt();
    if (parser.isSet("depth"))
        o.depth = intOption(parser, "depth", 0, 64);
    if (parser.isSet("samples"))
        o.samples = countOption(parser, "samples", 1, double(kMaxChaosSamples));
    o.tone = parser.value("tone");
    if (!o.tone.isEmpty() && o.tone != "hits" && o.tone != "density")
        throw Failure{ProjectCommandsTr::tr("--tone must be 'hits' or 'density', got '%1'").arg(o.tone), 2};
    if (parser.isSet("gamma"))
        o.gamma = realOption(parser, "gamma", 0.2, 10);
    o.vibrancy = realOption(parser, "vibrancy", 0, 1);
    o.supersample = intOption(parser, "supersample", 1, 4);
    if (parser.isSet("threads"))
        o.threads = intOption(parser, "threads", 1, 64);
    if (parser.isSet("view"))
        o.view = parser.value("view");
    if (parser.isSet("bounds")) {
        const QStringList parts = parser.value("bounds").split(',');
        double v[4] = {};
        bool ok = parts.size() == 4;
        for (int i = 0; ok && i < 4; ++i)
            v[i] = parts[i].trimmed().toDouble(&ok), ok = ok && std::isfinite(v[i]);
        if (!ok || !(v[2] > v[0]) || !(v[3] > v[1]))
            throw Failure{ProjectCommandsTr::tr("--bounds must be x0,y0,x1,y1 with x0 < x1 and y0 < y1, got '%1'")
                              .arg(parser.value("bounds"))};
        o.bounds = QRectF(QPointF(v[0], v[1]), QPointF(v[2], v[3]));
    }
    if (parser.isSet("format")) {
        o.format = parser.value("format").toLower();
        if (o.format != "png" && o.format != "svg" && o.format != "pdf")
            throw Failure{ProjectCommandsTr::tr("--format must be png, svg or pdf, got '%1'")
                              .arg(parser.value("format")), 2};
    }
    return o;
}

// Draws `item` (of `project`, or a copy of one of its items: an animation frame) as
// `render` does and writes the figure to `outFile`; or, with `measure`, only measures the
// world rectangle the figure would fit (invalid for surfaces). Throws Failure.
void renderFigure(const Project &project, AttractorItem *item, const FigureOptions &o,
                  const QString &outFile, QRectF *measure = nullptr)
{
    auto d = derived(item);
    const AlgorithmSpec &alg = item->algorithm();
    FigureSpec spec;
    spec.ifs = &d->ifs;
    spec.iterate = d->iterate;
    spec.random = o.samples || (alg.mode == AlgorithmSpec::Mode::Random && !o.depth);
    spec.samples = o.samples ? *o.samples : std::uint64_t(alg.samples);
    spec.seed = std::uint64_t(alg.seed);
    spec.tone.mode =
        o.tone == "density" || (o.tone.isEmpty() && item->style().densityTone(spec.random))
            ? Accumulation::Density
            : Accumulation::Hits;
    spec.tone.gamma = o.gamma ? *o.gamma : item->style().gamma;
    spec.colouring = attractorColouring(item->style());  // as the application's view draws it
    spec.tone.vibrancy = o.vibrancy;
    spec.supersample = o.supersample;
    if (o.threads > 0)
        spec.threads = o.threads;
    const int depth = o.depth ? *o.depth : alg.depth;
    if (d->ifs.size() > 0 && !spec.random && !d->iterate) {
        const IfsCheck check = checkIfs(d->ifs);
        if (!check.contractive)
            throw Failure{ProjectCommandsTr::tr("item '%1': %2").arg(item->name(),
                                                       QString::fromStdString(check.message))};
        const double images = imageCount(d->ifs, depth);
        if (images > 4e9)
            throw Failure{ProjectCommandsTr::tr("depth %1 makes %2 images; at most 4e9 are rendered")
                              .arg(depth)
                              .arg(images, 0, 'g', 3)};
    }
    if (d->ifs.size() > 0 || d->iterate)
        spec.start = item->coreStartSet(*d);
    const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(item);
    if (d->surface || mesh) {
        const auto *surface = qobject_cast<const SubdivisionSurfaceItem *>(item);
        const SurfaceCamera camera = surface ? surface->camera() : SurfaceCamera{};
        const QStringList view =
            !o.view.isEmpty() ? o.view.split(',')
                                 : QStringList{QString::number(camera.azimuth, 'g', 17),
                                               QString::number(camera.elevation, 'g', 17)};
        bool okA = false, okE = false;
        const double az = view.value(0).toDouble(&okA), el = view.value(1).toDouble(&okE);
        if (view.size() != 2 || !okA || !okE || !std::isfinite(az) || std::abs(el) > 90)
            throw Failure{ProjectCommandsTr::tr("--view must be AZ,EL in degrees with |EL| <= 90, got '%1'")
                              .arg(o.view)};
        SurfaceFigureSpec s;
        s.ifs = &d->ifs;
        s.iterate = d->iterate;
        s.start = spec.start;
        s.depth = depth;
        s.random = spec.random;
        s.samples = spec.samples;
        s.seed = spec.seed;
        s.mapColors = d->mapIndex;
        for (int i = 0; i < 18; ++i)
            s.palette.push_back(mapColor(i));
        s.pointRadius = std::max(0.5, 0.5 * item->style().pointSize);
        s.azimuth = az;
        s.elevation = el;
        if (surface) {
            const LatticeMesh net = surface->refinedMesh(0);
            s.framePoints = net.points;
            s.netPoints = net.points;
            s.netFaces = net.faces;
        } else {
            s.framePoints = toMatrix(mesh->inputs().vertices, 3);
            s.netPoints = s.framePoints;
            s.netFaces = mesh->inputs().faces;
        }
        s.width = o.width;
        s.height = o.height;
        const QString what = s.random ? ProjectCommandsTr::tr("%1 random points").arg(s.samples)
                                      : ProjectCommandsTr::tr("F^%1(X0)").arg(depth);
        QString maps;
        if (!d->mapIndex.empty()) {
            QStringList on;
            for (int i : d->mapIndex)
                on << QString::number(i + 1);
            maps = ProjectCommandsTr::tr(", maps %1 of %2").arg(on.join(' ')).arg(d->S.count());
        }
        s.caption = ProjectCommandsTr::tr("%1: %2%3 — orthographic view from azimuth %4°, elevation %5°")
                        .arg(item->name(), what, maps)
                        .arg(az)
                        .arg(el);
        s.metadata = figureMetadata(project, *item);
        QString error;
        if (!writeSurfaceFigure(s, outFile, &error, o.format))
            throw Failure{error};
        return;
    }
    for (int s = 0; s < item->controlPointSetCount(); ++s)
        if (!item->controlPoints(s).empty()) {
            spec.controlPolygons.push_back(toMatrix(item->controlPoints(s)));
            spec.controlClosed.push_back(item->controlPointSetClosed(s));
        }
    if (d->polygon) {
        spec.polygons.push_back(*d->polygon);
        spec.polygonsClosed.push_back(d->polygonClosed);
    }
    if (const auto exact = exactCurveOf(item, 800))
        spec.overlays.push_back(exact->points);
    spec.panelWidth = o.width;
    spec.panelHeight = o.height - 26;
    QString caption = spec.random
                          ? ProjectCommandsTr::tr("%1: %2 random points").arg(item->name()).arg(spec.samples)
                          : ProjectCommandsTr::tr("%1: F^%2(X0)").arg(item->name()).arg(depth);
    if (d->polygon) // a normal-vector curve: the polygon after `steps` is the figure
        caption = ProjectCommandsTr::tr("%1: polygon after %2 steps")
                      .arg(item->name())
                      .arg(item->parameter("steps").toInt());
    spec.panels = {{caption + o.captionSuffix, depth}};
    spec.bounds = o.bounds;
    if (measure) {
        *measure = contentBounds(spec);
        return;
    }
    spec.metadata = figureMetadata(project, *item);
    QString error;
    if (!writeFigure(spec, outFile, &error, o.format))
        throw Failure{error};
}


} // namespace

int render(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            ProjectCommandsTr::tr("Render an item's attractor (with its control polygons) to PNG, SVG or PDF."));
        parser.addPositionalArgument("project", ProjectCommandsTr::tr("The .awb project file."));
        parser.addOptions({{"item", ProjectCommandsTr::tr("The item to render (default: the first with an "
                                           "attractor)."),
                            "name"},
                           {"out", ProjectCommandsTr::tr("Output file: .png, .svg or .pdf."), "file"}});
        parser.addOptions(figureOptionList());
        parseOrFail(parser, args, 1);
        if (!parser.isSet("out"))
            throw Failure{ProjectCommandsTr::tr("--out FILE is required"), 2};
        const FigureOptions options = figureOptions(parser);
        Project project;
        load(project, parser.positionalArguments().first());
        renderFigure(project, attractorItem(project, parser.value("item")), options,
                     parser.value("out"));
        out() << parser.value("out") << "\n";
        return 0;
    });
}

int animate(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            ProjectCommandsTr::tr("Render the frames of an item's animation (its keyframed parameters): numbered "
                   "PNG files in a folder, or an MP4 or GIF movie through ffmpeg. Frame k is the "
                   "item with its parameters at time k / fps, drawn exactly as `render` draws "
                   "it."));
        parser.addPositionalArgument("project", ProjectCommandsTr::tr("The .awb project file."));
        parser.addOptions(
            {{"item", ProjectCommandsTr::tr("The animated item (default: the first item with an "
                             "animation)."), "name"},
             {"out", ProjectCommandsTr::tr("A folder for frame-0000.png, frame-0001.png, ... (made if missing), a "
                            "movie .mp4 or .gif (made by ffmpeg), or with --frame one "
                            ".png/.svg/.pdf."),
              "dir|file"},
             {"fps", ProjectCommandsTr::tr("Frames per second (default: the animation's)."), "n"},
             {"frame", ProjectCommandsTr::tr("Render only frame K (0 = the start) to the file --out."), "k"},
             {"no-caption-values", ProjectCommandsTr::tr("Captions without the frame's time and values.")}});
        parser.addOptions(figureOptionList());
        parseOrFail(parser, args, 1);
        if (!parser.isSet("out"))
            throw Failure{ProjectCommandsTr::tr("--out DIR|FILE is required"), 2};
        const FigureOptions options = figureOptions(parser);
        Project project;
        load(project, parser.positionalArguments().first());
        AttractorItem *item = nullptr;
        if (parser.isSet("item")) {
            item = attractorItem(project, parser.value("item"));
        } else {
            for (Item *i : project.items())
                if (auto *a = qobject_cast<AttractorItem *>(i); a && !a->animation().isEmpty()) {
                    item = a;
                    break;
                }
            if (!item)
                throw Failure{ProjectCommandsTr::tr("%1 has no animated item").arg(project.fileName())};
        }
        if (item->animation().isEmpty())
            throw Failure{ProjectCommandsTr::tr("item '%1' has no animation: key its parameters in the "
                                 "Animation dock, or give it an \"animation\" field "
                                 "(docs/file-format.md)")
                              .arg(item->name())};
        for (const QString &target : inactiveAnimationTargets(*item))
            err() << ProjectCommandsTr::tr("attractor-cli: note: the track of %1 is skipped: item '%2' has no "
                            "such input now")
                         .arg(target, item->name())
                  << "\n";
        AnimationSpec timing = item->animation();
        if (parser.isSet("fps"))
            timing.fps = realOption(parser, "fps", 1, AnimationSpec::maxFps);
        const int frames = timing.frameCount();
        FigureOptions frameOptions = options;
        // One framing for every frame (the union of their contents): the attractor moves, the
        // frame stays. --bounds sets it.
        if (!frameOptions.bounds.isValid()) {
            QRectF all(0, 0, -1, -1);
            for (int k = 0; k < frames; ++k) {
                QString error;
                std::unique_ptr<Item> copy = animatedCopy(*item, timing.frameTime(k), &error);
                QRectF r(0, 0, -1, -1);
                if (copy)
                    try {
                        renderFigure(project, static_cast<AttractorItem *>(copy.get()), options,
                                     {}, &r);
                    } catch (const Failure &) {
                        // reported when the frame is drawn
                    }
                if (r.width() >= 0)
                    all = all.width() < 0 ? r : all.united(r);
            }
            if (all.width() > 0 && all.height() > 0)
                frameOptions.bounds = all;
        }
        const auto boundsText = [&] {
            const QRectF &b = frameOptions.bounds;
            return b.isValid() ? ProjectCommandsTr::tr("%1,%2,%3,%4")
                                     .arg(b.left(), 0, 'g', 17)
                                     .arg(b.top(), 0, 'g', 17)
                                     .arg(b.right(), 0, 'g', 17)
                                     .arg(b.bottom(), 0, 'g', 17)
                               : ProjectCommandsTr::tr("fitted per frame");
        };
        const auto renderFrame = [&](int k, const QString &file) {
            QString error;
            std::unique_ptr<Item> copy = animatedCopy(*item, timing.frameTime(k), &error);
            if (!copy)
                throw Failure{ProjectCommandsTr::tr("frame %1 (t = %2 s): %3")
                                  .arg(k)
                                  .arg(timing.frameTime(k))
                                  .arg(error)};
            FigureOptions o = frameOptions;
            if (!parser.isSet("no-caption-values"))
                o.captionSuffix = " — " + animationCaption(*item, timing.frameTime(k));
            try {
                renderFigure(project, static_cast<AttractorItem *>(copy.get()), o, file);
            } catch (const Failure &f) {
                throw Failure{ProjectCommandsTr::tr("frame %1 (t = %2 s): %3")
                                  .arg(k)
                                  .arg(timing.frameTime(k))
                                  .arg(f.message),
                              f.code};
            }
        };
        const QString outPath = parser.value("out");
        if (parser.isSet("frame")) {
            renderFrame(intOption(parser, "frame", 0, frames - 1), outPath);
            out() << outPath << "\nbounds: " << boundsText() << "\n";
            return 0;
        }
        const QString suffix = QFileInfo(outPath).suffix().toLower();
        const bool movie = suffix == "mp4" || suffix == "gif";
        QString ffmpeg;
        if (movie) {
            ffmpeg = qEnvironmentVariableIsSet("AWB_FFMPEG")
                         ? qEnvironmentVariable("AWB_FFMPEG")
                         : QStandardPaths::findExecutable("ffmpeg");
            if (ffmpeg.isEmpty() || !QFileInfo(ffmpeg).isExecutable())
                throw Failure{ProjectCommandsTr::tr("writing %1 needs ffmpeg, which is not installed (Debian: "
                                     "apt-get install ffmpeg); give --out a folder to get the "
                                     "frames as PNG files")
                                  .arg(outPath)};
        }
        QTemporaryDir scratch;
        const QString dir = movie ? scratch.path() : outPath;
        if (movie && !scratch.isValid())
            throw Failure{ProjectCommandsTr::tr("cannot make a temporary folder for the frames: %1")
                              .arg(scratch.errorString())};
        if (!movie && QFileInfo(dir).exists() && !QFileInfo(dir).isDir())
            throw Failure{ProjectCommandsTr::tr("%1 is a file, not a folder (a movie needs .mp4 or .gif)")
                              .arg(dir)};
        if (!QDir().mkpath(dir))
            throw Failure{ProjectCommandsTr::tr("cannot make the folder %1").arg(dir)};
        const int digits = std::max(4, int(QString::number(frames - 1).size()));
        const QString pattern = "frame-%0" + QString::number(digits) + "d.png"; // ffmpeg's
        QElapsedTimer clock;
        clock.start();
        for (int k = 0; k < frames; ++k)
            renderFrame(k, QDir(dir).filePath(
                               ProjectCommandsTr::tr("frame-%1.png").arg(k, digits, 10, QLatin1Char('0'))));
        const double seconds = clock.elapsed() / 1000.0;
        if (movie) {
            QStringList ffArgs{"-y", "-loglevel", "error", "-framerate",
                               QString::number(timing.fps), "-i", QDir(dir).filePath(pattern)};
            if (suffix == "gif")
                ffArgs << "-vf" << "split[a][b];[a]palettegen[p];[b][p]paletteuse";
            else
                ffArgs << "-c:v" << "libx264" << "-pix_fmt" << "yuv420p" << "-vf"
                       << "pad=ceil(iw/2)*2:ceil(ih/2)*2";
            ffArgs << outPath;
            QProcess process;
            process.start(ffmpeg, ffArgs);
            if (!process.waitForFinished(-1) || process.exitStatus() != QProcess::NormalExit
                || process.exitCode() != 0)
                throw Failure{ProjectCommandsTr::tr("ffmpeg could not write %1: %2")
                                  .arg(outPath, QString::fromLocal8Bit(process.readAllStandardError())
                                                    .trimmed())};
        }
        out() << ProjectCommandsTr::tr("%1: %2 frames of %3x%4 at %5 frames/s (%6 s); rendered in %7 s, "
                        "%8 frames/s\nbounds: %9\n")
                     .arg(outPath)
                     .arg(frames)
                     .arg(options.width)
                     .arg(options.height)
                     .arg(timing.fps)
                     .arg(timing.duration)
                     .arg(seconds, 0, 'f', 2)
                     .arg(frames / std::max(seconds, 1e-9), 0, 'f', 1)
                     .arg(boundsText());
        return 0;
    });
}

int analyse(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            ProjectCommandsTr::tr("Analyse the items of a project: per map S_i (exact fractions), M_i = P^-1 S_i "
                   "P with its blocks A_i, b_i, the eigenvalues of S_i and A_i, spectral radius, "
                   "contractivity and fixed point; per item the subdominant eigenvalues, the "
                   "Hausdorff distance to the exact curve and the box-counting dimension; per "
                   "subdivision curve the certified Hölder regularity of its scheme."));
        parser.addPositionalArgument("project", ProjectCommandsTr::tr("The .awb project file."));
        parser.addOptions({{"item", ProjectCommandsTr::tr("Only this item."), "name"},
                           {"json", ProjectCommandsTr::tr("Print JSON (the only format so far).")}});
        parseOrFail(parser, args, 1);
        if (!parser.isSet("json"))
            throw Failure{ProjectCommandsTr::tr("--json is required (the only output format)"), 2};
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
            ProjectCommandsTr::tr("Print the points of F^k(X0) as CSV: x, y (and z for a surface), the map "
                   "applied last (1-based), and the view. --address w limits them to the sub-copy "
                   "f_w(A): the points f_w(F^k(X0))."));
        parser.addPositionalArgument("project", ProjectCommandsTr::tr("The .awb project file."));
        parser.addOptions({{"item", ProjectCommandsTr::tr("The item."), "name"},
                           {"depth", ProjectCommandsTr::tr("Iteration depth (default: the item's)."), "k"},
                           {"start", ProjectCommandsTr::tr("Start set: point:x,y | segment:x1,y1,x2,y2 | "
                                            "triangle:... | polygon:... | points:... (plane "
                                            "coordinates; x,y,z for a surface) | "
                                            "lifted:x,y,c1,...;x,y,c1,... (points of the lifted "
                                            "space of 000 §2) | vertex-limits (a mesh item: the "
                                            "limit positions of the vertices of the mesh refined "
                                            "k times; default: the item's)."),
                            "set"},
                           {"csv", ProjectCommandsTr::tr("Print CSV (the only format so far).")},
                           {"address", ProjectCommandsTr::tr("Only the sub-copy f_w(A) of this address: 0-based "
                                              "map numbers, w_1 (the outermost map) first, e.g. "
                                              "0,1,1."),
                            "w"},
                           {"max-points", ProjectCommandsTr::tr("Refuse to print more (default 10000000)."), "n",
                            "10000000"}});
        parseOrFail(parser, args, 1);
        if (!parser.isSet("item"))
            throw Failure{ProjectCommandsTr::tr("--item NAME is required"), 2};
        if (!parser.isSet("csv"))
            throw Failure{ProjectCommandsTr::tr("--csv is required (the only output format)"), 2};
        Project project;
        load(project, parser.positionalArguments().first());
        AttractorItem *item = attractorItem(project, parser.value("item"));
        auto d = derived(item);
        const int depth = parser.isSet("depth") ? intOption(parser, "depth", 0, 64)
                                                : item->algorithm().depth;
        Address address;
        if (parser.isSet("address")) {
            try {
                address = parseItemAddress(parser.value("address"), *d);
            } catch (const InputError &e) {
                throw Failure{ProjectCommandsTr::tr("--address %1: %2")
                                  .arg(parser.value("address"), QString::fromStdString(e.what())),
                              2};
            }
        }
        StartSet start = item->coreStartSet(*d);
        if (parser.isSet("start") && parser.value("start").startsWith("lifted:")) {
            // Points of the lifted space, ';' between points: lifted:x,y,c1,..;x,y,c1,..
            std::vector<std::vector<double>> lifted;
            for (const QString &point :
                 parser.value("start").mid(7).split(';', Qt::SkipEmptyParts)) {
                std::vector<double> p;
                for (const QString &n : point.split(',', Qt::SkipEmptyParts)) {
                    bool ok = false;
                    p.push_back(n.trimmed().toDouble(&ok));
                    if (!ok || !std::isfinite(p.back()))
                        throw Failure{ProjectCommandsTr::tr("--start: '%1' is not a finite number").arg(n)};
                }
                lifted.push_back(std::move(p));
            }
            if (lifted.empty())
                throw Failure{ProjectCommandsTr::tr("--start lifted: needs at least one point")};
            start = StartSet::points(liftedStartPoints(*d, lifted));
        } else if (parser.isSet("start") && parser.value("start") == "vertex-limits") {
            // The limit positions of the vertices of the mesh refined `depth` times (exact).
            if (!d->vertexLimitStart)
                throw Failure{ProjectCommandsTr::tr("--start vertex-limits needs a mesh item; '%1' "
                                                    "is a %2")
                                  .arg(item->name(), item->typeName())};
            start = StartSet::points(Mat(0, 3));
        } else if (parser.isSet("start")) {
            Mat pts;
            const StartSet::Kind kind =
                parseStart(parser.value("start"), &pts, item->pointDimension());
            start = {kind, d->toIfsSpace(pts)};
        }
        const double maxPoints = intOption(parser, "max-points", 1, 2000000000);
        requirePointBudget(*d, start, depth, maxPoints);
        out().flush();
        QFile stdoutFile;
        if (!stdoutFile.open(stdout, QIODevice::WriteOnly))
            throw Failure{ProjectCommandsTr::tr("cannot write to the standard output")};
        std::atomic<bool> cancel{false};
        IterationControl control;
        control.cancel = &cancel;
        writePointsCsv(stdoutFile, *d, start, depth, control, address);
        stdoutFile.flush();
        return 0;
    });
}

int check(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            ProjectCommandsTr::tr("Validate a project file: it must load, and every item's IFS must be computable "
                   "(exit 1: the file is refused; exit 3: it loads but items cannot be "
                   "computed)."));
        parser.addPositionalArgument("project", ProjectCommandsTr::tr("The .awb project file."));
        parseOrFail(parser, args, 1);
        Project project;
        load(project, parser.positionalArguments().first());
        // A figure PNG opens as an untitled project: name the file that was given.
        const QString name = project.fileName().isEmpty() ? parser.positionalArguments().first()
                                                          : project.fileName();
        const QStringList problems = project.problems();
        for (const QString &p : problems)
            err() << name << ": " << p << "\n";
        if (!problems.isEmpty())
            return 3;
        // What the items say about themselves: a singular lifting drawn in barycentric form,
        // a nearly singular one, maps that are not (eventually) contractive.
        for (Item *item : project.items()) {
            auto *a = qobject_cast<AttractorItem *>(item);
            const auto d = a ? a->derivedIfs() : nullptr;
            if (!d)
                continue;
            if (!d->note.isEmpty())
                err() << ProjectCommandsTr::tr("%1: %2: note: %3").arg(name, a->name(), d->note)
                      << "\n";
            if (!d->iterate && d->ifs.size() > 0)
                if (const IfsCheck c = checkIfs(d->ifs); !c.contractive)
                    err() << ProjectCommandsTr::tr("%1: %2: note: %3")
                                 .arg(name, a->name(),
                                      QString::fromStdString(c.message))
                          << "\n";
        }
        const auto n = project.items().size();
        out() << name << ": OK, " << n << (n == 1 ? " item\n" : " items\n");
        return 0;
    });
}

int rewrite(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            ProjectCommandsTr::tr("Load a project and save it again in the canonical form of this version (sorted "
                   "keys, every field written): to upgrade or normalise a hand-written file."));
        parser.addPositionalArgument("project", ProjectCommandsTr::tr("The .awb project file."));
        parser.addOption({"out", ProjectCommandsTr::tr("Write here instead of over the input."), "file"});
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

namespace awb::cli {

namespace {

// Wavefront OBJ of the control net after `rounds` rounds of classic subdivision.
void writeObj(QIODevice &file, const SubdivisionSurfaceItem *item, int rounds)
{
    const LatticeMesh mesh = item->refinedMesh(rounds);
    QByteArray text;
    text += QString("# Attractor Workbench: item %1, %2 scheme, net after %3 rounds of "
                    "subdivision\n# %4 vertices, %5 faces\n")
                .arg(item->name(), SurfaceSchemeSpec::kindNames().at(int(item->scheme().kind)))
                .arg(rounds)
                .arg(mesh.points.rows())
                .arg(mesh.faces.size())
                .toUtf8();
    for (Eigen::Index k = 0; k < mesh.points.rows(); ++k)
        text += ProjectCommandsTr::tr("v %1 %2 %3\n")
                    .arg(mesh.points(k, 0), 0, 'g', 17)
                    .arg(mesh.points(k, 1), 0, 'g', 17)
                    .arg(mesh.points(k, 2), 0, 'g', 17)
                    .toUtf8();
    for (const auto &face : mesh.faces) {
        text += "f";
        for (int i : face)
            text += " " + QByteArray::number(i + 1);
        text += "\n";
    }
    file.write(text);
}

} // namespace

int exportData(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            ProjectCommandsTr::tr("Export an item's geometry: the attractor F^k(X0) as a PLY point cloud (with "
                   "the map applied last per point), a surface item's net after k rounds of "
                   "classic subdivision as an OBJ mesh, or a mesh item after k steps with every "
                   "vertex at its limit position (OBJ)."));
        parser.addPositionalArgument("project", ProjectCommandsTr::tr("The .awb project file."));
        parser.addOptions({{"item", ProjectCommandsTr::tr("The item."), "name"},
                           {"format", ProjectCommandsTr::tr("ply (attractor points) or obj (subdivided "
                                             "mesh)."), "fmt"},
                           {"out", ProjectCommandsTr::tr("Output file."), "file"},
                           {"depth", ProjectCommandsTr::tr("PLY: iteration depth (default: the item's)."), "k"},
                           {"rounds", ProjectCommandsTr::tr("OBJ: rounds of subdivision (default: the "
                                             "item's; a mesh item: its depth, at most 6)."), "r"},
                           {"max-points", ProjectCommandsTr::tr("PLY: refuse to write more (default "
                                                 "50000000)."), "n",
                            "50000000"}});
        parseOrFail(parser, args, 1);
        if (!parser.isSet("item") || !parser.isSet("out") || !parser.isSet("format"))
            throw Failure{ProjectCommandsTr::tr("--item NAME, --format ply|obj and --out FILE are required"), 2};
        const QString format = parser.value("format").toLower();
        if (format != "ply" && format != "obj")
            throw Failure{ProjectCommandsTr::tr("--format must be ply or obj, got '%1'").arg(format), 2};
        Project project;
        load(project, parser.positionalArguments().first());
        AttractorItem *item = attractorItem(project, parser.value("item"));
        auto d = derived(item);
        const QString outFile = parser.value("out");
        WholeFileWriter writer;
        QString reason;
        if (!writer.open(outFile, &reason))
            throw Failure{ProjectCommandsTr::tr("cannot write %1: %2").arg(outFile, reason)};
        QIODevice &file = *writer.device();
        if (format == "ply") {
            const int depth = parser.isSet("depth") ? intOption(parser, "depth", 0, 64)
                                                    : item->algorithm().depth;
            const StartSet start = item->coreStartSet(*d);
            requirePointBudget(*d, start, depth, intOption(parser, "max-points", 1, 2000000000));
            writePointsPly(file, item->name(), *d, start, depth, mapColor);
        } else if (const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(item)) {
            // The mesh after k steps, every vertex at its exact limit position.
            const int rounds = parser.isSet("rounds") ? intOption(parser, "rounds", 0, 8)
                               : parser.isSet("depth") ? intOption(parser, "depth", 0, 8)
                                                       : std::min(item->algorithm().depth, 6);
            Mesh refined = refineMesh(mesh->mesh(), mesh->scheme(), rounds);
            if (refined.vertices.rows() > 50000000)
                throw Failure{ProjectCommandsTr::tr("%1 steps give %2 vertices: too many")
                                  .arg(rounds)
                                  .arg(refined.vertices.rows())};
            refined.vertices = limitPositions(refined, mesh->scheme());
            std::ostringstream text;
            writeObj(text, refined,
                     ProjectCommandsTr::tr("Attractor Workbench: item %1, %2 after %3 steps, "
                                           "every vertex at its limit position")
                         .arg(mesh->name(), MeshInputs::schemeNames().at(int(mesh->scheme())))
                         .arg(rounds)
                         .toStdString());
            const std::string bytes = text.str();
            if (file.write(bytes.data(), qint64(bytes.size())) != qint64(bytes.size()))
                throw Failure{ProjectCommandsTr::tr("cannot write %1: %2")
                                  .arg(outFile, file.errorString())};
        } else {
            const auto *surface = qobject_cast<const SubdivisionSurfaceItem *>(item);
            if (!surface)
                throw Failure{ProjectCommandsTr::tr("OBJ export writes the subdivided net of a surface item; "
                                     "'%1' is a %2").arg(item->name(), item->typeName())};
            const int rounds = parser.isSet("rounds")
                                   ? intOption(parser, "rounds", 0,
                                               SubdivisionSurfaceItem::maxMeshRounds)
                                   : surface->meshRounds();
            writeObj(file, surface, rounds);
        }
        if (!writer.commit(&reason))
            throw Failure{ProjectCommandsTr::tr("cannot write %1: %2").arg(outFile, reason)};
        out() << parser.value("out") << "\n";
        return 0;
    });
}

} // namespace awb::cli

namespace awb::cli {

int polygon(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            ProjectCommandsTr::tr("Print the control polygon after K subdivision steps as JSON {\"closed\", "
                   "\"points\"}: the figures of 001 for a normal-vector item (eq. (1) applied K "
                   "times), classic subdivision S_w P for a subdivision curve."));
        parser.addPositionalArgument("project", ProjectCommandsTr::tr("The .awb project file."));
        parser.addOptions({{"item", ProjectCommandsTr::tr("The item."), "name"},
                           {"level", ProjectCommandsTr::tr("Subdivision steps K (0: the control "
                                            "polygon)."), "k", "0"},
                           {"json", ProjectCommandsTr::tr("Print JSON (the only format).")}});
        parseOrFail(parser, args, 1);
        if (!parser.isSet("item"))
            throw Failure{ProjectCommandsTr::tr("--item NAME is required"), 2};
        if (!parser.isSet("json"))
            throw Failure{ProjectCommandsTr::tr("--json is required (the only output format)"), 2};
        Project project;
        load(project, parser.positionalArguments().first());
        AttractorItem *item = attractorItem(project, parser.value("item"));
        const int level = intOption(parser, "level", 0, 30);
        Mat points;
        bool closed = false;
        if (const auto *nv = qobject_cast<const NormalVectorItem *>(item)) {
            const ControlPolygon poly{toMatrix(nv->controlPoints()), nv->spec().closed};
            points = nv->spec().makeScheme().subdivide(poly, level).points;
            closed = poly.closed;
        } else if (const auto *curve = qobject_cast<const SubdivisionCurveItem *>(item)) {
            if (curve->scheme().isComplex())
                throw Failure{ProjectCommandsTr::tr("item '%1' has a complex split parameter: its control "
                                     "polygon has complex points").arg(item->name())};
            const Mat P = toMatrix(curve->controlPoints());
            const auto scheme = curve->scheme().makeScheme();
            if (std::pow(double(scheme->arity()), level) * double(P.rows()) > 5e7)
                throw Failure{ProjectCommandsTr::tr("level %1 gives more than 5e7 points").arg(level)};
            points = subdivide(*scheme, P, level);
        } else {
            throw Failure{ProjectCommandsTr::tr("item '%1' (%2) is not polygon-based: the polygon command "
                                 "takes normal-vector items and subdivision curves")
                              .arg(item->name(), item->typeName())};
        }
        QJsonArray list;
        for (Eigen::Index r = 0; r < points.rows(); ++r)
            list.append(QJsonArray{points(r, 0), points(r, 1)});
        out() << QJsonDocument(QJsonObject{{"closed", closed}, {"level", level}, {"points", list}})
                     .toJson(QJsonDocument::Compact)
              << "\n";
        return 0;
    });
}

} // namespace awb::cli
