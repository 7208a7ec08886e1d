/* simd-avx512: the y-buffer kernel on 16 lanes, byte-identical to naive in modes exact and
 * course. simd-avx2 (8 lanes) and simd-sse2 (4 lanes) share the design; this note is theirs.
 *
 * Mode exact: lanes are 16 adjacent columns at one distance d. Steps 4-6 of SEMANTICS.md have
 * no dependence between columns, so each lane evaluates exactly naive's float operations (mul,
 * then add: no FMA anywhere, -ffp-contract=off) and only the y-buffers are state. A step paints
 * rows y+1..v of the lanes that rise with one masked store per row across the 16 columns, which
 * are adjacent in out; the sky above the last samples likewise. Painting lane by lane (a column
 * span each, as ybuffer does) measured 1.6x slower overall, though only 1.5-3.5 of 16 lanes
 * paint an average row. The early exit carries over exactly: the group stops at the first d
 * where every lane's y-buffer has reached vcap[d]; a lane that got there sooner keeps sampling
 * but cannot paint, since its v <= vcap[d] <= y. The next distance's loads are issued before
 * the paint branch, so a mispredicted branch does not delay them (15-25% faster).
 *
 * Mode course accumulates positions column by column, so columns are not independent; lanes
 * are 16 consecutive distances of one column instead, each carrying its line's accumulator
 * through the very additions of SEMANTICS.md (sampled, then advanced, every column, past the
 * early exit too). The y-buffer pass over a block is an exclusive prefix max (4 shifted maxes):
 * lane l paints rows e+1..v_l, as a column span, where v_l > e = max(y, v_<l). The early exit
 * is tested per block; samples in a block past the exact exit cannot paint either.
 *
 * Wrap (exact): i = floor(q) mod S. Power-of-two S: a floor-rounding conversion and a mask.
 * Any S, in float and exact: |floor(q)| < 2^23 (|q| <= 2^22 * sqrt 2 + S), so
 * n = floor(floor(q) * (1/S)) is off by at most one (relative error < 2^-23 on a quotient
 * below 2^23 / S), r = floor(q) - n*S is an exact integer (|n*S| < 2^24), and one conditional
 * +S and one -S put r in [0, S).
 *
 * Course: (int)float_mod(q, S-1) needs fmodf(q, k). For |q| < 2^23, n = trunc(q * (1/k)) is
 * off by at most one and q - n*k is exact (n*k is an integer below 2^24; the result is a
 * multiple of q's ulp below 2k), so one correction by k gives fmodf exactly; the course's
 * float_mod steps then follow as written (a rounded +k when negative, 0 at >= k). Frames whose
 * lines reach 2^22 (positions beyond about 4e6) render with the scalar kernel; simd_map.c
 * checks the bound per frame. The row is (cw2*dh)/d with a true division, as in the scalar
 * code. Both wraps were checked against the scalar definitions on 480 million lanes.
 *
 * Heights: h - height is formed in int32 and converted once, which is the 64-bit difference
 * rounded once while it fits, i.e. for camera heights >= INT_MIN + 256; lower ones render
 * with the scalar ybuffer.
 *
 * Map reads and layout. The whole-frame kernels read a packed copy owned by the context:
 * colour | height in one uint32 (colours have a zero low byte), so one load fetches both,
 * tiled 4x4 cells to a 64-byte line so that the lanes, which sample along a line across the
 * view, and the next distances, which move along it, share lines at every angle. It is
 * rebuilt only when the map pointers or S change (simd_map.c; about 3 ms for 1024x1024). A
 * colour with a non-zero low byte or a failed allocation means reading the maps directly, as
 * strips always do (threaded kernels call strips without a context): heights lane by lane,
 * colours for painting lanes only; that costs 5-15% against the packed copy.
 *
 * Measured 2026-11-22 on this machine (AMD EPYC Zen 5, 2 cores, KVM, other jobs running on
 * the other core), 640x480, D=800, default views, one thread pinned with taskset -c 1,
 * median of 5 runs of 301 frames each, ms/frame (speed-up over ybuffer):
 *   mode exact   ybuffer  simd-sse2    simd-avx2    simd-avx512
 *   alpine         5.44   1.82 (3.0)   0.55 ( 9.9)  0.37 (14.9)
 *   islands        4.37   1.53 (2.9)   0.47 ( 9.3)  0.32 (13.5)
 *   canyon         3.11   1.27 (2.5)   0.46 ( 6.7)  0.33 ( 9.5)
 *   mode course  (3 runs; ybuffer varied most under the load)
 *   alpine        10.99   6.87 (1.6)   2.57 ( 4.3)  1.80 ( 6.1)
 *   islands        7.85   4.64 (1.7)   1.76 ( 4.5)  1.28 ( 6.1)
 *   canyon         5.96   5.14 (1.2)   1.83 ( 3.3)  1.35 ( 4.4)
 * Gathers against scalar loads. In isolation (random uint32 loads from L1 / L2 / L3, ns per
 * vector): vpgatherdd zmm 4.97 / 5.49 / 6.17 per 16 lanes against 2.87 / 4.58 / 5.32 for 16
 * scalar loads; ymm 3.04 / 3.09 / 3.15 per 8 against 1.37 / 2.21 / 2.63: Zen 5's gathers are
 * microcoded and lose. In the kernel, where the loads overlap other work: the zmm gather is
 * 5-7% faster than 16 scalar loads (0.374 / 0.318 / 0.319 ms against 0.394 / 0.338 / 0.342
 * on alpine / islands / canyon), so simd-avx512 gathers; for simd-avx2 scalar loads and
 * vpgatherdd ymm tie within 3% (scalar loads won by 5-15% before the loads were pipelined),
 * and it keeps the scalar loads. Tiling 4x4 (measured before pipelining) cut the worst view
 * angle (0: the lanes spread along y, 16 rows of a row-major map) from 0.61 to 0.48 ms and
 * evened the angles out (0.42-0.48 ms over 0/45/90/135 against 0.39-0.61 row-major).
 */
