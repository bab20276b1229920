#include "core/flame/FlameChaos.h"

#include "core/Messages.h"
#include "core/Threads.h"
#include "core/Types.h"
#include "core/flame/Variations.h"
#include "core/ifs/Random.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>

namespace awb::flame {

namespace {

std::string tr(const char *text) { return coreTranslate("awb::flame", text); }


bool finiteAffine(const Affine2 &m)
{
    return std::isfinite(m.a) && std::isfinite(m.b) && std::isfinite(m.c) && std::isfinite(m.d)
           && std::isfinite(m.e) && std::isfinite(m.f);
}

void checkXform(const FlameXform &x, const std::string &which)
{
    if (!finiteAffine(x.pre) || !finiteAffine(x.post))
        throw InputError(formatMessage(tr("%1: a coefficient is not a finite number"), which));
    for (const VariationTerm &v : x.variations) {
        if (v.id < 0 || v.id >= kVariationCount)
            throw InputError(formatMessage(tr("%1: variation %2 does not exist"), which, v.id));
        if (!std::isfinite(v.weight))
            throw InputError(formatMessage(tr("%1: the weight of variation %2 is not a finite "
                                              "number"),
                                           which, variationName(v.id)));
    }
    if (x.parameters.size() != std::size_t(parameterCount()))
        throw InputError(formatMessage(tr("%1: its variation parameters are incomplete"), which));
    for (std::size_t p = 0; p < x.parameters.size(); ++p)
        if (!std::isfinite(x.parameters[p]))
            throw InputError(formatMessage(tr("%1: parameter %2 is not a finite number"), which,
                                           parameterName(int(p))));
    for (double v : {x.colour, x.colourSpeed, x.opacity})
        if (!std::isfinite(v))
            throw InputError(formatMessage(tr("%1: its colour, colour speed or opacity is not a "
                                              "finite number"),
                                           which));
}

// The choice of the next xform: row 0 by the weights alone, row i + 1 after xform i by the
// weights times its xaos row (one row when no xaos differs from 1).
struct Choice {
    std::vector<AliasTable> rows;
    bool xaos = false;

    explicit Choice(const Flame &f)
    {
        const std::size_t n = f.xforms.size();
        std::vector<double> w(n);
        for (std::size_t j = 0; j < n; ++j)
            w[j] = f.xforms[j].weight;
        rows.emplace_back(w, int(n));
        for (const FlameXform &x : f.xforms)
            for (std::size_t j = 0; j < n; ++j)
                xaos = xaos || x.xaosTo(j) != 1.0;
        if (!xaos)
            return;
        for (const FlameXform &x : f.xforms) {
            std::vector<double> r(n);
            for (std::size_t j = 0; j < n; ++j)
                r[j] = w[j] * x.xaosTo(j);
            rows.emplace_back(r, int(n));
        }
    }
};

struct Plot {
    // World to cells: col = (x - x0) sx, row = (y_flame + y1) sy (y_flame = -y_world).
    double x0, y1, sx, sy;
    int w, h;
    // Rotation about the centre (flam3 rotates the plotted points, not the orbit).
    bool rotated = false;
    double cx = 0, cy = 0, r00 = 1, r01 = 0, r10 = 0, r11 = 1;

    Plot(const Flame &f, const RasterFrame &frame)
        : x0(frame.x0), y1(frame.y1), sx(frame.cellsX() / (frame.x1 - frame.x0)),
          sy(frame.cellsY() / (frame.y1 - frame.y0)), w(frame.cellsX()), h(frame.cellsY())
    {
        if (f.rotate != 0) {
            rotated = true;
            cx = f.centre[0];
            cy = f.centre[1];
            const double a = f.rotate * 2 * M_PI / 360.0;
            r00 = std::cos(a);
            r01 = -std::sin(a);
            r10 = -r01;
            r11 = r00;
        }
    }
    // The cell of a point, or -1 off the frame.
    std::ptrdiff_t cell(double x, double y) const
    {
        if (rotated) {
            const double dx = x - cx, dy = y - cy;
            x = dx * r00 + dy * r01 + cx;
            y = dx * r10 + dy * r11 + cy;
        }
        const double u = (x - x0) * sx, v = (y + y1) * sy;
        if (!(u >= 0 && v >= 0 && u < w && v < h))
            return -1;
        return std::ptrdiff_t(v) * w + std::ptrdiff_t(u);
    }
};

struct Xforms {
    std::vector<XformMap> maps;
    std::vector<double> colour, speed, opacity;
    std::unique_ptr<XformMap> final;
    double finalColour = 0, finalSpeed = 0, finalOpacity = 1;

