/* simd-sse2: the voxel y-buffer kernel on 4 lanes for any x86-64 (docs/KERNELS.md). This file
 * holds what SSE2 does its own way; the strips are simd_strip_tpl.h's. SSE2 lacks a floor, a
 * 32-bit multiply, a signed max and masked loads and stores: floor is truncation corrected by a
 * compare, the multiply is two pmuludq, partial vectors go through a copy, and pixels are
 * stored lane by lane, a column span per painting lane (SIMD_ROW_STORES 0), which beat storing
 * row by row through a bit loop. */
#include <emmintrin.h>

#include "kernels.h"
#include "simd_common.h"

#define SIMD_ISA sse2
#define SIMD_LANES 4
#define SIMD_ROW_STORES 0

#define simd_f32 __m128
#define simd_i32 __m128i
#define simd_mask __m128i

#define SSE2_M(m) _mm_castsi128_ps(m)  /* a mask where float bits are wanted */
#define SSE2_FM(m) _mm_castps_si128(m) /* a float compare as a mask */

#define v_set1_f(x) _mm_set1_ps(x)
#define v_set1_i(x) _mm_set1_epi32(x)
#define v_zero_f() _mm_setzero_ps()
#define v_zero_i() _mm_setzero_si128()
#define v_iota_f() _mm_setr_ps(0, 1, 2, 3)
#define v_add_f(a, b) _mm_add_ps(a, b)
#define v_sub_f(a, b) _mm_sub_ps(a, b)
#define v_mul_f(a, b) _mm_mul_ps(a, b)
#define v_div_f(a, b) _mm_div_ps(a, b)
#define v_min_f(a, b) _mm_min_ps(a, b)
#define v_max_f(a, b) _mm_max_ps(a, b)
#define v_floor_f(q) _mm_cvtepi32_ps(SIMD_NAME(floor_epi32)(q))
#define v_trunc_f(q) _mm_cvtepi32_ps(_mm_cvttps_epi32(q)) /* |q| < 2^23 where it is used */
#define v_floor_i(q) SIMD_NAME(floor_epi32)(q)
#define v_cvtt_i(q) _mm_cvttps_epi32(q)
#define v_cvt_f(i) _mm_cvtepi32_ps(i)
#define v_add_i(a, b) _mm_add_epi32(a, b)
#define v_sub_i(a, b) _mm_sub_epi32(a, b)
#define v_mullo_i(a, b) SIMD_NAME(mullo_epi32)(a, b)
#define v_and_i(a, b) _mm_and_si128(a, b)
#define v_or_i(a, b) _mm_or_si128(a, b)
#define v_min_i(a, b) SIMD_NAME(min_epi32)(a, b)
#define v_max_i(a, b) SIMD_NAME(max_epi32)(a, b)
#define v_srli_i(a, n) _mm_srli_epi32(a, n)
#define v_byte_i(a, b) _mm_and_si128(_mm_srli_epi32(a, 8 * (b)), _mm_set1_epi32(0xff))
#define v_srl_i(a, n) _mm_srl_epi32(a, _mm_cvtsi32_si128(n))
#define v_slli_i(a, n) _mm_slli_epi32(a, n)
#define v_flt(a, b) SSE2_FM(_mm_cmplt_ps(a, b))
#define v_fle(a, b) SSE2_FM(_mm_cmple_ps(a, b))
#define v_fgt(a, b) SSE2_FM(_mm_cmpgt_ps(a, b))
#define v_fge(a, b) SSE2_FM(_mm_cmpge_ps(a, b))
#define v_igt(a, b) _mm_cmpgt_epi32(a, b)
#define v_mand(a, b) _mm_and_si128(a, b)
#define v_mandnot(a, b) _mm_andnot_si128(a, b)
#define v_add_where(m, a, b) _mm_add_ps(a, _mm_and_ps(SSE2_M(m), b))
#define v_sub_where(m, a, b) _mm_sub_ps(a, _mm_and_ps(SSE2_M(m), b))
#define v_keep_f(m, a) _mm_and_ps(SSE2_M(m), a)
#define v_keep_i(m, a) _mm_and_si128(m, a)
#define v_select_i(m, a, b) _mm_or_si128(_mm_and_si128(m, a), _mm_andnot_si128(m, b))
#define v_bits(m) ((unsigned)_mm_movemask_ps(SSE2_M(m)))
#define v_first(n) _mm_cmpgt_epi32(_mm_set1_epi32(n), _mm_setr_epi32(0, 1, 2, 3))
#define v_load_first_f(p, n, m) ((void)(m), SIMD_NAME(load_first)(p, n))
#define v_store_first_f(p, n, m, x) ((void)(m), SIMD_NAME(store_first)(p, n, x))
#define v_store_i(p, a) _mm_storeu_si128((__m128i *)(p), a)
#define v_gather_cells(c, idx) SIMD_NAME(gather_cells)(c, idx)
#define v_gather_bytes(h, idx) SIMD_NAME(gather_bytes)(h, idx)
#define v_gather_bytes_pad(h, idx) SIMD_NAME(gather_bytes)(h, idx)
#define v_gather_colours(c, at, m) ((void)(m), SIMD_NAME(gather_cells)(c, at)) /* every lane */
#define v_sub_f64(a, h) SIMD_NAME(sub_f64)(a, h)
#define v_last_i(a) _mm_cvtsi128_si32(_mm_shuffle_epi32(a, _MM_SHUFFLE(3, 3, 3, 3)))
#define V_SHIFT_UP(p, fill, k)                                                                                   \
    _mm_or_si128(_mm_slli_si128(p, 4 * (k)),                                                            \
                 _mm_and_si128(fill, _mm_setr_epi32(-(0 < (k)), -(1 < (k)), -(2 < (k)), 0)))

