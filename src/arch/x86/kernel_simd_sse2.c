/* simd-sse2: the simd-avx512 kernel on 4 lanes for any x86-64; the design note at the top of
 * kernel_simd_avx512.c covers it. SSE2 lacks a floor, a 32-bit multiply, a signed max and
 * masked stores: floor is truncation corrected by a compare, the multiply is two pmuludq,
 * and pixels are stored lane by lane through RETRO_PUT, a column span per painting lane
 * (storing row by row with a bit loop measured 1.4x slower). */
#include <emmintrin.h>

#include "kernels.h"
#include "simd_common.h"

enum { LANES = 4 };

/* The frame's constants, broadcast once. */
typedef struct {
    __m128i tiles;     /* tiles per row of the packed map */
    __m128i S;         /* map size, for row-major indices */
    __m128i height;    /* camera height, int32 (retro_simd_check checked the range) */
    __m128i H;         /* H */
    __m128 fH;         /* H */
    /* mode exact */
    __m128 x0, y0;     /* position reduced modulo S */
    __m128 half_h;     /* 0.5f * H */
    __m128 fS, inv_S;  /* S and 1/S, for the float remainder */
    __m128i wrap;      /* S - 1 when S is a power of two */
    /* mode course */
    __m128 fK, inv_K;  /* the wrap period S - 1 and its reciprocal */
    __m128 cw2;        /* (float)(W / 2) */
    __m128i ch2;       /* H / 2 */
} consts;

static void init_consts(consts *k, const retro_frame *f, const retro_simd_frame *sf)
{
    k->tiles = _mm_set1_epi32(sf->tiles);
    k->S = _mm_set1_epi32(f->S);
    k->height = _mm_set1_epi32(sf->height);
    k->H = _mm_set1_epi32(f->H);
    k->fH = _mm_set1_ps((float)f->H);
    k->x0 = _mm_set1_ps(f->x0);
    k->y0 = _mm_set1_ps(f->y0);
    k->half_h = _mm_set1_ps(f->half_h);
    k->fS = _mm_set1_ps(sf->fS);
    k->inv_S = _mm_set1_ps(sf->inv_S);
    k->wrap = _mm_set1_epi32(sf->pow2_mask);
    k->fK = _mm_set1_ps(sf->fK);
    k->inv_K = _mm_set1_ps(sf->inv_K);
    k->cw2 = _mm_set1_ps(f->cw2);
    k->ch2 = _mm_set1_epi32(f->ch2);
}

static inline int lanes_of(__m128i mask)
{
    return _mm_movemask_ps(_mm_castsi128_ps(mask));
}

/* floor(q) for |q| < 2^31: truncation, minus one where it rounded a negative q up. */
static inline __m128i floor_epi32(__m128 q)
{
    __m128i t = _mm_cvttps_epi32(q);
    return _mm_add_epi32(t, _mm_castps_si128(_mm_cmpgt_ps(_mm_cvtepi32_ps(t), q)));
}

static inline __m128i mullo_epi32(__m128i a, __m128i b)
{
    __m128i even = _mm_mul_epu32(a, b);
    __m128i odd = _mm_mul_epu32(_mm_srli_epi64(a, 32), _mm_srli_epi64(b, 32));
    return _mm_unpacklo_epi32(_mm_shuffle_epi32(even, _MM_SHUFFLE(0, 0, 2, 0)),
                              _mm_shuffle_epi32(odd, _MM_SHUFFLE(0, 0, 2, 0)));
}

static inline __m128i max_epi32(__m128i a, __m128i b)
{
    __m128i gt = _mm_cmpgt_epi32(a, b);
    return _mm_or_si128(_mm_and_si128(gt, a), _mm_andnot_si128(gt, b));
}

static inline __m128i min_epi32(__m128i a, __m128i b)
{
    __m128i gt = _mm_cmpgt_epi32(a, b);
    return _mm_or_si128(_mm_and_si128(gt, b), _mm_andnot_si128(gt, a));
}

/* floor(q) mod S for a power-of-two S: the two's-complement mask is the non-negative remainder. */
static inline __m128i wrap_pow2(__m128 q, const consts *k)
{
    return _mm_and_si128(floor_epi32(q), k->wrap);
}

