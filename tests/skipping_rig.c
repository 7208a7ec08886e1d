/* The rig of tests/test_skipping.c (skipping_rig.h). */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ctx.h"
#include "skip_course.h"
#include "skipping_rig.h"

/* The kernels whose strips skip (the SIMD strips, and the threaded kernels running them). */
static const char *const skipping_kernels[NSIMD] = {"simd-sse2", "simd-avx2", "simd-avx512", "pthreads", "omp"};

typedef struct {
    const retro_check *chk;
    const char *what;
    int ran, with_pyramid;
    char first[200];
} report_ctx;

static void report(void *user, const retro_check_variant *v, const retro_check_result *r)
{
    report_ctx *rep = user;
    rep->ran += r->ran;
    const retro_frame *f = retro_ctx_frame(v->ctx);
    rep->with_pyramid += r->ran && f->pyr;
    if (r->ran && (r->err || r->differ) && !rep->first[0])
        retro_check_describe(rep->chk, v, r, rep->first, sizeof rep->first);
}

trio *rig_open(void)
{
    trio *g = calloc(1, sizeof *g);
    cr_assert(g);
    for (int i = 0; i < NCTX; i++)
        cr_assert(g->rc[i] = retro_ctx_new());
    for (int k = 0; k < NSIMD; k++) {
        cr_assert_eq(retro_check_init(&g->chk[k], &retro_family_voxel, skipping_kernels[k], 2), 0, "%s",
                     skipping_kernels[k]);
    }
    return g;
}

void rig_close(trio *g)
{
    for (int i = 0; i < NCTX; i++)
        retro_ctx_free(g->rc[i]);
    for (int k = 0; k < NSIMD; k++)
        retro_check_free(&g->chk[k]);
    free(g->ref);
    free(g->out);
    free(g);
}

/* A new map may reuse a freed one's address: the contexts must forget their caches. */
void new_map(trio *g)
{
    for (int i = 0; i < NCTX; i++)
        retro_ctx_map_changed(g->rc[i]);
    for (int k = 0; k < NSIMD; k++)
        retro_check_map_changed(&g->chk[k]);
}

/* Colours that differ from cell to cell, so a frame that reads the wrong cell shows it. */
static void paint_cells(retro_map *m)
{
    for (int j = 0; j < m->size; j++)
        for (int i = 0; i < m->size; i++)
            m->color[(size_t)j * (size_t)m->size + (size_t)i] =
                ((uint32_t)i * 73856093u ^ (uint32_t)j * 19349663u ^ 0x9e3779b9u) << 8;
}

void make_map(retro_map *m, int S)
{
    char err[256];
    cr_assert_eq(retro_map_alloc(m, S, err, sizeof err), 0, "%s", err);
    paint_cells(m);
}

/* Renders pose p with naive, ybuffer skipping and ybuffer not skipping, and compares; mode is
 * exact (as the effects decide: lod with RETRO_FX_LOD) or course; lod is mode lod's rate
 * (retro_render_opts.lod), 0 for the default. */
