/* simd-avx2: the voxel y-buffer kernel on 8 lanes (docs/KERNELS.md). This file holds what AVX2
 * does its own way; the strips are simd_strip_tpl.h's. AVX2 has no mask registers, no
 * rounding-mode conversion and no masked reductions: masks are vectors (a fix that does not
 * apply adds +0, leaving a value unchanged), floor is vroundps, and the rows a step paints are
 * found by shuffles. Map cells are read with 8 scalar loads, which tie with vpgatherdd ymm on
 * Zen 5 (docs/KERNELS.md). */
#include <immintrin.h>
#include <limits.h>

#include "kernels.h"
#include "simd_common.h"

/* v_compress_store's lane order for each 8-bit lane mask m: nibble k (from the low end) is
 * the lane of m's k-th set bit, counted from lane 0; nibbles past popcount(m) are 0. AVX2 has
 * no compress instruction, so the set lanes are moved down with one vpermd. */
static const uint32_t avx2_compress_lut[256] = {
    0x00000000, 0x00000000, 0x00000001, 0x00000010, 0x00000002, 0x00000020, 0x00000021, 0x00000210,
    0x00000003, 0x00000030, 0x00000031, 0x00000310, 0x00000032, 0x00000320, 0x00000321, 0x00003210,
    0x00000004, 0x00000040, 0x00000041, 0x00000410, 0x00000042, 0x00000420, 0x00000421, 0x00004210,
    0x00000043, 0x00000430, 0x00000431, 0x00004310, 0x00000432, 0x00004320, 0x00004321, 0x00043210,
    0x00000005, 0x00000050, 0x00000051, 0x00000510, 0x00000052, 0x00000520, 0x00000521, 0x00005210,
    0x00000053, 0x00000530, 0x00000531, 0x00005310, 0x00000532, 0x00005320, 0x00005321, 0x00053210,
    0x00000054, 0x00000540, 0x00000541, 0x00005410, 0x00000542, 0x00005420, 0x00005421, 0x00054210,
    0x00000543, 0x00005430, 0x00005431, 0x00054310, 0x00005432, 0x00054320, 0x00054321, 0x00543210,
    0x00000006, 0x00000060, 0x00000061, 0x00000610, 0x00000062, 0x00000620, 0x00000621, 0x00006210,
    0x00000063, 0x00000630, 0x00000631, 0x00006310, 0x00000632, 0x00006320, 0x00006321, 0x00063210,
    0x00000064, 0x00000640, 0x00000641, 0x00006410, 0x00000642, 0x00006420, 0x00006421, 0x00064210,
    0x00000643, 0x00006430, 0x00006431, 0x00064310, 0x00006432, 0x00064320, 0x00064321, 0x00643210,
    0x00000065, 0x00000650, 0x00000651, 0x00006510, 0x00000652, 0x00006520, 0x00006521, 0x00065210,
    0x00000653, 0x00006530, 0x00006531, 0x00065310, 0x00006532, 0x00065320, 0x00065321, 0x00653210,
    0x00000654, 0x00006540, 0x00006541, 0x00065410, 0x00006542, 0x00065420, 0x00065421, 0x00654210,
    0x00006543, 0x00065430, 0x00065431, 0x00654310, 0x00065432, 0x00654320, 0x00654321, 0x06543210,
    0x00000007, 0x00000070, 0x00000071, 0x00000710, 0x00000072, 0x00000720, 0x00000721, 0x00007210,
    0x00000073, 0x00000730, 0x00000731, 0x00007310, 0x00000732, 0x00007320, 0x00007321, 0x00073210,
    0x00000074, 0x00000740, 0x00000741, 0x00007410, 0x00000742, 0x00007420, 0x00007421, 0x00074210,
    0x00000743, 0x00007430, 0x00007431, 0x00074310, 0x00007432, 0x00074320, 0x00074321, 0x00743210,
    0x00000075, 0x00000750, 0x00000751, 0x00007510, 0x00000752, 0x00007520, 0x00007521, 0x00075210,
    0x00000753, 0x00007530, 0x00007531, 0x00075310, 0x00007532, 0x00075320, 0x00075321, 0x00753210,
    0x00000754, 0x00007540, 0x00007541, 0x00075410, 0x00007542, 0x00075420, 0x00075421, 0x00754210,
    0x00007543, 0x00075430, 0x00075431, 0x00754310, 0x00075432, 0x00754320, 0x00754321, 0x07543210,
    0x00000076, 0x00000760, 0x00000761, 0x00007610, 0x00000762, 0x00007620, 0x00007621, 0x00076210,
    0x00000763, 0x00007630, 0x00007631, 0x00076310, 0x00007632, 0x00076320, 0x00076321, 0x00763210,
    0x00000764, 0x00007640, 0x00007641, 0x00076410, 0x00007642, 0x00076420, 0x00076421, 0x00764210,
    0x00007643, 0x00076430, 0x00076431, 0x00764310, 0x00076432, 0x00764320, 0x00764321, 0x07643210,
    0x00000765, 0x00007650, 0x00007651, 0x00076510, 0x00007652, 0x00076520, 0x00076521, 0x00765210,
    0x00007653, 0x00076530, 0x00076531, 0x00765310, 0x00076532, 0x00765320, 0x00765321, 0x07653210,
    0x00007654, 0x00076540, 0x00076541, 0x00765410, 0x00076542, 0x00765420, 0x00765421, 0x07654210,
    0x00076543, 0x00765430, 0x00765431, 0x07654310, 0x00765432, 0x07654320, 0x07654321, 0x76543210,
};
#define SIMD_ISA avx2
#define SIMD_LANES 8
#define SIMD_ROW_STORES 1

