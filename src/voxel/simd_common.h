/* Shared by the SIMD kernels (kernel_simd_<isa>.c): the per-frame decision whether the vector
 * path can reproduce SEMANTICS.md exactly, the packed map it reads, and the write-counting hook
 * for vector pixel stores. The strips themselves are simd_strip_tpl.h; the design is
 * docs/KERNELS.md's "simd-sse2, simd-avx2, simd-avx512". */
#ifndef RETRO_SIMD_COMMON_H
#define RETRO_SIMD_COMMON_H

#include <stddef.h>
#include <stdint.h>

#include "retro.h"
#include "retro_internal.h"
#include "retro_scene.h"

/* Occlusion skipping (docs/SKIPPING.md, "The SIMD strips"): the group probe is
 * simd_skip_tpl.h's. The submission has no pyramid (its frames never carry one). */
#ifndef RETRO_SUBMISSION
#include "hmax_pyramid.h"
#endif

/* The packed map is tiled: 4x4 cells of 4 bytes fill one 64-byte line, so the 16 columns of a
 * vector, which sample along a line across the view, and the next distances, which move along
 * it, hit a few lines whatever the view angle (row-major rows put a vector looking along x on
 * 16 lines). Cell (i, j) is at retro_simd_tiled(i, j, T) with T = ceil(S / 4) tiles a row; the
 * padding cells of a partial tile are never read. */
#define RETRO_SIMD_TILE 4
/* The packed buffer holds the tiled cells, then (but in the submission) the tiled quads. */
#ifdef RETRO_SUBMISSION
#define RETRO_SIMD_REGIONS 1
#else
#define RETRO_SIMD_REGIONS 2
#endif

static inline size_t retro_simd_tiled(size_t i, size_t j, size_t tiles)
{
    return ((j / RETRO_SIMD_TILE) * tiles + i / RETRO_SIMD_TILE) * RETRO_SIMD_TILE * RETRO_SIMD_TILE +
           (j % RETRO_SIMD_TILE) * RETRO_SIMD_TILE + i % RETRO_SIMD_TILE;
}

/* What a vector kernel needs beyond retro_frame, valid for one frame. */
typedef struct retro_simd_frame {
    const uint32_t *cells; /* the tiled packed map (colour | height per cell), or NULL: read
                            * height_map and color_map (row-major) one lane at a time */
    const uint32_t *quads; /* with cells: per cell (i, j), tiled alike, the heights of (i, j),
                            * (i+1, j), (i, j+1), (i+1, j+1) (wrapped) in bytes 0..3: a bilinear
                            * sample's four heights in one load; NULL in the submission */
    int tiles;             /* T: tiles per row of the packed map */
    int32_t height;        /* camera height: h - height fits in int32 for every h in 0..255 */
    int pow2_mask;         /* S - 1 when S is a power of two (wrap by masking), else -1 */
    float fS;              /* (float)S, exact */
    float inv_S;           /* 1.0f / S, for the remainder in float */
    float fK;              /* mode course: the wrap period S - 1, exact */
    float inv_K;           /* mode course: 1.0f / (S - 1), for fmodf in float */
} retro_simd_frame;

/* Mode course: the vector fmodf is exact while |q| < 2^23; retro_simd_check() sends a frame
 * to the scalar kernel unless every line keeps its accumulators within this bound. */
#define RETRO_SIMD_COURSE_BOUND 4194304.0 /* 2^22, leaving 2^22 for the rounding of W steps */
/* Mode course's columns paint into a tile of RETRO_SIMD_COURSE_GROUP columns (64 bytes of a row
 * of out) and RETRO_SIMD_COURSE_ROWS rows at most, on the strip's stack (simd_course_tpl.h's
 * course_group): about 70 KB (80 KB with the chains' span lists), kept that small because the
 * strip may run on a thread whose stack is small (musl's default is 128 KB). Taller frames paint into out. */
#define RETRO_SIMD_COURSE_GROUP 16
#define RETRO_SIMD_COURSE_ROWS 1080
/* Mode course walks this many of a group's columns in one loop (course_cols), independent
 * chains whose gathers overlap; it divides RETRO_SIMD_COURSE_GROUP. */
#define RETRO_SIMD_COURSE_CHAINS 4
/* Mode course: the spans a tile column lists before it paints the finished ones (a few KB of
 * the strip's stack per chain). hard/course_span_lists renders columns with more. */
#define RETRO_SIMD_SPAN_LIST 256
/* Mode course: a truncated row beyond +-2^20 clamps to H or 0 whatever H/2 adds (H <= 2^14),
 * so the vector kernels clamp the float there and convert it in int32. */
#define RETRO_SIMD_ROW_CLAMP 1048576.0f

