/* Occlusion skipping, counted and probed (docs/SKIPPING.md): the counting build of ybuffer
 * shows that skipping skips and that exactly the same samples paint with and without it, and
 * retro_skip_column, the interface the SIMD strips will use, is checked on its own against a
 * brute force. Counts only, never timings. Frames: tests/test_skipping.c. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cone_map.h"
#include "ctx.h"
#include "frame.h"
#include "hmax_pyramid.h"
#include "kernels.h"
#include "retro_scene.h"
#include "skip_wide.h"
#include "test_util.h"

static player_t at(float x, float y, int angle, int height)
{
    player_t p = {x, y, angle, height, 0, 0, 0};
    return p;
}

static void make_map(retro_map *m, int S)
{
    char err[256];
    cr_assert_eq(retro_map_alloc(m, S, err, sizeof err), 0, "%s", err);
    for (int j = 0; j < S; j++)
        for (int i = 0; i < S; i++)
            m->color[(size_t)j * (size_t)S + (size_t)i] = ((uint32_t)i * 73856093u ^ (uint32_t)j * 19349663u) << 8;
}

/* The samples of one frame as the counting build of ybuffer sees them. */
static retro_sample_counts count_fx(retro_ctx *rc, retro_mode mode, int no_skip, const retro_map *m, player_t p,
                                    int W, int H, int D, uint32_t *out, const retro_effects *fx)
{
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = (int)mode;
    o.no_skip = no_skip;
    o.fx = fx;
    retro_kernel counted = *retro_kernel_find("ybuffer");
    counted.fn = retro_kernel_ybuffer_counted;
    ctx_t c = {W, H, m->size, D, 0, m->height, m->color, out};
    memset(&retro_ybuffer_counts, 0, sizeof retro_ybuffer_counts);
    cr_assert_eq(retro_render(rc, &counted, &o, &p, &c), RETRO_OK);
    cr_assert(no_skip || retro_ctx_frame(rc)->pyr, "the frame had no pyramid");
    return retro_ybuffer_counts;
}

static retro_sample_counts count(retro_ctx *rc, retro_mode mode, int no_skip, const retro_map *m, player_t p, int W,
                                 int H, int D, uint32_t *out)
{
    return count_fx(rc, mode, no_skip, m, p, W, H, D, out, NULL);
}

static void counts_mode_fx(retro_mode mode, const char *what, const retro_map *m, player_t p, int W, int H, int D,
                           int must_skip, const retro_effects *fx)
{
    retro_ctx *on = retro_ctx_new(), *off = retro_ctx_new();
    cr_assert(on && off);
    size_t n = (size_t)W * (size_t)H;
    uint32_t *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    cr_assert(a && b);
    retro_sample_counts s = count_fx(on, mode, 0, m, p, W, H, D, a, fx);
    retro_sample_counts t = count_fx(off, mode, 1, m, p, W, H, D, b, fx);
    cr_assert_eq(memcmp(a, b, n * sizeof *a), 0, "%s: the counting build's frames differ", what);
    cr_assert_eq(s.painting, t.painting, "%s: %llu samples paint with skipping, %llu without", what,
                 (unsigned long long)s.painting, (unsigned long long)t.painting);
    /* A batch after a probe may compute up to RETRO_SKIP_NEAR - 1 samples past a column's
     * early exit (they cannot paint), so only "at most all" holds in general. */
    uint64_t all = (uint64_t)W * (uint64_t)(D - 1);
    cr_assert_leq(s.evaluated, all, "%s", what);
    cr_assert_leq(t.evaluated, all, "%s", what);
    if (must_skip)
        cr_assert_lt(s.evaluated, t.evaluated / 2, "%s: %llu samples evaluated with skipping, %llu without", what, (unsigned long long)s.evaluated,
                     (unsigned long long)t.evaluated);
    free(a);
    free(b);
    retro_ctx_free(on);
    retro_ctx_free(off);
}

static void counts_mode(retro_mode mode, const char *what, const retro_map *m, player_t p, int W, int H, int D,
                        int must_skip)
{
    counts_mode_fx(mode, what, m, p, W, H, D, must_skip, NULL);
}

static void counts_compare(const char *what, const retro_map *m, player_t p, int W, int H, int D, int must_skip)
{
    counts_mode(RETRO_MODE_EXACT, what, m, p, W, H, D, must_skip);
    char course[160];
    snprintf(course, sizeof course, "%s (mode course)", what);
    counts_mode(RETRO_MODE_COURSE, course, m, p, W, H, D, 0);
}

/* A view where skipping must skip, from (128.5, 128.5) at height 100 looking along +x: a low
 * ridge near the camera hides the plain behind it, and a tall spike behind the camera keeps
 * vcap at the top of the screen for most distances, so the early exit cannot stop the columns:
 * only skipping avoids evaluating the hidden plain. */
static void ridge_map(retro_map *m)
{
    make_map(m, 256);
    for (int j = 0; j < 256; j++)
        for (int i = 140; i < 144; i++)
            m->height[(size_t)j * 256 + (size_t)i] = 107;
    m->height[(size_t)128 * 256 + 20] = 255;
}