#include <immintrin.h>

#include "kernels.h"
#include "simd_common.h"

enum { LANES = 16 };

#ifdef RETRO_COUNT_SAMPLES /* the counting build (hmax_pyramid.h), never the kernel's own */
retro_sample_counts retro_simd_counts;
#define COUNT_LANES(field, n) (retro_simd_counts.field += (uint64_t)(n))
#else
#define COUNT_LANES(field, n) ((void)0)
#endif

#define FLOOR (_MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)
#define TRUNC (_MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC)

/* The frame's constants, broadcast once. */
typedef struct {
    __m512i tiles;     /* tiles per row of the packed map */
    __m512i S;         /* map size, for row-major indices */
    __m512i height;    /* camera height, int32 (retro_simd_check checked the range) */
    __m512i H;         /* H */
    __m512 fH;         /* H */
    /* mode exact */
    __m512 x0, y0;     /* position reduced modulo S */
    __m512 half_h;     /* 0.5f * H */
    __m512 fS, inv_S;  /* S and 1/S, for the float remainder */
    __m512i wrap;      /* S - 1 when S is a power of two */
    /* mode course */
    __m512 fK, inv_K;  /* the wrap period S - 1 and its reciprocal */
    __m512 cw2;        /* (float)(W / 2) */
    __m512i ch2;       /* H / 2 */
} consts;

static void init_consts(consts *k, const retro_frame *f, const retro_simd_frame *sf)
{
    k->tiles = _mm512_set1_epi32(sf->tiles);
    k->S = _mm512_set1_epi32(f->S);
    k->height = _mm512_set1_epi32(sf->height);
    k->H = _mm512_set1_epi32(f->H);
    k->fH = _mm512_set1_ps((float)f->H);
    k->x0 = _mm512_set1_ps(f->x0);
    k->y0 = _mm512_set1_ps(f->y0);
    k->half_h = _mm512_set1_ps(f->half_h);
    k->fS = _mm512_set1_ps(sf->fS);
    k->inv_S = _mm512_set1_ps(sf->inv_S);
    k->wrap = _mm512_set1_epi32(sf->pow2_mask);
    k->fK = _mm512_set1_ps(sf->fK);
    k->inv_K = _mm512_set1_ps(sf->inv_K);
    k->cw2 = _mm512_set1_ps(f->cw2);
    k->ch2 = _mm512_set1_epi32(f->ch2);
}

