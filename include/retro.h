/* retro: one interface, many voxel-space kernels.
 *
 * A frame is defined by ../shared/SEMANTICS.md in two modes. retro_frame_setup() validates the
 * input and computes, once per frame, every constant the formulas need (angle, column rays,
 * per-distance scale, course-mode line endpoints), so kernels differ only in traversal and
 * machinery, never in arithmetic. Every kernel is one row of retro_kernels[]; the CLI, the
 * equivalence checker, the tests and the benchmark all walk that one table.
 */
#ifndef RETRO_H
#define RETRO_H

#include <stddef.h>
#include <stdint.h>

#include "render.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct retro_mesh_state retro_mesh_state;

typedef enum {
    RETRO_MODE_EXACT = 0,  /* the specification done right, binary32 */
    RETRO_MODE_COURSE = 1, /* bit-compatible with the course's reference images */
    RETRO_MODE_TRUTH = 2,  /* mode exact in binary64, the ground truth (docs/ACCURACY.md) */
    RETRO_MODE_FIXED = 3,  /* integer-only fixed point in the inner loop */
    RETRO_MODE_LOD = 4,    /* mode exact at distances whose step grows with distance */
    RETRO_MODE_COUNT
} retro_mode;

#define RETRO_MODE_BIT(m) (1u << (m))

typedef enum {
    RETRO_OK = 0,
    RETRO_EINVAL = 1,      /* input outside the valid domain of SEMANTICS.md */
    RETRO_ENOMEM = 2,      /* scratch memory could not be reserved */
    RETRO_EUNSUPPORTED = 3 /* the kernel lacks this mode or this CPU lacks its ISA */
} retro_err;

/* Limits that make "absurd" precise: beyond them the API reports RETRO_EINVAL. */
#define RETRO_MAX_SCREEN 16384       /* W and H */
#define RETRO_MAX_PIXELS (1L << 26)  /* W*H */
#define RETRO_MAX_MAP 16384          /* S */
#define RETRO_MAX_DISTANCE (1 << 22) /* D */

#define RETRO_FX_POS 24  /* fractional bits of mode fixed's positions */
#define RETRO_FX_PROJ 16 /* fractional bits of mode fixed's projection */
#define RETRO_LOD_DEFAULT 0.02f

/* Everything a kernel may read for one frame. Built by retro_frame_setup(). */
typedef struct retro_frame {
    retro_mode mode;
    int W, H, S, D;
    uint32_t sky;
    const uint8_t *height_map;
    const uint32_t *color_map;
    uint32_t *out;
    int64_t height;    /* camera height, widened so h - height never overflows */
    int hmax;          /* maximum of the height map, for exact early exits */
    /* mode exact */
    float cs, sn;      /* view direction, exact at multiples of 90 degrees */
    float x0, y0;      /* position reduced modulo S */
    float half_w;      /* 0.5f * W */
    float half_h;      /* 0.5f * H */
    const float *rx;   /* [W] column ray x: cs + t_u * sn */
    const float *ry;   /* [W] column ray y: t_u * cs - sn */
    const float *kd;   /* [D] projection scale (0.5f*W)/d, entry 0 unused */
    /* mode course */
    float cw2;         /* (float)(W/2) */
    int ch2;           /* H/2 */
    const float *lx, *ly; /* [D] left endpoint of line d */
    const float *sx, *sy; /* [D] per-column step of line d */
    /* mode truth: exact's quantities in binary64 */
    double cs_d, sn_d, x0_d, y0_d;
    const double *rxd, *ryd; /* [W] */
    const double *kdd;       /* [D] (0.5*W)/d */
    /* mode fixed: positions with RETRO_FX_POS fractional bits, projection with RETRO_FX_PROJ */
    int64_t x0_fx, y0_fx, half_h_fx;
    const int64_t *rx_fx, *ry_fx; /* [W] */
    const int64_t *kd_fx;         /* [D] */
    /* the context's packed colour|height map (src/simd_map.c) when a threaded kernel offers
     * it to its strips, else NULL: strips then read the maps themselves */
    const uint32_t *packed;
    /* per-sample effects in force (RETRO_FX_FOG, RETRO_FX_BILINEAR of retro_scene.h) */
    unsigned fx;
    const uint16_t *fog;  /* [D] fog weight 0..256 at distance d */
    /* mode lod: the sample distances, increasing from 1 */
    const int *dist;
    int ndist;
    /* every mode: vcap[n] = max over n' >= n of the projected row of a sample of height hmax
     * at the n'-th distance (distance n, or dist[n] in mode lod); no sample from there on
     * can rise above it. The entry past the last distance is 0. */
    const int *vcap;
    /* modes exact and lod: the map's maximum-height pyramid when occlusion skipping is on
     * (src/voxel/hmax_pyramid.h, docs/SKIPPING.md), else NULL */
    const struct retro_pyramid *pyr;
    /* with pyr: the SIMD strips skip too, per group of columns (retro_ctx.simd_skip) */
    int simd_skip;
    /* the strip the threaded kernels run: the fastest of the strip table (src/voxel/strips.h)
     * for this frame's mode and effects at the CPU's ISA level, chosen once by setup */
    void (*strip)(const struct retro_frame *f, float *qx, float *qy, int u0, int u1);
} retro_frame;

