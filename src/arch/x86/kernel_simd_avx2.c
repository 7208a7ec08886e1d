/* simd-avx2: the simd-avx512 kernel on 8 lanes; the design note at the top of
 * kernel_simd_avx512.c covers both. AVX2 has no mask registers, no rounding-mode conversion
 * and no masked reductions: masks are vectors (a fix that does not apply adds +0, leaving a
 * value unchanged), floor is vroundps, and the rows a step paints are found by shuffles.
 * Map cells are read with 8 scalar loads, which tie with vpgatherdd ymm on Zen 5 (design note). */
#include <immintrin.h>
#include <limits.h>

#include "kernels.h"
#include "simd_common.h"

enum { LANES = 8 };

#define FLOOR (_MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)
#define TRUNC (_MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC)

/* The frame's constants, broadcast once. */
typedef struct {
    __m256i tiles;     /* tiles per row of the packed map */
    __m256i S;         /* map size, for row-major indices */
    __m256i height;    /* camera height, int32 (retro_simd_check checked the range) */
    __m256i H;         /* H */
    __m256 fH;         /* H */
    /* mode exact */
    __m256 x0, y0;     /* position reduced modulo S */
    __m256 half_h;     /* 0.5f * H */
    __m256 fS, inv_S;  /* S and 1/S, for the float remainder */
    __m256i wrap;      /* S - 1 when S is a power of two */
    /* mode course */
    __m256 fK, inv_K;  /* the wrap period S - 1 and its reciprocal */
    __m256 cw2;        /* (float)(W / 2) */
    __m256i ch2;       /* H / 2 */
} consts;

static void init_consts(consts *k, const retro_frame *f, const retro_simd_frame *sf)
{
    k->tiles = _mm256_set1_epi32(sf->tiles);
    k->S = _mm256_set1_epi32(f->S);
    k->height = _mm256_set1_epi32(sf->height);
    k->H = _mm256_set1_epi32(f->H);
    k->fH = _mm256_set1_ps((float)f->H);
    k->x0 = _mm256_set1_ps(f->x0);
    k->y0 = _mm256_set1_ps(f->y0);
    k->half_h = _mm256_set1_ps(f->half_h);
    k->fS = _mm256_set1_ps(sf->fS);
    k->inv_S = _mm256_set1_ps(sf->inv_S);
    k->wrap = _mm256_set1_epi32(sf->pow2_mask);
    k->fK = _mm256_set1_ps(sf->fK);
    k->inv_K = _mm256_set1_ps(sf->inv_K);
    k->cw2 = _mm256_set1_ps(f->cw2);
    k->ch2 = _mm256_set1_epi32(f->ch2);
}

static inline int lanes_of(__m256i mask)
{
    return _mm256_movemask_ps(_mm256_castsi256_ps(mask));
}

static inline int hmin(__m256i a)
{
    __m128i m = _mm_min_epi32(_mm256_castsi256_si128(a), _mm256_extracti128_si256(a, 1));
    m = _mm_min_epi32(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(1, 0, 3, 2)));
    return _mm_cvtsi128_si32(_mm_min_epi32(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(2, 3, 0, 1))));
}

static inline int hmax(__m256i a)
{
    __m128i m = _mm_max_epi32(_mm256_castsi256_si128(a), _mm256_extracti128_si256(a, 1));
    m = _mm_max_epi32(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(1, 0, 3, 2)));
    return _mm_cvtsi128_si32(_mm_max_epi32(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(2, 3, 0, 1))));
}

/* floor(q) mod S for a power-of-two S: the two's-complement mask is the non-negative remainder. */
static inline __m256i wrap_pow2(__m256 q, const consts *k)
{
    return _mm256_and_si256(_mm256_cvttps_epi32(_mm256_round_ps(q, FLOOR)), k->wrap);
}

/* floor(q) mod S for any S, in float and exact: "wrap" in the design note. */
static inline __m256i wrap_any(__m256 q, const consts *k)
{
    __m256 fl = _mm256_round_ps(q, FLOOR);
    __m256 n = _mm256_round_ps(_mm256_mul_ps(fl, k->inv_S), FLOOR);
    __m256 r = _mm256_sub_ps(fl, _mm256_mul_ps(n, k->fS));
    r = _mm256_add_ps(r, _mm256_and_ps(_mm256_cmp_ps(r, _mm256_setzero_ps(), _CMP_LT_OQ), k->fS));
    r = _mm256_sub_ps(r, _mm256_and_ps(_mm256_cmp_ps(r, k->fS, _CMP_GE_OQ), k->fS));
    return _mm256_cvttps_epi32(r);
}

