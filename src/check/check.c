/* The equivalence checker: see check.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "retro_scene.h"

static int add(retro_check *chk, const retro_kernel *k, int level, int threads)
{
    if (chk->n >= RETRO_CHECK_MAX_VARIANTS)
        return 0;
    retro_check_variant *v = &chk->v[chk->n];
    v->kernel = k;
    v->level = level;
    v->threads = threads;
    if (threads)
        snprintf(v->label, sizeof v->label, "%s/%s/%dt", k->name, retro_isa_names[level], threads);
    else
        snprintf(v->label, sizeof v->label, "%s/%s", k->name, retro_isa_names[level]);
    if (!(v->ctx = retro_ctx_new()))
        return -1;
    chk->n++;
    return 0;
}

int retro_check_init(retro_check *chk, const retro_family *fam, const char *only, int max_threads)
{
    memset(chk, 0, sizeof *chk);
    chk->family = fam;
    chk->level = retro_cpu_level(retro_cpu_features());
    chk->select_level = chk->select_threads = -1;
    int found = 0, oom = !(chk->ref_ctx = retro_ctx_new());
    for (int l = 0; l <= chk->level; l++) {
        retro_cpu_limit(retro_isa_names[l]);
        for (size_t i = 0; i < retro_kernel_count; i++) {
            const retro_kernel *k = &retro_kernels[i];
            if (k->family != fam || !strcmp(k->name, fam->reference) || (only && strcmp(only, k->name)))
                continue;
            found = 1;
            if (!retro_kernel_runs_here(k))
                continue;
            if (k->flags & RETRO_KF_THREADED)
                for (int t = 1; t <= max_threads; t++)
                    oom |= add(chk, k, l, t);
            else
                oom |= add(chk, k, l, 0);
        }
    }
    retro_cpu_limit(retro_isa_names[chk->level]);
    return oom ? -2 : only && !found ? -1 : 0;
}

void retro_check_free(retro_check *chk)
{
    for (int i = 0; i < chk->n; i++)
        retro_ctx_free(chk->v[i].ctx);
    retro_ctx_free(chk->ref_ctx);
    free(chk->ref);
    free(chk->out);
    memset(chk, 0, sizeof *chk);
}

static void poison(uint32_t *out, size_t n)
{
    for (size_t i = 0; i < n; i++)
        out[i] = RETRO_CHECK_POISON;
}

static int reserve(retro_check *chk, size_t n)
{
    if (n <= chk->cap)
        return 0;
    uint32_t *a = realloc(chk->ref, n * sizeof *a);
    if (!a)
        return -1;
    chk->ref = a;
    uint32_t *b = realloc(chk->out, n * sizeof *b);
    if (!b)
        return -1;
    chk->out = b;
    chk->cap = n;
    return 0;
}

/* What every render of the checker asks for. */
static retro_render_opts opts(const retro_check *chk, int mode, const retro_effects *fx, int threads)
{
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = mode;
    o.fx = fx;
    o.lod = chk->lod;
    o.threads = threads;
    return o;
}

static void run_variant(retro_check *chk, retro_check_variant *v, int mode, const retro_effects *fx,
                        const player_t *p, ctx_t c, retro_check_result *r)
{
    size_t n = (size_t)c.scr_width * (size_t)c.scr_height;
    memset(r, 0, sizeof *r);
    if ((chk->select_level >= 0 && v->level != chk->select_level) ||
        (chk->select_threads >= 0 && v->threads && v->threads != chk->select_threads))
        return;
    retro_cpu_limit(retro_isa_names[v->level]);
    retro_render_opts o = opts(chk, mode, fx, v->threads);
    if (retro_render_check(v->kernel, &o, NULL, 0) != RETRO_OK) {
        retro_cpu_limit(retro_isa_names[chk->level]);
        return;
    }
    r->ran = 1;
    c.out = chk->out;
    poison(chk->out, n);
    r->err = retro_render(v->ctx, v->kernel, &o, p, &c);
    retro_cpu_limit(retro_isa_names[chk->level]);
    if (r->err)
        return;
    const retro_family *fam = v->kernel->family;
    r->documented = fam->documented_difference ? fam->documented_difference(v->kernel, mode, fx, n) : 0;
    for (size_t i = 0; i < n; i++)
        if (chk->out[i] != chk->ref[i] && r->differ++ == 0) {
            r->u = (int)(i % (size_t)c.scr_width) + 1;
            r->r = c.scr_height - (int)(i / (size_t)c.scr_width);
            r->got = chk->out[i];
            r->want = chk->ref[i];
        }
}

retro_err retro_check_frame(retro_check *chk, int mode, const retro_effects *fx, const player_t *p,
                            const ctx_t *c, retro_check_report report, void *user, int *bad)
{
    if (c->scr_width < 1 || c->scr_height < 1 || c->scr_width > RETRO_MAX_SCREEN ||
        c->scr_height > RETRO_MAX_SCREEN || (long)c->scr_width * c->scr_height > RETRO_MAX_PIXELS)
        return RETRO_EINVAL;
    size_t n = (size_t)c->scr_width * (size_t)c->scr_height;
    if (reserve(chk, n))
        return RETRO_ENOMEM;
    ctx_t rc = *c;
    rc.out = chk->ref;
    poison(chk->ref, n);
    retro_render_opts o = opts(chk, mode, fx, 0);
    retro_err e = retro_render(chk->ref_ctx, retro_family_reference(chk->family), &o, p, &rc);
    if (e)
        return e;
    for (size_t i = 0; i < n; i++)
        if (chk->ref[i] == RETRO_CHECK_POISON)
            return RETRO_EINVAL; /* the reference must write every pixel */
    return retro_check_against(chk, mode, fx, p, c, chk->ref, report, user, bad);
}

retro_err retro_check_against(retro_check *chk, int mode, const retro_effects *fx, const player_t *p,
                              const ctx_t *c, const uint32_t *ref, retro_check_report report, void *user,
                              int *bad)
{
    size_t n = (size_t)c->scr_width * (size_t)c->scr_height;
    if (reserve(chk, n))
        return RETRO_ENOMEM;
    if (ref != chk->ref)
        memcpy(chk->ref, ref, n * sizeof *ref);
    for (int i = 0; i < chk->n; i++) {
        retro_check_result r;
        run_variant(chk, &chk->v[i], mode, fx, p, *c, &r);
        if (r.ran && (r.err || r.differ > r.documented) && bad)
            (*bad)++;
        if (report)
            report(user, &chk->v[i], &r);
    }
    return RETRO_OK;
}

void retro_check_map_changed(retro_check *chk)
{
    retro_ctx_map_changed(chk->ref_ctx);
    for (int i = 0; i < chk->n; i++)
        retro_ctx_map_changed(chk->v[i].ctx);
}

void retro_check_describe(const retro_check *chk, const retro_check_variant *v, const retro_check_result *r,
                          char *buf, size_t n)
{
    if (!r->ran)
        snprintf(buf, n, "%s: not run", v->label);
    else if (r->err)
        snprintf(buf, n, "%s: %s", v->label, retro_strerror(r->err));
    else if (r->differ && r->differ <= r->documented)
        snprintf(buf, n, "%s: %zu px differ, as documented (at most %zu here), first (u=%d, r=%d)", v->label,
                 r->differ, r->documented, r->u, r->r);
    else if (r->differ)
        snprintf(buf, n, "%s: %zu px differ, first (u=%d, r=%d): %08x, %s %08x", v->label, r->differ, r->u, r->r,
                 r->got, chk->family->reference, r->want);
    else
        snprintf(buf, n, "%s: identical", v->label);
}
