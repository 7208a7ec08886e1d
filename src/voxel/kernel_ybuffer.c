/* ybuffer: front to back with a y-buffer per column: the rows already covered by nearer
 * samples. A sample paints only the rows above its column's y-buffer, and the rest of each
 * column above its last sample is sky, so every pixel of out is written exactly once and no
 * sky pre-fill is needed.
 *
 * Traversal: chunks of up to CHUNK (256) adjacent columns, distance-outer inside a chunk. At one
 * distance the chunk's samples lie next to each other on the map, and their spans land on
 * the same rows of out, so reads and writes stay within a few cache lines and pages, where
 * walking one column's ray to the end strides across a row of the map per sample. With the
 * power-of-two mask and the branch-free floor this measured faster than the column walk on
 * the three default scenes. Either order gives the same bytes: each column still sees its
 * samples nearest first.
 *
 * Early exit: a column stops at the n-th distance once its y-buffer reaches vcap[n], the
 * highest row any sample from there on can reach. That bound is exact because the projected
 * row is monotone in the map height: k_d > 0, so h -> (float)(h - height) -> k_d*dh + H/2 ->
 * floor and clamp are each non-decreasing (rounding to nearest is monotone), and no sample is
 * higher than the map's maximum. A full column (y-buffer = H >= vcap) stops by the same test;
 * the chunk stops when all its columns have.
 *
 * Each mode and effect set is one instantiation of chunk() with its choices as compile-time
 * constants, so a frame runs a loop with exactly the work it calls for: the plain exact loop
 * carries no effect code at all.
 *
 * Occlusion skipping (docs/SKIPPING.md): in modes exact and lod, with any per-sample effects, a
 * frame that has a pyramid (f->pyr) runs columns_skip() instead, where each column asks retro_skip_run
 * (src/voxel/hmax_pyramid.h, where the bound is proved) for the first distance that may still paint
 * before evaluating samples; modes course, truth and fixed walk their columns the same way with
 * probes of their own (skip_course.h, skip_wide.h). Built with RETRO_COUNT_SAMPLES, the file
 * counts samples evaluated and painting into retro_ybuffer_counts, and per column into
 * retro_ybuffer_columns when set (ybuffer_columns.h; the library holds that build too, under
 * other names).
 */
#include "kernels.h"
#include "retro_internal.h"
#include "retro_scene.h"
#ifndef RETRO_SUBMISSION
#include "hmax_pyramid.h"
#include "skip_course.h"
#include "skip_wide.h"
#endif

#ifdef RETRO_COUNT_SAMPLES
#include "cone_map.h"
#include "ybuffer_columns.h"
retro_sample_counts retro_ybuffer_counts;
retro_column_counts *retro_ybuffer_columns;
int retro_skip_ideal = -1;
int retro_skip_ideal_kind = RETRO_IDEAL_MAX;
int retro_skip_window = RETRO_WINDOW_BLOCKS, retro_skip_every = 0;
const retro_cone_map *retro_skip_cone;
int retro_skip_cone_pyramid;
#define IDEAL_ONE_BY_ONE (retro_skip_ideal >= 0 || retro_skip_every)
/* Every use has the sample's column in u. */
#define COUNT_EVAL()                                                                               \
    (retro_ybuffer_counts.evaluated++, retro_ybuffer_columns ? (void)retro_ybuffer_columns[u].evaluated++ : (void)0)
#define COUNT_PAINT()                                                                              \
    (retro_ybuffer_counts.painting++, retro_ybuffer_columns ? (void)retro_ybuffer_columns[u].painting++ : (void)0)
#else
#define COUNT_EVAL() ((void)0)
#define COUNT_PAINT() ((void)0)
#define IDEAL_ONE_BY_ONE 0
#endif

enum { CHUNK = 256 };

/* What one instantiation of chunk() computes. */
enum { KIND_EXACT, KIND_EXACT_POW2, KIND_LOD, KIND_TRUTH, KIND_FIXED, KIND_COURSE };