/* (int)float_mod(q, S - 1) for |q| < 2^23: "course" in the design note. */
static inline __m256i course_wrap(__m256 q, const consts *k)
{
    const __m256 zero = _mm256_setzero_ps(), K = k->fK;
    __m256 n = _mm256_round_ps(_mm256_mul_ps(q, k->inv_K), TRUNC);
    __m256 r = _mm256_sub_ps(q, _mm256_mul_ps(n, K));
    __m256 neg = _mm256_cmp_ps(q, zero, _CMP_LT_OQ);
    /* fmodf: r takes q's sign and |r| < k */
    r = _mm256_add_ps(r, _mm256_and_ps(_mm256_andnot_ps(neg, _mm256_cmp_ps(r, zero, _CMP_LT_OQ)), K));
    r = _mm256_sub_ps(r, _mm256_and_ps(_mm256_andnot_ps(neg, _mm256_cmp_ps(r, K, _CMP_GE_OQ)), K));
    r = _mm256_sub_ps(r, _mm256_and_ps(_mm256_and_ps(neg, _mm256_cmp_ps(r, zero, _CMP_GT_OQ)), K));
    __m256 low = _mm256_cmp_ps(r, _mm256_sub_ps(zero, K), _CMP_LE_OQ);
    r = _mm256_add_ps(r, _mm256_and_ps(_mm256_and_ps(neg, low), K));
    /* float_mod */
    r = _mm256_add_ps(r, _mm256_and_ps(_mm256_cmp_ps(r, zero, _CMP_LT_OQ), K));
    return _mm256_cvttps_epi32(_mm256_and_ps(_mm256_cmp_ps(r, K, _CMP_LT_OQ), r));
}

/* The heights of cells (i, j). *at receives what colours() needs: the packed cell itself, or
 * the row-major index when the maps are read directly. */
static inline __m256i heights(const retro_frame *f, const retro_simd_frame *sf, const consts *k,
                              __m256i i, __m256i j, __m256i *at, const int packed)
{
    const __m256i low = _mm256_set1_epi32(RETRO_SIMD_TILE - 1);
    uint32_t x[LANES] __attribute__((aligned(32)));
    if (packed) {
        __m256i tile = _mm256_add_epi32(_mm256_mullo_epi32(_mm256_srli_epi32(j, 2), k->tiles),
                                        _mm256_srli_epi32(i, 2));
        __m256i within = _mm256_or_si256(_mm256_slli_epi32(_mm256_and_si256(j, low), 2),
                                         _mm256_and_si256(i, low));
        _mm256_store_si256((__m256i *)x, _mm256_or_si256(_mm256_slli_epi32(tile, 4), within));
        const uint32_t *c = sf->cells;
        *at = _mm256_setr_epi32((int)c[x[0]], (int)c[x[1]], (int)c[x[2]], (int)c[x[3]],
                                (int)c[x[4]], (int)c[x[5]], (int)c[x[6]], (int)c[x[7]]);
        return _mm256_and_si256(*at, _mm256_set1_epi32(RETRO_SIMD_HEIGHT_MASK));
    }
    *at = _mm256_add_epi32(_mm256_mullo_epi32(j, k->S), i);
    _mm256_store_si256((__m256i *)x, *at);
    const uint8_t *h = f->height_map;
    return _mm256_setr_epi32(h[x[0]], h[x[1]], h[x[2]], h[x[3]], h[x[4]], h[x[5]], h[x[6]], h[x[7]]);
}

/* The colours of every lane, from what heights() left in at. */
static inline __m256i colours(const retro_frame *f, __m256i at, const int packed)
{
    if (packed)
        return _mm256_and_si256(at, _mm256_set1_epi32((int)RETRO_SIMD_COLOR_MASK));
    uint32_t x[LANES] __attribute__((aligned(32)));
    _mm256_store_si256((__m256i *)x, at);
    const uint32_t *c = f->color_map;
    return _mm256_setr_epi32((int)c[x[0]], (int)c[x[1]], (int)c[x[2]], (int)c[x[3]], (int)c[x[4]],
                             (int)c[x[5]], (int)c[x[6]], (int)c[x[7]]);
}

