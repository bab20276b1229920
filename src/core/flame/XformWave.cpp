// XformWave's parts that run on any processor: the lanes' generators, which terms have a
// vector kernel, whether they run here, and the lane-by-lane apply where they do not. The
// kernels are in XformWaveAvx2.cpp, the one file compiled for AVX2.
#include "core/flame/XformWave.h"

#include "core/flame/VariationIds.h"
#include "core/flame/VariationTerm.h"
#include "core/render/EngineShared.h"

#include <stdexcept>

namespace awb::flame {

using namespace detail;

WaveRandom::WaveRandom(std::uint64_t seed, std::uint64_t stream) : scalar(seed, stream)
{
    // The lanes' generators seeded apart from every stream's own (streams are < 2^32).
    for (std::uint64_t j = 0; j < 4; ++j) {
        const Xoshiro256 lane(seed, (stream + 1) * 0x100000000ULL + j);
        for (int w = 0; w < 4; ++w)
            lanes[w][j] = lane.s[w];
    }
    for (std::uint64_t j = 0; j < 8; ++j) {
        const Xoshiro256 kernel(seed, (stream + 1) * 0x100000000ULL + 4 + j);
        const Xoshiro256 lane(seed, (stream + 1) * 0x100000000ULL + 12 + j);
        for (int w = 0; w < 4; ++w) {
            wide[w][j] = kernel.s[w];
            step[w][j] = lane.s[w];
        }
    }
}

bool XformWave::vectorKernel(int id)
{
    switch (id) {
    case kLinear: case kSinusoidal: case kSpherical: case kSwirl: case kHorseshoe: case kPolar:
    case kHandkerchief: case kHeart: case kDisc: case kSpiral: case kHyperbolic: case kDiamond:
    case kEx: case kJulia: case kBent: case kWaves: case kFisheye: case kPopcorn:
    case kExponential: case kPower: case kCosine: case kBlob: case kPdj: case kEyefish:
    case kBubble: case kCylinder: case kPerspective: case kNoise: case kJulian:
    case kJuliascope: case kBlur: case kGaussianBlur: case kRadialBlur: case kCurl:
    case kTangent: case kSquare: case kCross: case kBent2: case kButterfly: case kPolar2:
    case kScry: case kSplits: case kWaves2: case kExp: case kLog: case kSin: case kCos:
    case kSinh: case kCosh: case kTanh: case kRings: case kFan: case kFan2: case kRings2:
    case kPie: case kArch: case kRays: case kBlade: case kSecant2: case kDisc2: case kWedge:
    case kWedgeJulia: case kWedgeSph: case kWhorl:
        return true;
    default:
        return false;
    }
}

XformWave::XformWave(const XformMap &map, bool wide)
    : m_map(&map), m_vector(available()), m_wide(wide && XformWave::wide())
{
}

void XformWave::apply(const double *x, const double *y, double *qx, double *qy,
                      std::uint8_t *bad, int n, WaveRandom &rng) const
{
    if (m_wide) {
        applyAvx512(x, y, qx, qy, bad, n, rng);
        return;
    }
    if (m_vector) {
        applyAvx2(x, y, qx, qy, bad, n, rng);
        return;
    }
    for (int i = 0; i < n; ++i) {
        const double p[2] = {x[i], y[i]};
        double q[2];
        bad[i] = !m_map->apply(p, q, rng.scalar);
        qx[i] = q[0];
        qy[i] = q[1];
    }
}

#if defined(AWB_AVX2_KERNELS)

bool XformWave::available() { return engine::haveAvx2(); }

bool XformWave::wide() { return engine::haveAvx512(); }

#else

bool XformWave::available() { return false; }

bool XformWave::wide() { return false; }

void XformWave::applyAvx2(const double *, const double *, double *, double *, std::uint8_t *,
                          int, WaveRandom &) const
{
    throw std::logic_error("XformWave::applyAvx2: no vector kernels on this platform");
}

void XformWave::applyAvx512(const double *, const double *, double *, double *,
                            std::uint8_t *, int, WaveRandom &) const
{
    throw std::logic_error("XformWave::applyAvx512: no vector kernels on this platform");
}

#endif

} // namespace awb::flame
