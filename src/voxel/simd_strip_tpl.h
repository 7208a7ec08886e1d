/* The SIMD strips of the voxel kernels, written once for every vector width (zlib-ng's *_tpl.h
 * style): included at the end of src/arch/<arch>/kernel_simd_<isa>.c, which defines what
 * differs between ISAs, then writes the group and column loops and the two entry points
 * retro_strip_simd_<isa> and retro_kernel_simd_<isa>. The design is docs/KERNELS.md's
 * "simd-sse2, simd-avx2, simd-avx512"; the kernels are byte-identical to naive.
 *
 * It lives beside simd_common.h in src/voxel, not in src/arch/x86: it holds no intrinsic, only
 * the voxel algorithm over the operations below, so a file for another architecture would
 * include it unchanged.
 *
 * The contract. Before `#include "simd_strip_tpl.h"` the ISA file defines
 *   SIMD_ISA        the ISA's token (sse2, avx2, avx512): every name this file makes carries it
 *                   through SIMD_NAME(x) = <isa>_x (simd_common.h), and the public ones are
 *                   retro_strip_simd_<isa> and retro_kernel_simd_<isa>, so several ISA files can
 *                   be concatenated into one translation unit (the submission) without renaming;
 *   SIMD_LANES      4, 8 or 16;
 *   SIMD_ROW_STORES 1: a step paints rows across the lanes with masked stores (then the row
 *                   operations below are needed); 0: each rising lane paints a column span;
 *   simd_f32, simd_i32, simd_mask   the float and int32 vectors and a lane mask;
 * and these operations as macros (helpers they call are named SIMD_NAME(...)):
 *   v_set1_f(x) v_set1_i(x) v_zero_f() v_zero_i() v_iota_f()      broadcasts; 0, 1, 2, ... per lane
 *   v_add_f v_sub_f v_mul_f v_div_f v_min_f v_max_f (a, b)       float arithmetic, one rounding each
 *   v_floor_f(q) v_trunc_f(q)      floor and truncation in float (|q| < 2^31)
 *   v_floor_i(q) v_cvtt_i(q)       floor and truncation to int32; v_cvt_f(i): int32 to float
 *   v_add_i v_sub_i v_mullo_i v_and_i v_or_i v_min_i v_max_i (a, b)   int32 lane operations
 *   v_srli_i(a, n) v_slli_i(a, n)  shifts by a constant
 *   v_flt v_fle v_fgt v_fge (a, b) float compares, v_igt(a, b) int32 compare: masks
 *   v_mand(a, b) v_mandnot(a, b)   a & b, ~a & b on masks
 *   v_add_where(m, a, b) v_sub_where(m, a, b)   a + b (a - b) in the lanes of m, a elsewhere
 *   v_keep_f(m, a) v_keep_i(m, a)  a in the lanes of m, 0 elsewhere
 *   v_select_i(m, a, b)            a in the lanes of m, b elsewhere
 *   v_bits(m)                      the mask as lane bits (unsigned); v_first(n): lanes < n, any n
 *   v_load_first_f(p, n, m) v_store_first_f(p, n, m, x)   the first min(n, LANES) floats at p
 *                                  (m = v_first(n)); lanes past them load 0 and do not store
 *   v_store_i(p, a)                all lanes to int p[SIMD_LANES]
 *   v_gather_cells(c, idx) v_gather_bytes(h, idx)   c[idx] (uint32), h[idx] (uint8) per lane
 *   v_gather_colours(c, at, m)     c[at] (uint32) in the lanes of m at least
 *   v_sub_f64(a, h)                (float)((double)a - h) per lane: one rounding in double, one to
 *                                  float (bilinear's height difference, docs/EFFECTS.md)
 *   v_last_i(a)                    the last lane; V_SHIFT_UP(p, fill, k): lanes up by k (1, 2,
 *                                  4, 8), the first k from fill
 * with SIMD_ROW_STORES 1 also
 *   v_rows(r, y, top)              the lanes with y < r <= top
 *   v_maskstore(p, m, a)           stores the lanes of m at p (uint32)
 *   v_min_where(m, a) v_max_where(m, a)   the least / greatest lane of a in m (m not empty;
 *                                  v_max_where may assume a >= 0)
 *   v_set1_16(x) v_mullo_16 v_add_16 (a, b) v_srli_16(a, n)   16-bit lane operations (fog)
 * Every float operation of SEMANTICS.md is one of these, in the order written here, so each
 * lane evaluates exactly naive's arithmetic (no FMA: -ffp-contract=off). At its end this file
 * #undefs all of the above, leaving the next ISA file a clean slate. */

#if !defined(SIMD_ISA) || !defined(SIMD_LANES) || !defined(SIMD_ROW_STORES) || !defined(simd_f32) ||           \
    !defined(simd_i32) || !defined(simd_mask) || !defined(v_gather_cells) || !defined(V_SHIFT_UP)