/* SEMANTICS.md step 6 on every lane; clamping to [0, H] before truncating is the same
 * three-way case, since truncation is the floor for 0 <= vf. */
static inline __m256i exact_project(__m256i h, float kd, const consts *k)
{
    __m256 dh = _mm256_cvtepi32_ps(_mm256_sub_epi32(h, k->height));
    __m256 vf = _mm256_add_ps(_mm256_mul_ps(_mm256_set1_ps(kd), dh), k->half_h);
    vf = _mm256_min_ps(_mm256_max_ps(vf, _mm256_setzero_ps()), k->fH);
    return _mm256_cvttps_epi32(vf);
}

/* retro_course_row() on every lane, clamped at RETRO_SIMD_ROW_CLAMP first to stay in int. */
static inline __m256i course_project(__m256i h, __m256 fd, const consts *k)
{
    __m256 dh = _mm256_cvtepi32_ps(_mm256_sub_epi32(h, k->height));
    __m256 t = _mm256_div_ps(_mm256_mul_ps(k->cw2, dh), fd);
    t = _mm256_min_ps(_mm256_max_ps(t, _mm256_set1_ps(-RETRO_SIMD_ROW_CLAMP)),
                      _mm256_set1_ps(RETRO_SIMD_ROW_CLAMP));
    __m256i v = _mm256_add_epi32(_mm256_cvttps_epi32(t), k->ch2);
    return _mm256_min_epi32(_mm256_max_epi32(v, _mm256_setzero_si256()), k->H);
}

/* Rows lo..hi of columns u0.. get colour where y < row <= top, one masked store per row
 * (vpmaskmovd stores are fast on Zen 5: lane-by-lane stores measured 2x slower). */
static void paint_rows(const retro_frame *f, int u0, int lo, int hi, __m256i y, __m256i top,
                       __m256i colour)
{
    const size_t W = (size_t)f->W;
    size_t at = (size_t)(f->H - lo) * W + (size_t)u0;
    __m256i r = _mm256_set1_epi32(lo);
    for (int row = lo; row <= hi; row++, at -= W) {
        __m256i m = _mm256_andnot_si256(_mm256_cmpgt_epi32(r, top), _mm256_cmpgt_epi32(r, y));
        _mm256_maskstore_epi32((int *)(f->out + at), m, colour);
        RETRO_SIMD_COUNT(f->out, at, (unsigned)lanes_of(m));
        r = _mm256_add_epi32(r, _mm256_set1_epi32(1));
    }
}

/* Steps 4-5 of SEMANTICS.md at distance d for every lane: the heights of the cells, and in *at
 * what colours() needs. */
static inline __attribute__((always_inline)) __m256i
sample(const retro_frame *f, const retro_simd_frame *sf, const consts *k, __m256 rx, __m256 ry, int d,
       __m256i *at, const int pow2, const int packed)
{
    __m256 fd = _mm256_set1_ps((float)d);
    __m256 qx = _mm256_add_ps(k->x0, _mm256_mul_ps(fd, rx));
    __m256 qy = _mm256_add_ps(k->y0, _mm256_mul_ps(fd, ry));
    __m256i i = pow2 ? wrap_pow2(qx, k) : wrap_any(qx, k);
    __m256i j = pow2 ? wrap_pow2(qy, k) : wrap_any(qy, k);
    return heights(f, sf, k, i, j, at, packed);
}

/* Fog toward the sky by weight F/256 (docs/EFFECTS.md) on every lane: R|B and G in 16-bit
 * halves, x*(256-F) + s*F + 128 stays below 2^16, so 16-bit products are exact and the bytes
 * equal retro_fog()'s. */
