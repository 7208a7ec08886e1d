/* The render entry point: what a caller asks for (retro_render_opts) is checked once, taken
 * into the context, set up by the kernel's family and rendered by the kernel. */
#include <stdio.h>

#include "ctx.h"
#include "retro.h"

retro_render_opts retro_render_opts_default(void)
{
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    return o;
}

int retro_render_mode(const retro_kernel *k, const retro_render_opts *o)
{
    return k->family->effective_mode(o->mode, o->fx);
}

retro_err retro_render_check(const retro_kernel *k, const retro_render_opts *o, char *why, size_t n)
{
    char buf[160];
    if (!why) {
        why = buf;
        n = sizeof buf;
    }
    if (!k || !o) {
        snprintf(why, n, "no kernel or no options");
        return RETRO_EINVAL;
    }
    /* written so that NaN fails too */
    if (!(o->lod >= 0.0f && o->lod <= 100.0f)) {
        snprintf(why, n, "lod rate %g is outside 0 (the default) .. 100", (double)o->lod);
        return RETRO_EINVAL;
    }
    return retro_kernel_check(k, o->mode, o->fx, why, n);
}

void retro_ctx_take_opts(retro_ctx *rc, const retro_render_opts *o)
{
    rc->fx = o->fx;
    rc->lod = o->lod;
    rc->threads = o->threads;
    rc->no_skip = o->no_skip;
}

retro_err retro_render(retro_ctx *rc, const retro_kernel *k, const retro_render_opts *o, const player_t *p,
                       ctx_t *c)
{
    retro_render_opts defaults = RETRO_RENDER_OPTS_DEFAULT;
    if (!o)
        o = &defaults;
    if (!rc)
        return RETRO_EINVAL;
    retro_err e = retro_render_check(k, o, NULL, 0);
    if (e)
        return e;
    retro_ctx_take_opts(rc, o);
    const void *frame = NULL;
    e = k->family->setup(rc, retro_render_mode(k, o), p, c, &frame);
    if (!e) {
        rc->kernel_err = RETRO_OK;
        k->fn(frame, rc);
        e = rc->kernel_err;
    }
    rc->fx = NULL; /* the caller's: read during the call only */
    return e;
}
