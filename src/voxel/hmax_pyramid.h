/* Exact occlusion skipping (docs/SKIPPING.md): a maximum-height pyramid of the map, built once
 * per map, and the per-column traversal that jumps over runs of distances none of whose
 * samples can rise above the column's y-buffer.
 *
 * Level L (RETRO_PYR_LMIN <= L <= lmax) cuts the S x S torus into blocks of B = 2^L cells per
 * side (the last block of a side is partial when B does not divide S) and stores, for block
 * (bi, bj), win = the maximum height over the blocks A(bi) x A(bj) with
 *     A(b) = {b, (b + 1) mod n}, plus block 0 when B does not divide S and b = n - 2,
 * n = ceil(S / B). Window lemma: for a cell c in block b and 0 <= w <= B, the cells
 * c, c+1, .., c+w (mod S) all lie in the blocks A(b). Without wrap (c + w < S) they lie in
 * [bB, (b+2)B) ∩ [0, S), blocks b and b + 1. With wrap, c >= S - B, and the cells past the
 * seam are 0..c+w-S <= B-1, block 0; the cells before it lie in blocks b..n-1. If B divides S,
 * c >= S - B puts b = n - 1, so {n-1, 0} = A(b). If not, block(S - B) = n - 2, so b is n - 2
 * ({n-2, n-1, 0} = A(n-2)) or n - 1 ({n-1, 0}). So any box of cells whose unwrapped floor
 * indices span at most B per axis is covered by the one window at the block of its smallest
 * corner, taken mod S: one load bounds every height in the box.
 *
 * The traversal (retro_skip_column) needs only that bound and the monotonicity proved at
 * retro_skip_column; see there. Single-threaded state per column, read-only pyramid: any
 * number of threads may share one pyramid.
 */
#ifndef RETRO_HMAX_PYRAMID_H
#define RETRO_HMAX_PYRAMID_H

#include <stddef.h>
#include <stdint.h>

#include "retro_internal.h"

enum {
    RETRO_PYR_LMIN = 2,   /* blocks of 4 cells: a run of ~3 distances, finer is not worth a load */
    RETRO_PYR_LMAX = 12,  /* blocks of 4096 cells */
    RETRO_SKIP_NEAR = 4,  /* distances evaluated one by one after a probe that cannot skip, */
    RETRO_SKIP_FAR = 32,  /* doubling up to this many while the probes keep failing */
    /* the SIMD strips' probe (simd_skip_tpl.h): failing windows per probe before it gives up.
     * A failing window costs about one vector step, so a group cannot afford a long descent. */
    RETRO_SKIP_GROUP_TRIES = 64,
};

typedef struct retro_pyramid {
    const uint8_t *map;   /* the height map it was built from (NULL: none built) */
    int S;                /* the map's side, its row stride */
    int P;                /* the torus' side: S in modes exact and lod, S - 1 in mode course */
    int lmax;             /* levels RETRO_PYR_LMIN..lmax exist; lmax < LMIN: none (S <= 4) */
    int n[RETRO_PYR_LMAX + 1];            /* blocks per side at level L */
    const uint8_t *win[RETRO_PYR_LMAX + 1]; /* [n*n] window maxima at level L, row-major */
    uint8_t *mem;         /* every level's windows, then build scratch */
    size_t cap;
} retro_pyramid;

/* Makes p the pyramid of the torus of the top-left P x P cells of map h (S x S, P <= S)
 * unless it already is. The header's S is P here: blocks, windows and the lemma are of the
 * P x P torus, whose cell (i, j) is h[j * S + i]. Allocates only when the map is new and larger
 * than any before. Returns 0, or -1 when out of memory (p then holds none). */
int retro_pyramid_build(retro_pyramid *p, const uint8_t *h, int S, int P);
void retro_pyramid_free(retro_pyramid *p);
/* Forgets which map p was built from, so the next build recomputes it. */
void retro_pyramid_stale(retro_pyramid *p);
/* A context's pyramid (retro_ctx.pyr or pyr_course, allocated into *slot on first use) made
 * the pyramid of period P of map h (S x S); *out is it, or NULL when the map is too small to
 * have levels. Returns 0, or -1 when out of memory (*out NULL). */
int retro_pyramid_get(retro_pyramid **slot, const uint8_t *h, int S, int P, const retro_pyramid **out);

