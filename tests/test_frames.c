/* Frames whose image is known: analytic maps reasoned out by hand, an independent
 * implementation of mode exact on random poses, and every kernel against naive. */
#include <criterion/criterion.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "ctx.h"
#include "ref_exact.h"
#include "retro_scene.h"
#include "test_util.h"

#define SKY 0x66a3ff00u

/* Flat ground at 50 seen from above: v(d) = floor(k_d * (50 - z) + H/2) rises towards H/2
 * with d, so the farthest sample sets the horizon and every column is the same. */
Test(analytic, flat_map_rows)
{
    retro_map m;
    test_map("test/flat-64", &m);
    enum { W = 120, H = 90 };
    const int D = 300, z = 80;
    uint32_t px[W * H];
    ctx_t c = {W, H, m.size, D, SKY, m.height, m.color, px};
    player_t p = {10.25f, 20.5f, 33, z, 0, 0, 0};
    render_with("naive", RETRO_MODE_EXACT, &p, &c);
    float vf = (0.5f * (float)W) / (float)(D - 1) * (float)(50 - z) + 0.5f * (float)H;
    int horizon = (int)floorf(vf);
    cr_assert(horizon > 0 && horizon < H);
    for (int u = 0; u < W; u++)
        for (int r = 1; r <= H; r++) {
            uint32_t want = r <= horizon ? m.color[0] : SKY;
            cr_assert_eq(px[(H - r) * W + u], want, "pixel (%d,%d)", u + 1, r);
        }
    retro_map_free(&m);
}

/* One spike of height 255 at cell (32, 32); the camera at (12.5, 32.5) looks along +x from
 * height 240, so the spike is the sample at d = 20 where |t_u| * 20 < 0.5, i.e. the columns
 * u = 99..103 of W = 201 (t_u = (u - 101) / 100). The ground (height 0) projects below row 1
 * for every d < 50, so nothing else is drawn. */
Test(analytic, spike_in_predicted_columns)
{
    retro_map m;
    test_map("test/spike-64", &m);
    enum { W = 201, H = 300 };
    uint32_t *px = malloc(sizeof(uint32_t) * W * H);
    ctx_t c = {W, H, m.size, 50, SKY, m.height, m.color, px};
    player_t p = {12.5f, 32.5f, 0, 240, 0, 0, 0};
    render_with("naive", RETRO_MODE_EXACT, &p, &c);
    int top = (int)floorf((0.5f * W) / 20.0f * 15.0f + 0.5f * H);
    uint32_t red = m.color[32 * 64 + 32];
    for (int u = 1; u <= W; u++)
        for (int r = 1; r <= H; r++) {
            uint32_t want = u >= 99 && u <= 103 && r <= top ? red : SKY;
            cr_assert_eq(px[(H - r) * W + u - 1], want, "pixel (%d,%d)", u, r);
        }
    free(px);
    retro_map_free(&m);
}

static void compare(const uint32_t *a, const uint32_t *b, int W, int H, const char *what)
{
    for (int i = 0; i < W * H; i++)
        cr_assert_eq(a[i], b[i], "%s: first difference at (u=%d, r=%d)", what, i % W + 1, H - i / W);
}

/* Random poses, sizes and maps neither implementation was written against. */
Test(exact, matches_independent_implementation)
{
    retro_map maps[3];
    test_map("test/alpine-200", &maps[0]);
    noise_map(&maps[1], 37, 99);
    test_map("test/ramp-3", &maps[2]);
    uint64_t rng = 20261122;
    uint32_t *a = malloc(sizeof(uint32_t) * 200 * 150), *b = malloc(sizeof(uint32_t) * 200 * 150);
    for (int n = 0; n < 120; n++) {
        const retro_map *m = &maps[n % 3];
        int W = 1 + (int)(rng_next(&rng) % 200), H = 1 + (int)(rng_next(&rng) % 150);
        int D = (int)(rng_next(&rng) % 400);
        player_t p = {0};
        p.x = (float)((double)(rng_next(&rng) % 2000000) / 997.0 - 1000.0);
        p.y = (float)((double)(rng_next(&rng) % 2000000) / 991.0 - 1000.0);
        p.angle = (int)(rng_next(&rng) % 2000) - 1000;
        p.height = (int)(rng_next(&rng) % 600) - 100;
        ctx_t c = {W, H, m->size, D, SKY, m->height, m->color, a};
        render_with("naive", RETRO_MODE_EXACT, &p, &c);
        c.out = b;
        ref_exact_render(&p, &c);
        char what[160];
        snprintf(what, sizeof what, "pose %d (x=%g y=%g a=%d z=%d %dx%d D=%d S=%d)", n, (double)p.x,
                 (double)p.y, p.angle, p.height, W, H, D, m->size);
        compare(a, b, W, H, what);
    }
    free(a);
    free(b);
    for (int i = 0; i < 3; i++)
        retro_map_free(&maps[i]);
}