Test(skipping, skipping_skips)
{
    retro_map m;
    ridge_map(&m);
    counts_compare("ridge", &m, at(128.5f, 128.5f, 0, 100), 64, 64, 400, 1);
    /* mode lod samples fewer distances behind the ridge, still most of them hidden */
    counts_mode(RETRO_MODE_LOD, "ridge (mode lod)", &m, at(128.5f, 128.5f, 0, 100), 64, 64, 400, 1);
    /* mode course walks the torus of side S - 1 from its accumulated positions */
    counts_mode(RETRO_MODE_COURSE, "ridge (mode course)", &m, at(128.5f, 128.5f, 0, 100), 64, 64, 400, 1);
    /* modes truth and fixed probe with their own positions and rows (skip_wide.h) */
    counts_mode(RETRO_MODE_TRUTH, "ridge (mode truth)", &m, at(128.5f, 128.5f, 0, 100), 64, 64, 400, 1);
    counts_mode(RETRO_MODE_FIXED, "ridge (mode fixed)", &m, at(128.5f, 128.5f, 0, 100), 64, 64, 400, 1);
    retro_map_free(&m);
}

/* Bilinear on flat ground at the camera's height, a frame an odd number of rows tall: every
 * filtered height is the ground's up to rounding, so every sample projects to the middle row
 * and only each column's first one paints. Skipping must prove the rest hidden from the
 * first batch on: the bound's margin over the block maximum (RETRO_BILINEAR_OVER) moves a
 * row by kd times the margin, and with a margin of a whole unit of height, near distances
 * (kd >= 1) projected above the middle row and were evaluated one by one. */
Test(skipping, bilinear_flat_ground_skips)
{
    static const int levels[] = {0, 1, 100, 254, 255};
    retro_effects fx;
    memset(&fx, 0, sizeof fx);
    fx.flags = RETRO_FX_BILINEAR;
    for (size_t k = 0; k < sizeof levels / sizeof levels[0]; k++) {
        retro_map m;
        make_map(&m, 64);
        memset(m.height, levels[k], (size_t)64 * 64);
        char what[64];
        snprintf(what, sizeof what, "flat ground at %d, bilinear", levels[k]);
        counts_mode_fx(RETRO_MODE_EXACT, what, &m, at(20.3f, 40.7f, 33, levels[k]), 64, 63, 400, 1, &fx);
        retro_map_free(&m);
    }
}

/* RETRO_BILINEAR_OVER's proof (hmax_pyramid.h) checked by brute force: filtered heights of
 * corners at most M, through the kernels' own retro_bilinear_height, at random weights and
 * at weights as near 0, 1/2 and 1 as a position in the first cell allows (q = p + 1/2 is
 * rounded, so 1 - 2^-24 becomes 0 and 1 - 2^-23 stays), never exceed M + RETRO_BILINEAR_OVER,
 * nor does their rounded difference from a camera height exceed the bound's. (None of them exceeds M at all
 * here; the proof does not rule that out, so the margin stays.) */
Test(skipping, bilinear_over_bound)
{
    static const float edges[] = {0.0f, 0x1p-24f, 0x1p-20f, 0.1f, 0.5f - 0x1p-25f, 0.5f, 0.5f + 0x1p-24f,
                                  0.9f, 1.0f - 0x1p-24f, 1.0f - 0x1p-23f, 1.0f - 0x1p-20f};
    static const int64_t cams[] = {0, 77, 255, 256, -1000, (1 << 24) + 1, -(1 << 30)};
    enum { NE = sizeof edges / sizeof edges[0] };
    uint8_t h[4];
    retro_frame f;
    memset(&f, 0, sizeof f);
    f.S = 2;
    f.height_map = h;
    uint64_t st = 4242;
    for (long t = 0; t < 400000; t++) {
        const int M = 1 + (int)(rng_next(&st) % 255);
        for (int c = 0; c < 4; c++)
            h[c] = (uint8_t)((t & 1) ? (uint64_t)M : rng_next(&st) % (uint64_t)(M + 1));
        h[rng_next(&st) % 4] = (uint8_t)M;
        float px, py;
        if (t % 3 == 0) {
            px = edges[rng_next(&st) % NE];
            py = edges[rng_next(&st) % NE];
        } else {
            px = (float)(rng_next(&st) % (1u << 24)) * 0x1p-24f;
            py = (float)(rng_next(&st) % (1u << 24)) * 0x1p-24f;
        }
        retro_bilerp b;
        /* q = p + 1/2 rounds, and the kernel takes q - 1/2 again: p stays in [0, 1] */
        const float hf = retro_bilinear_height(&f, px + 0.5f, py + 0.5f, &b);
        const float bound = (float)M + RETRO_BILINEAR_OVER;
        cr_assert_leq(hf, bound, "corners %d %d %d %d at (%a, %a): %a above M + margin", h[0], h[1], h[2], h[3],
                      (double)px, (double)py, (double)hf);
        const int64_t cam = cams[t % (long)(sizeof cams / sizeof cams[0])];
        cr_assert_leq(retro_bilinear_dh(hf, cam), retro_bilinear_dh(bound, cam));
    }
}