    explicit Xforms(const Flame &f)
    {
        for (const FlameXform &x : f.xforms) {
            maps.emplace_back(x);
            colour.push_back(x.colour);
            speed.push_back(x.colourSpeed);
            opacity.push_back(x.opacity);
        }
        if (f.finalXform) {
            final = std::make_unique<XformMap>(*f.finalXform);
            finalColour = f.finalXform->colour;
            finalSpeed = f.finalXform->colourSpeed;
            finalOpacity = f.finalXform->opacity;
        }
    }
};

std::uint32_t paletteIndex(double c)
{
    // flam3: (int)(c * 256), the last entry for c = 1.
    const double i = c * 256.0;
    return i >= 255.0 ? 255u : (i > 0 ? std::uint32_t(i) : 0u);
}

// Where the engine's histogram takes a hit: its palette index as the label; an xform's opacity
// as the probability of drawing the hit (the same expected density in whole hits).
struct LabelSink {
    DensityImage &image;
    const std::uint8_t *coordinates;

    bool keep(double opacity, Xoshiro256 &rng) const
    {
        return opacity == 1.0 || (opacity > 0 && uniform01(rng) < opacity);
    }
    void hit(std::size_t k, double c, double) { image.add(k, paletteIndex(c), coordinates); }
    void flush() {}
};

// Where flam3's buckets take a hit (rect.c, iter_thread): the palette's colour at the colour
// coordinate, step or linear, weighted by the xform's opacity. A hit's 32-byte cell is
// scattered over a histogram larger than the caches: the cell is prefetched when the hit
// comes and added kPending hits later, so that the orbit's next steps hide the miss
// (measured on a 1024^2 variation flame: the add's load was 35 % of the render).
struct ColourSink {
    static constexpr std::size_t kPending = 16;  // a power of 2
    FlameHistogram &histogram;
    const std::array<double, 3> *dmap;  // the palette times 255
    bool linear;
    struct Hit {
        std::size_t k;
        double r, g, b, a;
    };
    std::array<Hit, kPending> pending{};
    std::size_t count = 0;

