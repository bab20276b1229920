// XformMap::apply: flam3 3.1.1's apply_xform (flam3.c) without the colour coordinate, and the
// variations' formulas (variations.c), written anew from them. Each kernel keeps flam3's order
// of floating-point operations -- its products associate left to right, its constants are
// the same doubles (XformMap's constructor computes them as flam3's xform_precalc does) --
// so that a point's image is the one flam3's sources compute, bit for bit (checked against
// variations.c built without -ffast-math); libflam3 itself is built with -O3 -ffast-math,
// which moves its results by up to ~1e-12 relative. tests/test_flame_variations.cpp checks
// the kernels against libflam3's apply_xform.
//
// flam3's quirks are kept on purpose: waves, rings, fan and popcorn read the pre-affine's
// coefficients; radial_blur adds its radius unweighted; arch, rays, blade, twintrian, secant2,
// loonie, scry, whorl and flux use the weight inside the formula; cell, fan2 and rings2
// truncate to an int as C does on x86-64 (out of range: INT_MIN). Where flam3 draws a uniform
// number (ISAAC, [0, 1]) the kernels draw uniform01 (xoshiro, [0, 1)); its random bit is the
// top bit of one 64-bit draw.
#include "core/flame/Variations.h"

#include "core/flame/VariationIds.h"
#include "core/flame/VariationTerm.h"

#include <climits>
#include <limits>
#include <cmath>
#include <numbers>

