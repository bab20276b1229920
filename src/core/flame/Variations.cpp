// flam3 3.1.1's variations: the name and parameter tables (flam3's variations.c names, its
// parser.c attributes with the defaults of initialize_xforms) and XformMap's constants (its
// xform_precalc and prepare_precalc_flags). The kernels, XformMap::apply, are in
// VariationKernels.cpp.
#include "core/flame/Variations.h"

#include "core/flame/VariationIds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace awb::flame {

using namespace detail;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInvPi = std::numbers::inv_pi;
constexpr double kEps = 1e-10;  // flam3's EPS

constexpr std::array<std::string_view, kVariationCount> kNames = {
    "linear",       "sinusoidal",  "spherical",   "swirl",        "horseshoe",
    "polar",        "handkerchief", "heart",      "disc",         "spiral",
    "hyperbolic",   "diamond",     "ex",          "julia",        "bent",
    "waves",        "fisheye",     "popcorn",     "exponential",  "power",
    "cosine",       "rings",       "fan",         "blob",         "pdj",
    "fan2",         "rings2",      "eyefish",     "bubble",       "cylinder",
    "perspective",  "noise",       "julian",      "juliascope",   "blur",
    "gaussian_blur", "radial_blur", "pie",        "ngon",         "curl",
    "rectangles",   "arch",        "tangent",     "square",       "rays",
    "blade",        "secant2",     "twintrian",   "cross",        "disc2",
    "super_shape",  "flower",      "conic",       "parabola",     "bent2",
    "bipolar",      "boarders",    "butterfly",   "cell",         "cpow",
    "curve",        "edisc",       "elliptic",    "escher",       "foci",
    "lazysusan",    "loonie",      "pre_blur",    "modulus",      "oscilloscope",
    "polar2",       "popcorn2",    "scry",        "separation",   "split",
    "splits",       "stripes",     "wedge",       "wedge_julia",  "wedge_sph",
    "whorl",        "waves2",      "exp",         "log",          "sin",
    "cos",          "tan",         "sec",         "csc",          "cot",
    "sinh",         "cosh",        "tanh",        "sech",         "csch",
    "coth",         "auger",       "flux",        "mobius",
};
static_assert(kVariationCount == kVarCount);

struct ParameterInfo {
    std::string_view name;
    int variation;
    double defaultValue;
};