static inline __m256i fog_colours(__m256i c, int F, uint32_t sky)
{
    const __m256i low = _mm256_set1_epi32(0x00ff00ff), byte = _mm256_set1_epi32(0xff);
    const __m256i wc = _mm256_set1_epi16((short)(256 - F)), ws = _mm256_set1_epi16((short)F);
    const __m256i half = _mm256_set1_epi16(128);
    __m256i rb = _mm256_and_si256(_mm256_srli_epi32(c, 8), low), g = _mm256_and_si256(_mm256_srli_epi32(c, 16), byte);
    __m256i srb = _mm256_set1_epi32((int)((sky >> 8) & 0x00ff00ffu)), sg = _mm256_set1_epi32((int)((sky >> 16) & 0xffu));
    rb = _mm256_srli_epi16(_mm256_add_epi16(_mm256_add_epi16(_mm256_mullo_epi16(rb, wc), _mm256_mullo_epi16(srb, ws)), half), 8);
    g = _mm256_srli_epi16(_mm256_add_epi16(_mm256_add_epi16(_mm256_mullo_epi16(g, wc), _mm256_mullo_epi16(sg, ws)), half), 8);
    return _mm256_or_si256(_mm256_slli_epi32(rb, 8), _mm256_slli_epi32(g, 16));
}

