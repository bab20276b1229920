// How a figure of an item is drawn: the options `render` and `animate` share, and the
// drawing itself (plane attractors, surfaces and meshes).

#include "cli/FigureOptions.h"

#include "render/DensityFile.h"
#include "cli/CommandSupport.h"
#include "cli/ProjectCommands.h"

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

// The options of `render` that `animate` shares: how a figure of an item is drawn.
QList<QCommandLineOption> frameOptionList()
{
    return {{"size", CliTr::tr("Image size in pixels (default 900x700)."), "WxH", "900x700"},
            {"bounds", CliTr::tr("Plane figures: the world rectangle to frame (padded by 6%), e.g. to "
                              "compare figures at one scale (default: fit the content)."),
             "x0,y0,x1,y1"}};
}

QList<QCommandLineOption> figureOptionList()
{
    QList<QCommandLineOption> list = frameOptionList();
    list += QList<QCommandLineOption>{
            {"depth", CliTr::tr("Deterministic iteration depth (default: the item's)."), "k"},
            {"samples", CliTr::tr("Random iteration with this many points (up to 1e12; "
                               "memory stays that of the raster)."), "n"},
            {"tone", CliTr::tr("Raster tone: 'hits' (every lit pixel opaque, the papers' "
                            "look) or 'density' (log density of the invariant measure, "
                            "gamma and vibrancy as flame renderers). Default: the item's "
                            "style (auto: hits for deterministic, density for random "
                            "iteration)."),
             "hits|density"},
            {"gamma", CliTr::tr("Density tone: display gamma (default: the item's, 2.2)."), "g"},
            {"vibrancy", CliTr::tr("Density tone: 1 saturated colours, 0 per-channel "
                                "gamma (default 1)."), "v", "1"},
            {"supersample", CliTr::tr("Histogram cells per pixel side, 1..4 (default 1; "
                                   "2 or 3 anti-alias edges)."), "s", "1"},
            {"threads", CliTr::tr("Threads of the raster engine (default: all cores)."), "n"},
            {"view", CliTr::tr("Surfaces: the camera's azimuth and elevation in degrees "
                            "(orthographic; default: the item's camera)."),
             "az,el"},
            {"format", CliTr::tr("The output's format when its name has no suffix (e.g. /dev/stdout): "
                              "png, svg, pdf or exr (default: the suffix)."),
             "png|svg|pdf|exr"},
            {"bits", CliTr::tr("PNG: 8 (the figure, default) or 16 (the attractor's raw density: "
                               "alpha = log(1 + hits) / log(1 + most hits), the colour the "
                               "hits' mean; no title, polygons or margins). An .exr file always "
                               "holds the raw density, as float32 counts."),
             "8|16", "8"}};
    return list;
}


void readFrameOptions(const QCommandLineParser &parser, FigureOptions &o)
{
    const QRegularExpression sizeRe("^(\\d+)x(\\d+)$");
    const auto sm = sizeRe.match(parser.value("size"));
    if (!sm.hasMatch() || sm.captured(1).toInt() < 64 || sm.captured(2).toInt() < 64
        || sm.captured(1).toInt() > 16384 || sm.captured(2).toInt() > 16384)
        throw Failure{CliTr::tr("--size must be WxH with 64..16384 pixels each, got '%1'")
                          .arg(parser.value("size"))};
    o.width = sm.captured(1).toInt();
    o.height = sm.captured(2).toInt();
    if (parser.isSet("bounds")) {
        const QStringList parts = parser.value("bounds").split(',');
        double v[4] = {};
        bool ok = parts.size() == 4;
        for (int i = 0; ok && i < 4; ++i)
            v[i] = parts[i].trimmed().toDouble(&ok), ok = ok && std::isfinite(v[i]);
        if (!ok || !(v[2] > v[0]) || !(v[3] > v[1]))
            throw Failure{CliTr::tr("--bounds must be x0,y0,x1,y1 with x0 < x1 and y0 < y1, got '%1'")
                              .arg(parser.value("bounds"))};
        o.bounds = QRectF(QPointF(v[0], v[1]), QPointF(v[2], v[3]));
    }
}