// flam3's attributes and initialize_xforms' defaults. amw_amp, which flam3 3.1.1 still parses
// (default 1) but which no variation of it reads (the amw variation is gone), is not here: a
// reader may skip it as flam3 effectively does.
constexpr std::array<ParameterInfo, kParamCount> kParameters = {{
    {"blob_low", kBlob, 0.0},
    {"blob_high", kBlob, 1.0},
    {"blob_waves", kBlob, 1.0},
    {"pdj_a", kPdj, 0.0},
    {"pdj_b", kPdj, 0.0},
    {"pdj_c", kPdj, 0.0},
    {"pdj_d", kPdj, 0.0},
    {"fan2_x", kFan2, 0.0},
    {"fan2_y", kFan2, 0.0},
    {"rings2_val", kRings2, 0.0},
    {"perspective_angle", kPerspective, 0.0},
    {"perspective_dist", kPerspective, 0.0},
    {"julian_power", kJulian, 1.0},
    {"julian_dist", kJulian, 1.0},
    {"juliascope_power", kJuliascope, 1.0},
    {"juliascope_dist", kJuliascope, 1.0},
    {"radial_blur_angle", kRadialBlur, 0.0},
    {"pie_slices", kPie, 6.0},
    {"pie_rotation", kPie, 0.0},
    {"pie_thickness", kPie, 0.5},
    {"ngon_sides", kNgon, 5.0},
    {"ngon_power", kNgon, 3.0},
    {"ngon_circle", kNgon, 1.0},
    {"ngon_corners", kNgon, 2.0},
    {"curl_c1", kCurl, 1.0},
    {"curl_c2", kCurl, 0.0},
    {"rectangles_x", kRectangles, 1.0},
    {"rectangles_y", kRectangles, 1.0},
    {"disc2_rot", kDisc2, 0.0},
    {"disc2_twist", kDisc2, 0.0},
    {"super_shape_rnd", kSuperShape, 0.0},
    {"super_shape_m", kSuperShape, 0.0},
    {"super_shape_n1", kSuperShape, 1.0},
    {"super_shape_n2", kSuperShape, 1.0},
    {"super_shape_n3", kSuperShape, 1.0},
    {"super_shape_holes", kSuperShape, 0.0},
    {"flower_petals", kFlower, 0.0},
    {"flower_holes", kFlower, 0.0},
    {"conic_eccentricity", kConic, 1.0},
    {"conic_holes", kConic, 0.0},
    {"parabola_height", kParabola, 0.0},
    {"parabola_width", kParabola, 0.0},
    {"bent2_x", kBent2, 1.0},
    {"bent2_y", kBent2, 1.0},
    {"bipolar_shift", kBipolar, 0.0},
    {"cell_size", kCell, 1.0},
    {"cpow_r", kCpow, 1.0},
    {"cpow_i", kCpow, 0.0},
    {"cpow_power", kCpow, 1.0},
    {"curve_xamp", kCurve, 0.0},
    {"curve_yamp", kCurve, 0.0},
    {"curve_xlength", kCurve, 1.0},
    {"curve_ylength", kCurve, 1.0},
    {"escher_beta", kEscher, 0.0},
    {"lazysusan_spin", kLazysusan, 0.0},
    {"lazysusan_space", kLazysusan, 0.0},
    {"lazysusan_twist", kLazysusan, 0.0},
    {"lazysusan_x", kLazysusan, 0.0},
    {"lazysusan_y", kLazysusan, 0.0},
    {"modulus_x", kModulus, 0.0},
    {"modulus_y", kModulus, 0.0},
    {"oscilloscope_separation", kOscilloscope, 1.0},
    {"oscilloscope_frequency", kOscilloscope, kPi},
    {"oscilloscope_amplitude", kOscilloscope, 1.0},
    {"oscilloscope_damping", kOscilloscope, 0.0},
    {"popcorn2_x", kPopcorn2, 0.0},
    {"popcorn2_y", kPopcorn2, 0.0},
    {"popcorn2_c", kPopcorn2, 0.0},
    {"separation_x", kSeparation, 0.0},
    {"separation_xinside", kSeparation, 0.0},
    {"separation_y", kSeparation, 0.0},
    {"separation_yinside", kSeparation, 0.0},
    {"split_xsize", kSplit, 0.0},
    {"split_ysize", kSplit, 0.0},
    {"splits_x", kSplits, 0.0},
    {"splits_y", kSplits, 0.0},
    {"stripes_space", kStripes, 0.0},
    {"stripes_warp", kStripes, 0.0},
    {"wedge_angle", kWedge, 0.0},
    {"wedge_hole", kWedge, 0.0},
    {"wedge_count", kWedge, 1.0},
    {"wedge_swirl", kWedge, 0.0},
    {"wedge_julia_angle", kWedgeJulia, 0.0},
    {"wedge_julia_count", kWedgeJulia, 1.0},
    {"wedge_julia_power", kWedgeJulia, 1.0},
    {"wedge_julia_dist", kWedgeJulia, 0.0},
    {"wedge_sph_angle", kWedgeSph, 0.0},
    {"wedge_sph_count", kWedgeSph, 1.0},
    {"wedge_sph_hole", kWedgeSph, 0.0},
    {"wedge_sph_swirl", kWedgeSph, 0.0},
    {"whorl_inside", kWhorl, 0.0},
    {"whorl_outside", kWhorl, 0.0},
    {"waves2_freqx", kWaves2, 0.0},
    {"waves2_scalex", kWaves2, 0.0},
    {"waves2_freqy", kWaves2, 0.0},
    {"waves2_scaley", kWaves2, 0.0},
    {"auger_sym", kAuger, 0.0},
    {"auger_weight", kAuger, 0.5},
    {"auger_freq", kAuger, 1.0},
    {"auger_scale", kAuger, 1.0},
    {"flux_spread", kFlux, 0.0},
    {"mobius_re_a", kMobius, 0.0},
    {"mobius_im_a", kMobius, 0.0},
    {"mobius_re_b", kMobius, 0.0},
    {"mobius_im_b", kMobius, 0.0},
    {"mobius_re_c", kMobius, 0.0},
    {"mobius_im_c", kMobius, 0.0},
    {"mobius_re_d", kMobius, 0.0},
    {"mobius_im_d", kMobius, 0.0},
}};