/* Fills sf (cells = f->packed: the maps themselves unless a threaded kernel offered its
 * context's packed map) and returns 1 when the vector path is
 * exact for f; returns 0 when the caller must use the scalar y-buffer instead: a mode other
 * than exact and course, per-sample effects other than fog, a camera height near INT_MIN, or in mode course
 * a position so far out that fmodf needs more than float. Touches no context, so strips of
 * threaded kernels can call it. */
int retro_simd_check(const retro_frame *f, retro_simd_frame *sf);

/* Points sf at rc's packed map, rebuilt only when the maps or S changed since the last frame
 * rendered with rc; leaves sf->cells NULL if a colour has a non-zero low byte (the packing
 * would lose it) or memory is short. */
void retro_simd_use_packed(const retro_frame *f, retro_ctx *rc, retro_simd_frame *sf);

/* The colour bits of a packed cell: SEMANTICS.md colours have a zero low byte, which the
 * packing fills with the height. */
#define RETRO_SIMD_COLOR_MASK 0xffffff00u
#define RETRO_SIMD_HEIGHT_MASK 0xffu

/* Rows y+1..v of column u (0-based) get colour, each store through RETRO_PUT: the paint of
 * the kernels whose lanes do not lie along a row of out. The frame's fields are read once:
 * a pixel store may alias them, which would reload them every row. */
static inline void retro_simd_span(const retro_frame *f, int u, int y, int v, uint32_t colour)
{
    uint32_t *out = f->out;
    const ptrdiff_t W = f->W;
    ptrdiff_t i = (ptrdiff_t)(f->H - y - 1) * W + u;
    for (int r = y + 1; r <= v; r++, i -= W)
        RETRO_PUT(out, (size_t)i, colour);
}

/* Vector pixel stores bypass RETRO_PUT, so the counting build reports each stored lane of a
 * masked store at base + lane to the same counter RETRO_PUT feeds. */
#ifdef RETRO_COUNT_WRITES
static inline void retro_simd_count(const uint32_t *out, size_t base, unsigned lanes)
{
    for (; lanes; lanes &= lanes - 1)
        retro_count_write(out, base + (size_t)__builtin_ctz(lanes));
}
#define RETRO_SIMD_COUNT(out, base, lanes) retro_simd_count((out), (base), (lanes))
#else
#define RETRO_SIMD_COUNT(out, base, lanes) ((void)0)
#endif

/* The probe schedule of a group that skips, as the scalar strip's: after a probe that cannot
 * skip, RETRO_SKIP_NEAR distances are evaluated before the next, doubling up to
 * RETRO_SKIP_FAR while probes keep failing, back to RETRO_SKIP_NEAR after a skip. */
enum { RETRO_SIMD_SKIP_NEAR = 4, RETRO_SIMD_SKIP_FAR = 32 };

/* Painting steps a group of modes exact and lod holds before storing them in one pass over their
 * rows (simd_exact_tpl.h, paint_batch): more steps share a row's store, but each row then picks
 * its colour among more. 4 measured faster than 2 and no slower than 8 (docs/KERNELS.md). */
enum { RETRO_SIMD_PAINT_BATCH = 4 };

/* Distances a group of modes exact and lod has loaded ahead of the one it projects (without
 * bilinear): a step's loads issue before the paint branches of the steps before it, so when
 * those mispredict the loads are already in flight. 3 and 4 measured faster than 1 and 2, 6
 * no faster; with bilinear, whose samples hold seven vectors, more than 1 was slower
 * (docs/studies/KERNEL_STUDIES.md, "Loading ahead"). */
enum { RETRO_SIMD_AHEAD = 4 };

/* Groups a strip of modes exact and lod renders before painting the sky above them row by row
 * (simd_strip_tpl.h, exact_run): a row's stores then cover up to this many groups' columns
 * side by side, and their final y-buffers stay on the stack (4 KiB at 16 lanes). */
enum { RETRO_SIMD_SKY_GROUPS = 64 };

/* The names simd_strip_tpl.h makes, and the helpers of an ISA file: SIMD_NAME(x) is <isa>_x for
 * the SIMD_ISA the file defines (sse2, avx2, avx512), expanded where it is used. */
#define RETRO_SIMD_CAT_(a, b) a##b
#define RETRO_SIMD_CAT(a, b) RETRO_SIMD_CAT_(a, b)
#define SIMD_NAME(x) RETRO_SIMD_CAT(RETRO_SIMD_CAT(SIMD_ISA, _), x)
/* The helpers of the strips' inner loops: inlined even where the compiler would rather not,
 * so each instantiation's constant choices fold away. */
#define RETRO_SIMD_INLINE static inline __attribute__((always_inline))

#endif
