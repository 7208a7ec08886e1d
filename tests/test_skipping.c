/* Occlusion skipping (docs/SKIPPING.md, src/voxel/hmax_pyramid.h): cases aimed at the bound,
 * each rendered by naive, by ybuffer with skipping and by ybuffer without, and by every
 * kernel whose strips skip at every ISA level and thread count (the shared checker,
 * skipping_rig.c), compared byte for byte.
 * Every frame that should skip is checked to have had a pyramid, so a case cannot pass by
 * quietly taking the path without skipping. The counting build checks that skipping skips:
 * fewer samples evaluated, exactly the same samples painting. Counts only, never timings. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hmax_pyramid.h"
#include "kernels.h"
#include "retro_scene.h"
#include "skipping_rig.h"
#include "test_util.h"

static const int angles[] = {0, 1, 30, 45, 89, 90, 137, 180, 200, 270, 315, 359};
#define NANGLES ((int)(sizeof angles / sizeof angles[0]))

Test(skipping, single_spike)
{
    trio *g = rig_open();
    static const int sizes[] = {5, 8, 37, 64, 100};
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        int S = sizes[si];
        /* the centre, the four corners (the seam), and cells on both sides of block edges */
        int spots[][2] = {{S / 2, S / 2}, {0, 0}, {S - 1, 0}, {0, S - 1}, {S - 1, S - 1}, {3, 4}, {4, 3}, {7, 8 % S}};
        for (size_t k = 0; k < sizeof spots / sizeof spots[0]; k++)
            for (int tall = 0; tall < 2; tall++) {
                retro_map m;
                make_map(&m, S);
                int h = tall ? 255 : 130, i = spots[k][0] % S, j = spots[k][1] % S;
                m.height[(size_t)j * (size_t)S + (size_t)i] = (uint8_t)h;
                new_map(g);
                static const int heights[] = {-50, 0, 1, 100, 129, 130, 131, 254, 255, 256, 400};
                for (int a = 0; a < NANGLES; a += 2)
                    for (size_t z = 0; z < sizeof heights / sizeof heights[0]; z++) {
                        /* from a few cells off the spike, so it stands near the camera */
                        float x = (float)i - 6.5f, y = (float)j + 0.25f;
                        check(g, "spike", &m, at(x, y, angles[a], heights[z]), 37, 23, 3 * S, NULL);
                    }
                retro_map_free(&m);
            }
    }
    rig_close(g);
}

Test(skipping, cliffs_at_block_edges)
{
    trio *g = rig_open();
    static const int sizes[] = {16, 24, 64, 100};
    static const int edges[] = {4, 8, 16, 32, 5, 15, 31, 33};
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++)
        for (size_t e = 0; e < sizeof edges / sizeof edges[0]; e++)
            for (int axis = 0; axis < 2; axis++) {
                int S = sizes[si], edge = edges[e] % S;
                retro_map m;
                make_map(&m, S);
                for (int j = 0; j < S; j++)
                    for (int i = 0; i < S; i++)
                        m.height[(size_t)j * (size_t)S + (size_t)i] = (axis ? j : i) < edge ? 180 : 20;
                new_map(g);
                static const int heights[] = {19, 20, 21, 179, 180, 181, 250};
                for (int a = 0; a < NANGLES; a += 3)
                    for (size_t z = 0; z < sizeof heights / sizeof heights[0]; z++) {
                        float before = (float)edge - 3.5f, after = (float)edge + 2.0f;
                        float x = axis ? 1.5f : before, y = axis ? before : 1.5f;
                        check(g, "cliff (camera before)", &m, at(x, y, angles[a], heights[z]), 29, 31, 2 * S, NULL);
                        x = axis ? 1.5f : after;
                        y = axis ? after : 1.5f;
                        check(g, "cliff (camera after)", &m, at(x, y, angles[a], heights[z]), 29, 31, 2 * S, NULL);
                    }
                retro_map_free(&m);
            }
    rig_close(g);
}

