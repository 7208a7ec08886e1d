/* The vector operations of the fast mesh block stage (fast_tmpl.h) on AVX2: 8 binary32 or
 * int32 lanes; comparisons return one bit per lane. */
#ifndef RETRO_MESH_VEC_AVX2_H
#define RETRO_MESH_VEC_AVX2_H

#include <immintrin.h>
#include <stdint.h>

#define VN 8
typedef __m256 vf;
typedef __m256i vi;

static inline vf vf_load(const float *p) { return _mm256_loadu_ps(p); }
static inline void vf_store(float *p, vf a) { _mm256_storeu_ps(p, a); }
static inline vf vf_set1(float a) { return _mm256_set1_ps(a); }
static inline vf vf_add(vf a, vf b) { return _mm256_add_ps(a, b); }
static inline vf vf_sub(vf a, vf b) { return _mm256_sub_ps(a, b); }
static inline vf vf_mul(vf a, vf b) { return _mm256_mul_ps(a, b); }
static inline vf vf_div(vf a, vf b) { return _mm256_div_ps(a, b); }
static inline vf vf_floor(vf a) { return _mm256_floor_ps(a); }
static inline vf vf_clamp(vf a, float lo, float hi)
{
    return _mm256_min_ps(_mm256_max_ps(a, _mm256_set1_ps(lo)), _mm256_set1_ps(hi));
}
static inline unsigned vf_lt(vf a, vf b) { return (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(a, b, _CMP_LT_OQ)); }
static inline unsigned vf_gt(vf a, vf b) { return (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(a, b, _CMP_GT_OQ)); }

static inline vi vi_load(const int32_t *p) { return _mm256_loadu_si256((const __m256i *)(const void *)p); }
static inline void vi_store(int32_t *p, vi a) { _mm256_storeu_si256((__m256i *)(void *)p, a); }
static inline vi vi_set1(int32_t a) { return _mm256_set1_epi32(a); }
static inline vi vi_add(vi a, vi b) { return _mm256_add_epi32(a, b); }
static inline vi vi_sub(vi a, vi b) { return _mm256_sub_epi32(a, b); }
static inline vi vi_or(vi a, vi b) { return _mm256_or_si256(a, b); }
static inline vi vi_and(vi a, vi b) { return _mm256_and_si256(a, b); }
static inline vi vi_min(vi a, vi b) { return _mm256_min_epi32(a, b); }
static inline vi vi_max(vi a, vi b) { return _mm256_max_epi32(a, b); }
static inline vi vi_sra8(vi a) { return _mm256_srai_epi32(a, 8); }
static inline vi vi_sll8(vi a) { return _mm256_slli_epi32(a, 8); }
static inline vi vf_to_vi(vf a) { return _mm256_cvttps_epi32(a); } /* a integral, |a| < 2^31 */
static inline unsigned vi_gt(vi a, vi b) { return (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpgt_epi32(a, b))); }
static inline unsigned vi_eq(vi a, vi b) { return (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(a, b))); }
/* acc with bit set in the lanes where a < b */
static inline vi vi_bit_if_lt(vi acc, vf a, vf b, int32_t bit)
{
    vi m = _mm256_castps_si256(_mm256_cmp_ps(a, b, _CMP_LT_OQ));
    return _mm256_or_si256(acc, _mm256_and_si256(m, _mm256_set1_epi32(bit)));
}
/* The sign of a*b - c*d, exact (|a|, |b|, |c|, |d| < 2^24: products and difference are exact in
 * binary64): bits of the lanes where it is > 0, and in *zero where it is 0. */
static inline unsigned vi_cross(vi a, vi b, vi c, vi d, unsigned *zero)
{
    unsigned pos = 0, z = 0;
    for (int h = 0; h < 2; h++) {
        __m128i a4 = h ? _mm256_extracti128_si256(a, 1) : _mm256_castsi256_si128(a);
        __m128i b4 = h ? _mm256_extracti128_si256(b, 1) : _mm256_castsi256_si128(b);
        __m128i c4 = h ? _mm256_extracti128_si256(c, 1) : _mm256_castsi256_si128(c);
        __m128i d4 = h ? _mm256_extracti128_si256(d, 1) : _mm256_castsi256_si128(d);
        __m256d r = _mm256_sub_pd(_mm256_mul_pd(_mm256_cvtepi32_pd(a4), _mm256_cvtepi32_pd(b4)),
                                  _mm256_mul_pd(_mm256_cvtepi32_pd(c4), _mm256_cvtepi32_pd(d4)));
        pos |= (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(r, _mm256_setzero_pd(), _CMP_GT_OQ)) << (4 * h);
        z |= (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(r, _mm256_setzero_pd(), _CMP_EQ_OQ)) << (4 * h);
    }
    *zero = z;
    return pos;
}

/* Binary64 halves of an int32 vector (VH lanes each): exact edge functions of the tiny
 * triangles (fast_tiny.h), whose products reach 2^46. */
#define VH 4
typedef __m256d vd;
static inline vd vd_half(vi a, int h)
{
    return _mm256_cvtepi32_pd(h ? _mm256_extracti128_si256(a, 1) : _mm256_castsi256_si128(a));
}
static inline vd vd_add(vd a, vd b) { return _mm256_add_pd(a, b); }
static inline vd vd_sub(vd a, vd b) { return _mm256_sub_pd(a, b); }
static inline vd vd_mul(vd a, vd b) { return _mm256_mul_pd(a, b); }
static inline vd vd_set1(double a) { return _mm256_set1_pd(a); }
static inline unsigned vd_gt0(vd a) { return (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(a, _mm256_setzero_pd(), _CMP_GT_OQ)); }
static inline unsigned vd_eq0(vd a) { return (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(a, _mm256_setzero_pd(), _CMP_EQ_OQ)); }
/* each lane rounded once to binary32 (round to nearest, as a C conversion) */
static inline vf vf_from_vd(vd lo, vd hi) { return _mm256_set_m128(_mm256_cvtpd_ps(hi), _mm256_cvtpd_ps(lo)); }
static inline unsigned vf_ge(vf a, vf b) { return (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(a, b, _CMP_GE_OQ)); }

#endif
