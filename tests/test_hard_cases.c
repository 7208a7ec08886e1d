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
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "retro_internal.h"
#include "test_util.h"

#define SKY 0x66a3ff00u
/* Its low byte is non-zero, so no colour of a valid map and not the sky can equal it: a pixel
 * a kernel failed to write keeps it. */
#define POISON 0xababababu
#define MAX_KERNELS 32
#define MAX_THREADS 3
#define MAX_REPORTS 40

static const char *const levels[] = {"none", "sse2", "avx2", "avx512"};

/* One context per kernel and thread count for a whole test: a threaded kernel's pool loads the
 * hwloc topology once per context (milliseconds), which would dominate thousands of tiny
 * frames. The contexts cache per map pointer, so maps stay allocated until the test ends and
 * in-place edits are announced through rig_map_changed(). */
typedef struct {
    retro_ctx rc[MAX_KERNELS][MAX_THREADS + 1];
    uint32_t *ref, *out;
    size_t cap;
    int failures, cases, renders;
} rig;

static rig *rig_new(void)
{
    cr_assert(retro_kernel_count <= MAX_KERNELS, "raise MAX_KERNELS to %zu", retro_kernel_count);
    cr_assert(!strcmp(retro_kernels[0].name, "naive"), "row 0 of the table must be naive");
    rig *g = calloc(1, sizeof *g);
    cr_assert(g);
    for (int k = 0; k < MAX_KERNELS; k++)
        for (int t = 0; t <= MAX_THREADS; t++)
            retro_ctx_init(&g->rc[k][t]);
    return g;
}

static void rig_map_changed(rig *g)
{
    for (int k = 0; k < MAX_KERNELS; k++)
        for (int t = 0; t <= MAX_THREADS; t++)
            retro_ctx_map_changed(&g->rc[k][t]);
}

/* Frees the rig and fails the test if any case failed; the cases were printed as they failed. */
static void rig_done(rig *g, const char *test)
{
    for (int k = 0; k < MAX_KERNELS; k++)
        for (int t = 0; t <= MAX_THREADS; t++)
            retro_ctx_free(&g->rc[k][t]);
    free(g->ref);
    free(g->out);
    int failures = g->failures, cases = g->cases, renders = g->renders;
    free(g);
    cr_assert_eq(failures, 0, "%s: %d failures in %d cases (%d renders), listed on stderr", test,
                 failures, cases, renders);
}

static void rig_reserve(rig *g, size_t n)
{
    if (n <= g->cap)
        return;
    free(g->ref);
    free(g->out);
    g->ref = malloc(n * sizeof *g->ref);
    g->out = malloc(n * sizeof *g->out);
    cr_assert(g->ref && g->out);
    g->cap = n;
}

static void poison(uint32_t *px, size_t n)
{
    for (size_t i = 0; i < n; i++)
        px[i] = POISON;
}