/* floor(q) for |q| < 2^31: truncation, minus one where it rounded a negative q up. */
RETRO_SIMD_INLINE __m128i SIMD_NAME(floor_epi32)(__m128 q)
{
    __m128i t = _mm_cvttps_epi32(q);
    return _mm_add_epi32(t, _mm_castps_si128(_mm_cmpgt_ps(_mm_cvtepi32_ps(t), q)));
}

RETRO_SIMD_INLINE __m128i SIMD_NAME(mullo_epi32)(__m128i a, __m128i b)
{
    __m128i even = _mm_mul_epu32(a, b);
    __m128i odd = _mm_mul_epu32(_mm_srli_epi64(a, 32), _mm_srli_epi64(b, 32));
    return _mm_unpacklo_epi32(_mm_shuffle_epi32(even, _MM_SHUFFLE(0, 0, 2, 0)),
                              _mm_shuffle_epi32(odd, _MM_SHUFFLE(0, 0, 2, 0)));
}

RETRO_SIMD_INLINE __m128i SIMD_NAME(max_epi32)(__m128i a, __m128i b)
{
    __m128i gt = _mm_cmpgt_epi32(a, b);
    return _mm_or_si128(_mm_and_si128(gt, a), _mm_andnot_si128(gt, b));
}

RETRO_SIMD_INLINE __m128i SIMD_NAME(min_epi32)(__m128i a, __m128i b)
{
    __m128i gt = _mm_cmpgt_epi32(a, b);
    return _mm_or_si128(_mm_and_si128(gt, b), _mm_andnot_si128(gt, a));
}

/* The first n floats at p (all 4 when n >= 4), zeros after them. */
RETRO_SIMD_INLINE __m128 SIMD_NAME(load_first)(const float *p, int n)
{
    if (n >= SIMD_LANES)
        return _mm_loadu_ps(p);
    float t[SIMD_LANES] = {0};
    for (int l = 0; l < n; l++)
        t[l] = p[l];
    return _mm_loadu_ps(t);
}

static inline void SIMD_NAME(store_first)(float *p, int n, __m128 x)
{
    if (n >= SIMD_LANES) {
        _mm_storeu_ps(p, x);
        return;
    }
    float t[SIMD_LANES];
    _mm_storeu_ps(t, x);
    for (int l = 0; l < n; l++)
        p[l] = t[l];
}

RETRO_SIMD_INLINE __m128i SIMD_NAME(gather_cells)(const uint32_t *c, __m128i idx)
{
    uint32_t x[SIMD_LANES] __attribute__((aligned(16)));
    _mm_store_si128((__m128i *)x, idx);
    return _mm_setr_epi32((int)c[x[0]], (int)c[x[1]], (int)c[x[2]], (int)c[x[3]]);
}

RETRO_SIMD_INLINE __m128i SIMD_NAME(gather_bytes)(const uint8_t *h, __m128i idx)
{
    uint32_t x[SIMD_LANES] __attribute__((aligned(16)));
    _mm_store_si128((__m128i *)x, idx);
    return _mm_setr_epi32(h[x[0]], h[x[1]], h[x[2]], h[x[3]]);
}

/* (float)((double)a - h) per lane, in two halves of 2 doubles. */
RETRO_SIMD_INLINE __m128 SIMD_NAME(sub_f64)(__m128 a, double h)
{
    const __m128d hd = _mm_set1_pd(h);
    __m128 lo = _mm_cvtpd_ps(_mm_sub_pd(_mm_cvtps_pd(a), hd));
    __m128 hi = _mm_cvtpd_ps(_mm_sub_pd(_mm_cvtps_pd(_mm_movehl_ps(a, a)), hd));
    return _mm_movelh_ps(lo, hi);
}

#include "simd_strip_tpl.h"

#undef SSE2_M
#undef SSE2_FM
