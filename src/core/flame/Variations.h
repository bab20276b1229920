#pragma once
// flam3 3.1.1's variations (variations.c), every one it renders, in its order: the index of
// the `var` and `var1` attributes, and the ids of FlameXform::variations. Each is written
// here from its formula (Draves & Reckase, "The Fractal Flame Algorithm", appendix, and
// flam3's sources, which are the reference where the two differ); tests/core/
// test_flame_variations.cpp checks every deterministic one point by point against libflam3's
// own apply_xform, and the random ones by their distributions.

#include "core/flame/Flame.h"
#include "core/ifs/Random.h"

#include <string_view>
#include <vector>

namespace awb::flame {

inline constexpr int kVariationCount = 99;

std::string_view variationName(int id);
int variationId(std::string_view name);  // -1 for none
// True for the variations that draw random numbers (blur, noise, julian's branch, ...): their
// image of a point is not a function of the point.
bool variationIsRandom(int id);

// The variations' parameters (julian_power, blob_low, ...: flam3's attribute names), each
// belonging to one variation, ids 0 .. parameterCount() - 1.
int parameterCount();
std::string_view parameterName(int p);
int parameterId(std::string_view name);  // -1 for none
int parameterVariation(int p);
double parameterDefault(int p);
std::vector<int> variationParameters(int id);
// Every parameter at its default: FlameXform::parameters of a new xform.
const std::vector<double> &defaultParameters();

// Uniform numbers of the random variations: [0, 1) from 53 bits of the stream.
inline double uniform01(Xoshiro256 &rng) { return double(rng.next() >> 11) * 0x1.0p-53; }

// One xform ready to apply, flam3's apply_xform without the colour: its variations'
// constants computed once (julian's 1/power, supershape's pm_4, ...).
class XformMap {
public:
    explicit XformMap(const FlameXform &xform);

    // q = post( sum_v w_v V_v( pre(p) ) ), pre_blur moving pre(p) first. Returns false for
    // a bad value (NaN, or a coordinate beyond +-1e10), as flam3 does; q is then a random
    // point of [-1, 1]^2 (flam3's replacement).
    bool apply(const double p[2], double q[2], Xoshiro256 &rng) const;
    bool random() const { return m_random; }

private:
    friend class XformWave;  // the same xform on a wave of orbits (XformWave.h)
    struct Term {
        int id;
        double weight;
    };
    Affine2 m_pre, m_post;
    bool m_hasPost = false;
    bool m_random = false;
    double m_preBlur = 0;  // pre_blur's weight (applied before the others)
    // What the terms need of the point: flam3's precalc flags (m_sqrt: its radius; where no
    // term reads it, the radius is left NaN, so that a kernel that did read it would fail its
    // tests rather than read a stale value).
    bool m_sqrt = false, m_atanXY = false, m_angles = false, m_atanYX = false;
    std::vector<Term> m_terms;
    std::vector<double> m_p;       // the xform's parameters by id
    std::vector<double> m_consts;  // per-variation precalculated constants (implementation's)
};

} // namespace awb::flame