/* Reusable memory for one rendering thread. Grown by retro_frame_setup(), never per frame
 * once the sizes are reached, freed by retro_ctx_free(). */
typedef struct retro_ctx {
    retro_frame frame;
    float *rx, *ry;     /* capacity cap_w */
    float *kd;          /* capacity cap_d */
    float *lx, *ly, *sx, *sy;
    int *vcap;          /* capacity cap_d + 1 */
    int *ybuf;          /* per-column y-buffer, capacity cap_w */
    float *qx, *qy;     /* course-mode accumulators per distance, capacity cap_d */
    double *rxd, *ryd, *kdd;       /* mode truth */
    int64_t *rx_fx, *ry_fx, *kd_fx; /* mode fixed */
    int *dist;                     /* mode lod, capacity cap_d */
    float lod;          /* mode lod's step growth (0: the default 0.02) */
    const struct retro_effects *fx; /* effects to simulate (include/retro_scene.h), or NULL */
    uint8_t *fx_height;  /* baked maps (morph, shade, water), capacity fx_cap cells */
    uint32_t *fx_color;
    size_t fx_cap;
    void *fx_key;        /* the inputs the baked maps were made from */
    uint16_t *fog;       /* fog weight per distance, capacity cap_d */
    int cap_w, cap_d;
    const uint8_t *hmax_map; /* map whose maximum is cached in hmax_value */
    int hmax_size;
    int hmax_value;
    int threads;        /* requested threads for parallel kernels (0 = default) */
    float *tscratch;    /* pthreads kernel: per-thread course accumulators */
    size_t tscratch_cap;
    void *pool;         /* owned by parallel kernels */
    struct retro_pt_pool *pt_pool; /* the pthreads kernel's workers, kept until retro_ctx_free */
    /* SIMD kernels (src/simd_map.c): colour | height packed into one uint32 per cell, so one
     * load or gather fetches both. Rebuilt only when the map pointers or S change; like the
     * height maximum, call retro_ctx_map_changed() after editing either map in place. */
    uint32_t *simd_cells;               /* capacity simd_cells_cap cells */
    size_t simd_cells_cap;
    const uint8_t *simd_height_map;     /* the maps simd_cells was built from */
    const uint32_t *simd_color_map;
    int simd_map_size;
    int simd_cells_ok;                  /* every colour had a zero low byte: packing is lossless */
    /* Occlusion skipping (docs/SKIPPING.md): the height map's maximum pyramid, cached per map
     * pointer like the maximum; no_skip = 1 turns skipping off (the same bytes, every sample
     * evaluated), for measuring what it saves. */
    struct retro_pyramid *pyr;
    int no_skip;
    /* simd_skip = 1: the SIMD strips (and the threaded kernels running them) skip as well, per
     * group of adjacent columns (docs/SKIPPING.md). Exact, but not yet faster than their plain
     * loop where measured, so off by default; the scalar strips always skip unless no_skip. */
    int simd_skip;
    /* The mesh family's state (src/mesh/family.c): the module's context, the frame's inputs,
     * the last frame's counts; NULL until a mesh frame is set up. */
    struct retro_mesh_state *mesh;
    /* Set by a kernel that fails after setup (out of memory); retro_render returns it. */
    retro_err kernel_err;
} retro_ctx;