/* Paints rows y+1..v of column u (0-based) of a W-wide, H-high frame; returns the new y-buffer.
 * Frame fields are passed as values: a pixel store may alias an int field of the frame, so
 * the compiler would reload every field after every store. */
static inline int span(uint32_t *out, int W, int H, int u, int y, int v, uint32_t color)
{
    ptrdiff_t i = (ptrdiff_t)(H - y - 1) * W + u;
    for (int r = y + 1; r <= v; r++, i -= W)
        RETRO_PUT(out, (size_t)i, color);
    return v;
}

/* Row v of sample (u, d) and, when it rises above y, its colour; the per-sample effects of
 * docs/EFFECTS.md when asked. q is mode course's accumulated position of this column. */
static inline __attribute__((always_inline)) int sample(const retro_frame *f, const int kind, const int fog,
                                                        const int bilinear, int u, int d, float fd, float kd,
                                                        float cqx, float cqy, int y, uint32_t *color)
{
    const int S = f->S, H = f->H;
    size_t idx;
    int v;
    if (kind == KIND_COURSE) {
        const float k = (float)(S - 1), inv_k = 1.0f / k;
        idx = (size_t)retro_course_cell_fast(cqy, k, inv_k) * (size_t)S + (size_t)retro_course_cell_fast(cqx, k, inv_k);
        v = retro_course_row(f->cw2, f->ch2, H, f->height_map[idx] - f->height, d);
    } else if (kind == KIND_TRUTH) {
        idx = retro_truth_sample(f, u, d);
        v = retro_truth_row(f->kdd[d], 0.5 * (double)H, H, f->height_map[idx] - f->height);
    } else if (kind == KIND_FIXED) {
        idx = retro_fixed_sample(f, u, d);
        v = retro_fixed_row(f->kd_q[d], f->half_h_q, H, f->height_map[idx] - f->height);
    } else {
        const float qx = f->x0 + fd * f->rx[u], qy = f->y0 + fd * f->ry[u];
        if (bilinear) {
            retro_bilerp b;
            float hf = retro_bilinear_height(f, qx, qy, &b);
            v = retro_exact_row_f(kd, f->half_h, H, retro_bilinear_dh(hf, f->height));
            if (v > y)
                *color = fog ? retro_fog(retro_bilinear_color(f, &b), f->sky, f->fog[d]) : retro_bilinear_color(f, &b);
            return v;
        }
        if (kind == KIND_EXACT_POW2) {
            const int mask = S - 1;
            idx = (size_t)(retro_floor(qy) & mask) * (size_t)S + (size_t)(retro_floor(qx) & mask);
        } else {
            idx = (size_t)retro_cell(qy, S) * (size_t)S + (size_t)retro_cell(qx, S);
        }
        /* retro_exact_row's vf. For y < H, v > y exactly when vf >= y + 1 ((float)(y + 1) is
         * exact, and the floor and the clamp are monotone), so most samples, which paint
         * nothing, stop at one compare. */
        const float vf = kd * (float)(f->height_map[idx] - f->height) + f->half_h;
        if (!(vf >= (float)(y + 1)))
            return y;
        v = vf >= (float)H ? H : (int)vf;
    }
    if (v > y)
        *color = fog ? retro_fog(f->color_map[idx], f->sky, f->fog[d]) : f->color_map[idx];
    return v;
}

/* Columns [c0, c1), c1 - c0 <= CHUNK. Mode course: qx[d], qy[d] hold column c0's positions
 * on entry and column c1's on return, every accumulator advanced by every column in order,
 * sampled or not. */
