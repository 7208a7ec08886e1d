/* retro_hmax_get: the maximum of every cell, whichever lane of the vector scan or tail holds
 * it; a maximum it missed would move every frame's early exit (frame.c's vcap). */
#include <criterion/criterion.h>
#include <stdlib.h>
#include <string.h>

#include "ctx.h"
#include "frame.h"
#include "hmax_cache.h"
#include "kernels.h"
#include "retro.h"

Test(hmax, every_position_and_size)
{
    for (int S = 1; S <= 40; S++) {
        size_t n = (size_t)S * (size_t)S;
        uint8_t *map = malloc(n);
        cr_assert_not_null(map);
        for (size_t at = 0; at < n; at++) {
            for (size_t i = 0; i < n; i++)
                map[i] = (uint8_t)(i * 37 % 200); /* below the planted maximum */
            map[at] = (uint8_t)(201 + at % 55);
            retro_hmax_cache hc = {0};
            cr_assert_eq(retro_hmax_get(&hc, map, S), map[at], "S %d, maximum at %zu", S, at);
        }
        free(map);
    }
}

Test(hmax, cached_until_stale)
{
    uint8_t map[64 * 64];
    memset(map, 9, sizeof map);
    retro_hmax_cache hc = {0};
    cr_assert_eq(retro_hmax_get(&hc, map, 64), 9);
    map[4095] = 255;
    cr_assert_eq(retro_hmax_get(&hc, map, 64), 9, "the same map and size: the cached value");
    retro_hmax_stale(&hc);
    cr_assert_eq(retro_hmax_get(&hc, map, 64), 255);
    cr_assert_eq(retro_hmax_get(&hc, map, 63), 9, "a new size scans 63*63 cells again");
}

/* A context's map_scan is the scan frame setup fills its stale cache with (the submission's
 * split scan), called once per stale map, with the context as its argument. */
static int scans;
static uint8_t counting_scan(void *arg, const uint8_t *map, size_t n)
{
    scans++;
    cr_assert_not_null(arg);
    return retro_map_max(map, n);
}

Test(hmax, frame_setup_scans_with_the_contexts_scan)
{
    retro_ctx *rc = retro_ctx_new();
    cr_assert_not_null(rc);
    rc->map_scan = counting_scan;
    enum { S = 32, W = 8, H = 6 };
    static uint8_t heights[S * S];
    static uint32_t colours[S * S], out[W * H];
    memset(heights, 7, sizeof heights);
    heights[S * S - 1] = 250;
    player_t p = {.x = 5.0f, .y = 5.0f, .height = 100, .angle = 0};
    ctx_t c = {.height_map = heights, .color_map = colours, .map_size = S, .distance = 20,
               .scr_width = W, .scr_height = H, .out = out};
    cr_assert_eq(retro_frame_setup(rc, RETRO_MODE_EXACT, &p, &c), RETRO_OK);
    cr_assert_eq(scans, 1);
    cr_assert_eq(retro_ctx_frame(rc)->hmax, 250, "the scan's maximum reaches the frame");
    cr_assert_eq(retro_frame_setup(rc, RETRO_MODE_EXACT, &p, &c), RETRO_OK);
    cr_assert_eq(scans, 1, "a cached maximum is not scanned again");
    retro_ctx_map_changed(rc);
    cr_assert_eq(retro_frame_setup(rc, RETRO_MODE_EXACT, &p, &c), RETRO_OK);
    cr_assert_eq(scans, 2, "a stale cache is scanned by the context's scan");
    retro_ctx_free(rc);
}

/* The submission's scan, split between the pthreads kernel's threads: each thread's slice,
 * the last one short, for 1 to 4 threads. */
Test(hmax, split_between_threads)
{
    retro_ctx *rc = retro_ctx_new();
    cr_assert_not_null(rc);
    const int sizes[] = {2, 3, 17, 64, 100, 257};
    for (int T = 1; T <= 4; T++) {
        rc->threads = T;
        for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
            const int S = sizes[k];
            const size_t n = (size_t)S * (size_t)S;
            uint8_t *map = malloc(n);
            cr_assert_not_null(map);
            const size_t ats[] = {0, n / 4, n / 2, n / 2 + 1, 3 * n / 4, n - 65, n - 2, n - 1};
            for (size_t a = 0; a < sizeof ats / sizeof ats[0]; a++) {
                const size_t at = ats[a] < n ? ats[a] : n - 1;
                memset(map, 3, n);
                map[at] = 99;
                cr_assert_eq(retro_pthreads_map_scan(rc, map, n), 99, "%d threads, S %d, maximum at %zu", T, S, at);
            }
            free(map);
        }
    }
    retro_ctx_free(rc);
}