/* Fails the test at the first variant that errs or differs from the reference. */
static void assert_identical(void *user, const retro_check_variant *v, const retro_check_result *r)
{
    const retro_check *chk = ((void **)user)[0];
    const char *pose = ((void **)user)[1];
    char line[256];
    retro_check_describe(chk, v, r, line, sizeof line);
    cr_assert(!r->ran || (!r->err && !r->differ), "%s, %s", line, pose);
}

/* Every kernel, at every ISA level this CPU has, in every mode, against naive (src/check/). */
Test(kernels, identical_to_naive_on_random_poses)
{
    retro_map maps[2];
    test_map("test/alpine-200", &maps[0]);
    noise_map(&maps[1], 5, 3);
    retro_check chk;
    cr_assert_eq(retro_check_init(&chk, &retro_family_voxel, NULL, 3), 0);
    uint64_t rng = 7;
    for (int n = 0; n < 40; n++) {
        const retro_map *m = &maps[n % 2];
        int W = 1 + (int)(rng_next(&rng) % 160), H = 1 + (int)(rng_next(&rng) % 120);
        int D = (int)(rng_next(&rng) % 500);
        player_t p = {(float)(rng_next(&rng) % 4000) / 7.0f - 200.0f,
                      (float)(rng_next(&rng) % 4000) / 3.0f - 200.0f,
                      (int)(rng_next(&rng) % 800) - 400, (int)(rng_next(&rng) % 400) - 50, 0, 0, 0};
        if (n == 7)
            p.height = INT_MIN;
        if (n == 8)
            p.height = INT_MAX;
        for (int mode = 0; mode < RETRO_MODE_COUNT; mode++) {
            ctx_t c = {W, H, m->size, D, SKY, m->height, m->color, NULL};
            char pose[96];
            snprintf(pose, sizeof pose, "mode %s, pose %d", retro_mode_name((retro_mode)mode), n);
            void *user[2] = {&chk, pose};
            int bad = 0;
            cr_assert_eq(retro_check_frame(&chk, mode, NULL, &p, &c, assert_identical, user, &bad), RETRO_OK,
                         "naive, %s", pose);
            cr_assert_eq(bad, 0);
        }
    }
    retro_check_free(&chk);
    retro_map_free(&maps[0]);
    retro_map_free(&maps[1]);
}

/* Frame setup alone, as retro_render does it before the kernel runs (frame.h). */
static retro_err setup(retro_ctx *rc, int mode, const retro_effects *fx, const player_t *p, const ctx_t *c)
{
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = mode;
    o.fx = fx;
    const retro_frame *f;
    return retro_frame_prepare(rc, &o, p, c, &f);
}