void retro_ctx_init(retro_ctx *rc);
void retro_ctx_free(retro_ctx *rc);
/* The map's maximum and packed copies are cached per map pointer: call this after editing a
 * map in place, or after freeing a map and loading another with the same context (its
 * buffers may reuse the old addresses). */
void retro_ctx_map_changed(retro_ctx *rc);

/* Validates (player, ctx) for mode and fills rc->frame. Returns RETRO_OK or an error. */
retro_err retro_frame_setup(retro_ctx *rc, retro_mode mode, const player_t *p, const ctx_t *c);

/* A kernel renders one frame from its family's frame constants (for voxel kernels a
 * const retro_frame *), using rc only for scratch. Each family sets its frames up its own way
 * (retro_family.setup) and hands its kernels a pointer to what it built. */
typedef void (*retro_kernel_fn)(const void *frame, retro_ctx *rc);
/* Renders columns [u0, u1) (0-based). In mode course qx[d], qy[d] hold the positions of column
 * u0 on entry and of column u1 on return. Threaded kernels run strips of single-thread ones. */
typedef void (*retro_strip_fn)(const retro_frame *f, float *qx, float *qy, int u0, int u1);

/* CPU features a kernel may require. */
enum {
    RETRO_CPU_SSE2 = 1u << 0,
    RETRO_CPU_AVX2 = 1u << 1,
    RETRO_CPU_AVX512 = 1u << 2, /* F + BW + VL + DQ */
};

/* Kernel properties. */
enum {
    RETRO_KF_WRITE_ONCE = 1u << 0, /* writes every pixel of out exactly once per frame */
    RETRO_KF_THREADED = 1u << 1,   /* uses more than one thread */
};

/* A family of kernels: kernels that render the same frames from the same frame constants and
 * are checked against one reference kernel. voxel is the first (src/voxel/family.c). */
struct retro_kernel;
struct retro_strip; /* src/voxel/strips.h */

typedef struct retro_family {
    const char *name;                /* "voxel": `retro kernels` groups by it */
    const char *reference;           /* the kernel every other kernel of the family must equal */
    int mode_count;                  /* modes are 0 .. mode_count-1 */
    const char *const *mode_names;   /* [mode_count], for the CLI and refusals */
    unsigned fx;                     /* the effects (RETRO_FX_*) defined for this family */
    /* The mode a frame renders in: mode itself, or what the effects turn it into (voxel: lod
     * effect on mode exact gives mode lod). Decided here once, for checks and setup alike. */
    int (*effective_mode)(int mode, const struct retro_effects *fx);
    /* Validates the inputs for mode and builds the frame constants in rc; *frame is what the
     * family's kernels receive. */
    retro_err (*setup)(retro_ctx *rc, int mode, const player_t *p, const ctx_t *c, const void **frame);
    /* The pixels (of npx) kernel k may differ from the reference by in mode with the effects
     * fx, as the family's documentation explains and bounds (mesh-painter without culling,
     * docs/MESH.md); NULL or 0: byte-identical. The checker reports such differences as
     * measured, not as failures. */
    size_t (*documented_difference)(const struct retro_kernel *k, int mode, const struct retro_effects *fx,
                                    size_t npx);
} retro_family;