/* The same invariants on every default terrain, and on the course's valley frame if present. */
Test(skipping, counts_agree)
{
    static const char *const styles[] = {"alpine", "islands", "canyon"};
    for (size_t k = 0; k < 3; k++) {
        retro_map m;
        char err[256];
        cr_assert_eq(retro_mapgen(styles[k], 3, 256, &m, err, sizeof err), 0, "%s", err);
        struct retro_view v;
        retro_default_view(&m, &v);
        counts_compare(styles[k], &m, at(v.x, v.y, v.angle, v.height), 160, 120, 300, 0);
        retro_map_free(&m);
    }
}

/* The same on the course's valley frame, which must skip. A skip, not a warning, where the
 * course data is absent: Criterion exits non-zero after a warning. */
Test(skipping, counts_agree_valley)
{
    retro_map valley;
    if (course_map("valley", &valley))
        cr_skip_test("../shared/course absent: the valley frame's counts are not checked");
    counts_compare("valley", &valley, at(997.808716f, 559.177063f, 0, 230), 640, 480, 800, 1);
    retro_map_free(&valley);
}

/* One frame of the studies' walks (hmax_pyramid.h's counting-build switches): its reference,
 * rendered and counted without skipping, and a context and buffer for the walks'. */
typedef struct {
    retro_mode mode;
    const char *what;
    const retro_map *m;
    player_t p;
    int W, H, D;
    const retro_effects *fx;
    retro_ctx *rc;
    uint32_t *a, *b; /* a walk's frame, the reference */
    retro_sample_counts t; /* the reference's counts */
} study_frame;

/* The counts of the walk the switches select now, whose frame and painting samples must be the
 * reference's: skipping only leaves out samples that paint nothing. */
static retro_sample_counts study_walk(const study_frame *f, const char *walk)
{
    retro_sample_counts s = count_fx(f->rc, f->mode, 0, f->m, f->p, f->W, f->H, f->D, f->a, f->fx);
    cr_assert_eq(memcmp(f->a, f->b, (size_t)f->W * (size_t)f->H * sizeof *f->a), 0, "%s: the frame with %s differs",
                 f->what, walk);
    cr_assert_eq(s.painting, f->t.painting, "%s, %s: %llu samples paint, %llu without skipping", f->what, walk,
                 (unsigned long long)s.painting, (unsigned long long)f->t.painting);
    /* a batch after a probe may run past a column's early exit: only "at most all" in general */
    cr_assert_leq(s.evaluated, (uint64_t)f->W * (uint64_t)(f->D - 1), "%s, %s", f->what, walk);
    return s;
}

typedef void study_case(const study_frame *);
static void study_run(study_case *each, retro_mode mode, const char *what, const retro_map *m, player_t p, int W,
                      int H, int D, const retro_effects *fx)
{
    study_frame f = {mode, what, m, p, W, H, D, fx, retro_ctx_new(), NULL, NULL, {0}};
    retro_ctx *off = retro_ctx_new();
    cr_assert(f.rc && off);
    size_t n = (size_t)W * (size_t)H;
    f.a = malloc(n * sizeof *f.a);
    f.b = malloc(n * sizeof *f.b);
    cr_assert(f.a && f.b);
    f.t = count_fx(off, mode, 1, m, p, W, H, D, f.b, fx);
    each(&f);
    free(f.a);
    free(f.b);
    retro_ctx_free(f.rc);
    retro_ctx_free(off);
}

/* The ideal bound (hmax_pyramid.h, retro_skip_ideal) on one frame: still exact at blocks down
 * to 4, 2 and 1 cells, and at 1 cell, where each run of plain samples is one sample bounded by
 * its own height, it evaluates exactly the samples that paint: the probe's row test is then
 * the sample's own. */
static void ideal_case(const study_frame *f)
{
    const int bilinear = f->fx && (f->fx->flags & RETRO_FX_BILINEAR);
    static const char *const bounds[] = {"max", "plane", "oracle"};
    for (int kind = RETRO_IDEAL_MAX; kind <= RETRO_IDEAL_ORACLE; kind++)
        for (int l = RETRO_PYR_LMIN; l >= 0; l--) {
            char walk[64];
            snprintf(walk, sizeof walk, "the ideal %s bound, blocks down to %d", bounds[kind], 1 << l);
            retro_skip_ideal = l;
            retro_skip_ideal_kind = kind;
            retro_sample_counts s = study_walk(f, walk);
            retro_skip_ideal = -1;
            retro_skip_ideal_kind = RETRO_IDEAL_MAX;
            /* one sample at a time: never past the early exit */
            cr_assert_leq(s.evaluated, f->t.evaluated, "%s, %s", f->what, walk);
            if (l == 0 && !bilinear) /* a bilinear box is two cells wide, its bound above the filter */
                cr_assert_eq(s.evaluated, s.painting, "%s, %s: %llu samples evaluated, %llu paint", f->what, walk,
                             (unsigned long long)s.evaluated, (unsigned long long)s.painting);
        }
}

