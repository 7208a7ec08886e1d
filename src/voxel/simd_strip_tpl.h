/* The SIMD strips of the voxel kernels, written once for every vector width (zlib-ng's *_tpl.h
 * style): included at the end of src/arch/<arch>/kernel_simd_<isa>.c, which defines what
 * differs between ISAs, then writes the group and column loops and the two entry points
 * retro_strip_simd_<isa> and retro_kernel_simd_<isa>, from three parts it includes
 * (simd_sample_tpl.h, simd_exact_tpl.h, simd_course_tpl.h). The design is docs/KERNELS.md's
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
 *   v_srli_i(a, n) v_slli_i(a, n)  shifts by a constant; v_srl_i(a, n): by an int, every lane
 *   v_byte_i(a, b)                 byte b (0..3, a constant) of each lane, as an int32 0..255
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
 *   v_gather_bytes_pad(h, idx)     h[idx] (uint8) per lane, free to read h[idx + 1..idx + 3] too
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
 * and optionally
 *   v_compress_store(p, m, a)      the lanes of m, in lane order, to p[0..popcount(m) - 1]; it may
 *                                  write all of p[0..SIMD_LANES - 1] (mode course's span lists)
 *   SIMD_TILE_BLOCK 1 with SIMD_NAME(tile_block)(out, at, W, tile, th): mode course's tile
 *                   columns (LANES of them, th entries apart) rows r..r+LANES-1 into out, row
 *                   r + k at out + at - k*W, by a transpose in registers; without it the tile
 *                   is copied pixel by pixel
 * Every float operation of SEMANTICS.md is one of these, in the order written here, so each
 * lane evaluates exactly naive's arithmetic (no FMA: -ffp-contract=off). At its end this file
 * #undefs all of the above, leaving the next ISA file a clean slate. */

#if !defined(SIMD_ISA) || !defined(SIMD_LANES) || !defined(SIMD_ROW_STORES) || !defined(simd_f32) ||           \
    !defined(simd_i32) || !defined(simd_mask) || !defined(v_gather_cells) || !defined(V_SHIFT_UP) ||           \
    !defined(v_byte_i)
#error "simd_strip_tpl.h: the including file defines SIMD_ISA, SIMD_LANES, the types and operations first"
#endif

#ifdef RETRO_COUNT_SAMPLES /* the counting build of one ISA (hmax_pyramid.h), never the kernel's own */
retro_sample_counts retro_simd_counts;
#define SIMD_COUNT_LANES(field, n) (retro_simd_counts.field += (uint64_t)(n))
#else
#define SIMD_COUNT_LANES(field, n) ((void)0)
#endif

/* The parts, in order: what a sample reads and computes, the group's occlusion probe, the
 * group of mode exact and lod, the column of mode course. */
#include "simd_sample_tpl.h"
#include "simd_skip_tpl.h"
#include "simd_exact_tpl.h"
#include "simd_course_tpl.h"

/* The width of a group starting at column u: up to the next column whose pixel begins a
 * SIMD_LANES * 4-byte block of out's first row, or SIMD_LANES when u's pixel does. Groups after
 * it then store each row as one aligned vector (one 64-byte line for 16 lanes), not a vector
 * split across two lines (docs/KERNELS.md, "Where the stores go"). Which columns share a group
 * changes where the group may skip, never a pixel. */
RETRO_SIMD_INLINE int SIMD_NAME(head)(const retro_frame *f, int u)
{
    const int m = (int)(((uintptr_t)(f->out + u) / sizeof *f->out) % SIMD_LANES);
    return m ? SIMD_LANES - m : SIMD_LANES;
}

/* Columns [u0, u1) in groups aligned by head, RETRO_SIMD_SKY_GROUPS groups at a time, each
 * run's sky then painted across it (sky_rows). */
RETRO_SIMD_INLINE void SIMD_NAME(exact_run)(const retro_frame *f, const retro_simd_frame *sf,
                                            const SIMD_NAME(consts) *k, int u0, int u1, const int pow2,
                                            const int packed, const int fog, const int skip, const int lod,
                                            const int bilinear)
{
    simd_i32 top[RETRO_SIMD_SKY_GROUPS];
    int u = u0, w = SIMD_NAME(head)(f, u0);
    while (u < u1) {
        const int c = u, first = w;
        int g = 0;
        for (; u < u1 && g < RETRO_SIMD_SKY_GROUPS; u += w, w = SIMD_LANES, g++)
            SIMD_NAME(exact_group)(f, sf, k, u, u1 - u < w ? u1 - u : w, pow2, packed, fog, skip, lod, bilinear,
                                   &top[g]);
#if SIMD_ROW_STORES
        SIMD_NAME(sky_rows)(f, c, first, top, g, k);
#else
        (void)c;
        (void)first;
#endif
    }
}

/* One instantiation per (lod, bilinear, fog, power-of-two S, packed map), so the inner loops
 * carry no tests of them; occlusion skipping (a frame with a pyramid, docs/SKIPPING.md) is one
 * more. The bilinear ones test the packed map per sample: four loads each outweigh it. */
#define SIMD_EXACT_STRIP(name, lod, bilinear, fog, pow2, packed)                                        \
    static void SIMD_NAME(name)(const retro_frame *f, const retro_simd_frame *sf,                       \
                                const SIMD_NAME(consts) *k, int u0, int u1)                              \
    {                                                                                                    \
        if (f->pyr)                                                                                      \
            SIMD_NAME(exact_run)(f, sf, k, u0, u1, pow2, packed, fog, 1, lod, bilinear);                \
        else                                                                                             \
            SIMD_NAME(exact_run)(f, sf, k, u0, u1, pow2, packed, fog, 0, lod, bilinear);                \
    }
