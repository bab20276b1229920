#include "core/flame/FlameChaos.h"

#include "core/BigAllocator.h"
#include "core/Messages.h"
#include "core/Threads.h"
#include "core/Types.h"
#include "core/flame/Variations.h"
#include "core/flame/FlameGame.h"
#include "core/flame/FlameStep.h"
#include "core/flame/XformWave.h"
#include "core/ifs/Random.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

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

// The orbits of one stream: how many run at once. Enough that the orbits waiting for each
// xform fill registers and a stack's pass through its xform and step amortises their setup
// (256 orbits against 64: about 5-8 % faster on the bench's three-xform flame; the stacks,
// 32 bytes an orbit per xform, stay in the first-level cache), few enough that a small request
// (a window's first pictures) does not spend its samples on fuses. A function of the stream's
// samples and the flame alone: equal requests give equal pictures on any number of threads.
std::size_t waveOrbits(std::uint64_t samples, std::size_t xforms)
{
    const std::uint64_t most = std::clamp<std::uint64_t>(32 * xforms, 256, 512);
    return std::size_t(std::clamp<std::uint64_t>(samples / 2048, 4, most));
}

static_assert(kBatch <= 0xffff && kFuse <= 0xff && kMaxXforms < 0xffff);

// Subnormal numbers as zero while the game runs on this thread (MXCSR's flush-to-zero and
// denormals-are-zero), restored after: an orbit drawn towards an axis (a coordinate shrinking
// by a factor each step, as in most flames with linear and spherical) reaches them within a
// few thousand steps, and every operation on one costs a microcode assist -- the flame of
// three linear+spherical xforms took 16.6 ns a sample, 7.9 without. They are far inside one
// cell (a picture's cell is some 1e-3 of the plane), so the picture does not change.
struct SubnormalsAsZero {
#if defined(__SSE__) || defined(__x86_64__)
    unsigned saved = _mm_getcsr();
    SubnormalsAsZero() { _mm_setcsr(saved | 0x8040u); }  // FTZ (bit 15) and DAZ (bit 6)
    ~SubnormalsAsZero() { _mm_setcsr(saved); }
#endif
    SubnormalsAsZero(const SubnormalsAsZero &) = delete;
    SubnormalsAsZero &operator=(const SubnormalsAsZero &) = delete;
};