static void report(rig *g, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void report(rig *g, const char *fmt, ...)
{
    if (g->failures++ >= MAX_REPORTS)
        return;
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

/* Index of the first pixel where a and b differ, or -1. */
static long first_diff(const uint32_t *a, const uint32_t *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (a[i] != b[i])
            return (long)i;
    return -1;
}

static retro_err rig_render(rig *g, size_t k, int threads, retro_mode mode, const player_t *p,
                            ctx_t *c)
{
    retro_ctx *rc = &g->rc[k][threads];
    rc->threads = threads;
    g->renders++;
    return retro_render(rc, &retro_kernels[k], mode, p, c);
}

/* Every kernel but naive, at every ISA level and thread count, must render g->ref exactly. */
static void all_kernels_match(rig *g, const char *what, retro_mode mode, const player_t *p,
                              ctx_t c)
{
    size_t n = (size_t)c.scr_width * (size_t)c.scr_height;
    c.out = g->out;
    for (size_t l = 0; l < sizeof levels / sizeof levels[0]; l++) {
        cr_assert_eq(retro_cpu_limit(levels[l]), RETRO_OK);
        for (size_t k = 1; k < retro_kernel_count; k++) {
            const retro_kernel *kr = &retro_kernels[k];
            if (!retro_kernel_runs_here(kr) || !retro_kernel_has_mode(kr, mode))
                continue;
            int threaded = (kr->flags & RETRO_KF_THREADED) != 0;
            for (int t = threaded; t <= (threaded ? MAX_THREADS : 0); t++) {
                poison(g->out, n);
                retro_err e = rig_render(g, k, t, mode, p, &c);
                long i = e ? -1 : first_diff(g->ref, g->out, n);
                if (e)
                    report(g, "FAIL %s: %s/%s isa %s %dt: %s", what, kr->name, retro_mode_name(mode),
                           levels[l], t, retro_strerror(e));
                else if (i >= 0)
                    report(g, "MISMATCH %s: %s/%s isa %s %dt: first difference at pixel (u=%ld, r=%ld): "
                           "%08x, naive %08x", what, kr->name, retro_mode_name(mode), levels[l], t,
                           i % c.scr_width + 1, c.scr_height - i / c.scr_width, g->out[i], g->ref[i]);
            }
        }
    }
    retro_cpu_limit(NULL);
}

/* Renders g->ref with naive; returns 0 on success. */
static int naive_ref(rig *g, const char *what, retro_mode mode, const player_t *p, ctx_t c)
{
    size_t n = (size_t)c.scr_width * (size_t)c.scr_height;
    rig_reserve(g, n);
    c.out = g->ref;
    poison(g->ref, n);
    retro_err e = rig_render(g, 0, 0, mode, p, &c);
    if (e) {
        report(g, "FAIL %s: naive/%s: %s", what, retro_mode_name(mode), retro_strerror(e));
        return -1;
    }
    for (size_t i = 0; i < n; i++)
        if (g->ref[i] == POISON) {
            report(g, "FAIL %s: naive/%s left pixel %zu unwritten", what, retro_mode_name(mode), i);
            return -1;
        }
    return 0;
}

static void describe(char *buf, size_t len, const char *tag, const player_t *p, int W, int H, int D,
                     int S)
{
    snprintf(buf, len, "[%s] x=%.9g (%a) y=%.9g (%a) angle=%d height=%d %dx%d D=%d S=%d", tag,
             (double)p->x, (double)p->x, (double)p->y, (double)p->y, p->angle, p->height, W, H, D, S);
}

/* One hard case: every kernel against naive in every mode valid for it (course needs S >= 2). */
static void check_case(rig *g, const char *tag, player_t p, int W, int H, int D, const retro_map *m)
{
    char what[320];
    describe(what, sizeof what, tag, &p, W, H, D, m->size);
    g->cases++;
    for (int mode = 0; mode < RETRO_MODE_COUNT; mode++) {
        if (mode == RETRO_MODE_COURSE && m->size < 2)
            continue;
        ctx_t c = {W, H, m->size, D, SKY, m->height, m->color, NULL};
        if (naive_ref(g, what, (retro_mode)mode, &p, c) == 0)
            all_kernels_match(g, what, (retro_mode)mode, &p, c);
    }
}

/* The small frame most cases use: 37 columns are two 16-lane groups and a partial one, two
 * 32-column thread chunks and a partial one; D = 48 keeps it cheap under the sanitizers. */
enum { CW = 37, CH = 23, CD = 48 };

static player_t pose(float x, float y, int angle, int height)
{
    player_t p = {x, y, angle, height, 0, 0, 0};
    return p;
}

/* Maps of the sizes the cases need: powers of two, tiny ones and non-powers of two. */
static const int map_sizes[] = {1, 2, 3, 5, 64, 1000};
enum { NMAPS = sizeof map_sizes / sizeof map_sizes[0] };

static void load_maps(retro_map *maps)
{
    for (int i = 0; i < NMAPS; i++)
        noise_map(&maps[i], map_sizes[i], 1000 + (uint64_t)map_sizes[i]);
}

/* Indices into map_sizes[] of a test's maps. */
enum { S1, S2, S3, S5, S64, S1000 };

static void free_maps(retro_map *maps, int n)
{
    for (int i = 0; i < n; i++)
        retro_map_free(&maps[i]);
}

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
            retro_ctx rc;
            retro_ctx_init(&rc);
            ctx_t c = {2, 2, S, 8, SKY, maps[mi].height, maps[mi].color, out};
            player_t p = pose(xs[i], xs[i], 0, 100);
            cr_assert_eq(retro_frame_setup(&rc, RETRO_MODE_EXACT, &p, &c), RETRO_OK);
            cr_assert(rc.frame.x0 == (float)S && rc.frame.y0 == (float)S,
                      "S=%d x=%a: x0=%a y0=%a, expected S", S, (double)xs[i], (double)rc.frame.x0,
                      (double)rc.frame.y0);
            retro_ctx_free(&rc);
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
        retro_ctx rc;
        retro_ctx_init(&rc);
        rc.lod = bad[i];
        cr_expect_eq(retro_frame_setup(&rc, RETRO_MODE_LOD, &p, &c), RETRO_EINVAL, "lod %g accepted", (double)bad[i]);
        retro_ctx_free(&rc);
    }
    static const float lambdas[] = {0.0f, 1e-30f, 0.02f, 0.5f, 1.0f, 100.0f};
    for (size_t i = 0; i < sizeof lambdas / sizeof lambdas[0]; i++) {
        for (int k = 0; k < MAX_KERNELS; k++)
            for (int t = 0; t <= MAX_THREADS; t++)
                g->rc[k][t].lod = lambdas[i];
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

/* The cell mode exact reads for column u (1-based) at distance d, by SEMANTICS.md steps 1-5
 * written out here rather than taken from src/. */
static size_t exact_cell(const player_t *p, int W, int S, int u, int d)
{
    int A = p->angle % 360;
    A += A < 0 ? 360 : 0;
    double rad = (double)(A % 90) * 3.14159265358979323846 / 180.0;
    float c0 = (float)cos(rad), s0 = (float)sin(rad), cs, sn;
    switch (A / 90) {
    case 0: cs = c0; sn = s0; break;
    case 1: cs = -s0; sn = c0; break;
    case 2: cs = -c0; sn = -s0; break;
    default: cs = s0; sn = -c0; break;
    }
    double wx = fmod((double)p->x, S), wy = fmod((double)p->y, S);
    float x0 = (float)(wx < 0 ? wx + S : wx), y0 = (float)(wy < 0 ? wy + S : wy);
    float t = W == 1 ? 0.0f : (float)(2 * (u - 1) - (W - 1)) / (float)(W - 1);
    float rx = cs + t * sn, ry = t * cs - sn;
    float qx = x0 + (float)d * rx, qy = y0 + (float)d * ry;
    long i = (long)floorf(qx) % S, j = (long)floorf(qy) % S;
    i += i < 0 ? S : 0;
    j += j < 0 ? S : 0;
    return (size_t)j * (size_t)S + (size_t)i;
}

static void exact_reads(const player_t *p, int W, int D, int S, uint8_t *marks)
{
    for (int u = 1; u <= W; u++)
        for (int d = 1; d < D; d++)
            marks[exact_cell(p, W, S, u, d)] = 1;
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
                size_t idx = exact_cell(&p, W, S, 1, 1);
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

/* --- numerics: binary32 sampling against the truth (docs/NUMERICS.md) -------------------- */

/* One pose of mode exact evaluated twice: in binary32 as SEMANTICS.md specifies, and as the
 * truth (mode truth of docs/ACCURACY.md): the same formulas in binary64 with exact floor and
 * wrap, whose own error (a few units of 2^-53 relative) is negligible against binary32's. */
typedef struct {
    int W, S;
    float cs, sn, x0, y0;
    double dcs, dsn, dx0, dy0;
} npose;

static void npose_init(npose *n, float x, float y, int angle, int W, int S)
{
    int A = angle % 360;
    A += A < 0 ? 360 : 0;
    double rad = (double)(A % 90) * 3.14159265358979323846 / 180.0;
    double c0 = cos(rad), s0 = sin(rad);
    static const double csign[4] = {1, -1, -1, 1}, ssign[4] = {1, 1, -1, -1};
    int q = A / 90, swap = q & 1;
    n->dcs = csign[q] * (swap ? s0 : c0);
    n->dsn = ssign[q] * (swap ? c0 : s0);
    n->cs = (float)csign[q] * (float)(swap ? s0 : c0);
    n->sn = (float)ssign[q] * (float)(swap ? c0 : s0);
    double wx = fmod((double)x, S), wy = fmod((double)y, S);
    n->dx0 = wx < 0 ? wx + S : wx;
    n->dy0 = wy < 0 ? wy + S : wy;
    n->x0 = (float)n->dx0;
    n->y0 = (float)n->dy0;
    n->W = W;
    n->S = S;
}

static double npose_t(const npose *n, int u)
{
    return n->W == 1 ? 0.0 : (double)(2 * (u - 1) - (n->W - 1)) / (double)(n->W - 1);
}

static void sample32(const npose *n, int u, int d, float *qx, float *qy)
{
    float t = n->W == 1 ? 0.0f : (float)(2 * (u - 1) - (n->W - 1)) / (float)(n->W - 1);
    float rx = n->cs + t * n->sn, ry = t * n->cs - n->sn;
    *qx = n->x0 + (float)d * rx;
    *qy = n->y0 + (float)d * ry;
}

static void sample64(const npose *n, int u, int d, double *qx, double *qy)
{
    double t = npose_t(n, u);
    *qx = n->dx0 + d * (n->dcs + t * n->dsn);
    *qy = n->dy0 + d * (t * n->dcs - n->dsn);
}

/* The a-priori bound on |q32 - truth| along x (axis 0) or y (axis 1), with u = 2^-24:
 * c0, s0, t and x0 each carry one rounding, t*sn one, the sum cs + t*sn one, d*rx one and
 * x0 + d*rx one, so
 *   |err| <= u * (x0 + d * (|cs| + 3|t sn| + 2|rx|) + |q|)        (x; y likewise)
 * to first order; the factor 1 + 2^-20 covers the second-order terms. */
static double bound32(const npose *n, int u, int d, int axis)
{
    double t = npose_t(n, u), a = axis ? n->dsn : n->dcs, b = axis ? n->dcs : n->dsn;
    double r = axis ? t * n->dcs - n->dsn : n->dcs + t * n->dsn;
    double x0 = axis ? n->dy0 : n->dx0, q = x0 + d * r;
    double e = x0 + d * (fabs(a) + 3.0 * fabs(t * b) + 2.0 * fabs(r)) + fabs(q);
    return ldexp(e, -24) * (1.0 + ldexp(1.0, -20)) + 1e-12 * (1.0 + fabs(q));
}

static long cell_of(double q, int S)
{
    long i = (long)floor(q) % S;
    return i < 0 ? i + S : i;
}

/* Torus distance between two cell indices. */
static long cell_gap(long a, long b, int S)
{
    long g = labs(a - b);
    return g > S - g ? S - g : g;
}

/* Every binary32 sample position stays within the bound of the truth, on poses from tiny to
 * the largest map and distance; while the bound is below one cell the cell is off by at most
 * one. This is the derivation of docs/NUMERICS.md, checked. */
Test(numerics, error_within_bound)
{
    static const int sizes[] = {1, 3, 64, 1000, 1024, 16384};
    static const int widths[] = {1, 2, 37, 640};
    uint64_t rng = 2026;
    long checked = 0;
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++)
        for (int n = 0; n < 40; n++) {
            const int S = sizes[si];
            float x = (float)((double)(rng_next(&rng) % 2000000) / 1000.0 - 1000.0) * (n % 4 ? 1.0f : 1e4f);
            float y = (float)((double)(rng_next(&rng) % 2000000) / 777.0 - 1000.0);
            int angle = (int)(rng_next(&rng) % 100000) - 50000;
            int W = widths[n % 4];
            npose p;
            npose_init(&p, x, y, angle, W, S);
            for (int k = 0; k < 400; k++) {
                int d = k < 100 ? k + 1 : 1 + (int)(rng_next(&rng) % RETRO_MAX_DISTANCE);
                int u = 1 + (int)(rng_next(&rng) % (uint64_t)W);
                float fx, fy;
                double tx, ty;
                sample32(&p, u, d, &fx, &fy);
                sample64(&p, u, d, &tx, &ty);
                double ex = fabs((double)fx - tx), ey = fabs((double)fy - ty);
                double bx = bound32(&p, u, d, 0), by = bound32(&p, u, d, 1);
                cr_assert(ex <= bx && ey <= by,
                          "S=%d x=%a y=%a angle=%d W=%d u=%d d=%d: error (%g, %g) above bound (%g, %g)",
                          S, (double)x, (double)y, angle, W, u, d, ex, ey, bx, by);
                if (bx < 1.0)
                    cr_assert(cell_gap(cell_of(fx, S), cell_of(tx, S), S) <= 1);
                if (by < 1.0)
                    cr_assert(cell_gap(cell_of(fy, S), cell_of(ty, S), S) <= 1);
                checked++;
            }
        }
    cr_assert(checked > 0);
}

/* The measurements quoted in docs/NUMERICS.md, printed when RETRO_NUMERICS=1 (they take tens
 * of seconds, so `make check` skips them):
 *   RETRO_NUMERICS=1 RETRO_SHARED=../shared build/bin/retro-tests --filter 'numerics/report' */
static int first_mismatch(const npose *p, int dmax)
{
    for (int d = 1; d <= dmax; d++)
        for (int u = 1; u <= p->W; u++) {
            float fx, fy;
            double tx, ty;
            sample32(p, u, d, &fx, &fy);
            sample64(p, u, d, &tx, &ty);
            if (cell_of(fx, p->S) != cell_of(tx, p->S) || cell_of(fy, p->S) != cell_of(ty, p->S))
                return d;
        }
    return -1;
}

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

static void report_first_mismatch(uint64_t *rng)
{
    enum { POSES = 100, DMAX = 1 << 16 };
    static const int sizes[] = {16, 64, 256, 1024, 4096, 16384};
    printf("\nFirst distance with a cell different from the truth, W = 640, %d random poses\n", POSES);
    printf("| S | min | 10%% | median | 90%% | max | poses without one up to %d |\n|---|---|---|---|---|---|---|\n", DMAX);
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        int S = sizes[si], first[POSES], n = 0, none = 0;
        for (int k = 0; k < POSES; k++) {
            npose p;
            float x = (float)((double)(rng_next(rng) % (1u << 30)) / (1u << 30) * S);
            float y = (float)((double)(rng_next(rng) % (1u << 30)) / (1u << 30) * S);
            npose_init(&p, x, y, (int)(rng_next(rng) % 360), 640, S);
            int d = first_mismatch(&p, DMAX);
            if (d < 0)
                none++;
            else
                first[n++] = d;
        }
        qsort(first, (size_t)n, sizeof first[0], cmp_int);
        if (n)
            printf("| %d | %d | %d | %d | %d | %d | %d |\n", S, first[0], first[n / 10], first[n / 2],
                   first[n * 9 / 10], first[n - 1], none);
        else
            printf("| %d | - | - | - | - | - | %d |\n", S, none);
    }
}

static void report_bands(uint64_t *rng)
{
    static const int sizes[] = {64, 1024, 16384};
    static const int band[] = {1, 10, 100, 1000, 10000, 100000, 1000000, RETRO_MAX_DISTANCE};
    enum { NB = sizeof band / sizeof band[0] - 1, POSES = 400, PER = 200 };
    printf("\nSamples whose cell differs from the truth, by distance (%d poses x %d samples per band, W = 640)\n",
           POSES, PER);
    printf("| S | d from | d to | differing samples | max error (cells) | max bound (cells) | max cell gap |\n"
           "|---|---|---|---|---|---|---|\n");
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++)
        for (int b = 0; b < NB; b++) {
            int S = sizes[si];
            long diff = 0, total = 0, gap = 0;
            double emax = 0, bmax = 0;
            for (int k = 0; k < POSES; k++) {
                npose p;
                float x = (float)((double)(rng_next(rng) % (1u << 30)) / (1u << 30) * S);
                float y = (float)((double)(rng_next(rng) % (1u << 30)) / (1u << 30) * S);
                npose_init(&p, x, y, (int)(rng_next(rng) % 360), 640, S);
                for (int j = 0; j < PER; j++) {
                    int d = band[b] + (int)(rng_next(rng) % (uint64_t)(band[b + 1] - band[b]));
                    int u = 1 + (int)(rng_next(rng) % 640);
                    float fx, fy;
                    double tx, ty;
                    sample32(&p, u, d, &fx, &fy);
                    sample64(&p, u, d, &tx, &ty);
                    long gx = cell_gap(cell_of(fx, S), cell_of(tx, S), S);
                    long gy = cell_gap(cell_of(fy, S), cell_of(ty, S), S);
                    diff += gx || gy;
                    gap = gx > gap ? gx : gap;
                    gap = gy > gap ? gy : gap;
                    double e = fmax(fabs(fx - tx), fabs(fy - ty));
                    emax = e > emax ? e : emax;
                    double bd = fmax(bound32(&p, u, d, 0), bound32(&p, u, d, 1));
                    bmax = bd > bmax ? bd : bmax;
                    total++;
                }
            }
            printf("| %d | %d | %d | %.3g%% | %.3g | %.3g | %ld |\n", S, band[b], band[b + 1] - 1,
                   100.0 * (double)diff / (double)total, emax, bmax, gap);
        }
}