/* The walk given one part of the ideal walk at a time (hmax_pyramid.h, retro_skip_window and
 * retro_skip_every; docs/studies/SKIPPING_LIMITS.md, "Window or schedule"): still exact, and both
 * parts together evaluate the very samples the ideal max bound at the pyramid's finest blocks does,
 * which --stats and the doc's table take for granted. */
static void walk_parts_case(const study_frame *f)
{
    static const char *const windows[] = {"level windows", "own boxes", "unaligned windows"};
    for (int w = RETRO_WINDOW_BLOCKS; w <= RETRO_WINDOW_UNALIGNED; w++)
        for (int every = 0; every <= 1; every++) {
            char walk[64];
            snprintf(walk, sizeof walk, "%s%s", windows[w], every ? ", one probe per sample" : "");
            retro_skip_window = w;
            retro_skip_every = every;
            retro_sample_counts s = study_walk(f, walk);
            retro_skip_window = RETRO_WINDOW_BLOCKS;
            retro_skip_every = 0;
            if (w == RETRO_WINDOW_OWN_BOX && every) {
                retro_skip_ideal = RETRO_PYR_LMIN;
                retro_sample_counts i = study_walk(f, "the ideal max bound");
                retro_skip_ideal = -1;
                cr_assert_eq(s.evaluated, i.evaluated, "%s: %s evaluate %llu samples, the ideal bound %llu", f->what,
                             walk, (unsigned long long)s.evaluated, (unsigned long long)i.evaluated);
            }
        }
}

/* The frames the studies' walks are checked on: a ridge in modes exact and lod, and three
 * generated styles at their default views, and turned so that D beyond S crosses the wrap seam,
 * plainly and with bilinear (whose boxes are a cell wider). */
static void study_frames(study_case *each)
{
    retro_effects bilinear;
    memset(&bilinear, 0, sizeof bilinear);
    bilinear.flags = RETRO_FX_BILINEAR;
    retro_map m;
    ridge_map(&m);
    study_run(each, RETRO_MODE_EXACT, "ridge", &m, at(128.5f, 128.5f, 0, 100), 64, 64, 400, NULL);
    study_run(each, RETRO_MODE_LOD, "ridge (mode lod)", &m, at(128.5f, 128.5f, 0, 100), 64, 64, 400, NULL);
    retro_map_free(&m);
    static const char *const styles[] = {"alpine", "islands", "canyon"};
    for (size_t k = 0; k < 3; k++) {
        char err[256];
        cr_assert_eq(retro_mapgen(styles[k], 3, 256, &m, err, sizeof err), 0, "%s", err);
        struct retro_view v;
        retro_default_view(&m, &v);
        study_run(each, RETRO_MODE_EXACT, styles[k], &m, at(v.x, v.y, v.angle, v.height), 160, 120, 300, NULL);
        study_run(each, RETRO_MODE_EXACT, styles[k], &m, at(v.x, v.y, v.angle + 37, v.height), 96, 72, 700, NULL);
        study_run(each, RETRO_MODE_EXACT, styles[k], &m, at(v.x, v.y, v.angle + 37, v.height), 96, 72, 700,
                  &bilinear);
        retro_map_free(&m);
    }
}

Test(skipping, ideal_bound)
{
    study_frames(ideal_case);
}

Test(skipping, walk_parts)
{
    study_frames(walk_parts_case);
}

/* The cone steps' study (cone_map.h) on one frame: exact alone, with the pyramid's probe and
 * with the ideal max bound's, and where the frame is one the map serves (mode exact, plain samples), it skips. */
static void cone_case(const study_frame *f)
{
    retro_cone_map cm;
    cr_assert_eq(retro_cone_build(&cm, f->m->height, f->m->size, 16, 16), 0);
    static const char *const walks[] = {"cone steps", "cone steps and the pyramid", "cone steps and the ideal max bound"};
    for (int v = 0; v < 3; v++) {
        retro_skip_cone = &cm;
        retro_skip_cone_pyramid = v > 0;
        retro_skip_ideal = v == 2 ? RETRO_PYR_LMIN : -1;
        retro_sample_counts s = study_walk(f, walks[v]);
        retro_skip_cone = NULL;
        retro_skip_cone_pyramid = 0;
        retro_skip_ideal = -1;
        const retro_frame *fr = retro_ctx_frame(f->rc);
        if (retro_cone_applies(&cm, fr))
            cr_assert_lt(s.evaluated, (uint64_t)f->W * (uint64_t)(f->D - 1), "%s: cone steps skipped nothing",
                         f->what);
    }
    retro_cone_free(&cm);
}

Test(skipping, cone_steps)
{
    study_frames(cone_case);
}