/* Counts of the counting build of the ybuffer kernel (retro_kernel_ybuffer_counted, in
 * the library as an object of kernel_ybuffer.c compiled with RETRO_COUNT_SAMPLES). Global and
 * unsynchronised: one thread at a time, reset by the caller. */
typedef struct retro_sample_counts {
    uint64_t evaluated; /* samples whose cell and row were computed */
    uint64_t painting;  /* samples that raised their column's y-buffer */
    uint64_t probes;    /* calls of retro_skip_column */
    uint64_t windows;   /* windows it read */
} retro_sample_counts;
extern retro_sample_counts retro_ybuffer_counts;
void retro_kernel_ybuffer_counted(const void *frame, retro_ctx *rc);
/* The same counts for the counting build of simd-avx512 (kernel_simd_avx512.c compiled with
 * RETRO_COUNT_SAMPLES): a sample is a live lane at a distance its group evaluated, painting a
 * lane that rose; probes and windows are the group probe's (simd_skip_tpl.h). Frames the vector path does not
 * render (retro_simd_check) go to the uncounted scalar kernel and count nothing. */
extern retro_sample_counts retro_simd_counts;
void retro_kernel_simd_avx512_counted(const void *frame, retro_ctx *rc);

/* The counting ybuffer's ideal bound (docs/studies/SKIPPING_LIMITS.md, "How far a max bound can
 * go"), a study of the method's limit, not a kernel: when it is L >= 0, a run's bound is the
 * largest height of the run's own box of cells instead of its block window (boxes wider than
 * RETRO_IDEAL_BOX cells keep the window, which is no smaller), the probe descends to blocks of 2^L
 * cells, and columns probe before every sample. -1 (the default): the kernel's own traversal. Still
 * exact, so its frames equal naive's. Global like the counts: one thread at a time. */
extern int retro_skip_ideal;
enum { RETRO_IDEAL_BOX = 64 };
/* Which bound the ideal walk tries after its box's maximum (docs/studies/SKIPPING_LIMITS.md, "Other
 * bounds at the same granularity"): none (RETRO_IDEAL_MAX, the default), a plane above every cell
 * of the box (retro_skip_plane_hides; plain samples only), or the oracle, which skips a run exactly
 * when none of its samples paints (retro_skip_oracle_hides): what any bound at all could do with
 * the same runs. Global like the counts. */
enum { RETRO_IDEAL_MAX, RETRO_IDEAL_PLANE, RETRO_IDEAL_ORACLE };
extern int retro_skip_ideal_kind;
/* Which part of the ideal walk the kernel's own walk is given (docs/studies/SKIPPING_LIMITS.md,
 * "Window or schedule"), to tell apart what its windows and its probe schedule each cost: the bound
 * of a run whose box spans at most B = 2^L cells per axis is its level's window
 * (RETRO_WINDOW_BLOCKS, the kernel's), the largest height of the run's own box
 * (RETRO_WINDOW_OWN_BOX, as the ideal bound takes it), or of the B x B cells from the box's
 * smallest corner where the box spans fewer than B (RETRO_WINDOW_UNALIGNED: what a table of
 * unaligned B x B maxima per level, a sparse table, would hold); the last two up to boxes of
 * RETRO_IDEAL_BOX cells, windows above. retro_skip_every: columns probe before every sample
 * (no batch after a failed probe). Both only where retro_skip_ideal is -1, and still exact (the
 * boxes hold every cell the run samples). Global like the counts. */
enum { RETRO_WINDOW_BLOCKS, RETRO_WINDOW_OWN_BOX, RETRO_WINDOW_UNALIGNED };
extern int retro_skip_window, retro_skip_every;
/* The cone steps' study (cone_map.h): when set, the counting ybuffer walks mode exact's plain
 * frames by cone steps from this map (the frame's own map, built by the caller), and with
 * retro_skip_cone_pyramid probes the pyramid before every sample too. Global like the counts. */
struct retro_cone_map;
extern const struct retro_cone_map *retro_skip_cone;
extern int retro_skip_cone_pyramid;

/* Whether the ybuffer strip skips this frame: mode exact or lod with a pyramid (any
 * per-sample effects: fog changes colours only, bilinear is covered by the bound). */
RETRO_HELPER int retro_skip_applies(const retro_frame *f)
{
    return f->pyr && (f->mode == RETRO_MODE_EXACT || f->mode == RETRO_MODE_LOD);
}

