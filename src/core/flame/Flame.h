#pragma once
// Fractal flames (S. Draves, E. Reckase, "The Fractal Flame Algorithm", 2003/2008) as flam3
// 3.1.1 draws them: a flame is an IFS of non-linear maps, the xforms, each
//     q = post( sum_v w_v V_v( pre(p) ) )
// with pre and post affine maps of the plane and the variations V_v of flam3's variations.c
// (flame/Variations.h), chosen with probabilities proportional to their weights -- or, with
// xaos, to the weights times the row of the previous xform -- and followed on every point by the
// final xform when there is one. Each point carries a colour coordinate c in [0, 1] that xform
// i moves to s_i c_i + (1 - s_i) c (colour_speed s_i), and an opacity (the xform's), which the
// renderer uses as the hit's weight.
//
// This is the data; flame/FlameChaos.h draws it, model/FlameExchange reads and writes flam3's
// XML. Coordinates are flam3's: y grows down the picture.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace awb::flame {

// x' = a x + b y + c, y' = d x + e y + f. flam3 writes it coefs="a d b e c f" (its c[3][2],
// row k the coefficients of x, y, 1).
struct Affine2 {
    double a = 1, b = 0, c = 0, d = 0, e = 1, f = 0;

    bool isIdentity() const { return a == 1 && b == 0 && c == 0 && d == 0 && e == 1 && f == 0; }
    double determinant() const { return a * e - b * d; }
    void apply(double x, double y, double *ox, double *oy) const
    {
        *ox = a * x + b * y + c;
        *oy = d * x + e * y + f;
    }
    bool operator==(const Affine2 &) const = default;
};

// One variation of an xform with its weight; id indexes flame/Variations.h's table.
struct VariationTerm {
    int id = 0;
    double weight = 0;
    bool operator==(const VariationTerm &) const = default;
};

struct FlameXform {
    Affine2 pre, post;
    std::vector<VariationTerm> variations;  // increasing id, non-zero weights
    // Every variation parameter of flame/Variations.h by its id (defaults when not given).
    std::vector<double> parameters;
    double weight = 0;       // flam3's density; 0 (flam3's default) never chosen
    double colour = 0;       // the colour coordinate it moves the points' towards, 0..1
    double colourSpeed = 0.5;
    double opacity = 1;      // 0: the points it gives are not drawn (still iterated)
    double animate = 1;      // flam3's rotation in animations (0 for symmetry xforms)
    // xaos: the factors of the next xform's weight after this one (missing entries 1).
    std::vector<double> xaos;
    std::string name;

    FlameXform();  // identity pre and post, linear 1, default parameters
    double xaosTo(std::size_t j) const { return j < xaos.size() ? xaos[j] : 1.0; }
    bool operator==(const FlameXform &) const = default;
};

struct FlameColour {
    double r = 0, g = 0, b = 0;  // 0..1
    bool operator==(const FlameColour &) const = default;
};

// How a colour coordinate picks its colour: flam3's palette_mode. Step: the entry int(256 c)
// (flam3's default); linear: between the two entries around 256 c.
enum class PaletteMode { Step, Linear };

// The spatial filter's shape: flam3's filter_shape, numbered as flam3's parser numbers the
// names (flam3.h). flam3's filters.c numbers its functions otherwise from 6 on, so the name
// "lanczos3" draws with Mitchell's filter there, and so here (flame/FlameTone.cpp).
enum class FilterShape {
    Gaussian, Hermite, Box, Triangle, Bell, BSpline, Lanczos3, Lanczos2, Mitchell, Blackman,
    Catrom, Hamming, Hanning, Quadratic
};
inline constexpr int kFilterShapeCount = 14;

struct Flame {
    std::string name;
    std::vector<FlameXform> xforms;
    std::optional<FlameXform> finalXform;
    std::array<FlameColour, 256> palette{};
    // Camera (flam3's): the picture is width x height pixels, `scale` pixels per unit (times
    // 2^zoom), centred on `centre`, rotated by `rotate` degrees about it.
    double centre[2] = {0, 0};
    double scale = 50;
    double rotate = 0;
    double zoom = 0;
    int width = 100, height = 100;
    // Tone: flam3's log-density display and its sampling.
    double quality = 1;      // samples per output pixel (flam3's default)
    // flam3's passes: the samples drawn in that many histograms, each log-scaled (and density
    // estimated) apart and summed; a little smoother than one pass.
    int passes = 1;
    double brightness = 4;
    double gamma = 4;
    double gammaThreshold = 0.01;
    double vibrancy = 1;
    double highlightPower = -1;
    FlameColour background;
    int supersample = 1;
    double filter = 0.5;     // spatial filter radius (pixels)
    FilterShape filterShape = FilterShape::Gaussian;
    PaletteMode paletteMode = PaletteMode::Step;
    double estimatorRadius = 9, estimatorMinimum = 0, estimatorCurve = 0.4;
    bool operator==(const Flame &) const = default;
};

} // namespace awb::flame