// Other spellings flam3's parser accepts for the same parameters.
struct ParameterAlias {
    std::string_view name;
    int parameter;
};
constexpr std::array<ParameterAlias, 12> kAliases = {{
    {"oscope_separation", kOscSeparation},
    {"oscope_frequency", kOscFrequency},
    {"oscope_amplitude", kOscAmplitude},
    {"oscope_damping", kOscDamping},
    {"Re_A", kMobiusReA},
    {"Im_A", kMobiusImA},
    {"Re_B", kMobiusReB},
    {"Im_B", kMobiusImB},
    {"Re_C", kMobiusReC},
    {"Im_C", kMobiusImC},
    {"Re_D", kMobiusReD},
    {"Im_D", kMobiusImD},
}};

} // namespace

std::string_view variationName(int id)
{
    return id >= 0 && id < kVariationCount ? kNames[std::size_t(id)] : std::string_view();
}

int variationId(std::string_view name)
{
    for (int v = 0; v < kVariationCount; ++v)
        if (kNames[std::size_t(v)] == name)
            return v;
    return -1;
}

namespace {

// Whether the variation's kernel reads the point's radius (Point::sqrt: flam3's precalc_sqrt;
// the angles' flag implies it). Those that do not, listed; any other reads it.
bool readsRadius(int id)
{
    switch (id) {
    case kLinear: case kSinusoidal: case kSpherical: case kSwirl: case kBent: case kWaves:
    case kPopcorn: case kExponential: case kCosine: case kPdj: case kBubble: case kCylinder:
    case kPerspective: case kNoise: case kJulian: case kJuliascope: case kBlur:
    case kGaussianBlur: case kPie: case kNgon: case kCurl: case kRectangles: case kArch:
    case kTangent: case kSquare: case kRays: case kCross: case kDisc2: case kBent2:
    case kBipolar: case kBoarders: case kButterfly: case kCell: case kCpow: case kCurve:
    case kEdisc: case kElliptic: case kEscher: case kFoci: case kLazysusan: case kLoonie:
    case kModulus: case kOscilloscope: case kPolar2: case kPopcorn2: case kSeparation:
    case kSplit: case kSplits: case kStripes: case kWedgeJulia: case kWaves2: case kExp:
    case kLog: case kSin: case kCos: case kTan: case kSec: case kCsc: case kCot: case kSinh:
    case kCosh: case kTanh: case kSech: case kCsch: case kCoth: case kAuger: case kFlux:
        return false;
    default:
        return true;
    }
}

} // namespace

bool variationIsRandom(int id)
{
    switch (id) {
    case kJulia:        // the branch of the square root
    case kNoise:
    case kJulian:       // the branch of the root
    case kJuliascope:
    case kBlur:
    case kGaussianBlur:
    case kRadialBlur:
    case kPie:
    case kArch:
    case kSquare:
    case kRays:
    case kBlade:
    case kTwintrian:
    case kSuperShape:   // unless super_shape_rnd is 0
    case kFlower:
    case kConic:
    case kParabola:
    case kBoarders:
    case kCpow:         // the branch of the power
    case kPreBlur:
    case kWedgeJulia:
        return true;
    default:
        return false;
    }
}

int parameterCount() { return kParamCount; }

std::string_view parameterName(int p)
{
    return p >= 0 && p < kParamCount ? kParameters[std::size_t(p)].name : std::string_view();
}

int parameterId(std::string_view name)
{
    for (int p = 0; p < kParamCount; ++p)
        if (kParameters[std::size_t(p)].name == name)
            return p;
    for (const ParameterAlias &a : kAliases)
        if (a.name == name)
            return a.parameter;
    return -1;
}

int parameterVariation(int p)
{
    return p >= 0 && p < kParamCount ? kParameters[std::size_t(p)].variation : -1;
}

