// XformWave::applyAvx2 (XformWave.h) and its vector kernels: the scalar ones of
// VariationKernels.cpp in GCC's vector extension (the same expressions on four doubles),
// calling libmvec's AVX2 variants (_ZGVdN4v_sin, ...: glibc's vector ABI names), declared here
// since glibc declares them only under -ffast-math.
//
// The one file of the core compiled with -mavx2 -mfma (src/core/CMakeLists.txt), and only run
// where the processor has AVX2 (XformWave::available). Not a target attribute: Clang passes
// the 256-bit arguments of an external function by the file's own target, not the attribute's
// (libmvec's two-argument pow and atan2 then read garbage). It calls no inline function of the
// shared headers that a compiler might keep out of line (vector's data and size only), so that
// no AVX2 copy of one reaches the rest of the program.
#include "core/flame/XformWave.h"

#include "core/flame/VariationIds.h"
#include "core/flame/VariationTerm.h"

#if defined(__x86_64__) && defined(__AVX2__) && defined(__FMA__)

#include <immintrin.h>

#include <cstring>
#include <numbers>

namespace awb::flame {

using namespace detail;

extern "C" {
__m256d _ZGVdN4v_sin(__m256d);
__m256d _ZGVdN4v_cos(__m256d);
__m256d _ZGVdN4v_tan(__m256d);
__m256d _ZGVdN4v_exp(__m256d);
__m256d _ZGVdN4v_log(__m256d);
__m256d _ZGVdN4v_sinh(__m256d);
__m256d _ZGVdN4v_cosh(__m256d);
__m256d _ZGVdN4vv_atan2(__m256d, __m256d);
__m256d _ZGVdN4vv_pow(__m256d, __m256d);
}

namespace {

using V = double __attribute__((vector_size(32)));
using U = std::uint64_t __attribute__((vector_size(32)));

constexpr double kPi = std::numbers::pi;
constexpr double kInvPi = std::numbers::inv_pi;
constexpr double kEps = 1e-10;  // flam3's EPS

#define AWB_WAVE_INLINE __attribute__((always_inline)) inline

AWB_WAVE_INLINE V vsin(V x) { return V(_ZGVdN4v_sin(__m256d(x))); }
AWB_WAVE_INLINE V vcos(V x) { return V(_ZGVdN4v_cos(__m256d(x))); }
AWB_WAVE_INLINE V vtan(V x) { return V(_ZGVdN4v_tan(__m256d(x))); }
AWB_WAVE_INLINE V vexp(V x) { return V(_ZGVdN4v_exp(__m256d(x))); }
AWB_WAVE_INLINE V vlog(V x) { return V(_ZGVdN4v_log(__m256d(x))); }
AWB_WAVE_INLINE V vsinh(V x) { return V(_ZGVdN4v_sinh(__m256d(x))); }
AWB_WAVE_INLINE V vcosh(V x) { return V(_ZGVdN4v_cosh(__m256d(x))); }
AWB_WAVE_INLINE V vatan2(V y, V x) { return V(_ZGVdN4vv_atan2(__m256d(y), __m256d(x))); }
AWB_WAVE_INLINE V vpow(V x, V y) { return V(_ZGVdN4vv_pow(__m256d(x), __m256d(y))); }
AWB_WAVE_INLINE V vsqrt(V x) { return V(_mm256_sqrt_pd(__m256d(x))); }
AWB_WAVE_INLINE V vtrunc(V x)
{
    return V(_mm256_round_pd(__m256d(x), _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC));
}
AWB_WAVE_INLINE V vabs(V x) { return V(U(x) & 0x7fffffffffffffffULL); }
AWB_WAVE_INLINE V splat(double a) { return V{a, a, a, a}; }

// x^c for x >= 0 as exp(c log x): half of libmvec's pow's time, within a few ulp of it for
// the exponents here (julian's dist / power / 2); x = 0 gives pow's 0 or infinity, c = 0 its 1.
AWB_WAVE_INLINE V vpowPositive(V x, double c)
{
    if (c == 0)
        return splat(1.0);
    return vexp(c * vlog(x));
}

// xoshiro256+ on four lanes, uniform01 as [1, 2) - 1 from the top 52 bits of each draw.
struct Rng4 {
    U s0, s1, s2, s3;

