#pragma once
// A chaos game of an item's own, played in random mode instead of the engine's (layer 1, core):
// a fractal flame's (flame/FlameChaos.h, model/FlameItem), whose maps are not affine. The one
// raster path (render/AttractorImage.h) hands it the picture's frame and histogram; it fills
// the histogram with hits whose labels index `colours`.

#include "core/Lazy.h"
#include "core/ifs/Attractor.h"
#include "core/render/Density.h"

#include <array>
#include <functional>
#include <optional>
#include <vector>

namespace awb {

struct ChaosJob {
    RasterFrame frame;  // the world rectangle (y up) and its cells
    Accumulation accumulation = Accumulation::Density;
    std::uint64_t samples = 100000;
    std::uint64_t seed = 1;
    int threads = 1;
};

struct CustomChaos {
    // Fills `out` (cleared and sized to job.frame's cells); throws InputError for input it
    // cannot draw; returns with `cancelled` when control.cancel is set.
    std::function<IterationStats(const ChaosJob &, DensityImage &, const IterationControl &)> run;
    std::vector<Rgb8> colours;  // the labels' colours
    // Set when the item also tone-maps its own game (a flame: flam3's estimator, spatial
    // filter and tone, flame/FlameTone.h): the picture of job.frame, width x height pixels
    // 0xAARRGGBB (cleared and sized here). The density tone draws with it.
    std::function<IterationStats(const ChaosJob &, std::vector<std::uint32_t> &,
                                 const IterationControl &)>
        picture;
    // The rectangle (x0, y0, x1, y1; y up) the item frames when asked to fit its content (a
    // flame's camera): its points may lie anywhere, so none are measured.
    std::optional<std::array<double, 4>> frame;
    // The item's own picture (a flame's camera): its size in pixels and the samples it draws
    // per pixel (flam3's quality), for a picture drawn as the item's own tool draws it.
    int width = 0, height = 0;
    double samplesPerPixel = 0;
    // The top Lyapunov exponent of the game along its own orbit (per step; negative: it
    // contracts on average), when the item measures it: what its maps' spectra cannot tell.
    // Measured when first asked for (milliseconds, which a picture does not wait for); empty
    // when the item does not measure it, nullopt inside when the measure gave no number.
    Lazy<std::optional<double>> lyapunov;
    // Its value, measured now if not yet; nullopt when the item does not measure it.
    std::optional<double> lyapunovExponent() const
    {
        return lyapunov ? *lyapunov : std::nullopt;
    }

    explicit operator bool() const { return bool(run); }
};

} // namespace awb