static inline __attribute__((always_inline)) void chunk(const retro_frame *frame, float *qx, float *qy, int c0,
                                                        int c1, const int kind, const int fog, const int bilinear)
{
    /* A local copy whose address never escapes: no pixel store can alias it, so its fields
     * stay in registers instead of being reloaded after every store. */
    const retro_frame copy = *frame, *f = &copy;
    const int W = f->W, H = f->H, n_end = kind == KIND_LOD ? f->ndist : f->D;
    const int *vcap = f->vcap;
    uint32_t *out = f->out;
    int ybuf[CHUNK];
    for (int u = c0; u < c1; u++)
        ybuf[u - c0] = 0;
    int lo = c0, hi = c1; /* the columns still open lie in [lo, hi) */
    int n = 1;
    for (; n < n_end; n++) {
        const int cap = vcap[n];
        while (lo < hi && ybuf[lo - c0] >= cap)
            lo++;
        while (hi > lo && ybuf[hi - 1 - c0] >= cap)
            hi--;
        if (lo >= hi)
            break;
        const int d = kind == KIND_LOD ? f->dist[n] : n;
        if (kind == KIND_COURSE) {
            float x = qx[d], y = qy[d];
            const float sx = f->sx[d], sy = f->sy[d];
            for (int u = c0; u < c1; u++, x += sx, y += sy) {
                int *yb = &ybuf[u - c0];
                if (u < lo || u >= hi || *yb >= cap)
                    continue;
                uint32_t color;
                COUNT_EVAL();
                int v = sample(f, kind, 0, 0, u, d, 0, 0, x, y, *yb, &color);
                if (v > *yb) {
                    COUNT_PAINT();
                    *yb = span(out, W, H, u, *yb, v, color);
                }
            }
            qx[d] = x;
            qy[d] = y;
            continue;
        }
        /* Per distance, not per sample: the loop below has registers to spare for them. */
        const float fd = (float)d, kd = kind == KIND_TRUTH || kind == KIND_FIXED ? 0 : f->kd[d];
        if (kind == KIND_EXACT_POW2 && !fog && !bilinear) {
            /* Two passes: every open column's vf (retro_exact_row's, the same operations) with no
             * branch, so the map loads overlap instead of waiting behind a mispredicted paint
             * branch, then the few that rise above their y-buffer paint: faster most where no
             * column stops early (alpine), less where many do (islands). The cell index
             * is j << log2 S | i: S is a power of two here. */
            const int mask = f->S - 1, shift = __builtin_ctz((unsigned)f->S);
            const float x0 = f->x0, y0 = f->y0, half_h = f->half_h;
            const int64_t height = f->height;
            const uint8_t *hm = f->height_map;
            float vfs[CHUNK];
            uint32_t cell[CHUNK];
            for (int u = lo; u < hi; u++) {
                COUNT_EVAL();
                const float px = x0 + fd * f->rx[u], py = y0 + fd * f->ry[u];
                const uint32_t idx = (uint32_t)(retro_floor(py) & mask) << shift | (uint32_t)(retro_floor(px) & mask);
                cell[u - c0] = idx;
                vfs[u - c0] = kd * (float)(hm[idx] - height) + half_h;
            }
            for (int u = lo; u < hi; u++) {
                int *yb = &ybuf[u - c0];
                const float vf = vfs[u - c0];
                if (*yb >= cap || !(vf >= (float)(*yb + 1)))
                    continue;
                int v = vf >= (float)H ? H : (int)vf;
                COUNT_PAINT();
                *yb = span(out, W, H, u, *yb, v, f->color_map[cell[u - c0]]);
            }
            continue;
        }
        for (int u = lo; u < hi; u++) {
            int *yb = &ybuf[u - c0];
            if (*yb >= cap)
                continue;
            uint32_t color;
            COUNT_EVAL();
            int v = sample(f, kind, fog, bilinear, u, d, fd, kd, 0, 0, *yb, &color);
            if (v > *yb) {
                COUNT_PAINT();
                *yb = span(out, W, H, u, *yb, v, color);
            }
        }
    }
    if (kind == KIND_COURSE) /* distances past the early exit still step over the chunk */
        for (int d = n; d < f->D; d++)
            for (int u = c0; u < c1; u++) {
                qx[d] += f->sx[d];
                qy[d] += f->sy[d];
            }
    for (int u = c0; u < c1; u++)
        span(out, W, H, u, ybuf[u - c0], H, f->sky);
}


