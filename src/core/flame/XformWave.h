#pragma once
// One xform on a wave of orbits: XformMap::apply on lanes of points held as arrays (x[i],
// y[i]), four at a time in AVX2 registers where the processor has them, the variations' sines,
// exponentials and arctangents by glibc's vector math library (libmvec, 4 ulp). What
// FlameChaos.cpp's chaos game runs on every processor: the orbits that chose the same xform in
// one step go through it together (lane by lane through XformMap::apply without AVX2). A term with no vector kernel here runs lane by lane through XformMap's own code
// (VariationTerm.h), so every variation runs and each has one definition of its formula
// besides its vector form. The vector kernels keep the scalar formulas' operations; their
// results differ from XformMap::apply's in the last bits (libmvec's 4 ulp, fused
// multiply-adds), and their random draws come from four more streams, so a wave's picture is
// the scalar one's in distribution, not point by point (tests/core/test_flame_wave.cpp).

#include "core/flame/Variations.h"

#include <cstdint>
#include <vector>

namespace awb::flame {

// The random numbers of one stream's wave: the stream's own generator (lane-by-lane terms,
// the chaos game's choices) and four generators of the vector kernels' draws.
struct WaveRandom {
    WaveRandom(std::uint64_t seed, std::uint64_t stream);
    Xoshiro256 scalar;
    alignas(32) std::uint64_t lanes[4][4];  // word w of lane j's state: lanes[w][j]
    // Eight more generators for the AVX-512 kernels' draws, and eight for the AVX-512 step's
    // (FlameStep.h), the same layout.
    alignas(64) std::uint64_t wide[4][8];
    alignas(64) std::uint64_t step[4][8];
};

class XformWave {
public:
    static constexpr int kWidth = 8;  // lanes per register at most (AVX-512; AVX2 has 4)
    // Whether this machine runs the vector kernels: AVX2, and the engine's kernels not forced
    // to the baseline (engine::forceBaselineKernels, as the IFS engine's own AVX2 kernels).
    // Elsewhere a wave applies XformMap::apply lane by lane: the same game, scalar kernels.
    static bool available();
    // Whether the game's step runs on AVX-512 registers here (FlameStep.h): available(), and
    // the processor has AVX-512 (engine::haveAvx512).
    static bool wide();
    // Whether term `id` has a vector kernel (the others run lane by lane).
    static bool vectorKernel(int id);

    // `wide`: the eight-lane kernels where wide() holds (else the four-lane ones).
    explicit XformWave(const XformMap &map, bool wide = true);

    // (qx[i], qy[i]) = map(x[i], y[i]) and bad[i] = whether that was a bad value (q then
    // flam3's replacement, a random point of [-1, 1]^2), for i < n. Each array holds n rounded
    // up to kWidth entries (the extra lanes are computed and ignored). By the eight-lane
    // kernels when wide() was true at construction, the four-lane ones when available() was,
    // else by XformMap::apply on each lane.
    void apply(const double *x, const double *y, double *qx, double *qy, std::uint8_t *bad,
               int n, WaveRandom &rng) const;

private:
    // The vector kernels (XformWaveAvx2.cpp, XformWaveAvx512.cpp).
    void applyAvx2(const double *x, const double *y, double *qx, double *qy, std::uint8_t *bad,
                   int n, WaveRandom &rng) const;
    void applyAvx512(const double *x, const double *y, double *qx, double *qy,
                     std::uint8_t *bad, int n, WaveRandom &rng) const;

    const XformMap *m_map;
    bool m_vector, m_wide;
};

} // namespace awb::flame