FigureOptions figureOptions(const QCommandLineParser &parser)
{
    FigureOptions o;
    if (parser.isSet("depth") && parser.isSet("samples"))
        throw Failure{CliTr::tr("--depth and --samples exclude each other"), 2};
    readFrameOptions(parser, o);
    if (parser.isSet("depth"))
        o.depth = intOption(parser, "depth", 0, 64);
    if (parser.isSet("samples"))
        o.samples = countOption(parser, "samples", 1, double(kMaxChaosSamples));
    o.tone = parser.value("tone");
    if (!o.tone.isEmpty() && o.tone != "hits" && o.tone != "density")
        throw Failure{CliTr::tr("--tone must be 'hits' or 'density', got '%1'").arg(o.tone), 2};
    if (parser.isSet("gamma"))
        o.gamma = realOption(parser, "gamma", 0.2, 10);
    o.vibrancy = realOption(parser, "vibrancy", 0, 1);
    o.supersample = intOption(parser, "supersample", 1, 4);
    if (parser.isSet("threads"))
        o.threads = intOption(parser, "threads", 1, 64);
    if (parser.isSet("view"))
        o.view = parser.value("view");
    if (parser.isSet("format")) {
        o.format = parser.value("format").toLower();
        if (o.format != "png" && o.format != "svg" && o.format != "pdf" && o.format != "exr")
            throw Failure{CliTr::tr("--format must be png, svg, pdf or exr, got '%1'")
                              .arg(parser.value("format")), 2};
    }
    o.bits = intOption(parser, "bits", 8, 16);
    if (o.bits != 8 && o.bits != 16)
        throw Failure{CliTr::tr("--bits must be 8 or 16, got '%1'").arg(parser.value("bits")), 2};
    return o;
}

namespace {

// The attractor's raw density in the figure's frame, without title, polygons or margins:
// float32 counts (.exr) or the 16-bit log density (PNG), render/DensityFile.h.
void writeRawDensity(const FigureSpec &spec, const std::shared_ptr<const DerivedIfs> &d,
                     int depth, const FigureOptions &o, const QString &suffix,
                     const QString &caption, const QString &outFile)
{
    if (suffix != QLatin1String("exr") && suffix != QLatin1String("png"))
        throw Failure{CliTr::tr("--bits 16 writes PNG files, got '%1'").arg(outFile), 2};
    if (d->polygon || (d->ifs.size() == 0 && !d->iterate))
        throw Failure{CliTr::tr("the raw density (.exr, --bits 16) counts an attractor's "
                                "points; this item's figure is a polygon")};
    RenderRequest r;
    r.ifs = std::shared_ptr<const Ifs>(d, &d->ifs);
    r.iterate = d->iterate;
    r.start = spec.start;
    r.mode = spec.random ? RenderRequest::Mode::Random : RenderRequest::Mode::Deterministic;
    r.depth = depth;
    r.samples = spec.samples;
    r.seed = spec.seed;
    const QRectF content = spec.bounds.isValid() ? spec.bounds : contentBounds(spec);
    r.world = figureWorld(content, QSizeF(o.width, o.height));
    r.size = QSize(o.width, o.height);
    r.colouring = spec.colouring;
    r.supersample = 1;  // counts per pixel, not per anti-aliasing cell
    r.threads = spec.threads;
    AttractorDensity density;
    try {
        IterationControl control;
        control.cancel = o.cancel;
        density = renderAttractorDensity(r, control);
    } catch (const InputError &e) {
        throw Failure{QString::fromStdString(e.what())};
    }
    if (o.cancel && o.cancel->load())
        throw Failure{CliTr::tr("the rendering was cancelled")};
    DensityFileInfo info{r.world, caption, spec.metadata};
    QString error;
    const bool ok = suffix == QLatin1String("exr")
                        ? writeDensityExr(outFile, density, info, &error)
                        : writeDensityPng16(outFile, density, info, &error);
    if (!ok)
        throw Failure{error};
}

} // namespace