    bool keep(double opacity, Xoshiro256 &) const { return opacity != 0; }
    void hit(std::size_t k, double c, double opacity)
    {
        // flam3: (int)(c * 256), clamped; NaN cannot occur (finite colours, convex steps).
        const double d = std::clamp(c * 256.0, -1.0, 257.0);
        int i = int(d);
        std::array<double, 3> rgb;
        if (linear) {
            double frac;
            if (i < 0) {
                i = 0;
                frac = 0;
            } else if (i >= 255) {
                i = 254;
                frac = 1;
            } else {
                frac = d - i;
            }
            for (int j = 0; j < 3; ++j)
                rgb[std::size_t(j)] = dmap[i][std::size_t(j)] * (1.0 - frac)
                                      + dmap[i + 1][std::size_t(j)] * frac;
        } else {
            rgb = dmap[std::clamp(i, 0, 255)];
        }
        __builtin_prefetch(&histogram.cells[k], 1);
        Hit &slot = pending[count++ & (kPending - 1)];
        if (count > kPending)
            add(slot);
        slot = {k, opacity * rgb[0], opacity * rgb[1], opacity * rgb[2], opacity * 255.0};
    }
    // flam3's bump_no_overflow on an unsigned sum: dest = (unsigned)(dest + delta), held at
    // UINT_MAX -- and at 0 (a negative opacity, which flam3 would convert undefined).
    static void bump(std::uint32_t &dest, double delta)
    {
        constexpr std::uint32_t top = std::numeric_limits<std::uint32_t>::max();
        const double sum = double(dest) + delta;
        if (!(double(top - dest) > delta))
            dest = top;
        else if (sum > 0)
            dest = std::uint32_t(sum);
        else
            dest = 0;
    }
    void add(const Hit &h)
    {
        auto &cell = histogram.cells[h.k];
        bump(cell[0], h.r);
        bump(cell[1], h.g);
        bump(cell[2], h.b);
        bump(cell[3], h.a);
    }
    // The hits still pending, in the order they came (a cell takes its sums in hit order).
    void flush()
    {
        const std::size_t n = std::min(count, kPending);
        for (std::size_t j = count - n; j < count; ++j)
            add(pending[j & (kPending - 1)]);
        count = 0;
    }
};

// One stream's samples into `sink`.
template <class Sink>
FlameStats runStream(const Xforms &xf, const Choice &choice, const Plot &plot,
                     std::uint64_t seed, int stream, std::uint64_t samples, Sink &sink,
                     const IterationControl &control, std::atomic<std::uint64_t> &done,
                     double total)
{
    FlameStats stats;
    Xoshiro256 rng(seed, std::uint64_t(stream));
    auto uniform11 = [&] { return 2.0 * uniform01(rng) - 1.0; };
    std::uint64_t left = samples;
    while (left > 0) {
        if (control.cancel && control.cancel->load(std::memory_order_relaxed)) {
            stats.cancelled = true;
            sink.flush();
            return stats;
        }
        const int batch = int(std::min<std::uint64_t>(left, kBatch));
        double p[2] = {uniform11(), uniform11()};
        double c = uniform01(rng);
        int last = 0;
        int consecutive = 0;
        for (int i = -kFuse; i < batch; ++i) {
            const int fn = choice.rows[std::size_t(choice.xaos ? last : 0)].pick(rng.next());
            double q[2];
            // flam3's apply_xform moves the colour before it knows the point is bad, and a
            // retry keeps it (flam3_iterate: p[2] = q[2]).
            const double s = xf.speed[std::size_t(fn)];
            c = s * xf.colour[std::size_t(fn)] + (1.0 - s) * c;
            if (!xf.maps[std::size_t(fn)].apply(p, q, rng)) {
                ++stats.badValues;
                if (++consecutive < 5) {
                    p[0] = q[0];
                    p[1] = q[1];
                    --i;
                    continue;
                }
            }
            consecutive = 0;
            last = fn + 1;
            p[0] = q[0];
            p[1] = q[1];
            double r[2] = {p[0], p[1]};
            double rc = c;
            if (xf.final && (xf.finalOpacity == 1.0 || uniform01(rng) < xf.finalOpacity)) {
                xf.final->apply(p, r, rng);
                rc = xf.finalSpeed * xf.finalColour + (1.0 - xf.finalSpeed) * c;
            }
            if (i < 0)
                continue;
            const double opacity = xf.opacity[std::size_t(fn)];
            if (!sink.keep(opacity, rng))
                continue;
            const std::ptrdiff_t k = plot.cell(r[0], r[1]);
            if (k < 0) {
                ++stats.offscreen;
                continue;
            }
            sink.hit(std::size_t(k), rc, opacity);
        }
        left -= std::uint64_t(batch);
        stats.samples += std::uint64_t(batch);
        const std::uint64_t d = done.fetch_add(std::uint64_t(batch)) + std::uint64_t(batch);
        if (control.progress)
            control.progress(std::min(1.0, double(d) / total));
    }
    sink.flush();
    return stats;
}

// The streams of `job` on its threads, each thread's sink made by makeSink(t) (t = 0 first, on
// the caller's thread); returns the summed stats.
template <class MakeSink>
FlameStats playStreams(const FlameRaster &job, const IterationControl &control,
                       MakeSink makeSink)
{
    if (!job.flame)
        throw InputError(tr("there is no flame to draw"));
    const Flame &flame = *job.flame;
    checkFlame(flame);
    job.frame.validate();
    const Xforms xf(flame);
    const Choice choice(flame);
    const Plot plot(flame, job.frame);
    const int threads = std::clamp(job.threads, 1, kChaosStreams);
    std::vector<FlameStats> results(static_cast<std::size_t>(threads));
    std::atomic<std::uint64_t> done{0};
    const double total = std::max(1.0, double(job.samples));
    onThreads(threads, [&](int t) {
        auto sink = makeSink(t);
        const int first = kChaosStreams * t / threads, last = kChaosStreams * (t + 1) / threads;
        FlameStats &r = results[std::size_t(t)];
        for (int s = first; s < last && !r.cancelled; ++s) {
            const FlameStats one = runStream(xf, choice, plot, job.seed, s,
                                             streamShare(job.samples, s), sink, control, done,
                                             total);
            r.samples += one.samples;
            r.badValues += one.badValues;
            r.offscreen += one.offscreen;
            r.cancelled = one.cancelled;
        }
    });
    FlameStats stats;
    for (const FlameStats &r : results) {
        stats.samples += r.samples;
        stats.badValues += r.badValues;
        stats.offscreen += r.offscreen;
        stats.cancelled = stats.cancelled || r.cancelled;
    }
    return stats;
}

} // namespace

FlameLyapunov flameLyapunov(const Flame &f, std::uint64_t steps, std::uint64_t seed)
{
    checkFlame(f);
    const Xforms xf(f);
    const Choice choice(f);
    Xoshiro256 rng(seed, 0);
    FlameLyapunov out;
    double p[2] = {2.0 * uniform01(rng) - 1.0, 2.0 * uniform01(rng) - 1.0};
    double v[2] = {std::sqrt(0.5), std::sqrt(0.5)};
    double sum = 0;
    int last = 0;
    for (std::uint64_t i = 0; i < steps + std::uint64_t(kFuse); ++i) {
        const int fn = choice.rows[std::size_t(choice.xaos ? last : 0)].pick(rng.next());
        last = fn + 1;
        const XformMap &m = xf.maps[std::size_t(fn)];
        Xoshiro256 twin = rng;  // the displaced point takes the same random numbers
        const double h = 1e-7 * std::max(1.0, std::hypot(p[0], p[1]));
        const double pd[2] = {p[0] + h * v[0], p[1] + h * v[1]};
        double q[2], qd[2];
        const bool ok = m.apply(p, q, rng);
        const bool okd = m.apply(pd, qd, twin);
        p[0] = q[0];
        p[1] = q[1];
        if (!ok || !okd) {
            ++out.badValues;
            continue;
        }
        const double dx = qd[0] - q[0], dy = qd[1] - q[1];
        const double d = std::hypot(dx, dy);
        if (!std::isfinite(d))
            continue;
        if (i >= std::uint64_t(kFuse)) {
            // A map that collapses the direction (d = 0) contracts it by at least 1e-16.
            sum += std::log(std::max(d / h, 1e-16));
            ++out.steps;
        }
        if (d > 0) {
            v[0] = dx / d;
            v[1] = dy / d;
        }
    }
    out.exponent = out.steps ? sum / double(out.steps) : std::numeric_limits<double>::quiet_NaN();
    return out;
}

void checkFlame(const Flame &flame)
{
    const std::size_t n = flame.xforms.size();
    if (n == 0)
        throw InputError(tr("the flame has no xform"));
    if (n > std::size_t(kMaxXforms))
        throw InputError(formatMessage(tr("the flame has %1 xforms; at most %2 are drawn"), n,
                                       kMaxXforms));
    double total = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const FlameXform &x = flame.xforms[i];
        const std::string which = formatMessage(tr("xform %1"), i + 1);
        checkXform(x, which);
        if (!std::isfinite(x.weight) || x.weight < 0)
            throw InputError(formatMessage(tr("%1: its weight %2 is not a number >= 0"), which,
                                           streamedNumber(x.weight)));
        if (x.xaos.size() > n)
            throw InputError(formatMessage(tr("%1: its xaos row has %2 entries for %3 xforms"),
                                           which, x.xaos.size(), n));
        for (double v : x.xaos)
            if (!std::isfinite(v) || v < 0)
                throw InputError(formatMessage(tr("%1: a xaos entry is not a number >= 0"), which));
        total += x.weight;
    }
    if (!(total > 0) || !std::isfinite(total))
        throw InputError(tr("every xform of the flame has weight 0: none is ever chosen"));
    for (std::size_t i = 0; i < n; ++i) {
        double row = 0;
        for (std::size_t j = 0; j < n; ++j)
            row += flame.xforms[j].weight * flame.xforms[i].xaosTo(j);
        if (!(row > 0))
            throw InputError(formatMessage(tr("xform %1: its xaos row forbids every xform, so an "
                                              "orbit that reaches it cannot go on"),
                                           i + 1));
    }
    if (flame.finalXform)
        checkXform(*flame.finalXform, tr("the final xform"));
}

