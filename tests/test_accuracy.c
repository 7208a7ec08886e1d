/* The accuracy variants (docs/ACCURACY.md): properties that hold exactly, and error bounds
 * loose enough to hold for any pose yet tight enough to catch a misplaced cell or shift. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "retro_internal.h"
#include "test_util.h"

static int retro_fixed_cell_test(int64_t v, int S) { return retro_fixed_cell(v, S); }

enum { W = 200, H = 150 };

static void render_mode(const retro_map *m, retro_mode mode, float lod, const player_t *p, int D,
                        uint32_t *out)
{
    ctx_t c = {W, H, m->size, D, 0x000000ffu, m->height, m->color, out};
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = mode;
    o.lod = lod;
    cr_assert_eq(retro_render(rc, retro_kernel_find("naive"), &o, p, &c), RETRO_OK);
    retro_ctx_free(rc);
}

static double differ(const uint32_t *a, const uint32_t *b)
{
    int n = 0;
    for (int i = 0; i < W * H; i++)
        n += a[i] != b[i];
    return (double)n / (W * H);
}

/* With a step growth so small that every step is 1, mode lod samples every distance. */
Test(accuracy, lod_with_unit_steps_is_exact)
{
    retro_map m;
    test_map("test/alpine-200", &m);
    uint32_t *a = malloc(sizeof(uint32_t) * W * H), *b = malloc(sizeof(uint32_t) * W * H);
    player_t p = {37.25f, 120.5f, 222, m.height[120 * 200 + 37] + 40, 0, 0, 0};
    render_mode(&m, RETRO_MODE_EXACT, 0, &p, 600, a);
    render_mode(&m, RETRO_MODE_LOD, 1e-7f, &p, 600, b);
    cr_assert_eq(differ(a, b), 0.0);
    render_mode(&m, RETRO_MODE_LOD, 0.05f, &p, 600, b); /* coarser steps must change it */
    cr_assert_gt(differ(a, b), 0.0);
    free(a);
    free(b);
    retro_map_free(&m);
}

/* Truth, exact and fixed describe the same geometry: they may disagree only where a sample
 * sits within rounding of a cell edge or a row boundary, which is rare. */
Test(accuracy, variants_stay_close_to_truth)
{
    retro_map m;
    test_map("test/alpine-200", &m);
    uint32_t *t = malloc(sizeof(uint32_t) * W * H), *v = malloc(sizeof(uint32_t) * W * H);
    uint64_t rng = 5;
    for (int n = 0; n < 20; n++) {
        player_t p = {(float)(rng_next(&rng) % 20000) / 100.0f, (float)(rng_next(&rng) % 20000) / 100.0f,
                      (int)(rng_next(&rng) % 360), 0, 0, 0, 0};
        p.height = m.height[(int)p.y * 200 + (int)p.x] + 30 + (int)(rng_next(&rng) % 100);
        render_mode(&m, RETRO_MODE_TRUTH, 0, &p, 400, t);
        render_mode(&m, RETRO_MODE_EXACT, 0, &p, 400, v);
        cr_assert_lt(differ(t, v), 0.01, "exact vs truth at pose %d", n);
        render_mode(&m, RETRO_MODE_FIXED, 0, &p, 400, v);
        cr_assert_lt(differ(t, v), 0.03, "fixed vs truth at pose %d", n);
    }
    free(t);
    free(v);
    retro_map_free(&m);
}

/* Mode fixed's cell is the floor of a negative fixed-point position too. */
Test(accuracy, fixed_cell_floors_negative_positions)
{
    cr_assert_eq(retro_fixed_cell_test(-1, 7), 6);                    /* just below 0 */
    cr_assert_eq(retro_fixed_cell_test(-(1LL << 24), 7), 6);          /* exactly -1 */
    cr_assert_eq(retro_fixed_cell_test(-(1LL << 24) - 1, 7), 5);      /* just below -1 */
    cr_assert_eq(retro_fixed_cell_test((7LL << 24) + 5, 7), 0);       /* S wraps to 0 */
    cr_assert_eq(retro_fixed_cell_test((3LL << 24) - 1, 7), 2);
}

/* Mode truth's floor (retro_floor_d) against libm's floor on both sides of 0 and of the
 * integers, -0 and the largest doubles below an integer included: truncation is the floor
 * only from 0 up. */
Test(accuracy, truth_floor_is_floor)
{
    const double q[] = {0.0, -0.0, 0.25, 0.999999999, 1.0, 1.5, -0x1p-1074, -0.25, -1.0, -1.5, -2.0,
                        nextafter(-1.0, 0.0), nextafter(-1.0, -2.0), nextafter(3.0, 0.0), 4194303.75,
                        -4194303.75, 0x1p52 + 1.0, -0x1p52 - 1.0};
    for (size_t i = 0; i < sizeof q / sizeof q[0]; i++)
        cr_assert_eq(retro_floor_d(q[i]), (int64_t)floor(q[i]), "q = %a", q[i]);
}

Test(accuracy, mode_names_round_trip)
{
    for (int m = 0; m < RETRO_MODE_COUNT; m++) {
        retro_mode back;
        cr_assert_eq(retro_mode_parse(retro_mode_name((retro_mode)m), &back), 0);
        cr_assert_eq((int)back, m);
    }
    retro_mode x;
    cr_assert_eq(retro_mode_parse("approximate", &x), -1);
}
