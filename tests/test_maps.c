/* Map and image files: every malformed input is an error naming the problem, never a crash. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "test_util.h"

static char dir[] = "/tmp/retro-maps-XXXXXX";

static void setup(void) { cr_assert(mkdtemp(dir)); }
static void teardown(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    cr_assert_eq(system(cmd), 0);
}

static void put(const char *name, const void *data, size_t n)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    cr_assert(f);
    fwrite(data, 1, n, f);
    fclose(f);
}

/* Writes NAME.pgm and NAME.ppm with the given headers and pixel byte counts. */
static void put_map(const char *name, const char *pgm_hdr, size_t pgm_px, const char *ppm_hdr,
                    size_t ppm_px)
{
    char fn[128];
    unsigned char *buf = calloc(1, 4096 + pgm_px + ppm_px);
    size_t h = strlen(pgm_hdr);
    memcpy(buf, pgm_hdr, h);
    snprintf(fn, sizeof fn, "%s.pgm", name);
    put(fn, buf, h + pgm_px);
    h = strlen(ppm_hdr);
    memcpy(buf, ppm_hdr, h);
    memset(buf + h, 0, ppm_px);
    snprintf(fn, sizeof fn, "%s.ppm", name);
    put(fn, buf, h + ppm_px);
    free(buf);
}

static void expect_error(const char *name, const char *needle)
{
    char prefix[256], err[512] = "";
    retro_map m;
    snprintf(prefix, sizeof prefix, "%s/%s", dir, name);
    cr_assert_eq(retro_map_load(prefix, &m, err, sizeof err), -1, "%s loaded but should fail", name);
    cr_assert(strstr(err, needle), "%s: error '%s' does not mention '%s'", name, err, needle);
    cr_assert(!strchr(err, '\n'), "error must be one line: %s", err);
}

TestSuite(maps, .init = setup, .fini = teardown);

Test(maps, loads_valid_map)
{
    put_map("ok", "P5\n# comment\n4 4\n255\n", 16, "P6\n4 4\n255\n", 48);
    char prefix[256], err[256];
    snprintf(prefix, sizeof prefix, "%s/ok", dir);
    retro_map m;
    cr_assert_eq(retro_map_load(prefix, &m, err, sizeof err), 0, "%s", err);
    cr_assert_eq(m.size, 4);
    retro_map_free(&m);
}

Test(maps, missing) { expect_error("nothing", "No such file"); }
Test(maps, missing_colour)
{
    put("hm.pgm", "P5\n2 2\n255\n\0\0\0\0", 15);
    expect_error("hm", "no colour map");
}
Test(maps, truncated)
{
    put_map("t", "P5\n4 4\n255\n", 10, "P6\n4 4\n255\n", 48);
    expect_error("t", "truncated");
}
Test(maps, truncated_header)
{
    put_map("th", "P5\n4 ", 0, "P6\n4 4\n255\n", 48);
    expect_error("th", "truncated");
}
Test(maps, not_square)
{
    put_map("ns", "P5\n4 2\n255\n", 8, "P6\n4 2\n255\n", 24);
    expect_error("ns", "not square");
}
Test(maps, size_mismatch)
{
    put_map("mm", "P5\n4 4\n255\n", 16, "P6\n2 2\n255\n", 12);
    expect_error("mm", "colour map is 2x2 but height map is 4x4");
}
Test(maps, maxval_not_255)
{
    put_map("mv", "P5\n4 4\n65535\n", 32, "P6\n4 4\n255\n", 48);
    expect_error("mv", "maxval");
}
Test(maps, absurd_size)
{
    put_map("ab", "P5\n99999 99999\n255\n", 0, "P6\n4 4\n255\n", 48);
    expect_error("ab", "absurd");
}
Test(maps, zero_size)
{
    put_map("z", "P5\n0 0\n255\n", 0, "P6\n4 4\n255\n", 48);
    expect_error("z", "positive");
}
Test(maps, wrong_magic)
{
    put_map("wm", "P2\n4 4\n255\n", 16, "P6\n4 4\n255\n", 48);
    expect_error("wm", "not a binary P5");
}

Test(maps, png_colour_map_round_trip)
{
    retro_map m;
    char err[256], prefix[256];
    cr_assert_eq(retro_mapgen("ramp", 0, 17, &m, err, sizeof err), 0, "%s", err);
    snprintf(prefix, sizeof prefix, "%s/rt", dir);
    cr_assert_eq(retro_map_save(prefix, &m, 1, err, sizeof err), 0, "%s", err);
    retro_map back;
    cr_assert_eq(retro_map_load(prefix, &back, err, sizeof err), 0, "%s", err);
    cr_assert_eq(back.size, 17);
    cr_assert(!memcmp(back.height, m.height, 17 * 17));
    cr_assert(!memcmp(back.color, m.color, 17 * 17 * sizeof(uint32_t)));
    retro_map_free(&m);
    retro_map_free(&back);
}

Test(maps, failed_write_leaves_nothing)
{
    uint32_t px[4] = {0};
    char path[256], err[256];
    snprintf(path, sizeof path, "%s/no-such-dir/out.png", dir);
    cr_assert_eq(retro_image_write(path, px, 2, 2, err, sizeof err), -1);
    snprintf(path, sizeof path, "%s/out.bmp", dir);
    cr_assert_eq(retro_image_write(path, px, 2, 2, err, sizeof err), -1);
    cr_assert_neq(access(path, F_OK), 0);
}

Test(maps, generator_is_deterministic)
{
    const char *styles[] = {"alpine", "islands", "canyon"};
    for (int s = 0; s < 3; s++) {
        retro_map a, b, c;
        char err[256];
        cr_assert_eq(retro_mapgen(styles[s], 5, 100, &a, err, sizeof err), 0, "%s", err);
        cr_assert_eq(retro_mapgen(styles[s], 5, 100, &b, err, sizeof err), 0, "%s", err);
        cr_assert_eq(retro_mapgen(styles[s], 6, 100, &c, err, sizeof err), 0, "%s", err);
        cr_assert(!memcmp(a.height, b.height, 100 * 100) && !memcmp(a.color, b.color, 4 * 100 * 100));
        cr_assert(memcmp(a.height, c.height, 100 * 100), "%s: seeds 5 and 6 gave the same map", styles[s]);
        retro_map_free(&a);
        retro_map_free(&b);
        retro_map_free(&c);
    }
    retro_map m;
    char err[256];
    cr_assert_eq(retro_mapgen("volcano", 1, 8, &m, err, sizeof err), -1);
    cr_assert(strstr(err, "unknown map style"));
    for (int size = 1; size <= 3; size++) {
        cr_assert_eq(retro_mapgen("alpine", 1, size, &m, err, sizeof err), 0, "%s", err);
        retro_map_free(&m);
    }
}
