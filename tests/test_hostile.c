/* Hostile input at the library's level (issue 13); the CLI's contract is in tests/hostile_*.sh.
 * Each test here failed before its fix. */
#include <criterion/criterion.h>
#include <spng.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "retro_scene.h"
#include "test_util.h"

/* The accuracy command's pose drawing lives with the CLI, which this binary does not link. */
#include "../src/cli/accuracy_metrics.c"

/* Draws near 1 made (float)(rand * S) exactly S, and the ground lookup read row S. */
Test(hostile, accuracy_poses_stay_inside_the_map)
{
    static const struct { uint64_t seed; int S; } edge[] = {
        {8732044540224338163ull, 1024}, /* the first pose of the 1024 maps: y = 1024 */
        {6858133517494099162ull, 1448},
    };
    for (size_t i = 0; i < sizeof edge / sizeof edge[0]; i++) {
        int S = edge[i].S;
        uint64_t rng = edge[i].seed;
        float x = (float)(acc_rand(&rng) * S), y = (float)(acc_rand(&rng) * S);
        cr_assert(x == (float)S || y == (float)S, "seed %llu no longer reaches the edge of %d",
                  (unsigned long long)edge[i].seed, S);
        uint8_t *h = calloc((size_t)S * (size_t)S, 1);
        rng = edge[i].seed;
        player_t p;
        acc_pose(&rng, S, h, &p);
        cr_assert(p.x >= 0 && p.x < (float)S && p.y >= 0 && p.y < (float)S,
                  "pose (%g, %g) outside [0, %d)", (double)p.x, (double)p.y, S);
        free(h);
    }
}

/* RETRO_OMP_CHUNK=2147483647 overflowed the chunk count: the frame was never rendered. */
Test(hostile, omp_chunk_out_of_range_falls_back)
{
    static const char *const bad[] = {"2147483647", "0", "-64", "12abc", ""};
    retro_map m;
    noise_map(&m, 64, 7);
    player_t p = {30.5f, 20.25f, 45, 120, 0, 0, 0};
    uint32_t *want = malloc(sizeof(uint32_t) * 80 * 60), *got = malloc(sizeof(uint32_t) * 80 * 60);
    ctx_t c = {80, 60, 64, 300, 0x000000ffu, m.height, m.color, want};
    render_with("naive", RETRO_MODE_EXACT, &p, &c);
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        setenv("RETRO_OMP_CHUNK", bad[i], 1);
        memset(got, 0, sizeof(uint32_t) * 80 * 60);
        c.out = got;
        render_with("omp", RETRO_MODE_EXACT, &p, &c);
        cr_assert(!memcmp(got, want, sizeof(uint32_t) * 80 * 60), "RETRO_OMP_CHUNK=%s", bad[i]);
    }
    free(want);
    free(got);
    retro_map_free(&m);
}

Test(hostile, retro_isa_naming_no_level_limits_to_none)
{
    setenv("RETRO_ISA", "avx", 1);
    cr_assert_eq(retro_cpu_features(), 0u);
}

/* Writes a PNG of the given colour type and depth holding pixels px (already in that format). */
static void write_png(const char *path, int type, int depth, const void *px, size_t len,
                      const struct spng_plte *plte)
{
    spng_ctx *ctx = spng_ctx_new(SPNG_CTX_ENCODER);
    struct spng_ihdr ihdr = {.width = 2, .height = 2, .bit_depth = (uint8_t)depth, .color_type = (uint8_t)type};
    spng_set_option(ctx, SPNG_ENCODE_TO_BUFFER, 1);
    spng_set_ihdr(ctx, &ihdr);
    if (plte)
        spng_set_plte(ctx, (struct spng_plte *)plte);
    cr_assert_eq(spng_encode_image(ctx, px, len, SPNG_FMT_PNG, SPNG_ENCODE_FINALIZE), 0);
    size_t n;
    int e;
    void *png = spng_get_png_buffer(ctx, &n, &e);
    FILE *f = fopen(path, "wb");
    cr_assert(png && f && fwrite(png, 1, n, f) == n);
    fclose(f);
    free(png);
    spng_ctx_free(ctx);
}

