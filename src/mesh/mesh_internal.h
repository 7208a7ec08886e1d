/* The mesh family's pipeline, one function per stage (docs/MESH.md). Every per-vertex stage
 * computes in binary64 storage; in mode binary32 each operation's result is rounded to
 * binary32 by rn(), which gives exactly binary32 arithmetic (a binary64 result of +, -, *, /
 * or sqrt on binary32 operands rounded to binary32 is the correctly rounded binary32 result). */
#ifndef RETRO_MESH_INTERNAL_H
#define RETRO_MESH_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "retro_mesh.h"

/* The stages keep short names in the source; the linker sees them under the library's prefix
 * (as zlib's Z_PREFIX does), so no name of libretro clashes with a program's own. */
#define mesh_clip_and_draw retro_mesh_clip_and_draw
#define mesh_frame_setup retro_mesh_frame_setup
#define mesh_plane_distances retro_mesh_plane_distances
#define mesh_primitive_assembly retro_mesh_primitive_assembly
#define mesh_project retro_mesh_project
#define mesh_raster_f32 retro_mesh_raster_f32
#define mesh_raster_f64 retro_mesh_raster_f64
#define mesh_raster_int retro_mesh_raster_int
#define mesh_scan_convert retro_mesh_scan_convert
#define mesh_traverse retro_mesh_traverse
#define mesh_vertex_stage retro_mesh_vertex_stage
#define mesh_grid_vertex retro_mesh_grid_vertex
#define mesh_water_add retro_mesh_water_add
#define mesh_water_draw retro_mesh_water_draw
#define mesh_fast_block_avx2 retro_mesh_fast_block_avx2
#define mesh_fast_block_avx512 retro_mesh_fast_block_avx512
#define mesh_frame_passes retro_mesh_frame_passes
#define mesh_omp_render retro_mesh_omp_render
#define mesh_omp_free retro_mesh_omp_free
#define mesh_block_draw retro_mesh_block_draw
#pragma GCC visibility push(hidden)

#define MESH_SUB RETRO_MESH_SUBPIXEL_BITS
#define MESH_ONE ((int64_t)1 << MESH_SUB) /* one pixel in fixed point */
#define MESH_BLOCK 16                     /* squares per block side (frustum culling) */
#define MESH_MAXPOLY 12                   /* 3 vertices + one per clip plane, with room */

/* Vertex attributes, interpolated perspective-correct. */
enum {
    A_SX, A_SY,       /* plan position inside the triangle's square, 0.5 .. 1.5 */
    A_R, A_G, A_B,    /* vertex colour (gouraud); in mode int, times 256 */
    A_NX, A_NY, A_NZ, /* vertex normal (shade); mode int keeps the light (times 256) in A_NX */
    A_ALPHA,          /* water opacity; in mode int, times 256 */
    MESH_NA
};

typedef struct {
    double l, z, e;     /* eye space: lateral (right), depth (forward), height above the eye */
    double h;           /* terrain height at the vertex (water opacity) */
    double a[MESH_NA];
} mesh_vert;

/* Everything the stages read for one frame (built by mesh_frame_setup). */
typedef struct mesh_frame {
    retro_mesh_kernel kernel;
    retro_mesh_mode mode;
    int f32;                  /* round every operation to binary32 */
    int W, H, S;
    double far;               /* far plane: min(D, RETRO_MESH_MAX_FAR) */
    uint32_t sky;
    const uint8_t *h0, *h1;   /* heights; h1 the morph keyframe or NULL */
    double morph_t;
    const uint32_t *color;
    int64_t height;
    double cs, sn, x0, y0;    /* view direction and position reduced mod S */
    double kx, cx, ky, cy;    /* X = kx*l/z + cx, V = ky*e/z + cy */
    double cl, cr, cb, ct;    /* side planes: X >= -0.5, X <= W-0.5, V >= 0.5, V <= H+0.5 */
    double hmin, hmax;        /* vertex heights lie in [hmin, hmax] */
    unsigned fx;              /* scene effects in force (RETRO_FX_*) */
    unsigned mfx;             /* mesh effects (RETRO_MESH_FX_*) */
    const retro_effects *fxp;
    double sun[3], ambient, diffuse;
    double fog_start, fog_end, fog_density;
    int fog_exp;
    int level;                /* water */
    uint32_t water_color;
    double alpha0, alpha_per_unit;
    const uint16_t *fogtab;   /* mode int: fog weight at integer depth 0..far */
    int Ie, Je;               /* the square holding the eye (painter order) */
    /* The fast kernels (mesh_fast.h) draw the z-buffer's image: kernel is then ZBUFFER and
     * fast names the ISA of the block stage (MESH_FAST_*). */
    int fast;
    /* Rows this frame writes, rlo..rhi (1..H, or a band of mesh-omp's water pass), and the
     * band's bottom and top planes for block culling (cb, ct for the whole screen). */
    int rlo, rhi;
    double bcb, bct;
} mesh_frame;

enum { MESH_FAST_NONE = 0, MESH_FAST_AVX2 = 1, MESH_FAST_AVX512 = 2 };
static inline int mesh_row_mine(const struct mesh_frame *f, int r)
{
    return r >= f->rlo && r <= f->rhi;
}
/* A triangle handed from assembly to clipping. */
typedef struct {
    mesh_vert v[3];
    int I, J;        /* its square's cell (mod S) */
    int back;        /* seen from behind (two-sided lighting) */
    int water;
} mesh_tri;