#ifndef RETRO_SUBMISSION
/* Whether every position of the samples at distances d0..d1 is non-negative: positions are
 * monotone in the distance (hmax_pyramid.h, retro_skip_run, point 1), so their smallest is at an
 * end. Their floors are then the truncating conversions alone, and the cells their remainders
 * without the sign's correction: the same integers as retro_floor and retro_cell give, at less
 * cost than their conversion back and compare (docs/SKIPPING.md, "The traversal"). chunk() keeps
 * retro_floor: its distance-outer order measured no faster with a cheaper floor. */
static inline int batch_nonneg(float x0, float y0, float rx, float ry, int d0, int d1)
{
    const float f0 = (float)d0, f1 = (float)d1;
    return x0 + f0 * rx >= 0.0f && x0 + f1 * rx >= 0.0f && y0 + f0 * ry >= 0.0f && y0 + f1 * ry >= 0.0f;
}

/* A batch's cells and rows (columns_skip): cnt samples from index n, their cells in cell[] and
 * their rows' floats in vfs[]. nonneg: batch_nonneg holds, so (int)q is floor(q). */
static inline __attribute__((always_inline)) void batch_cells(const retro_frame *f, const int kind, const int nonneg,
                                                              float x0, float y0, float rx, float ry, const int *dist,
                                                              int n, int cnt, int64_t height, float half_h,
                                                              uint32_t *cell, float *vfs)
{
    const int S = f->S;
    const uint8_t *hm = f->height_map;
    for (int t = 0; t < cnt; t++) {
        const int d = dist ? dist[n + t] : n + t;
        const float fd = (float)d, qx = x0 + fd * rx, qy = y0 + fd * ry;
        uint32_t idx;
        if (kind == KIND_EXACT_POW2) {
            const int I = nonneg ? (int)qx : retro_floor(qx), J = nonneg ? (int)qy : retro_floor(qy);
            idx = (uint32_t)(J & (S - 1)) * (uint32_t)S + (uint32_t)(I & (S - 1));
        } else if (nonneg)
            idx = (uint32_t)((int)qy % S) * (uint32_t)S + (uint32_t)((int)qx % S);
        else
            idx = (uint32_t)retro_cell(qy, S) * (uint32_t)S + (uint32_t)retro_cell(qx, S);
        cell[t] = idx;
        vfs[t] = f->kd[d] * (float)(hm[idx] - height) + half_h;
    }
}

#ifdef RETRO_COUNT_SAMPLES
/* The cone steps' study (cone_map.h, docs/studies/SKIPPING_LIMITS.md "Cone steps"): columns
 * [c0, c1) of mode exact, plain samples, each walked nearest first; after every sample it
 * evaluates, the column jumps over the distances retro_cone_step proves hidden. With
 * retro_skip_cone_pyramid, the pyramid is probed before every sample too (retro_skip_run, one
 * sample at a time), and the walk takes the longer of the two jumps. Exact, so the frame is
 * naive's. */