/* floor(q) mod S for any S, in float and exact: "wrap" in the design note. */
static inline __m128i wrap_any(__m128 q, const consts *k)
{
    __m128 fl = _mm_cvtepi32_ps(floor_epi32(q));
    __m128 n = _mm_cvtepi32_ps(floor_epi32(_mm_mul_ps(fl, k->inv_S)));
    __m128 r = _mm_sub_ps(fl, _mm_mul_ps(n, k->fS));
    r = _mm_add_ps(r, _mm_and_ps(_mm_cmplt_ps(r, _mm_setzero_ps()), k->fS));
    r = _mm_sub_ps(r, _mm_and_ps(_mm_cmpge_ps(r, k->fS), k->fS));
    return _mm_cvttps_epi32(r);
}

/* (int)float_mod(q, S - 1) for |q| < 2^23: "course" in the design note. Truncating through
 * int32 is exact since |q / (S - 1)| < 2^23. */
static inline __m128i course_wrap(__m128 q, const consts *k)
{
    const __m128 zero = _mm_setzero_ps(), K = k->fK;
    __m128 n = _mm_cvtepi32_ps(_mm_cvttps_epi32(_mm_mul_ps(q, k->inv_K)));
    __m128 r = _mm_sub_ps(q, _mm_mul_ps(n, K));
    __m128 neg = _mm_cmplt_ps(q, zero);
    /* fmodf: r takes q's sign and |r| < k */
    r = _mm_add_ps(r, _mm_and_ps(_mm_andnot_ps(neg, _mm_cmplt_ps(r, zero)), K));
    r = _mm_sub_ps(r, _mm_and_ps(_mm_andnot_ps(neg, _mm_cmpge_ps(r, K)), K));
    r = _mm_sub_ps(r, _mm_and_ps(_mm_and_ps(neg, _mm_cmpgt_ps(r, zero)), K));
    r = _mm_add_ps(r, _mm_and_ps(_mm_and_ps(neg, _mm_cmple_ps(r, _mm_sub_ps(zero, K))), K));
    /* float_mod */
    r = _mm_add_ps(r, _mm_and_ps(_mm_cmplt_ps(r, zero), K));
    return _mm_cvttps_epi32(_mm_and_ps(_mm_cmplt_ps(r, K), r));
}

/* The heights of cells (i, j). *at receives what colour_of() needs: the packed cell itself,
 * or the row-major index when the maps are read directly. */
static inline __m128i heights(const retro_frame *f, const retro_simd_frame *sf, const consts *k,
                              __m128i i, __m128i j, __m128i *at, const int packed)
{
    const __m128i low = _mm_set1_epi32(RETRO_SIMD_TILE - 1);
    uint32_t x[LANES] __attribute__((aligned(16)));
    if (packed) {
        __m128i tile = _mm_add_epi32(mullo_epi32(_mm_srli_epi32(j, 2), k->tiles), _mm_srli_epi32(i, 2));
        __m128i within = _mm_or_si128(_mm_slli_epi32(_mm_and_si128(j, low), 2), _mm_and_si128(i, low));
        _mm_store_si128((__m128i *)x, _mm_or_si128(_mm_slli_epi32(tile, 4), within));
        const uint32_t *c = sf->cells;
        *at = _mm_setr_epi32((int)c[x[0]], (int)c[x[1]], (int)c[x[2]], (int)c[x[3]]);
        return _mm_and_si128(*at, _mm_set1_epi32(RETRO_SIMD_HEIGHT_MASK));
    }
    *at = _mm_add_epi32(mullo_epi32(j, k->S), i);
    _mm_store_si128((__m128i *)x, *at);
    const uint8_t *h = f->height_map;
    return _mm_setr_epi32(h[x[0]], h[x[1]], h[x[2]], h[x[3]]);
}

/* The colour of a lane, from its entry of what heights() left in at. */
static inline uint32_t colour_of(const retro_frame *f, uint32_t at, const int packed)
{
    return packed ? at & RETRO_SIMD_COLOR_MASK : f->color_map[at];
}

/* SEMANTICS.md step 6 on every lane; clamping to [0, H] before truncating is the same
 * three-way case, since truncation is the floor for 0 <= vf. */
static inline __m128i exact_project(__m128i h, float kd, const consts *k)
{
    __m128 dh = _mm_cvtepi32_ps(_mm_sub_epi32(h, k->height));
    __m128 vf = _mm_add_ps(_mm_mul_ps(_mm_set1_ps(kd), dh), k->half_h);
    vf = _mm_min_ps(_mm_max_ps(vf, _mm_setzero_ps()), k->fH);
    return _mm_cvttps_epi32(vf);
}