#error "simd_strip_tpl.h: the including file defines SIMD_ISA, SIMD_LANES, the types and operations first"
#endif

#ifdef RETRO_COUNT_SAMPLES /* the counting build of one ISA (hmax_pyramid.h), never the kernel's own */
retro_sample_counts retro_simd_counts;
#define SIMD_COUNT_LANES(field, n) (retro_simd_counts.field += (uint64_t)(n))
#else
#define SIMD_COUNT_LANES(field, n) ((void)0)
#endif

/* The frame's constants, broadcast once. */
typedef struct {
    simd_i32 tiles;       /* tiles per row of the packed map */
    simd_i32 S;           /* map size, for row-major indices */
    simd_i32 height;      /* camera height, int32 (retro_simd_check checked the range) */
    simd_i32 H;           /* H */
    simd_f32 fH;          /* H */
    /* mode exact */
    simd_f32 x0, y0;      /* position reduced modulo S */
    simd_f32 half_h;      /* 0.5f * H */
    simd_f32 fS, inv_S;   /* S and 1/S, for the float remainder */
    simd_i32 wrap;        /* S - 1 when S is a power of two */
    /* mode course */
    simd_f32 fK, inv_K;   /* the wrap period S - 1 and its reciprocal */
    simd_f32 cw2;         /* (float)(W / 2) */
    simd_i32 ch2;         /* H / 2 */
} SIMD_NAME(consts);

static void SIMD_NAME(init_consts)(SIMD_NAME(consts) *k, const retro_frame *f, const retro_simd_frame *sf)
{
    k->tiles = v_set1_i(sf->tiles);
    k->S = v_set1_i(f->S);
    k->height = v_set1_i(sf->height);
    k->H = v_set1_i(f->H);
    k->fH = v_set1_f((float)f->H);
    k->x0 = v_set1_f(f->x0);
    k->y0 = v_set1_f(f->y0);
    k->half_h = v_set1_f(f->half_h);
    k->fS = v_set1_f(sf->fS);
    k->inv_S = v_set1_f(sf->inv_S);
    k->wrap = v_set1_i(sf->pow2_mask);
    k->fK = v_set1_f(sf->fK);
    k->inv_K = v_set1_f(sf->inv_K);
    k->cw2 = v_set1_f(f->cw2);
    k->ch2 = v_set1_i(f->ch2);
}

/* floor(q) mod S for a power-of-two S: the two's-complement mask is the non-negative remainder. */
static inline simd_i32 SIMD_NAME(wrap_pow2)(simd_f32 q, const SIMD_NAME(consts) *k)
{
    return v_and_i(v_floor_i(q), k->wrap);
}

/* floor(q) mod S for any S, in float and exact (docs/KERNELS.md, "Wrap"): |floor(q)| < 2^23,
 * so n = floor(floor(q) / S) computed with 1/S is off by at most one, r = floor(q) - n*S is
 * an exact integer, and one conditional +S and one -S put it in [0, S). */
static inline simd_i32 SIMD_NAME(wrap_any)(simd_f32 q, const SIMD_NAME(consts) *k)
{
    simd_f32 fl = v_floor_f(q);
    simd_f32 n = v_floor_f(v_mul_f(fl, k->inv_S));
    simd_f32 r = v_sub_f(fl, v_mul_f(n, k->fS));
    r = v_add_where(v_flt(r, v_zero_f()), r, k->fS);
    r = v_sub_where(v_fge(r, k->fS), r, k->fS);
    return v_cvtt_i(r);
}

/* (int)float_mod(q, S - 1) for |q| < 2^23 (docs/KERNELS.md, "Course wrap"): fmodf by one
 * truncated quotient and one correction, then the course's float_mod steps as written. */
static inline simd_i32 SIMD_NAME(course_wrap)(simd_f32 q, const SIMD_NAME(consts) *k)
{
    const simd_f32 zero = v_zero_f(), K = k->fK;
    simd_f32 n = v_trunc_f(v_mul_f(q, k->inv_K));
    simd_f32 r = v_sub_f(q, v_mul_f(n, K));
    simd_mask neg = v_flt(q, zero);
    /* fmodf: r takes q's sign and |r| < k */
    r = v_add_where(v_mandnot(neg, v_flt(r, zero)), r, K);
    r = v_sub_where(v_mandnot(neg, v_fge(r, K)), r, K);
    r = v_sub_where(v_mand(neg, v_fgt(r, zero)), r, K);
    r = v_add_where(v_mand(neg, v_fle(r, v_sub_f(zero, K))), r, K);
    /* float_mod */
    r = v_add_where(v_flt(r, zero), r, K);
    return v_cvtt_i(v_keep_f(v_flt(r, K), r));
}