/* Per-column traversal state. */
typedef struct retro_skip_col {
    float rx, ry;   /* the column's ray, as the kernel reads it */
    float inv_r;    /* 1 / max(|rx|, |ry|) (an estimate only: every run is confirmed) */
    int level;      /* the level the next probe starts at */
} retro_skip_col;

RETRO_HELPER void retro_skip_col_init(retro_skip_col *c, const retro_frame *f, int u)
{
    c->rx = f->rx[u];
    c->ry = f->ry[u];
    float ax = fabsf(c->rx), ay = fabsf(c->ry), r = ax > ay ? ax : ay;
    c->inv_r = r > 0.0f ? 1.0f / r : 1.0f; /* |r| >= |(cs, sn)| / sqrt 2 > 0.7 in fact */
    c->level = RETRO_PYR_LMIN;
}

/* floor(q) mod S for the unwrapped floor I of a sample (retro_cell's integer part); pow2 when
 * S is a power of two (two's complement: I & (S - 1) is the non-negative remainder). */
RETRO_HELPER int retro_skip_wrap(int I, int S, const int pow2)
{
    if (pow2)
        return I & (S - 1);
    int i = I % S;
    return i < 0 ? i + S : i;
}

/* The studies' bounds below are used only by the counting build (RETRO_COUNT_SAMPLES); they are
 * visible everywhere so that tests can check them on their own. */
/* The largest height of the cells I..I+wi x J..J+wj of the torus of side S (the ideal bound). */
RETRO_HELPER int retro_skip_box_max(const retro_pyramid *p, int S, int I, int J, int wi, int wj)
{
    int m = 0;
    for (int b = 0; b <= wj; b++) {
        const uint8_t *row = p->map + (size_t)retro_skip_wrap(J + b, S, 0) * (size_t)p->S;
        for (int a = 0; a <= wi; a++) {
            const int h = row[retro_skip_wrap(I + a, S, 0)];
            m = h > m ? h : m;
        }
    }
    return m;
}

/* Whether no sample of the run at distances [d, d1] of a column (ray rx, ry) can paint above
 * y (need = y + 1), judged by a plane above the heights of the confirmed box of cells
 * I..I+wi x J..J+wj (unwrapped floors; the torus only maps them to heights). A study, in
 * double precision with explicit margins; plain samples only (no bilinear).
 * Proof. The plane's slopes gx, gy are the box's least-squares gradient and its offset c the
 * largest residual, so every cell (I+a, J+b) of the box has h <= c + gx a + gy b. A sample at
 * distance e has qx = fl(x0 + fl(e rx)) within ex = 2^-23 (|x0| + 2 |e rx|) of the real
 * X(e) = x0 + e rx (two roundings of relative error 2^-24), and its cell a = floor(qx) - I
 * lies in (X - ex - 1 - I, X + ex - I], so gx a <= gx (X(e) - I) + |gx| ex + max(0, -gx); y
 * alike. The sum P(e) of these bounds is linear in e, so (half_w / e) (P(e) - height) + half_h
 * = half_w ((P(0) - height) / e + P') + half_h is monotone in e and largest at e = d or d1.
 * The kernel's row vf = fl(fl(kd (float)dh) + half_h) with kd = fl(half_w / e) is
 * non-decreasing in h (retro_skip_run, point 3) and, with four roundings of relative error
 * 2^-24, exceeds the real (half_w / e) dh + half_h by at most 2^-21 ((half_w / d) |dh|max +
 * half_h), |dh| <= max(255, |height|) + 255. So when both ends' real rows plus that margin
 * stay below need, no sample of the run reaches need: it paints nothing (point 4). */