Test(frame, invalid_input_is_an_error)
{
    uint8_t h[4] = {0};
    uint32_t col[4] = {0}, out[4];
    player_t p = {1, 1, 0, 10, 0, 0, 0};
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    ctx_t ok = {2, 2, 2, 10, 0, h, col, out};
    cr_assert_eq(setup(rc, RETRO_MODE_EXACT, NULL, &p, &ok), RETRO_OK);
    ctx_t bad[] = {
        {0, 2, 2, 10, 0, h, col, out},  {2, -1, 2, 10, 0, h, col, out},
        {2, 2, 0, 10, 0, h, col, out},  {2, 2, 2, RETRO_MAX_DISTANCE + 1, 0, h, col, out},
        {2, 2, 2, 10, 0, NULL, col, out}, {2, 2, 2, 10, 0, h, NULL, out}, {2, 2, 2, 10, 0, h, col, NULL},
        {RETRO_MAX_SCREEN + 1, 1, 2, 10, 0, h, col, out},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        cr_assert_eq(setup(rc, RETRO_MODE_EXACT, NULL, &p, &bad[i]), RETRO_EINVAL, "case %zu", i);
    player_t nan_p = {NAN, 1, 0, 10, 0, 0, 0}, inf_p = {1, INFINITY, 0, 10, 0, 0, 0};
    cr_assert_eq(setup(rc, RETRO_MODE_EXACT, NULL, &nan_p, &ok), RETRO_EINVAL);
    cr_assert_eq(setup(rc, RETRO_MODE_EXACT, NULL, &inf_p, &ok), RETRO_EINVAL);
    ctx_t s1 = {2, 2, 1, 10, 0, h, col, out};
    cr_assert_eq(setup(rc, RETRO_MODE_EXACT, NULL, &p, &s1), RETRO_OK);
    cr_assert_eq(setup(rc, RETRO_MODE_COURSE, NULL, &p, &s1), RETRO_EINVAL, "course needs S >= 2");
    cr_assert_eq(setup(rc, 7, NULL, &p, &ok), RETRO_EINVAL);
    retro_ctx_free(rc);
}

/* Quarter turns only swap and negate: angle 90 must give exactly (cs, sn) = (0, 1). */
Test(frame, quarter_turns_are_exact)
{
    uint8_t h[4] = {0};
    uint32_t col[4] = {0}, out[4];
    ctx_t c = {2, 2, 2, 10, 0, h, col, out};
    static const int angles[] = {0, 90, 180, 270, 360, -90, 450};
    static const float want[][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 0}, {0, -1}, {0, 1}};
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    for (int i = 0; i < 7; i++) {
        player_t p = {1, 1, angles[i], 10, 0, 0, 0};
        cr_assert_eq(setup(rc, RETRO_MODE_EXACT, NULL, &p, &c), RETRO_OK);
        const retro_frame *f = retro_ctx_frame(rc);
        cr_assert(f->cs == want[i][0] && f->sn == want[i][1], "angle %d", angles[i]);
        cr_assert(f->rx[0] == want[i][0] - want[i][1], "t_1 must be -1 exactly");
    }
    retro_ctx_free(rc);
}

/* Effect parameters outside docs/EFFECTS.md's ranges (NaN included) are refused, not baked. */
Test(frame, effect_parameters_out_of_range_are_errors)
{
    uint8_t h[4] = {0};
    uint32_t col[4] = {0}, out[4];
    ctx_t c = {2, 2, 2, 10, 0, h, col, out};
    player_t p = {1, 1, 0, 10, 0, 0, 0};
    retro_effects fx;
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    for (int i = 0; i < 8; i++) {
        retro_effects_defaults(&fx);
        fx.morph_height = h;
        switch (i) {
        case 0: fx.flags = RETRO_FX_MORPH; fx.morph_t = NAN; break;
        case 1: fx.flags = RETRO_FX_FOG; fx.fog_exp = 1; fx.fog_density = INFINITY; break;
        case 2: fx.flags = RETRO_FX_FOG; fx.fog_start = NAN; break;
        case 3: fx.flags = RETRO_FX_SHADE; fx.ambient = 1e30f; break;
        case 4: fx.flags = RETRO_FX_SHADE; fx.sun[2] = 5; break;
        case 5: fx.flags = RETRO_FX_WATER; fx.water_alpha0 = NAN; break;
        case 6: fx.flags = RETRO_FX_WATER; fx.water_level = 256; break;
        default: fx.flags = RETRO_FX_MORPH; fx.morph_height = NULL; break;
        }
        cr_expect_eq(setup(rc, RETRO_MODE_EXACT, &fx, &p, &c), RETRO_EINVAL, "case %d accepted", i);
    }
    retro_effects_defaults(&fx);
    fx.flags = RETRO_FX_FOG | RETRO_FX_SHADE | RETRO_FX_WATER;
    cr_assert_eq(setup(rc, RETRO_MODE_EXACT, &fx, &p, &c), RETRO_OK, "the defaults are valid");
    retro_ctx_free(rc);
}