/* The strips of one (lod, fog), named strip_lod<0|1>_fog<0|1>_<map reads>. */
#define SIMD_STRIP_NAME(lod, fog, rest) strip_lod##lod##_fog##fog##_##rest
#define SIMD_EXACT_STRIPS(lod, fog)                                                                      \
    SIMD_EXACT_STRIP(SIMD_STRIP_NAME(lod, fog, any), lod, 0, fog, 0, 0)                                 \
    SIMD_EXACT_STRIP(SIMD_STRIP_NAME(lod, fog, pow2), lod, 0, fog, 1, 0)                                \
    SIMD_EXACT_STRIP(SIMD_STRIP_NAME(lod, fog, any_packed), lod, 0, fog, 0, 1)                          \
    SIMD_EXACT_STRIP(SIMD_STRIP_NAME(lod, fog, pow2_packed), lod, 0, fog, 1, 1)                         \
    SIMD_EXACT_STRIP(SIMD_STRIP_NAME(lod, fog, bilinear_any), lod, 1, fog, 0, sf->cells != NULL)        \
    SIMD_EXACT_STRIP(SIMD_STRIP_NAME(lod, fog, bilinear_pow2), lod, 1, fog, 1, sf->cells != NULL)
SIMD_EXACT_STRIPS(0, 0)
SIMD_EXACT_STRIPS(0, 1)
SIMD_EXACT_STRIPS(1, 0)
SIMD_EXACT_STRIPS(1, 1)
#undef SIMD_EXACT_STRIPS
#undef SIMD_EXACT_STRIP

typedef void (*SIMD_NAME(exact_fn))(const retro_frame *f, const retro_simd_frame *sf,
                                    const SIMD_NAME(consts) *k, int u0, int u1);
/* The strips of one (lod, fog) as [bilinear][pow2][packed]; the bilinear ones test the map
 * themselves. */
#define SIMD_STRIP(lod, fog, rest) SIMD_NAME(SIMD_STRIP_NAME(lod, fog, rest))
#define SIMD_STRIPS_OF(lod, fog)                                                                         \
    {{{SIMD_STRIP(lod, fog, any), SIMD_STRIP(lod, fog, any_packed)},                                    \
      {SIMD_STRIP(lod, fog, pow2), SIMD_STRIP(lod, fog, pow2_packed)}},                                  \
     {{SIMD_STRIP(lod, fog, bilinear_any), SIMD_STRIP(lod, fog, bilinear_any)},                         \
      {SIMD_STRIP(lod, fog, bilinear_pow2), SIMD_STRIP(lod, fog, bilinear_pow2)}}}
/* [lod][fog][bilinear][pow2][packed] */
static const SIMD_NAME(exact_fn) SIMD_NAME(exact_strips)[2][2][2][2][2] = {
    {SIMD_STRIPS_OF(0, 0), SIMD_STRIPS_OF(0, 1)},
    {SIMD_STRIPS_OF(1, 0), SIMD_STRIPS_OF(1, 1)},
};
#undef SIMD_STRIPS_OF
#undef SIMD_STRIP
#undef SIMD_STRIP_NAME

/* Mode course's strip: it reads the maps directly (retro_simd_use_packed). The tile of
 * course_group lives on the strip's stack (no allocation per frame, nothing shared between
 * threads); frames taller than RETRO_SIMD_COURSE_ROWS paint straight into out. */
static void SIMD_NAME(course_strip)(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k,
                                    float *qx, float *qy, int u0, int u1)
{
    uint32_t tile[RETRO_SIMD_COURSE_GROUP * (RETRO_SIMD_COURSE_ROWS + SIMD_LANES)];
    const size_t th = (size_t)f->H + SIMD_LANES;
    uint32_t *t = f->H <= RETRO_SIMD_COURSE_ROWS ? tile : NULL;
    for (int u = u0; u < u1; u += RETRO_SIMD_COURSE_GROUP)
        SIMD_NAME(course_group)(f, sf, k, qx, qy, t, th, u,
                                u1 - u < RETRO_SIMD_COURSE_GROUP ? u1 - u : RETRO_SIMD_COURSE_GROUP);
}

/* Columns [u0, u1) of a frame retro_simd_check() accepted. */
static void SIMD_NAME(render_strip)(const retro_frame *f, const retro_simd_frame *sf, float *qx, float *qy, int u0,
                                    int u1)
{
    SIMD_NAME(consts) k;
    SIMD_NAME(init_consts)(&k, f, sf);
    if (f->mode == RETRO_MODE_COURSE) {
        SIMD_NAME(course_strip)(f, sf, &k, qx, qy, u0, u1);
        return;
    }
    const int lod = f->mode == RETRO_MODE_LOD, fog = (f->fx & RETRO_FX_FOG) != 0;
    const int bilinear = (f->fx & RETRO_FX_BILINEAR) != 0;
    SIMD_NAME(exact_strips)[lod][fog][bilinear][sf->pow2_mask >= 0][sf->cells != NULL](f, sf, &k, u0, u1);
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
#undef SIMD_TILE_BLOCK
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
#undef v_byte_i
#undef v_srl_i
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
#undef v_gather_bytes_pad
#undef v_last_i
#undef v_sub_f64
#undef V_SHIFT_UP
#undef v_gather_colours
#undef v_rows
#undef v_maskstore
#undef v_compress_store
#undef v_min_where
#undef v_max_where
#undef v_set1_16
#undef v_mullo_16
#undef v_add_16
#undef v_srli_16