/* floor(q) mod S for a power-of-two S: the two's-complement mask is the non-negative remainder. */
static inline __m512i wrap_pow2(__m512 q, const consts *k)
{
    return _mm512_and_si512(_mm512_cvt_roundps_epi32(q, FLOOR), k->wrap);
}

/* floor(q) mod S for any S, in float and exact: "wrap" in the design note. */
static inline __m512i wrap_any(__m512 q, const consts *k)
{
    __m512 fl = _mm512_roundscale_ps(q, FLOOR);
    __m512 n = _mm512_roundscale_ps(_mm512_mul_ps(fl, k->inv_S), FLOOR);
    __m512 r = _mm512_sub_ps(fl, _mm512_mul_ps(n, k->fS));
    r = _mm512_mask_add_ps(r, _mm512_cmp_ps_mask(r, _mm512_setzero_ps(), _CMP_LT_OQ), r, k->fS);
    r = _mm512_mask_sub_ps(r, _mm512_cmp_ps_mask(r, k->fS, _CMP_GE_OQ), r, k->fS);
    return _mm512_cvttps_epi32(r);
}

/* (int)float_mod(q, S - 1) for |q| < 2^23: "course" in the design note. */
static inline __m512i course_wrap(__m512 q, const consts *k)
{
    const __m512 zero = _mm512_setzero_ps();
    __m512 n = _mm512_roundscale_ps(_mm512_mul_ps(q, k->inv_K), TRUNC);
    __m512 r = _mm512_sub_ps(q, _mm512_mul_ps(n, k->fK));
    __mmask16 neg = _mm512_cmp_ps_mask(q, zero, _CMP_LT_OQ);
    /* fmodf: r takes q's sign and |r| < k */
    r = _mm512_mask_add_ps(r, _mm512_mask_cmp_ps_mask(~neg, r, zero, _CMP_LT_OQ), r, k->fK);
    r = _mm512_mask_sub_ps(r, _mm512_mask_cmp_ps_mask(~neg, r, k->fK, _CMP_GE_OQ), r, k->fK);
    r = _mm512_mask_sub_ps(r, _mm512_mask_cmp_ps_mask(neg, r, zero, _CMP_GT_OQ), r, k->fK);
    r = _mm512_mask_add_ps(r, _mm512_mask_cmp_ps_mask(neg, r, _mm512_sub_ps(zero, k->fK), _CMP_LE_OQ),
                           r, k->fK);
    /* float_mod */
    r = _mm512_mask_add_ps(r, _mm512_cmp_ps_mask(r, zero, _CMP_LT_OQ), r, k->fK);
    return _mm512_cvttps_epi32(_mm512_maskz_mov_ps(_mm512_cmp_ps_mask(r, k->fK, _CMP_LT_OQ), r));
}

/* The heights of cells (i, j). *at receives what colours() needs: the packed cell itself, or
 * the row-major index when the maps are read directly. */
static inline __m512i heights(const retro_frame *f, const retro_simd_frame *sf, const consts *k,
                              __m512i i, __m512i j, __m512i *at, const int packed)
{
    const __m512i low = _mm512_set1_epi32(RETRO_SIMD_TILE - 1);
    if (packed) {
        __m512i tile = _mm512_add_epi32(_mm512_mullo_epi32(_mm512_srli_epi32(j, 2), k->tiles),
                                        _mm512_srli_epi32(i, 2));
        __m512i within = _mm512_or_si512(_mm512_slli_epi32(_mm512_and_si512(j, low), 2),
                                         _mm512_and_si512(i, low));
        *at = _mm512_i32gather_epi32(_mm512_or_si512(_mm512_slli_epi32(tile, 4), within),
                                     (const void *)sf->cells, 4);
        return _mm512_and_si512(*at, _mm512_set1_epi32(RETRO_SIMD_HEIGHT_MASK));
    }
    *at = _mm512_add_epi32(_mm512_mullo_epi32(j, k->S), i);
    uint32_t x[LANES] __attribute__((aligned(64)));
    _mm512_store_si512(x, *at);
    const uint8_t *h = f->height_map;
    return _mm512_setr_epi32(h[x[0]], h[x[1]], h[x[2]], h[x[3]], h[x[4]], h[x[5]], h[x[6]],
                             h[x[7]], h[x[8]], h[x[9]], h[x[10]], h[x[11]], h[x[12]], h[x[13]],
                             h[x[14]], h[x[15]]);
}

