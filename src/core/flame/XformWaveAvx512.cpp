// XformWave::applyAvx512 (XformWave.h): the wave's kernels (XformWaveKernels.inc) on eight
// doubles, calling libmvec's AVX-512 variants (_ZGVeN8v_sin, ...: glibc's vector ABI names).
// Compiled for AVX-512 F, DQ, BW and VL (src/core/CMakeLists.txt) and run only where the
// processor has them (XformWave::wide); otherwise as XformWaveAvx2.cpp, whose notes on target
// attributes and shared inline functions hold here too.
#include "core/flame/XformWave.h"

#include "core/flame/VariationIds.h"
#include "core/flame/VariationTerm.h"

#if defined(__x86_64__) && defined(__AVX512F__) && defined(__AVX512DQ__) && defined(__AVX512BW__) \
    && defined(__AVX512VL__)

#include <immintrin.h>

#include <cstring>
#include <numbers>

namespace awb::flame {

using namespace detail;

extern "C" {
__m512d _ZGVeN8v_sin(__m512d);
__m512d _ZGVeN8v_cos(__m512d);
__m512d _ZGVeN8v_tan(__m512d);
__m512d _ZGVeN8v_exp(__m512d);
__m512d _ZGVeN8v_log(__m512d);
__m512d _ZGVeN8v_sinh(__m512d);
__m512d _ZGVeN8v_cosh(__m512d);
__m512d _ZGVeN8v_cbrt(__m512d);
__m512d _ZGVeN8vv_atan2(__m512d, __m512d);
__m512d _ZGVeN8vv_pow(__m512d, __m512d);
}

using V = double __attribute__((vector_size(64)));
using U = std::uint64_t __attribute__((vector_size(64)));

constexpr int kLanes = 8;

#define AWB_WAVE_INLINE __attribute__((always_inline)) inline
#define AWB_WAVE_APPLY applyAvx512
#define AWB_WAVE_STATE wide

static AWB_WAVE_INLINE V vsin(V x) { return V(_ZGVeN8v_sin(__m512d(x))); }
static AWB_WAVE_INLINE V vcos(V x) { return V(_ZGVeN8v_cos(__m512d(x))); }
static AWB_WAVE_INLINE V vtan(V x) { return V(_ZGVeN8v_tan(__m512d(x))); }
static AWB_WAVE_INLINE V vexp(V x) { return V(_ZGVeN8v_exp(__m512d(x))); }
static AWB_WAVE_INLINE V vlog(V x) { return V(_ZGVeN8v_log(__m512d(x))); }
static AWB_WAVE_INLINE V vsinh(V x) { return V(_ZGVeN8v_sinh(__m512d(x))); }
static AWB_WAVE_INLINE V vcosh(V x) { return V(_ZGVeN8v_cosh(__m512d(x))); }
static AWB_WAVE_INLINE V vcbrt(V x) { return V(_ZGVeN8v_cbrt(__m512d(x))); }
static AWB_WAVE_INLINE V vatan2(V y, V x) { return V(_ZGVeN8vv_atan2(__m512d(y), __m512d(x))); }
static AWB_WAVE_INLINE V vpow(V x, V y) { return V(_ZGVeN8vv_pow(__m512d(x), __m512d(y))); }
static AWB_WAVE_INLINE V vsqrt(V x) { return V(_mm512_sqrt_pd(__m512d(x))); }
static AWB_WAVE_INLINE V vtrunc(V x)
{
    return V(_mm512_roundscale_pd(__m512d(x), _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC));
}
// c - a b with one rounding (fused: not left to the compiler's contraction, which clang does
// not apply to these vector types).
static AWB_WAVE_INLINE V vfnmadd(V a, V b, V c)
{
    return V(_mm512_fnmadd_pd(__m512d(a), __m512d(b), __m512d(c)));
}

// The lanes where x is NaN or |x| > most, lane j as bit j.
static AWB_WAVE_INLINE unsigned beyond(V x, double most)
{
    return unsigned(
        _mm512_cmp_pd_mask(_mm512_abs_pd(__m512d(x)), _mm512_set1_pd(most), _CMP_NLE_UQ));
}
static AWB_WAVE_INLINE void storeLaneFlags(std::uint8_t *flags, unsigned bits)
{
    _mm_storel_epi64(reinterpret_cast<__m128i *>(flags), _mm_maskz_set1_epi8(__mmask16(bits), 1));
}
#include "core/flame/XformWaveKernels.inc"

} // namespace awb::flame

#endif
