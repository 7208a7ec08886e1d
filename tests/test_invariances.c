/* Invariances mode exact promises exactly: x and x + kS, angle and angle + 360k, and an
 * image that depends only on the cells its samples read. */
#include <criterion/criterion.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "retro_internal.h"
#include "hard_rig.h"
#include "ref_exact.h"
#include "test_util.h"


/* --- invariances mode exact promises exactly --------------------------------------------- */

/* Renders with naive into dst (W*H), failing the test on an error. */
static void naive_into(rig *g, uint32_t *dst, const player_t *p, ctx_t c)
{
    c.out = dst;
    retro_err e = rig_render(g, 0, 0, RETRO_MODE_EXACT, p, &c);
    cr_assert_eq(e, RETRO_OK, "%s", retro_strerror(e));
}

/* x and x + k*S give the same frame when both are floats exactly: the reduction modulo S is
 * exact (fmod in double of a float is exact), so nothing of k survives into x0. */
Test(invariance, position_period)
{
    rig *g = rig_new();
    retro_map maps[2];
    noise_map(&maps[0], 1024, 41);
    noise_map(&maps[1], 1000, 42);
    static const float base[][2] = {{100.5f, 37.25f}, {100.25f, 999.75f}};
    uint32_t *ref = malloc(sizeof(uint32_t) * CW * CH), *img = malloc(sizeof(uint32_t) * CW * CH);
    rig_reserve(g, (size_t)CW * CH);
    for (int mi = 0; mi < 2; mi++) {
        const retro_map *m = &maps[mi];
        const int S = m->size;
        ctx_t c = {CW, CH, S, CD, SKY, m->height, m->color, NULL};
        for (int angle = 0; angle < 160; angle += 53) {
            player_t p0 = pose(base[mi][0], base[mi][1], angle, 170);
            naive_into(g, ref, &p0, c);
            for (int k = -1000; k <= 1000; k++) {
                /* Both axes at once for every k, each axis alone for every 7th. */
                for (int axis = k % 7 ? 2 : 0; axis < 3; axis++) {
                    double x = p0.x + (axis != 1 ? (double)k * S : 0.0);
                    double y = p0.y + (axis != 0 ? (double)(-k) * S : 0.0);
                    player_t p = pose((float)x, (float)y, angle, p0.height);
                    cr_assert((double)p.x == x && (double)p.y == y, "x + k*S must be exact: k=%d", k);
                    naive_into(g, img, &p, c);
                    long i = first_diff(ref, img, (size_t)CW * CH);
                    if (i >= 0)
                        report(g, "MISMATCH position period: S=%d angle=%d k=%d axis=%d: (%a, %a) "
                               "differs from (%a, %a) at pixel %ld", S, angle, k, axis, x, y,
                               (double)p0.x, (double)p0.y, i);
                    /* Every kernel on a few shifts: they share the reduction, but not the code
                     * after it. */
                    if ((k == -1000 || k == -1 || k == 1 || k == 1000) && axis == 2) {
                        memcpy(g->ref, ref, sizeof(uint32_t) * CW * CH);
                        all_kernels_match(g, "position period", RETRO_MODE_EXACT, &p, c);
                    }
                }
            }
        }
    }
    free(ref);
    free(img);
    free_maps(maps, 2);
    rig_done(g, "invariance/position_period");
}

/* a and a + 360k give the same frame for every k keeping a + 360k an int, up to INT_MIN and
 * INT_MAX: the reduction is an exact integer remainder. */
Test(invariance, angle_period)
{
    rig *g = rig_new();
    retro_map m;
    noise_map(&m, 64, 43);
    enum { W = 19, H = 13, D = 24 };
    uint32_t ref[W * H], img[W * H];
    rig_reserve(g, W * H);
    ctx_t c = {W, H, m.size, D, SKY, m.height, m.color, NULL};
    for (int a = 0; a < 360; a++) {
        player_t p0 = pose(30.3f, 12.7f, a, 150);
        naive_into(g, ref, &p0, c);
        long long kmin = ((long long)INT_MIN - a + 359) / 360, kmax = ((long long)INT_MAX - a) / 360;
        const long long ks[] = {-3, -2, -1, 1, 2, 3, 1000, -1000, kmin, kmin + 1, kmax, kmax - 1};
        for (size_t i = 0; i < sizeof ks / sizeof ks[0]; i++) {
            long long angle = a + 360LL * ks[i];
            cr_assert(angle >= INT_MIN && angle <= INT_MAX);
            player_t p = pose(p0.x, p0.y, (int)angle, p0.height);
            naive_into(g, img, &p, c);
            long at = first_diff(ref, img, (size_t)W * H);
            if (at >= 0)
                report(g, "MISMATCH angle period: %d and %lld differ at pixel %ld", a, angle, at);
            if (a % 45 == 0 || a % 90 == 1 || a % 90 == 89) {
                memcpy(g->ref, ref, sizeof ref);
                all_kernels_match(g, "angle period", RETRO_MODE_EXACT, &p, c);
            }
        }
    }
    retro_map_free(&m);
    rig_done(g, "invariance/angle_period");
}

