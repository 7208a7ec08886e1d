/* Occlusion skipping in mode course (docs/SKIPPING.md): the pyramid of hmax_pyramid.h built
 * over the course's torus of period P = S - 1, and a probe that bounds a run of distances of
 * one column from the positions at its two ends, widened by the margin E the accumulated
 * positions may drift from a straight line.
 *
 * Why a margin. In mode exact a sample's position is one rounded expression of its distance,
 * monotone in it. In mode course the position of column u (0-based here, k = u additions) at
 * distance d is the accumulator q(u, d): Lx[d] plus k float additions of sx[d]
 * (SEMANTICS.md), not monotone in d. It is however close to the line
 *     l(u, d) = x + d * (c - s + 2 k s / W)      (c, s: the frame's cosf(phi), sinf(phi))
 * which for a fixed column is linear in d. If |q(u, d) - l(u, d)| <= eps for every sample of
 * the frame, then for d <= e <= d1 in one column
 *     q(u, e) in [min(q(u, d), q(u, d1)) - 2 eps, max(q(u, d), q(u, d1)) + 2 eps],
 * because l(u, e) lies between l(u, d) and l(u, d1), each within eps of its q. y alike.
 *
 * The bound eps. With u = 2^-24 (rounding to nearest: |fl(z) - z| <= u |z|), X = max(|x|, |y|),
 * D the frame's distance, |c|, |s| <= 1, and for d < D, k < W:
 *   a = fl(c d), b = fl(s d):                 |a - c d|, |b - s d| <= u d;
 *   Lx = fl(fl(x + a) - b):                   |Lx - (x + c d - s d)| <= u (2X + 5d) + O(u^2),
 *     two roundings of values below X + d and X + 2d, plus the errors of a and b;
 *   Rx = fl(fl(x + a) + b): the same; sx = fl(fl(Rx - Lx) / W), with Rx - Lx near 2 s d:
 *                                             |sx - 2 s d / W| <= u (4X + 14d) / W + O(u^2);
 *   k additions q <- fl(q + sx), each rounded by u times a value below X + 4D + 3 (|Lx| and
 *     W |sx| are below X + 2d + 1 and 2d + 1, and the drift itself is below 2, see below):
 *                                             <= (W - 1) u (X + 4D + 3).
 * Summed, |q - l| <= u (6X + 19D + W (X + 4D + 3)) + O(u^2)
 *                <= u (W + 8)(X + 4D + 8) =: eps,
 * since (W + 8)(X + 4D + 8) - W (X + 4D + 3) = 5W + 8X + 32D + 64 exceeds 6X + 19D by far more
 * than the O(u^2) terms. The y coordinate is the same with c and s exchanged. Skipping is used
 * only when E = ceil(2 eps) <= RETRO_COURSE_MARGIN_MAX (so eps <= 2, which the bound on each
 * addition assumed), and then |q| < 2^22: every floor below fits an int. tests/test_skipping_course.c
 * measures the drift at the extremes against eps.
 *
 * Cells. The kernel's cell of q is (int)float_mod(q, P). float_mod is exact for q >= 0 and
 * gives floor(q) mod P; for q < 0 its res + P rounds, and rounding to nearest is monotone with
 * the integers up to P representable, so it gives floor(q) mod P or floor(q) + 1 mod P (the
 * res >= P case maps P to 0, the same neighbour). So a run's cells have floors in
 * [min(F0, F1) - E, max(F0, F1) + E + 1] with F0, F1 the floors of its end positions
 * (floor(q - t) >= floor(q) - ceil(t)): a box of width |F1 - F0| + 2E + 1 per axis, which the
 * probe confirms is at most B. By the window lemma of hmax_pyramid.h on the P x P torus, the
 * window of the block of (min corner mod P) bounds every height the run reads.
 *
 * Rows. The row retro_course_row(cw2, ch2, H, dh, e) is non-decreasing in dh ((float) dh,
 * the product with cw2 > 0, the division by (float)e > 0, trunc and the clamp are monotone),
 * and for a fixed dh its quotient is non-increasing in e when dh >= 0 and non-decreasing when
 * dh < 0. So every sample of the run has v <= retro_course_row(.., M - height, d or d1), the
 * first end when M - height >= 0. A sample paints only when v > y; when that bound is <= y
 * no sample of the run paints and the y-buffer stays y across it.
 *
 * The accumulation is not skipped: the kernels advance every accumulator of the column after
 * it (retro_course_advance, course_column), sampled or not, so the next column reads the same
 * positions. */
#ifndef RETRO_SKIP_COURSE_H
#define RETRO_SKIP_COURSE_H

#include <math.h>

#include "hmax_pyramid.h"

enum { RETRO_COURSE_MARGIN_MAX = 4 };