/* retro_course_row() on every lane, clamped at RETRO_SIMD_ROW_CLAMP first to stay in int. */
static inline __m128i course_project(__m128i h, __m128 fd, const consts *k)
{
    __m128 dh = _mm_cvtepi32_ps(_mm_sub_epi32(h, k->height));
    __m128 t = _mm_div_ps(_mm_mul_ps(k->cw2, dh), fd);
    t = _mm_min_ps(_mm_max_ps(t, _mm_set1_ps(-RETRO_SIMD_ROW_CLAMP)),
                   _mm_set1_ps(RETRO_SIMD_ROW_CLAMP));
    __m128i v = _mm_add_epi32(_mm_cvttps_epi32(t), k->ch2);
    return min_epi32(max_epi32(v, _mm_setzero_si128()), k->H);
}

/* Steps 4-5 of SEMANTICS.md at distance d for every lane: the heights of the cells, and in *at
 * what colour_of() needs. */
static inline __attribute__((always_inline)) __m128i
sample(const retro_frame *f, const retro_simd_frame *sf, const consts *k, __m128 rx, __m128 ry, int d,
       __m128i *at, const int pow2, const int packed)
{
    __m128 fd = _mm_set1_ps((float)d);
    __m128 qx = _mm_add_ps(k->x0, _mm_mul_ps(fd, rx));
    __m128 qy = _mm_add_ps(k->y0, _mm_mul_ps(fd, ry));
    __m128i i = pow2 ? wrap_pow2(qx, k) : wrap_any(qx, k);
    __m128i j = pow2 ? wrap_pow2(qy, k) : wrap_any(qy, k);
    return heights(f, sf, k, i, j, at, packed);
}