/* The heights of cells (i, j). *at receives what the colours need: the packed cell itself, or
 * the row-major index when the maps are read directly. */
static inline simd_i32 SIMD_NAME(heights)(const retro_frame *f, const retro_simd_frame *sf,
                                          const SIMD_NAME(consts) *k, simd_i32 i, simd_i32 j, simd_i32 *at,
                                          const int packed)
{
    if (packed) {
        const simd_i32 low = v_set1_i(RETRO_SIMD_TILE - 1);
        simd_i32 tile = v_add_i(v_mullo_i(v_srli_i(j, 2), k->tiles), v_srli_i(i, 2));
        simd_i32 within = v_or_i(v_slli_i(v_and_i(j, low), 2), v_and_i(i, low));
        *at = v_gather_cells(sf->cells, v_or_i(v_slli_i(tile, 4), within));
        return v_and_i(*at, v_set1_i(RETRO_SIMD_HEIGHT_MASK));
    }
    *at = v_add_i(v_mullo_i(j, k->S), i);
    return v_gather_bytes(f->height_map, *at);
}

/* SEMANTICS.md step 6 on every lane; clamping to [0, H] before truncating is the same
 * three-way case, since truncation is the floor for 0 <= vf. */
static inline simd_i32 SIMD_NAME(exact_project)(simd_i32 h, float kd, const SIMD_NAME(consts) *k)
{
    simd_f32 dh = v_cvt_f(v_sub_i(h, k->height));
    simd_f32 vf = v_add_f(v_mul_f(v_set1_f(kd), dh), k->half_h);
    vf = v_min_f(v_max_f(vf, v_zero_f()), k->fH);
    return v_cvtt_i(vf);
}

/* retro_course_row() on every lane, clamped at RETRO_SIMD_ROW_CLAMP first to stay in int. */
static inline simd_i32 SIMD_NAME(course_project)(simd_i32 h, simd_f32 fd, const SIMD_NAME(consts) *k)
{
    simd_f32 dh = v_cvt_f(v_sub_i(h, k->height));
    simd_f32 t = v_div_f(v_mul_f(k->cw2, dh), fd);
    t = v_min_f(v_max_f(t, v_set1_f(-RETRO_SIMD_ROW_CLAMP)), v_set1_f(RETRO_SIMD_ROW_CLAMP));
    simd_i32 v = v_add_i(v_cvtt_i(t), k->ch2);
    return v_min_i(v_max_i(v, v_zero_i()), k->H);
}

/* What one distance's samples leave for projecting and painting them. */
typedef struct {
    simd_i32 h;      /* the cells' heights (bilinear: unused) */
    simd_f32 dh;     /* bilinear: the filtered height minus the camera's, rounded once */
    simd_i32 at[4];  /* what the colours need: the packed cells or their row-major indices
                      * (bilinear: the four corners, docs/EFFECTS.md's order; else at[0]) */
    simd_f32 tx, ty; /* bilinear: the weights */
} SIMD_NAME(sample_t);

/* Steps 4-5 of SEMANTICS.md at distance d for every lane (with bilinear, docs/EFFECTS.md's
 * filtered height, each float operation in the order written there). */
static inline __attribute__((always_inline)) void
SIMD_NAME(sample)(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k, simd_f32 rx,
                  simd_f32 ry, int d, SIMD_NAME(sample_t) *s, const int pow2, const int packed, const int bilinear)
{
    simd_f32 fd = v_set1_f((float)d);
    simd_f32 qx = v_add_f(k->x0, v_mul_f(fd, rx));
    simd_f32 qy = v_add_f(k->y0, v_mul_f(fd, ry));
    if (!bilinear) {
        simd_i32 i = pow2 ? SIMD_NAME(wrap_pow2)(qx, k) : SIMD_NAME(wrap_any)(qx, k);
        simd_i32 j = pow2 ? SIMD_NAME(wrap_pow2)(qy, k) : SIMD_NAME(wrap_any)(qy, k);
        s->h = SIMD_NAME(heights)(f, sf, k, i, j, &s->at[0], packed);
        return;
    }
    const simd_f32 half = v_set1_f(0.5f), one = v_set1_f(1.0f);
    const simd_i32 one_i = v_set1_i(1);
    simd_f32 px = v_sub_f(qx, half), py = v_sub_f(qy, half);
    simd_i32 i0 = pow2 ? SIMD_NAME(wrap_pow2)(px, k) : SIMD_NAME(wrap_any)(px, k);
    simd_i32 j0 = pow2 ? SIMD_NAME(wrap_pow2)(py, k) : SIMD_NAME(wrap_any)(py, k);
    simd_i32 i1 = v_add_i(i0, one_i), j1 = v_add_i(j0, one_i);
    i1 = v_keep_i(v_igt(k->S, i1), i1); /* i0 + 1 == S wraps to 0 */
    j1 = v_keep_i(v_igt(k->S, j1), j1);
    s->tx = v_sub_f(px, v_floor_f(px));
    s->ty = v_sub_f(py, v_floor_f(py));
    simd_f32 h00 = v_cvt_f(SIMD_NAME(heights)(f, sf, k, i0, j0, &s->at[0], packed));
    simd_f32 h10 = v_cvt_f(SIMD_NAME(heights)(f, sf, k, i1, j0, &s->at[1], packed));
    simd_f32 h01 = v_cvt_f(SIMD_NAME(heights)(f, sf, k, i0, j1, &s->at[2], packed));
    simd_f32 h11 = v_cvt_f(SIMD_NAME(heights)(f, sf, k, i1, j1, &s->at[3], packed));
    simd_f32 wx = v_sub_f(one, s->tx), wy = v_sub_f(one, s->ty);
    simd_f32 hf = v_add_f(v_mul_f(v_add_f(v_mul_f(h00, wx), v_mul_f(h10, s->tx)), wy),
                          v_mul_f(v_add_f(v_mul_f(h01, wx), v_mul_f(h11, s->tx)), s->ty));
    s->dh = v_sub_f64(hf, (double)f->height);
}

