/* simd-avx512: the voxel y-buffer kernel on 16 lanes (docs/KERNELS.md). This file holds what
 * AVX-512 does its own way; the strips are simd_strip_tpl.h's. Mask registers carry the lane
 * masks, floor and truncation are rounding-mode conversions, and map cells are fetched with
 * vpgatherdd, which beat 16 scalar loads inside this kernel on Zen 5 (docs/KERNELS.md). */
#include <immintrin.h>

#include "kernels.h"
#include "simd_common.h"

#define SIMD_ISA avx512
#define SIMD_LANES 16
#define SIMD_ROW_STORES 1

#define simd_f32 __m512
#define simd_i32 __m512i
#define simd_mask __mmask16

#define AVX512_FLOOR (_MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)
#define AVX512_TRUNC (_MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC)

#define v_set1_f(x) _mm512_set1_ps(x)
#define v_set1_i(x) _mm512_set1_epi32(x)
#define v_zero_f() _mm512_setzero_ps()
#define v_zero_i() _mm512_setzero_si512()
#define v_iota_f() _mm512_setr_ps(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15)
#define v_add_f(a, b) _mm512_add_ps(a, b)
#define v_sub_f(a, b) _mm512_sub_ps(a, b)
#define v_mul_f(a, b) _mm512_mul_ps(a, b)
#define v_div_f(a, b) _mm512_div_ps(a, b)
#define v_min_f(a, b) _mm512_min_ps(a, b)
#define v_max_f(a, b) _mm512_max_ps(a, b)
#define v_floor_f(q) _mm512_roundscale_ps(q, AVX512_FLOOR)
#define v_trunc_f(q) _mm512_roundscale_ps(q, AVX512_TRUNC)
#define v_floor_i(q) _mm512_cvt_roundps_epi32(q, AVX512_FLOOR)
#define v_cvtt_i(q) _mm512_cvttps_epi32(q)
#define v_cvt_f(i) _mm512_cvtepi32_ps(i)
#define v_add_i(a, b) _mm512_add_epi32(a, b)
#define v_sub_i(a, b) _mm512_sub_epi32(a, b)
#define v_mullo_i(a, b) _mm512_mullo_epi32(a, b)
#define v_and_i(a, b) _mm512_and_si512(a, b)
#define v_or_i(a, b) _mm512_or_si512(a, b)
#define v_min_i(a, b) _mm512_min_epi32(a, b)
#define v_max_i(a, b) _mm512_max_epi32(a, b)
#define v_srli_i(a, n) _mm512_srli_epi32(a, n)
#define v_byte_i(a, b) _mm512_shuffle_epi8(a, SIMD_NAME(byte_ctrl)(b))
#define v_srl_i(a, n) _mm512_srl_epi32(a, _mm_cvtsi32_si128(n))
#define v_slli_i(a, n) _mm512_slli_epi32(a, n)
#define v_flt(a, b) _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ)
#define v_fle(a, b) _mm512_cmp_ps_mask(a, b, _CMP_LE_OQ)
#define v_fgt(a, b) _mm512_cmp_ps_mask(a, b, _CMP_GT_OQ)
#define v_fge(a, b) _mm512_cmp_ps_mask(a, b, _CMP_GE_OQ)
#define v_igt(a, b) _mm512_cmpgt_epi32_mask(a, b)
#define v_mand(a, b) ((__mmask16)((a) & (b)))
#define v_mandnot(a, b) ((__mmask16)(~(a) & (b)))
#define v_add_where(m, a, b) _mm512_mask_add_ps(a, m, a, b)
#define v_sub_where(m, a, b) _mm512_mask_sub_ps(a, m, a, b)
#define v_keep_f(m, a) _mm512_maskz_mov_ps(m, a)
#define v_keep_i(m, a) _mm512_maskz_mov_epi32(m, a)
#define v_select_i(m, a, b) _mm512_mask_mov_epi32(b, m, a)
#define v_bits(m) ((unsigned)(m))
#define v_first(n) SIMD_NAME(first)(n)
#define v_load_first_f(p, n, m) _mm512_maskz_loadu_ps(m, p)
#define v_store_first_f(p, n, m, x) _mm512_mask_storeu_ps(p, m, x)
#define v_store_i(p, a) _mm512_storeu_si512(p, a)
#define v_gather_cells(c, idx) SIMD_NAME(gather_words)(c, idx)
#define v_gather_bytes(h, idx) SIMD_NAME(gather_bytes)(h, idx)
#define v_gather_bytes_pad(h, idx) _mm512_and_si512(SIMD_NAME(gather_at_bytes)(h, idx), _mm512_set1_epi32(0xff))
#define v_sub_f64(a, h) SIMD_NAME(sub_f64)(a, h)
#define v_last_i(a) _mm_cvtsi128_si32(_mm512_castsi512_si128(_mm512_alignr_epi32(a, a, 15)))
#define V_SHIFT_UP(p, fill, k) _mm512_alignr_epi32(p, fill, 16 - (k))
#define v_gather_colours(c, at, m) _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), m, at, (const void *)(c), 4)
#define v_rows(r, y, top) _mm512_mask_cmpge_epi32_mask(_mm512_cmplt_epi32_mask(y, r), top, r)
#define v_maskstore(p, m, a) _mm512_mask_storeu_epi32(p, m, a)
#define v_compress_store(p, m, a) _mm512_storeu_si512(p, _mm512_maskz_compress_epi32(m, a))
#define v_min_where(m, a) _mm512_mask_reduce_min_epi32(m, a)
#define v_max_where(m, a) _mm512_mask_reduce_max_epi32(m, a)
#define v_set1_16(x) _mm512_set1_epi16(x)
#define v_mullo_16(a, b) _mm512_mullo_epi16(a, b)
#define v_add_16(a, b) _mm512_add_epi16(a, b)
#define v_srli_16(a, n) _mm512_srli_epi16(a, n)