/* Square pyramids of side 64 on flat ground, each face a plane of slope 3: the terrain where a
 * plane bounds a box of cells more tightly than its maximum. */
static void pyramid_map(retro_map *m, int S)
{
    make_map(m, S);
    for (int j = 0; j < S; j++)
        for (int i = 0; i < S; i++) {
            int a = i % 64 - 32, b = j % 64 - 32;
            int r = (a < 0 ? -a : a) > (b < 0 ? -b : b) ? (a < 0 ? -a : a) : (b < 0 ? -b : b);
            m->height[(size_t)j * (size_t)S + (size_t)i] = (uint8_t)(r < 30 ? 3 * (30 - r) : 0);
        }
}

/* The other bounds of the ideal walk (retro_skip_ideal_kind) are exact on planar faces too, and
 * there each evaluates fewer samples than the one before: a face rising away from the camera
 * has its box maximum at the box's far edge, which the plane follows, and the oracle skips
 * every run none of whose samples paints. */
Test(skipping, ideal_bounds_on_slopes)
{
    retro_map m;
    pyramid_map(&m, 256);
    player_t p = at(10.5f, 40.5f, 10, 140);
    study_run(ideal_case, RETRO_MODE_EXACT, "pyramids", &m, p, 160, 120, 500, NULL);
    study_run(ideal_case, RETRO_MODE_LOD, "pyramids (mode lod)", &m, p, 160, 120, 500, NULL);
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    uint32_t *out = malloc((size_t)160 * 120 * sizeof *out);
    cr_assert(out);
    uint64_t evaluated[3];
    for (int kind = RETRO_IDEAL_MAX; kind <= RETRO_IDEAL_ORACLE; kind++) {
        retro_skip_ideal = RETRO_PYR_LMIN;
        retro_skip_ideal_kind = kind;
        evaluated[kind] = count(rc, RETRO_MODE_EXACT, 0, &m, p, 160, 120, 500, out).evaluated;
        retro_skip_ideal = -1;
        retro_skip_ideal_kind = RETRO_IDEAL_MAX;
    }
    cr_assert_lt(evaluated[RETRO_IDEAL_PLANE], evaluated[RETRO_IDEAL_MAX],
                 "pyramids: the plane bound evaluates %llu samples, the max bound %llu",
                 (unsigned long long)evaluated[RETRO_IDEAL_PLANE], (unsigned long long)evaluated[RETRO_IDEAL_MAX]);
    cr_assert_lt(evaluated[RETRO_IDEAL_ORACLE], evaluated[RETRO_IDEAL_PLANE],
                 "pyramids: the oracle evaluates %llu samples, the plane bound %llu",
                 (unsigned long long)evaluated[RETRO_IDEAL_ORACLE], (unsigned long long)evaluated[RETRO_IDEAL_PLANE]);
    free(out);
    retro_ctx_free(rc);
    retro_map_free(&m);
}

/* Low noise terrain (seed) with three spikes placed by st: the probes' queries below. */
static void spiky_map(retro_map *m, int S, uint64_t seed, uint64_t *st)
{
    noise_map(m, S, seed);
    for (size_t i = 0; i < (size_t)S * (size_t)S; i++)
        m->height[i] = (uint8_t)(m->height[i] / 4);
    for (int k = 0; k < 3; k++)
        m->height[rng_next(st) % ((uint64_t)S * (uint64_t)S)] = (uint8_t)(200 + k * 20);
}

/* The probe tests' map of side S (spiky_map from seed) and a context to render it with. */
static retro_ctx *probe_setup(retro_map *m, int S, uint64_t seed, uint64_t *st)
{
    spiky_map(m, S, seed, st);
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    return rc;
}

/* A random frame of map m (side S) for the probe tests: screen up to 200 x 300, D up to
 * dmul * S, a position within a map's side of the origin (negative x too), any angle, camera
 * heights from below the ground to above the highest cell; o sets the mode. */
static const retro_frame *random_frame(retro_ctx *rc, const retro_render_opts *o, const retro_map *m, int dmul,
                                       uint32_t *out, uint64_t *st)
{
    const int S = m->size;
    int W = 1 + (int)(rng_next(st) % 200), H = 1 + (int)(rng_next(st) % 300);
    int D = 2 + (int)(rng_next(st) % (unsigned)(dmul * S));
    float x = (float)(rng_next(st) % 100000) * (float)S / 100000.0f - (float)S;
    float y = (float)(rng_next(st) % 100000) * (float)S / 100000.0f;
    player_t p = at(x, y, (int)(rng_next(st) % 360), (int)(rng_next(st) % 300) - 20);
    ctx_t c = {W, H, S, D, 0, m->height, m->color, out};
    const retro_frame *f = NULL;
    cr_assert_eq(retro_frame_prepare(rc, o, &p, &c, &f), RETRO_OK);
    cr_assert_not_null(f->pyr);
    return f;
}

/* The column probe on its own: for random frames, columns, distances and y-buffers, every
 * distance retro_skip_column skips has a row at or below y (brute force from the sample's own
 * cell), across the spike, seam and size cases above. */