/* Columns u0..u0+n-1 (n <= 4), front to back, as in simd-avx512. Lanes past n start full. */
static inline __attribute__((always_inline)) void
exact_group(const retro_frame *f, const retro_simd_frame *sf, const consts *k, int u0, int n,
            const int pow2, const int packed, const int fog, const int skip)
{
    float rxs[LANES] = {0}, rys[LANES] = {0};
    for (int l = 0; l < n; l++) {
        rxs[l] = f->rx[u0 + l];
        rys[l] = f->ry[u0 + l];
    }
    __m128 rx = _mm_loadu_ps(rxs), ry = _mm_loadu_ps(rys);
    __m128i live = _mm_cmpgt_epi32(_mm_set1_epi32(n), _mm_setr_epi32(0, 1, 2, 3));
    __m128i y = _mm_andnot_si128(live, k->H);
    __m128i at, h = sample(f, sf, k, rx, ry, 1, &at, pow2, packed);
    retro_simd_grp g;
    int hd = 1, probe = 1, batch = RETRO_SIMD_SKIP_NEAR;
    if (skip) /* skipping as in simd-avx512 */
        RETRO_SIMD_GRP_INIT(&g, f, u0, n);
    for (int d = 1; d < f->D; d++) {
        if (!lanes_of(_mm_cmpgt_epi32(_mm_set1_epi32(f->vcap[d]), y)))
            break;
        if (skip && d >= probe) {
            int ys[LANES];
            _mm_storeu_si128((__m128i *)ys, y);
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
        __m128i v = exact_project(h, f->kd[d], k), at_d = at;
        /* The next distance's loads issue before the paint branch, as in simd-avx512. */
        h = sample(f, sf, k, rx, ry, d + 1, &at, pow2, packed);
        hd = d + 1;
        int up = lanes_of(_mm_cmpgt_epi32(v, y));
        if (up) {
            int ys[LANES], vs[LANES];
            uint32_t as[LANES];
            _mm_storeu_si128((__m128i *)ys, y);
            _mm_storeu_si128((__m128i *)vs, v);
            _mm_storeu_si128((__m128i *)as, at_d);
            for (; up; up &= up - 1) {
                int l = __builtin_ctz((unsigned)up);
                uint32_t c = colour_of(f, as[l], packed);
                retro_simd_span(f, u0 + l, ys[l], vs[l], fog ? retro_fog(c, f->sky, f->fog[d]) : c);
            }
            y = max_epi32(y, v);
        }
    }
    int ys[LANES];
    _mm_storeu_si128((__m128i *)ys, y);
    for (int l = 0; l < n; l++)
        retro_simd_span(f, u0 + l, ys[l], f->H, f->sky);
}

/* The y-buffer pass over distances d..d+3 of column u, as in simd-avx512: lane l paints rows
 * e+1..v_l when v_l exceeds e = max(y, v_<l) (a prefix max in 2 shifts). */
static inline int course_scan(const retro_frame *f, int u, int y, __m128i v, __m128i at,
                              const int packed)
{
    const __m128i fill = _mm_set1_epi32(y);
    const __m128i first = _mm_setr_epi32(-1, 0, 0, 0), two = _mm_setr_epi32(-1, -1, 0, 0);
    __m128i p = max_epi32(v, fill);
    p = max_epi32(p, _mm_or_si128(_mm_slli_si128(p, 4), _mm_and_si128(fill, first)));
    p = max_epi32(p, _mm_or_si128(_mm_slli_si128(p, 8), _mm_and_si128(fill, two)));
    __m128i e = _mm_or_si128(_mm_slli_si128(p, 4), _mm_and_si128(fill, first));
    int up = lanes_of(_mm_cmpgt_epi32(v, e));
    if (up) {
        int es[LANES], vs[LANES];
        uint32_t as[LANES];
        _mm_storeu_si128((__m128i *)es, e);
        _mm_storeu_si128((__m128i *)vs, v);
        _mm_storeu_si128((__m128i *)as, at);
        for (; up; up &= up - 1) {
            int l = __builtin_ctz((unsigned)up);
            retro_simd_span(f, u, es[l], vs[l], colour_of(f, as[l], packed));
        }
    }
    return _mm_cvtsi128_si32(_mm_shuffle_epi32(p, _MM_SHUFFLE(3, 3, 3, 3)));
}

/* Distances d..d+3 of column u, as in simd-avx512: sampled while the y-buffer is below
 * vcap[d], advanced always. Returns the new y-buffer. */
static inline __attribute__((always_inline)) int
course_block(const retro_frame *f, const retro_simd_frame *sf, const consts *k, float *qx, float *qy,
             int u, int y, int d, const int packed)
{
    __m128 x = _mm_loadu_ps(qx + d), z = _mm_loadu_ps(qy + d);
    if (y < f->vcap[d]) {
        __m128i at, h = heights(f, sf, k, course_wrap(x, k), course_wrap(z, k), &at, packed);
        __m128 fd = _mm_add_ps(_mm_set1_ps((float)d), _mm_setr_ps(0, 1, 2, 3));
        y = course_scan(f, u, y, course_project(h, fd, k), at, packed);
    }
    _mm_storeu_ps(qx + d, _mm_add_ps(x, _mm_loadu_ps(f->sx + d)));
    _mm_storeu_ps(qy + d, _mm_add_ps(z, _mm_loadu_ps(f->sy + d)));
    return y;
}

/* Distance d of column u in scalar code, for the last (D - 1) mod 4 distances: SSE2 has no
 * masked loads, and copying a partial block into vectors costs more than these few samples. */
static int course_sample(const retro_frame *f, float *qx, float *qy, int u, int y, int d)
{
    if (y < f->vcap[d]) {
        const float k = (float)(f->S - 1), inv_k = 1.0f / k;
        size_t idx = (size_t)retro_course_cell_fast(qy[d], k, inv_k) * (size_t)f->S +
                     (size_t)retro_course_cell_fast(qx[d], k, inv_k);
        int v = retro_course_row(f->cw2, f->ch2, f->H, f->height_map[idx] - f->height, d);
        if (v > y) {
            retro_simd_span(f, u, y, v, f->color_map[idx]);
            y = v;
        }
    }
    qx[d] += f->sx[d];
    qy[d] += f->sy[d];
    return y;
}

/* One instantiation per (mode, power-of-two S, packed map), as in simd-avx512. */
/* One column of mode course: blocks of LANES distances, then the remaining ones lane by lane. */
static inline __attribute__((always_inline)) void course_column(const retro_frame *f, const retro_simd_frame *sf,
                                                                const consts *k, float *qx, float *qy, int u,
                                                                const int packed)
{
    int y = 0, d = 1;
    for (; d + LANES <= f->D; d += LANES)
        y = course_block(f, sf, k, qx, qy, u, y, d, packed);
    for (; d < f->D; d++)
        y = course_sample(f, qx, qy, u, y, d);
    retro_simd_span(f, u, y, f->H, f->sky);
}

RETRO_SIMD_ENTRY_POINTS(sse2)