/* Without the reduction modulo S the sum x + d*rx is rounded at the magnitude of x. */
static void report_unreduced(uint64_t *rng)
{
    enum { S = 1024, POSES = 50, D = 800, W = 640 };
    static const double bases[] = {0, 1e4, 1e6, 1e7, 1e9};
    printf("\nSamples (d < %d, W = %d, S = %d) whose cell differs from the truth, with and without the reduction\n",
           D, W, S);
    printf("| x from | ulp at x + S/2 | reduced first | not reduced |\n|---|---|---|---|\n");
    for (size_t bi = 0; bi < sizeof bases / sizeof bases[0]; bi++) {
        long red = 0, raw = 0, total = 0;
        for (int k = 0; k < POSES; k++) {
            float x = (float)(bases[bi] + (double)(rng_next(rng) % 1000000) / 1000000.0 * S);
            float y = (float)(bases[bi] + (double)(rng_next(rng) % 1000000) / 1000000.0 * S);
            npose p;
            npose_init(&p, x, y, (int)(rng_next(rng) % 360), W, S);
            for (int d = 1; d < D; d += 7)
                for (int u = 1; u <= W; u += 5) {
                    float fx, fy;
                    double tx, ty;
                    sample32(&p, u, d, &fx, &fy);
                    sample64(&p, u, d, &tx, &ty);
                    float t = (float)(2 * (u - 1) - (W - 1)) / (float)(W - 1);
                    float rx = p.cs + t * p.sn, ry = t * p.cs - p.sn;
                    float gx = x + (float)d * rx, gy = y + (float)d * ry; /* no reduction */
                    red += cell_of(fx, S) != cell_of(tx, S) || cell_of(fy, S) != cell_of(ty, S);
                    raw += cell_of(gx, S) != cell_of(tx, S) || cell_of(gy, S) != cell_of(ty, S);
                    total++;
                }
        }
        float xb = (float)(bases[bi] + S / 2);
        printf("| %.0e | %g | %.3g%% | %.3g%% |\n", bases[bi], (double)(nextafterf(xb, INFINITY) - xb),
               100.0 * (double)red / (double)total, 100.0 * (double)raw / (double)total);
    }
}

