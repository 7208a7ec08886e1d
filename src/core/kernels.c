/* The one table of kernels, slowest first: retro_kernel_best() takes the last row this CPU
 * runs. Adding a kernel is one file, one prototype in kernels.h and one row here. */
#include <string.h>

#include "kernels.h"
#include "retro_scene.h"

/* Every mode, the accuracy variants of docs/ACCURACY.md included. */
#define ALL ((1u << RETRO_MODE_COUNT) - 1)
/* The per-sample effects a kernel implements in its inner loop (docs/EFFECTS.md). */
#define FX RETRO_FX_PER_SAMPLE
#define EXACT RETRO_MODE_BIT(RETRO_MODE_EXACT)
#define EXACT_COURSE (EXACT | RETRO_MODE_BIT(RETRO_MODE_COURSE))
/* Each ISA level includes the ones below it, as the files are compiled (cpu.c levels). */
#define ISA_SSE2 RETRO_CPU_SSE2
#define ISA_AVX2 (ISA_SSE2 | RETRO_CPU_AVX2)
#define ISA_AVX512 (ISA_AVX2 | RETRO_CPU_AVX512)

const retro_kernel retro_kernels[] = {
    {"naive", retro_kernel_naive, 0, ALL, 0, "painter, back to front: the reference", NULL, FX},
    {"ybuffer", retro_kernel_ybuffer, 0, ALL, RETRO_KF_WRITE_ONCE,
     "front to back with a per-column y-buffer, each pixel written once", retro_strip_ybuffer, FX},
    {"simd-sse2", retro_kernel_simd_sse2, ISA_SSE2, EXACT_COURSE, RETRO_KF_WRITE_ONCE,
     "y-buffer, 4 columns per SSE2 vector, packed map, stores lane by lane",
     retro_strip_simd_sse2, RETRO_FX_FOG},
    {"simd-avx2", retro_kernel_simd_avx2, ISA_AVX2, EXACT_COURSE, RETRO_KF_WRITE_ONCE,
     "y-buffer, 8 columns per AVX2 vector, packed map, masked row stores",
     retro_strip_simd_avx2, RETRO_FX_FOG},
    {"simd-avx512", retro_kernel_simd_avx512, ISA_AVX512, EXACT_COURSE, RETRO_KF_WRITE_ONCE,
     "y-buffer, 16 columns per AVX-512 vector, packed map, masked row stores",
     retro_strip_simd_avx512, RETRO_FX_FOG},
    /* Threaded kernels stay last: they run the strip of the best single-thread row above. */
    {"pthreads", retro_kernel_pthreads, 0, ALL, RETRO_KF_WRITE_ONCE | RETRO_KF_THREADED,
     "column chunks on POSIX threads started per frame: the submission's engine", NULL, FX},
    {"omp", retro_kernel_omp, 0, ALL, RETRO_KF_WRITE_ONCE | RETRO_KF_THREADED,
     "column chunks on every core (OpenMP, pinned with hwloc), each the best strip", NULL, FX},
};

const size_t retro_kernel_count = sizeof retro_kernels / sizeof retro_kernels[0];

const retro_kernel *retro_kernel_find(const char *name)
{
    for (size_t i = 0; i < retro_kernel_count; i++)
        if (!strcmp(retro_kernels[i].name, name))
            return &retro_kernels[i];
    return NULL;
}

int retro_kernel_runs_here(const retro_kernel *k)
{
    return (k->cpu & retro_cpu_features()) == k->cpu;
}

int retro_kernel_has_mode(const retro_kernel *k, retro_mode mode)
{
    return (unsigned)mode < RETRO_MODE_COUNT && (k->modes & RETRO_MODE_BIT(mode)) != 0;
}

/* The per-sample effects fx asks of a kernel. */
static unsigned per_sample(const retro_effects *fx)
{
    return fx ? fx->flags & RETRO_FX_PER_SAMPLE : 0;
}

/* An effect set with lod renders in mode lod. */
static retro_mode effective_mode(retro_mode mode, const retro_effects *fx)
{
    return fx && (fx->flags & RETRO_FX_LOD) && mode == RETRO_MODE_EXACT ? RETRO_MODE_LOD : mode;
}

const retro_kernel *retro_kernel_best_fx(retro_mode mode, const retro_effects *fx)
{
    const retro_kernel *best = NULL;
    mode = effective_mode(mode, fx);
    for (size_t i = 0; i < retro_kernel_count; i++) {
        const retro_kernel *k = &retro_kernels[i];
        if (retro_kernel_runs_here(k) && retro_kernel_has_mode(k, mode) && !(per_sample(fx) & ~k->fx))
            best = k;
    }
    return best;
}

const retro_kernel *retro_kernel_best(retro_mode mode)
{
    return retro_kernel_best_fx(mode, NULL);
}

retro_strip_fn retro_best_strip(retro_mode mode, unsigned fx)
{
    retro_strip_fn best = NULL;
    for (size_t i = 0; i < retro_kernel_count; i++) {
        const retro_kernel *k = &retro_kernels[i];
        if (k->strip && retro_kernel_runs_here(k) && retro_kernel_has_mode(k, mode) && !(fx & ~k->fx))
            best = k->strip;
    }
    return best;
}

retro_err retro_render(retro_ctx *rc, const retro_kernel *k, retro_mode mode, const player_t *p,
                       ctx_t *c)
{
    if (!k)
        return RETRO_EINVAL;
    mode = effective_mode(mode, rc->fx);
    if (!retro_kernel_has_mode(k, mode) || !retro_kernel_runs_here(k) || (per_sample(rc->fx) & ~k->fx))
        return RETRO_EUNSUPPORTED;
    retro_err e = retro_frame_setup(rc, mode, p, c);
    if (e)
        return e;
    k->fn(&rc->frame, rc);
    return RETRO_OK;
}
