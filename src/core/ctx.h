/* The rendering context behind the opaque retro_ctx of include/retro.h: the options of the
 * render in progress, the frame, scratch memory grown by frame setup (never per frame once the
 * sizes are reached), and one small state struct per cache, each defined and built by the file
 * that owns it. Only the library includes this header. */
#ifndef RETRO_CTX_H
#define RETRO_CTX_H

#include <stddef.h>
#include <stdint.h>

#include "retro.h"
#include "frame.h"
#include "effects_bake.h"
#include "hmax_cache.h"
#include "simd_map.h"

struct retro_pyramid;
struct retro_mesh_state;

struct retro_ctx {
    /* The options of the render in progress, taken from its retro_render_opts by
     * retro_render(); fx is cleared when the call returns (the caller owns what it points to). */
    const struct retro_effects *fx;
    float lod;          /* mode lod's step growth, 0 for RETRO_LOD_DEFAULT */
    int threads;        /* threads of threaded kernels (0: the default) */
    int no_skip;        /* occlusion skipping off */

    retro_frame frame;  /* built by the voxel family's setup (frame.c); kernels get it const */
    /* Frame constants, capacity cap_w (per column) or cap_d (per distance). */
    float *rx, *ry;
    float *kd;
    float *lx, *ly, *sx, *sy;
    int *vcap;          /* capacity cap_d + 1 */
    double *rxd, *ryd, *kdd;        /* mode truth */
    int64_t *rx_q, *ry_q, *kd_q; /* mode fixed */
    int *dist;          /* mode lod, capacity cap_d + 1 */
    uint16_t *fog;      /* fog weight per distance */
    int cap_w, cap_d;
    /* Kernel scratch. */
    int *ybuf;          /* per-column y-buffer, capacity cap_w */
    float *qx, *qy;     /* course-mode accumulators per distance, capacity cap_d */
    float *tscratch;    /* pthreads kernel: per-thread course accumulators */
    size_t tscratch_cap;
    void *pool;         /* the omp kernel's thread pool (src/threads/omp_pool.c) */
    struct retro_pt_pool *pt_pool; /* the pthreads kernel's workers (src/threads/pt_pool.c),
                                    * kept until retro_ctx_free */

    /* Caches, each per map: call retro_ctx_map_changed() after editing a map in place. */
    retro_hmax_cache hmax;     /* the height map's maximum (hmax_cache.c) */
    retro_map_scan map_scan;   /* how frame setup fills hmax when stale (NULL: retro_map_max) */
    retro_packed_map packed;   /* the SIMD kernels' packed map (simd_map.c) */
    retro_fx_bake bake;        /* morph, shade and water baked into maps (effects_bake.c) */
    /* occlusion skipping's maximum pyramids (hmax_pyramid.c), allocated on first use: of period
     * S (modes exact, lod) and S - 1 (mode course), so frames of both kinds keep theirs */
    struct retro_pyramid *pyr, *pyr_course;

    /* The mesh family's state (src/mesh/family.c): the module's context, the frame's inputs,
     * the last frame's counts; NULL until a mesh frame is set up. */
    struct retro_mesh_state *mesh;
    /* Set by a kernel that fails after setup (out of memory); retro_render returns it. */
    retro_err kernel_err;
};

/* Takes the options of one render into rc (retro_render, retro_frame_prepare). */
void retro_ctx_take_opts(retro_ctx *rc, const retro_render_opts *o);
/* The caches built from the maps a frame reads (height maximum, packed map, pyramid) are
 * stale: the same pointers hold new cells (a bake rewrote them). The bake itself stays. */
void retro_ctx_maps_rewritten(retro_ctx *rc);
/* The frame rc's last setup built, for tests and tools that inspect its constants. */
const retro_frame *retro_ctx_frame(const retro_ctx *rc);

#endif