/* The row of each lane's sample: step 6 on the height or, with bilinear, on dh. */
static inline simd_i32 SIMD_NAME(project)(const SIMD_NAME(sample_t) *s, float kd, const SIMD_NAME(consts) *k,
                                          const int bilinear)
{
    if (!bilinear)
        return SIMD_NAME(exact_project)(s->h, kd, k);
    simd_f32 vf = v_add_f(v_mul_f(v_set1_f(kd), s->dh), k->half_h);
    vf = v_min_f(v_max_f(vf, v_zero_f()), k->fH);
    return v_cvtt_i(vf);
}

/* One channel of the bilinear colour, its four corners' bytes in float: (int)(value + 0.5f). */
static inline simd_i32 SIMD_NAME(bilerp_channel)(simd_i32 c00, simd_i32 c10, simd_i32 c01, simd_i32 c11,
                                                 const SIMD_NAME(sample_t) *s)
{
    const simd_f32 one = v_set1_f(1.0f);
    simd_f32 wx = v_sub_f(one, s->tx), wy = v_sub_f(one, s->ty);
    simd_f32 v = v_add_f(v_mul_f(v_add_f(v_mul_f(v_cvt_f(c00), wx), v_mul_f(v_cvt_f(c10), s->tx)), wy),
                         v_mul_f(v_add_f(v_mul_f(v_cvt_f(c01), wx), v_mul_f(v_cvt_f(c11), s->tx)), s->ty));
    return v_cvtt_i(v_add_f(v, v_set1_f(0.5f)));
}

/* The colours of the lanes in m (bilinear: filtered per channel, docs/EFFECTS.md). */
static inline simd_i32 SIMD_NAME(colours)(const retro_frame *f, const SIMD_NAME(sample_t) *s, simd_mask m,
                                          const int packed, const int bilinear)
{
    if (!bilinear)
        return packed ? v_and_i(s->at[0], v_set1_i((int)RETRO_SIMD_COLOR_MASK))
                      : v_gather_colours(f->color_map, s->at[0], m);
    const simd_i32 byte = v_set1_i(0xff);
    simd_i32 c[4];
    for (int i = 0; i < 4; i++) /* a packed cell's low byte is its height: the shifts drop it */
        c[i] = packed ? s->at[i] : v_gather_colours(f->color_map, s->at[i], m);
#define SIMD_BYTE(x, sh) v_and_i(v_srli_i(x, sh), byte)
    simd_i32 r = SIMD_NAME(bilerp_channel)(SIMD_BYTE(c[0], 24), SIMD_BYTE(c[1], 24), SIMD_BYTE(c[2], 24),
                                           SIMD_BYTE(c[3], 24), s);
    simd_i32 g = SIMD_NAME(bilerp_channel)(SIMD_BYTE(c[0], 16), SIMD_BYTE(c[1], 16), SIMD_BYTE(c[2], 16),
                                           SIMD_BYTE(c[3], 16), s);
    simd_i32 b = SIMD_NAME(bilerp_channel)(SIMD_BYTE(c[0], 8), SIMD_BYTE(c[1], 8), SIMD_BYTE(c[2], 8),
                                           SIMD_BYTE(c[3], 8), s);
#undef SIMD_BYTE
    return v_or_i(v_or_i(v_slli_i(r, 24), v_slli_i(g, 16)), v_slli_i(b, 8));
}

