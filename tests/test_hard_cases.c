/* Hard cases (issue 8): inputs at the edges of the valid domain of SEMANTICS.md, rendered by
 * every kernel at every ISA level (threaded kernels at 1, 2 and 3 threads) in every mode the
 * case is valid for, each byte-identical to naive; the invariances mode exact promises
 * exactly; and the numerics of binary32 sampling against an exact-arithmetic truth
 * (docs/NUMERICS.md; RETRO_NUMERICS=1 prints the tables quoted there).
 *
 * A mismatch is printed with its case, kernel, mode, ISA level, thread count and first
 * differing pixel, and the remaining cases still run: one failing kernel must not hide
 * another. */
#include <criterion/criterion.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "retro_internal.h"
#include "hard_rig.h"
#include "simd_common.h"
#include "test_util.h"


static const int hard_angles[] = {0,   1,   -1,  89,  90,  91,   179,  180,  181,  269,
                                  270, 271, 359, 360, 361, -90, -360, 45,   INT_MIN, INT_MIN + 1,
                                  INT_MAX, INT_MAX - 1, 1000000000, -1000000000};

Test(hard, angles)
{
    rig *g = rig_new();
    retro_map maps[NMAPS];
    load_maps(maps);
    /* A generic position, and one on a cell corner where axis-aligned rays run along edges. */
    static const float xy[][2] = {{10.5f, 20.25f}, {3.0f, 7.0f}};
    static const int on[] = {S2, S5, S64, S1000};
    for (size_t mi = 0; mi < sizeof on / sizeof on[0]; mi++)
        for (size_t a = 0; a < sizeof hard_angles / sizeof hard_angles[0]; a++)
            for (size_t q = 0; q < sizeof xy / sizeof xy[0]; q++)
                check_case(g, "angle", pose(xy[q][0], xy[q][1], hard_angles[a], 180), CW, CH, CD,
                           &maps[on[mi]]);
    free_maps(maps, NMAPS);
    rig_done(g, "hard/angles");
}

/* Positions at the edges of [0, S) and of float: zero and its sign, just below 0 and S, S
 * itself, cell edges, huge values, and the values whose reduction modulo S rounds up to S. */
static int positions_for(int S, float *v)
{
    float fS = (float)S;
    float list[] = {0.0f,
                    -0.0f,
                    -1e-7f,
                    1e-7f,
                    -1e-30f,
                    -FLT_TRUE_MIN,
                    FLT_TRUE_MIN,
                    nextafterf(fS, 0.0f),
                    fS,
                    -nextafterf(fS, 0.0f),
                    -fS,
                    1.0f,
                    (float)(S / 2),
                    0.5f,
                    nextafterf(1.0f, 0.0f),
                    1e6f,
                    -1e6f,
                    1e9f,
                    -1e9f,
                    16777216.0f,
                    nextafterf(-1e6f * fS, 0.0f),
                    FLT_MAX,
                    -FLT_MAX};
    memcpy(v, list, sizeof list);
    return (int)(sizeof list / sizeof list[0]);
}

static void positions_test(const char *test, int axis)
{
    rig *g = rig_new();
    retro_map maps[NMAPS];
    load_maps(maps);
    /* Axis-aligned views put x (or y) exactly on x0 + d: edge cases stay edge cases. */
    static const int angles[3][2] = {{0, 37}, {90, 233}, {180, 315}};
    static const int on[] = {S1, S3, S64, S1000};
    const float other = 2.75f;
    for (size_t mi = 0; mi < sizeof on / sizeof on[0]; mi++) {
        const retro_map *m = &maps[on[mi]];
        float v[32];
        int nv = positions_for(m->size, v);
        for (int i = 0; i < nv; i++)
            for (int a = 0; a < 2; a++) {
                float x = axis == 1 ? other : v[i], y = axis == 0 ? other : v[i];
                check_case(g, "position", pose(x, y, angles[axis][a], 170), CW, CH, CD, m);
            }
    }
    free_maps(maps, NMAPS);
    rig_done(g, test);
}

Test(hard, positions_x) { positions_test("hard/positions_x", 0); }
Test(hard, positions_y) { positions_test("hard/positions_y", 1); }
Test(hard, positions_xy) { positions_test("hard/positions_xy", 2); }