// Draws `item` (of `project`, or a copy of one of its items: an animation frame) as
// `render` does and writes the figure to `outFile`; or, with `measure`, only measures the
// world rectangle the figure would fit (invalid for surfaces). Throws Failure.
void renderFigure(const Project &project, AttractorItem *item, const FigureOptions &o,
                  const QString &outFile, QRectF *measure)
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
            throw Failure{CliTr::tr("item '%1': %2").arg(item->name(),
                                                       QString::fromStdString(check.message))};
        const double images = imageCount(d->ifs, depth);
        if (images > 4e9)
            throw Failure{CliTr::tr("depth %1 makes %2 images; at most 4e9 are rendered")
                              .arg(depth)
                              .arg(images, 0, 'g', 3)};
    }
    if (d->ifs.size() > 0 || d->iterate)
        spec.start = item->coreStartSet(*d);
    const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(item);
    if (d->surface || mesh || item->pointDimension() == 3) {
        if (o.bits == 16 || o.format == QLatin1String("exr")
            || QFileInfo(outFile).suffix().toLower() == QLatin1String("exr"))
            throw Failure{CliTr::tr("the raw density (.exr, --bits 16) is of attractors "
                                    "drawn in the plane; '%1' is drawn in space")
                              .arg(item->name())};
        const auto *surface = qobject_cast<const SubdivisionSurfaceItem *>(item);
        const SurfaceCamera camera = surface ? surface->camera() : SurfaceCamera{};
        const QStringList view =
            !o.view.isEmpty() ? o.view.split(',')
                                 : QStringList{QString::number(camera.azimuth, 'g', 17),
                                               QString::number(camera.elevation, 'g', 17)};
        bool okA = false, okE = false;
        const double az = view.value(0).toDouble(&okA), el = view.value(1).toDouble(&okE);
        if (view.size() != 2 || !okA || !okE || !std::isfinite(az) || std::abs(el) > 90)
            throw Failure{CliTr::tr("--view must be AZ,EL in degrees with |EL| <= 90, got '%1'")
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
        } else if (mesh) {
            s.framePoints = toMatrix(mesh->inputs().vertices, 3);
            s.netPoints = s.framePoints;
            s.netFaces = mesh->inputs().faces;
        } else {
            // A fractal of space (an imported 3D IFS): its control points frame the view.
            s.framePoints = toMatrix(item->controlPoints(0), 3);
            s.netPoints = s.framePoints;
        }
        s.width = o.width;
        s.height = o.height;
        const QString what = s.random ? CliTr::tr("%1 random points").arg(s.samples)
                                      : CliTr::tr("F^%1(X0)").arg(depth);
        QString maps;
        if (!d->mapIndex.empty()) {
            QStringList on;
            for (int i : d->mapIndex)
                on << QString::number(i + 1);
            maps = CliTr::tr(", maps %1 of %2").arg(on.join(' ')).arg(d->S.count());
        }
        s.caption = CliTr::tr("%1: %2%3 — orthographic view from azimuth %4°, elevation %5°")
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
                          ? CliTr::tr("%1: %2 random points").arg(item->name()).arg(spec.samples)
                          : CliTr::tr("%1: F^%2(X0)").arg(item->name()).arg(depth);
    if (d->polygon) // a normal-vector curve: the polygon after `steps` is the figure
        caption = CliTr::tr("%1: polygon after %2 steps")
                      .arg(item->name())
                      .arg(item->parameter("steps").toInt());
    spec.panels = {{caption + o.captionSuffix, depth}};
    spec.bounds = o.bounds;
    if (measure) {
        *measure = contentBounds(spec);
        return;
    }
    spec.metadata = figureMetadata(project, *item);
    spec.cancel = o.cancel;
    const QString suffix = o.format.isEmpty() ? QFileInfo(outFile).suffix().toLower() : o.format;
    if (suffix == QLatin1String("exr") || o.bits == 16) {
        writeRawDensity(spec, d, depth, o, suffix, caption, outFile);
        return;
    }
    QString error;
    if (!writeFigure(spec, outFile, &error, o.format))
        throw Failure{error};
    if (o.cancel && o.cancel->load()) {
        // An unfinished picture is not left behind as if it were the figure.
        QFile::remove(outFile);
        throw Failure{CliTr::tr("the rendering was cancelled")};
    }
}

} // namespace awb::cli