/* Mode course at the valley pose (the course's public frame), or the alpine scene without
 * ../shared: its wrap, step, rounding and accumulation, measured. */
static void report_course(void)
{
    retro_map m;
    float px = 997.808716f, py = 559.177063f;
    int z = 230;
    const char *scene = "course valley";
    if (course_map("valley", &m)) {
        test_map("alpine", &m);
        px = py = (float)m.size / 2.0f + 0.5f;
        z = 200;
        scene = "maps/alpine";
    }
    enum { W = 640, H = 480, D = 800 };
    const int S = m.size;
    uint32_t *a = malloc(sizeof(uint32_t) * W * H), *b = malloc(sizeof(uint32_t) * W * H);
    ctx_t c = {W, H, S, D, SKY, m.height, m.color, a};
    player_t p = {px, py, 0, z, 0, 0, 0};
    printf("\nMode course, %s (S = %d), pose (%g, %g), height %d, %dx%d, D = %d\n", scene, S,
           (double)px, (double)py, z, W, H, D);

    /* (a) period S - 1: the frame at x and x + S, and at x and x + (S - 1). */
    render_with("naive", RETRO_MODE_COURSE, &p, &c);
    static const int shifts[] = {1, 0};
    for (int i = 0; i < 2; i++) {
        player_t q = p;
        q.x = px + (float)(S - shifts[i]);
        c.out = b;
        render_with("naive", RETRO_MODE_COURSE, &q, &c);
        long n = 0;
        for (int k = 0; k < W * H; k++)
            n += a[k] != b[k];
        printf("x + %d: %.3g%% of pixels differ\n", S - shifts[i], 100.0 * (double)n / (W * H));
    }
    c.out = a;

    retro_ctx rc;
    retro_ctx_init(&rc);
    cr_assert_eq(retro_frame_setup(&rc, RETRO_MODE_COURSE, &p, &c), RETRO_OK);
    const retro_frame *f = &rc.frame;
    /* (a) cells read over many poses: never the last row or column. */
    {
        uint8_t *seen = calloc((size_t)S * S, 1);
        uint64_t rng = 5;
        for (int k = 0; k < 40; k++) {
            player_t q = {(float)(rng_next(&rng) % (uint64_t)S) + 0.37f, (float)(rng_next(&rng) % (uint64_t)S) + 0.61f,
                          (int)(rng_next(&rng) % 360), z, 0, 0, 0};
            retro_ctx r2;
            retro_ctx_init(&r2);
            cr_assert_eq(retro_frame_setup(&r2, RETRO_MODE_COURSE, &q, &c), RETRO_OK);
            for (int d = 1; d < D; d++) {
                float qx = r2.frame.lx[d], qy = r2.frame.ly[d];
                for (int u = 0; u < W; u++, qx += r2.frame.sx[d], qy += r2.frame.sy[d])
                    seen[(size_t)retro_course_cell(qy, S) * S + (size_t)retro_course_cell(qx, S)] = 1;
            }
            retro_ctx_free(&r2);
        }
        long last = 0, other = 0;
        for (int j = 0; j < S; j++)
            for (int i = 0; i < S; i++)
                *(i == S - 1 || j == S - 1 ? &last : &other) += seen[(size_t)j * S + i];
        printf("cells read in 40 frames: %ld of the %d in the last row and column, %ld of the other %ld\n",
               last, 2 * S - 1, other, (long)(S - 1) * (S - 1));
        free(seen);
    }
    /* (b) the last column's sample misses R by |R - L| / W = 2d / W. */
    for (int d = 100; d < D; d += 349) {
        double ca = cos(0.0) * d, sb = sin(0.0) * d; /* angle 0 */
        double rx = px + ca + sb, ry = py - sb + ca;
        double lastx = f->lx[d] + (W - 1) * (double)f->sx[d], lasty = f->ly[d] + (W - 1) * (double)f->sy[d];
        printf("d = %d: column W samples (%.3f, %.3f), R is (%.3f, %.3f): %.3f cells short (2d/W = %.3f)\n",
               d, lastx, lasty, rx, ry, hypot(rx - lastx, ry - lasty), 2.0 * d / W);
    }
    /* (c) truncation toward zero, then + H/2: rows differ from floor(f) + H/2 for f < 0. The
     * frame is painted here with either rounding; the truncating one must be naive's. */
    {
        long below = 0, diff = 0, total = 0;
        for (int d = 1; d < D; d++) {
            float qx = f->lx[d], qy = f->ly[d];
            for (int u = 0; u < W; u++, qx += f->sx[d], qy += f->sy[d]) {
                size_t idx = (size_t)retro_course_cell(qy, S) * S + (size_t)retro_course_cell(qx, S);
                float fr = f->cw2 * (float)(m.height[idx] - z) / (float)d;
                double vt = trunc((double)fr) + f->ch2, vf = floor((double)fr) + f->ch2;
                if (vt > 0 && vt < H) {
                    total++;
                    diff += vt != vf;
                    below += fr < 0;
                }
            }
        }
        printf("samples projecting inside the screen: %ld; below the horizon %.3g%%; one row higher than "
               "floor: %.3g%%\n", total, 100.0 * (double)below / (double)total, 100.0 * (double)diff / (double)total);
        for (int use_floor = 0; use_floor < 2; use_floor++) {
            for (int k = 0; k < W * H; k++)
                b[k] = SKY;
            for (int d = D - 1; d >= 1; d--) {
                float qx = f->lx[d], qy = f->ly[d];
                for (int u = 1; u <= W; u++, qx += f->sx[d], qy += f->sy[d]) {
                    size_t idx = (size_t)retro_course_cell(qy, S) * S + (size_t)retro_course_cell(qx, S);
                    float fr = f->cw2 * (float)(m.height[idx] - z) / (float)d;
                    double v = (use_floor ? floor((double)fr) : trunc((double)fr)) + f->ch2;
                    int top = v >= H ? H : v <= 0 ? 0 : (int)v;
                    for (int r = 1; r <= top; r++)
                        b[(size_t)(H - r) * W + (size_t)(u - 1)] = m.color[idx];
                }
            }
            long n = 0;
            for (int k = 0; k < W * H; k++)
                n += a[k] != b[k];
            if (!use_floor)
                cr_assert_eq(n, 0, "the painter here must be mode course");
            else
                printf("the frame with floor instead of truncation: %.3g%% of pixels differ\n",
                       100.0 * (double)n / (W * H));
        }
    }
    /* (d) the accumulated position against the same line evaluated directly, L + (u-1)*step. */
    {
        static const int cols[] = {1, 2, 10, 80, 160, 320, 480, 640};
        enum { NC = sizeof cols / sizeof cols[0] };
        double emax[NC] = {0};
        long cellx[NC] = {0};
        long total_cells = 0, samples = 0;
        for (int d = 1; d < D; d++) {
            float qx = f->lx[d], qy = f->ly[d];
            int ci = 0;
            for (int u = 1; u <= W; u++, qx += f->sx[d], qy += f->sy[d]) {
                double dx = (double)f->lx[d] + (u - 1) * (double)f->sx[d];
                double dy = (double)f->ly[d] + (u - 1) * (double)f->sy[d];
                double e = fmax(fabs(qx - dx), fabs(qy - dy));
                int moved = retro_course_cell((float)dx, S) != retro_course_cell(qx, S) ||
                            retro_course_cell((float)dy, S) != retro_course_cell(qy, S);
                total_cells += moved;
                samples++;
                while (ci < NC - 1 && u > cols[ci])
                    ci++;
                emax[ci] = e > emax[ci] ? e : emax[ci];
                cellx[ci] += moved;
            }
        }
        printf("accumulated vs direct position, by column (max error in cells, samples whose cell moves):\n");
        for (int i = 0; i < NC; i++)
            printf("  columns up to %d: %.3g, %ld\n", cols[i], emax[i], cellx[i]);
        printf("  in all: %ld of %ld samples (%.3g%%) read another cell\n", total_cells, samples,
               100.0 * (double)total_cells / (double)samples);
    }
    retro_ctx_free(&rc);
    free(a);
    free(b);
    retro_map_free(&m);
}