/* The colour of one lane, from its entry of what heights() left in at. */
static inline uint32_t SIMD_NAME(colour_of)(const retro_frame *f, uint32_t at, const int packed)
{
    return packed ? at & RETRO_SIMD_COLOR_MASK : f->color_map[at];
}

#if SIMD_ROW_STORES
/* Rows lo..hi of columns u0.. get colour where y < row <= top, one masked store per row. */
static void SIMD_NAME(paint_rows)(const retro_frame *f, int u0, int lo, int hi, simd_i32 y, simd_i32 top,
                                  simd_i32 colour)
{
    const size_t W = (size_t)f->W;
    size_t at = (size_t)(f->H - lo) * W + (size_t)u0;
    simd_i32 r = v_set1_i(lo);
    for (int row = lo; row <= hi; row++, at -= W) {
        simd_mask m = v_rows(r, y, top);
        v_maskstore(f->out + at, m, colour);
        RETRO_SIMD_COUNT(f->out, at, v_bits(m));
        r = v_add_i(r, v_set1_i(1));
    }
}

/* Fog toward the sky by weight F/256 (docs/EFFECTS.md) on every lane: R|B and G in 16-bit
 * halves, x*(256-F) + s*F + 128 stays below 2^16, so 16-bit products are exact and the bytes
 * equal retro_fog()'s. */
static inline simd_i32 SIMD_NAME(fog_colours)(simd_i32 c, int F, uint32_t sky)
{
    const simd_i32 low = v_set1_i(0x00ff00ff), byte = v_set1_i(0xff);
    const simd_i32 wc = v_set1_16((short)(256 - F)), ws = v_set1_16((short)F), half = v_set1_16(128);
    simd_i32 rb = v_and_i(v_srli_i(c, 8), low), g = v_and_i(v_srli_i(c, 16), byte);
    simd_i32 srb = v_set1_i((int)((sky >> 8) & 0x00ff00ffu)), sg = v_set1_i((int)((sky >> 16) & 0xffu));
    rb = v_srli_16(v_add_16(v_add_16(v_mullo_16(rb, wc), v_mullo_16(srb, ws)), half), 8);
    g = v_srli_16(v_add_16(v_add_16(v_mullo_16(g, wc), v_mullo_16(sg, ws)), half), 8);
    return v_or_i(v_slli_i(rb, 8), v_slli_i(g, 16));
}
#endif

/* Columns u0..u0+width-1 (width <= SIMD_LANES), front to back: docs/KERNELS.md's mode exact.
 * Lanes past width start full (y = H), so they neither paint nor hold the group back. The n-th
 * distance is n, or dist[n] in mode lod (lod), where vcap is indexed by n as well. With skip,
 * the group probes the pyramid with its smallest y-buffer (simd_common.h's schedule) and jumps
 * over the distances retro_skip_group proves no lane paints; s then holds a distance the loop
 * no longer wants, and sn says which. */