/* The colours of the lanes in m, from what heights() left in at. */
static inline __m512i colours(const retro_frame *f, __m512i at, __mmask16 m, const int packed)
{
    if (packed)
        return _mm512_and_si512(at, _mm512_set1_epi32((int)RETRO_SIMD_COLOR_MASK));
    return _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), m, at, (const void *)f->color_map, 4);
}

/* SEMANTICS.md step 6 on every lane; clamping to [0, H] before truncating is the same
 * three-way case, since truncation is the floor for 0 <= vf. */
static inline __m512i exact_project(__m512i h, float kd, const consts *k)
{
    __m512 dh = _mm512_cvtepi32_ps(_mm512_sub_epi32(h, k->height));
    __m512 vf = _mm512_add_ps(_mm512_mul_ps(_mm512_set1_ps(kd), dh), k->half_h);
    vf = _mm512_min_ps(_mm512_max_ps(vf, _mm512_setzero_ps()), k->fH);
    return _mm512_cvttps_epi32(vf);
}

/* retro_course_row() on every lane, clamped at RETRO_SIMD_ROW_CLAMP first to stay in int. */
static inline __m512i course_project(__m512i h, __m512 fd, const consts *k)
{
    __m512 dh = _mm512_cvtepi32_ps(_mm512_sub_epi32(h, k->height));
    __m512 t = _mm512_div_ps(_mm512_mul_ps(k->cw2, dh), fd);
    t = _mm512_min_ps(_mm512_max_ps(t, _mm512_set1_ps(-RETRO_SIMD_ROW_CLAMP)),
                      _mm512_set1_ps(RETRO_SIMD_ROW_CLAMP));
    __m512i v = _mm512_add_epi32(_mm512_cvttps_epi32(t), k->ch2);
    return _mm512_min_epi32(_mm512_max_epi32(v, _mm512_setzero_si512()), k->H);
}

/* Rows lo..hi of columns u0.. get colour where y < row <= top, one masked store per row. */
static void paint_rows(const retro_frame *f, int u0, int lo, int hi, __m512i y, __m512i top,
                       __m512i colour)
{
    const size_t W = (size_t)f->W;
    size_t at = (size_t)(f->H - lo) * W + (size_t)u0;
    __m512i r = _mm512_set1_epi32(lo);
    for (int row = lo; row <= hi; row++, at -= W) {
        __mmask16 m = _mm512_mask_cmpge_epi32_mask(_mm512_cmplt_epi32_mask(y, r), top, r);
        _mm512_mask_storeu_epi32(f->out + at, m, colour);
        RETRO_SIMD_COUNT(f->out, at, m);
        r = _mm512_add_epi32(r, _mm512_set1_epi32(1));
    }
}

/* Steps 4-5 of SEMANTICS.md at distance d for every lane: the heights of the cells, and in *at
 * what colours() needs. */
static inline __attribute__((always_inline)) __m512i
sample(const retro_frame *f, const retro_simd_frame *sf, const consts *k, __m512 rx, __m512 ry, int d,
       __m512i *at, const int pow2, const int packed)
{
    __m512 fd = _mm512_set1_ps((float)d);
    __m512 qx = _mm512_add_ps(k->x0, _mm512_mul_ps(fd, rx));
    __m512 qy = _mm512_add_ps(k->y0, _mm512_mul_ps(fd, ry));
    __m512i i = pow2 ? wrap_pow2(qx, k) : wrap_any(qx, k);
    __m512i j = pow2 ? wrap_pow2(qy, k) : wrap_any(qy, k);
    return heights(f, sf, k, i, j, at, packed);
}

/* Fog toward the sky by weight F/256 (docs/EFFECTS.md) on every lane: R|B and G in 16-bit
 * halves, x*(256-F) + s*F + 128 stays below 2^16, so 16-bit products are exact and the bytes
 * equal retro_fog()'s. */
