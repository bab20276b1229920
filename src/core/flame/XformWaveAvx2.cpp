// XformWave::applyAvx2 (XformWave.h) and its vector kernels: the scalar ones of
// VariationKernels.cpp in GCC's vector extension (the same expressions on four doubles:
// XformWaveKernels.inc, shared with the eight-lane XformWaveAvx512.cpp), calling libmvec's AVX2
// variants (_ZGVdN4v_sin, ...: glibc's vector ABI names), declared here since glibc declares
// them only under -ffast-math.
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
__m256d _ZGVdN4v_cbrt(__m256d);
__m256d _ZGVdN4vv_atan2(__m256d, __m256d);
__m256d _ZGVdN4vv_pow(__m256d, __m256d);
}

using V = double __attribute__((vector_size(32)));
using U = std::uint64_t __attribute__((vector_size(32)));

constexpr int kLanes = 4;

#define AWB_WAVE_INLINE __attribute__((always_inline)) inline
#define AWB_WAVE_APPLY applyAvx2
#define AWB_WAVE_STATE lanes

static AWB_WAVE_INLINE V vsin(V x) { return V(_ZGVdN4v_sin(__m256d(x))); }
static AWB_WAVE_INLINE V vcos(V x) { return V(_ZGVdN4v_cos(__m256d(x))); }
static AWB_WAVE_INLINE V vtan(V x) { return V(_ZGVdN4v_tan(__m256d(x))); }
static AWB_WAVE_INLINE V vexp(V x) { return V(_ZGVdN4v_exp(__m256d(x))); }
static AWB_WAVE_INLINE V vlog(V x) { return V(_ZGVdN4v_log(__m256d(x))); }
static AWB_WAVE_INLINE V vsinh(V x) { return V(_ZGVdN4v_sinh(__m256d(x))); }
static AWB_WAVE_INLINE V vcosh(V x) { return V(_ZGVdN4v_cosh(__m256d(x))); }
static AWB_WAVE_INLINE V vcbrt(V x) { return V(_ZGVdN4v_cbrt(__m256d(x))); }
static AWB_WAVE_INLINE V vatan2(V y, V x) { return V(_ZGVdN4vv_atan2(__m256d(y), __m256d(x))); }
static AWB_WAVE_INLINE V vpow(V x, V y) { return V(_ZGVdN4vv_pow(__m256d(x), __m256d(y))); }
static AWB_WAVE_INLINE V vsqrt(V x) { return V(_mm256_sqrt_pd(__m256d(x))); }
static AWB_WAVE_INLINE V vtrunc(V x)
{
    return V(_mm256_round_pd(__m256d(x), _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC));
}
// c - a b with one rounding (fused: not left to the compiler's contraction, which clang does
// not apply to these vector types).
static AWB_WAVE_INLINE V vfnmadd(V a, V b, V c)
{
    return V(_mm256_fnmadd_pd(__m256d(a), __m256d(b), __m256d(c)));
}

// The lanes where x is NaN or |x| > most, lane j as bit j.
static AWB_WAVE_INLINE unsigned beyond(V x, double most)
{
    const __m256d magnitude = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffffLL));
    return unsigned(_mm256_movemask_pd(
        _mm256_cmp_pd(_mm256_and_pd(__m256d(x), magnitude), _mm256_set1_pd(most), _CMP_NLE_UQ)));
}
static AWB_WAVE_INLINE void storeLaneFlags(std::uint8_t *flags, unsigned bits)
{
    // Four bits spread to the low bits of four bytes: bit j moves by 7 j (no two bits of the
    // product meet, so nothing carries).
    const std::uint32_t bytes = (bits * 0x204081u) & 0x01010101u;
    __builtin_memcpy(flags, &bytes, 4);
}
#include "core/flame/XformWaveKernels.inc"

} // namespace awb::flame

#endif