#define simd_f32 __m256
#define simd_i32 __m256i
#define simd_mask __m256i

#define AVX2_FLOOR (_MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)
#define AVX2_TRUNC (_MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC)
#define AVX2_M(m) _mm256_castsi256_ps(m)  /* a mask where float bits are wanted */
#define AVX2_FM(m) _mm256_castps_si256(m) /* a float compare as a mask */
/* V_SHIFT_UP's lane permutation: lane l takes lane l - k, the first k any (then filled) */
#define AVX2_FROM(l, k) ((l) < (k) ? 0 : (l) - (k))

#define v_set1_f(x) _mm256_set1_ps(x)
#define v_set1_i(x) _mm256_set1_epi32(x)
#define v_zero_f() _mm256_setzero_ps()
#define v_zero_i() _mm256_setzero_si256()
#define v_iota_f() _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7)
#define v_add_f(a, b) _mm256_add_ps(a, b)
#define v_sub_f(a, b) _mm256_sub_ps(a, b)
#define v_mul_f(a, b) _mm256_mul_ps(a, b)
#define v_div_f(a, b) _mm256_div_ps(a, b)
#define v_min_f(a, b) _mm256_min_ps(a, b)
#define v_max_f(a, b) _mm256_max_ps(a, b)
#define v_floor_f(q) _mm256_round_ps(q, AVX2_FLOOR)
#define v_trunc_f(q) _mm256_round_ps(q, AVX2_TRUNC)
#define v_floor_i(q) _mm256_cvttps_epi32(_mm256_round_ps(q, AVX2_FLOOR))
#define v_cvtt_i(q) _mm256_cvttps_epi32(q)
#define v_cvt_f(i) _mm256_cvtepi32_ps(i)
#define v_add_i(a, b) _mm256_add_epi32(a, b)
#define v_sub_i(a, b) _mm256_sub_epi32(a, b)
#define v_mullo_i(a, b) _mm256_mullo_epi32(a, b)
#define v_and_i(a, b) _mm256_and_si256(a, b)
#define v_or_i(a, b) _mm256_or_si256(a, b)
#define v_min_i(a, b) _mm256_min_epi32(a, b)
#define v_max_i(a, b) _mm256_max_epi32(a, b)
#define v_srli_i(a, n) _mm256_srli_epi32(a, n)
#define v_byte_i(a, b) _mm256_shuffle_epi8(a, SIMD_NAME(byte_ctrl)(b))
#define v_srl_i(a, n) _mm256_srl_epi32(a, _mm_cvtsi32_si128(n))
#define v_slli_i(a, n) _mm256_slli_epi32(a, n)
#define v_flt(a, b) AVX2_FM(_mm256_cmp_ps(a, b, _CMP_LT_OQ))
#define v_fle(a, b) AVX2_FM(_mm256_cmp_ps(a, b, _CMP_LE_OQ))
#define v_fgt(a, b) AVX2_FM(_mm256_cmp_ps(a, b, _CMP_GT_OQ))
#define v_fge(a, b) AVX2_FM(_mm256_cmp_ps(a, b, _CMP_GE_OQ))
#define v_igt(a, b) _mm256_cmpgt_epi32(a, b)
#define v_mand(a, b) _mm256_and_si256(a, b)
#define v_mandnot(a, b) _mm256_andnot_si256(a, b)
#define v_add_where(m, a, b) _mm256_add_ps(a, _mm256_and_ps(AVX2_M(m), b))
#define v_sub_where(m, a, b) _mm256_sub_ps(a, _mm256_and_ps(AVX2_M(m), b))
#define v_keep_f(m, a) _mm256_and_ps(AVX2_M(m), a)
#define v_keep_i(m, a) _mm256_and_si256(m, a)
#define v_select_i(m, a, b) _mm256_blendv_epi8(b, a, m)
#define v_bits(m) ((unsigned)_mm256_movemask_ps(AVX2_M(m)))
#define v_first(n) _mm256_cmpgt_epi32(_mm256_set1_epi32(n), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7))
#define v_load_first_f(p, n, m) _mm256_maskload_ps(p, m)
#define v_store_first_f(p, n, m, x) _mm256_maskstore_ps(p, m, x)
#define v_store_i(p, a) _mm256_storeu_si256((__m256i *)(p), a)
#define v_gather_cells(c, idx) SIMD_NAME(gather_cells)(c, idx)
#define v_gather_bytes(h, idx) SIMD_NAME(gather_bytes)(h, idx)
#define v_gather_bytes_pad(h, idx) SIMD_NAME(gather_bytes)(h, idx)
#define v_sub_f64(a, h) SIMD_NAME(sub_f64)(a, h)
#define v_last_i(a) _mm256_extract_epi32(a, 7)
#define V_SHIFT_UP(p, fill, k)                                                                           \
    _mm256_blend_epi32(_mm256_permutevar8x32_epi32(p, _mm256_setr_epi32(AVX2_FROM(0, k), AVX2_FROM(1, k),   \
                                                                        AVX2_FROM(2, k), AVX2_FROM(3, k),   \
                                                                        AVX2_FROM(4, k), AVX2_FROM(5, k),   \
                                                                        AVX2_FROM(6, k), AVX2_FROM(7, k))), \
                       fill, (1 << (k)) - 1)