/* x = -1e-30 reduces to fmod = -1e-30, + S = S in double already; -1e-7 is within half an ulp
 * of S in float for S >= 3. Both give x0 == S exactly, one past the last cell: the kernels
 * must wrap floor(S + d*rx), not assume x0 < S. This pins that the cases above reach it. */
Test(hard, reduction_rounds_to_S)
{
    retro_map maps[NMAPS];
    load_maps(maps);
    uint32_t out[4];
    for (int mi = 0; mi < NMAPS; mi++) {
        int S = maps[mi].size;
        const float xs[] = {-1e-30f, -FLT_TRUE_MIN, S >= 3 ? -1e-7f : -1e-30f};
        for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++) {
            retro_ctx *rc = retro_ctx_new();
            cr_assert(rc);
            ctx_t c = {2, 2, S, 8, SKY, maps[mi].height, maps[mi].color, out};
            player_t p = pose(xs[i], xs[i], 0, 100);
            retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
            const retro_frame *f;
            cr_assert_eq(retro_frame_prepare(rc, &o, &p, &c, &f), RETRO_OK);
            cr_assert(f->x0 == (float)S && f->y0 == (float)S, "S=%d x=%a: x0=%a y0=%a, expected S", S,
                      (double)xs[i], (double)f->x0, (double)f->y0);
            retro_ctx_free(rc);
        }
    }
    free_maps(maps, NMAPS);
}

Test(hard, screens)
{
    rig *g = rig_new();
    retro_map maps[NMAPS];
    load_maps(maps);
    static const int screens[][2] = {{1, 1},  {1, 40}, {40, 1}, {2, 2},   {2, 1},  {1, 2},
                                     {17, 1}, {1, 17}, {16, 3}, {33, 64}, {4096, 2}, {3, 3}};
    static const int angles[] = {0, 33, 181};
    static const int on[] = {S1, S5, S64};
    for (size_t mi = 0; mi < sizeof on / sizeof on[0]; mi++)
        for (size_t s = 0; s < sizeof screens / sizeof screens[0]; s++)
            for (size_t a = 0; a < sizeof angles / sizeof angles[0]; a++) {
                int W = screens[s][0], H = screens[s][1];
                check_case(g, "screen", pose(7.25f, 1.5f, angles[a], 160), W, H, W > 1000 ? 24 : CD,
                           &maps[on[mi]]);
            }
    free_maps(maps, NMAPS);
    rig_done(g, "hard/screens");
}

Test(hard, distances)
{
    rig *g = rig_new();
    retro_map maps[NMAPS];
    load_maps(maps);
    static const int dists[] = {INT_MIN, -1, 0, 1, 2, 3, 4, 17, 100};
    static const int angles[] = {45, 90};
    static const int on[] = {S2, S5, S64};
    for (size_t mi = 0; mi < sizeof on / sizeof on[0]; mi++)
        for (size_t d = 0; d < sizeof dists / sizeof dists[0]; d++)
            for (size_t a = 0; a < sizeof angles / sizeof angles[0]; a++)
                check_case(g, "distance", pose(5.5f, 9.125f, angles[a], 150), CW, CH, dists[d],
                           &maps[on[mi]]);
    /* 2^20 samples a column on a 2x2 screen: positions reach about 1.5e6, where an ulp of the
     * sample position is 1/8. The camera is below the terrain's top, so samples keep painting
     * row 1 all the way out. */
    check_case(g, "far", pose(0.5f, 0.25f, 30, 100), 2, 2, 1 << 20, &maps[S64]);
    check_case(g, "far", pose(999.75f, -3.5f, 135, 100), 2, 2, 1 << 20, &maps[S1000]);
    free_maps(maps, NMAPS);
    rig_done(g, "hard/distances");
}

/* Mode course's SIMD column wraps positions in (-2K, 3K), K = S - 1, by one or two exact
 * additions of K (simd_sample_tpl.h, course_wrap2) and others by the general remainder. Axis
 * views put a column's positions on exactly x + d (angle 0), so these starts put whole vectors
 * of distances on -2K, -K, 0, K, 2K and 3K, just inside and just outside the range, and the
 * camera low enough that the terrain paints far out. */