Test(skipping, probe_bound)
{
    static const int sizes[] = {5, 6, 37, 64, 100, 129};
    uint64_t st = 99;
    /* (bilinear on every other pair of queries: its box is a cell wider and its height M + 1) */
    long skipped = 0;
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        int S = sizes[si];
        retro_map m;
        retro_ctx *rc = probe_setup(&m, S, 31 + (uint64_t)S, &st);
        uint32_t out[1];
        retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
        for (int frame = 0; frame < 60; frame++) {
            const retro_frame *f = random_frame(rc, &o, &m, 6, out, &st);
            const int W = f->W, H = f->H, D = f->D;
            int pow2 = (S & (S - 1)) == 0;
            for (int q = 0; q < 40; q++) {
                int u = (int)(rng_next(&st) % (unsigned)W), d = 1 + (int)(rng_next(&st) % (unsigned)(D - 1));
                int yb = (int)(rng_next(&st) % (unsigned)H);
                retro_skip_col col;
                retro_skip_col_init(&col, f, u);
                col.level = RETRO_PYR_LMIN + (int)(rng_next(&st) % 4);
                /* The run length is only an estimate, confirmed from the end cells: a wrong one
                 * (here up to 4 times too long) must cost skips, never exactness. */
                if (q & 1)
                    col.inv_r *= 1.0f + (float)(rng_next(&st) % 4);
                if (col.level > f->pyr->lmax)
                    col.level = f->pyr->lmax;
                int bil = (q >> 1) & 1, e;
                if (pow2)
                    e = bil ? retro_skip_column(f->pyr, f, &col, d, D, yb, 1, 1)
                            : retro_skip_column(f->pyr, f, &col, d, D, yb, 1, 0);
                else
                    e = bil ? retro_skip_column(f->pyr, f, &col, d, D, yb, 0, 1)
                            : retro_skip_column(f->pyr, f, &col, d, D, yb, 0, 0);
                cr_assert(e >= d && e <= D, "skip from %d returned %d (D %d)", d, e, D);
                for (int dd = d; dd < e; dd++) {
                    int v;
                    if (bil) {
                        retro_bilerp b;
                        float qx = f->x0 + (float)dd * f->rx[u], qy = f->y0 + (float)dd * f->ry[u];
                        float hf = retro_bilinear_height(f, qx, qy, &b);
                        v = retro_exact_row_f(f->kd[dd], f->half_h, H, retro_bilinear_dh(hf, f->height));
                    } else {
                        size_t idx = retro_exact_sample(f, u, dd);
                        v = retro_exact_row(f->kd[dd], f->half_h, H, f->height_map[idx] - f->height);
                    }
                    cr_assert_leq(v, yb, "S %d: column %d skipped distance %d of [%d, %d) with row %d above %d", S, u,
                                  dd, d, e, v, yb);
                }
                skipped += e - d;
            }
        }
        retro_ctx_free(rc);
        retro_map_free(&m);
    }
    cr_assert_gt(skipped, 1000, "the probes skipped almost nothing (%ld distances)", skipped);
}

/* The cone step on its own (cone_map.h): for random frames, columns, distances and y-buffers,
 * every distance retro_cone_step jumps over has a row at or below y (brute force from the
 * sample's own cell), across spikes, the seam, sizes that are not powers of two, D up to 6 S,
 * and sector counts and radii from the smallest to the largest (beyond the smaller maps' sides). */
Test(skipping, cone_step_bound)
{
    static const int sizes[] = {5, 6, 37, 64, 100, 129};
    static const int shapes[][2] = {{4, 1}, {16, 8}, {64, 32}, {4, 32}};
    uint64_t st = 4242;
    long skipped = 0, queries = 0;
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        const int S = sizes[si];
        retro_map m;
        retro_ctx *rc = probe_setup(&m, S, 77 + (uint64_t)S, &st);
        uint32_t out[1];
        retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
        for (size_t sh = 0; sh < sizeof shapes / sizeof shapes[0]; sh++) {
            retro_cone_map cm;
            cr_assert_eq(retro_cone_build(&cm, m.height, S, shapes[sh][0], shapes[sh][1]), 0);
            for (int frame = 0; frame < 15; frame++) {
                const retro_frame *f = random_frame(rc, &o, &m, 6, out, &st);
                if (!retro_cone_applies(&cm, f))
                    continue;
                const int W = f->W, H = f->H, D = f->D;
                for (int q = 0; q < 60; q++) {
                    const int u = (int)(rng_next(&st) % (unsigned)W), e0 = 1 + (int)(rng_next(&st) % (unsigned)(D - 1));
                    const int yb = (int)(rng_next(&st) % (unsigned)H);
                    const size_t idx = retro_exact_sample(f, u, e0);
                    const int k = retro_cone_step(&cm, f, retro_cone_sector(&cm, f->rx[u], f->ry[u]), f->rx[u],
                                                  f->ry[u], idx, f->height_map[idx], e0, D, yb);
                    cr_assert(k >= 0 && e0 + k < D, "a step of %d from %d (D %d)", k, e0, D);
                    for (int e = e0 + 1; e <= e0 + k; e++) {
                        const size_t ci = retro_exact_sample(f, u, e);
                        const int v = retro_exact_row(f->kd[e], f->half_h, H, f->height_map[ci] - f->height);
                        cr_assert_leq(v, yb, "S %d, %d sectors, radius %d: column %d jumped from %d over %d, row %d above %d",
                                      S, cm.sectors, cm.R, u, e0, e, v, yb);
                    }
                    skipped += k;
                    queries++;
                }
            }
            retro_cone_free(&cm);
        }
        retro_ctx_free(rc);
        retro_map_free(&m);
    }
    cr_assert_gt(queries, 1000, "too few frames the cone maps serve (%ld queries)", queries);
    cr_assert_gt(skipped, 1000, "the cone steps skipped almost nothing (%ld distances)", skipped);
}