static inline __m512i fog_colours(__m512i c, int F, uint32_t sky)
{
    const __m512i low = _mm512_set1_epi32(0x00ff00ff), byte = _mm512_set1_epi32(0xff);
    const __m512i wc = _mm512_set1_epi16((short)(256 - F)), ws = _mm512_set1_epi16((short)F);
    const __m512i half = _mm512_set1_epi16(128);
    __m512i rb = _mm512_and_si512(_mm512_srli_epi32(c, 8), low), g = _mm512_and_si512(_mm512_srli_epi32(c, 16), byte);
    __m512i srb = _mm512_set1_epi32((int)((sky >> 8) & 0x00ff00ffu)), sg = _mm512_set1_epi32((int)((sky >> 16) & 0xffu));
    rb = _mm512_srli_epi16(_mm512_add_epi16(_mm512_add_epi16(_mm512_mullo_epi16(rb, wc), _mm512_mullo_epi16(srb, ws)), half), 8);
    g = _mm512_srli_epi16(_mm512_add_epi16(_mm512_add_epi16(_mm512_mullo_epi16(g, wc), _mm512_mullo_epi16(sg, ws)), half), 8);
    return _mm512_or_si512(_mm512_slli_epi32(rb, 8), _mm512_slli_epi32(g, 16));
}

/* Columns u0..u0+n-1 (n <= 16), front to back: the design note's mode exact. Lanes past n
 * start full (y = H), so they neither paint nor hold the group back. With skip, the group
 * probes the pyramid with its smallest y-buffer (simd_common.h's schedule) and jumps over the
 * distances retro_skip_group proves no lane paints; h then holds a distance the loop no longer
 * wants, and hd says which. */
static inline __attribute__((always_inline)) void
exact_group(const retro_frame *f, const retro_simd_frame *sf, const consts *k, int u0, int n,
            const int pow2, const int packed, const int fog, const int skip)
{
    __mmask16 live = (__mmask16)((1u << n) - 1);
    __m512 rx = _mm512_maskz_loadu_ps(live, f->rx + u0), ry = _mm512_maskz_loadu_ps(live, f->ry + u0);
    __m512i y = _mm512_mask_mov_epi32(k->H, live, _mm512_setzero_si512());
    __m512i at, h = sample(f, sf, k, rx, ry, 1, &at, pow2, packed);
    retro_simd_grp g;
    int hd = 1, probe = 1, batch = RETRO_SIMD_SKIP_NEAR;
    if (skip)
        RETRO_SIMD_GRP_INIT(&g, f, u0, n);
    for (int d = 1; d < f->D;) {
        if (!_mm512_cmplt_epi32_mask(y, _mm512_set1_epi32(f->vcap[d])))
            break;
        if (skip && d >= probe) { /* some lane has y < vcap[d] <= H, so the minimum is < H */
            int ys[LANES];
            _mm512_storeu_si512(ys, y);
            const int e = RETRO_SIMD_PROBE(&g, f, d, ys, pow2);
            if (e > d) {
                d = e;
                probe = e;
                batch = RETRO_SIMD_SKIP_NEAR;
                continue;
            }
            probe = d + batch;
            batch = batch < RETRO_SIMD_SKIP_FAR ? 2 * batch : batch;
        }
        if (skip && hd != d)
            h = sample(f, sf, k, rx, ry, d, &at, pow2, packed);
        __m512i v = exact_project(h, f->kd[d], k), at_d = at;
        /* The next distance's loads issue before the paint branch, so they are in flight
         * when it mispredicts (15-25% faster than sampling after painting). d = D samples a
         * valid cell that is never used. */
        h = sample(f, sf, k, rx, ry, d + 1, &at, pow2, packed);
        hd = d + 1;
        __mmask16 up = _mm512_cmpgt_epi32_mask(v, y);
        COUNT_LANES(evaluated, n);
        COUNT_LANES(painting, __builtin_popcount(up));
        if (up) {
            int lo = _mm512_mask_reduce_min_epi32(up, y) + 1, hi = _mm512_mask_reduce_max_epi32(up, v);
            __m512i c = colours(f, at_d, up, packed);
            paint_rows(f, u0, lo, hi, y, v, fog ? fog_colours(c, f->fog[d], f->sky) : c);
            y = _mm512_max_epi32(y, v);
        }
        d++;
    }
    int lo = _mm512_mask_reduce_min_epi32(live, y) + 1;
    paint_rows(f, u0, lo, f->H, y, k->H, _mm512_set1_epi32((int)f->sky));
}

/* The y-buffer pass over distances d..d+15 of column u: the exclusive prefix max of the design
 * note, then a column span per painting lane. Returns the new y-buffer. */