static void columns_cone(const retro_frame *f, int c0, int c1, const int kind, const int fog)
{
    const int W = f->W, H = f->H;
    const int *vcap = f->vcap;
    const int n_end = f->D;
    const retro_cone_map *m = retro_skip_cone;
    uint32_t *out = f->out;
    for (int u = c0; u < c1; u++) {
        retro_skip_col col;
        retro_skip_col_init(&col, f, u);
        const float rx = col.rx, ry = col.ry;
        const int sigma = retro_cone_sector(m, rx, ry);
        int y = 0, n = 1;
        while (n < n_end && y < vcap[n]) {
            if (retro_skip_cone_pyramid) {
                const int e = retro_skip_run(f->pyr, f, &col, n, n_end, y, kind == KIND_EXACT_POW2, 0, NULL);
                if (e > n) {
                    n = e;
                    continue;
                }
            }
            const size_t idx = retro_exact_sample(f, u, n);
            const int h0 = f->height_map[idx];
            const float vf = f->kd[n] * (float)(h0 - f->height) + f->half_h;
            COUNT_EVAL();
            if (vf >= (float)(y + 1)) {
                const int v = vf >= (float)H ? H : (int)vf;
                const uint32_t c = f->color_map[idx];
                COUNT_PAINT();
                y = span(out, W, H, u, y, v, fog ? retro_fog(c, f->sky, f->fog[n]) : c);
                if (y >= H)
                    break;
            }
            n += 1 + retro_cone_step(m, f, sigma, rx, ry, idx, h0, n, n_end, y);
        }
        span(out, W, H, u, y, H, f->sky);
    }
}
#endif

/* Columns [c0, c1) of mode exact or lod with skipping, each walked nearest first: the pyramid
 * is probed (retro_skip_run) at every sample the walk reaches, and where it cannot skip the
 * next RETRO_SKIP_NEAR samples are evaluated in two passes, their cells and vf first (sample()'s
 * operations, no branch on a map load, so the loads overlap), then the y-buffer pass over them
 * nearest first. Samples at or past the vcap exit may be evaluated in that batch but cannot
 * paint (their v <= vcap <= y). Walking a column keeps it free of the per-distance cost of the
 * columns that skip, which chunk() pays at every distance. Each column paints the same samples
 * in the same order as in chunk(), so the bytes are the same. The walk is over sample indices
 * n: the distance is n in mode exact and dist[n] in mode lod (kind KIND_LOD), as in chunk(). */
static inline __attribute__((always_inline)) void columns_skip(const retro_frame *frame, int c0, int c1,
                                                               const int kind, const int fog, const int bilinear)
{
    const retro_frame copy = *frame, *f = &copy;
    const int W = f->W, H = f->H;
    const int *vcap = f->vcap, *dist = kind == KIND_LOD ? f->dist : NULL;
    const int n_end = kind == KIND_LOD ? f->ndist : f->D;
    const float x0 = f->x0, y0 = f->y0, half_h = f->half_h;
    const int64_t height = f->height;
    uint32_t *out = f->out;
#ifdef RETRO_COUNT_SAMPLES
    if (retro_skip_cone && kind != KIND_LOD && !bilinear && retro_cone_applies(retro_skip_cone, f)) {
        columns_cone(f, c0, c1, kind, fog);
        return;
    }
#endif
    for (int u = c0; u < c1; u++) {
        retro_skip_col col;
        retro_skip_col_init(&col, f, u);
        const float rx = col.rx, ry = col.ry;
        int y = 0, n = 1, batch = RETRO_SKIP_NEAR;
        while (n < n_end && y < vcap[n]) {
            int e = retro_skip_run(f->pyr, f, &col, n, n_end, y, kind == KIND_EXACT_POW2, bilinear, dist);
            if (e > n) {
                n = e;
                batch = RETRO_SKIP_NEAR;
                continue;
            }
            const int cnt = IDEAL_ONE_BY_ONE ? 1 : n_end - n < batch ? n_end - n : batch;
            /* probes that keep failing (terrain that keeps rising) come less often */
            batch = batch < RETRO_SKIP_FAR ? 2 * batch : batch;
            if (bilinear) { /* four cells and a colour blend per sample: one pass */
                for (int t = 0; t < cnt && y < H; t++) {
                    const int d = dist ? dist[n + t] : n + t;
                    uint32_t color;
                    COUNT_EVAL();
                    int v = sample(f, kind, fog, 1, u, d, (float)d, f->kd[d], 0, 0, y, &color);
                    if (v > y) {
                        COUNT_PAINT();
                        y = span(out, W, H, u, y, v, color);
                    }
                }
                n += cnt;
                continue;
            }
            uint32_t cell[RETRO_SKIP_FAR];
            float vfs[RETRO_SKIP_FAR];
            if (batch_nonneg(x0, y0, rx, ry, dist ? dist[n] : n, dist ? dist[n + cnt - 1] : n + cnt - 1))
                batch_cells(f, kind, 1, x0, y0, rx, ry, dist, n, cnt, height, half_h, cell, vfs);
            else
                batch_cells(f, kind, 0, x0, y0, rx, ry, dist, n, cnt, height, half_h, cell, vfs);
            for (int t = 0; t < cnt; t++)
                COUNT_EVAL();
            for (int t = 0; t < cnt && y < H; t++) { /* a full column takes nothing more */
                if (!(vfs[t] >= (float)(y + 1)))
                    continue;
                const int v = vfs[t] >= (float)H ? H : (int)vfs[t];
                const uint32_t c = f->color_map[cell[t]];
                COUNT_PAINT();
                y = span(out, W, H, u, y, v, fog ? retro_fog(c, f->sky, f->fog[dist ? dist[n + t] : n + t]) : c);
            }
            n += cnt;
        }
        span(out, W, H, u, y, H, f->sky);
    }
}
#endif