/* S that no block size divides: the last block of each side is partial, and runs cross the
 * seam where cell S - 1 meets cell 0 through a partial block. */
Test(skipping, wrap_seam)
{
    trio *g = rig_open();
    static const int sizes[] = {37, 100, 1000};
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        int S = sizes[si];
        retro_map m;
        make_map(&m, S);
        /* walls one cell each side of the seam, a low plain elsewhere */
        for (int j = 0; j < S; j++)
            for (int i = 0; i < S; i++) {
                int wall = i == S - 1 || i == 0 || j == S - 1 || j == 1;
                m.height[(size_t)j * (size_t)S + (size_t)i] = (uint8_t)(wall ? 90 + (i * 7 + j * 3) % 40 : (i ^ j) & 15);
            }
        new_map(g);
        const float xs[] = {(float)S - 3.25f, 2.5f, (float)S - 0.5f, 0.0f, (float)S / 2};
        for (size_t q = 0; q < sizeof xs / sizeof xs[0]; q++)
            for (int a = 0; a < NANGLES; a++)
                for (int z = 40; z <= 160; z += 30) {
                    check(g, "seam", &m, at(xs[q], xs[(q + 1) % 5], angles[a], z), 41, 27, S + S / 2, NULL);
                    check(g, "seam, far", &m, at(xs[q], xs[(q + 2) % 5], angles[a], z), 23, 19, 3 * S, NULL);
                }
        retro_map_free(&m);
    }
    rig_close(g);
}

/* Camera heights equal to window maxima of the pyramid (and one off), where the bound's row
 * is the horizon itself. */
Test(skipping, camera_at_block_maximum)
{
    trio *g = rig_open();
    static const int sizes[] = {50, 64};
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        int S = sizes[si];
        retro_map m;
        noise_map(&m, S, 1800 + (uint64_t)S);
        new_map(g);
        player_t p = at((float)S / 3, (float)S / 4, 20, 100);
        check(g, "block maximum (setup)", &m, p, 37, 23, 2 * S, NULL);
        const retro_pyramid *pyr = retro_ctx_frame(g->rc[SKIP])->pyr;
        cr_assert(pyr && pyr->lmax >= RETRO_PYR_LMIN);
        int tried = 0;
        for (int L = RETRO_PYR_LMIN; L <= pyr->lmax; L++)
            for (int b = 0; b < pyr->n[L] * pyr->n[L]; b += 1 + pyr->n[L] * pyr->n[L] / 5) {
                int M = pyr->win[L][b];
                for (int dz = -1; dz <= 1; dz++)
                    for (int a = 0; a < NANGLES; a += 4) {
                        check(g, "block maximum", &m, at((float)S / 3, (float)S / 4, angles[a], M + dz), 37, 23, 2 * S,
                              NULL);
                        tried++;
                    }
            }
        cr_assert_gt(tried, 20);
        retro_map_free(&m);
    }
    rig_close(g);
}

Test(skipping, distance_at_and_beyond_map)
{
    trio *g = rig_open();
    static const int sizes[] = {5, 16, 37, 64};
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        int S = sizes[si];
        retro_map m;
        noise_map(&m, S, 77 + (uint64_t)S);
        new_map(g);
        const int Ds[] = {S - 1, S, S + 1, 2 * S, 4 * S + 3, 10 * S, 4000};
        for (size_t k = 0; k < sizeof Ds / sizeof Ds[0]; k++)
            for (int a = 0; a < NANGLES; a += 2)
                check(g, "distance", &m, at(1.75f, (float)S - 0.25f, angles[a], 140), 31, 29, Ds[k], NULL);
        retro_map_free(&m);
    }
    rig_close(g);
}

