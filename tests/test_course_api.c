/* The course's functions: draw_line, update_player and render against the course's data. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "test_util.h"

#define RED 0xff000000u
#define GREEN 0x00ff0000u
#define BLUE 0x0000ff00u

/* The course's draw_line test image (../shared/course/README.md). */
Test(course, draw_line_test_image)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/test_image_ref.ppm", course_dir());
    unsigned char *ref;
    long n = read_file(path, &ref);
    if (n < 0)
        cr_skip_test("%s absent: course data not available", path);
    enum { W = 321, H = 241 };
    uint32_t *px = malloc(sizeof(uint32_t) * W * H);
    ctx_t c = {W, H, 0, 0, 0, NULL, NULL, px};
    for (int i = 0; i < W * H; i++)
        px[i] = 0x55555500u;
    draw_line(&c, 1, 0, H, RED);
    draw_line(&c, W, 0, H, RED);
    for (int u = 1; u <= W; u++) {
        draw_line(&c, u, 0, 1, BLUE);
        draw_line(&c, u, H - 1, H, BLUE);
    }
    draw_line(&c, 161, 0, H, 0);
    for (int u = 1; u <= W; u++)
        draw_line(&c, u, 120, 121, 0xffffff00u);
    int step = 161 / 5;
    draw_line(&c, step, 121, 151, RED);
    draw_line(&c, 2 * step, 121, 181, GREEN);
    draw_line(&c, 3 * step, 121, 211, BLUE);
    draw_line(&c, 161 + step, 30, 121, 0x00ffff00u);
    draw_line(&c, 161 + 2 * step, 60, 121, 0xff00ff00u);
    draw_line(&c, 161 + 3 * step, 90, 121, 0xffff0000u);
    char tmp[64];
    snprintf(tmp, sizeof tmp, "/tmp/retro-test-%d.ppm", (int)getpid());
    char err[256];
    cr_assert_eq(retro_image_write(tmp, px, W, H, err, sizeof err), 0, "%s", err);
    unsigned char *got;
    long m = read_file(tmp, &got);
    unlink(tmp);
    cr_assert_eq(m, n, "size %ld, reference %ld", m, n);
    cr_assert(!memcmp(got, ref, (size_t)n), "test image differs from %s", path);
    free(got);
    free(ref);
    free(px);
}

Test(course, draw_line_bounds)
{
    uint32_t px[4 * 3];
    ctx_t c = {4, 3, 0, 0, 0, NULL, NULL, px};
    memset(px, 0, sizeof px);
    draw_line(&c, 2, 1, 1, RED); /* v_from == v_to: nothing */
    draw_line(&c, 0, 0, 3, RED); /* column outside the screen */
    draw_line(&c, 5, 0, 3, RED);
    for (int i = 0; i < 12; i++)
        cr_assert_eq(px[i], 0u);
    draw_line(&c, 3, -5, 99, RED); /* clipped to the screen */
    for (int r = 0; r < 3; r++)
        cr_assert_eq(px[r * 4 + 2], RED);
    draw_line(&c, 1, 1, 2, GREEN); /* rows 2 only: v_from exclusive, v_to inclusive */
    cr_assert_eq(px[1 * 4 + 0], GREEN);
    cr_assert_eq(px[2 * 4 + 0], 0u);
    cr_assert_eq(px[0 * 4 + 0], 0u);
}

static uint8_t ground[16 * 16];
static ctx_t player_ctx(void)
{
    ctx_t c = {640, 480, 16, 100, 0, ground, NULL, NULL};
    memset(ground, 0, sizeof ground);
    return c;
}

Test(player, course_cases)
{
    uint8_t h[1024 * 16];
    memset(h, 0, sizeof h);
    ctx_t c = {640, 480, 128, 100, 0, h, NULL, NULL};
    player_t p = {100, 100, 90, 100, 5, 0, 0};
    update_player(&p, &c);
    cr_assert_float_eq(p.y, 95.0f, 0.001f);
    cr_assert_float_eq(p.x, 100.0f, 0.001f);
    player_t q = {100, 100, 90, 100, 0, 5, 0};
    update_player(&q, &c);
    cr_assert_eq(q.height, 105);
    player_t r = {100, 100, 90, 100, 0, 0, 5};
    update_player(&r, &c);
    cr_assert_eq(r.angle, 95);
}

Test(player, wraps_both_directions)
{
    ctx_t c = player_ctx();
    player_t p = {15.5f, 0.5f, 0, 100, 1, 0, 0}; /* east across x = S */
    update_player(&p, &c);
    cr_assert_float_eq(p.x, 0.5f, 1e-4f);
    player_t q = {0.5f, 3, 180, 100, 1, 0, 0}; /* west across x = 0 */
    update_player(&q, &c);
    cr_assert_float_eq(q.x, 15.5f, 1e-4f);
    player_t r = {3, 0.5f, 90, 100, 1, 0, 0}; /* north: y decreases across 0 */
    update_player(&r, &c);
    cr_assert_float_eq(r.y, 15.5f, 1e-4f);
    player_t s = {3, 15.5f, 270, 100, 1, 0, 0}; /* south across y = S */
    update_player(&s, &c);
    cr_assert_float_eq(s.y, 0.5f, 1e-4f);
    cr_assert(p.x >= 0 && p.x < 16 && q.x >= 0 && q.x < 16);
}

Test(player, angle_normalised)
{
    ctx_t c = player_ctx();
    int cases[][3] = {{10, -20, 350}, {0, -360, 0}, {0, -725, 355}, {350, 20, 10},
                      {0, 1000000, 1000000 % 360}, {0, -2147483647 - 1, 232}, {359, 2147483647, 126}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        player_t p = {1, 1, cases[i][0], 100, 0, 0, cases[i][1]};
        update_player(&p, &c);
        cr_assert_eq(p.angle, cases[i][2], "angle %d + %d gave %d", cases[i][0], cases[i][1], p.angle);
    }
}

