#include <stdio.h>
#include <string.h>

#include "verify_variants.h"

static void add(verify_variant *vars, int *n, int max, const retro_kernel *k, int threads)
{
    if (*n >= max)
        return;
    verify_variant *v = &vars[(*n)++];
    v->kernel = k;
    v->threads = threads;
    if (threads)
        snprintf(v->label, sizeof v->label, "%s/%dt", k->name, threads);
    else
        snprintf(v->label, sizeof v->label, "%s", k->name);
    retro_ctx_init(&v->ctx);
    v->ctx.threads = threads;
}

int verify_variants(verify_variant *vars, int max, const char *only)
{
    int n = 0;
    for (size_t i = 0; i < retro_kernel_count; i++) {
        const retro_kernel *k = &retro_kernels[i];
        if (!strcmp(k->name, "naive") || !retro_kernel_runs_here(k) || (only && strcmp(only, k->name)))
            continue;
        if (k->flags & RETRO_KF_THREADED)
            for (int t = 1; t <= 3; t++)
                add(vars, &n, max, k, t);
        else
            add(vars, &n, max, k, 0);
    }
    return n;
}

retro_err verify_variant_render(verify_variant *v, retro_mode mode, const player_t *p, ctx_t *c)
{
    return retro_render(&v->ctx, v->kernel, mode, p, c);
}

void verify_variants_free(verify_variant *vars, int n)
{
    for (int i = 0; i < n; i++)
        retro_ctx_free(&vars[i].ctx);
}