static void check_one(trio *g, const char *what, const retro_map *m, player_t p, int W, int H, int D,
                      const retro_effects *fx, float lod, retro_mode mode)
{
    size_t n = (size_t)W * (size_t)H;
    if (n > g->cap) {
        g->ref = realloc(g->ref, n * sizeof *g->ref);
        g->out = realloc(g->out, n * sizeof *g->out);
        cr_assert(g->ref && g->out);
        g->cap = n;
    }
    ctx_t c = {W, H, m->size, D, 0x66a3ff00u, m->height, m->color, g->ref};
    const retro_kernel *naive = retro_kernel_find("naive"), *yb = retro_kernel_find("ybuffer");
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = (int)mode;
    o.fx = fx;
    o.lod = lod;
    cr_assert_eq(retro_render(g->rc[NAIVE], naive, &o, &p, &c), RETRO_OK, "%s", what);
    for (int k = SKIP; k <= NOSKIP; k++) {
        c.out = g->out;
        memset(g->out, 0xab, n * sizeof *g->out);
        o.no_skip = k == NOSKIP;
        cr_assert_eq(retro_render(g->rc[k], yb, &o, &p, &c), RETRO_OK, "%s", what);
        if (memcmp(g->ref, g->out, n * sizeof *g->out)) {
            size_t i = 0;
            while (g->ref[i] == g->out[i])
                i++;
            cr_assert_fail("%s, skipping %s: S %d, (%.9g, %.9g), angle %d, height %d, %dx%d, D %d: "
                           "pixel (%zu, %zu) is %08x, naive %08x",
                           what, k == SKIP ? "on" : "off", m->size, (double)p.x, (double)p.y, p.angle, p.height, W,
                           H, D, i % (size_t)W + 1, (size_t)H - i / (size_t)W, g->out[i], g->ref[i]);
        }
    }
    /* The skipping context took the skipping path whenever the map (the course's torus of
     * side S - 1 in mode course) has pyramid levels and, in mode course, the drift is bounded. */
    const struct retro_pyramid *skip_pyr = retro_ctx_frame(g->rc[SKIP])->pyr;
    const int course = mode == RETRO_MODE_COURSE;
    const int expect_pyr = course ? m->size - 1 > 4 && retro_course_margin(p.x, p.y, W, D) > 0 : m->size > 4;
    cr_assert_eq(skip_pyr != NULL, expect_pyr, "%s: pyramid %s for S %d", what, skip_pyr ? "present" : "absent",
                 m->size);
    cr_assert_null(retro_ctx_frame(g->rc[NOSKIP])->pyr, "%s: no_skip still had a pyramid", what);
    /* The kernels whose strips skip, at every level and thread count, against naive. */
    for (int k = 0; k < NSIMD; k++) {
        report_ctx rep = {&g->chk[k], what, 0, 0, ""};
        int bad = 0;
        g->chk[k].lod = lod;
        cr_assert_eq(retro_check_frame(&g->chk[k], mode, fx, &p, &c, report, &rep, &bad), RETRO_OK, "%s", what);
        cr_assert_eq(bad, 0, "%s: S %d, (%.9g, %.9g), angle %d, height %d, %dx%d, D %d: %s", what, m->size,
                     (double)p.x, (double)p.y, p.angle, p.height, W, H, D, rep.first);
        /* each of them rendered with the pyramid, so it had the chance to skip */
        cr_assert_eq(rep.with_pyramid, expect_pyr ? rep.ran : 0, "%s: %d of %d variants had a pyramid", what,
                     rep.with_pyramid, rep.ran);
        g->variants += rep.ran;
    }
    g->frames++;
    g->skipped_frames += skip_pyr != NULL;
}

/* Each case in mode exact, then in mode lod (the lod effect on the same effects) at a rate
 * taking the smallest steps allowed, the default's, or ones longer than the finest blocks,
 * in turn: mode lod's runs are of sample indices whose distances grow (hmax_pyramid.h); and
 * without effects in mode course (maps of S >= 2), whose torus is of side S - 1, and in modes
 * truth and fixed (skip_wide.h), which have no effects. */
void check(trio *g, const char *what, const retro_map *m, player_t p, int W, int H, int D,
           const retro_effects *fx)
{
    check_one(g, what, m, p, W, H, D, fx, 0, RETRO_MODE_EXACT);
    if (!fx && m->size >= 2) {
        char course[160];
        snprintf(course, sizeof course, "%s (mode course)", what);
        check_one(g, course, m, p, W, H, D, NULL, 0, RETRO_MODE_COURSE);
    }
    if (!fx) {
        static const retro_mode wide[] = {RETRO_MODE_TRUTH, RETRO_MODE_FIXED};
        for (int i = 0; i < 2; i++) {
            char label[160];
            snprintf(label, sizeof label, "%s (mode %s)", what, wide[i] == RETRO_MODE_TRUTH ? "truth" : "fixed");
            check_one(g, label, m, p, W, H, D, NULL, 0, wide[i]);
        }
    }
    static const float rates[] = {0.02f, 0.3f, 0.001f};
    const float rate = rates[g->frames % 3];
    retro_effects lod;
    if (fx)
        lod = *fx;
    else
        memset(&lod, 0, sizeof lod);
    lod.flags |= RETRO_FX_LOD;
    char label[160];
    snprintf(label, sizeof label, "%s (mode lod %g)", what, (double)rate);
    check_one(g, label, m, p, W, H, D, &lod, rate, RETRO_MODE_EXACT);
}

player_t at(float x, float y, int angle, int height)
{
    player_t p = {x, y, angle, height, 0, 0, 0};
    return p;
}