    AWB_WAVE_INLINE U next()
    {
        const U result = s0 + s3;
        const U t = s1 << 17;
        s2 ^= s0;
        s3 ^= s1;
        s1 ^= s2;
        s0 ^= s3;
        s2 ^= t;
        s3 = (s3 << 45) | (s3 >> 19);
        return result;
    }
    AWB_WAVE_INLINE V uniform() { return V((next() >> 12) | 0x3FF0000000000000ULL) - 1.0; }
    // flam3's pseudo-gaussian: four uniforms summed, minus 2.
    AWB_WAVE_INLINE V gaussian()
    {
        V sum = uniform();
        sum += uniform();
        sum += uniform();
        sum += uniform();
        return sum - 2.0;
    }
};

// Point of VariationTerm.h, four lanes.
struct Point4 {
    V tx, ty, sumsq, sqrt;
    V atanXY{}, sina{}, cosa{}, atanYX{};
    V px{}, py{};

    AWB_WAVE_INLINE void add(V x, V y)
    {
        px += x;
        py += y;
    }
};

// One term on four lanes, as addTerm on one; false when the term has no vector kernel.
bool addTerm4(int id, double w, Point4 &s, const double *P, const double *K,
                              const Affine2 &pre, Rng4 &rng)
{
    const V tx = s.tx, ty = s.ty;
    switch (id) {
    case kLinear:
        s.add(w * tx, w * ty);
        return true;
    case kSinusoidal:
        s.add(w * vsin(tx), w * vsin(ty));
        return true;
    case kSpherical: {
        const V r2 = w / (s.sumsq + kEps);
        s.add(r2 * tx, r2 * ty);
        return true;
    }
    case kSwirl: {
        const V c1 = vsin(s.sumsq), c2 = vcos(s.sumsq);
        s.add(w * (c1 * tx - c2 * ty), w * (c2 * tx + c1 * ty));
        return true;
    }
    case kHorseshoe: {
        const V r = w / (s.sqrt + kEps);
        s.add((tx - ty) * (tx + ty) * r, 2.0 * tx * ty * r);
        return true;
    }
    case kPolar:
        s.add(w * (s.atanXY * kInvPi), w * (s.sqrt - 1.0));
        return true;
    case kHandkerchief: {
        const V a = s.atanXY, r = s.sqrt;
        s.add(w * r * vsin(a + r), w * r * vcos(a - r));
        return true;
    }
    case kHeart: {
        const V a = s.sqrt * s.atanXY;
        const V r = w * s.sqrt;
        s.add(r * vsin(a), (-r) * vcos(a));
        return true;
    }
    case kDisc: {
        const V a = s.atanXY * kInvPi;
        const V r = kPi * s.sqrt;
        s.add(w * vsin(r) * a, w * vcos(r) * a);
        return true;
    }
    case kSpiral: {
        const V r = s.sqrt + kEps;
        const V r1 = w / r;
        s.add(r1 * (s.cosa + vsin(r)), r1 * (s.sina - vcos(r)));
        return true;
    }
    case kHyperbolic: {
        const V r = s.sqrt + kEps;
        s.add(w * s.sina / r, w * s.cosa * r);
        return true;
    }
    case kDiamond:
        s.add(w * s.sina * vcos(s.sqrt), w * s.cosa * vsin(s.sqrt));
        return true;
    case kEx: {
        const V a = s.atanXY, r = s.sqrt;
        const V n0 = vsin(a + r), n1 = vcos(a - r);
        const V m0 = n0 * n0 * n0 * r, m1 = n1 * n1 * n1 * r;
        s.add(w * (m0 + m1), w * (m0 - m1));
        return true;
    }
    case kJulia: {  // one of the two square roots, by a random bit
        const V a = 0.5 * s.atanXY + V((rng.next() >> 63) != 0 ? splat(kPi) : splat(0.0));
        const V r = w * vsqrt(s.sqrt);
        s.add(r * vcos(a), r * vsin(a));
        return true;
    }
    case kBent: {
        const V nx = tx < 0.0 ? tx * 2.0 : tx;
        const V ny = ty < 0.0 ? ty / 2.0 : ty;
        s.add(w * nx, w * ny);
        return true;
    }
    case kWaves:
        s.add(w * (tx + pre.b * vsin(ty * K[cWavesX])), w * (ty + pre.e * vsin(tx * K[cWavesY])));
        return true;
    case kFisheye: {
        const V r = 2 * w / (s.sqrt + 1);
        s.add(r * ty, r * tx);
        return true;
    }
    case kPopcorn: {
        const V dx = vtan(3 * ty), dy = vtan(3 * tx);
        s.add(w * (tx + pre.c * vsin(dx)), w * (ty + pre.f * vsin(dy)));
        return true;
    }
    case kExponential: {
        const V dx = w * vexp(tx - 1.0);
        const V dy = kPi * ty;
        s.add(dx * vcos(dy), dx * vsin(dy));
        return true;
    }
    case kPower: {
        const V r = w * vpow(s.sqrt, s.sina);
        s.add(r * s.cosa, r * s.sina);
        return true;
    }
    case kCosine: {
        const V a = tx * kPi;
        s.add(w * (vcos(a) * vcosh(ty)), w * (-vsin(a) * vsinh(ty)));
        return true;
    }
    case kBlob: {
        const V r = s.sqrt
                    * (P[kBlobLow] + K[cBlobSpan] * (0.5 + 0.5 * vsin(P[kBlobWaves] * s.atanXY)));
        s.add(w * s.sina * r, w * s.cosa * r);
        return true;
    }
    case kPdj: {
        const V nx1 = vcos(P[kPdjB] * tx), nx2 = vsin(P[kPdjC] * tx);
        const V ny1 = vsin(P[kPdjA] * ty), ny2 = vcos(P[kPdjD] * ty);
        s.add(w * (ny1 - nx1), w * (nx2 - ny2));
        return true;
    }
    case kEyefish: {
        const V r = (w * 2.0) / (s.sqrt + 1.0);
        s.add(r * tx, r * ty);
        return true;
    }
    case kBubble: {
        const V r = w / (0.25 * s.sumsq + 1);
        s.add(r * tx, r * ty);
        return true;
    }
    case kCylinder:
        s.add(w * vsin(tx), w * ty);
        return true;
    case kPerspective: {
        const V t = 1.0 / (P[kPerspectiveDist] - ty * K[cPerspSin]);
        s.add(w * P[kPerspectiveDist] * tx * t, w * K[cPerspDistCos] * ty * t);
        return true;
    }
    case kNoise: {
        const V a = rng.uniform() * (2 * kPi);
        const V r = w * rng.uniform();
        s.add(tx * r * vcos(a), ty * r * vsin(a));
        return true;
    }
    case kJulian:
    case kJuliascope: {  // one of |power| roots at random; juliascope mirrors the odd ones
        const bool scope = id == kJuliascope;
        const double absN = K[scope ? cScopeAbsN : cJulianAbsN];
        const double power = P[scope ? kJuliascopePower : kJulianPower];
        const V branch = vtrunc(absN * rng.uniform());
        V t = s.atanYX;
        if (scope) {  // an odd branch: -atan (the branch is a whole number below 2^53)
            const V half = vtrunc(branch * 0.5);
            t = branch - 2.0 * half != 0.0 ? -t : t;
        }
        const V a = (t + 2 * kPi * branch) / power;
        const V r = w * vpowPositive(s.sumsq, K[scope ? cScopeCn : cJulianCn]);
        s.add(r * vcos(a), r * vsin(a));
        return true;
    }
    case kBlur: {
        const V a = rng.uniform() * (2 * kPi);
        const V r = w * rng.uniform();
        s.add(r * vcos(a), r * vsin(a));
        return true;
    }
    case kGaussianBlur: {
        const V a = rng.uniform() * (2 * kPi);
        const V r = w * rng.gaussian();
        s.add(r * vcos(a), r * vsin(a));
        return true;
    }
    case kRadialBlur: {  // the radius is added unweighted, as in flam3
        const V rndG = w * rng.gaussian();
        const V a = s.atanYX + K[cRadialSpin] * rndG;
        const V rz = K[cRadialZoom] * rndG - 1;
        s.add(s.sqrt * vcos(a) + rz * tx, s.sqrt * vsin(a) + rz * ty);
        return true;
    }
    case kCurl: {
        const double c1 = P[kCurlC1], c2 = P[kCurlC2];
        const V re = 1.0 + c1 * tx + c2 * (tx * tx - ty * ty);
        const V im = c1 * ty + 2.0 * c2 * tx * ty;
        const V r = w / (re * re + im * im);
        s.add((tx * re + ty * im) * r, (ty * re - tx * im) * r);
        return true;
    }
    case kTangent:
        s.add(w * vsin(tx) / vcos(ty), w * vtan(ty));
        return true;
    case kSquare: {
        const V u = rng.uniform();
        s.add(w * (u - 0.5), w * (rng.uniform() - 0.5));
        return true;
    }
    case kCross: {
        const V q = tx * tx - ty * ty;
        const V r = w * vsqrt(1.0 / (q * q + kEps));
        s.add(tx * r, ty * r);
        return true;
    }
    case kBent2: {
        const V nx = tx < 0.0 ? tx * P[kBent2X] : tx;
        const V ny = ty < 0.0 ? ty * P[kBent2Y] : ty;
        s.add(w * nx, w * ny);
        return true;
    }
    case kButterfly: {
        const double wx = w * 1.3029400317411197908970256609023;  // 4 / sqrt(3 pi)
        const V y2 = ty * 2.0;
        const V r = wx * vsqrt(vabs(ty * tx) / (kEps + tx * tx + y2 * y2));
        s.add(r * tx, r * y2);
        return true;
    }
    case kPolar2: {
        const double p2v = w / kPi;
        s.add(p2v * s.atanXY, p2v / 2.0 * vlog(s.sumsq));
        return true;
    }
    case kScry: {
        const V r = 1.0 / (s.sqrt * (s.sumsq + 1.0 / (w + kEps)));
        s.add(tx * r, ty * r);
        return true;
    }
    case kSplits:
        s.add(w * (tx >= 0.0 ? tx + P[kSplitsX] : tx - P[kSplitsX]),
              w * (ty >= 0.0 ? ty + P[kSplitsY] : ty - P[kSplitsY]));
        return true;
    case kWaves2:
        s.add(w * (tx + P[kWaves2Scalex] * vsin(ty * P[kWaves2Freqx])),
              w * (ty + P[kWaves2Scaley] * vsin(tx * P[kWaves2Freqy])));
        return true;
    case kExp: {
        const V e = vexp(tx);
        s.add(w * e * vcos(ty), w * e * vsin(ty));
        return true;
    }
    case kLog:
        s.add(w * 0.5 * vlog(s.sumsq), w * s.atanYX);
        return true;
    case kSin:
        s.add(w * vsin(tx) * vcosh(ty), w * vcos(tx) * vsinh(ty));
        return true;
    case kCos:
        s.add(w * vcos(tx) * vcosh(ty), -(w * vsin(tx) * vsinh(ty)));
        return true;
    case kSinh:
        s.add(w * vsinh(tx) * vcos(ty), w * vcosh(tx) * vsin(ty));
        return true;
    case kCosh:
        s.add(w * vcosh(tx) * vcos(ty), w * vsinh(tx) * vsin(ty));
        return true;
    case kTanh: {
        const V den = 1.0 / (vcos(2.0 * ty) + vcosh(2.0 * tx));
        s.add(w * den * vsinh(2.0 * tx), w * den * vsin(2.0 * ty));
        return true;
    }
    default:
        return false;
    }
}

// flam3's badvalue() on four lanes: NaN or beyond +-1e10.
AWB_WAVE_INLINE auto badValue4(V x) { return x != x || x > 1e10 || x < -1e10; }

} // namespace

void XformWave::applyAvx2(const double *x, const double *y, double *qx, double *qy,
                                      std::uint8_t *bad, int n, WaveRandom &random) const
{
    const XformMap &m = *m_map;
    const Affine2 &pre = m.m_pre, &post = m.m_post;
    const double *P = m.m_p.data();
    const double *K = m.m_consts.data();
    Rng4 rng;
    std::uint64_t(&lanes)[4][4] = random.lanes;
    __builtin_memcpy(&rng.s0, lanes[0], 32);
    __builtin_memcpy(&rng.s1, lanes[1], 32);
    __builtin_memcpy(&rng.s2, lanes[2], 32);
    __builtin_memcpy(&rng.s3, lanes[3], 32);

    const XformMap::Term *terms = m.m_terms.data();
    const std::size_t termCount = m.m_terms.size();
    for (int i = 0; i < n; i += kWidth) {
        V px, py;
        __builtin_memcpy(&px, x + i, 32);
        __builtin_memcpy(&py, y + i, 32);
        Point4 s;
        s.tx = pre.a * px + pre.b * py + pre.c;
        s.ty = pre.d * px + pre.e * py + pre.f;
        if (m.m_preBlur != 0.0) {  // a pseudo-gaussian step in a uniform direction
            const V rndG = m.m_preBlur * rng.gaussian();
            const V a = rng.uniform() * (2.0 * kPi);
            s.tx += rndG * vcos(a);
            s.ty += rndG * vsin(a);
        }
        s.sumsq = s.tx * s.tx + s.ty * s.ty;
        s.sqrt = vsqrt(s.sumsq);
        if (m.m_atanXY)
            s.atanXY = vatan2(s.tx, s.ty);
        if (m.m_angles) {
            s.sina = s.tx / s.sqrt;
            s.cosa = s.ty / s.sqrt;
        }
        if (m.m_atanYX)
            s.atanYX = vatan2(s.ty, s.tx);

        for (std::size_t k = 0; k < termCount; ++k) {
            const XformMap::Term &t = terms[k];
            if (addTerm4(t.id, t.weight, s, P, K, pre, rng))
                continue;
            // No vector kernel: the lanes one by one through XformMap's own term.
            const int lanesHere = n - i < kWidth ? n - i : kWidth;
            for (int j = 0; j < lanesHere; ++j) {
                Point one;
                one.tx = s.tx[j];
                one.ty = s.ty[j];
                one.sumsq = s.sumsq[j];
                one.sqrt = s.sqrt[j];
                one.atanXY = s.atanXY[j];
                one.sina = s.sina[j];
                one.cosa = s.cosa[j];
                one.atanYX = s.atanYX[j];
                addTerm(t.id, t.weight, one, P, K, pre, random.scalar);
                s.px[j] += one.px;
                s.py[j] += one.py;
            }
        }

        V ox = s.px, oy = s.py;
        if (m.m_hasPost) {
            ox = post.a * s.px + post.b * s.py + post.c;
            oy = post.d * s.px + post.e * s.py + post.f;
        }
        const auto isBad = badValue4(ox) || badValue4(oy);
        if (isBad[0] | isBad[1] | isBad[2] | isBad[3]) {
            const V rx = 2.0 * rng.uniform() - 1.0, ry = 2.0 * rng.uniform() - 1.0;
            ox = isBad ? rx : ox;
            oy = isBad ? ry : oy;
        }
        __builtin_memcpy(qx + i, &ox, 32);
        __builtin_memcpy(qy + i, &oy, 32);
        for (int j = 0; j < kWidth; ++j)
            bad[i + j] = isBad[j] != 0;
    }
    __builtin_memcpy(lanes[0], &rng.s0, 32);
    __builtin_memcpy(lanes[1], &rng.s1, 32);
    __builtin_memcpy(lanes[2], &rng.s2, 32);
    __builtin_memcpy(lanes[3], &rng.s3, 32);
}

} // namespace awb::flame

#endif
