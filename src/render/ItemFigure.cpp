// The figure of one item: ItemFigure.h.

#include "render/ItemFigure.h"

#include "core/analysis/Spectrum.h"
#include "core/ifs/SurfaceIfs.h"
#include "model/AttractorItem.h"
#include "model/ExactCurve.h"
#include "model/Project.h"
#include "model/SubdivisionMeshItem.h"
#include "model/SubdivisionSurfaceItem.h"
#include "render/AttractorImage.h"
#include "render/DensityFile.h"
#include "render/FigureFile.h"
#include "render/FigureRenderer.h"
#include "render/SurfaceFigure.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

#include <cmath>

namespace awb {

namespace {

// lupdate takes the context of FigureTr::tr() from the macro.
struct FigureTr {
    Q_DECLARE_TR_FUNCTIONS(awb::ItemFigure)
};

[[noreturn]] void fail(const QString &message) { throw InputError(message.toStdString()); }

// The attractor's raw density in the figure's frame, without title, polygons or margins:
// float32 counts (.exr) or the 16-bit log density (PNG), render/DensityFile.h.
void writeRawDensity(const FigureSpec &spec, const std::shared_ptr<const DerivedIfs> &d,
                     int depth, const FigureOptions &o, const QString &suffix,
                     const QString &caption, const QString &outFile)
{
    if (suffix != QLatin1String("exr") && suffix != QLatin1String("png"))
        fail(FigureTr::tr("the 16-bit density is written to PNG files, got '%1'").arg(outFile));
    if (d->polygon || (d->ifs.size() == 0 && !d->iterate))
        fail(FigureTr::tr("the raw density (.exr, 16-bit PNG) counts an attractor's points; "
                          "this item's figure is a polygon"));
    RenderRequest r;
    r.ifs = std::shared_ptr<const Ifs>(d, &d->ifs);
    r.iterate = d->iterate;
    r.chaos = d->chaos;
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
    IterationControl control;
    control.cancel = o.cancel;
    control.progress = o.progress;
    const AttractorDensity density = renderAttractorDensity(r, control);
    if (o.cancel && o.cancel->load())
        fail(FigureTr::tr("the rendering was cancelled"));
    DensityFileInfo info{r.world, caption, spec.metadata};
    if (o.rawDensity) {
        *o.rawDensity = RawDensity{density, info};
        return;
    }
    QString error;
    const bool ok = suffix == QLatin1String("exr")
                        ? writeDensityExr(outFile, density, info, &error)
                        : writeDensityPng16(outFile, density, info, &error);
    if (!ok)
        fail(error);
}

} // namespace

namespace {

// An item that draws its own picture (a flame, as flam3-render draws it): that picture alone,
// no caption or margins, in the item's own frame and size unless --bounds or --size are given
// (--bounds then exactly, without the figures' padding), with the item's own sample count
// (a flame's quality) unless --samples is.
void writeOwnPicture(const QString &itemName, const DerivedIfs &d, const FigureSpec &spec,
                     const FigureOptions &o, const FigureMetadata &metadata,
                     const QString &outFile)
{
    RenderRequest r;
    r.chaos = d.chaos;
    r.mode = RenderRequest::Mode::Random;
    r.tone = spec.tone;
    r.seed = spec.seed;
    r.threads = spec.threads;
    const bool own = d.chaos.width > 0 && d.chaos.height > 0;
    r.size = o.sizeGiven || !own ? QSize(o.width, o.height) : QSize(d.chaos.width, d.chaos.height);
    if (o.bounds.isValid()) {
        r.world = o.bounds;
    } else if (d.chaos.frame) {
        // The item's frame, centred and whole in the picture at square pixels (another --size
        // is the same picture at another resolution, more of the plane on the longer side).
        const auto &f = *d.chaos.frame;
        const double fw = f[2] - f[0], fh = f[3] - f[1];
        const double ppu = std::min(r.size.width() / fw, r.size.height() / fh);
        const double w = r.size.width() / ppu, h = r.size.height() / ppu;
        const double cx = 0.5 * (f[0] + f[2]), cy = 0.5 * (f[1] + f[3]);
        r.world = QRectF(cx - w / 2, cy - h / 2, w, h);
    } else {
        fail(FigureTr::tr("give --bounds: the item has no frame of its own"));
    }
    r.samples = o.samples ? *o.samples
                : d.chaos.samplesPerPixel > 0
                    ? std::uint64_t(std::max(1.0, std::round(d.chaos.samplesPerPixel * r.size.width()
                                                              * r.size.height())))
                    : spec.samples;
    if (double(r.samples) > double(kMaxChaosSamples))
        fail(FigureTr::tr("%1 samples; at most %2").arg(r.samples).arg(double(kMaxChaosSamples)));
    IterationControl control;
    control.cancel = o.cancel;
    control.progress = o.progress;
    QImage image;
    try {
        image = renderAttractorImage(r, 0, r.samples, nullptr, control);
    } catch (const InputError &e) {  // the picture's own limits: a flame's filters, its memory
        fail(FigureTr::tr("item '%1': %2").arg(itemName, QString::fromStdString(e.what())));
    }
    if (image.isNull() || (o.cancel && o.cancel->load()))
        fail(FigureTr::tr("the rendering was cancelled"));
    // The project inside, as every figure: File > Open of the PNG opens it.
    addPngText(image, metadata);
    // As every figure: zlib level 1, the whole file written at once.
    QString error;
    if (!writeFigureFile(outFile, [&](QIODevice &out, QString *) { return writePng(image, out); },
                         &error))
        fail(error);
}

} // namespace

void renderItemFigure(const Project &project, AttractorItem *item, const FigureOptions &o,
                      const QString &outFile, QRectF *measure)
{
    const auto d = item->derivedIfs();
    if (!d)
        fail(FigureTr::tr("item '%1': %2").arg(item->name(), item->derivedError()));
    const AlgorithmSpec &alg = item->algorithm();
    FigureSpec spec;
    spec.ifs = &d->ifs;
    spec.iterate = d->iterate;
    spec.chaos = d->chaos;
    spec.random = o.samples || (alg.mode == AlgorithmSpec::Mode::Random && !o.depth);
    spec.samples = o.samples ? *o.samples : std::uint64_t(alg.samples);
    spec.seed = o.seed ? *o.seed : std::uint64_t(alg.seed);
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
    if (d->chaos && !spec.random)
        fail(FigureTr::tr("item '%1' is drawn by random iteration only (its maps are not "
                          "affine): give --samples, not --depth")
                 .arg(item->name()));
    if (d->ifs.size() > 0 && !spec.random && !d->iterate) {
        const IfsCheck check = checkIfs(d->ifs);
        if (!check.contractive)
            fail(FigureTr::tr("item '%1': %2").arg(item->name(),
                                                   QString::fromStdString(check.message)));
        const double images = imageCount(d->ifs, depth);
        if (images > 4e9)
            fail(FigureTr::tr("depth %1 makes %2 images; at most 4e9 are rendered")
                     .arg(depth)
                     .arg(images, 0, 'g', 3));
    }
    if (d->ifs.size() > 0 || d->iterate)
        spec.start = item->coreStartSet(*d);
    const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(item);
    if (d->surface || mesh || item->pointDimension() == 3) {
        if (o.bits == 16 || o.format == QLatin1String("exr")
            || QFileInfo(outFile).suffix().toLower() == QLatin1String("exr"))
            fail(FigureTr::tr("the raw density (.exr, 16-bit PNG) is of attractors drawn in "
                              "the plane; '%1' is drawn in space")
                     .arg(item->name()));
        const auto *surface = qobject_cast<const SubdivisionSurfaceItem *>(item);
        const SurfaceCamera camera = surface ? surface->camera() : SurfaceCamera{};
        const auto [az, el] = o.view ? *o.view : std::pair{camera.azimuth, camera.elevation};
        if (!std::isfinite(az) || !std::isfinite(el) || std::abs(el) > 90)
            fail(FigureTr::tr("the view must be azimuth and elevation in degrees with "
                              "|elevation| <= 90, got %1, %2")
                     .arg(az)
                     .arg(el));
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
        const QString what = s.random ? FigureTr::tr("%1 random points").arg(s.samples)
                                      : FigureTr::tr("F^%1(X0)").arg(depth);
        QString maps;
        if (!d->mapIndex.empty()) {
            QStringList on;
            for (int i : d->mapIndex)
                on << QString::number(i + 1);
            maps = FigureTr::tr(", maps %1 of %2").arg(on.join(' ')).arg(d->S.count());
        }
        s.caption = FigureTr::tr("%1: %2%3 — orthographic view from azimuth %4°, elevation %5°")
                        .arg(item->name(), what, maps)
                        .arg(az)
                        .arg(el);
        s.metadata = itemFigureMetadata(project, *item);
        s.control.cancel = o.cancel;
        s.control.progress = o.progress;
        QString error;
        if (!writeSurfaceFigure(s, outFile, &error, o.format))
            fail(error);
        return;
    }
    const QString format =
        o.format.isEmpty() ? QFileInfo(outFile).suffix().toLower() : o.format;
    if (d->chaos.picture && spec.tone.mode == Accumulation::Density && !measure
        && format == QLatin1String("png") && o.bits == 8 && !o.rawDensity) {
        writeOwnPicture(item->name(), *d, spec, o, itemFigureMetadata(project, *item), outFile);
        return;
    }
    // A game of its own (a flame): its points are handles of its maps, not of the figure.
    for (int s = 0; !d->chaos && s < item->controlPointSetCount(); ++s)
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
                          ? FigureTr::tr("%1: %2 random points").arg(item->name()).arg(spec.samples)
                          : FigureTr::tr("%1: F^%2(X0)").arg(item->name()).arg(depth);
    if (d->polygon) // a normal-vector curve: the polygon after `steps` is the figure
        caption = FigureTr::tr("%1: polygon after %2 steps")
                      .arg(item->name())
                      .arg(item->parameter("steps").toInt());
    spec.panels = {{caption + o.captionSuffix, depth}};
    spec.bounds = o.bounds;
    if (measure) {
        *measure = contentBounds(spec);
        return;
    }
    spec.metadata = itemFigureMetadata(project, *item);
    spec.cancel = o.cancel;
    spec.progress = o.progress;
    const QString suffix = o.format.isEmpty() ? QFileInfo(outFile).suffix().toLower() : o.format;
    if (suffix == QLatin1String("exr") || o.bits == 16 || o.rawDensity) {
        writeRawDensity(spec, d, depth, o, suffix, caption, outFile);
        return;
    }
    QString error;
    if (!writeFigure(spec, outFile, &error, o.format))
        fail(error);
    if (o.cancel && o.cancel->load()) {
        // An unfinished picture is not left behind as if it were the figure.
        QFile::remove(outFile);
        fail(FigureTr::tr("the rendering was cancelled"));
    }
}

} // namespace awb