#ifndef RETRO_SUBMISSION
/* Columns [c0, c1) of mode course with skipping (skip_course.h, where the bound is proved),
 * each walked nearest first over its accumulators qx[d], qy[d] as columns_skip() walks mode
 * exact's, then every accumulator advanced by the column, sampled or not, so the next column
 * reads the same positions as in chunk(). */
static void columns_skip_course(const retro_frame *frame, float *qx, float *qy, int c0, int c1)
{
    const retro_frame copy = *frame, *f = &copy;
    const int W = f->W, H = f->H, D = f->D;
    const int *vcap = f->vcap;
    const int lmin = retro_course_lmin(f->course_margin, 2);
    uint32_t *out = f->out;
    for (int u = c0; u < c1; u++) {
        retro_course_col col;
        retro_course_col_init(&col, f, qx, qy, lmin);
        int y = 0, d = 1, batch = RETRO_SKIP_NEAR;
        while (d < D && y < vcap[d]) {
            int e = retro_skip_course(f, &col, qx, qy, d, D, y);
            if (e > d) {
                d = e;
                batch = RETRO_SKIP_NEAR;
                continue;
            }
            const int end = D - d < batch ? D : d + batch;
            batch = batch < RETRO_SKIP_FAR ? 2 * batch : batch;
            for (; d < end && y < H; d++) {
                uint32_t color;
                COUNT_EVAL();
                int v = sample(f, KIND_COURSE, 0, 0, u, d, 0, 0, qx[d], qy[d], y, &color);
                if (v > y) {
                    COUNT_PAINT();
                    y = span(out, W, H, u, y, v, color);
                }
            }
            d = end;
        }
        span(out, W, H, u, y, H, f->sky);
        retro_course_advance(f, qx, qy, u, u + 1);
    }
}

/* Columns [c0, c1) of mode truth or fixed (kind) with skipping (skip_wide.h, where the bound is
 * proved), each walked nearest first as columns_skip() walks mode exact's: a batch's cells and
 * rows first (the mode's sample and row functions, as sample() calls them), so their integer
 * divisions overlap, then the y-buffer pass over them nearest first. Each column paints the
 * same samples in the same order as in chunk(), so the bytes are the same. On a power-of-two
 * map (pow2) the cell is the mode's floor masked by S - 1: in two's complement that is the
 * non-negative remainder floor mod S the mode's sample function takes with a division. */
