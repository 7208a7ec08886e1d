/* retro: one interface, many voxel-space kernels.
 *
 * A frame is defined by ../shared/SEMANTICS.md. retro_render() validates the input and
 * computes, once per frame, every constant the formulas need (angle, column rays, per-distance
 * scale, course-mode line endpoints), so kernels differ only in traversal and machinery, never
 * in arithmetic. Every kernel is one row of retro_kernels[]; the CLI, the equivalence checker,
 * the tests and the benchmark all walk that one table.
 *
 *     retro_ctx *rc = retro_ctx_new();
 *     retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;    (mode exact, no effects)
 *     const retro_kernel *k = retro_family_best(&retro_family_voxel, o.mode, o.fx);
 *     retro_err e = retro_render(rc, k, &o, &player, &course_ctx);  (each frame)
 *     retro_ctx_free(rc);
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

#define RETRO_Q_POS 24  /* fractional bits of mode fixed's positions */
#define RETRO_Q_PROJ 16 /* fractional bits of mode fixed's projection */
#define RETRO_LOD_DEFAULT 0.02f

/* The voxel family's frame constants: everything its kernels read for one frame, built by
 * the library (src/voxel/frame.h defines it). Opaque here: a caller never builds or reads one. */
typedef struct retro_frame retro_frame;

/* A rendering context: reusable scratch memory and per-map caches for one rendering thread,
 * grown on the first frames of a size and then never per frame. Opaque (src/core/ctx.h): make
 * one with retro_ctx_new(), say what to render in a retro_render_opts, free it with
 * retro_ctx_free(). One context per thread that renders. */
typedef struct retro_ctx retro_ctx;

/* NULL when out of memory. */
retro_ctx *retro_ctx_new(void);
/* Frees rc and everything it holds; NULL is allowed. */
void retro_ctx_free(retro_ctx *rc);
/* The map's maximum and packed copies are cached per map pointer: call this after editing a
 * map in place, or after freeing a map and loading another with the same context (its
 * buffers may reuse the old addresses). */
void retro_ctx_map_changed(retro_ctx *rc);

/* What to render, said once per call of retro_render(). Start from RETRO_RENDER_OPTS_DEFAULT
 * (or retro_render_opts_default()) and set what differs. The library reads the options, and
 * the effects fx points to, only during the call: fx may change or go away between calls
 * (baked maps are cached by the effects' values, not by the pointer). */
typedef struct retro_render_opts {
    int mode;        /* a mode of the kernel's family: retro_mode (voxel) or retro_mesh_mode */
    const struct retro_effects *fx; /* effects to simulate (include/io/retro_scene.h) or NULL;
                                     * with RETRO_FX_LOD, voxel mode exact renders as mode lod */
    float lod;       /* mode lod's step growth, given here only: 0 for RETRO_LOD_DEFAULT, else
                      * 0 < lod <= 100 (docs/ACCURACY.md) */
    int threads;     /* threads of threaded kernels; 0: OMP_NUM_THREADS or the core count */
    int no_skip;     /* 1: occlusion skipping off (the same bytes, every sample evaluated) */
} retro_render_opts;

/* Mode exact, no effects, the default lod rate and thread count, scalar skipping on. */
#define RETRO_RENDER_OPTS_DEFAULT {RETRO_MODE_EXACT, NULL, 0.0f, 0, 0}
retro_render_opts retro_render_opts_default(void);

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
    /* its worker threads belong to the context (retro_ctx), not to the process: two contexts
     * rendering with it keep two sets of workers, which compete for the cores */
    RETRO_KF_CTX_THREADS = 1u << 2,
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
    unsigned fx_modes;               /* RETRO_MODE_BIT()s of the modes effects are defined on;
                                      * 0: every mode */
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
/* Whether frames of kernel a on ta threads and of kernel b on tb threads, rendered in turn by
 * two contexts, keep two sets of workers that compete for the cores (one set's idle workers
 * spin while the other renders): different threaded kernels, or one with RETRO_KF_CTX_THREADS,
 * each on more than one thread. Timing such frames in turn measures the competition. */
int retro_kernels_two_pools(const retro_kernel *a, int ta, const retro_kernel *b, int tb);
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
/* The fastest kernel of family fam this CPU runs for mode and the effects fx (NULL: none): the
 * last capable row of the table, which lists each family slowest first. */
const retro_kernel *retro_family_best(const retro_family *fam, int mode, const struct retro_effects *fx);
/* retro_family_best() of the voxel family. */
const retro_kernel *retro_kernel_best_fx(retro_mode mode, const struct retro_effects *fx);
int retro_kernel_runs_here(const retro_kernel *k);
int retro_kernel_has_mode(const retro_kernel *k, retro_mode mode);
/* Whether k can render mode with the effects fx on this CPU: RETRO_OK; RETRO_EINVAL for a
 * mode its family lacks or effects the mode does not define; else RETRO_EUNSUPPORTED. With
 * why (n bytes) it says which mode, effect or ISA level is missing, in one line ("kernel
 * simd-avx2 does not render bilinear"). The one place the mode and the capability are
 * decided: retro_render_check() and retro_render() call it. */
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

/* Threads a threaded kernel uses with rc: the last render's retro_render_opts.threads if set,
 * else OMP_NUM_THREADS, else the number of cores. */
int retro_ctx_threads(const retro_ctx *rc);
/* One line saying how threads are bound to cores here (hwloc), for reports. */
const char *retro_ctx_binding(retro_ctx *rc);

/* The mode a frame of kernel k with the options o renders in: o->mode, or what the effects
 * turn it into (voxel: the lod effect on mode exact gives mode lod). */
int retro_render_mode(const retro_kernel *k, const retro_render_opts *o);
/* Whether retro_render(rc, k, o, ...) would render rather than refuse: retro_kernel_check()
 * of k, o->mode and o->fx, and o's own values (lod, threads); the reason in why as there. */
retro_err retro_render_check(const retro_kernel *k, const retro_render_opts *o, char *why, size_t n);
/* Validates, sets up and renders one frame with kernel k as o says (NULL: the defaults).
 * RETRO_EUNSUPPORTED or RETRO_EINVAL when retro_render_check() refuses (print its why). */
retro_err retro_render(retro_ctx *rc, const retro_kernel *k, const retro_render_opts *o, const player_t *p,
                       ctx_t *c);

const char *retro_mode_name(retro_mode mode);
/* The voxel family's modes: returns 0 and sets *mode for a mode's name; -1 otherwise. */
int retro_mode_parse(const char *name, retro_mode *mode);
const char *retro_strerror(retro_err e);

#ifdef __cplusplus
}
#endif

#endif
