#include "render/AttractorImage.h"

#include "core/analysis/Spectrum.h"
#include "core/ifs/Random.h"
#include "core/render/Engine.h"
#include "model/ItemValues.h"

#include <QElapsedTimer>

#include <cstring>

#include <algorithm>
#include <cmath>
#include <thread>

namespace awb {

namespace {

QColor gradientAt(const QList<QColor> &stops, double t)
{
    if (stops.isEmpty())
        return QColor(Qt::black);
    if (stops.size() == 1)
        return stops.front();
    const double x = std::clamp(t, 0.0, 1.0) * double(stops.size() - 1);
    const int i = std::min(int(x), int(stops.size()) - 2);
    const double u = x - i;
    const QColor &a = stops[i], &b = stops[i + 1];
    return QColor::fromRgbF(float(a.redF() + u * (b.redF() - a.redF())),
                            float(a.greenF() + u * (b.greenF() - a.greenF())),
                            float(a.blueF() + u * (b.blueF() - a.blueF())));
}

// Address symbols that pick the colour: 0 for one colour, 1 for the map, up to 3 (never more
// than the depth drawn) along the address.
int colourPrefix(const RenderRequest &r, int depth, int maps)
{
    switch (r.colouring.mode) {
    case AttractorColorMode::Single: return 0;
    case AttractorColorMode::ByMap: return 1;
    case AttractorColorMode::ByAddress: break;
    }
    int L = std::clamp(r.colouring.prefixLength, 1, 3);
    if (r.mode == RenderRequest::Mode::Deterministic)
        L = std::min(L, std::max(1, depth));
    // At most 65536 colour labels (three symbols of up to 40 maps).
    while (L > 1 && std::pow(double(maps), L) > 65536.0)
        --L;
    return L;
}

EngineColours colourTable(const RenderRequest &r, int prefix, int maps)
{
    EngineColours c;
    c.prefix = prefix;
    std::size_t labels = 1;
    for (int k = 0; k < prefix; ++k)
        labels *= std::size_t(maps);
    c.labelColours.resize(labels);
    std::uint8_t address[3] = {0, 0, 0};
    for (std::size_t label = 0; label < labels; ++label) {
        std::size_t code = label;
        for (int k = prefix - 1; k >= 0; --k) {
            address[k] = std::uint8_t(code % std::size_t(maps));
            code /= std::size_t(maps);
        }
        const QColor q = attractorAddressColor(r.colouring.mode, std::max(1, prefix), r.colouring.palette, maps,
                                               address, std::max(1, prefix));
        c.labelColours[label] = Rgb8{std::uint8_t(q.red()), std::uint8_t(q.green()),
                                     std::uint8_t(q.blue())};
    }
    return c;
}

int threadsFor(const RenderRequest &r)
{
    if (r.threads > 0)
        return std::min(r.threads, kChaosStreams);
    return std::clamp(int(std::thread::hardware_concurrency()), 1, kChaosStreams);
}

} // namespace

void checkRenderRequest(const RenderRequest &r)
{
    if (r.chaos) {
        // Its own chaos game: no start set, no contraction of `ifs` to check (a flame's
        // variations, not its affine parts, decide where its points go).
        if (r.mode != RenderRequest::Mode::Random)
            throw InputError("this item is drawn by random iteration only");
        if (r.size.width() < 1 || r.size.height() < 1)
            throw InputError("the image is empty");
        return;
    }
    if (!r.ifs || (r.ifs->size() == 0 && !r.iterate))
        throw InputError("there is no IFS to draw");
    if (r.ifs->views.empty())
        throw InputError("the IFS has no view to draw it with");
    if (r.size.width() < 1 || r.size.height() < 1)
        throw InputError("the image is empty");
    if (!r.iterate) {
        // Random iteration needs only contraction on average (a flame's maps, IfsCheck).
        const IfsCheck check = checkIfs(*r.ifs);
        const bool random = r.mode == RenderRequest::Mode::Random;
        if (!(random ? check.contractsOnAverage() : check.contractive))
            throw InputError(check.message);
    }
    if (r.start.vertices.rows() == 0)
        throw InputError("the start set is empty");
}

namespace {

QImage newPicture(const RasterFrame &frame)
{
    QImage image(frame.width, frame.height, QImage::Format_ARGB32_Premultiplied);
    if (image.isNull())
        throw InputError("not enough memory for a " + std::to_string(frame.width) + "x"
                         + std::to_string(frame.height) + " picture");
    return image;
}

RasterFrame pictureFrame(const RenderRequest &r)
{
    RasterFrame frame;
    const QRectF w = r.world.normalized();
    frame.width = r.size.width();
    frame.height = r.size.height();
    frame.x0 = w.left(), frame.x1 = w.right(), frame.y0 = w.top(), frame.y1 = w.bottom();
    frame.supersample = std::clamp(r.supersample, 1, 4);
    // Large exports: fewer cells per pixel rather than a histogram beyond 256 MB.
    while (frame.supersample > 1 && 8.0 * frame.cellsX() * frame.cellsY() > 256.0 * (1 << 20))
        --frame.supersample;
    frame.validate();
    return frame;
}

// The histogram of a picture: the frame, the colours and the engine's (or an automaton's)
// hits. False when control.cancel stopped it.
bool accumulatePicture(const RenderRequest &r, int depth, std::uint64_t samples,
                       const IterationControl &control, DensityImage &density, RasterFrame &frame,
                       EngineColours &colours, IterationStats &stats)
{
    checkRenderRequest(r);
    frame = pictureFrame(r);
    if (r.chaos) {
        // Its own chaos game, its own colours (a flame's palette, labels 0..255).
        colours.prefix = 1;
        colours.labelColours = r.chaos.colours;
        ChaosJob job;
        job.frame = frame;
        job.accumulation = r.tone.mode;
        job.samples = samples;
        job.seed = r.seed;
        job.threads = threadsFor(r);
        stats = r.chaos.run(job, density, control);
        return !(stats.cancelled || (control.cancel && control.cancel->load()));
    }
    // An automaton's address symbols are its arcs, up to the byte's range: colour them all
    // (its `ifs` has no maps).
    const int maps = r.iterate ? kMaxMaps : std::max(1, r.ifs->size());
    colours = colourTable(r, colourPrefix(r, depth, maps), maps);
    if (r.iterate) {
        // An automaton: its own iteration into the engine's rasteriser, one sink per thread.
        std::vector<std::unique_ptr<DensitySink>> sinks;
        std::vector<AttractorSink *> raw;
        for (int t = 0, n = threadsFor(r); t < n; ++t) {
            sinks.push_back(std::make_unique<DensitySink>(frame, r.ifs->views, r.tone.mode,
                                                          colours, maps));
            raw.push_back(sinks.back().get());
        }
        stats = r.iterate(r.start, depth, raw, control);
        density = std::move(sinks.front()->image());
        for (std::size_t t = 1; t < sinks.size(); ++t)
            density.merge(sinks[t]->image());
    } else {
        EngineJob job;
        job.ifs = r.ifs.get();
        job.start = r.start;
        job.random = r.mode == RenderRequest::Mode::Random;
        job.depth = depth;
        job.samples = samples;
        job.seed = r.seed;
        job.frame = frame;
        job.accumulation = r.tone.mode;
        job.colours = colours;
        job.threads = threadsFor(r);
        stats = accumulate(job, density, control);
    }
    return !(stats.cancelled || (control.cancel && control.cancel->load()));
}

} // namespace

AttractorDensity renderAttractorDensity(const RenderRequest &request,
                                        const IterationControl &control)
{
    RenderRequest r = request;
    r.tone.mode = Accumulation::Density;
    DensityImage density;
    AttractorDensity out;
    EngineColours colours;
    IterationStats stats;
    if (!accumulatePicture(r, r.depth, r.samples, control, density, out.frame, colours, stats))
        return {};
    out.rgba = densityChannels(density, out.frame, colours.labelColours);
    out.images = double(stats.images);
    return out;
}

QImage renderAttractorImage(const RenderRequest &r, int depth, std::uint64_t samples,
                            RenderInfo *info, const IterationControl &control)
{
    QElapsedTimer timer;
    timer.start();
    const QRectF w = r.world.normalized();
    if (r.chaos.picture && r.tone.mode == Accumulation::Density) {
        // The item's own tone (a flame as flam3 draws it): its pixels as they are.
        checkRenderRequest(r);
        ChaosJob job;
        job.frame = pictureFrame(r);
        job.accumulation = Accumulation::Density;
        job.samples = samples;
        job.seed = r.seed;
        job.threads = threadsFor(r);
        std::vector<std::uint32_t> pixels;
        const IterationStats stats = r.chaos.picture(job, pixels, control);
        if (stats.cancelled || (control.cancel && control.cancel->load())
            || pixels.size() != std::size_t(job.frame.width) * std::size_t(job.frame.height))
            return {};
        QImage image = newPicture(job.frame);
        for (int y = 0; y < job.frame.height; ++y)
            std::memcpy(image.scanLine(y), pixels.data() + std::size_t(y) * std::size_t(job.frame.width),
                        std::size_t(job.frame.width) * 4);
        if (info) {
            info->depth = 0;
            info->images = double(stats.images);
            info->seconds = timer.nsecsElapsed() * 1e-9;
            info->final = samples == r.samples;
            info->world = w;
            info->litPixels = std::uint64_t(job.frame.width) * std::uint64_t(job.frame.height);
        }
        return image;
    }
    // Reused by the next picture rendered on this thread (a drag: no allocation per step).
    static thread_local DensityImage density;
    RasterFrame frame;
    EngineColours colours;
    IterationStats stats;
    if (!accumulatePicture(r, depth, samples, control, density, frame, colours, stats))
        return {};

    QImage image = newPicture(frame);
    // 32-bit rows are contiguous: the tone mapping writes straight into the image.
    auto *argb = reinterpret_cast<std::uint32_t *>(image.bits());
    toneMapInto(density, frame, r.tone, colours.labelColours, argb);
    std::uint64_t lit = 0;
    for (std::size_t i = 0, n = std::size_t(frame.width) * frame.height; i < n; ++i)
        lit += (argb[i] >> 24) != 0;
    dilate(argb, frame.width, frame.height, std::clamp(r.dotRadius, 0, 4));
    if (info) {
        info->depth = r.mode == RenderRequest::Mode::Deterministic ? depth : 0;
        info->images = double(stats.images);
        info->seconds = timer.nsecsElapsed() * 1e-9;
        info->final = depth == r.depth && samples == r.samples;
        info->world = w;
        info->litPixels = lit;
    }
    return image;
}

AttractorColouring attractorColouring(const StyleSpec &style)
{
    AttractorColouring c;
    switch (style.colorBy) {
    case StyleSpec::ColorBy::Map: c.mode = AttractorColorMode::ByMap; break;
    case StyleSpec::ColorBy::Address: c.mode = AttractorColorMode::ByAddress; break;
    case StyleSpec::ColorBy::None: c.mode = AttractorColorMode::Single; break;
    }
    c.prefixLength = std::clamp(style.prefixLength, 1, 3);
    for (const QString &name : style.colors)
        c.palette.append(QColor(name));
    return c;
}

QColor attractorMapColor(int i)
{
    // Qualitative colours that read on white and in print (Tableau 10 without grey).
    static const QColor palette[] = {QColor(31, 119, 180), QColor(214, 39, 40),
                                     QColor(44, 160, 44),  QColor(148, 103, 189),
                                     QColor(255, 127, 14), QColor(140, 86, 75),
                                     QColor(227, 119, 194), QColor(23, 190, 207),
                                     QColor(188, 189, 34)};
    return palette[((i % 9) + 9) % 9];
}

QList<QColor> defaultAddressGradient()
{
    // Dark enough everywhere to stay visible on a white background.
    return {QColor(68, 1, 84), QColor(59, 82, 139), QColor(33, 145, 140), QColor(53, 170, 80),
            QColor(200, 150, 20), QColor(214, 39, 40)};
}

QColor attractorAddressColor(AttractorColorMode mode, int prefixLength,
                             const QList<QColor> &palette, int maps, const std::uint8_t *address,
                             int length)
{
    switch (mode) {
    case AttractorColorMode::Single:
        return palette.isEmpty() ? QColor(20, 20, 20) : palette.front();
    case AttractorColorMode::ByMap: {
        const int map = length > 0 ? address[0] : 0;
        return palette.isEmpty() ? attractorMapColor(map) : palette[map % palette.size()];
    }
    case AttractorColorMode::ByAddress: {
        // Dense index of the prefix in base N: neighbouring pieces of the curve get
        // neighbouring colours of the gradient.
        const int L = std::min(std::clamp(prefixLength, 1, 3), std::max(length, 1));
        const double N = std::max(1, maps);
        double index = 0;
        for (int k = 0; k < L; ++k)
            index = index * N + (k < length ? address[k] : 0);
        return gradientAt(palette.isEmpty() ? defaultAddressGradient() : palette,
                          (index + 0.5) / std::pow(N, L));
    }
    }
    return QColor(Qt::black);
}

} // namespace awb
