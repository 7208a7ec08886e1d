/* The equivalence checker (in the spirit of dav1d's checkasm): every variant this CPU runs —
 * kernel x ISA level (each level lowered in turn) x thread count — against its family's
 * reference, byte for byte, on output poisoned first. `retro verify`, the Criterion tests, the
 * hard-case rig and the fuzz target all call retro_check_frame(); none keeps its own loop. */
#ifndef RETRO_CHECK_H
#define RETRO_CHECK_H

#include <stddef.h>
#include <stdint.h>

#include "retro.h"

#define RETRO_CHECK_MAX_VARIANTS 64
/* The value every pixel holds before a render. Its low byte is non-zero, so no colour of a
 * valid map, no sky and no colour the fuzz target makes (low bytes up to 0x7f) equals it: a
 * pixel a kernel failed to write keeps it. */
#define RETRO_CHECK_POISON 0xababababu

/* One way a kernel runs here. */
typedef struct retro_check_variant {
    const retro_kernel *kernel;
    int level;       /* ISA level (index of retro_isa_names) forced while it renders */
    int threads;     /* threads for a threaded kernel, 0 for the others */
    char label[40];  /* "omp/avx2/2t", "simd-sse2/avx512": kernel/level[/threads] */
    retro_ctx *ctx;  /* reused from frame to frame, as a real caller would */
} retro_check_variant;

/* What one variant did with one frame. */
typedef struct retro_check_result {
    int ran;         /* 0: the variant cannot render this mode or these effects (not an error) */
    retro_err err;   /* the library's status when it ran */
    size_t differ;   /* pixels that differ from the reference */
    size_t documented; /* differing pixels the family documents and bounds for this variant
                        * (retro_family.documented_difference): up to that many is no failure */
    int u, r;        /* first differing pixel: column 1..W, row 1..H from the bottom */
    uint32_t got, want;
} retro_check_result;

typedef struct retro_check {
    const retro_family *family;
    retro_check_variant v[RETRO_CHECK_MAX_VARIANTS];
    int n;
    int level;         /* the ISA level in force when the set was made, restored after each render */
    retro_ctx *ref_ctx; /* the reference kernel's context */
    uint32_t *ref, *out; /* the last frame's reference and variant images (W*H) */
    size_t cap;
    /* Variants to run, -1 for all (retro_check_init's choice): only this ISA level, only
     * threaded kernels at this thread count. The fuzz target lets its input choose. */
    int select_level, select_threads;
    float lod;         /* mode lod's step growth every render asks for (retro_render_opts.lod), 0 default */
} retro_check;

/* Fills chk with every kernel of fam but its reference that runs here, at every ISA level up
 * to the one in force, threaded kernels at 1..max_threads threads. only: a kernel name, or
 * NULL for all. Returns 0, -1 when only names no kernel of fam, -2 when out of memory (free
 * chk either way). */
int retro_check_init(retro_check *chk, const retro_family *fam, const char *only, int max_threads);
void retro_check_free(retro_check *chk);

/* Called once per variant and frame; the images are chk->ref and chk->out. */
typedef void (*retro_check_report)(void *user, const retro_check_variant *v, const retro_check_result *r);

/* Renders (mode, fx, p, c) with the reference into chk->ref, then every variant into chk->out,
 * comparing each; c->out is ignored. Returns the reference's status (a reference that leaves a
 * pixel unwritten is RETRO_EINVAL, its variants then not run) and adds the number of
 * variants that failed or differ by more than their family documents to *bad. */
retro_err retro_check_frame(retro_check *chk, int mode, const struct retro_effects *fx, const player_t *p,
                            const ctx_t *c, retro_check_report report, void *user, int *bad);

/* The same against a reference image the caller made (W*H, copied to chk->ref): invariance
 * tests compare every variant at one pose with the reference at another. Returns RETRO_OK
 * or RETRO_ENOMEM. */
retro_err retro_check_against(retro_check *chk, int mode, const struct retro_effects *fx, const player_t *p,
                              const ctx_t *c, const uint32_t *ref, retro_check_report report, void *user,
                              int *bad);

/* After editing a map in place: every context's per-map caches (retro_ctx_map_changed). */
void retro_check_map_changed(retro_check *chk);

/* One line for a failing result: "omp/avx2/2t: 12 px differ, first (u=3, r=7): 00ff0000, naive 00fe0000". */
void retro_check_describe(const retro_check *chk, const retro_check_variant *v, const retro_check_result *r,
                          char *buf, size_t n);

#endif