/* Tiny maps: S <= 4 has no pyramid level (the frame must say so), 5 has one. */
Test(skipping, tiny_maps)
{
    trio *g = rig_open();
    uint64_t st = 42;
    for (int S = 1; S <= 6; S++) {
        retro_map m;
        noise_map(&m, S, 5 + (uint64_t)S);
        new_map(g);
        for (int k = 0; k < 40; k++) {
            float x = (float)(rng_next(&st) % 10000) / 100.0f - 20, y = (float)(rng_next(&st) % 10000) / 100.0f - 20;
            int angle = (int)(rng_next(&st) % 720) - 360, z = (int)(rng_next(&st) % 400) - 50;
            check(g, "tiny", &m, at(x, y, angle, z), 1 + (int)(rng_next(&st) % 40), 1 + (int)(rng_next(&st) % 30),
                  (int)(rng_next(&st) % 60), NULL);
        }
        retro_map_free(&m);
    }
    rig_close(g);
}

/* Seeded random poses on the generated terrains, with no effect, fog, bilinear and both. */
Test(skipping, random_poses_on_generated_maps)
{
    trio *g = rig_open();
    static const struct { const char *style; int S; } maps[] = {
        {"alpine", 128}, {"islands", 100}, {"canyon", 200}, {"spike", 64}, {"checker", 45}};
    retro_effects fx[3];
    memset(fx, 0, sizeof fx);
    fx[0].flags = RETRO_FX_FOG;
    fx[1].flags = RETRO_FX_BILINEAR;
    fx[2].flags = RETRO_FX_FOG | RETRO_FX_BILINEAR;
    for (int i = 0; i < 3; i++) {
        fx[i].fog_start = 10;
        fx[i].fog_end = 150;
    }
    uint64_t st = 2026;
    for (size_t mi = 0; mi < sizeof maps / sizeof maps[0]; mi++) {
        retro_map m;
        char err[256];
        cr_assert_eq(retro_mapgen(maps[mi].style, 7 + mi, maps[mi].S, &m, err, sizeof err), 0, "%s", err);
        new_map(g);
        int S = m.size;
        for (int k = 0; k < 60; k++) {
            float x = (float)(rng_next(&st) % 100000) * (float)S / 100000.0f;
            float y = (float)(rng_next(&st) % 100000) * (float)S / 100000.0f;
            int angle = (int)(rng_next(&st) % 360), z = (int)(rng_next(&st) % 320) - 20;
            int W = 8 + (int)(rng_next(&st) % 90), H = 4 + (int)(rng_next(&st) % 70);
            int D = 1 + (int)(rng_next(&st) % (unsigned)(3 * S));
            check(g, maps[mi].style, &m, at(x, y, angle, z), W, H, D, (k & 3) ? &fx[(k & 3) - 1] : NULL);
        }
        retro_map_free(&m);
    }
    rig_close(g);
}

/* Bilinear's bound is the block maximum plus a rounding margin far below a unit of height
 * (RETRO_BILINEAR_OVER): flat ground and a single step of one unit, with the camera at,
 * just above and just below the ground, put the filtered heights and the bound within that
 * margin of each other on every probe. Even and odd frame heights put the middle of the
 * screen on and between rows. */
Test(skipping, bilinear_flat_ground)
{
    trio *g = rig_open();
    retro_effects fx;
    memset(&fx, 0, sizeof fx);
    fx.flags = RETRO_FX_BILINEAR;
    static const int levels[] = {0, 1, 128, 254, 255};
    for (size_t k = 0; k < sizeof levels / sizeof levels[0]; k++)
        for (int step = 0; step < 2; step++) {
            retro_map m;
            make_map(&m, 48);
            memset(m.height, levels[k], (size_t)48 * 48);
            if (step) /* the far half one unit lower, or higher at level 0 */
                for (int j = 0; j < 48; j++)
                    memset(m.height + (size_t)j * 48 + 24, levels[k] ? levels[k] - 1 : 1, 24);
            new_map(g);
            for (int dz = -1; dz <= 1; dz++)
                for (int a = 0; a < NANGLES; a += 3) {
                    check(g, "bilinear flat", &m, at(10.3f, 20.6f, angles[a], levels[k] + dz), 40, 31, 120, &fx);
                    check(g, "bilinear flat", &m, at(10.5f, 20.5f, angles[a], levels[k] + dz), 33, 40, 200, &fx);
                }
            retro_map_free(&m);
        }
    rig_close(g);
}