Test(hard, course_wrap_ranges)
{
    rig *g = rig_new();
    retro_map maps[NMAPS];
    load_maps(maps);
    static const int on[] = {S5, S64};
    static const int angles[] = {0, 90, 180, 270};
    for (size_t mi = 0; mi < sizeof on / sizeof on[0]; mi++) {
        const retro_map *m = &maps[on[mi]];
        const float K = (float)(m->size - 1);
        const float xs[] = {-2 * K - 1, -2 * K, nextafterf(-2 * K, 0), -2 * K + 0.5f, -K, -K - 0.25f, 0,
                            K - 0.5f, K, 2 * K, 3 * K - 17, 3 * K - 16, nextafterf(3 * K, 0), 3 * K};
        const int D = 3 * m->size + 40;
        for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++)
            for (size_t a = 0; a < sizeof angles / sizeof angles[0]; a++)
                check_case(g, "course wrap", pose(xs[i], xs[i], angles[a], 60), CW, CH, D, m);
    }
    free_maps(maps, NMAPS);
    rig_done(g, "hard/course_wrap_ranges");
}

/* Mode course's SIMD columns list a tile column's spans and paint the finished ones when the
 * list holds RETRO_SIMD_SPAN_LIST (simd_course_tpl.h). Heights that depend on x alone, chosen
 * distance by distance to raise the y-buffer by as little as they can, give every column of a
 * 1080-row frame (the tallest tile) looking along +x several hundred spans, more than the list
 * holds: counted on naive's image as runs of one colour down a column, each x its own colour. */
Test(hard, course_span_lists)
{
    enum { W = 256, H = 1080, D = 1000, S = 1024, HC = 900 };
    rig *g = rig_new();
    retro_map m;
    char err[128];
    cr_assert_eq(retro_map_alloc(&m, S, err, sizeof err), 0, "%s", err);
    uint8_t f[S] = {0};
    for (int d = 1, y = 0; d < D; d++)
        for (int h = 0; h < 256; h++) {
            const int v = retro_course_row((float)(W / 2), H / 2, H, h - HC, d);
            if (v > y) {
                f[d] = (uint8_t)h;
                y = v;
                break;
            }
        }
    for (int j = 0; j < S; j++)
        for (int i = 0; i < S; i++) {
            m.height[(size_t)j * S + i] = f[i];
            m.color[(size_t)j * S + i] = (uint32_t)(i + 1) << 8;
        }
    player_t p = pose(0.5f, 300.5f, 0, HC);
    ctx_t c = {W, H, S, D, SKY, m.height, m.color, NULL};
    char what[320];
    describe(what, sizeof what, "course span lists", &p, W, H, D, S);
    if (naive_ref(g, what, RETRO_MODE_COURSE, &p, c) == 0) {
        int fewest = H;
        for (int u = 0; u < W; u++) {
            int runs = 1;
            for (int r = 1; r < H; r++)
                runs += g->ref[(size_t)r * W + u] != g->ref[(size_t)(r - 1) * W + u];
            fewest = runs < fewest ? runs : fewest;
        }
        cr_assert_gt(fewest, RETRO_SIMD_SPAN_LIST, "the case needs columns of more spans than a list holds (fewest %d)", fewest);
        all_kernels_match(g, what, RETRO_MODE_COURSE, &p, c);
    }
    retro_map_free(&m);
    rig_done(g, "hard/course_span_lists");
}

Test(hard, heights)
{
    rig *g = rig_new();
    retro_map maps[NMAPS];
    load_maps(maps);
    /* INT_MIN + 256 is where the SIMD kernels switch from the scalar path to int32 lanes. */
    static const int heights[] = {INT_MIN,     INT_MIN + 1, INT_MIN + 255, INT_MIN + 256,
                                  INT_MIN + 257, -1000000,  -1,            0,
                                  1,           127,         255,           256,
                                  1000000,     INT_MAX - 255, INT_MAX - 1,  INT_MAX};
    static const int angles[] = {0, 271};
    static const int on[] = {S2, S5, S64, S1000};
    for (size_t mi = 0; mi < sizeof on / sizeof on[0]; mi++)
        for (size_t h = 0; h < sizeof heights / sizeof heights[0]; h++)
            for (size_t a = 0; a < sizeof angles / sizeof angles[0]; a++)
                check_case(g, "height", pose(4.75f, 11.5f, angles[a], heights[h]), CW, CH, CD,
                           &maps[on[mi]]);
    free_maps(maps, NMAPS);
    rig_done(g, "hard/heights");
}