double parameterDefault(int p)
{
    return p >= 0 && p < kParamCount ? kParameters[std::size_t(p)].defaultValue : 0.0;
}

std::vector<int> variationParameters(int id)
{
    std::vector<int> out;
    for (int p = 0; p < kParamCount; ++p)
        if (kParameters[std::size_t(p)].variation == id)
            out.push_back(p);
    return out;
}

const std::vector<double> &defaultParameters()
{
    static const std::vector<double> defaults = [] {
        std::vector<double> d(static_cast<std::size_t>(kParamCount));
        for (int p = 0; p < kParamCount; ++p)
            d[std::size_t(p)] = kParameters[std::size_t(p)].defaultValue;
        return d;
    }();
    return defaults;
}

// flam3's prepare_precalc_flags and xform_precalc, and the per-xform constants of its kernels,
// each computed in the kernels' own order of operations (so the kernels see the same doubles).
XformMap::XformMap(const FlameXform &xform)
    : m_pre(xform.pre), m_post(xform.post), m_hasPost(!xform.post.isIdentity()),
      m_p(defaultParameters()), m_consts(std::size_t(kConstCount), 0.0)
{
    for (std::size_t p = 0; p < m_p.size() && p < xform.parameters.size(); ++p)
        m_p[p] = xform.parameters[p];
    // flam3's parser clamps super_shape_rnd to [0, 1].
    m_p[kSuperShapeRnd] = std::clamp(m_p[kSuperShapeRnd], 0.0, 1.0);

    // The terms by increasing id, as flam3 runs them (a repeated id adds its weights).
    std::array<double, kVariationCount> weights{};
    for (const VariationTerm &t : xform.variations)
        if (t.id >= 0 && t.id < kVariationCount)
            weights[std::size_t(t.id)] += t.weight;
    for (int v = 0; v < kVariationCount; ++v) {
        const double w = weights[std::size_t(v)];
        if (w == 0)
            continue;
        if (v == kPreBlur) {  // moves the point before the others see it
            m_preBlur = w;
            m_random = true;
            continue;
        }
        m_terms.push_back({v, w});
        if (variationIsRandom(v) && !(v == kSuperShape && m_p[kSuperShapeRnd] == 0))
            m_random = true;
        m_sqrt = m_sqrt || readsRadius(v);
        switch (v) {  // what the kernels read of the point (flam3's precalc flags)
        case kPolar: case kHandkerchief: case kHeart: case kDisc: case kEx: case kJulia:
        case kFan: case kFan2: case kDisc2: case kPolar2:
            m_atanXY = true;
            break;
        case kBlob:
            m_atanXY = true;
            m_angles = true;
            m_sqrt = true;  // the angles' denominator
            break;
        case kSpiral: case kHyperbolic: case kDiamond: case kPower: case kRings: case kRings2:
            m_angles = true;
            m_sqrt = true;
            break;
        case kJulian: case kJuliascope: case kRadialBlur: case kNgon: case kSuperShape:
        case kFlower: case kConic: case kCpow: case kEscher: case kWedge: case kWedgeJulia:
        case kWedgeSph: case kWhorl: case kLog:
            m_atanYX = true;
            break;
        default:
            break;
        }
    }

    const auto P = [this](int p) { return m_p[std::size_t(p)]; };
    const auto set = [this](int c, double value) { m_consts[std::size_t(c)] = value; };

    // perspective: the view tilted by angle * pi / 2, at distance dist
    const double tilt = P(kPerspectiveAngle) * kPi / 2.0;
    set(cPerspSin, std::sin(tilt));
    set(cPerspDistCos, P(kPerspectiveDist) * std::cos(tilt));
    // julian, juliascope: power's branches, |z|^(dist / power)
    set(cJulianAbsN, std::fabs(P(kJulianPower)));
    set(cJulianCn, P(kJulianDist) / P(kJulianPower) / 2.0);
    set(cScopeAbsN, std::fabs(P(kJuliascopePower)));
    set(cScopeCn, P(kJuliascopeDist) / P(kJuliascopePower) / 2.0);
    set(cJulianInvN, 1.0 / P(kJulianPower));
    set(cScopeInvN, 1.0 / P(kJuliascopePower));
    // wedge_julia: the wedges' compression and julian's constants
    set(cWedgeJuliaFactor, 1.0 - P(kWedgeJuliaAngle) * P(kWedgeJuliaCount) * kInvPi * 0.5);
    set(cWedgeJuliaAbsN, std::fabs(P(kWedgeJuliaPower)));
    set(cWedgeJuliaCn, P(kWedgeJuliaDist) / P(kWedgeJuliaPower) / 2.0);
    set(cWedgeJuliaInvN, 1.0 / P(kWedgeJuliaPower));
    // radial_blur: spin and zoom shares of the blur angle
    const double blurAngle = P(kRadialBlurAngle) * kPi / 2.0;
    set(cRadialSpin, std::sin(blurAngle));
    set(cRadialZoom, std::cos(blurAngle));
    // waves: the pre-transform's translation sets the wavelengths
    set(cWavesX, 1.0 / (m_pre.c * m_pre.c + kEps));
    set(cWavesY, 1.0 / (m_pre.f * m_pre.f + kEps));
    // disc2: rot * pi, and the twist's offsets (grown by how far twist exceeds 2 pi)
    const double twist = P(kDisc2Twist);
    set(cDisc2TimesPi, P(kDisc2Rot) * kPi);
    double sinAdd = std::sin(twist), cosAdd = std::cos(twist) - 1;
    if (twist > 2 * kPi) {
        const double k = 1 + twist - 2 * kPi;
        cosAdd *= k;
        sinAdd *= k;
    }
    if (twist < -2 * kPi) {
        const double k = 1 + twist + 2 * kPi;
        cosAdd *= k;
        sinAdd *= k;
    }
    set(cDisc2SinAdd, sinAdd);
    set(cDisc2CosAdd, cosAdd);
    // super_shape: m / 4 and -1 / n1
    set(cSuperQuarterM, P(kSuperShapeM) / 4.0);
    set(cSuperNegInvN1, -1.0 / P(kSuperShapeN1));
    set(cSuperRnd, P(kSuperShapeRnd));
    // rings, fan: widths from the pre-transform's translation
    set(cRingsDx, m_pre.c * m_pre.c + kEps);
    set(cFanDx, kPi * (m_pre.c * m_pre.c + kEps));
    set(cFanHalfDx, 0.5 * m_consts[cFanDx]);
    set(cFan2Dx, kPi * (P(kFan2X) * P(kFan2X) + kEps));
    set(cFan2HalfDx, 0.5 * m_consts[cFan2Dx]);
    set(cRings2Dx, P(kRings2Val) * P(kRings2Val) + kEps);
    set(cBlobSpan, P(kBlobHigh) - P(kBlobLow));
    set(cNgonSector, 2 * kPi / P(kNgonSides));
    set(cNgonHalfSector, m_consts[cNgonSector] / 2);
    set(cCpowAngleStep, 2.0 * kPi / P(kCpowPower));
    set(cCpowRe, P(kCpowR) / P(kCpowPower));
    set(cCpowIm, P(kCpowI) / P(kCpowPower));
    set(cCurveXlen2, std::max(P(kCurveXlength) * P(kCurveXlength), 1e-20));
    set(cCurveYlen2, std::max(P(kCurveYlength) * P(kCurveYlength), 1e-20));
    set(cEscherC, 0.5 * (1.0 + std::cos(P(kEscherBeta))));
    set(cEscherD, 0.5 * std::sin(P(kEscherBeta)));
    set(cOscTwoPiF, 2 * kPi * P(kOscFrequency));
    set(cWedgeFactor, 1 - P(kWedgeAngle) * P(kWedgeCount) * kInvPi * 0.5);
    set(cWedgeSphFactor, 1 - P(kWedgeSphAngle) * P(kWedgeSphCount) * kInvPi * 0.5);
    set(cCellInvSize, 1.0 / P(kCellSize));
    set(cSeparationX2, P(kSeparationX) * P(kSeparationX));
    set(cSeparationY2, P(kSeparationY) * P(kSeparationY));
    set(cModulusX2, 2 * P(kModulusX));
    set(cModulusY2, 2 * P(kModulusY));
}

} // namespace awb::flame