/* No distance is safe for every pose: a d = 1 sample whose cell differs from the truth's. */
static void report_example(uint64_t *rng)
{
    for (long k = 0; k < 100000000; k++) {
        npose p;
        float x = (float)((double)(rng_next(rng) % (1u << 30)) / (1u << 30) * 1024);
        float y = (float)((double)(rng_next(rng) % (1u << 30)) / (1u << 30) * 1024);
        int angle = (int)(rng_next(rng) % 360), u = 1 + (int)(rng_next(rng) % 640);
        npose_init(&p, x, y, angle, 640, 1024);
        float fx, fy;
        double tx, ty;
        sample32(&p, u, 1, &fx, &fy);
        sample64(&p, u, 1, &tx, &ty);
        if (cell_of(fx, 1024) != cell_of(tx, 1024)) {
            printf("\nd = 1 off by a cell: x=%.9g (%a) y=%.9g angle=%d W=640 u=%d S=1024: qx = %.9g in "
                   "binary32 (%a), truth %.17g\n", (double)x, (double)x, (double)y, angle, u, (double)fx,
                   (double)fx, tx);
            return;
        }
    }
}

Test(numerics, report, .timeout = 600)
{
    if (!getenv("RETRO_NUMERICS"))
        return;
    uint64_t rng = 88;
    report_example(&rng);
    report_first_mismatch(&rng);
    report_bands(&rng);
    report_unreduced(&rng);
    report_course();
    fflush(stdout);
}