static inline __attribute__((always_inline)) void columns_skip_wide(const retro_frame *frame, int c0, int c1,
                                                                    const int kind, const int pow2)
{
    const retro_frame copy = *frame, *f = &copy;
    const int W = f->W, H = f->H, D = f->D, S = f->S;
    const int *vcap = f->vcap;
    uint32_t *out = f->out;
    for (int u = c0; u < c1; u++) {
        retro_skip_col col;
        retro_skip_wide_init(&col, f, u);
        int y = 0, d = 1, batch = RETRO_SKIP_NEAR;
        while (d < D && y < vcap[d]) {
            const int next = retro_skip_run_wide(f->pyr, f, &col, u, d, D, y, kind == KIND_FIXED);
            if (next > d) {
                d = next;
                batch = RETRO_SKIP_NEAR;
                continue;
            }
            const int cnt = D - d < batch ? D - d : batch;
            batch = batch < RETRO_SKIP_FAR ? 2 * batch : batch;
            size_t cell[RETRO_SKIP_FAR];
            int rows[RETRO_SKIP_FAR];
            for (int t = 0; t < cnt; t++) {
                const int e = d + t;
                COUNT_EVAL();
                if (pow2) {
                    int I, J;
                    retro_skip_wide_floors(f, u, e, kind == KIND_FIXED, &I, &J);
                    cell[t] = (size_t)(J & (S - 1)) * (size_t)S + (size_t)(I & (S - 1));
                } else
                    cell[t] = kind == KIND_FIXED ? retro_fixed_sample(f, u, e) : retro_truth_sample(f, u, e);
                rows[t] = retro_skip_wide_row(f, e, f->height_map[cell[t]] - f->height, kind == KIND_FIXED);
            }
            for (int t = 0; t < cnt && y < H; t++) { /* a full column takes nothing more */
                if (rows[t] > y) {
                    COUNT_PAINT();
                    y = span(out, W, H, u, y, rows[t], f->color_map[cell[t]]);
                }
            }
            d += cnt;
        }
        span(out, W, H, u, y, H, f->sky);
    }
}

#define SKIP_WIDE_FN(name, kind)                                                                   \
    static void name(const retro_frame *f, float *qx, float *qy, int c0, int c1)                   \
    {                                                                                              \
        (void)qx;                                                                                  \
        (void)qy;                                                                                  \
        if (f->S & (f->S - 1))                                                                     \
            columns_skip_wide(f, c0, c1, kind, 0);                                                 \
        else                                                                                       \
            columns_skip_wide(f, c0, c1, kind, 1);                                                 \
    }
SKIP_WIDE_FN(skip_truth, KIND_TRUTH)
SKIP_WIDE_FN(skip_fixed, KIND_FIXED)
#endif

typedef void (*chunk_fn)(const retro_frame *f, float *qx, float *qy, int c0, int c1);
#define CHUNK_FN(name, kind, fog, bilinear)                                                        \
    static void name(const retro_frame *f, float *qx, float *qy, int c0, int c1)                   \
    {                                                                                              \
        chunk(f, qx, qy, c0, c1, kind, fog, bilinear);                                             \
    }
CHUNK_FN(exact_any, KIND_EXACT, 0, 0)
CHUNK_FN(exact_pow2, KIND_EXACT_POW2, 0, 0)
CHUNK_FN(lod_plain, KIND_LOD, 0, 0)
CHUNK_FN(truth, KIND_TRUTH, 0, 0)
CHUNK_FN(fixed, KIND_FIXED, 0, 0)
CHUNK_FN(course, KIND_COURSE, 0, 0)
#ifndef RETRO_SUBMISSION
#define SKIP_FN(name, kind, fog, bilinear)                                                         \
    static void name(const retro_frame *f, float *qx, float *qy, int c0, int c1)                   \
    {                                                                                              \
        (void)qx;                                                                                  \
        (void)qy;                                                                                  \
        columns_skip(f, c0, c1, kind, fog, bilinear);                                              \
    }