static inline __attribute__((always_inline)) void
SIMD_NAME(exact_group)(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k, int u0,
                       int width, const int pow2, const int packed, const int fog, const int skip, const int lod,
                       const int bilinear)
{
    const simd_mask live = v_first(width);
    const int n_end = lod ? f->ndist : f->D;
    simd_f32 rx = v_load_first_f(f->rx + u0, width, live), ry = v_load_first_f(f->ry + u0, width, live);
    simd_i32 y = v_select_i(live, v_zero_i(), k->H);
    SIMD_NAME(sample_t) s, s_d;
    /* mode lod: dist[n] exists for n < n_end only; a sample past it is loaded but never used */
#define SIMD_DIST(n) (lod ? f->dist[(n) < n_end ? (n) : 1] : (n))
    SIMD_NAME(sample)(f, sf, k, rx, ry, n_end > 1 ? SIMD_DIST(1) : 1, &s, pow2, packed, bilinear);
    retro_simd_grp g;
    int sn = 1, probe = 1, batch = RETRO_SIMD_SKIP_NEAR;
    if (skip)
        RETRO_SIMD_GRP_INIT(&g, f, u0, width);
    for (int n = 1; n < n_end;) {
        if (!v_bits(v_igt(v_set1_i(f->vcap[n]), y)))
            break;
        if (skip && n >= probe) { /* some lane has y < vcap[n] <= H, so the minimum is < H */
            int ys[SIMD_LANES];
            v_store_i(ys, y);
            const int e = RETRO_SIMD_PROBE(&g, f, n, ys, pow2);
            if (e > n) {
                n = e;
                probe = e;
                batch = RETRO_SIMD_SKIP_NEAR;
                continue;
            }
            probe = n + batch;
            batch = batch < RETRO_SIMD_SKIP_FAR ? 2 * batch : batch;
        }
        const int d = SIMD_DIST(n);
        if (skip && sn != n)
            SIMD_NAME(sample)(f, sf, k, rx, ry, d, &s, pow2, packed, bilinear);
        simd_i32 v = SIMD_NAME(project)(&s, f->kd[d], k, bilinear);
        s_d = s;
        /* The next distance's loads issue before the paint branch, so they are in flight when
         * it mispredicts. n + 1 = D samples a valid cell that is never used. */
        SIMD_NAME(sample)(f, sf, k, rx, ry, SIMD_DIST(n + 1), &s, pow2, packed, bilinear);
        sn = n + 1;
        const simd_mask up = v_igt(v, y);
        SIMD_COUNT_LANES(evaluated, width);
        SIMD_COUNT_LANES(painting, __builtin_popcount(v_bits(up)));
        if (v_bits(up)) {
#if SIMD_ROW_STORES
            /* Lanes that do not rise must not widen the rows. */
            int lo = v_min_where(up, y) + 1, hi = v_max_where(up, v);
            simd_i32 c = SIMD_NAME(colours)(f, &s_d, up, packed, bilinear);
            SIMD_NAME(paint_rows)(f, u0, lo, hi, y, v, fog ? SIMD_NAME(fog_colours)(c, f->fog[d], f->sky) : c);
#else
            int ys[SIMD_LANES], vs[SIMD_LANES];
            uint32_t cs[SIMD_LANES];
            v_store_i(ys, y);
            v_store_i(vs, v);
            v_store_i((int *)cs, bilinear ? SIMD_NAME(colours)(f, &s_d, up, packed, 1) : s_d.at[0]);
            for (unsigned m = v_bits(up); m; m &= m - 1) {
                int l = __builtin_ctz(m);
                uint32_t c = bilinear ? cs[l] : SIMD_NAME(colour_of)(f, cs[l], packed);
                retro_simd_span(f, u0 + l, ys[l], vs[l], fog ? retro_fog(c, f->sky, f->fog[d]) : c);
            }
#endif
            y = v_max_i(y, v);
        }
        n++;
    }
#undef SIMD_DIST
#if SIMD_ROW_STORES
    SIMD_NAME(paint_rows)(f, u0, v_min_where(live, y) + 1, f->H, y, k->H, v_set1_i((int)f->sky));
#else
    int ys[SIMD_LANES];
    v_store_i(ys, y);
    for (int l = 0; l < width; l++)
        retro_simd_span(f, u0 + l, ys[l], f->H, f->sky);
#endif
}

/* The y-buffer pass over distances d..d+LANES-1 of column u: lane l paints rows e+1..v_l, as a
 * column span, when v_l exceeds e = max(y, v_<l), an exclusive prefix max in log2(LANES)
 * shifted maxes. Returns the new y-buffer. */
static inline int SIMD_NAME(course_scan)(const retro_frame *f, int u, int y, simd_i32 v, simd_i32 at,
                                         const int packed)
{
    const simd_i32 fill = v_set1_i(y);
    simd_i32 p = v_max_i(v, fill);
    p = v_max_i(p, V_SHIFT_UP(p, fill, 1));
    p = v_max_i(p, V_SHIFT_UP(p, fill, 2));
#if SIMD_LANES > 4
    p = v_max_i(p, V_SHIFT_UP(p, fill, 4));
#endif
#if SIMD_LANES > 8
    p = v_max_i(p, V_SHIFT_UP(p, fill, 8));
#endif
    simd_i32 e = V_SHIFT_UP(p, fill, 1);
    unsigned up = v_bits(v_igt(v, e));
    if (up) {
        int es[SIMD_LANES], vs[SIMD_LANES];
        uint32_t as[SIMD_LANES];
        v_store_i(es, e);
        v_store_i(vs, v);
        v_store_i((int *)as, at);
        for (; up; up &= up - 1) {
            int l = __builtin_ctz(up);
            retro_simd_span(f, u, es[l], vs[l], SIMD_NAME(colour_of)(f, as[l], packed));
        }
    }
    return v_last_i(p);
}

/* The rows of distances d..d+LANES-1 (those below D; the others get v = 0) of the column whose
 * positions qx, qy hold, and in *at what the scan needs for colours. */
static inline __attribute__((always_inline)) simd_i32
SIMD_NAME(course_sample)(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k,
                         const float *qx, const float *qy, int d, simd_i32 *at, const int packed)
{
    const int n = f->D - d;
    const simd_mask live = v_first(n);
    simd_f32 x = v_load_first_f(qx + d, n, live), z = v_load_first_f(qy + d, n, live);
    /* Dead lanes sample cell 0 (their q is 0). */
    simd_i32 h = SIMD_NAME(heights)(f, sf, k, SIMD_NAME(course_wrap)(x, k), SIMD_NAME(course_wrap)(z, k), at,
                                    packed);
    simd_f32 fd = v_add_f(v_set1_f((float)d), v_iota_f());
    return v_keep_i(live, SIMD_NAME(course_project)(h, fd, k));
}

