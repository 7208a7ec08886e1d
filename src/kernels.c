/* The one table of kernels, slowest first: retro_kernel_best() takes the last row this CPU
 * runs. Adding a kernel is one file, one prototype in kernels.h and one row here. */
#include <string.h>

#include "kernels.h"

/* Every mode, the accuracy variants of docs/ACCURACY.md included. */
#define ALL ((1u << RETRO_MODE_COUNT) - 1)
const retro_kernel retro_kernels[] = {
    {"naive", retro_kernel_naive, 0, ALL, 0, "painter, back to front: the reference", NULL},
    {"ybuffer", retro_kernel_ybuffer, 0, ALL, RETRO_KF_WRITE_ONCE,
     "front to back with a per-column y-buffer, each pixel written once", retro_strip_ybuffer},
    {"pthreads", retro_kernel_pthreads, 0, ALL, RETRO_KF_WRITE_ONCE | RETRO_KF_THREADED,
     "column chunks on POSIX threads started per frame: the submission's engine", NULL},
    {"omp", retro_kernel_omp, 0, ALL, RETRO_KF_WRITE_ONCE | RETRO_KF_THREADED,
     "column chunks on every core (OpenMP, pinned with hwloc), each the best strip", NULL},
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

const retro_kernel *retro_kernel_best(retro_mode mode)
{
    const retro_kernel *best = NULL;
    for (size_t i = 0; i < retro_kernel_count; i++)
        if (retro_kernel_runs_here(&retro_kernels[i]) && retro_kernel_has_mode(&retro_kernels[i], mode))
            best = &retro_kernels[i];
    return best;
}

retro_strip_fn retro_best_strip(retro_mode mode)
{
    retro_strip_fn best = NULL;
    for (size_t i = 0; i < retro_kernel_count; i++) {
        const retro_kernel *k = &retro_kernels[i];
        if (k->strip && retro_kernel_runs_here(k) && retro_kernel_has_mode(k, mode))
            best = k->strip;
    }
    return best;
}

retro_err retro_render(retro_ctx *rc, const retro_kernel *k, retro_mode mode, const player_t *p,
                       ctx_t *c)
{
    if (!k)
        return RETRO_EINVAL;
    if (!retro_kernel_has_mode(k, mode) || !retro_kernel_runs_here(k))
        return RETRO_EUNSUPPORTED;
    retro_err e = retro_frame_setup(rc, mode, p, c);
    if (e)
        return e;
    k->fn(&rc->frame, rc);
    return RETRO_OK;
}