/* vpshufb's control that moves byte b of every 32-bit lane to its lowest byte and clears the
 * others: it indexes bytes within each 128-bit lane, so word w of a lane takes byte 4w + b. */
RETRO_SIMD_INLINE __m512i SIMD_NAME(byte_ctrl)(int b)
{
    const int z = (int)0x80808000u;
    return _mm512_set4_epi32(z | (12 + b), z | (8 + b), z | (4 + b), z | b);
}

RETRO_SIMD_INLINE __mmask16 SIMD_NAME(first)(int n)
{
    return (__mmask16)(n < SIMD_LANES ? (1u << (n > 0 ? n : 0)) - 1 : 0xffffu);
}

/* vpgatherdd merges into its destination, so the CPU waits for that register's last value even
 * when every lane is fetched. For an unmasked gather gcc picks any register as the destination,
 * often the one holding the previous step's (masked) cells, which chains a walk's gathers one
 * after another through their results. A mask the compiler cannot prove full keeps the zero
 * source it would otherwise drop, and a zero has no producer to wait for. */
RETRO_SIMD_INLINE __mmask16 SIMD_NAME(every_lane)(void)
{
    __mmask16 m;
    __asm__("kxnorw %0, %0, %0" : "=k"(m));
    return m;
}

RETRO_SIMD_INLINE __m512i SIMD_NAME(gather_words)(const uint32_t *c, __m512i idx)
{
    return _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), SIMD_NAME(every_lane)(), idx, (const void *)c, 4);
}

/* The 4 bytes at each byte offset, of which the caller keeps the low one. */
RETRO_SIMD_INLINE __m512i SIMD_NAME(gather_at_bytes)(const uint8_t *h, __m512i idx)
{
    return _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), SIMD_NAME(every_lane)(), idx, (const void *)h, 1);
}

/* Bytes are not gathered: 16 scalar loads. */
RETRO_SIMD_INLINE __m512i SIMD_NAME(gather_bytes)(const uint8_t *h, __m512i idx)
{
    uint32_t x[SIMD_LANES] __attribute__((aligned(64)));
    _mm512_store_si512(x, idx);
    return _mm512_setr_epi32(h[x[0]], h[x[1]], h[x[2]], h[x[3]], h[x[4]], h[x[5]], h[x[6]], h[x[7]], h[x[8]],
                             h[x[9]], h[x[10]], h[x[11]], h[x[12]], h[x[13]], h[x[14]], h[x[15]]);
}

