/* Built against kernels compiled with RETRO_COUNT_WRITES: counts the stores to every pixel and
 * fails if a kernel declared write-once (RETRO_KF_WRITE_ONCE) writes a pixel other than
 * exactly once in a frame. */
#include <criterion/criterion.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "test_util.h"

static const uint32_t *counted_out;
static size_t counted_n;
static unsigned *counts;

void retro_count_write(const uint32_t *out, size_t idx);
void retro_count_write(const uint32_t *out, size_t idx)
{
    if (out == counted_out && idx < counted_n)
        counts[idx]++;
    else
        counts[counted_n]++; /* a store outside the frame */
}

static void check(const retro_kernel *k, retro_mode mode, const retro_map *m, const player_t *p,
                  int W, int H, int D)
{
    size_t n = (size_t)W * (size_t)H;
    uint32_t *out = malloc(n * sizeof *out);
    counts = calloc(n + 1, sizeof *counts);
    counted_out = out;
    counted_n = n;
    ctx_t c = {W, H, m->size, D, 0, m->height, m->color, out};
    render_with(k->name, mode, p, &c);
    cr_assert_eq(counts[n], 0u, "%s wrote outside the frame", k->name);
    for (size_t i = 0; i < n; i++)
        cr_assert_eq(counts[i], 1u, "%s/%s wrote pixel (%zu,%zu) %u times (%dx%d, D %d)", k->name,
                     retro_mode_name(mode), i % (size_t)W + 1, (size_t)H - i / (size_t)W, counts[i], W, H, D);
    free(out);
    free(counts);
}

/* Both map size classes: 200 takes the general wrap, 64 the power-of-two paths. */
static void every_pixel_on(const char *map)
{
    retro_map m;
    test_map(map, &m);
    struct { int W, H, D, z, angle; float x, y; } cases[] = {
        {160, 120, 300, 120, 30, 50.5f, 70.25f}, {1, 1, 800, 100, 0, 3, 3}, {64, 1, 100, 100, 90, 1, 1},
        {1, 64, 100, 100, 180, 1, 1},           {33, 17, 0, 100, 0, 5, 5},  {33, 17, 2, 100, 0, 5, 5},
        {50, 40, 200, INT_MIN, 45, 9, 9},        {50, 40, 200, INT_MAX, 45, 9, 9},
        {120, 90, 1000, 20, 300, -40, 1e6f},
    };
    int checked = 0;
    for (size_t k = 0; k < retro_kernel_count; k++) {
        const retro_kernel *kr = &retro_kernels[k];
        if (!(kr->flags & RETRO_KF_WRITE_ONCE) || !retro_kernel_runs_here(kr))
            continue;
        for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            player_t p = {cases[i].x, cases[i].y, cases[i].angle, cases[i].z, 0, 0, 0};
            for (int mode = 0; mode < RETRO_MODE_COUNT; mode++)
                if (retro_kernel_has_mode(kr, (retro_mode)mode))
                    check(kr, (retro_mode)mode, &m, &p, cases[i].W, cases[i].H, cases[i].D);
        }
        checked++;
    }
    cr_assert(checked >= 1, "no write-once kernel was checked");
    retro_map_free(&m);
}

Test(write_once, every_pixel_exactly_once) { every_pixel_on("test/alpine-200"); }
Test(write_once, every_pixel_exactly_once_pow2) { every_pixel_on("test/ramp-64"); }

/* The counter itself must catch a double write: naive paints the sky and then terrain. */
Test(write_once, counter_catches_the_painter)
{
    retro_map m;
    test_map("test/alpine-200", &m);
    size_t n = 40 * 30;
    uint32_t *out = malloc(n * sizeof *out);
    counts = calloc(n + 1, sizeof *counts);
    counted_out = out;
    counted_n = n;
    ctx_t c = {40, 30, m.size, 200, 0, m.height, m.color, out};
    player_t p = {50, 50, 0, m.height[50 * 200 + 50] + 30, 0, 0, 0};
    render_with("naive", RETRO_MODE_EXACT, &p, &c);
    unsigned most = 0;
    for (size_t i = 0; i < n; i++)
        most = counts[i] > most ? counts[i] : most;
    cr_assert_gt(most, 1u);
    free(out);
    free(counts);
    retro_map_free(&m);
}