SKIP_FN(skip_any, KIND_EXACT, 0, 0)
SKIP_FN(skip_pow2, KIND_EXACT_POW2, 0, 0)
SKIP_FN(skip_lod, KIND_LOD, 0, 0)
#ifndef RETRO_NO_EFFECTS
SKIP_FN(skip_fog, KIND_EXACT, 1, 0)
SKIP_FN(skip_bilinear, KIND_EXACT, 0, 1)
SKIP_FN(skip_fog_bilinear, KIND_EXACT, 1, 1)
SKIP_FN(skip_lod_fog, KIND_LOD, 1, 0)
SKIP_FN(skip_lod_bilinear, KIND_LOD, 0, 1)
SKIP_FN(skip_lod_fog_bilinear, KIND_LOD, 1, 1)
#endif
#endif
#ifndef RETRO_NO_EFFECTS /* the benchmark builds it without, to show effect code costs nothing */
CHUNK_FN(exact_fog, KIND_EXACT, 1, 0)
CHUNK_FN(exact_bilinear, KIND_EXACT, 0, 1)
CHUNK_FN(exact_fog_bilinear, KIND_EXACT, 1, 1)
CHUNK_FN(lod_fog, KIND_LOD, 1, 0)
CHUNK_FN(lod_bilinear, KIND_LOD, 0, 1)
CHUNK_FN(lod_fog_bilinear, KIND_LOD, 1, 1)
#endif

/* The instantiation for a frame: its mode, map size class and per-sample effects. */
static chunk_fn chunk_for(const retro_frame *f)
{
#ifndef RETRO_SUBMISSION
    if (retro_skip_applies(f)) {
        const int lod = f->mode == RETRO_MODE_LOD;
#ifndef RETRO_NO_EFFECTS
        static const chunk_fn skip_fx[2][3] = {{skip_fog, skip_bilinear, skip_fog_bilinear},
                                               {skip_lod_fog, skip_lod_bilinear, skip_lod_fog_bilinear}};
        if (f->fx)
            return skip_fx[lod][((f->fx & RETRO_FX_FOG) ? 1 : 0) + ((f->fx & RETRO_FX_BILINEAR) ? 2 : 0) - 1];
#endif
        return lod ? skip_lod : (f->S & (f->S - 1)) ? skip_any : skip_pow2;
    }
#endif
#ifndef RETRO_NO_EFFECTS
    static const chunk_fn with_fx[2][3] = {
        {exact_fog, exact_bilinear, exact_fog_bilinear},
        {lod_fog, lod_bilinear, lod_fog_bilinear},
    };
    if (f->fx && (f->mode == RETRO_MODE_EXACT || f->mode == RETRO_MODE_LOD)) {
        int which = ((f->fx & RETRO_FX_FOG) ? 1 : 0) | ((f->fx & RETRO_FX_BILINEAR) ? 2 : 0);
        return with_fx[f->mode == RETRO_MODE_LOD][which - 1];
    }
#endif
    switch (f->mode) {
    case RETRO_MODE_COURSE:
#ifndef RETRO_SUBMISSION
        if (f->pyr)
            return columns_skip_course;
#endif
        return course;
#ifndef RETRO_SUBMISSION
    case RETRO_MODE_TRUTH: return retro_skip_wide_applies(f) ? skip_truth : truth;
    case RETRO_MODE_FIXED: return retro_skip_wide_applies(f) ? skip_fixed : fixed;
#else
    case RETRO_MODE_TRUTH: return truth;
    case RETRO_MODE_FIXED: return fixed;
#endif
    case RETRO_MODE_LOD: return lod_plain;
    default: return (f->S & (f->S - 1)) ? exact_any : exact_pow2;
    }
}

void retro_strip_ybuffer(const retro_frame *f, float *qx, float *qy, int u0, int u1)
{
    chunk_fn run = chunk_for(f);
    for (int c0 = u0; c0 < u1; c0 += CHUNK)
        run(f, qx, qy, c0, c0 + CHUNK < u1 ? c0 + CHUNK : u1);
}

void retro_kernel_ybuffer(const void *frame, retro_ctx *rc)
{
    const retro_frame *f = frame;
    retro_course_start(f, rc->qx, rc->qy);
    retro_strip_ybuffer(f, rc->qx, rc->qy, 0, f->W);
}