/* The probe of modes truth and fixed on its own (skip_wide.h), as probe_bound checks mode
 * exact's: every distance retro_skip_run_wide skips has a row at or below y, brute-forced from
 * the sample's own cell and row in the mode's arithmetic, with run lengths up to 4 times too
 * long, across spikes, the seam, odd sizes and D up to 6 S. */
Test(skipping, probe_bound_wide)
{
    static const int sizes[] = {5, 6, 37, 64, 100, 129};
    static const retro_mode modes[] = {RETRO_MODE_TRUTH, RETRO_MODE_FIXED};
    uint64_t st = 123;
    long skipped[2] = {0, 0};
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        const int S = sizes[si];
        retro_map m;
        retro_ctx *rc = probe_setup(&m, S, 53 + (uint64_t)S, &st);
        uint32_t out[1];
        for (int frame = 0; frame < 60; frame++) {
            const int fixed = frame & 1;
            retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
            o.mode = (int)modes[fixed];
            const retro_frame *f = random_frame(rc, &o, &m, 6, out, &st);
            const int W = f->W, H = f->H, D = f->D;
            for (int q = 0; q < 40; q++) {
                int u = (int)(rng_next(&st) % (unsigned)W), d = 1 + (int)(rng_next(&st) % (unsigned)(D - 1));
                int yb = (int)(rng_next(&st) % (unsigned)H);
                retro_skip_col col;
                retro_skip_wide_init(&col, f, u);
                col.level = RETRO_PYR_LMIN + (int)(rng_next(&st) % 4);
                if (col.level > f->pyr->lmax)
                    col.level = f->pyr->lmax;
                if (q & 1)
                    col.inv_r *= 1.0f + (float)(rng_next(&st) % 4);
                const int e = fixed ? retro_skip_run_wide(f->pyr, f, &col, u, d, D, yb, 1)
                                    : retro_skip_run_wide(f->pyr, f, &col, u, d, D, yb, 0);
                cr_assert(e >= d && e <= D, "skip from %d returned %d (D %d)", d, e, D);
                for (int dd = d; dd < e; dd++) {
                    int v;
                    if (fixed) {
                        size_t idx = retro_fixed_sample(f, u, dd);
                        v = retro_fixed_row(f->kd_q[dd], f->half_h_q, H, f->height_map[idx] - f->height);
                    } else {
                        size_t idx = retro_truth_sample(f, u, dd);
                        v = retro_truth_row(f->kdd[dd], 0.5 * (double)H, H, f->height_map[idx] - f->height);
                    }
                    cr_assert_leq(v, yb, "mode %s, S %d: column %d skipped distance %d of [%d, %d) with row %d above %d",
                                  fixed ? "fixed" : "truth", S, u, dd, d, e, v, yb);
                }
                skipped[fixed] += e - d;
            }
        }
        retro_ctx_free(rc);
        retro_map_free(&m);
    }
    cr_assert_gt(skipped[0], 1000, "mode truth: the probes skipped almost nothing (%ld distances)", skipped[0]);
    cr_assert_gt(skipped[1], 1000, "mode fixed: the probes skipped almost nothing (%ld distances)", skipped[1]);
}

/* The ideal plane bound on its own (retro_skip_plane_hides): for random frames, columns, runs
 * and y-buffers on sloped, spiky and seam-crossing terrain, a run it calls hidden has every
 * sample's row at or below y, brute-forced from each sample's own cell. Runs are boxed as
 * retro_skip_run boxes them, from the floors at their two ends. */