namespace awb::flame {

using namespace detail;

namespace {

constexpr double kPi = std::numbers::pi;        // M_PI
constexpr double kHalfPi = kPi / 2;             // M_PI_2 (halving is exact)
constexpr double kQuarterPi = kPi / 4;          // M_PI_4
constexpr double kInvPi = std::numbers::inv_pi; // M_1_PI
constexpr double kTwoInvPi = 2 * kInvPi;        // M_2_PI (doubling is exact)
constexpr double kEps = 1e-10;                  // flam3's EPS

// flam3's badvalue(): NaN or beyond +-1e10.
inline bool badValue(double x) { return x != x || x > 1e10 || x < -1e10; }

// C's double -> int conversion as x86-64 does it (cvttsd2si): truncation, and INT_MIN for NaN
// or out of range, where C leaves it undefined. flam3's fan2, rings2, cell, julian, pie and
// wedge_julia convert so.
inline int truncToInt(double v)
{
    if (!(v > -2147483649.0 && v < 2147483648.0))
        return INT_MIN;
    return int(v);
}

} // namespace

// One term: px, py += weight * V(tx, ty), as flam3's varN_... functions. P: the parameters
// by Param id, K: the constants by Const id.
void detail::addTerm(int id, double w, Point &s, const double *P, const double *K,
                     const Affine2 &pre, Xoshiro256 &rng)
{
    const double tx = s.tx, ty = s.ty;
    double &px = s.px, &py = s.py;
    switch (id) {
    // ---- the classic variations (Draves & Reckase's appendix) ----
    case kLinear:
        return s.add(w * tx, w * ty);
    case kSinusoidal:
        return s.add(w * std::sin(tx), w * std::sin(ty));
    case kSpherical: {
        const double r2 = w / (s.sumsq + kEps);
        return s.add(r2 * tx, r2 * ty);
    }
    case kSwirl: {
        const double c1 = std::sin(s.sumsq), c2 = std::cos(s.sumsq);
        const double nx = c1 * tx - c2 * ty;
        const double ny = c2 * tx + c1 * ty;
        return s.add(w * nx, w * ny);
    }
    case kHorseshoe: {
        const double r = w / (s.sqrt + kEps);
        return s.add((tx - ty) * (tx + ty) * r, 2.0 * tx * ty * r);
    }
    case kPolar: {
        const double nx = s.atanXY * kInvPi;
        const double ny = s.sqrt - 1.0;
        return s.add(w * nx, w * ny);
    }
    case kHandkerchief: {
        const double a = s.atanXY, r = s.sqrt;
        return s.add(w * r * std::sin(a + r), w * r * std::cos(a - r));
    }
    case kHeart: {
        const double a = s.sqrt * s.atanXY;
        const double r = w * s.sqrt;
        return s.add(r * std::sin(a), (-r) * std::cos(a));
    }
    case kDisc: {
        const double a = s.atanXY * kInvPi;
        const double r = kPi * s.sqrt;
        return s.add(w * std::sin(r) * a, w * std::cos(r) * a);
    }
    case kSpiral: {
        const double r = s.sqrt + kEps;
        const double r1 = w / r;
        return s.add(r1 * (s.cosa + std::sin(r)), r1 * (s.sina - std::cos(r)));
    }
    case kHyperbolic: {
        const double r = s.sqrt + kEps;
        return s.add(w * s.sina / r, w * s.cosa * r);
    }
    case kDiamond: {
        const double r = s.sqrt;
        return s.add(w * s.sina * std::cos(r), w * s.cosa * std::sin(r));
    }
    case kEx: {
        const double a = s.atanXY, r = s.sqrt;
        const double n0 = std::sin(a + r), n1 = std::cos(a - r);
        const double m0 = n0 * n0 * n0 * r, m1 = n1 * n1 * n1 * r;
        return s.add(w * (m0 + m1), w * (m0 - m1));
    }
    case kJulia: {  // one of the two square roots, by a random bit
        double a = 0.5 * s.atanXY;
        if (rng.next() >> 63)
            a += kPi;
        const double r = w * std::sqrt(s.sqrt);
        return s.add(r * std::cos(a), r * std::sin(a));
    }
    case kBent: {
        double nx = tx, ny = ty;
        if (nx < 0.0)
            nx = nx * 2.0;
        if (ny < 0.0)
            ny = ny / 2.0;
        return s.add(w * nx, w * ny);
    }
    case kWaves: {  // amplitudes: the pre-affine's b, e (flam3's c[1][0], c[1][1])
        const double nx = tx + pre.b * std::sin(ty * K[cWavesX]);
        const double ny = ty + pre.e * std::sin(tx * K[cWavesY]);
        return s.add(w * nx, w * ny);
    }
    case kFisheye: {  // x and y swapped, as flam3 has it
        const double r = 2 * w / (s.sqrt + 1);
        return s.add(r * ty, r * tx);
    }
    case kPopcorn: {  // amplitudes: the pre-affine's translation c, f
        const double dx = std::tan(3 * ty), dy = std::tan(3 * tx);
        const double nx = tx + pre.c * std::sin(dx);
        const double ny = ty + pre.f * std::sin(dy);
        return s.add(w * nx, w * ny);
    }
    case kExponential: {
        const double dx = w * std::exp(tx - 1.0);
        const double dy = kPi * ty;
        return s.add(dx * std::cos(dy), dx * std::sin(dy));
    }
    case kPower: {
        const double r = w * std::pow(s.sqrt, s.sina);
        return s.add(r * s.cosa, r * s.sina);
    }
    case kCosine: {
        const double a = tx * kPi;
        const double nx = std::cos(a) * std::cosh(ty);
        const double ny = -std::sin(a) * std::sinh(ty);
        return s.add(w * nx, w * ny);
    }
    case kRings: {  // width: the pre-affine's c
        const double dx = K[cRingsDx];
        const double r0 = s.sqrt;
        const double r = w * (std::fmod(r0 + dx, 2 * dx) - dx + r0 * (1 - dx));
        return s.add(r * s.cosa, r * s.sina);
    }
    case kFan: {  // width: the pre-affine's c, offset its f
        const double dx = K[cFanDx], dy = pre.f, dx2 = K[cFanHalfDx];
        double a = s.atanXY;
        const double r = w * s.sqrt;
        a += (std::fmod(a + dy, dx) > dx2) ? -dx2 : dx2;
        return s.add(r * std::cos(a), r * std::sin(a));
    }
    case kBlob: {
        const double a = s.atanXY;
        const double r =
            s.sqrt * (P[kBlobLow] + K[cBlobSpan] * (0.5 + 0.5 * std::sin(P[kBlobWaves] * a)));
        return s.add(w * s.sina * r, w * s.cosa * r);
    }
    case kPdj: {
        const double nx1 = std::cos(P[kPdjB] * tx);
        const double nx2 = std::sin(P[kPdjC] * tx);
        const double ny1 = std::sin(P[kPdjA] * ty);
        const double ny2 = std::cos(P[kPdjD] * ty);
        return s.add(w * (ny1 - nx1), w * (nx2 - ny2));
    }
    case kFan2: {
        const double dy = P[kFan2Y], dx = K[cFan2Dx], dx2 = K[cFan2HalfDx];
        double a = s.atanXY;
        const double r = w * s.sqrt;
        const double t = a + dy - dx * truncToInt((a + dy) / dx);
        if (t > dx2)
            a = a - dx2;
        else
            a = a + dx2;
        return s.add(r * std::sin(a), r * std::cos(a));
    }
    case kRings2: {
        double r = s.sqrt;
        const double dx = K[cRings2Dx];
        r += -2.0 * dx * truncToInt((r + dx) / (2.0 * dx)) + r * (1.0 - dx);
        return s.add(w * s.sina * r, w * s.cosa * r);
    }
    case kEyefish: {
        const double r = (w * 2.0) / (s.sqrt + 1.0);
        return s.add(r * tx, r * ty);
    }
    case kBubble: {
        const double r = w / (0.25 * s.sumsq + 1);
        return s.add(r * tx, r * ty);
    }
    case kCylinder:
        return s.add(w * std::sin(tx), w * ty);
    case kPerspective: {
        const double t = 1.0 / (P[kPerspectiveDist] - ty * K[cPerspSin]);
        return s.add(w * P[kPerspectiveDist] * tx * t, w * K[cPerspDistCos] * ty * t);
    }
    // ---- the random blurs and roots ----
    case kNoise: {
        const double a = uniform01(rng) * 2 * kPi;
        const double r = w * uniform01(rng);
        return s.add(tx * r * std::cos(a), ty * r * std::sin(a));
    }
    case kJulian: {  // one of |power| roots, at random
        const int branch = truncToInt(std::trunc(K[cJulianAbsN] * uniform01(rng)));
        const double a = (s.atanYX + 2 * kPi * branch) / P[kJulianPower];
        const double r = w * std::pow(s.sumsq, K[cJulianCn]);
        return s.add(r * std::cos(a), r * std::sin(a));
    }
    case kJuliascope: {  // julian, the odd branches mirrored
        const int branch = truncToInt(std::trunc(K[cScopeAbsN] * uniform01(rng)));
        double a;
        if ((branch & 1) == 0)
            a = (2 * kPi * branch + s.atanYX) / P[kJuliascopePower];
        else
            a = (2 * kPi * branch - s.atanYX) / P[kJuliascopePower];
        const double r = w * std::pow(s.sumsq, K[cScopeCn]);
        return s.add(r * std::cos(a), r * std::sin(a));
    }
    case kBlur: {
        const double a = uniform01(rng) * 2 * kPi;
        const double r = w * uniform01(rng);
        return s.add(r * std::cos(a), r * std::sin(a));
    }
    case kGaussianBlur: {
        const double a = uniform01(rng) * 2 * kPi;
        double sum = uniform01(rng);
        sum += uniform01(rng);
        sum += uniform01(rng);
        sum += uniform01(rng);
        const double r = w * (sum - 2.0);
        return s.add(r * std::cos(a), r * std::sin(a));
    }
    case kRadialBlur: {  // the radius is added unweighted, as in flam3
        double sum = uniform01(rng);
        sum += uniform01(rng);
        sum += uniform01(rng);
        sum += uniform01(rng);
        const double rndG = w * (sum - 2.0);
        const double ra = s.sqrt;
        const double a = s.atanYX + K[cRadialSpin] * rndG;
        const double rz = K[cRadialZoom] * rndG - 1;
        return s.add(ra * std::cos(a) + rz * tx, ra * std::sin(a) + rz * ty);
    }
    case kPie: {
        const int slice = truncToInt(uniform01(rng) * P[kPieSlices] + 0.5);
        const double a = P[kPieRotation] +
            2.0 * kPi * (slice + uniform01(rng) * P[kPieThickness]) / P[kPieSlices];
        const double r = w * uniform01(rng);
        return s.add(r * std::cos(a), r * std::sin(a));
    }
    // ---- Joel Faber's, Zy0rg's (Apophysis "Z+") and cyberxaos' ----
    case kNgon: {
        const double rFactor = std::pow(s.sumsq, P[kNgonPower] / 2.0);
        const double theta = s.atanYX;
        const double b = K[cNgonSector];
        double phi = theta - (b * std::floor(theta / b));
        if (phi > K[cNgonHalfSector])
            phi -= b;
        double amp = P[kNgonCorners] * (1.0 / (std::cos(phi) + kEps) - 1.0) + P[kNgonCircle];
        amp /= (rFactor + kEps);
        return s.add(w * tx * amp, w * ty * amp);
    }
    case kCurl: {
        const double c1 = P[kCurlC1], c2 = P[kCurlC2];
        const double re = 1.0 + c1 * tx + c2 * (tx * tx - ty * ty);
        const double im = c1 * ty + 2.0 * c2 * tx * ty;
        const double r = w / (re * re + im * im);
        return s.add((tx * re + ty * im) * r, (ty * re - tx * im) * r);
    }
    case kRectangles: {
        const double rx = P[kRectanglesX], ry = P[kRectanglesY];
        if (rx == 0)
            px += w * tx;
        else
            px += w * ((2 * std::floor(tx / rx) + 1) * rx - tx);
        if (ry == 0)
            py += w * ty;
        else
            py += w * ((2 * std::floor(ty / ry) + 1) * ry - ty);
        break;
    }
    case kArch: {
        const double a = uniform01(rng) * w * kPi;
        const double sinr = std::sin(a), cosr = std::cos(a);
        return s.add(w * sinr, w * (sinr * sinr) / cosr);
    }
    case kTangent:
        return s.add(w * std::sin(tx) / std::cos(ty), w * std::tan(ty));
    case kSquare: {
        const double u = uniform01(rng);
        return s.add(w * (u - 0.5), w * (uniform01(rng) - 0.5));
    }
    case kRays: {
        const double a = w * uniform01(rng) * kPi;
        const double r = w / (s.sumsq + kEps);
        const double tanr = w * std::tan(a) * r;
        return s.add(tanr * std::cos(tx), tanr * std::sin(ty));
    }
    case kBlade: {
        const double r = uniform01(rng) * w * s.sqrt;
        const double sinr = std::sin(r), cosr = std::cos(r);
        return s.add(w * tx * (cosr + sinr), w * tx * (cosr - sinr));
    }
    case kSecant2: {
        const double r = w * s.sqrt;
        const double cr = std::cos(r);
        const double icr = 1.0 / cr;
        px += w * tx;
        if (cr < 0)
            py += w * (icr + 1);
        else
            py += w * (icr - 1);
        break;
    }
    case kTwintrian: {
        const double r = uniform01(rng) * w * s.sqrt;
        const double sinr = std::sin(r), cosr = std::cos(r);
        double diff = std::log10(sinr * sinr) + cosr;
        if (badValue(diff))
            diff = -30.0;
        return s.add(w * tx * diff, w * tx * (diff - sinr * kPi));
    }
    case kCross: {
        const double q = tx * tx - ty * ty;
        const double r = w * std::sqrt(1.0 / (q * q + kEps));
        return s.add(tx * r, ty * r);
    }
    case kDisc2: {
        const double t = K[cDisc2TimesPi] * (tx + ty);
        const double r = w * s.atanXY / kPi;
        return s.add((std::sin(t) + K[cDisc2CosAdd]) * r, (std::cos(t) + K[cDisc2SinAdd]) * r);
    }
    case kSuperShape: {
        const double theta = K[cSuperQuarterM] * s.atanYX + kQuarterPi;
        const double st = std::sin(theta), ct = std::cos(theta);
        const double t1 = std::pow(std::fabs(ct), P[kSuperShapeN2]);
        const double t2 = std::pow(std::fabs(st), P[kSuperShapeN3]);
        const double rnd = K[cSuperRnd];
        // rnd 0: flam3's 0 * (its uniform number) adds exactly 0; nothing is drawn.
        const double jitter = rnd == 0 ? 0.0 : rnd * uniform01(rng);
        const double r = w * ((jitter + (1.0 - rnd) * s.sqrt) - P[kSuperShapeHoles]) *
            std::pow(t1 + t2, K[cSuperNegInvN1]) / s.sqrt;
        return s.add(r * tx, r * ty);
    }
    case kFlower: {
        const double r = w * (uniform01(rng) - P[kFlowerHoles]) *
            std::cos(P[kFlowerPetals] * s.atanYX) / s.sqrt;
        return s.add(r * tx, r * ty);
    }
    case kConic: {
        const double ct = tx / s.sqrt;
        const double e = P[kConicEccentricity];
        const double r = w * (uniform01(rng) - P[kConicHoles]) * e / (1 + e * ct) / s.sqrt;
        return s.add(r * tx, r * ty);
    }
    case kParabola: {
        const double sr = std::sin(s.sqrt), cr = std::cos(s.sqrt);
        const double ux = uniform01(rng), uy = uniform01(rng);  // flam3's order of draws
        return s.add(P[kParabolaHeight] * w * sr * sr * ux, P[kParabolaWidth] * w * cr * uy);
    }
    // ---- the Apophysis plugin pack's ----
    case kBent2: {
        double nx = tx, ny = ty;
        if (nx < 0.0)
            nx = nx * P[kBent2X];
        if (ny < 0.0)
            ny = ny * P[kBent2Y];
        return s.add(w * nx, w * ny);
    }
    case kBipolar: {
        const double x2y2 = s.sumsq;
        const double t = x2y2 + 1;
        const double x2 = 2 * tx;
        const double ps = -kHalfPi * P[kBipolarShift];
        double y = 0.5 * std::atan2(2.0 * ty, x2y2 - 1.0) + ps;
        if (y > kHalfPi)
            y = -kHalfPi + std::fmod(y + kHalfPi, kPi);
        else if (y < -kHalfPi)
            y = kHalfPi - std::fmod(kHalfPi - y, kPi);
        return s.add(w * 0.25 * kTwoInvPi * std::log((t + x2) / (t - x2)), w * kTwoInvPi * y);
    }
    case kBoarders: {
        const double roundX = std::rint(tx), roundY = std::rint(ty);
        const double offX = tx - roundX, offY = ty - roundY;
        if (uniform01(rng) >= 0.75) {
            px += w * (offX * 0.5 + roundX);
            py += w * (offY * 0.5 + roundY);
        } else if (std::fabs(offX) >= std::fabs(offY)) {
            if (offX >= 0.0) {
                px += w * (offX * 0.5 + roundX + 0.25);
                py += w * (offY * 0.5 + roundY + 0.25 * offY / offX);
            } else {
                px += w * (offX * 0.5 + roundX - 0.25);
                py += w * (offY * 0.5 + roundY - 0.25 * offY / offX);
            }
        } else if (offY >= 0.0) {
            py += w * (offY * 0.5 + roundY + 0.25);
            px += w * (offX * 0.5 + roundX + offX / offY * 0.25);
        } else {
            py += w * (offY * 0.5 + roundY - 0.25);
            px += w * (offX * 0.5 + roundX - offX / offY * 0.25);
        }
        break;
    }
    case kButterfly: {
        const double wx = w * 1.3029400317411197908970256609023;  // 4 / sqrt(3 pi)
        const double y2 = ty * 2.0;
        const double r = wx * std::sqrt(std::fabs(ty * tx) / (kEps + tx * tx + y2 * y2));
        return s.add(r * tx, r * y2);
    }
    case kCell: {
        const double size = P[kCellSize], inv = K[cCellInvSize];
        int x = truncToInt(std::floor(tx * inv));
        int y = truncToInt(std::floor(ty * inv));
        const double dx = tx - x * size;
        const double dy = ty - y * size;
        // interleave the cells: non-negative to even, negative to odd
        y = y >= 0 ? y * 2 : -(2 * y + 1);
        x = x >= 0 ? x * 2 : -(2 * x + 1);
        px += w * (dx + x * size);
        py -= w * (dy + y * size);
        break;
    }
    case kCpow: {
        const double a = s.atanYX;
        const double lnr = 0.5 * std::log(s.sumsq);
        const double va = K[cCpowAngleStep], vc = K[cCpowRe], vd = K[cCpowIm];
        const double ang = vc * a + vd * lnr + va * std::floor(P[kCpowPower] * uniform01(rng));
        const double m = w * std::exp(vc * lnr - vd * a);
        return s.add(m * std::cos(ang), m * std::sin(ang));
    }
    case kCurve:
        return s.add(w * (tx + P[kCurveXamp] * std::exp(-ty * ty / K[cCurveXlen2])),
                     w * (ty + P[kCurveYamp] * std::exp(-tx * tx / K[cCurveYlen2])));
    case kEdisc: {
        const double tmp = s.sumsq + 1.0;
        const double tmp2 = 2.0 * tx;
        const double r1 = std::sqrt(tmp + tmp2), r2 = std::sqrt(tmp - tmp2);
        const double xmax = (r1 + r2) * 0.5;
        const double a1 = std::log(xmax + std::sqrt(xmax - 1.0));
        const double a2 = -std::acos(tx / xmax);
        const double ww = w / 11.57034632;
        double snv = std::sin(a1);
        const double csv = std::cos(a1);
        const double snhu = std::sinh(a2), cshu = std::cosh(a2);
        if (ty > 0.0)
            snv = -snv;
        return s.add(ww * cshu * csv, ww * snhu * snv);
    }
    case kElliptic: {
        const double tmp = s.sumsq + 1.0;
        const double x2 = 2.0 * tx;
        const double xmax = 0.5 * (std::sqrt(tmp + x2) + std::sqrt(tmp - x2));
        const double a = tx / xmax;
        double b = 1.0 - a * a;
        double ssx = xmax - 1.0;
        const double ww = w / kHalfPi;
        b = b < 0 ? 0 : std::sqrt(b);
        ssx = ssx < 0 ? 0 : std::sqrt(ssx);
        px += ww * std::atan2(a, b);
        if (ty > 0)
            py += ww * std::log(xmax + ssx);
        else
            py -= ww * std::log(xmax + ssx);
        break;
    }
    case kEscher: {
        const double a = s.atanYX;
        const double lnr = 0.5 * std::log(s.sumsq);
        const double vc = K[cEscherC], vd = K[cEscherD];
        const double m = w * std::exp(vc * lnr - vd * a);
        const double n = vc * a + vd * lnr;
        return s.add(m * std::cos(n), m * std::sin(n));
    }
    case kFoci: {
        const double expx = std::exp(tx) * 0.5;
        const double expnx = 0.25 / expx;
        const double sn = std::sin(ty), cn = std::cos(ty);
        const double tmp = w / (expx + expnx - cn);
        return s.add(tmp * (expx - expnx), tmp * sn);
    }
    case kLazysusan: {
        const double lx = P[kLazysusanX], ly = P[kLazysusanY];
        const double x = tx - lx, y = ty + ly;
        double r = std::sqrt(x * x + y * y);
        if (r < w) {
            const double a = std::atan2(y, x) + P[kLazysusanSpin] + P[kLazysusanTwist] * (w - r);
            r = w * r;
            px += r * std::cos(a) + lx;
            py += r * std::sin(a) - ly;
        } else {
            r = w * (1.0 + P[kLazysusanSpace] / r);
            px += r * x + lx;
            py += r * y - ly;
        }
        break;
    }
    case kLoonie: {
        const double r2 = s.sumsq, w2 = w * w;
        if (r2 < w2) {
            const double r = w * std::sqrt(w2 / r2 - 1.0);
            px += r * tx;
            py += r * ty;
        } else {
            px += w * tx;
            py += w * ty;
        }
        break;
    }
    case kModulus: {
        const double mx = P[kModulusX], my = P[kModulusY];
        if (tx > mx)
            px += w * (-mx + std::fmod(tx + mx, K[cModulusX2]));
        else if (tx < -mx)
            px += w * (mx - std::fmod(mx - tx, K[cModulusX2]));
        else
            px += w * tx;
        if (ty > my)
            py += w * (-my + std::fmod(ty + my, K[cModulusY2]));
        else if (ty < -my)
            py += w * (my - std::fmod(my - ty, K[cModulusY2]));
        else
            py += w * ty;
        break;
    }
    case kOscilloscope: {
        const double tpf = K[cOscTwoPiF];
        double t;
        if (P[kOscDamping] == 0.0)
            t = P[kOscAmplitude] * std::cos(tpf * tx) + P[kOscSeparation];
        else
            t = P[kOscAmplitude] * std::exp(-std::fabs(tx) * P[kOscDamping]) * std::cos(tpf * tx) +
                P[kOscSeparation];
        px += w * tx;
        if (std::fabs(ty) <= t)
            py -= w * ty;
        else
            py += w * ty;
        break;
    }
    case kPolar2: {
        const double p2v = w / kPi;
        return s.add(p2v * s.atanXY, p2v / 2.0 * std::log(s.sumsq));
    }
    case kPopcorn2: {
        const double c = P[kPopcorn2C];
        return s.add(w * (tx + P[kPopcorn2X] * std::sin(std::tan(ty * c))),
                     w * (ty + P[kPopcorn2Y] * std::sin(std::tan(tx * c))));
    }
    case kScry: {
        const double r = 1.0 / (s.sqrt * (s.sumsq + 1.0 / (w + kEps)));
        return s.add(tx * r, ty * r);
    }
    case kSeparation: {
        const double xi = P[kSeparationXinside], yi = P[kSeparationYinside];
        if (tx > 0.0)
            px += w * (std::sqrt(tx * tx + K[cSeparationX2]) - tx * xi);
        else
            px -= w * (std::sqrt(tx * tx + K[cSeparationX2]) + tx * xi);
        if (ty > 0.0)
            py += w * (std::sqrt(ty * ty + K[cSeparationY2]) - ty * yi);
        else
            py -= w * (std::sqrt(ty * ty + K[cSeparationY2]) + ty * yi);
        break;
    }
    case kSplit:
        if (std::cos(tx * P[kSplitXsize] * kPi) >= 0)
            py += w * ty;
        else
            py -= w * ty;
        if (std::cos(ty * P[kSplitYsize] * kPi) >= 0)
            px += w * tx;
        else
            px -= w * tx;
        break;
    case kSplits:
        return s.add(w * (tx >= 0 ? tx + P[kSplitsX] : tx - P[kSplitsX]),
                     w * (ty >= 0 ? ty + P[kSplitsY] : ty - P[kSplitsY]));
    case kStripes: {
        const double roundX = std::floor(tx + 0.5);
        const double offX = tx - roundX;
        return s.add(w * (offX * (1.0 - P[kStripesSpace]) + roundX),
                     w * (ty + offX * offX * P[kStripesWarp]));
    }
    case kWedge: {
        double r = s.sqrt;
        double a = s.atanYX + P[kWedgeSwirl] * r;
        const double c = std::floor((P[kWedgeCount] * a + kPi) * kInvPi * 0.5);
        a = a * K[cWedgeFactor] + c * P[kWedgeAngle];
        r = w * (r + P[kWedgeHole]);
        return s.add(r * std::cos(a), r * std::sin(a));
    }
    case kWedgeJulia: {
        const double r = w * std::pow(s.sumsq, K[cWedgeJuliaCn]);
        const int branch = truncToInt(K[cWedgeJuliaAbsN] * uniform01(rng));
        double a = (s.atanYX + 2 * kPi * branch) / P[kWedgeJuliaPower];
        const double c = std::floor((P[kWedgeJuliaCount] * a + kPi) * kInvPi * 0.5);
        a = a * K[cWedgeJuliaFactor] + c * P[kWedgeJuliaAngle];
        return s.add(r * std::cos(a), r * std::sin(a));
    }
    case kWedgeSph: {
        double r = 1.0 / (s.sqrt + kEps);
        double a = s.atanYX + P[kWedgeSphSwirl] * r;
        const double c = std::floor((P[kWedgeSphCount] * a + kPi) * kInvPi * 0.5);
        a = a * K[cWedgeSphFactor] + c * P[kWedgeSphAngle];
        r = w * (r + P[kWedgeSphHole]);
        return s.add(r * std::cos(a), r * std::sin(a));
    }
    case kWhorl: {
        const double r = s.sqrt;
        const double a = s.atanYX + (r < w ? P[kWhorlInside] : P[kWhorlOutside]) / (w - r);
        return s.add(w * r * std::cos(a), w * r * std::sin(a));
    }
    case kWaves2:
        return s.add(w * (tx + P[kWaves2Scalex] * std::sin(ty * P[kWaves2Freqx])),
                     w * (ty + P[kWaves2Scaley] * std::sin(tx * P[kWaves2Freqy])));
    // ---- cothe's complex functions of z = tx + i ty ----
    case kExp: {
        const double e = std::exp(tx);
        return s.add(w * e * std::cos(ty), w * e * std::sin(ty));
    }
    case kLog:
        return s.add(w * 0.5 * std::log(s.sumsq), w * s.atanYX);
    case kSin:
        return s.add(w * std::sin(tx) * std::cosh(ty), w * std::cos(tx) * std::sinh(ty));
    case kCos:
        px += w * std::cos(tx) * std::cosh(ty);
        py -= w * std::sin(tx) * std::sinh(ty);
        break;
    case kTan: {
        const double den = 1.0 / (std::cos(2 * tx) + std::cosh(2.0 * ty));
        return s.add(w * den * std::sin(2 * tx), w * den * std::sinh(2.0 * ty));
    }
    case kSec: {
        const double den = 2.0 / (std::cos(2 * tx) + std::cosh(2 * ty));
        return s.add(w * den * std::cos(tx) * std::cosh(ty),
                     w * den * std::sin(tx) * std::sinh(ty));
    }
    case kCsc: {
        const double den = 2.0 / (std::cosh(2.0 * ty) - std::cos(2.0 * tx));
        px += w * den * std::sin(tx) * std::cosh(ty);
        py -= w * den * std::cos(tx) * std::sinh(ty);
        break;
    }
    case kCot: {
        const double den = 1.0 / (std::cosh(2.0 * ty) - std::cos(2.0 * tx));
        return s.add(w * den * std::sin(2.0 * tx), w * den * -1 * std::sinh(2.0 * ty));
    }
    case kSinh:
        return s.add(w * std::sinh(tx) * std::cos(ty), w * std::cosh(tx) * std::sin(ty));
    case kCosh:
        return s.add(w * std::cosh(tx) * std::cos(ty), w * std::sinh(tx) * std::sin(ty));
    case kTanh: {
        const double den = 1.0 / (std::cos(2.0 * ty) + std::cosh(2.0 * tx));
        return s.add(w * den * std::sinh(2.0 * tx), w * den * std::sin(2.0 * ty));
    }
    case kSech: {
        const double den = 2.0 / (std::cos(2.0 * ty) + std::cosh(2.0 * tx));
        px += w * den * std::cos(ty) * std::cosh(tx);
        py -= w * den * std::sin(ty) * std::sinh(tx);
        break;
    }
    case kCsch: {
        const double den = 2.0 / (std::cosh(2.0 * tx) - std::cos(2.0 * ty));
        px += w * den * std::sinh(tx) * std::cos(ty);
        py -= w * den * std::cosh(tx) * std::sin(ty);
        break;
    }
    case kCoth: {
        const double den = 1.0 / (std::cosh(2.0 * tx) - std::cos(2.0 * ty));
        return s.add(w * den * std::sinh(2.0 * tx), w * den * std::sin(2.0 * ty));
    }
    // ---- the last three of flam3 3.1.1 ----
    case kAuger: {  // by Xyrus01
        const double f = P[kAugerFreq], aw = P[kAugerWeight], sc = P[kAugerScale];
        const double sx = std::sin(f * tx), sy = std::sin(f * ty);
        const double dy = ty + aw * (sc * sx / 2.0 + std::fabs(ty) * sx);
        const double dx = tx + aw * (sc * sy / 2.0 + std::fabs(tx) * sy);
        return s.add(w * (tx + P[kAugerSym] * (dx - tx)), w * dy);
    }
    case kFlux: {  // by meckie
        const double xpw = tx + w, xmw = tx - w;
        const double avgr = w * (2 + P[kFluxSpread]) *
            std::sqrt(std::sqrt(ty * ty + xpw * xpw) / std::sqrt(ty * ty + xmw * xmw));
        const double avga = (std::atan2(ty, xmw) - std::atan2(ty, xpw)) * 0.5;
        return s.add(avgr * std::cos(avga), avgr * std::sin(avga));
    }
    case kMobius: {  // by eralex: (a z + b) / (c z + d)
        const double reU = P[kMobiusReA] * tx - P[kMobiusImA] * ty + P[kMobiusReB];
        const double imU = P[kMobiusReA] * ty + P[kMobiusImA] * tx + P[kMobiusImB];
        const double reV = P[kMobiusReC] * tx - P[kMobiusImC] * ty + P[kMobiusReD];
        const double imV = P[kMobiusReC] * ty + P[kMobiusImC] * tx + P[kMobiusImD];
        const double radV = w / (reV * reV + imV * imV);
        return s.add(radV * (reU * reV + imU * imV), radV * (imU * reV - reU * imV));
    }
    default:  // pre_blur runs before the terms (XformMap keeps it out of them)
        break;
    }
}

bool XformMap::apply(const double p[2], double q[2], Xoshiro256 &rng) const
{
    Point s;
    s.tx = m_pre.a * p[0] + m_pre.b * p[1] + m_pre.c;
    s.ty = m_pre.d * p[0] + m_pre.e * p[1] + m_pre.f;

    // pre_blur: a pseudo-gaussian step (the sum of four uniforms) in a uniform direction.
    if (m_preBlur != 0.0) {
        double sum = uniform01(rng);
        sum += uniform01(rng);
        sum += uniform01(rng);
        sum += uniform01(rng);
        const double rndG = m_preBlur * (sum - 2.0);
        const double a = uniform01(rng) * 2.0 * kPi;
        s.tx += rndG * std::cos(a);
        s.ty += rndG * std::sin(a);
    }

    s.sumsq = s.tx * s.tx + s.ty * s.ty;
    s.sqrt = m_sqrt ? std::sqrt(s.sumsq) : std::numeric_limits<double>::quiet_NaN();
    if (m_atanXY)
        s.atanXY = std::atan2(s.tx, s.ty);
    if (m_angles) {
        s.sina = s.tx / s.sqrt;
        s.cosa = s.ty / s.sqrt;
    }
    if (m_atanYX)
        s.atanYX = std::atan2(s.ty, s.tx);

    const double *P = m_p.data();
    const double *K = m_consts.data();
    for (const Term &t : m_terms)
        addTerm(t.id, t.weight, s, P, K, m_pre, rng);

    if (m_hasPost) {
        q[0] = m_post.a * s.px + m_post.b * s.py + m_post.c;
        q[1] = m_post.d * s.px + m_post.e * s.py + m_post.f;
    } else {
        q[0] = s.px;
        q[1] = s.py;
    }
    if (badValue(q[0]) || badValue(q[1])) {
        q[0] = 2 * uniform01(rng) - 1;
        q[1] = 2 * uniform01(rng) - 1;
        return false;
    }
    return true;
}

} // namespace awb::flame