/* (float)((double)a - h) per lane, in two halves of 8 doubles. */
RETRO_SIMD_INLINE __m512 SIMD_NAME(sub_f64)(__m512 a, double h)
{
    const __m512d hd = _mm512_set1_pd(h);
    __m256 lo = _mm512_cvtpd_ps(_mm512_sub_pd(_mm512_cvtps_pd(_mm512_castps512_ps256(a)), hd));
    __m256 hi = _mm512_cvtpd_ps(_mm512_sub_pd(_mm512_cvtps_pd(_mm512_extractf32x8_ps(a, 1)), hd));
    return _mm512_insertf32x8(_mm512_castps256_ps512(lo), hi, 1);
}

/* Mode course's tile (simd_course_tpl.h, course_group) into out 16 rows of 16 columns at a
 * time: the columns' rows r..r+15 load as 16 vectors, a 16x16 transpose of 32-bit words (4 rounds of
 * 16 shuffles) turns them into 16 rows of 16 adjacent pixels, and each row is one store, where
 * copying pixel by pixel costs a load and a store each. Row r of the tile goes to out + at,
 * row r + k to out + at - k*W. */
#define SIMD_TILE_BLOCK 1
RETRO_SIMD_INLINE void SIMD_NAME(tile_block)(uint32_t *out, ptrdiff_t at, ptrdiff_t W, const uint32_t *tile,
                                             size_t th)
{
    __m512i a[16], t[16];
    for (int c = 0; c < 16; c++)
        a[c] = _mm512_loadu_si512(tile + (size_t)c * th);
    /* word pairs, then quads: in 128-bit lane L, t[4k + m] holds row 4L + m of columns 4k..4k+3 */
    for (int k = 0; k < 8; k++) {
        t[2 * k] = _mm512_unpacklo_epi32(a[2 * k], a[2 * k + 1]);
        t[2 * k + 1] = _mm512_unpackhi_epi32(a[2 * k], a[2 * k + 1]);
    }
    for (int k = 0; k < 4; k++) {
        a[4 * k] = _mm512_unpacklo_epi64(t[4 * k], t[4 * k + 2]);
        a[4 * k + 1] = _mm512_unpackhi_epi64(t[4 * k], t[4 * k + 2]);
        a[4 * k + 2] = _mm512_unpacklo_epi64(t[4 * k + 1], t[4 * k + 3]);
        a[4 * k + 3] = _mm512_unpackhi_epi64(t[4 * k + 1], t[4 * k + 3]);
    }
    /* a 4x4 transpose of 128-bit lanes for each m: row 4L + m = lane L of a[m], a[4 + m], .. */
    for (int m = 0; m < 4; m++) {
        const __m512i v0 = _mm512_shuffle_i32x4(a[m], a[4 + m], 0x44), v1 = _mm512_shuffle_i32x4(a[m], a[4 + m], 0xee);
        const __m512i v2 = _mm512_shuffle_i32x4(a[8 + m], a[12 + m], 0x44);
        const __m512i v3 = _mm512_shuffle_i32x4(a[8 + m], a[12 + m], 0xee);
        t[m] = _mm512_shuffle_i32x4(v0, v2, 0x88);
        t[4 + m] = _mm512_shuffle_i32x4(v0, v2, 0xdd);
        t[8 + m] = _mm512_shuffle_i32x4(v1, v3, 0x88);
        t[12 + m] = _mm512_shuffle_i32x4(v1, v3, 0xdd);
    }
    for (int r = 0; r < 16; r++) {
        _mm512_storeu_si512(out + at - (ptrdiff_t)r * W, t[r]);
        RETRO_SIMD_COUNT(out, (size_t)(at - (ptrdiff_t)r * W), 0xffffu);
    }
}

#include "simd_strip_tpl.h"

#undef AVX512_FLOOR
#undef AVX512_TRUNC