/* A sub-triangle after clipping, ready for scan conversion. */
typedef struct {
    int64_t X[3], Y[3]; /* fixed-point screen position, MESH_SUB fractional bits, V up */
    const mesh_vert *v[3];
    unsigned edges;     /* bit k: edge k -> k+1 lies on an edge of the original triangle */
    const mesh_tri *t;
} mesh_sub;

/* A water triangle kept for the water pass: eye position and opacity per vertex. */
typedef struct {
    double l[3], z[3], e[3], alpha[3];
} mesh_water_tri;

typedef struct {
    int64_t X, Y;
    int ok;             /* inside every plane: X, Y valid */
    unsigned out;       /* bit p: outside plane p */
} mesh_snap;

/* mesh-omp (mesh_omp.c): the blocks traversal would draw, listed in its order (6 ints each: Ia,
 * Ib, Ja, Jb, sx, sy). A list that cannot grow sets oom. */
typedef struct {
    int32_t (*b)[6];
    size_t n, cap;
    int oom;
} mesh_blocks;

struct retro_mesh_ctx {
    mesh_frame f;
    void *depth;          /* W*H float, double or uint32 by mode */
    size_t depth_cap;     /* bytes */
    mesh_vert *grid;      /* (MESH_BLOCK+1)^2 block vertices */
    mesh_snap *snap;
    mesh_water_tri *water; /* water triangles of the frame, sorted before drawing */
    size_t water_n, water_cap;
    void *order;          /* water_key[order_cap] (mesh_render.c) */
    size_t order_cap;
    uint16_t *fogtab;
    size_t fogtab_cap;
    uint32_t *out;
    struct mesh_omp *omp; /* mesh-omp's threads and their contexts (mesh_omp.c), or NULL */
    mesh_blocks *collect; /* non-NULL: traversal lists its blocks here instead of drawing them */
    retro_mesh_stats st;
    int oom;              /* a water buffer could not grow */
    char err[160];
};

static inline double rn(const mesh_frame *f, double x)
{
    return f->f32 ? (double)(float)x : x;
}

/* Stages. */
retro_mesh_err mesh_frame_setup(retro_mesh_ctx *mc, retro_mesh_kernel k, retro_mesh_mode mode,
                                const player_t *p, const ctx_t *c, const retro_effects *fx,
                                unsigned mfx);
void mesh_vertex_stage(const mesh_frame *f, int I, int J, mesh_vert *v);
void mesh_plane_distances(const mesh_frame *f, const mesh_vert *v, double *d);
void mesh_project(const mesh_frame *f, const mesh_vert *v, int64_t *X, int64_t *Y);
/* Grid vertex (I, J) through the vertex stage, classified against the six frustum planes and,
 * when inside all of them, projected and snapped: the record every traversal keeps per vertex. */
void mesh_grid_vertex(const mesh_frame *f, int I, int J, mesh_vert *v, mesh_snap *s);
void mesh_primitive_assembly(retro_mesh_ctx *mc, const mesh_vert *g, const mesh_snap *s, int stride,
                             int a, int I, int J);
void mesh_clip_and_draw(retro_mesh_ctx *mc, const mesh_tri *t, const mesh_snap *s3[3]);
void mesh_scan_convert(retro_mesh_ctx *mc, const mesh_sub *s);
void mesh_raster_f32(retro_mesh_ctx *mc, const mesh_sub *s, int64_t A, const int64_t E0[3],
                     const int64_t dx[3], const int64_t dy[3], int c0, int c1, int r0, int r1);
void mesh_raster_f64(retro_mesh_ctx *mc, const mesh_sub *s, int64_t A, const int64_t E0[3],
                     const int64_t dx[3], const int64_t dy[3], int c0, int c1, int r0, int r1);
void mesh_raster_int(retro_mesh_ctx *mc, const mesh_sub *s, int64_t A, const int64_t E0[3],
                     const int64_t dx[3], const int64_t dy[3], int c0, int c1, int r0, int r1);
void mesh_traverse(retro_mesh_ctx *mc);
/* One listed block (mesh_blocks) through the frame's block stage. */
void mesh_block_draw(retro_mesh_ctx *mc, const int32_t b[6]);
void mesh_water_add(retro_mesh_ctx *mc, const mesh_tri *t);
void mesh_water_draw(retro_mesh_ctx *mc);
/* The fast kernels' block stage: squares [Ia, Ib] x [Ja, Jb] of a block not culled, in the
 * z-buffer's order (traversal.c's block()). */
void mesh_fast_block_avx2(retro_mesh_ctx *mc, int Ia, int Ib, int Ja, int Jb, int sx, int sy);
void mesh_fast_block_avx512(retro_mesh_ctx *mc, int Ia, int Ib, int Ja, int Jb, int sx, int sy);
/* The opaque and water passes of one frame set up in mc (mesh_render.c); mesh-omp runs it on
 * each thread's context. */
void mesh_frame_passes(retro_mesh_ctx *mc);
retro_mesh_err mesh_omp_render(retro_mesh_ctx *mc, int threads);
void mesh_omp_free(struct mesh_omp *o);

#pragma GCC visibility pop

#endif
