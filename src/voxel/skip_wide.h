/* Occlusion skipping in modes truth and fixed (docs/SKIPPING.md, "Modes truth and fixed"): the
 * pyramid of hmax_pyramid.h over the S x S torus, probed with each mode's own positions and
 * rows. Only the ybuffer strip renders these modes (ybuffer, and pthreads and omp, which run
 * it), so this probe is the scalar walk's, one column at a time.
 *
 * The same four points as retro_skip_run's proof, with the modes' arithmetic:
 * 1. Positions are monotone in the distance e. Mode truth: qx(e) = x0 + (double)e * rx in
 *    binary64 (retro_truth_sample), (double)e exact, each operation rounded to nearest and so
 *    monotone; mode fixed: qx(e) = x0 + e * rx in int64_t (retro_fixed_sample), exact and
 *    linear. Either way the floor of qx(e) over [d, d1] lies between its values at the two ends,
 *    computed here by the kernel's own expressions (retro_truth_floor, retro_fixed_floor). Their
 *    magnitude is below 2^23: 0 <= x0 <= S <= 16384, and e < 2^22 with |rx| <= sqrt 2, so they
 *    fit an int. y alike.
 * 2. Cells. The kernel's cell is (floor mod S) per axis, as in mode exact; the box of unwrapped
 *    floors is confirmed to span at most B per axis, and the window lemma (hmax_pyramid.h)
 *    bounds every height in it by the window M at its smallest corner, across the seam too.
 * 3. Rows. Mode truth: v = clamp(kdd[e] * (double)dh + H/2) (retro_truth_row); mode fixed:
 *    v = clamp((kd_q[e] * dh + half_h_q) >> RETRO_Q_PROJ) (retro_fixed_row), exact in int64_t
 *    (|kd_q| < 2^30, |dh| < 2^32). Each is non-decreasing in dh (kd >= 0, rounding and the
 *    clamp are monotone). kdd[e] = fl(0.5 W / e) is non-increasing in e, and kd_q[e] =
 *    llround(kdd[e] 2^RETRO_Q_PROJ) too (scaling by a power of two is exact, llround monotone),
 *    so for a fixed dh the row is monotone in e and its largest value over the run is at d or
 *    at d1. Every sample of the run has a height <= M, so its row is at most
 *    max(v(M, d), v(M, d1)), both computed here with the kernel's own row function.
 * 4. No paint. A sample paints when its row exceeds y; when both bounds are <= y, none of the
 *    run's samples paints and the y-buffer is y across it: skipping it changes no pixel.
 * tests/test_skipping.c renders every case in both modes against naive (skipping_rig.c). */
#ifndef RETRO_SKIP_WIDE_H
#define RETRO_SKIP_WIDE_H

#include <math.h>

#include "hmax_pyramid.h"

/* Whether the ybuffer strip skips this frame in mode truth or fixed: a frame with a pyramid. */
RETRO_HELPER int retro_skip_wide_applies(const retro_frame *f)
{
    return f->pyr && (f->mode == RETRO_MODE_TRUTH || f->mode == RETRO_MODE_FIXED);
}

/* retro_truth_sample's unwrapped floor of a position, in range (point 1). */
RETRO_HELPER int retro_truth_floor(double q)
{
    return (int)retro_floor_d(q);
}

/* The unwrapped cell floors of column u's sample at distance e, as the mode's sample computes
 * them (fixed: mode fixed, else mode truth). */
RETRO_HELPER void retro_skip_wide_floors(const retro_frame *f, int u, int e, const int fixed, int *I, int *J)
{
    if (fixed) {
        *I = (int)retro_fixed_floor(f->x0_q + (int64_t)e * f->rx_q[u]);
        *J = (int)retro_fixed_floor(f->y0_q + (int64_t)e * f->ry_q[u]);
    } else {
        *I = retro_truth_floor(f->x0_d + (double)e * f->rxd[u]);
        *J = retro_truth_floor(f->y0_d + (double)e * f->ryd[u]);
    }
}

/* The row of height difference dh at distance e, as the mode's sample computes it. */
RETRO_HELPER int retro_skip_wide_row(const retro_frame *f, int e, int64_t dh, const int fixed)
{
    if (fixed)
        return retro_fixed_row(f->kd_q[e], f->half_h_q, f->H, dh);
    return retro_truth_row(f->kdd[e], 0.5 * (double)f->H, f->H, dh);
}

/* Column u's traversal state: the run length's estimate from the binary64 ray (the run is
 * confirmed from its end cells, so any estimate is safe) and the level to start at. */
RETRO_HELPER void retro_skip_wide_init(retro_skip_col *c, const retro_frame *f, int u)
{
    const double ax = fabs(f->rxd[u]), ay = fabs(f->ryd[u]), r = ax > ay ? ax : ay;
    c->rx = c->ry = 0.0f; /* unused: the mode's own rays are read */
    c->inv_r = r > 0.0 ? (float)(1.0 / r) : 1.0f;
    c->level = RETRO_PYR_LMIN;
}

/* The first distance in [d, d_end) whose sample in column u may rise above y (y < H); d_end
 * when none may. Levels go up after a skip and down after a window that may paint; at
 * RETRO_PYR_LMIN the probe gives up. Proof: the head of this file. */
static inline __attribute__((always_inline, unused)) int
retro_skip_run_wide(const retro_pyramid *p, const retro_frame *f, retro_skip_col *c, int u, int d, int d_end, int y,
                    const int fixed)
{
    const int S = f->S, lmax = p->lmax, pow2 = !(S & (S - 1));
    const int64_t height = f->height;
    int L = c->level, at = 0, I0 = 0, J0 = 0; /* the floors at distance at (0: none yet) */
#ifdef RETRO_COUNT_SAMPLES
    retro_ybuffer_counts.probes++;
#endif
    while (d < d_end) {
#ifdef RETRO_COUNT_SAMPLES
        retro_ybuffer_counts.windows++;
#endif
        const int B = 1 << L;
        const int len = 1 + (int)((float)(B - 1) * c->inv_r); /* distances: an estimate */
        const int d1 = d_end - 1 - d < len - 1 ? d_end - 1 : d + len - 1;
        if (at != d) { /* a finer level starts where the coarser one did */
            retro_skip_wide_floors(f, u, d, fixed, &I0, &J0);
            at = d;
        }
        int I1, J1;
        retro_skip_wide_floors(f, u, d1, fixed, &I1, &J1);
        const int wi = I0 < I1 ? I1 - I0 : I0 - I1, wj = J0 < J1 ? J1 - J0 : J0 - J1;
        if (wi <= B && wj <= B) {
            const int bi = retro_skip_wrap(I0 < I1 ? I0 : I1, S, pow2) >> L;
            const int bj = retro_skip_wrap(J0 < J1 ? J0 : J1, S, pow2) >> L;
            const int64_t dh = (int64_t)p->win[L][(size_t)bj * (size_t)p->n[L] + (size_t)bi] - height;
            if (retro_skip_wide_row(f, d, dh, fixed) <= y && retro_skip_wide_row(f, d1, dh, fixed) <= y) {
                d = d1 + 1;
                if (L < lmax)
                    L++;
                continue;
            }
        }
        if (L <= RETRO_PYR_LMIN)
            break;
        L--;
    }
    c->level = L;
    return d;
}

#endif