/* Marks every cell mode exact reads, by SEMANTICS.md steps 1-5 as the independent reference
 * (ref_exact.c) writes them, not taken from src/. */
static void exact_reads(const player_t *p, int W, int D, int S, uint8_t *marks)
{
    const ref_view v = ref_exact_view(p, S);
    for (int u = 1; u <= W; u++)
        for (int d = 1; d < D; d++)
            marks[ref_exact_cell(&v, W, S, u, d)] = 1;
}

/* The image depends only on the cells the samples hit: rewriting every other cell (found by
 * evaluating the sample positions, and separately every cell beyond the view's reach on the
 * torus) leaves every kernel's frame unchanged, while raising the nearest sample's cell of
 * column 1 into view changes it. */
Test(invariance, unread_cells)
{
    rig *g = rig_new();
    enum { S = 200, W = CW, H = CH, D = 40 };
    retro_map m, edit;
    noise_map(&m, S, 44);
    noise_map(&edit, S, 45);
    uint8_t *marks = malloc(S * S);
    uint32_t *ref = malloc(sizeof(uint32_t) * W * H);
    uint64_t rng = 46;
    for (int n = 0; n < 12; n++) {
        player_t p = pose((float)(rng_next(&rng) % 100000) / 100.0f - 500.0f,
                          (float)(rng_next(&rng) % 100000) / 100.0f - 500.0f,
                          n < 4 ? 90 * n : (int)(rng_next(&rng) % 720) - 360, 170);
        ctx_t c = {W, H, S, D, SKY, m.height, m.color, NULL};
        for (int variant = 0; variant < 2; variant++) {
            memset(marks, 0, S * S);
            if (variant == 0) {
                exact_reads(&p, W, D, S, marks);
            } else {
                /* Every sample is within D * sqrt(2) of the camera: cells whose torus distance
                 * exceeds D * 1.5 + 2 on either axis are unreachable, whatever the rounding. */
                double cx = fmod(fmod((double)p.x, S) + S, S), cy = fmod(fmod((double)p.y, S) + S, S);
                for (int j = 0; j < S; j++)
                    for (int i = 0; i < S; i++) {
                        double dx = fabs(i + 0.5 - cx), dy = fabs(j + 0.5 - cy);
                        dx = dx > S / 2.0 ? S - dx : dx;
                        dy = dy > S / 2.0 ? S - dy : dy;
                        marks[j * S + i] = dx <= D * 1.5 + 2 && dy <= D * 1.5 + 2;
                    }
            }
            size_t kept = 0;
            for (size_t i = 0; i < (size_t)S * S; i++)
                kept += marks[i];
            cr_assert(kept > 0 && kept < (size_t)S * S / 2, "%zu cells read", kept);
            char what[320];
            describe(what, sizeof what, variant ? "unreachable cells" : "unread cells", &p, W, H, D, S);
            cr_assert_eq(naive_ref(g, what, RETRO_MODE_EXACT, &p, c), 0);
            memcpy(ref, g->ref, sizeof(uint32_t) * W * H);
            /* A copy whose unread cells come from another map, heights and colours. */
            retro_map mix;
            noise_map(&mix, S, 47);
            for (size_t i = 0; i < (size_t)S * S; i++) {
                mix.height[i] = marks[i] ? m.height[i] : edit.height[i];
                mix.color[i] = marks[i] ? m.color[i] : edit.color[i];
            }
            ctx_t cm = c;
            cm.height_map = mix.height;
            cm.color_map = mix.color;
            cr_assert_eq(naive_ref(g, what, RETRO_MODE_EXACT, &p, cm), 0);
            long at = first_diff(ref, g->ref, (size_t)W * H);
            if (at >= 0)
                report(g, "MISMATCH %s: naive changed at pixel %ld", what, at);
            memcpy(g->ref, ref, sizeof(uint32_t) * W * H);
            all_kernels_match(g, what, RETRO_MODE_EXACT, &p, cm);

            if (variant == 0) {
                /* The d = 1 sample of column 1, raised to 255 with a colour of its own, projects
                 * to k_1 * (255 - 170) + H/2 > H: it covers column 1 entirely. */
                const ref_view v = ref_exact_view(&p, S);
                size_t idx = ref_exact_cell(&v, W, S, 1, 1);
                cr_assert(marks[idx], "the d = 1 cell of column 1 must be among the cells read");
                mix.height[idx] = 255;
                mix.color[idx] = 0x12345600u;
                rig_map_changed(g);
                cr_assert_eq(naive_ref(g, what, RETRO_MODE_EXACT, &p, cm), 0);
                cr_assert(first_diff(ref, g->ref, (size_t)W * H) >= 0,
                          "%s: raising a cell the frame reads must change the image", what);
                cr_assert_eq(g->ref[(size_t)(H - 1) * W], 0x12345600u, "column 1, row 1");
                all_kernels_match(g, what, RETRO_MODE_EXACT, &p, cm);
            }
            /* The rig's contexts cache per map pointer; mix is freed and the next one may reuse
             * its address. */
            rig_map_changed(g);
            retro_map_free(&mix);
        }
    }
    free(marks);
    free(ref);
    retro_map_free(&m);
    retro_map_free(&edit);
    rig_done(g, "invariance/unread_cells");
}