static inline int course_scan(const retro_frame *f, int u, int y, __m512i v, __m512i at,
                              const int packed)
{
    const __m512i fill = _mm512_set1_epi32(y);
    __m512i p = _mm512_max_epi32(v, fill);
    p = _mm512_max_epi32(p, _mm512_alignr_epi32(p, fill, 15));
    p = _mm512_max_epi32(p, _mm512_alignr_epi32(p, fill, 14));
    p = _mm512_max_epi32(p, _mm512_alignr_epi32(p, fill, 12));
    p = _mm512_max_epi32(p, _mm512_alignr_epi32(p, fill, 8));
    __m512i e = _mm512_alignr_epi32(p, fill, 15);
    unsigned up = _mm512_cmpgt_epi32_mask(v, e);
    if (up) {
        int es[LANES], vs[LANES];
        uint32_t as[LANES];
        _mm512_storeu_si512(es, e);
        _mm512_storeu_si512(vs, v);
        _mm512_storeu_si512(as, at);
        for (; up; up &= up - 1) {
            int l = __builtin_ctz(up);
            uint32_t colour = packed ? as[l] & RETRO_SIMD_COLOR_MASK : f->color_map[as[l]];
            retro_simd_span(f, u, es[l], vs[l], colour);
        }
    }
    return _mm_cvtsi128_si32(_mm512_castsi512_si128(_mm512_alignr_epi32(p, p, 15)));
}

static inline __mmask16 first_lanes(int n)
{
    return (__mmask16)(n < LANES ? (1u << (n > 0 ? n : 0)) - 1 : 0xffffu);
}

/* The rows of distances d..d+15 (those below D; the others get v = 0) of the column whose
 * positions qx, qy hold, and in *at what the scan needs for colours. */
static inline __attribute__((always_inline)) __m512i
course_sample(const retro_frame *f, const retro_simd_frame *sf, const consts *k, const float *qx,
              const float *qy, int d, __m512i *at, const int packed)
{
    const __m512 iota = _mm512_setr_ps(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    __mmask16 live = first_lanes(f->D - d);
    __m512 x = _mm512_maskz_loadu_ps(live, qx + d), z = _mm512_maskz_loadu_ps(live, qy + d);
    /* Dead lanes sample cell 0 (their q is 0). */
    __m512i h = heights(f, sf, k, course_wrap(x, k), course_wrap(z, k), at, packed);
    __m512 fd = _mm512_add_ps(_mm512_set1_ps((float)d), iota);
    return _mm512_maskz_mov_epi32(live, course_project(h, fd, k));
}

/* Column u of mode course: the design note's lanes = distances. qx, qy hold the column's
 * positions on entry and the next column's on return: every accumulator is sampled (until
 * the early exit), then all advance, the additions of SEMANTICS.md in their order. */
static inline __attribute__((always_inline)) void
course_column(const retro_frame *f, const retro_simd_frame *sf, const consts *k, float *qx, float *qy,
              int u, const int packed)
{
    int y = 0;
    __m512i at, v = course_sample(f, sf, k, qx, qy, 1, &at, packed);
    for (int d = 1; d < f->D && y < f->vcap[d]; d += LANES) {
        __m512i at_d = at, v_d = v;
        /* The next block's loads issue before the scan's branches, as in mode exact. */
        if (d + LANES < f->D)
            v = course_sample(f, sf, k, qx, qy, d + LANES, &at, packed);
        y = course_scan(f, u, y, v_d, at_d, packed);
    }
    retro_simd_span(f, u, y, f->H, f->sky);
    for (int d = 1; d < f->D; d += LANES) {
        __mmask16 live = first_lanes(f->D - d);
        __m512 x = _mm512_maskz_loadu_ps(live, qx + d), z = _mm512_maskz_loadu_ps(live, qy + d);
        _mm512_mask_storeu_ps(qx + d, live, _mm512_add_ps(x, _mm512_maskz_loadu_ps(live, f->sx + d)));
        _mm512_mask_storeu_ps(qy + d, live, _mm512_add_ps(z, _mm512_maskz_loadu_ps(live, f->sy + d)));
    }
}

/* One instantiation per (mode, power-of-two S, packed map), so the inner loops carry no
 * tests of them. */
RETRO_SIMD_ENTRY_POINTS(avx512)