typedef struct retro_kernel {
    const char *name;     /* stable: the CLI, verify and the benchmark name kernels by it */
    retro_kernel_fn fn;
    unsigned cpu;         /* RETRO_CPU_* it needs */
    unsigned modes;       /* RETRO_MODE_BIT() of its family's modes it renders */
    unsigned flags;       /* RETRO_KF_* */
    const char *summary;  /* one line for `retro kernels` */
    const struct retro_strip *strip; /* its row of the strip table, or NULL (naive, threaded) */
    unsigned fx;          /* every effect (RETRO_FX_*) it renders */
    const retro_family *family;
} retro_kernel;

extern const retro_kernel retro_kernels[];
extern const size_t retro_kernel_count;
/* Every family, in the order `retro kernels` lists them. */
extern const retro_family *const retro_families[];
extern const size_t retro_family_count;
extern const retro_family retro_family_voxel;
extern const retro_family retro_family_mesh; /* include/retro_mesh.h, docs/MESH.md */

const retro_kernel *retro_kernel_find(const char *name);
const retro_family *retro_family_find(const char *name);
/* The family's reference kernel. */
const retro_kernel *retro_family_reference(const retro_family *fam);
const char *retro_family_mode_name(const retro_family *fam, int mode);
/* Returns 0 and sets *mode when name is one of the family's modes; -1 otherwise. */
int retro_family_mode_parse(const retro_family *fam, const char *name, int *mode);
/* The name of one effect bit (RETRO_FX_*), or "?". */
const char *retro_fx_name(unsigned bit);
/* The fastest voxel kernel this CPU runs for mode (the last capable row of the table). */
const retro_kernel *retro_kernel_best(retro_mode mode);
/* The same among kernels that render the effects of fx (NULL: none). */
/* The fastest kernel of family fam this CPU runs for mode and the effects fx (NULL: none): the
 * last capable row of the table, which lists each family slowest first. */
const retro_kernel *retro_family_best(const retro_family *fam, int mode, const struct retro_effects *fx);
const retro_kernel *retro_kernel_best_fx(retro_mode mode, const struct retro_effects *fx);
int retro_kernel_runs_here(const retro_kernel *k);
int retro_kernel_has_mode(const retro_kernel *k, retro_mode mode);
/* Whether k can render mode with the effects fx on this CPU: RETRO_OK, or RETRO_EUNSUPPORTED
 * with why (one line, "kernel simd-avx2 does not render bilinear") in why[n] if why is not
 * NULL. The one place the mode and the capability are decided. */
retro_err retro_kernel_check(const retro_kernel *k, int mode, const struct retro_effects *fx, char *why,
                             size_t n);

/* CPU features detected once and cached, masked by RETRO_ISA (none|sse2|avx2|avx512) or
 * retro_cpu_limit(). */
unsigned retro_cpu_features(void);
/* Forces a lower ISA level; returns RETRO_EINVAL for an unknown name. */
retro_err retro_cpu_limit(const char *level);
const char *retro_cpu_level_name(unsigned features);
/* The highest ISA level whose features all are in features (an index of retro_isa_names). */
int retro_cpu_level(unsigned features);
/* The ISA levels, lowest first: "none", "sse2", "avx2", "avx512". Spelled here only. */
extern const char *const retro_isa_names[];
extern const int retro_isa_count;

/* Threads a threaded kernel uses with rc: rc->threads if set, else OMP_NUM_THREADS, else the
 * number of cores. */
int retro_ctx_threads(const retro_ctx *rc);
/* One line saying how threads are bound to cores here (hwloc), for reports. */
const char *retro_ctx_binding(retro_ctx *rc);

/* Validates, sets up and renders one frame with kernel k in mode (a mode of k's family),
 * with the effects rc->fx. RETRO_EUNSUPPORTED when retro_kernel_check() refuses. */
retro_err retro_render(retro_ctx *rc, const retro_kernel *k, int mode, const player_t *p, ctx_t *c);

const char *retro_mode_name(retro_mode mode);
/* The voxel family's modes: returns 0 and sets *mode for a mode's name; -1 otherwise. */
int retro_mode_parse(const char *name, retro_mode *mode);
const char *retro_strerror(retro_err e);

#ifdef __cplusplus
}
#endif

#endif