/* Columns u0..u0+n-1 (n <= 8), front to back, as in simd-avx512. Lanes past n start full. */
static inline __attribute__((always_inline)) void
exact_group(const retro_frame *f, const retro_simd_frame *sf, const consts *k, int u0, int n,
            const int pow2, const int packed, const int fog, const int skip)
{
    __m256i live = _mm256_cmpgt_epi32(_mm256_set1_epi32(n), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
    __m256 rx = _mm256_maskload_ps(f->rx + u0, live), ry = _mm256_maskload_ps(f->ry + u0, live);
    __m256i y = _mm256_andnot_si256(live, k->H);
    __m256i at, h = sample(f, sf, k, rx, ry, 1, &at, pow2, packed);
    retro_simd_grp g;
    int hd = 1, probe = 1, batch = RETRO_SIMD_SKIP_NEAR;
    if (skip) /* skipping as in simd-avx512 */
        RETRO_SIMD_GRP_INIT(&g, f, u0, n);
    for (int d = 1; d < f->D; d++) {
        if (!lanes_of(_mm256_cmpgt_epi32(_mm256_set1_epi32(f->vcap[d]), y)))
            break;
        if (skip && d >= probe) {
            int ys[LANES];
            _mm256_storeu_si256((__m256i *)ys, y);
            const int e = RETRO_SIMD_PROBE(&g, f, d, ys, pow2);
            if (e > d) {
                d = e - 1; /* the loop's d++ */
                probe = e;
                batch = RETRO_SIMD_SKIP_NEAR;
                continue;
            }
            probe = d + batch;
            batch = batch < RETRO_SIMD_SKIP_FAR ? 2 * batch : batch;
        }
        if (skip && hd != d)
            h = sample(f, sf, k, rx, ry, d, &at, pow2, packed);
        __m256i v = exact_project(h, f->kd[d], k), at_d = at;
        /* The next distance's loads issue before the paint branch, as in simd-avx512. */
        h = sample(f, sf, k, rx, ry, d + 1, &at, pow2, packed);
        hd = d + 1;
        __m256i up = _mm256_cmpgt_epi32(v, y);
        if (lanes_of(up)) {
            /* Lanes that do not rise must not widen the rows; v >= 0, so 0 leaves them out. */
            int lo = hmin(_mm256_blendv_epi8(_mm256_set1_epi32(INT_MAX), y, up)) + 1;
            int hi = hmax(_mm256_and_si256(v, up));
            __m256i c = colours(f, at_d, packed);
            paint_rows(f, u0, lo, hi, y, v, fog ? fog_colours(c, f->fog[d], f->sky) : c);
            y = _mm256_max_epi32(y, v);
        }
    }
    paint_rows(f, u0, hmin(y) + 1, f->H, y, k->H, _mm256_set1_epi32((int)f->sky));
}

/* The y-buffer pass over distances d..d+7 of column u, as in simd-avx512: lane l paints rows
 * e+1..v_l when v_l exceeds e = max(y, v_<l) (a prefix max in 3 shifts). */
static inline int course_scan(const retro_frame *f, int u, int y, __m256i v, __m256i at,
                              const int packed)
{
    const __m256i fill = _mm256_set1_epi32(y);
    const __m256i by1 = _mm256_setr_epi32(0, 0, 1, 2, 3, 4, 5, 6);
    const __m256i by2 = _mm256_setr_epi32(0, 0, 0, 1, 2, 3, 4, 5);
    const __m256i by4 = _mm256_setr_epi32(0, 0, 0, 0, 0, 1, 2, 3);
    __m256i p = _mm256_max_epi32(v, fill);
    p = _mm256_max_epi32(p, _mm256_blend_epi32(_mm256_permutevar8x32_epi32(p, by1), fill, 0x01));
    p = _mm256_max_epi32(p, _mm256_blend_epi32(_mm256_permutevar8x32_epi32(p, by2), fill, 0x03));
    p = _mm256_max_epi32(p, _mm256_blend_epi32(_mm256_permutevar8x32_epi32(p, by4), fill, 0x0f));
    __m256i e = _mm256_blend_epi32(_mm256_permutevar8x32_epi32(p, by1), fill, 0x01);
    int up = lanes_of(_mm256_cmpgt_epi32(v, e));
    if (up) {
        int es[LANES], vs[LANES];
        uint32_t as[LANES];
        _mm256_storeu_si256((__m256i *)es, e);
        _mm256_storeu_si256((__m256i *)vs, v);
        _mm256_storeu_si256((__m256i *)as, at);
        for (; up; up &= up - 1) {
            int l = __builtin_ctz((unsigned)up);
            uint32_t colour = packed ? as[l] & RETRO_SIMD_COLOR_MASK : f->color_map[as[l]];
            retro_simd_span(f, u, es[l], vs[l], colour);
        }
    }
    return _mm256_extract_epi32(p, 7);
}

static inline __m256i first_lanes(int n)
{
    return _mm256_cmpgt_epi32(_mm256_set1_epi32(n), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
}

/* The rows of distances d..d+7 (those below D; the others get v = 0) of the column whose
 * positions qx, qy hold, and in *at what the scan needs for colours. */
static inline __attribute__((always_inline)) __m256i
course_sample(const retro_frame *f, const retro_simd_frame *sf, const consts *k, const float *qx,
              const float *qy, int d, __m256i *at, const int packed)
{
    const __m256 iota = _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7);
    __m256i live = first_lanes(f->D - d);
    __m256 x = _mm256_maskload_ps(qx + d, live), z = _mm256_maskload_ps(qy + d, live);
    /* Dead lanes sample cell 0 (their q is 0). */
    __m256i h = heights(f, sf, k, course_wrap(x, k), course_wrap(z, k), at, packed);
    __m256 fd = _mm256_add_ps(_mm256_set1_ps((float)d), iota);
    return _mm256_and_si256(live, course_project(h, fd, k));
}

/* Column u of mode course, lanes = distances, as in simd-avx512: every accumulator is sampled
 * (until the early exit), then all advance. */
static inline __attribute__((always_inline)) void
course_column(const retro_frame *f, const retro_simd_frame *sf, const consts *k, float *qx, float *qy,
              int u, const int packed)
{
    int y = 0;
    __m256i at, v = course_sample(f, sf, k, qx, qy, 1, &at, packed);
    for (int d = 1; d < f->D && y < f->vcap[d]; d += LANES) {
        __m256i at_d = at, v_d = v;
        /* The next block's loads issue before the scan's branches, as in mode exact. */
        if (d + LANES < f->D)
            v = course_sample(f, sf, k, qx, qy, d + LANES, &at, packed);
        y = course_scan(f, u, y, v_d, at_d, packed);
    }
    retro_simd_span(f, u, y, f->H, f->sky);
    for (int d = 1; d < f->D; d += LANES) {
        __m256i live = first_lanes(f->D - d);
        __m256 x = _mm256_maskload_ps(qx + d, live), z = _mm256_maskload_ps(qy + d, live);
        _mm256_maskstore_ps(qx + d, live, _mm256_add_ps(x, _mm256_maskload_ps(f->sx + d, live)));
        _mm256_maskstore_ps(qy + d, live, _mm256_add_ps(z, _mm256_maskload_ps(f->sy + d, live)));
    }
}

/* One instantiation per (mode, power-of-two S, packed map), as in simd-avx512. */
RETRO_SIMD_ENTRY_POINTS(avx2)