// One stream's samples into `sink`, as flam3's game (flam3_iterate) on each of its orbits:
// batches of kBatch samples from a random restart after kFuse steps, the xform by weight or
// xaos row, the colour moved first, a bad value retried from flam3's replacement up to four
// times (the fifth drawn), the final xform drawn with its opacity, the xform's opacity.
//
// Each xform keeps a stack of the orbits that chose it, their points side by side: the game
// takes a stack whole through its xform (XformWave: four orbits a register; the scalar kernels
// lane by lane without AVX2), then each orbit is drawn, chooses its next xform and goes onto
// that stack (the step: FlameStep.h, eight orbits a register on AVX-512, else the scalar loop
// here, which also takes the orbits the vector step leaves). Full registers first; the stacks
// that cannot fill one only when none can. The orbits advance at their own pace; each is
// flam3's chain, whatever the order they are taken in. A hit goes to the sink, which adds it
// some hits later (ColourSink).
template <class Sink>
FlameStats runWave(const Xforms &xf, const Choice &choice, const Plot &plot, std::uint64_t seed,
                   int stream, std::uint64_t samples, Sink &sink,
                   const IterationControl &control, std::atomic<std::uint64_t> &done,
                   double total)
{
    const SubnormalsAsZero subnormals;
    FlameStats stats;
    WaveRandom random(seed, std::uint64_t(stream));
    const std::size_t nx = xf.maps.size();
    const std::size_t orbits = waveOrbits(samples, nx);
    // A register's orbits: the game advances full ones first.
    const std::size_t W = xf.wide ? XformWave::kWidth : 4;

    // Each stack on its own cache lines: room for every orbit, rounded up to a register, and a
    // register's padding.
    constexpr std::size_t kRegister = XformWave::kWidth;
    const std::size_t cap = (orbits + kRegister - 1) / kRegister * kRegister + kStackPadding;
    static_assert(XformWave::kWidth <= kStackPadding);
    // On cache lines (BigAllocator), as the stacks' points after the xform.
    BigVector<double> sx(nx * cap), sy(nx * cap), sc(nx * cap);
    BigVector<OrbitCounters> sn(nx * cap);
    std::vector<std::uint32_t> top(nx, 0);
    const Stacks stacks{sx.data(), sy.data(), sc.data(), sn.data(), top.data(), cap};
    // One stack's points after its xform, and after the final xform.
    BigVector<double> qx(cap), qy(cap), gx(cap), gy(cap);
    std::vector<std::uint8_t> bad(cap), finalBad(cap);
    // The shares: samples left, and the batch being drawn.
    std::vector<std::uint64_t> left(orbits);
    std::vector<int> batch(orbits);
    const AliasTable *rows = choice.rows.data();
    const bool xaos = choice.xaos;
    // The AVX-512 step's orbits left to the scalar one.
    const bool wide = xf.wide;
    std::vector<std::uint32_t> deferred(wide ? cap : 0);
    std::vector<double> deferredColour(wide ? cap : 0);
    std::vector<OrbitCounters> deferredCounters(wide ? cap : 0);

    // Starts share s's next batch onto its first xform's stack; false when it has drawn its
    // samples.
    auto restart = [&](Xoshiro256 &rng, std::size_t s) {
        if (left[s] == 0)
            return false;
        batch[s] = int(std::min<std::uint64_t>(left[s], kBatch));
        left[s] -= std::uint64_t(batch[s]);
        const double x = 2.0 * uniform01(rng) - 1.0, y = 2.0 * uniform01(rng) - 1.0;
        const double c = uniform01(rng);
        stacks.push(std::size_t(rows[0].pick(rng.next())), x, y, c,
                    OrbitCounters{std::uint16_t(batch[s]), std::uint8_t(kFuse), 0, 0,
                                  std::uint16_t(s)});
        return true;
    };
    std::size_t alive = 0;
    for (std::size_t s = 0; s < orbits; ++s) {
        left[s] = samples / orbits + (s < samples % orbits ? 1 : 0);
        alive += restart(random.scalar, s) ? 1 : 0;
    }
    // A batch drawn: counted, and the share's next started, if any.
    auto finished = [&](Xoshiro256 &rng, std::size_t s) {
        stats.samples += std::uint64_t(batch[s]);
        const std::uint64_t d = done.fetch_add(std::uint64_t(batch[s])) + std::uint64_t(batch[s]);
        if (control.progress)
            control.progress(std::min(1.0, double(d) / total));
        if (!restart(rng, s))
            --alive;
    };
    const XformWave *finalWave = xf.finalWave.get();
    const double finalTowards = xf.finalSpeed * xf.finalColour, finalKeep = 1.0 - xf.finalSpeed;
    const double finalOpacity = xf.finalOpacity;

    // The AVX-512 step's rule for each xform, made once.
    std::vector<StepRule> rules;
    if (wide)
        for (std::size_t k = 0; k < nx; ++k) {
            const AliasTable &row = rows[xaos ? k + 1 : 0];
            rules.push_back({.towards = xf.speed[k] * xf.colour[k],
                             .keep = 1.0 - xf.speed[k],
                             .opacity = xf.opacity[k],
                             .opacityByChance = Sink::kOpacityByChance,
                             .table = sink.table(k),
                             .last = std::uint16_t(k + 1),
                             .final = finalWave != nullptr,
                             .finalTowards = finalTowards,
                             .finalKeep = finalKeep,
                             .finalOpacity = finalOpacity,
                             .next = {row.size(), row.uniform(), row.thresholds(), row.aliases()},
                             .camera = plot.numbers(),
                             .prefetch = sink.prefetchBase(),
                             .stride = sizeof(std::array<std::uint32_t, 4>)});
        }

    // Xform k on its stack's orbits, each then drawn and pushed onto its next xform's stack
    // (this one's too: an orbit is read before any push can reach its place).
    auto advance = [&](std::size_t k) {
        const Stacks st = stacks;
        const std::size_t m = st.top[k];
        st.top[k] = 0;
        const std::size_t base = k * st.cap;
        const double *px = qx.data(), *py = qy.data(), *fx = gx.data(), *fy = gy.data();
        const std::uint8_t *isBad = bad.data();
        xf.waves[k].apply(st.x + base, st.y + base, qx.data(), qy.data(), bad.data(), int(m),
                          random);
        if (finalWave)
            finalWave->apply(px, py, gx.data(), gy.data(), finalBad.data(), int(m), random);
        const FlameHits hits = sink.room(m);
        std::size_t drawn = 0, todo = m;
        const std::uint32_t *which = nullptr;
        const double *colours = st.c + base;
        const OrbitCounters *counters = st.n + base;
        std::uint64_t offscreen = 0;
        const double opacity = xf.opacity[k];
        const std::uint32_t table = sink.table(k);
        const int last = int(k) + 1;
        if (wide) {  // eight orbits a register; the rare ones left to the loop below
            const StepOrbits orbits{px, py, isBad, finalWave ? fx : nullptr,
                                    finalWave ? fy : nullptr, colours, counters, m};
            StepOut out{hits, deferred.data(), deferredColour.data(), deferredCounters.data()};
            stepAvx512(orbits, rules[k], st, random.step, out);
            drawn = out.drawn;
            offscreen = out.offscreen;
            todo = out.deferredCount;
            which = deferred.data();
            colours = deferredColour.data();
            counters = deferredCounters.data();
        }
        // In registers for the loop (the stores below could otherwise be any of these).
        Xoshiro256 rng = random.scalar;
        const Plot camera = plot;
        const AliasTable *next = rows;
        const bool byRow = xaos;
        std::uint64_t badValues = 0;
        // The colour's move by xform k (first, as in flam3's apply_xform).
        const double towards = xf.speed[k] * xf.colour[k], keep = 1.0 - xf.speed[k];
        for (std::size_t i = 0; i < todo; ++i) {
            // Orbit j of the stack; its colour and counters at i (the AVX-512 step's copies).
            const std::size_t j = which ? which[i] : i;
            OrbitCounters n = counters[i];
            const double colour = towards + keep * colours[i];
            const double x = px[j], y = py[j];
            if (isBad[j]) {  // retried from the replacement, the xaos row unchanged
                ++badValues;
                if (++n.bad < 5) {
                    st.push(std::size_t(next[byRow ? n.last : 0].pick(rng.next())), x, y, colour,
                            n);
                    continue;
                }
            }
            n.bad = 0;
            n.last = std::uint16_t(last);
            if (n.fuse > 0) {
                --n.fuse;
            } else {
                if (sink.keep(opacity, rng)) {
                    double hx = x, hy = y, hc = colour;
                    if (finalWave && (finalOpacity == 1.0 || uniform01(rng) < finalOpacity)) {
                        hx = fx[j];
                        hy = fy[j];
                        hc = finalTowards + finalKeep * colour;
                    }
                    const std::ptrdiff_t cell = camera.cell(hx, hy);
                    if (cell < 0) {
                        ++offscreen;
                    } else {
                        sink.prefetch(std::size_t(cell));
                        hits.put(drawn++, hc, opacity, std::size_t(cell), table);
                    }
                }
                if (--n.togo == 0) {
                    finished(rng, n.share);
                    continue;
                }
            }
            st.push(std::size_t(next[byRow ? last : 0].pick(rng.next())), x, y, colour, n);
        }
        random.scalar = rng;
        stats.badValues += badValues;
        stats.offscreen += offscreen;
        sink.take(drawn);
    };

    while (alive > 0) {
        if (control.cancel && control.cancel->load(std::memory_order_relaxed)) {
            stats.cancelled = true;
            break;
        }
        bool full = false;
        for (std::size_t k = 0; k < nx; ++k)
            if (top[k] >= W) {
                advance(k);
                full = true;
            }
        if (!full)
            for (std::size_t k = 0; k < nx; ++k)
                if (top[k] > 0)
                    advance(k);
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
    const SubnormalsAsZero subnormals;  // as the game (the displaced point is never one)
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
        return LabelSink{image, coordinates.data(), {}};
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
    std::vector<double> dmap(4 * 256);
    if (flame)
        for (std::size_t i = 0; i < 256; ++i) {
            dmap[4 * i] = flame->palette[i].r * 255.0;
            dmap[4 * i + 1] = flame->palette[i].g * 255.0;
            dmap[4 * i + 2] = flame->palette[i].b * 255.0;
            dmap[4 * i + 3] = 255.0;
        }
    const HitPalette palette{dmap.data(), flame && flame->paletteMode == PaletteMode::Linear};
    std::vector<double> opacities;
    if (flame)
        for (const FlameXform &x : flame->xforms)
            opacities.push_back(x.opacity);
    const HitDeltas deltas = HitDeltas::of(palette, opacities);
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
        using Adds = ColourSink::Adds;
        const Adds adds = XformWave::wide()        ? Adds::Avx512
                          : XformWave::available() ? Adds::Avx2
                                                   : Adds::Scalar;
        ColourSink sink{h, palette, adds, deltas.empty() ? nullptr : &deltas, {}};
        sink.hits.resize(2 * kHitRun);
        return sink;
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