#define v_gather_colours(c, at, m) ((void)(m), SIMD_NAME(gather_cells)(c, at)) /* every lane */
#define v_rows(r, y, top) _mm256_andnot_si256(_mm256_cmpgt_epi32(r, top), _mm256_cmpgt_epi32(r, y))
#define v_maskstore(p, m, a) _mm256_maskstore_epi32((int *)(p), m, a)
#define v_compress_store(p, m, a) _mm256_storeu_si256((__m256i *)(p), _mm256_permutevar8x32_epi32(a, AVX2_COMPRESS(m)))
#define AVX2_COMPRESS(m)                                                                                        \
    _mm256_and_si256(_mm256_srlv_epi32(_mm256_set1_epi32((int)avx2_compress_lut[v_bits(m)]),                  \
                                       _mm256_setr_epi32(0, 4, 8, 12, 16, 20, 24, 28)),                        \
                     _mm256_set1_epi32(7))
#define v_min_where(m, a) SIMD_NAME(hmin)(_mm256_blendv_epi8(_mm256_set1_epi32(INT_MAX), a, m))
#define v_max_where(m, a) SIMD_NAME(hmax)(_mm256_and_si256(a, m)) /* a >= 0: 0 leaves a lane out */
#define v_set1_16(x) _mm256_set1_epi16(x)
#define v_mullo_16(a, b) _mm256_mullo_epi16(a, b)
#define v_add_16(a, b) _mm256_add_epi16(a, b)
#define v_srli_16(a, n) _mm256_srli_epi16(a, n)

/* vpshufb's control that moves byte b of every 32-bit lane to its lowest byte and clears the
 * others: it indexes bytes within each 128-bit lane, so word w of a lane takes byte 4w + b. */
RETRO_SIMD_INLINE __m256i SIMD_NAME(byte_ctrl)(int b)
{
    const int z = (int)0x80808000u;
    return _mm256_setr_epi32(z | b, z | (4 + b), z | (8 + b), z | (12 + b), z | b, z | (4 + b), z | (8 + b),
                             z | (12 + b));
}

RETRO_SIMD_INLINE int SIMD_NAME(hmin)(__m256i a)
{
    __m128i m = _mm_min_epi32(_mm256_castsi256_si128(a), _mm256_extracti128_si256(a, 1));
    m = _mm_min_epi32(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(1, 0, 3, 2)));
    return _mm_cvtsi128_si32(_mm_min_epi32(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(2, 3, 0, 1))));
}