RETRO_HELPER int retro_skip_plane_hides(const retro_pyramid *p, const retro_frame *f, int I, int J, int wi, int wj,
                                        float rx, float ry, int d, int d1, float need)
{
    const int S = f->S;
    const double ca = 0.5 * wi, cb = 0.5 * wj;
    double sah = 0, sbh = 0, saa = 0, sbb = 0;
    for (int b = 0; b <= wj; b++) {
        const uint8_t *row = p->map + (size_t)retro_skip_wrap(J + b, S, 0) * (size_t)p->S;
        for (int a = 0; a <= wi; a++) {
            const double h = row[retro_skip_wrap(I + a, S, 0)];
            sah += (a - ca) * h;
            sbh += (b - cb) * h;
            saa += (a - ca) * (a - ca);
            sbb += (b - cb) * (b - cb);
        }
    }
    const double gx = saa > 0 ? sah / saa : 0.0, gy = sbb > 0 ? sbh / sbb : 0.0;
    double c = -1e300;
    for (int b = 0; b <= wj; b++) {
        const uint8_t *row = p->map + (size_t)retro_skip_wrap(J + b, S, 0) * (size_t)p->S;
        for (int a = 0; a <= wi; a++) {
            const double r = row[retro_skip_wrap(I + a, S, 0)] - gx * a - gy * b;
            c = r > c ? r : c;
        }
    }
    const double u2 = 0x1p-23, e1 = d > d1 ? d : d1;
    const double ex = u2 * (fabs((double)f->x0) + 2.0 * fabs(e1 * rx)),
                 ey = u2 * (fabs((double)f->y0) + 2.0 * fabs(e1 * ry));
    const double slack = fabs(gx) * ex + fabs(gy) * ey + (gx < 0 ? -gx : 0.0) + (gy < 0 ? -gy : 0.0);
    const double height = (double)f->height, half_w = f->half_w, half_h = f->half_h;
    const double dhmax = (fabs(height) > 255.0 ? fabs(height) : 255.0) + 255.0;
    const double margin = 0x1p-21 * (half_w / (d < d1 ? d : d1) * dhmax + fabs(half_h)) + 1e-9;
    for (int k = 0; k < 2; k++) {
        const double e = k ? d1 : d;
        const double P = c + gx * ((double)f->x0 + e * rx - I) + gy * ((double)f->y0 + e * ry - J) + slack;
        if (!(half_w / e * (P - height) + half_h + margin < (double)need))
            return 0;
    }
    return 1;
}

/* Whether no sample n..n1 of a column (ray rx, ry; distances dist[k], or k when dist is NULL)
 * rises above y: each sample's row computed as the kernel computes it (retro_skip_ideal_kind's
 * oracle, a study: it evaluates the run to decide whether to evaluate it). */
RETRO_HELPER int retro_skip_oracle_hides(const retro_frame *f, float rx, float ry, int n, int n1, const int *dist,
                                         int bilinear, int y)
{
    for (int k = n; k <= n1; k++) {
        const int e = dist ? dist[k] : k;
        const float qx = f->x0 + (float)e * rx, qy = f->y0 + (float)e * ry;
        int v;
        if (bilinear) {
            retro_bilerp b;
            v = retro_exact_row_f(f->kd[e], f->half_h, f->H,
                                  retro_bilinear_dh(retro_bilinear_height(f, qx, qy, &b), f->height));
        } else {
            const size_t idx = (size_t)retro_cell(qy, f->S) * (size_t)f->S + (size_t)retro_cell(qx, f->S);
            v = retro_exact_row(f->kd[e], f->half_h, f->H, f->height_map[idx] - f->height);
        }
        if (v > y)
            return 0;
    }
    return 1;
}

/* How far a bilinear height can exceed the largest of its four cells, M: by rounding only.
 * Proof. The filtered height is hf = ((h00*wx + h10*tx)*wy) + ((h01*wx + h11*tx)*ty) in
 * binary32, each operation rounded to nearest (relative error at most u = 2^-24, no fused
 * multiply-add), with tx, ty in [0, 1) and wx = fl(1 - tx) <= (1 - tx)(1 + u), wy alike, and
 * 0 <= h <= M (a product that underflows errs by at most 2^-150, far inside the margin below).
 * Then fl(h00*wx) <= M(1 - tx)(1 + u)^2 and fl(h10*tx) <= M tx (1 + u), so their
 * rounded sum is at most M(1 + u)^3; each row's sum times its weight adds (1 + u)^2 at most,
 * and the last sum one more (1 + u): hf <= M(1 + u)^6 < M + 6.0001 M u <= M + 9.2e-5 for
 * M <= 255 (heights are bytes), below 2^-13 = 1.2e-4. M + 2^-13 is an exact float (M < 2^8
 * needs 8 bits above the point and 2^-13 13 below). tests/test_skipping_counts.c checks the
 * bound by brute force (it finds no filtered height above M at all, which this proof does not
 * claim). M + 1, the earlier margin, held too, but it moves a row by kd[d] >= 1 near the
 * camera, so near runs of flat ground that cannot rise were never skipped. */
#define RETRO_BILINEAR_OVER 0x1p-13f

