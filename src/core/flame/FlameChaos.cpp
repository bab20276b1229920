#include "core/flame/FlameChaos.h"

#include "core/Messages.h"
#include "core/Threads.h"
#include "core/Types.h"
#include "core/flame/Variations.h"
#include "core/flame/FlameGame.h"
#include "core/flame/XformWave.h"
#include "core/ifs/Random.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>

namespace awb::flame {

using namespace detail;

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

// The orbits of one stream's wave: how many run side by side. Each runs its own batches of
// kBatch samples after kFuse steps, as one scalar orbit does; enough lanes that the orbits
// choosing one xform fill registers, few enough that a small request (a window's first
// pictures) does not spend its samples on fuses. A function of the stream's samples alone:
// equal requests give equal pictures on any number of threads.
int waveOrbits(std::uint64_t samples)
{
    return int(std::clamp<std::uint64_t>(samples / 2048, 4, 64));
}

// One stream's samples into `sink`, its orbits advanced together (XformWave.h): in each step
// every running orbit chooses its xform, the orbits of each xform go through it together, then
// through the final xform, each into the sink in orbit order. flam3's game (flam3_iterate) on
// each orbit: batches of kBatch samples from a random restart after kFuse steps, the xform by
// weight or xaos row, the colour moved first, a bad value retried from flam3's replacement up
// to four times (the fifth drawn), the final xform drawn with its opacity, the xform's
// opacity. On every processor: XformWave applies the scalar kernels where AVX2 does not run.
template <class Sink>
FlameStats runWave(const Xforms &xf, const Choice &choice, const Plot &plot, std::uint64_t seed,
                   int stream, std::uint64_t samples, Sink &sink,
                   const IterationControl &control, std::atomic<std::uint64_t> &done,
                   double total)
{
    FlameStats stats;
    WaveRandom random(seed, std::uint64_t(stream));
    Xoshiro256 &rng = random.scalar;
    const std::size_t orbits = std::size_t(waveOrbits(samples));
    const std::size_t nx = xf.maps.size();
    constexpr int W = XformWave::kWidth;

    // The orbits' state by orbit; `running` lists the orbits still drawing, in order.
    std::vector<double> X(orbits), Y(orbits), C(orbits);
    std::vector<int> last(orbits), step(orbits), batch(orbits), consecutive(orbits);
    std::vector<std::uint64_t> left(orbits);
    std::vector<int> running;
    // Per running orbit (by position in `running`): its xform and its slot in the arrays.
    std::vector<int> chosen(orbits), slot(orbits);
    // Each xform's orbits in one run of the arrays, the runs starting at multiples of W.
    const std::size_t room = orbits + nx * W + W;
    std::vector<double> ax(room), ay(room), qx(room), qy(room);
    std::vector<std::uint8_t> bad(room);
    std::vector<int> count(nx), start(nx);
    std::vector<double> fx(room), fy(room), gx(room), gy(room);
    std::vector<std::uint8_t> fbad(room);
    std::vector<int> finalOf(orbits), finished;
    // The colour's move by xform: c' = speed colour + (1 - speed) c.
    std::vector<double> towards(nx), keepC(nx);
    for (std::size_t k = 0; k < nx; ++k) {
        towards[k] = xf.speed[k] * xf.colour[k];
        keepC[k] = 1.0 - xf.speed[k];
    }
    const AliasTable *rows = choice.rows.data();

    auto uniform11 = [&] { return 2.0 * uniform01(rng) - 1.0; };
    // Starts orbit o's next batch; false when it has drawn its share.
    auto restart = [&](std::size_t o) {
        if (left[o] == 0)
            return false;
        batch[o] = int(std::min<std::uint64_t>(left[o], kBatch));
        left[o] -= std::uint64_t(batch[o]);
        X[o] = uniform11();
        Y[o] = uniform11();
        C[o] = uniform01(rng);
        last[o] = 0;
        consecutive[o] = 0;
        step[o] = -kFuse;
        return true;
    };
    for (std::size_t o = 0; o < orbits; ++o) {
        left[o] = samples / orbits + (o < samples % orbits ? 1 : 0);
        if (restart(o))
            running.push_back(int(o));
    }
    // One drawn point (of an orbit that went through xform fn) into the sink.
    auto draw = [&](int fn, double px, double py, double rc) {
        const double opacity = xf.opacity[std::size_t(fn)];
        if (!sink.keep(opacity, rng))
            return;
        const std::ptrdiff_t k = plot.cell(px, py);
        if (k < 0)
            ++stats.offscreen;
        else
            sink.hit(std::size_t(k), rc, opacity);
    };

    while (!running.empty()) {
        if (control.cancel && control.cancel->load(std::memory_order_relaxed)) {
            stats.cancelled = true;
            break;
        }
        const std::size_t n = running.size();
        // Choose (the colour moves first, as in flam3's apply_xform), then gather by xform.
        std::fill(count.begin(), count.end(), 0);
        for (std::size_t r = 0; r < n; ++r) {
            const std::size_t o = std::size_t(running[r]);
            const int fn = rows[choice.xaos ? last[o] : 0].pick(rng.next());
            C[o] = towards[std::size_t(fn)] + keepC[std::size_t(fn)] * C[o];
            chosen[r] = fn;
            ++count[std::size_t(fn)];
        }
        int at = 0;
        for (std::size_t k = 0; k < nx; ++k) {
            start[k] = at;
            at += (count[k] + W - 1) / W * W;
        }
        for (std::size_t r = 0; r < n; ++r) {
            const std::size_t o = std::size_t(running[r]);
            const int sl = start[std::size_t(chosen[r])]++;
            slot[r] = sl;
            ax[std::size_t(sl)] = X[o];
            ay[std::size_t(sl)] = Y[o];
        }
        for (std::size_t k = 0; k < nx; ++k)
            if (count[k] > 0) {
                const std::size_t s0 = std::size_t(start[k] - count[k]);
                xf.waves[k].apply(&ax[s0], &ay[s0], &qx[s0], &qy[s0], &bad[s0], count[k],
                                  random);
            }
        // Bad values retried (no step); past the fuse, the point is drawn -- through the
        // final xform first, when there is one (the orbit goes on from the point before it).
        std::size_t finals = 0;
        finished.clear();
        for (std::size_t r = 0; r < n; ++r) {
            const std::size_t o = std::size_t(running[r]);
            const std::size_t sl = std::size_t(slot[r]);
            X[o] = qx[sl];
            Y[o] = qy[sl];
            if (bad[sl]) {
                ++stats.badValues;
                if (++consecutive[o] < 5) {
                    slot[r] = -1;
                    continue;
                }
            }
            consecutive[o] = 0;
            const int fn = chosen[r];
            last[o] = fn + 1;
            if (step[o]++ < 0) {
                slot[r] = -1;
                continue;
            }
            if (step[o] == batch[o])
                finished.push_back(int(r));
            if (!xf.finalWave) {
                draw(fn, X[o], Y[o], C[o]);
                continue;
            }
            if (xf.finalOpacity == 1.0 || uniform01(rng) < xf.finalOpacity) {
                finalOf[r] = int(finals);
                fx[finals] = X[o];
                fy[finals] = Y[o];
                ++finals;
            } else {
                finalOf[r] = -1;
            }
        }
        if (xf.finalWave) {
            if (finals > 0)
                xf.finalWave->apply(fx.data(), fy.data(), gx.data(), gy.data(), fbad.data(),
                                    int(finals), random);
            for (std::size_t r = 0; r < n; ++r) {
                if (slot[r] < 0)
                    continue;
                const std::size_t o = std::size_t(running[r]);
                const int f = finalOf[r];
                if (f < 0)
                    draw(chosen[r], X[o], Y[o], C[o]);
                else
                    draw(chosen[r], gx[std::size_t(f)], gy[std::size_t(f)],
                         xf.finalSpeed * xf.finalColour + (1.0 - xf.finalSpeed) * C[o]);
            }
        }
        // Finished batches: their orbits restart, or leave when they have drawn their share.
        if (!finished.empty()) {
            std::size_t kept = 0, f = 0;
            for (std::size_t r = 0; r < n; ++r) {
                const std::size_t o = std::size_t(running[r]);
                if (f < finished.size() && std::size_t(finished[f]) == r) {
                    ++f;
                    stats.samples += std::uint64_t(batch[o]);
                    const std::uint64_t d =
                        done.fetch_add(std::uint64_t(batch[o])) + std::uint64_t(batch[o]);
                    if (control.progress)
                        control.progress(std::min(1.0, double(d) / total));
                    if (!restart(o))
                        continue;
                }
                running[kept++] = int(o);
            }
            running.resize(kept);
        }
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
            const std::uint64_t share = streamShare(job.samples, s);
            const FlameStats one =
                runWave(xf, choice, plot, job.seed, s, share, sink, control, done, total);
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
    std::vector<ColourSink::Sums> dmap(256);
    if (flame)
        for (std::size_t i = 0; i < 256; ++i)
            dmap[i] = ColourSink::Sums{flame->palette[i].r * 255.0, flame->palette[i].g * 255.0,
                                       flame->palette[i].b * 255.0, 255.0};
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
