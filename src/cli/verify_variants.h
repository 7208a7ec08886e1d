/* A variant is one way a kernel runs here: the kernel, the thread count for threaded kernels.
 * `retro verify` and the tests compare every variant with naive. */
#ifndef RETRO_VERIFY_VARIANTS_H
#define RETRO_VERIFY_VARIANTS_H

#include "retro.h"

#define VERIFY_MAX_VARIANTS 64
#define VERIFY_CELL_WIDTH 12

typedef struct verify_variant {
    const retro_kernel *kernel;
    int threads;       /* 0 for single-threaded kernels */
    char label[32];    /* column title: name, or name/Nt */
    retro_ctx ctx;     /* reused across cases, as a real caller would */
} verify_variant;

/* Fills vars with every kernel but naive that runs on this CPU (only `only` if not NULL);
 * threaded kernels at 1, 2 and 3 threads. Returns the count. */
int verify_variants(verify_variant *vars, int max, const char *only);
retro_err verify_variant_render(verify_variant *v, retro_mode mode, const player_t *p, ctx_t *c);
void verify_variants_free(verify_variant *vars, int n);

#endif
