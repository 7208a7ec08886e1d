/* The vector operations of the fast mesh block stage (fast_tmpl.h) on AVX-512 (F, DQ): 16
 * binary32 or int32 lanes; comparisons return one bit per lane. */
#ifndef RETRO_MESH_VEC_AVX512_H
#define RETRO_MESH_VEC_AVX512_H

#include <immintrin.h>
#include <stdint.h>

#define VN 16
typedef __m512 vf;
typedef __m512i vi;

static inline vf vf_load(const float *p) { return _mm512_loadu_ps(p); }
static inline void vf_store(float *p, vf a) { _mm512_storeu_ps(p, a); }
static inline vf vf_set1(float a) { return _mm512_set1_ps(a); }
static inline vf vf_add(vf a, vf b) { return _mm512_add_ps(a, b); }
static inline vf vf_sub(vf a, vf b) { return _mm512_sub_ps(a, b); }
static inline vf vf_mul(vf a, vf b) { return _mm512_mul_ps(a, b); }
static inline vf vf_div(vf a, vf b) { return _mm512_div_ps(a, b); }
static inline vf vf_floor(vf a) { return _mm512_roundscale_ps(a, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC); }
static inline vf vf_clamp(vf a, float lo, float hi)
{
    return _mm512_min_ps(_mm512_max_ps(a, _mm512_set1_ps(lo)), _mm512_set1_ps(hi));
}
static inline unsigned vf_lt(vf a, vf b) { return (unsigned)_mm512_cmp_ps_mask(a, b, _CMP_LT_OQ); }
static inline unsigned vf_gt(vf a, vf b) { return (unsigned)_mm512_cmp_ps_mask(a, b, _CMP_GT_OQ); }

static inline vi vi_load(const int32_t *p) { return _mm512_loadu_si512((const void *)p); }
static inline void vi_store(int32_t *p, vi a) { _mm512_storeu_si512((void *)p, a); }
static inline vi vi_set1(int32_t a) { return _mm512_set1_epi32(a); }
static inline vi vi_add(vi a, vi b) { return _mm512_add_epi32(a, b); }
static inline vi vi_sub(vi a, vi b) { return _mm512_sub_epi32(a, b); }
static inline vi vi_or(vi a, vi b) { return _mm512_or_si512(a, b); }
static inline vi vi_and(vi a, vi b) { return _mm512_and_si512(a, b); }
static inline vi vi_min(vi a, vi b) { return _mm512_min_epi32(a, b); }
static inline vi vi_max(vi a, vi b) { return _mm512_max_epi32(a, b); }
static inline vi vi_sra8(vi a) { return _mm512_srai_epi32(a, 8); }
static inline vi vi_sll8(vi a) { return _mm512_slli_epi32(a, 8); }
static inline vi vf_to_vi(vf a) { return _mm512_cvttps_epi32(a); } /* a integral, |a| < 2^31 */
static inline unsigned vi_gt(vi a, vi b) { return (unsigned)_mm512_cmpgt_epi32_mask(a, b); }
static inline unsigned vi_eq(vi a, vi b) { return (unsigned)_mm512_cmpeq_epi32_mask(a, b); }
static inline vi vi_bit_if_lt(vi acc, vf a, vf b, int32_t bit)
{
    return _mm512_mask_or_epi32(acc, _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ), acc, _mm512_set1_epi32(bit));
}
/* The sign of a*b - c*d, exact in binary64 (|a|, |b|, |c|, |d| < 2^24). */
static inline unsigned vi_cross(vi a, vi b, vi c, vi d, unsigned *zero)
{
    unsigned pos = 0, z = 0;
    for (int h = 0; h < 2; h++) {
        __m256i a8 = h ? _mm512_extracti64x4_epi64(a, 1) : _mm512_castsi512_si256(a);
        __m256i b8 = h ? _mm512_extracti64x4_epi64(b, 1) : _mm512_castsi512_si256(b);
        __m256i c8 = h ? _mm512_extracti64x4_epi64(c, 1) : _mm512_castsi512_si256(c);
        __m256i d8 = h ? _mm512_extracti64x4_epi64(d, 1) : _mm512_castsi512_si256(d);
        __m512d r = _mm512_sub_pd(_mm512_mul_pd(_mm512_cvtepi32_pd(a8), _mm512_cvtepi32_pd(b8)),
                                  _mm512_mul_pd(_mm512_cvtepi32_pd(c8), _mm512_cvtepi32_pd(d8)));
        pos |= (unsigned)_mm512_cmp_pd_mask(r, _mm512_setzero_pd(), _CMP_GT_OQ) << (8 * h);
        z |= (unsigned)_mm512_cmp_pd_mask(r, _mm512_setzero_pd(), _CMP_EQ_OQ) << (8 * h);
    }
    *zero = z;
    return pos;
}

/* Binary64 halves of an int32 vector (VH lanes each): exact edge functions of the tiny
 * triangles (fast_tiny.h), whose products reach 2^46. */
#define VH 8
typedef __m512d vd;
static inline vd vd_half(vi a, int h)
{
    return _mm512_cvtepi32_pd(h ? _mm512_extracti64x4_epi64(a, 1) : _mm512_castsi512_si256(a));
}
static inline vd vd_add(vd a, vd b) { return _mm512_add_pd(a, b); }
static inline vd vd_sub(vd a, vd b) { return _mm512_sub_pd(a, b); }
static inline vd vd_mul(vd a, vd b) { return _mm512_mul_pd(a, b); }
static inline vd vd_set1(double a) { return _mm512_set1_pd(a); }
static inline unsigned vd_gt0(vd a) { return (unsigned)_mm512_cmp_pd_mask(a, _mm512_setzero_pd(), _CMP_GT_OQ); }
static inline unsigned vd_eq0(vd a) { return (unsigned)_mm512_cmp_pd_mask(a, _mm512_setzero_pd(), _CMP_EQ_OQ); }
/* each lane rounded once to binary32 (round to nearest, as a C conversion) */
static inline vf vf_from_vd(vd lo, vd hi)
{
    return _mm512_insertf32x8(_mm512_castps256_ps512(_mm512_cvtpd_ps(lo)), _mm512_cvtpd_ps(hi), 1);
}
static inline unsigned vf_ge(vf a, vf b) { return (unsigned)_mm512_cmp_ps_mask(a, b, _CMP_GE_OQ); }

#endif