/* The first index n in [n, n_end) whose sample in this column may rise above y; n_end when
 * none may. The n-th sample is at distance dist[n] (mode lod), or n when dist is NULL (mode
 * exact: retro_skip_column). Every sample it skips has v <= y, so it cannot paint.
 *
 * Proof. A run [d, d1] is skipped only when the check below passes for it:
 * 1. Positions. For e in [d, d1], qx(e) = x0 + (float)e * rx with (float)e exact (e < 2^24)
 *    and each operation rounded to nearest: rounding is monotone, so e -> (float)e * rx is
 *    monotone (non-decreasing for rx >= 0, non-increasing otherwise) and so is x0 + that.
 *    These are the kernel's very operations (-ffp-contract=off everywhere), so qx(e) lies
 *    between the values computed here at d and d1, and floor(qx(e)) between I0 and I1,
 *    computed as the kernel computes them (retro_floor, or retro_floor_nn, which returns the
 *    same integer; |q| < 2^31 for valid frames). y alike.
 * 2. Cells. The kernel's cell is (floor(qx) mod S, floor(qy) mod S), the same integer
 *    remainder in the power-of-two path. The box [min I, max I] x [min J, max J] is confirmed
 *    here to span at most B per axis (the run length is only an estimate, so rounding at block
 *    edges or at large d cannot break this), and by the window lemma the window of the block
 *    holding (min I mod S, min J mod S) is >= the height of every cell the run samples, the
 *    wrap of the torus included.
 * 3. Rows. v(h, e) = clamp(floor(kd[e] * (float)(h - height) + half_h)) is non-decreasing in h
 *    (each step is monotone and kd > 0). kd[e] = half_w / (float)e is non-increasing in e, so
 *    for dh = M - height >= 0 the row of M is largest at e = d, and for dh < 0 at e = d1.
 *    Hence every sample of the run has v <= v(M, d or d1) =: vm.
 * 4. No paint. For y < H, vm > y exactly when vf >= (float)(y + 1) (y + 1 <= 16384 is exact
 *    in float; floor and clamp are monotone), the sample kernel's own test. So when the check
 *    fails, no sample of the run paints, the y-buffer stays y across it, and the skipped
 *    samples are exactly samples that would have painted nothing.
 * Bilinear (docs/EFFECTS.md) reads the cells floor(q - 1/2) and floor(q - 1/2) + 1 per axis, with
 * q - 1/2 = fl(qx - 0.5f) as retro_bilinear_height computes it (monotone in qx, so in e), so
 * the box grows by one cell per axis; its height is at most M + RETRO_BILINEAR_OVER (below),
 * and the row is computed from that float through the sample's own dh (retro_bilinear_dh,
 * monotone) and row operations.
 * Mode lod: a run is of indices [n, n1], whose distances dist[n] < .. < dist[n1] increase
 * (frame.c), so every distance the run samples lies in [d, d1] := [dist[n], dist[n1]], and
 * points 1 to 4 hold for those samples as they stand: 1 needs only that each sample's
 * distance lies between the two ends, 3 that kd is non-increasing in the distance (kd is
 * indexed by distance in mode lod as in mode exact). The index of the run's end is chosen
 * from the step at n (steps never shrink, so the run's distances span at most the estimated
 * length plus the later steps' growth); like the length in mode exact it is only an
 * estimate, the confirmed end cells decide.
 * The caller guarantees y < H (the vcap exit catches full columns). Levels go up after a
 * skip and down after a window that may paint; at RETRO_PYR_LMIN the probe gives up.
 */