RasterFrame flameFrame(const Flame &f)
{
    RasterFrame frame;
    frame.width = f.width;
    frame.height = f.height;
    const double ppu = f.scale * std::pow(2.0, f.zoom);
    const double W = f.width / ppu, H = f.height / ppu;
    frame.x0 = f.centre[0] - W / 2;
    frame.x1 = f.centre[0] + W / 2;
    // y up: the flame's [cy - H/2, cy + H/2] mirrored.
    frame.y0 = -f.centre[1] - H / 2;
    frame.y1 = -f.centre[1] + H / 2;
    return frame;
}

double flameSamples(const Flame &f)
{
    return f.quality * std::pow(4.0, f.zoom) * double(f.width) * double(f.height);
}

std::vector<Rgb8> flamePaletteRgb(const Flame &f)
{
    std::vector<Rgb8> out(256);
    auto byte = [](double v) {
        return std::uint8_t(std::clamp(std::lround(v * 255.0), long(0), long(255)));
    };
    for (std::size_t i = 0; i < 256; ++i)
        out[i] = Rgb8{byte(f.palette[i].r), byte(f.palette[i].g), byte(f.palette[i].b)};
    return out;
}

FlameStats accumulateFlame(const FlameRaster &job, DensityImage &out,
                           const IterationControl &control)
{
    std::vector<std::uint8_t> coordinates(256);
    for (int i = 0; i < 256; ++i)
        coordinates[std::size_t(i)] = std::uint8_t(i);
    const int threads = std::clamp(job.threads, 1, kChaosStreams);
    std::vector<DensityImage> images(static_cast<std::size_t>(threads - 1));
    const FlameStats stats = playStreams(job, control, [&](int t) {
        DensityImage &image = t == 0 ? out : images[std::size_t(t - 1)];
        image.reset(job.frame.cellsX(), job.frame.cellsY(), job.accumulation);
        return LabelSink{image, coordinates.data()};
    });
    for (const DensityImage &image : images)
        out.merge(image);
    out.offscreen = stats.offscreen;
    return stats;
}