/* The fact bilinear_dh rests on (simd_sample_tpl.h): for a binary32 hf and an integer height
 * within 2^24, hf - (float)height rounded once equals the definition's (float)((double)hf -
 * height) rounded twice, even where hf is so small that the double difference is inexact. hf
 * runs over every binade a filtered height can take, subnormals included, with mantissas that
 * put bits far below the height's. */
Test(skipping, bilinear_float_difference)
{
    static const int heights[] = {0,   1,   -1,  2,   3,   -3,          127,         200,
                                  255, 256, 511, 4095, (1 << 24) - 1, 1 << 24, -(1 << 24), -(1 << 24) + 1};
    uint32_t s = 12345u;
    long differ = 0, n = 0;
    for (int e = 0; e < 136; e++) /* biased exponents 0 (subnormal) .. 135 (up to 2^9) */
        for (int r = 0; r < 256; r++) {
            s = s * 1664525u + 1013904223u;
            const uint32_t mant = r < 4 ? (uint32_t[]){0, 1, 0x400000, 0x7fffff}[r] : s >> 9;
            const uint32_t bits = (uint32_t)e << 23 | mant;
            float hf;
            memcpy(&hf, &bits, sizeof hf);
            for (size_t k = 0; k < sizeof heights / sizeof heights[0]; k++) {
                const float once = hf - (float)heights[k];
                const float twice = (float)((double)hf - heights[k]);
                differ += memcmp(&once, &twice, sizeof once) != 0;
                n++;
            }
        }
    cr_expect_eq(differ, 0, "%ld of %ld differences rounded once differ from the definition's", differ, n);
}

/* Bilinear's height difference (simd_sample_tpl.h, bilinear_dh): one float subtraction where
 * the camera height is within 2^24, double otherwise. A map of zeros with isolated low cells
 * gives filtered heights down to the product of two tiny weights, where the definition's
 * difference is not exact in double and rounds twice, beside exact zeros and ordinary values;
 * camera heights on both sides of 2^24 switch the float path off and on. */
Test(skipping, bilinear_height_difference)
{
    trio *g = rig_open();
    retro_map m;
    make_map(&m, 64);
    for (int j = 0; j < 64; j += 5)
        for (int i = (j * 3) % 7; i < 64; i += 7)
            m.height[(size_t)j * 64 + (size_t)i] = (uint8_t)(1 + (i + j) % 3 * 127);
    new_map(g);
    retro_effects fx;
    memset(&fx, 0, sizeof fx);
    fx.flags = RETRO_FX_BILINEAR;
    static const int heights[] = {0, 1, 3, 200, (1 << 24) - 1, 1 << 24, (1 << 24) + 1, (1 << 24) + 3,
                                  -(1 << 24), -(1 << 24) - 1, 1 << 30};
    for (size_t z = 0; z < sizeof heights / sizeof heights[0]; z++)
        for (int a = 0; a < NANGLES; a += 3) {
            /* positions a hair off the cell centres: weights near 0 and 1 */
            check(g, "bilinear dh", &m, at(20.5f + 0x1p-17f, 30.5f - 0x1p-18f, angles[a], heights[z]), 41, 29, 90, &fx);
            check(g, "bilinear dh", &m, at(7.25f, 50.75f, angles[a], heights[z]), 41, 29, 90, &fx);
        }
    /* Camera heights near 2^24 only reach the screen from far away: a narrow, tall frame whose
     * distant samples project between the rows. */
    static const int far[] = {1 << 24, (1 << 24) + 1, -(1 << 24) - 1};
    for (size_t z = 0; z < sizeof far / sizeof far[0]; z++)
        for (int a = 1; a < NANGLES; a += 5)
            check(g, "bilinear dh far", &m, at(20.5f + 0x1p-17f, 30.5f, angles[a], far[z]), 2, 300, 200000, &fx);
    retro_map_free(&m);
    rig_close(g);
}