/* Column u of mode course: docs/KERNELS.md's lanes = distances. qx, qy hold the column's
 * positions on entry and the next column's on return: every accumulator is sampled (until the
 * early exit), then all advance, the additions of SEMANTICS.md in their order. */
static inline __attribute__((always_inline)) void
SIMD_NAME(course_column)(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k, float *qx,
                         float *qy, int u, const int packed)
{
    int y = 0;
    simd_i32 at, v = SIMD_NAME(course_sample)(f, sf, k, qx, qy, 1, &at, packed);
    for (int d = 1; d < f->D && y < f->vcap[d]; d += SIMD_LANES) {
        simd_i32 at_d = at, v_d = v;
        /* The next block's loads issue before the scan's branches, as in mode exact. */
        if (d + SIMD_LANES < f->D)
            v = SIMD_NAME(course_sample)(f, sf, k, qx, qy, d + SIMD_LANES, &at, packed);
        y = SIMD_NAME(course_scan)(f, u, y, v_d, at_d, packed);
    }
    retro_simd_span(f, u, y, f->H, f->sky);
    for (int d = 1; d < f->D; d += SIMD_LANES) {
        const int n = f->D - d;
        const simd_mask live = v_first(n);
        simd_f32 x = v_load_first_f(qx + d, n, live), z = v_load_first_f(qy + d, n, live);
        v_store_first_f(qx + d, n, live, v_add_f(x, v_load_first_f(f->sx + d, n, live)));
        v_store_first_f(qy + d, n, live, v_add_f(z, v_load_first_f(f->sy + d, n, live)));
    }
}

/* One instantiation per (lod, bilinear, fog, power-of-two S, packed map), so the inner loops
 * carry no tests of them; skipping (f->simd_skip, opt-in: docs/SKIPPING.md, mode exact without
 * bilinear) is one more. The bilinear ones test the packed map per sample: four loads each
 * outweigh it. */
#define SIMD_EXACT_STRIP(name, lod, bilinear, fog, pow2, packed)                                                  \
    static void SIMD_NAME(name)(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k,     \
                                int u0, int u1)                                                                    \
    {                                                                                                              \
        const int can_skip = !(lod) && !(bilinear);                                                                \
        if (can_skip && f->simd_skip)                                                                              \
            for (int u = u0; u < u1; u += SIMD_LANES)                                                             \
                SIMD_NAME(exact_group)(f, sf, k, u, u1 - u < SIMD_LANES ? u1 - u : SIMD_LANES, pow2, packed, fog,  \
                                       can_skip, lod, bilinear);                                                   \
        else                                                                                                       \
            for (int u = u0; u < u1; u += SIMD_LANES)                                                             \
                SIMD_NAME(exact_group)(f, sf, k, u, u1 - u < SIMD_LANES ? u1 - u : SIMD_LANES, pow2, packed, fog,  \
                                       0, lod, bilinear);                                                          \
    }