RETRO_SIMD_INLINE int SIMD_NAME(hmax)(__m256i a)
{
    __m128i m = _mm_max_epi32(_mm256_castsi256_si128(a), _mm256_extracti128_si256(a, 1));
    m = _mm_max_epi32(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(1, 0, 3, 2)));
    return _mm_cvtsi128_si32(_mm_max_epi32(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(2, 3, 0, 1))));
}

/* c[idx] per lane: 8 scalar loads. */
RETRO_SIMD_INLINE __m256i SIMD_NAME(gather_cells)(const uint32_t *c, __m256i idx)
{
    uint32_t x[SIMD_LANES] __attribute__((aligned(32)));
    _mm256_store_si256((__m256i *)x, idx);
    return _mm256_setr_epi32((int)c[x[0]], (int)c[x[1]], (int)c[x[2]], (int)c[x[3]], (int)c[x[4]], (int)c[x[5]],
                             (int)c[x[6]], (int)c[x[7]]);
}

RETRO_SIMD_INLINE __m256i SIMD_NAME(gather_bytes)(const uint8_t *h, __m256i idx)
{
    uint32_t x[SIMD_LANES] __attribute__((aligned(32)));
    _mm256_store_si256((__m256i *)x, idx);
    return _mm256_setr_epi32(h[x[0]], h[x[1]], h[x[2]], h[x[3]], h[x[4]], h[x[5]], h[x[6]], h[x[7]]);
}

/* (float)((double)a - h) per lane, in two halves of 4 doubles. */
RETRO_SIMD_INLINE __m256 SIMD_NAME(sub_f64)(__m256 a, double h)
{
    const __m256d hd = _mm256_set1_pd(h);
    __m128 lo = _mm256_cvtpd_ps(_mm256_sub_pd(_mm256_cvtps_pd(_mm256_castps256_ps128(a)), hd));
    __m128 hi = _mm256_cvtpd_ps(_mm256_sub_pd(_mm256_cvtps_pd(_mm256_extractf128_ps(a, 1)), hd));
    return _mm256_insertf128_ps(_mm256_castps128_ps256(lo), hi, 1);
}

/* Mode course's tile into out 8 rows of 8 columns at a time, as the AVX-512 file's
 * tile_block does with 16: an 8x8 transpose of 32-bit words in registers (word pairs, quads,
 * then 128-bit halves), one store per row of 8 adjacent pixels. Row r of the tile goes to
 * out + at, row r + k to out + at - k*W. */
#define SIMD_TILE_BLOCK 1
RETRO_SIMD_INLINE void SIMD_NAME(tile_block)(uint32_t *out, ptrdiff_t at, ptrdiff_t W, const uint32_t *tile,
                                             size_t th)
{
    __m256i a[8], t[8];
    for (int c = 0; c < 8; c++)
        a[c] = _mm256_loadu_si256((const __m256i *)(tile + (size_t)c * th));
    for (int k = 0; k < 4; k++) {
        t[2 * k] = _mm256_unpacklo_epi32(a[2 * k], a[2 * k + 1]);
        t[2 * k + 1] = _mm256_unpackhi_epi32(a[2 * k], a[2 * k + 1]);
    }
    /* in 128-bit half L, a[4k + m] holds row 4L + m of columns 4k..4k+3 */
    for (int k = 0; k < 2; k++) {
        a[4 * k] = _mm256_unpacklo_epi64(t[4 * k], t[4 * k + 2]);
        a[4 * k + 1] = _mm256_unpackhi_epi64(t[4 * k], t[4 * k + 2]);
        a[4 * k + 2] = _mm256_unpacklo_epi64(t[4 * k + 1], t[4 * k + 3]);
        a[4 * k + 3] = _mm256_unpackhi_epi64(t[4 * k + 1], t[4 * k + 3]);
    }
    for (int m = 0; m < 4; m++) {
        t[m] = _mm256_permute2x128_si256(a[m], a[4 + m], 0x20);
        t[4 + m] = _mm256_permute2x128_si256(a[m], a[4 + m], 0x31);
    }
    for (int r = 0; r < 8; r++) {
        _mm256_storeu_si256((__m256i *)(out + at - (ptrdiff_t)r * W), t[r]);
        RETRO_SIMD_COUNT(out, (size_t)(at - (ptrdiff_t)r * W), 0xffu);
    }
}

#include "simd_strip_tpl.h"

#undef AVX2_FLOOR
#undef AVX2_TRUNC
#undef AVX2_M
#undef AVX2_FM
#undef AVX2_FROM
