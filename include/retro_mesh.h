/* retro mesh family: the voxel terrain as a triangle mesh through a rasterization pipeline.
 *
 * The image is defined by docs/MESH.md: vertex (i, j) at the cell centre (i + 0.5, j + 0.5)
 * with height h(i, j) on the torus of period S, two triangles per grid square, the voxel
 * family's camera (SEMANTICS.md), so a mesh frame overlays a voxel frame of the same pose.
 * Self-contained: the kernel table will wrap retro_mesh_render() as family `mesh`.
 */
#ifndef RETRO_MESH_H
#define RETRO_MESH_H

#include <stdint.h>

#include "render.h"
#include "retro_scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct retro_mesh_ctx retro_mesh_ctx;

/* A context owns every scratch buffer (depth buffer, vertex grid, water triangles); buffers
 * only grow, so frames allocate nothing once the sizes are reached. NULL when out of memory. */
retro_mesh_ctx *retro_mesh_ctx_new(void);
void retro_mesh_ctx_free(retro_mesh_ctx *mc);

typedef enum {
    RETRO_MESH_BINARY32 = 0, /* the reference: binary32 throughout */
    RETRO_MESH_BINARY64 = 1, /* the same formulas in binary64: the family's truth */
    RETRO_MESH_INT = 2,      /* integer interpolation, depth and colour per fragment */
    RETRO_MESH_MODE_COUNT
} retro_mesh_mode;

typedef enum {
    RETRO_MESH_ZBUFFER = 0, /* reference: depth buffer, front to back in grid order */
    RETRO_MESH_PAINTER = 1, /* no depth buffer: back to front in grid order */
    /* The z-buffer's image, fast (docs/MESH_FAST.md): vertex stage and triangle setup in SIMD
     * lanes, binary32 only. */
    RETRO_MESH_AVX2 = 2,
    RETRO_MESH_AVX512 = 3,
    RETRO_MESH_OMP = 4, /* mesh-avx512 or mesh-avx2 on interleaved row bands, one per thread */
    RETRO_MESH_KERNEL_COUNT
} retro_mesh_kernel;

/* Mesh-only effects: the scene effects of retro_scene.h, and the switch that turns culling
 * off (the family's kernels set it when the scene does not ask for `cull`). */
enum {
    RETRO_MESH_FX_TEXTURE = RETRO_FX_TEXTURE,     /* colour map as a texture, bilinear between vertices */
    RETRO_MESH_FX_GOURAUD = RETRO_FX_GOURAUD,     /* vertex colours interpolated */
    RETRO_MESH_FX_WIREFRAME = RETRO_FX_WIREFRAME, /* only the pixels along triangle edges */
    RETRO_MESH_FX_NOCULL = 1u << 11,              /* back faces drawn too (the `cull` effect off) */
    RETRO_MESH_FX_ALL = RETRO_MESH_FX_TEXTURE | RETRO_MESH_FX_GOURAUD | RETRO_MESH_FX_WIREFRAME |
                        RETRO_MESH_FX_NOCULL
};

typedef struct retro_mesh_opts {
    unsigned flags; /* RETRO_MESH_FX_* */
    int threads;    /* mesh-omp: threads (0: OMP_NUM_THREADS or the core count), 1..64 */
} retro_mesh_opts;

typedef struct retro_mesh_stats {
    uint64_t submitted; /* triangles assembled from the squares of blocks not culled */
    uint64_t culled;    /* of those, dropped as back faces */
    uint64_t clipped_out; /* of those left, nothing inside the frustum after clipping */
    uint64_t rasterized;  /* sub-triangles handed to scan conversion (after clipping) */
    uint64_t fragments;   /* pixel centres covered (top-left rule) */
    uint64_t written;     /* fragments that passed the depth test and were stored */
} retro_mesh_stats;

typedef enum {
    RETRO_MESH_OK = 0,
    RETRO_MESH_EINVAL = 1,     /* input outside the valid domain (message says which) */
    RETRO_MESH_ENOMEM = 2,     /* scratch memory could not be reserved */
    RETRO_MESH_EUNSUPPORTED = 3 /* an effect or mode this kernel cannot render (named) */
} retro_mesh_err;

/* Far-plane cap: the far plane is min(D, RETRO_MESH_MAX_FAR) (docs/MESH.md, "Limits"). */
#define RETRO_MESH_MAX_FAR 4096
/* Sub-pixel bits of the fixed-point screen coordinates. */
#define RETRO_MESH_SUBPIXEL_BITS 8

/* Renders one frame into c->out. fx (scene effects, may be NULL): fog, shade, water, morph,
 * horizon; bilinear and lod are voxel effects and are refused. opts and stats may be NULL.
 * Nothing in c->out is written on error. */
retro_mesh_err retro_mesh_render(retro_mesh_ctx *mc, retro_mesh_kernel kernel, retro_mesh_mode mode,
                                 const player_t *p, const ctx_t *c, const retro_effects *fx,
                                 const retro_mesh_opts *opts, retro_mesh_stats *stats);

/* Through the kernel table (retro_render with a mesh-* kernel): the counts of the context's last
 * mesh frame (NULL before one), and its error message ("" after success). */
struct retro_ctx;
const retro_mesh_stats *retro_mesh_last_stats(const struct retro_ctx *rc);
const char *retro_mesh_last_error(const struct retro_ctx *rc);

/* One line describing the last error of mc ("" after success), naming the refused effect. */
const char *retro_mesh_error(const retro_mesh_ctx *mc);
const char *retro_mesh_mode_name(retro_mesh_mode mode);
const char *retro_mesh_kernel_name(retro_mesh_kernel kernel);
/* The scene effects (RETRO_FX_*) and mesh effects (RETRO_MESH_FX_*) kernel renders in mode. */
unsigned retro_mesh_supported_fx(retro_mesh_kernel kernel, retro_mesh_mode mode);
unsigned retro_mesh_supported_mesh_fx(retro_mesh_kernel kernel, retro_mesh_mode mode);
/* Non-zero when kernel renders mode (the SIMD kernels render binary32 only). */
int retro_mesh_supports_mode(retro_mesh_kernel kernel, retro_mesh_mode mode);
/* The CPU features (RETRO_CPU_* of retro.h) kernel needs; retro_mesh_render refuses it, naming
 * the ISA, when retro_cpu_features() lacks one. mesh-omp needs AVX2 and uses AVX-512 when the
 * CPU level allows it. */
unsigned retro_mesh_kernel_isa(retro_mesh_kernel kernel);

#ifdef __cplusplus
}
#endif

#endif
