#pragma once
// The chaos game of a fractal flame (flame/Flame.h) into the engine's histogram
// (render/Density.h), as flam3 3.1.1 plays it (flam3_iterate, rect.c): orbits restarted from a
// random point of [-1, 1]^2 every kBatch samples and run kFuse steps before they are drawn;
// the xform chosen by weight, or by weight times the previous xform's xaos row; a bad value
// (flame/Variations.h) retried up to four times from flam3's random replacement, the fifth
// drawn; the final xform drawn on every point (with its opacity as a probability) without
// moving the orbit; the camera's rotation about the centre; a hit weighted by the xform's
// opacity, here drawn with that probability (the same expected density in whole hits).
//
// A hit's label is its colour coordinate as a palette index (0..255): Density accumulation
// colours a pixel by the palette at the hits' mean index, Hits by the smallest index that hit
// it (flamePaletteRgb gives the labels' colours). Equal requests give equal pictures on any
// number of threads: the samples run in the kChaosStreams streams of ifs/Random.h.

#include "core/BigAllocator.h"
#include "core/flame/Flame.h"
#include "core/ifs/Attractor.h"
#include "core/render/Density.h"

namespace awb::flame {

inline constexpr int kBatch = 10000;  // flam3's sub_batch_size
inline constexpr int kFuse = 15;      // flam3's FUSE_27
// The most xforms a flame may have: each is a row of the xaos table (N^2 entries) and an
// alias table, and flam3 itself draws at most a few dozen.
inline constexpr int kMaxXforms = 256;

struct FlameRaster {
    const Flame *flame = nullptr;
    // The world rectangle with y up: the flame's y mirrored (flameFrame gives the flame's own).
    RasterFrame frame;
    Accumulation accumulation = Accumulation::Density;
    std::uint64_t samples = 100000;
    std::uint64_t seed = 1;
    int threads = 1;
};

struct FlameStats {
    std::uint64_t samples = 0;    // drawn (after the fuse)
    std::uint64_t badValues = 0;  // flam3's badvals: replaced points
    std::uint64_t offscreen = 0;
    bool cancelled = false;
};

// Throws InputError naming the problem when the flame cannot be played: no xform, a weight
// or coefficient that is not a finite number, negative weights, every weight 0, a xaos row
// that forbids every xform, more than kMaxXforms xforms, an unknown variation.
void checkFlame(const Flame &flame);

// The picture rectangle flam3 draws (centre, scale x 2^zoom pixels per unit, size), with y up,
// at supersample 1: flam3-render's frame of the flame.
RasterFrame flameFrame(const Flame &flame);

// The sample count flam3 draws: quality x 4^zoom x width x height (flam3's sample density is
// the quality times the zoom's scale squared).
double flameSamples(const Flame &flame);

// Accumulates the flame into `out` (cleared first, sized to the frame's cells). Throws
// InputError (checkFlame, the frame). Returns with stats.cancelled when control.cancel is set.
FlameStats accumulateFlame(const FlameRaster &job, DensityImage &out,
                           const IterationControl &control = {});

// The histogram flam3 fills (rect.c's buckets, as flam3-render's default bits=33 keeps them:
// unsigned 32-bit sums): per cell the sums of the hits' palette colours (r, g, b, 0..255, as
// flam3's dmap, step or linear by the flame's palette mode) and of 255 per hit, each hit
// weighted by its xform's opacity (flam3's logvis); each sum, as flam3's, truncated to a whole
// number after every hit and held at 2^32 - 1. Row 0 at the top. Whole numbers: the threads'
// parts sum to the same histogram in any order.
// The cells as huge pages where Linux gives them (BigAllocator.h): the chaos game's scattered
// hits miss the translation cache on 4 KiB pages (a 1024^2 histogram is 16 MiB).
struct FlameHistogram {
    int width = 0, height = 0;
    BigVector<std::array<std::uint32_t, 4>> cells;
};

// Accumulates the flame into `out` (resized to the frame's cells and cleared; frame.supersample
// 1: job.frame's width and height are the cells). Throws InputError as accumulateFlame.
// `parts` (when given) holds the other threads' histograms and keeps their memory for the
// next call (a window's renders of one size: no allocation, no page faults each time).
FlameStats accumulateFlameColours(const FlameRaster &job, FlameHistogram &out,
                                  const IterationControl &control = {},
                                  std::vector<FlameHistogram> *parts = nullptr);

// The top Lyapunov exponent of the flame's chaos game along one orbit (Benettin's method): the
// mean log of how much one step stretches a small displacement, renormalised every step, the
// xforms chosen as the chaos game chooses them (weights, xaos), a random variation's twin point
// drawn with the same random numbers. Negative: nearby orbits converge (the game contracts on
// average, so its picture is an attractor's); the affine parts' spectra cannot say this, since
// the variations bend the maps. `steps` after flam3's 15 fuse steps; bad values (flam3's
// replaced points) carry no derivative and are counted. Throws InputError (checkFlame).
struct FlameLyapunov {
    double exponent = 0;        // per step, natural log
    std::uint64_t steps = 0;    // steps that gave a derivative
    std::uint64_t badValues = 0;
};
FlameLyapunov flameLyapunov(const Flame &flame, std::uint64_t steps = 20000,
                            std::uint64_t seed = 1);

// The palette as the labels' colours (256 entries).
std::vector<Rgb8> flamePaletteRgb(const Flame &flame);

} // namespace awb::flame
