/* Mode course's skipping rests on one number: eps, the most an accumulated position may drift
 * from its column's straight line (src/voxel/skip_course.h, where it is derived). These tests
 * measure the drift of every sample of frames at the extremes skipping is used at (wide
 * screens, long distances, positions far from the origin, every octant) against eps, and check
 * that the margin turns skipping off where the drift could exceed two cells. Rendering cases
 * aimed at the bound are in test_skipping.c (its rig renders each in mode course too). */
#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>

#include "frame.h"
#include "skip_course.h"

/* The largest |q - l| over the frame's samples, in cells: q accumulated as the kernels do
 * (lx[d] plus u float additions of sx[d]), l = x + d (c - s + 2 u s / W) in long double with c, s
 * the frame's cosf and sinf of its angle; y alike. */
static double max_drift(const player_t *p, int W, int D)
{
    static uint32_t out[1];
    static uint8_t h[4];
    static uint32_t col[4];
    ctx_t c = {W, 1, 2, D, 0, h, col, out};
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = RETRO_MODE_COURSE;
    const retro_frame *f;
    cr_assert_eq(retro_frame_prepare(rc, &o, p, &c, &f), RETRO_OK);
    const float phi = (float)(p->angle * 3.14159265358979323846 / 180.0);
    const long double cs = cosf(phi), sn = sinf(phi), x = p->x, y = p->y;
    double worst = 0.0;
    for (int d = 1; d < D; d++) {
        float qx = f->lx[d], qy = f->ly[d];
        for (int u = 0; u < W; u++, qx += f->sx[d], qy += f->sy[d]) {
            const long double t = 2.0L * (long double)u / (long double)W;
            const long double lx = x + (long double)d * (cs - sn + t * sn);
            const long double ly = y + (long double)d * (-sn - cs + t * cs);
            const double e = (double)fmaxl(fabsl((long double)qx - lx), fabsl((long double)qy - ly));
            worst = e > worst ? e : worst;
        }
    }
    retro_ctx_free(rc);
    return worst;
}

Test(skipping_course, drift_within_bound_at_extremes)
{
    static const struct {
        int W, D;
    } sizes[] = {{640, 800}, {1920, 4000}, {16384, 200}, {4096, 1500}, {1, 30000}, {3, 2}};
    static const float positions[][2] = {{0.0f, 0.0f},        {511.37f, 1023.99f}, {-3000.25f, 77.5f},
                                         {65535.7f, -40000.2f}, {262143.9f, 3.0f},   {1.0e6f, -1.0e6f}};
    static const int angles[] = {0, 1, 37, 45, 90, 133, 181, 226, 271, 359};
    double worst_ratio = 0.0;
    int measured = 0, off = 0;
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (size_t k = 0; k < sizeof positions / sizeof positions[0]; k++)
            for (size_t a = 0; a < sizeof angles / sizeof angles[0]; a += 1 + (sizes[s].W > 2000)) {
                const int W = sizes[s].W, D = sizes[s].D;
                player_t p = {positions[k][0], positions[k][1], angles[a], 100, 0, 0, 0};
                const double eps = retro_course_drift(p.x, p.y, W, D);
                if (!retro_course_margin(p.x, p.y, W, D)) {
                    off++;
                    cr_assert_gt(2.0 * eps, RETRO_COURSE_MARGIN_MAX, "skipping off at W %d, D %d, (%g, %g) with eps %g",
                                 W, D, (double)p.x, (double)p.y, eps);
                    continue;
                }
                const double drift = max_drift(&p, W, D);
                cr_assert_leq(drift, eps, "W %d, D %d, (%g, %g), angle %d: drift %.6g cells, bound %.6g", W, D,
                              (double)p.x, (double)p.y, p.angle, drift, eps);
                worst_ratio = drift / eps > worst_ratio ? drift / eps : worst_ratio;
                measured++;
            }
    cr_assert_gt(measured, 100, "only %d frames measured", measured);
    cr_assert_gt(off, 0, "no frame was far enough out to turn skipping off");
    cr_log_info("%d frames measured, %d with skipping off; largest drift / eps: %.3f", measured, off, worst_ratio);
}

/* The margin is what the probe widens by, ceil(2 eps), and is 0 (no skipping) for positions
 * that are not finite or beyond 2^22. */
Test(skipping_course, margin_follows_the_bound)
{
    cr_assert_eq(retro_course_margin(512.0f, 512.0f, 640, 800), 1);
    cr_assert_eq(retro_course_margin(NAN, 0.0f, 640, 800), 0);
    cr_assert_eq(retro_course_margin(0.0f, INFINITY, 640, 800), 0);
    cr_assert_eq(retro_course_margin(8388608.0f, 0.0f, 1, 2), 0);
    for (int W = 1; W <= 16384; W *= 4)
        for (int D = 2; D <= 40000; D *= 3) {
            const int E = retro_course_margin(1000.0f, -1000.0f, W, D);
            const double eps = retro_course_drift(1000.0f, -1000.0f, W, D);
            if (E)
                cr_assert(E >= 2.0 * eps && E - 1 < 2.0 * eps && E <= RETRO_COURSE_MARGIN_MAX, "W %d, D %d", W, D);
            else
                cr_assert_gt(2.0 * eps, RETRO_COURSE_MARGIN_MAX, "W %d, D %d", W, D);
        }
}