Test(skipping, ideal_plane_bound)
{
    static const int sizes[] = {5, 37, 64, 100, 256};
    uint64_t st = 4242;
    long hidden = 0, runs = 0;
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        int S = sizes[si];
        retro_map m;
        if (S == 256)
            pyramid_map(&m, S);
        else
            spiky_map(&m, S, 17 + (uint64_t)S, &st);
        uint32_t out[1];
        retro_ctx *rc = retro_ctx_new();
        cr_assert(rc);
        retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
        for (int frame = 0; frame < 60; frame++) {
            const retro_frame *f = random_frame(rc, &o, &m, 6, out, &st);
            const int W = f->W, H = f->H, D = f->D;
            for (int q = 0; q < 60; q++) {
                int u = (int)(rng_next(&st) % (unsigned)W), d = 1 + (int)(rng_next(&st) % (unsigned)(D - 1));
                int d1 = d + (int)(rng_next(&st) % 24);
                d1 = d1 < D ? d1 : D - 1;
                int yb = (int)(rng_next(&st) % (unsigned)H);
                float rx = f->rx[u], ry = f->ry[u];
                int I0 = retro_floor(f->x0 + (float)d * rx), I1 = retro_floor(f->x0 + (float)d1 * rx);
                int J0 = retro_floor(f->y0 + (float)d * ry), J1 = retro_floor(f->y0 + (float)d1 * ry);
                int I = I0 < I1 ? I0 : I1, J = J0 < J1 ? J0 : J1;
                int wi = I0 < I1 ? I1 - I0 : I0 - I1, wj = J0 < J1 ? J1 - J0 : J0 - J1;
                runs++;
                if (!retro_skip_plane_hides(f->pyr, f, I, J, wi, wj, rx, ry, d, d1, (float)(yb + 1)))
                    continue;
                hidden++;
                for (int dd = d; dd <= d1; dd++) {
                    size_t idx = retro_exact_sample(f, u, dd);
                    int v = retro_exact_row(f->kd[dd], f->half_h, H, f->height_map[idx] - f->height);
                    cr_assert_leq(v, yb, "S %d: column %d, run [%d, %d] called hidden, distance %d has row %d above %d", S,
                                  u, d, d1, dd, v, yb);
                }
            }
        }
        retro_ctx_free(rc);
        retro_map_free(&m);
    }
    cr_assert_gt(hidden, runs / 10, "the plane hid %ld of %ld runs", hidden, runs);
}

/* The probe in mode lod (retro_skip_run over sample indices, distances dist[n]): every index
 * it skips has a row at or below y, brute-forced, at lod rates from the smallest steps to
 * steps longer than a block, plain and bilinear. */
Test(skipping, probe_bound_lod)
{
    static const int sizes[] = {5, 37, 64, 129};
    static const float rates[] = {0.001f, 0.02f, 0.1f, 0.7f};
    uint64_t st = 1234;
    long skipped = 0;
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        int S = sizes[si];
        retro_map m;
        retro_ctx *rc = probe_setup(&m, S, 71 + (uint64_t)S, &st);
        uint32_t out[1];
        for (int frame = 0; frame < 60; frame++) {
            retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
            o.mode = RETRO_MODE_LOD;
            o.lod = rates[frame % 4];
            const retro_frame *f = random_frame(rc, &o, &m, 8, out, &st);
            const int W = f->W, H = f->H;
            if (f->ndist < 2)
                continue;
            for (int q = 0; q < 40; q++) {
                int u = (int)(rng_next(&st) % (unsigned)W), n = 1 + (int)(rng_next(&st) % (unsigned)(f->ndist - 1));
                int yb = (int)(rng_next(&st) % (unsigned)H), bil = q & 1;
                retro_skip_col col;
                retro_skip_col_init(&col, f, u);
                col.level = RETRO_PYR_LMIN + (int)(rng_next(&st) % 4);
                if (col.level > f->pyr->lmax)
                    col.level = f->pyr->lmax;
                int e = bil ? retro_skip_run(f->pyr, f, &col, n, f->ndist, yb, 0, 1, f->dist)
                            : retro_skip_run(f->pyr, f, &col, n, f->ndist, yb, 0, 0, f->dist);
                cr_assert(e >= n && e <= f->ndist, "skip from %d returned %d (%d samples)", n, e, f->ndist);
                for (int k = n; k < e; k++) {
                    int dd = f->dist[k], v;
                    float qx = f->x0 + (float)dd * f->rx[u], qy = f->y0 + (float)dd * f->ry[u];
                    if (bil) {
                        retro_bilerp b;
                        float hf = retro_bilinear_height(f, qx, qy, &b);
                        v = retro_exact_row_f(f->kd[dd], f->half_h, H, retro_bilinear_dh(hf, f->height));
                    } else {
                        size_t idx = (size_t)retro_cell(qy, S) * (size_t)S + (size_t)retro_cell(qx, S);
                        v = retro_exact_row(f->kd[dd], f->half_h, H, f->height_map[idx] - f->height);
                    }
                    cr_assert_leq(v, yb, "S %d lod %g: column %d skipped sample %d (distance %d) with row %d above %d",
                                  S, (double)o.lod, u, k, dd, v, yb);
                }
                skipped += e - n;
            }
        }
        retro_ctx_free(rc);
        retro_map_free(&m);
    }
    cr_assert_gt(skipped, 1000, "the probes skipped almost nothing (%ld samples)", skipped);
}