/* Every colour type and depth PNG allows decodes to the colours it stores (alpha ignored). */
Test(hostile, png_colour_types)
{
    char path[] = "/tmp/retro-hostile-XXXXXX";
    int fd = mkstemp(path);
    cr_assert(fd >= 0);
    close(fd);
    const uint32_t grey[4] = {0x00000000u, 0x40404000u, 0x80808000u, 0xffffff00u};
    const uint32_t rgb[4] = {0x10203000u, 0x40506000u, 0x708090u << 8, 0xa0b0c000u};
    const uint8_t g8[4] = {0x00, 0x40, 0x80, 0xff}, ga8[8] = {0x00, 9, 0x40, 9, 0x80, 0, 0xff, 255};
    /* 16-bit samples go to the encoder in host order; 8-bit output keeps the high byte */
    const uint16_t g16[4] = {0x0001, 0x4002, 0x8003, 0xffff};
    const uint8_t g1[2] = {0x40, 0x40}; /* rows 01, 01: black, white */
    const uint8_t c8[12] = {0x10, 0x20, 0x30, 0x40, 0x50, 0x60, 0x70, 0x80, 0x90, 0xa0, 0xb0, 0xc0};
    const uint8_t ca8[16] = {0x10, 0x20, 0x30, 0, 0x40, 0x50, 0x60, 1, 0x70, 0x80, 0x90, 2, 0xa0, 0xb0, 0xc0, 3};
    uint16_t c16[12];
    for (int i = 0; i < 12; i++)
        c16[i] = (uint16_t)(c8[i] << 8 | 0x77);
    const uint8_t idx[4] = {0, 1, 2, 3};
    struct spng_plte plte = {.n_entries = 4};
    for (int i = 0; i < 4; i++)
        plte.entries[i] = (struct spng_plte_entry){c8[3 * i], c8[3 * i + 1], c8[3 * i + 2], 255};
    const uint32_t bw[4] = {0x00000000u, 0xffffff00u, 0x00000000u, 0xffffff00u};
    const struct { int type, depth; const void *px; size_t len; const uint32_t *want; } cases[] = {
        {SPNG_COLOR_TYPE_GRAYSCALE, 8, g8, 4, grey}, {SPNG_COLOR_TYPE_GRAYSCALE, 16, g16, 8, grey},
        {SPNG_COLOR_TYPE_GRAYSCALE, 1, g1, 2, bw}, {SPNG_COLOR_TYPE_GRAYSCALE_ALPHA, 8, ga8, 8, grey},
        {SPNG_COLOR_TYPE_TRUECOLOR, 8, c8, 12, rgb}, {SPNG_COLOR_TYPE_TRUECOLOR, 16, c16, 24, rgb},
        {SPNG_COLOR_TYPE_TRUECOLOR_ALPHA, 8, ca8, 16, rgb}, {SPNG_COLOR_TYPE_INDEXED, 8, idx, 4, rgb},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        write_png(path, cases[i].type, cases[i].depth, cases[i].px, cases[i].len,
                  cases[i].type == SPNG_COLOR_TYPE_INDEXED ? &plte : NULL);
        uint32_t *px = NULL;
        int w = 0, h = 0;
        char err[256];
        cr_assert_eq(retro_rgb_read(path, &px, &w, &h, err, sizeof err), 0, "type %d depth %d: %s",
                     cases[i].type, cases[i].depth, err);
        cr_assert(w == 2 && h == 2);
        cr_assert(!memcmp(px, cases[i].want, sizeof(uint32_t) * 4), "type %d depth %d: %08x %08x %08x %08x",
                  cases[i].type, cases[i].depth, px[0], px[1], px[2], px[3]);
        free(px);
    }
    unlink(path);
}

/* A FIFO is refused at once, not read (which blocked until a writer came). */
Test(hostile, fifo_map_refused_without_blocking, .timeout = 10)
{
    char dir[] = "/tmp/retro-hostile-XXXXXX", path[64];
    cr_assert(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/f.pgm", dir);
    cr_assert_eq(mkfifo(path, 0600), 0);
    uint8_t *h = NULL;
    int w, hh;
    char err[256];
    cr_assert_eq(retro_pgm_read(path, &h, &w, &hh, err, sizeof err), -1);
    cr_assert(strstr(err, "FIFO"), "%s", err);
    unlink(path);
    rmdir(dir);
}

/* A NUL ended a line early for inih: "height = 30\0width = 40" set both keys and line numbers
 * drifted. Now the line is refused, at its own number. */
Test(hostile, scene_nul_refused_at_its_line)
{
    char path[] = "/tmp/retro-hostile-XXXXXX";
    int fd = mkstemp(path);
    static const char text[] = "[scene]\nmap = m\n\n[screen]\nheight = 30\0width = 40\n[bogus]\n";
    cr_assert(write(fd, text, sizeof text - 1) == (ssize_t)(sizeof text - 1));
    close(fd);
    retro_scene s;
    char err[512], want[64];
    cr_assert_eq(retro_scene_load(path, &s, err, sizeof err), -1);
    snprintf(want, sizeof want, "%s:5: NUL byte", path);
    cr_assert(strstr(err, want), "%s", err);
    unlink(path);
}