#define SIMD_EXACT_STRIPS(lod, fog)                                                                                \
    SIMD_EXACT_STRIP(strip_lod##lod##_fog##fog##_any, lod, 0, fog, 0, 0)                                                         \
    SIMD_EXACT_STRIP(strip_lod##lod##_fog##fog##_pow2, lod, 0, fog, 1, 0)                                                        \
    SIMD_EXACT_STRIP(strip_lod##lod##_fog##fog##_any_packed, lod, 0, fog, 0, 1)                                                  \
    SIMD_EXACT_STRIP(strip_lod##lod##_fog##fog##_pow2_packed, lod, 0, fog, 1, 1)                                                 \
    SIMD_EXACT_STRIP(strip_lod##lod##_fog##fog##_bilinear_any, lod, 1, fog, 0, sf->cells != NULL)                                \
    SIMD_EXACT_STRIP(strip_lod##lod##_fog##fog##_bilinear_pow2, lod, 1, fog, 1, sf->cells != NULL)
SIMD_EXACT_STRIPS(0, 0)
SIMD_EXACT_STRIPS(0, 1)
SIMD_EXACT_STRIPS(1, 0)
SIMD_EXACT_STRIPS(1, 1)
#undef SIMD_EXACT_STRIPS
#undef SIMD_EXACT_STRIP

typedef void (*SIMD_NAME(exact_fn))(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k,
                                    int u0, int u1);
/* [lod][fog][bilinear][pow2][packed] */
#define SIMD_ROW(lod, fog)                                                                                               \
    {{{SIMD_NAME(strip_lod##lod##_fog##fog##_any), SIMD_NAME(strip_lod##lod##_fog##fog##_any_packed)}, {SIMD_NAME(strip_lod##lod##_fog##fog##_pow2), SIMD_NAME(strip_lod##lod##_fog##fog##_pow2_packed)}}, \
     {{SIMD_NAME(strip_lod##lod##_fog##fog##_bilinear_any), SIMD_NAME(strip_lod##lod##_fog##fog##_bilinear_any)},                                        \
      {SIMD_NAME(strip_lod##lod##_fog##fog##_bilinear_pow2), SIMD_NAME(strip_lod##lod##_fog##fog##_bilinear_pow2)}}}
static const SIMD_NAME(exact_fn) SIMD_NAME(exact_strips)[2][2][2][2][2] = {{SIMD_ROW(0, 0), SIMD_ROW(0, 1)},
                                                                         {SIMD_ROW(1, 0), SIMD_ROW(1, 1)}};
#undef SIMD_ROW

static void SIMD_NAME(course_maps)(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k,
                                   float *qx, float *qy, int u0, int u1)
{
    for (int u = u0; u < u1; u++)
        SIMD_NAME(course_column)(f, sf, k, qx, qy, u, 0);
}

static void SIMD_NAME(course_packed)(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k,
                                     float *qx, float *qy, int u0, int u1)
{
    for (int u = u0; u < u1; u++)
        SIMD_NAME(course_column)(f, sf, k, qx, qy, u, 1);
}

/* Columns [u0, u1) of a frame retro_simd_check() accepted. */
static void SIMD_NAME(render_strip)(const retro_frame *f, const retro_simd_frame *sf, float *qx, float *qy, int u0,
                                    int u1)
{
    SIMD_NAME(consts) k;
    SIMD_NAME(init_consts)(&k, f, sf);
    if (f->mode == RETRO_MODE_COURSE) {
        (sf->cells ? SIMD_NAME(course_packed) : SIMD_NAME(course_maps))(f, sf, &k, qx, qy, u0, u1);
        return;
    }
    SIMD_NAME(exact_strips)[f->mode == RETRO_MODE_LOD][(f->fx & RETRO_FX_FOG) != 0][(f->fx & RETRO_FX_BILINEAR) != 0]
                           [sf->pow2_mask >= 0][sf->cells != NULL](f, sf, &k, u0, u1);
}

void RETRO_SIMD_CAT(retro_strip_simd_, SIMD_ISA)(const retro_frame *f, float *qx, float *qy, int u0, int u1)
{
    retro_simd_frame sf;
    if (retro_simd_check(f, &sf))
        SIMD_NAME(render_strip)(f, &sf, qx, qy, u0, u1);
    else
        retro_strip_ybuffer(f, qx, qy, u0, u1);
}

void RETRO_SIMD_CAT(retro_kernel_simd_, SIMD_ISA)(const void *frame, retro_ctx *rc)
{
    const retro_frame *f = frame;
    retro_simd_frame sf;
    if (!retro_simd_check(f, &sf)) {
        retro_kernel_ybuffer(f, rc);
        return;
    }
    retro_simd_use_packed(f, rc, &sf);
    retro_course_start(f, rc->qx, rc->qy);
    SIMD_NAME(render_strip)(f, &sf, rc->qx, rc->qy, 0, f->W);
}

/* The contract's names, so that the next ISA file in the same translation unit starts clean. */
#undef SIMD_COUNT_LANES
#undef SIMD_ISA
#undef SIMD_LANES
#undef SIMD_ROW_STORES
#undef simd_f32
#undef simd_i32
#undef simd_mask
#undef v_set1_f
#undef v_set1_i
#undef v_zero_f
#undef v_zero_i
#undef v_iota_f
#undef v_add_f
#undef v_sub_f
#undef v_mul_f
#undef v_div_f
#undef v_min_f
#undef v_max_f
#undef v_floor_f
#undef v_trunc_f
#undef v_floor_i
#undef v_cvtt_i
#undef v_cvt_f
#undef v_add_i
#undef v_sub_i
#undef v_mullo_i
#undef v_and_i
#undef v_or_i
#undef v_min_i
#undef v_max_i
#undef v_srli_i
#undef v_slli_i
#undef v_flt
#undef v_fle
#undef v_fgt
#undef v_fge
#undef v_igt
#undef v_mand
#undef v_mandnot
#undef v_add_where
#undef v_sub_where
#undef v_keep_f
#undef v_keep_i
#undef v_select_i
#undef v_bits
#undef v_first
#undef v_load_first_f
#undef v_store_first_f
#undef v_store_i
#undef v_gather_cells
#undef v_gather_bytes
#undef v_last_i
#undef v_sub_f64
#undef V_SHIFT_UP
#undef v_gather_colours
#undef v_rows
#undef v_maskstore
#undef v_min_where
#undef v_max_where
#undef v_set1_16
#undef v_mullo_16
#undef v_add_16
#undef v_srli_16