Test(player, stays_20_above_ground)
{
    ctx_t c = player_ctx();
    ground[5 * 16 + 7] = 200;
    player_t p = {7.9f, 5.2f, 0, 100, 0, -50, 0};
    update_player(&p, &c);
    cr_assert_eq(p.height, 220);
    player_t q = {7.9f, 5.2f, 0, 300, 0, -50, 0}; /* high enough: only v_height applies */
    update_player(&q, &c);
    cr_assert_eq(q.height, 250);
    player_t r = {1.5f, 1.5f, 0, 5, 0, 0, 0}; /* flat ground 0: floor at 20 */
    update_player(&r, &c);
    cr_assert_eq(r.height, 20);
}

struct course_frame {
    const char *map, *ref;
    int W, H, D;
    float x, y;
    int height;
};
static const struct course_frame frames[] = {
    {"island", "public.island01.ppm", 800, 600, 600, 147.436798f, 539.899414f, 88},
    {"pyramids", "public.pyramids01.ppm", 640, 480, 800, 110.388893f, 887.813843f, 164},
    {"valley", "public.valley01.ppm", 640, 480, 800, 997.808716f, 559.177063f, 230},
};

/* Renders a course frame with render() (or a kernel) and compares the PPM file bytes. */
static void check_course_frame(const struct course_frame *f, const char *kernel)
{
    retro_map m;
    if (course_map(f->map, &m))
        cr_skip_test("%s absent: course data not available", course_dir());
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", course_dir(), f->ref);
    unsigned char *ref;
    long n = read_file(path, &ref);
    cr_assert(n > 0, "cannot read %s", path);
    uint32_t *px = malloc(sizeof(uint32_t) * (size_t)f->W * (size_t)f->H);
    ctx_t c = {f->W, f->H, m.size, f->D, 0x66a3ff00u, m.height, m.color, px};
    player_t p = {f->x, f->y, 0, f->height, 0, 0, 0};
    if (kernel)
        render_with(kernel, RETRO_MODE_COURSE, &p, &c);
    else
        render(&p, &c);
    char hdr[64];
    int hl = snprintf(hdr, sizeof hdr, "P6\n%d %d\n255\n", f->W, f->H);
    cr_assert_eq(n, hl + 3L * f->W * f->H);
    cr_assert(!memcmp(ref, hdr, (size_t)hl));
    long bad = 0;
    for (long i = 0; i < (long)f->W * f->H; i++) {
        const unsigned char *q = ref + hl + 3 * i;
        uint32_t want = (uint32_t)q[0] << 24 | (uint32_t)q[1] << 16 | (uint32_t)q[2] << 8;
        bad += px[i] != want;
    }
    cr_assert_eq(bad, 0, "%s with %s: %ld pixels differ from %s", f->map, kernel ? kernel : "render()",
                 bad, f->ref);
    free(px);
    free(ref);
    retro_map_free(&m);
}

Test(course, render_matches_island01) { check_course_frame(&frames[0], NULL); }
Test(course, render_matches_pyramids01) { check_course_frame(&frames[1], NULL); }
Test(course, render_matches_valley01) { check_course_frame(&frames[2], NULL); }
Test(course, naive_matches_references)
{
    for (int i = 0; i < 3; i++)
        check_course_frame(&frames[i], "naive");
}

Test(course, bonus_implemented) { cr_assert_eq(bonus_implemented(), 1); }

/* render() keeps nothing it learnt from the maps between calls: after a tower far above the
 * old maximum is written into the map in place, at the same address, the next frame draws it
 * as the naive kernel does. With the old maximum kept, the columns' early exit would stop them
 * short of the tower. */
Test(course, render_sees_a_map_edited_in_place)
{
    enum { S = 256, W = 160, H = 120, D = 200 };
    uint8_t *hm = malloc((size_t)S * S);
    uint32_t *cm = malloc(sizeof(uint32_t) * S * S);
    uint32_t *before = malloc(sizeof(uint32_t) * W * H), *after = malloc(sizeof(uint32_t) * W * H);
    uint32_t *want = malloc(sizeof(uint32_t) * W * H);
    cr_assert(hm && cm && before && after && want);
    for (int j = 0; j < S; j++)
        for (int i = 0; i < S; i++) {
            hm[j * S + i] = (uint8_t)(85 + (i * 7 + j * 13) % 5); /* just below the camera */
            cm[j * S + i] = ((uint32_t)i * 2654435761u ^ (uint32_t)j * 40503u) & 0xffffff00u;
        }
    ctx_t c = {W, H, S, D, 0x66a3ff00u, hm, cm, before};
    player_t p = {128.5f, 128.5f, 0, 90, 0, 0, 0};
    render(&p, &c);
    for (int j = 100; j < 157; j++) /* 140..160 cells ahead (+x), across the (S-1)-torus seam */
        for (int i = 268; i < 289; i++)
            hm[j * S + i % (S - 1)] = 250;
    c.out = after;
    render(&p, &c);
    c.out = want;
    render_with("naive", RETRO_MODE_COURSE, &p, &c);
    cr_assert(memcmp(before, want, sizeof(uint32_t) * W * H) != 0, "the tower must show in the frame");
    cr_assert(!memcmp(after, want, sizeof(uint32_t) * W * H), "render() drew the edited map unlike naive");
    free(hm);
    free(cm);
    free(before);
    free(after);
    free(want);
}
