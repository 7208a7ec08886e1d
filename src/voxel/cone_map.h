/* A study of cone steps for occlusion skipping (docs/studies/SKIPPING_LIMITS.md, "Cone steps"): how
 * many samples a column walk evaluates when, after each sample, it jumps over the distances that a
 * per-direction slope bound of the map proves hidden ("cone step mapping", Dummer 2006; the
 * relaxed cones of Policarpo and Oliveira, GPU Gems 3, 2007, bound the same thing for a ray that
 * may enter the surface). Only the counting build of ybuffer uses it (retro render --stats): a
 * measurement of what such a bound would buy, not a kernel.
 *
 * The map. Directions are cut into n sectors of width 2w = 2 pi / n around the angles
 * 2 pi sigma / n. For cell c, sector sigma and every offset o = (dx, dy) != 0 in sigma's wedge
 * (below) whose cells lie within R of each other, delta(o) is the least distance between the
 * unit squares of c and c + o: sqrt(max(|dx| - 1, 0)^2 + max(|dy| - 1, 0)^2), 0 for the eight
 * neighbours. The map stores
 *     b = max(0, max over the wedge's neighbours (delta = 0) of h(c + o) - h(c)),
 *     s = max(0, max over the wedge's other offsets of (h(c + o) - h(c) - b) / delta(o)),
 * so that every cell c' = c + o of the wedge within R has h(c') <= h(c) + b + s delta(o): a
 * cone of slope s whose apex is b above the cell. (Without b, one higher neighbour ahead would
 * make every cone flat: a ray can cross into a neighbour at once near the cell's edge.)
 *
 * The wedge of sigma holds o when the square of half side 1 + RETRO_CONE_EPS around o meets
 * {t (cos a, sin a) : t >= RETRO_CONE_RMIN, |a - 2 pi sigma / n| <= w + 1e-6}. A ray whose
 * angle lies in sigma's sector and whose step length is at least RETRO_CONE_RMIN + the
 * rounding of its positions (RETRO_CONE_EPS per sample) can only move from c into cells of the
 * wedge, which is what retro_cone_step needs (proved there).
 */
#ifndef RETRO_CONE_MAP_H
#define RETRO_CONE_MAP_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "env.h"
#include "retro_internal.h"

/* the largest error of two sample positions' difference the map allows for (cells) */
#define RETRO_CONE_EPS 0.01
/* the shortest step between a column's distances the wedge allows for (cells) */
#define RETRO_CONE_RMIN 0.69

/* The shape retro render --stats uses unless RETRO_CONE_SECTORS and RETRO_CONE_R say otherwise (the
 * lowest shares of the shapes measured in docs/studies/SKIPPING_LIMITS.md, "Cone steps"); the
 * ranges it takes are env.h's. */
enum { RETRO_CONE_SECTORS_DEFAULT = 64, RETRO_CONE_R_DEFAULT = 8 };

typedef struct retro_cone_map {
    int S;         /* the torus' side, the map's row stride */
    int sectors;   /* n */
    int R;         /* the radius the bound holds within (cells) */
    uint8_t *b;    /* [sectors][S * S] apex heights above the cell */
    float *s;      /* [sectors][S * S] slopes */
} retro_cone_map;

/* Builds the map of the S x S torus of heights h for n sectors and radius R (the ranges
 * above). Returns 0, or -1 when out of memory or the arguments are out of range (m then holds
 * none). A study: it allocates and takes seconds on large maps. */
int retro_cone_build(retro_cone_map *m, const uint8_t *h, int S, int sectors, int R);
void retro_cone_free(retro_cone_map *m);

/* The sector of a column's ray (rx, ry): the nearest multiple of 2 pi / n to its angle. */
int retro_cone_sector(const retro_cone_map *m, float rx, float ry);

/* Whether the map may be used for frame f at all: every column's step is long enough and the
 * rounding of its positions within RETRO_CONE_EPS (mode exact, plain samples). */
int retro_cone_applies(const retro_cone_map *m, const retro_frame *f);

/* How many distances after e0 (at most e_end - 1 - e0) a column of mode exact (ray rx, ry, of
 * sector sigma) can jump over after evaluating its sample at e0, whose cell is idx with height
 * h0, when its y-buffer is now y (< H): none of their samples can paint.
 * Proof. Let need = y + 1 and e = e0 + k, 1 <= k. The kernel's row float vf(e) exceeds the real
 * (half_w / e)(h - height) + half_h by at most mg(e) = 2^-21 ((half_w / e) dhmax + |half_h|)
 * (retro_skip_plane_hides's roundings), and mg is non-increasing in e, so the sample at e
 * paints nothing when h(e) < height + A e with A = (need - half_h - mg(e0)) / half_w
 * (multiply the row by e / half_w > 0). Its position P(e) = (qx, qy) lies within
 * ex = 2^-23 (|x0| + 2 D |rx|) of the real x0 + e rx per axis (retro_skip_plane_hides), so
 * |P(e) - P(e0) - k r| <= eps2 = 2 hypot(ex, ey) <= RETRO_CONE_EPS (retro_cone_applies), and
 * k r has the ray's angle and length k |r| >= |r| >= RETRO_CONE_RMIN. P(e0) lies in cell c
 * and P(e) in c + o, so P(e) - P(e0) lies in the open square of half side 1 around o and k r
 * in the one of half side 1 + eps2: o is in the wedge of the ray's sector. The least distance
 * between the two cells' squares is at most |P(e) - P(e0)| <= k |r| + eps2 =: rho; while
 * rho <= R, the cell is one the map bounds: h(e) <= h0 + b + s rho. So the sample cannot paint
 * when h0 + b + s (k |r| + eps2) < height + A (e0 + k), that is
 *     k (s |r| - A) < mrg := height + A e0 - h0 - b - s eps2.
 * The stored s is a maximum of binary32 quotients fl(fl(dh) fl(1 / delta)) (dh an integer, so
 * exact), each within 2^-23 of the true ratio relative, so s (1 + 1e-6) bounds every true one.
 * The step is the largest k meeting that and k |r| + eps2 <= R, each evaluated in double with
 * margins far above its rounding. The y-buffer stays y across the jump, since nothing paints.
 */
RETRO_HELPER int retro_cone_step(const retro_cone_map *m, const retro_frame *f, int sigma, float rx, float ry,
                                 size_t idx, int h0, int e0, int e_end, int y)
{
    const double rlen = sqrt((double)rx * rx + (double)ry * ry) * (1.0 - 1e-12);
    const double half_w = f->half_w, half_h = f->half_h, height = (double)f->height;
    const double dhmax = (fabs(height) > 255.0 ? fabs(height) : 255.0) + 255.0;
    const double mg = 0x1p-21 * (half_w / e0 * dhmax + fabs(half_h)) + 1e-9;
    const double A = ((double)(y + 1) - half_h - mg) / half_w;
    const size_t at = (size_t)sigma * (size_t)m->S * (size_t)m->S + idx;
    const double b = m->b[at], s = (double)m->s[at] * (1.0 + 1e-6);
    const double mrg = height + A * e0 - h0 - b - s * RETRO_CONE_EPS - 1e-6;
    if (!(mrg > 0.0))
        return 0;
    double k = (m->R - RETRO_CONE_EPS) / rlen;
    const double slope = s * rlen - A;
    if (slope > 0.0 && mrg / slope < k)
        k = mrg / slope * (1.0 - 1e-9);
    int steps = (int)ceil(k) - 1; /* the largest integer strictly below k */
    if (steps < 0)
        steps = 0;
    return steps < e_end - 1 - e0 ? steps : e_end - 1 - e0;
}

#endif