/* eps of the proof above for a frame at (x, y) with W columns and distance D (infinite for a
 * position beyond 2^22 or NaN, where skipping is off anyway). */
RETRO_HELPER double retro_course_drift(float x, float y, int W, int D)
{
    const double ax = fabs((double)x), ay = fabs((double)y);
    if (!(ax <= 4194304.0 && ay <= 4194304.0)) /* NaN fails too, which fmax would drop */
        return INFINITY;
    const double X = ax > ay ? ax : ay;
    return ldexp(((double)W + 8.0) * (X + 4.0 * (double)D + 8.0), -24);
}

/* E = ceil(2 eps) for such a frame, or 0 when mode course must not skip (the drift could
 * exceed 2 cells). */
RETRO_HELPER int retro_course_margin(float x, float y, int W, int D)
{
    const double E = ceil(2.0 * retro_course_drift(x, y, W, D));
    return E <= RETRO_COURSE_MARGIN_MAX ? (int)E : 0;
}

/* The finest level whose blocks hold a box of a run of about `run` cells widened by the margin:
 * finer windows could only confirm runs too short to be worth a probe. */
RETRO_HELPER int retro_course_lmin(int E, int run)
{
    int L = RETRO_PYR_LMIN;
    while (L < RETRO_PYR_LMAX && (1 << L) < 2 * E + 1 + run)
        L++;
    return L;
}

/* Per-column probe state. */
typedef struct retro_course_col {
    float inv_r; /* 1 / cells per distance along the column's larger axis: an estimate only */
    int level;   /* the level the next probe starts at */
    int lmin;    /* the probe gives up below this level */
} retro_course_col;

/* qx, qy: the column's positions (index d). */
RETRO_HELPER void retro_course_col_init(retro_course_col *c, const retro_frame *f, const float *qx,
                                        const float *qy, int lmin)
{
    const int d1 = f->D - 1;
    float r = 0.0f;
    if (d1 > 1)
        r = fmaxf(fabsf(qx[d1] - qx[1]), fabsf(qy[d1] - qy[1])) / (float)(d1 - 1);
    c->inv_r = r > 0.0625f ? 1.0f / r : 16.0f; /* r is about 1 to 1.4 for every column */
    c->lmin = lmin;
    c->level = lmin;
}

/* The first distance in [d, d_end) whose sample in this column may rise above y (y < H);
 * d_end when none may. Levels go up after a skip and down after a window that may paint;
 * below c->lmin the probe gives up. */
static inline __attribute__((always_inline, unused)) int
retro_skip_course(const retro_frame *f, retro_course_col *c, const float *qx, const float *qy, int d, int d_end,
                  int y)
{
    const retro_pyramid *p = f->pyr;
    const int P = p->P, E = f->course_margin, lmin = c->lmin, lmax = p->lmax;
    const int64_t height = f->height;
    int L = c->level, at = 0, I0 = 0, J0 = 0; /* the floors at distance at (0: none yet) */
    if (lmin > lmax)
        return d;
#ifdef RETRO_COUNT_SAMPLES
    retro_ybuffer_counts.probes++;
#endif
    while (d < d_end && L >= lmin) {
#ifdef RETRO_COUNT_SAMPLES
        retro_ybuffer_counts.windows++;
#endif
        const int B = 1 << L;
        const float est = (float)(B - 2 * E - 1) * c->inv_r; /* distances: an estimate */
        const int len = est >= (float)(d_end - d) ? d_end - d : est < 1.0f ? 1 : (int)est;
        const int d1 = d + len - 1;
        if (at != d) {
            I0 = retro_floor(qx[d]);
            J0 = retro_floor(qy[d]);
            at = d;
        }
        const int I1 = retro_floor(qx[d1]), J1 = retro_floor(qy[d1]);
        const int Imin = (I0 < I1 ? I0 : I1) - E, Jmin = (J0 < J1 ? J0 : J1) - E;
        const int wi = (I0 < I1 ? I1 - I0 : I0 - I1) + 2 * E + 1, wj = (J0 < J1 ? J1 - J0 : J0 - J1) + 2 * E + 1;
        if (wi <= B && wj <= B) {
            const int bi = retro_skip_wrap(Imin, P, 0) >> L, bj = retro_skip_wrap(Jmin, P, 0) >> L;
            const int64_t dh = (int64_t)p->win[L][(size_t)bj * (size_t)p->n[L] + (size_t)bi] - height;
            if (retro_course_row(f->cw2, f->ch2, f->H, dh, dh >= 0 ? d : d1) <= y) {
                d = d1 + 1;
                if (L < lmax)
                    L++;
                continue;
            }
        }
        L--;
    }
    c->level = L < lmin ? lmin : L;
    return d;
}

#endif
