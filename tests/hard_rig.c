/* The comparison rig of the hard-case and invariance tests (hard_rig.h). */
#include <criterion/criterion.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hard_rig.h"

const int map_sizes[NMAPS] = {1, 2, 3, 5, 64, 1000};

/* Its low byte is non-zero, so no colour of a valid map and not the sky can equal it: a pixel
 * a kernel failed to write keeps it. */



rig *rig_new(void)
{
    cr_assert(retro_kernel_count <= MAX_KERNELS, "raise MAX_KERNELS to %zu", retro_kernel_count);
    cr_assert(!strcmp(retro_kernels[0].name, "naive"), "row 0 of the table must be naive");
    rig *g = calloc(1, sizeof *g);
    cr_assert(g);
    for (int k = 0; k < MAX_KERNELS; k++)
        for (int t = 0; t <= MAX_THREADS; t++)
            cr_assert(g->rc[k][t] = retro_ctx_new());
    cr_assert_eq(retro_check_init(&g->chk, &retro_family_voxel, NULL, MAX_THREADS), 0);
    return g;
}

void rig_map_changed(rig *g)
{
    for (int k = 0; k < MAX_KERNELS; k++)
        for (int t = 0; t <= MAX_THREADS; t++)
            retro_ctx_map_changed(g->rc[k][t]);
    retro_check_map_changed(&g->chk);
}

/* Frees the rig and fails the test if any case failed; the cases were printed as they failed. */
void rig_done(rig *g, const char *test)
{
    for (int k = 0; k < MAX_KERNELS; k++)
        for (int t = 0; t <= MAX_THREADS; t++)
            retro_ctx_free(g->rc[k][t]);
    retro_check_free(&g->chk);
    free(g->ref);
    free(g->out);
    int failures = g->failures, cases = g->cases, renders = g->renders;
    free(g);
    cr_assert_eq(failures, 0, "%s: %d failures in %d cases (%d renders), listed on stderr", test,
                 failures, cases, renders);
}

void rig_reserve(rig *g, size_t n)
{
    if (n <= g->cap)
        return;
    free(g->ref);
    free(g->out);
    g->ref = malloc(n * sizeof *g->ref);
    g->out = malloc(n * sizeof *g->out);
    cr_assert(g->ref && g->out);
    g->cap = n;
}

void poison(uint32_t *px, size_t n)
{
    for (size_t i = 0; i < n; i++)
        px[i] = POISON;
}

void report(rig *g, const char *fmt, ...)
{
    if (g->failures++ >= MAX_REPORTS)
        return;
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

/* Index of the first pixel where a and b differ, or -1. */
long first_diff(const uint32_t *a, const uint32_t *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (a[i] != b[i])
            return (long)i;
    return -1;
}

retro_err rig_render(rig *g, size_t k, int threads, retro_mode mode, const player_t *p,
                            ctx_t *c)
{
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = mode;
    o.lod = g->lod;
    o.threads = threads;
    g->renders++;
    return retro_render(g->rc[k][threads], &retro_kernels[k], &o, p, c);
}

/* Reports a variant that failed or differs from g->ref. */
static void report_variant(void *user, const retro_check_variant *v, const retro_check_result *r)
{
    rig *g = ((void **)user)[0];
    const char *what = ((void **)user)[1];
    if (!r->ran)
        return;
    g->renders++;
    if (r->err || r->differ) {
        char line[256];
        retro_check_describe(&g->chk, v, r, line, sizeof line);
        report(g, "%s %s: %s", r->err ? "FAIL" : "MISMATCH", what, line);
    }
}

/* Every kernel but naive, at every ISA level and thread count (src/check/), must render g->ref
 * exactly. */
void all_kernels_match(rig *g, const char *what, retro_mode mode, const player_t *p, ctx_t c)
{
    void *user[2] = {g, (void *)what};
    cr_assert_eq(retro_check_against(&g->chk, mode, NULL, p, &c, g->ref, report_variant, user, NULL), RETRO_OK);
}

/* Renders g->ref with naive; returns 0 on success. */
int naive_ref(rig *g, const char *what, retro_mode mode, const player_t *p, ctx_t c)
{
    size_t n = (size_t)c.scr_width * (size_t)c.scr_height;
    rig_reserve(g, n);
    c.out = g->ref;
    poison(g->ref, n);
    retro_err e = rig_render(g, 0, 0, mode, p, &c);
    if (e) {
        report(g, "FAIL %s: naive/%s: %s", what, retro_mode_name(mode), retro_strerror(e));
        return -1;
    }
    for (size_t i = 0; i < n; i++)
        if (g->ref[i] == POISON) {
            report(g, "FAIL %s: naive/%s left pixel %zu unwritten", what, retro_mode_name(mode), i);
            return -1;
        }
    return 0;
}

void describe(char *buf, size_t len, const char *tag, const player_t *p, int W, int H, int D,
                     int S)
{
    snprintf(buf, len, "[%s] x=%.9g (%a) y=%.9g (%a) angle=%d height=%d %dx%d D=%d S=%d", tag,
             (double)p->x, (double)p->x, (double)p->y, (double)p->y, p->angle, p->height, W, H, D, S);
}

/* One hard case: every kernel against naive in every mode valid for it (course needs S >= 2). */
void check_case(rig *g, const char *tag, player_t p, int W, int H, int D, const retro_map *m)
{
    char what[320];
    describe(what, sizeof what, tag, &p, W, H, D, m->size);
    g->cases++;
    for (int mode = 0; mode < RETRO_MODE_COUNT; mode++) {
        if (mode == RETRO_MODE_COURSE && m->size < 2)
            continue;
        ctx_t c = {W, H, m->size, D, SKY, m->height, m->color, NULL};
        if (naive_ref(g, what, (retro_mode)mode, &p, c) == 0)
            all_kernels_match(g, what, (retro_mode)mode, &p, c);
    }
}

/* The small frame most cases use: 37 columns are two 16-lane groups and a partial one, two
 * 32-column thread chunks and a partial one; D = 48 keeps it cheap under the sanitizers. */

player_t pose(float x, float y, int angle, int height)
{
    player_t p = {x, y, angle, height, 0, 0, 0};
    return p;
}

/* Maps of the sizes the cases need: powers of two, tiny ones and non-powers of two. */

void load_maps(retro_map *maps)
{
    for (int i = 0; i < NMAPS; i++)
        noise_map(&maps[i], map_sizes[i], 1000 + (uint64_t)map_sizes[i]);
}

/* Indices into map_sizes[] of a test's maps. */

void free_maps(retro_map *maps, int n)
{
    for (int i = 0; i < n; i++)
        retro_map_free(&maps[i]);
}