/* Map sizes on random poses, and maps whose content is itself a corner: flat at 0 and at 255
 * (the height maximum and the early exit at its bounds) and colours with a non-zero low byte
 * (outside R<<24|G<<16|B<<8, where packed-map kernels must fall back, not lose the byte). */
Test(hard, map_sizes)
{
    rig *g = rig_new();
    static const int sizes[] = {1, 2, 3, 4, 5, 7, 31, 33, 255, 1000};
    enum { NS = sizeof sizes / sizeof sizes[0] };
    retro_map maps[NS * 4];
    for (int i = 0; i < NS; i++) {
        noise_map(&maps[4 * i], sizes[i], 77 + (uint64_t)i);
        noise_map(&maps[4 * i + 1], sizes[i], 5);
        noise_map(&maps[4 * i + 2], sizes[i], 6);
        noise_map(&maps[4 * i + 3], sizes[i], 7);
        size_t cells = (size_t)sizes[i] * (size_t)sizes[i];
        memset(maps[4 * i + 1].height, 0, cells);
        memset(maps[4 * i + 2].height, 255, cells);
        for (size_t c = 0; c < cells; c++)
            maps[4 * i + 3].color[c] |= (uint32_t)(c * 37 + 1) & 0xffu;
    }
    uint64_t rng = 8;
    for (int i = 0; i < NS * 4; i++)
        for (int n = 0; n < 4; n++) {
            float x = (float)((double)(rng_next(&rng) % 100000) / 64.0 - 700.0);
            float y = (float)((double)(rng_next(&rng) % 100000) / 128.0 - 300.0);
            int angle = (int)(rng_next(&rng) % 1440) - 720;
            int height = (int)(rng_next(&rng) % 400) - 60;
            int W = 1 + (int)(rng_next(&rng) % 50), H = 1 + (int)(rng_next(&rng) % 40);
            check_case(g, "map", pose(x, y, angle, height), W, H, 2 + (int)(rng_next(&rng) % 80),
                       &maps[i]);
        }
    free_maps(maps, NS * 4);
    rig_done(g, "hard/map_sizes");
}

/* Mode lod's step growth is a public float of the context: across its range (0 meaning the
 * default, up to 100) every kernel matches naive; outside it (huge, infinite, NaN, negative)
 * the frame setup refuses it instead of computing a step that could overflow. */
Test(hard, lod_lambda)
{
    rig *g = rig_new();
    retro_map maps[NMAPS];
    load_maps(maps);
    static const float bad[] = {100.5f, 1e30f, FLT_MAX, INFINITY, NAN, -1.0f};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        uint8_t h[4] = {0};
        uint32_t col[4] = {0}, out[4];
        ctx_t c = {2, 2, 2, 50, 0, h, col, out};
        player_t p = pose(1, 1, 0, 10);
        retro_ctx *rc = retro_ctx_new();
        cr_assert(rc);
        retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
        o.mode = RETRO_MODE_LOD;
        o.lod = bad[i];
        cr_expect_eq(retro_render(rc, retro_kernel_find("naive"), &o, &p, &c), RETRO_EINVAL, "lod %g accepted",
                     (double)bad[i]);
        retro_ctx_free(rc);
    }
    static const float lambdas[] = {0.0f, 1e-30f, 0.02f, 0.5f, 1.0f, 100.0f};
    for (size_t i = 0; i < sizeof lambdas / sizeof lambdas[0]; i++) {
        g->lod = g->chk.lod = lambdas[i];
        static const int on[] = {S1, S5, S64};
        for (size_t mi = 0; mi < sizeof on / sizeof on[0]; mi++) {
            const retro_map *m = &maps[on[mi]];
            char what[320];
            player_t p = pose(3.25f, 60.5f, 20, 150);
            describe(what, sizeof what, "lod", &p, CW, CH, 300, m->size);
            ctx_t c = {CW, CH, m->size, 300, SKY, m->height, m->color, NULL};
            g->cases++;
            if (naive_ref(g, what, RETRO_MODE_LOD, &p, c) == 0)
                all_kernels_match(g, what, RETRO_MODE_LOD, &p, c);
        }
    }
    free_maps(maps, NMAPS);
    rig_done(g, "hard/lod_lambda");
}
