/* Numerics: binary32 sampling against the truth, the bound of docs/NUMERICS.md, and the
 * measurements that document regenerates (RETRO_NUMERICS=1). */
#include <criterion/criterion.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "retro_internal.h"
#include "hard_rig.h"
#include "test_util.h"


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
/* The skip walk's floors (retro_floor_nn, and truncation where a batch's positions are
 * non-negative) against retro_floor and floorf on both sides of 0 and of the integers, -0, the
 * least subnormal and the floats nearest an integer included. */
Test(numerics, floor_by_sign_is_floor)
{
    const float q[] = {0.0f, -0.0f, 0x1p-149f, -0x1p-149f, 0.5f, -0.5f, 1.0f, -1.0f, nextafterf(1.0f, 0.0f),
                       nextafterf(-1.0f, 0.0f), nextafterf(-1.0f, -2.0f), 4194303.5f, -4194303.5f,
                       0x1p24f, -0x1p24f, 0x1p30f, -0x1p30f};
    for (size_t i = 0; i < sizeof q / sizeof q[0]; i++) {
        cr_assert_eq(retro_floor_nn(q[i]), (int)floorf(q[i]), "q = %a", (double)q[i]);
        cr_assert_eq(retro_floor(q[i]), (int)floorf(q[i]), "q = %a", (double)q[i]);
        if (q[i] >= 0.0f)
            cr_assert_eq((int)q[i], (int)floorf(q[i]), "q = %a", (double)q[i]);
    }
}

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

    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    retro_render_opts course = RETRO_RENDER_OPTS_DEFAULT;
    course.mode = RETRO_MODE_COURSE;
    const retro_frame *f;
    cr_assert_eq(retro_frame_prepare(rc, &course, &p, &c, &f), RETRO_OK);
    /* (a) cells read over many poses: never the last row or column. */
    {
        uint8_t *seen = calloc((size_t)S * S, 1);
        uint64_t rng = 5;
        for (int k = 0; k < 40; k++) {
            player_t q = {(float)(rng_next(&rng) % (uint64_t)S) + 0.37f, (float)(rng_next(&rng) % (uint64_t)S) + 0.61f,
                          (int)(rng_next(&rng) % 360), z, 0, 0, 0};
            retro_ctx *r2 = retro_ctx_new();
            cr_assert(r2);
            const retro_frame *f2;
            cr_assert_eq(retro_frame_prepare(r2, &course, &q, &c, &f2), RETRO_OK);
            for (int d = 1; d < D; d++) {
                float qx = f2->lx[d], qy = f2->ly[d];
                for (int u = 0; u < W; u++, qx += f2->sx[d], qy += f2->sy[d])
                    seen[(size_t)retro_course_cell(qy, S) * S + (size_t)retro_course_cell(qx, S)] = 1;
            }
            retro_ctx_free(r2);
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
    retro_ctx_free(rc);
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