FlameStats accumulateFlameColours(const FlameRaster &job, FlameHistogram &out,
                                  const IterationControl &control,
                                  std::vector<FlameHistogram> *kept)
{
    const Flame *flame = job.flame;
    std::array<std::array<double, 3>, 256> dmap{};
    if (flame)
        for (std::size_t i = 0; i < 256; ++i)
            dmap[i] = {flame->palette[i].r * 255.0, flame->palette[i].g * 255.0,
                       flame->palette[i].b * 255.0};
    const bool linear = flame && flame->paletteMode == PaletteMode::Linear;
    const int threads = std::clamp(job.threads, 1, kChaosStreams);
    const std::size_t cells = std::size_t(job.frame.cellsX()) * std::size_t(job.frame.cellsY());
    std::vector<FlameHistogram> own;
    std::vector<FlameHistogram> &parts = kept ? *kept : own;
    parts.resize(static_cast<std::size_t>(threads - 1));
    out.width = job.frame.cellsX();
    out.height = job.frame.cellsY();
    const FlameStats stats = playStreams(job, control, [&](int t) {
        FlameHistogram &h = t == 0 ? out : parts[std::size_t(t - 1)];
        h.cells.assign(cells, {0, 0, 0, 0});
        return ColourSink{h, dmap.data(), linear};
    });
    // The parts summed (whole numbers, held at 2^32 - 1), cell ranges on the threads.
    onThreads(threads, [&](int t) {
        const std::size_t first = cells * std::size_t(t) / std::size_t(threads);
        const std::size_t last = cells * std::size_t(t + 1) / std::size_t(threads);
        for (const FlameHistogram &part : parts)
            for (std::size_t i = first; i < last; ++i)
                for (int c = 0; c < 4; ++c) {
                    std::uint32_t &a = out.cells[i][std::size_t(c)];
                    const std::uint64_t sum = std::uint64_t(a) + part.cells[i][std::size_t(c)];
                    a = std::uint32_t(std::min<std::uint64_t>(sum, 0xffffffffu));
                }
    });
    return stats;
}

} // namespace awb::flame
