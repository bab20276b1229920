#pragma once
// flam3 3.1.1's picture of a flame (rect.c, filters.c, palettes.c): the histogram of palette
// colours (flame/FlameChaos.h) on a frame widened by the filters' gutter, each cell scaled by
// k1 log(1 + k2 a) / a -- spread by the density estimator, a Gaussian whose radius shrinks as
// the cell's hits grow -- then the spatial filter down to the output pixels, and per pixel the
// gamma of the log density with its linear range, vibrancy, highlight power and background.
// The filters are flam3's to the coefficient (tests/core/test_flame_tone.cpp compares them
// with libflam3's own); the whole picture is judged against flam3-render's
// (tests/cli/test_flame_tone.cpp). This is what flam3-render draws with its defaults (bits 33:
// the estimator on; earlyclip 0: filtered, then tone-mapped; one batch, one temporal sample).
//
// What differs, by design: the random numbers (ours are ifs/Random.h's streams), so two
// pictures agree as two renders of flam3 with different seeds agree; the estimator's rows are
// those of the histogram (flam3 reads one row past it).

#include "core/flame/FlameChaos.h"

#include <string_view>

namespace awb::flame {

std::string_view filterShapeName(FilterShape shape);
// flam3's filter_shape names; -1 for none.
int filterShapeId(std::string_view name);

// flam3's spatial filter: a width x width kernel of the shape's function, its support scaled
// to 2 x radius x supersample cells, normalised (flam3_create_spatial_filter). Throws
// InputError when the kernel would be wider than kMaxFilterWidth cells or sums to 0.
inline constexpr int kMaxFilterWidth = 1025;
struct SpatialFilter {
    int width = 1;
    std::vector<double> coefs;  // coefs[i + j * width]
    // The kernel is row x row (flam3's is the shape's product with itself, normalised): the
    // picture filters the rows, then the columns, with it.
    std::vector<double> row;
};
SpatialFilter spatialFilter(FilterShape shape, double radius, int supersample);

// flam3's density estimator (flam3_create_de_filters): for each hit count (up to
// maxFilteredCounts, beyond which the last kernel), a Gaussian of width filterWidths[k]; the
// coefficients of one eighth of each square kernel, kernelSize per kernel. Throws InputError
// for a curve <= 0, a maximum below the minimum, or more than kMaxEstimatorCoefs coefficients.
inline constexpr double kMaxEstimatorCoefs = 2e7;
struct DensityEstimator {
    int maxFilteredCounts = 0;
    int maxFilterIndex = 0;
    int kernelSize = 0;
    std::vector<double> filterWidths;
    std::vector<double> coefs;
};
DensityEstimator densityEstimator(double maxRadius, double minRadius, double curve,
                                  int supersample);

// palettes.c: the alpha of a log density (gamma with a linear range near 0), and a pixel's
// colour from its filtered sums with the highlight power.
double flam3Alpha(double density, double gamma, double linearRange);
void flam3NewRgb(const double sums[4], double ls, double highlightPower, double rgb[3]);

struct FlameImageJob {
    const Flame *flame = nullptr;
    // The output picture: width x height pixels showing [x0, x1] x [y0, y1] (y up, as
    // flameFrame gives the flame's camera); its supersample is ignored (the flame's).
    RasterFrame frame;
    std::uint64_t samples = 100000;  // the chaos game's samples (the flame's: flameSamples)
    std::uint64_t seed = 1;
    int threads = 1;
};

struct FlameImage {
    int width = 0, height = 0;
    std::vector<std::uint32_t> argb;  // 0xAARRGGBB, opaque: the flame on its background
    FlameStats stats;
};

// The most passes of a picture (flam3's own limit is the sample count).
inline constexpr int kMaxFlamePasses = 64;

// The most bytes the histograms of one picture may take (the threads' and the accumulator):
// a picture that needs more draws on fewer threads, then is refused (InputError).
inline constexpr double kMaxFlameHistogramBytes = 1.0 * (1 << 30);
// Below this, a thread keeps the buffers of its last picture for the next one.
inline constexpr double kKeptFlameBytes = 256.0 * (1 << 20);

// flam3's picture of job.flame (above). Throws InputError (checkFlame, the filters, the frame,
// the memory); returns with stats.cancelled (and no pixels) when control.cancel is set.
FlameImage renderFlameImage(const FlameImageJob &job, const IterationControl &control = {});

// flam3's rgb2hsv and hsv2rgb (palettes.c: channels 0..1, hue 0..6), for the highlight power and
// a palette's hue rotation (flam3_get_palette).
void rgbToHsv(const double rgb[3], double hsv[3]);
void hsvToRgb(const double hsv[3], double rgb[3]);

} // namespace awb::flame