static inline __attribute__((always_inline, unused)) int
retro_skip_run(const retro_pyramid *p, const retro_frame *f, retro_skip_col *c, int n, int n_end, int y,
               const int pow2, const int bilinear, const int *dist)
{
    const int S = f->S, lmax = p->lmax;
    const float x0 = f->x0, y0 = f->y0, half_h = f->half_h, need = (float)(y + 1);
    const float rx = c->rx, ry = c->ry;
    const int64_t height = f->height;
    int L = c->level, at = 0, I0 = 0, J0 = 0; /* the cell at index at (0: none yet) */
#ifdef RETRO_COUNT_SAMPLES
    const int lmin = retro_skip_ideal >= 0 ? retro_skip_ideal : RETRO_PYR_LMIN;
    retro_ybuffer_counts.probes++;
#else
    const int lmin = RETRO_PYR_LMIN;
#endif
    while (n < n_end) {
#ifdef RETRO_COUNT_SAMPLES
        retro_ybuffer_counts.windows++;
#endif
        const int B = 1 << L;
        int len = 1 + (int)((float)(B - 1) * c->inv_r); /* distances: an estimate */
        if (dist && n + 1 < n_end) /* in indices, by the step at n */
            len = 1 + (len - 1) / (dist[n + 1] - dist[n]);
        const int n1 = n_end - 1 - n < len - 1 ? n_end - 1 : n + len - 1;
        const int d = dist ? dist[n] : n, d1 = dist ? dist[n1] : n1;
        if (at != n) { /* a finer level starts where the coarser one did */
            const float f0 = (float)d;
            I0 = retro_floor_nn(bilinear ? x0 + f0 * rx - 0.5f : x0 + f0 * rx);
            J0 = retro_floor_nn(bilinear ? y0 + f0 * ry - 0.5f : y0 + f0 * ry);
            at = n;
        }
        const float f1 = (float)d1;
        const int I1 = retro_floor_nn(bilinear ? x0 + f1 * rx - 0.5f : x0 + f1 * rx);
        const int J1 = retro_floor_nn(bilinear ? y0 + f1 * ry - 0.5f : y0 + f1 * ry);
        const int Imin = I0 < I1 ? I0 : I1, Jmin = J0 < J1 ? J0 : J1;
        /* bilinear reads the cells floor(q - 1/2) and one more on each axis */
        const int wi = (I0 < I1 ? I1 - I0 : I0 - I1) + bilinear, wj = (J0 < J1 ? J1 - J0 : J0 - J1) + bilinear;
        if (wi <= B && wj <= B) {
            const int bi = retro_skip_wrap(Imin, S, pow2) >> L, bj = retro_skip_wrap(Jmin, S, pow2) >> L;
#ifdef RETRO_COUNT_SAMPLES
            /* levels under RETRO_PYR_LMIN have no windows, and their boxes are at most 2 wide */
            const int small = wi <= RETRO_IDEAL_BOX && wj <= RETRO_IDEAL_BOX;
            const int ideal = retro_skip_ideal >= 0 && small;
            const int own = ideal || (retro_skip_window == RETRO_WINDOW_OWN_BOX && small);
            const int unaligned = retro_skip_ideal < 0 && retro_skip_window == RETRO_WINDOW_UNALIGNED &&
                                  B <= RETRO_IDEAL_BOX && wi < B && wj < B;
            const int M = own         ? retro_skip_box_max(p, S, Imin, Jmin, wi, wj)
                          : unaligned ? retro_skip_box_max(p, S, Imin, Jmin, B - 1, B - 1)
                                      : p->win[L][(size_t)bj * (size_t)p->n[L] + (size_t)bi];
#else
            const int M = p->win[L][(size_t)bj * (size_t)p->n[L] + (size_t)bi];
#endif
            float fdh;
            if (bilinear) /* the sample's own dh of a height above any its rounding reaches */
                fdh = retro_bilinear_dh((float)M + RETRO_BILINEAR_OVER, height);
            else
                fdh = (float)((int64_t)M - height);
            const float vf = f->kd[fdh >= 0.0f ? d : d1] * fdh + half_h;
#ifdef RETRO_COUNT_SAMPLES
            const int kind = ideal ? retro_skip_ideal_kind : RETRO_IDEAL_MAX;
            const int hidden =
                !(vf >= need) ||
                (kind == RETRO_IDEAL_PLANE && !bilinear &&
                 retro_skip_plane_hides(p, f, Imin, Jmin, wi, wj, rx, ry, d, d1, need)) ||
                (kind == RETRO_IDEAL_ORACLE && retro_skip_oracle_hides(f, rx, ry, n, n1, dist, bilinear, y));
#else
            const int hidden = !(vf >= need);
#endif
            if (hidden) {
                n = n1 + 1;
                if (L < lmax)
                    L++;
                continue;
            }
        }
        if (L <= lmin)
            break;
        L--;
    }
    c->level = L;
    return n;
}

/* The first distance in [d, d_end) whose sample in this column may rise above y (mode
 * exact); see retro_skip_run. */
static inline __attribute__((always_inline, unused)) int
retro_skip_column(const retro_pyramid *p, const retro_frame *f, retro_skip_col *c, int d, int d_end, int y,
                  const int pow2, const int bilinear)
{
    return retro_skip_run(p, f, c, d, d_end, y, pow2, bilinear, NULL);
}


#endif
