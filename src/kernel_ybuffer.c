/* ybuffer: front to back, one column at a time, with the column's filled height (the
 * y-buffer) in a register. A sample paints only the rows above what nearer samples already
 * covered, and the rest of the column above the last sample is sky, so every pixel of out is
 * written exactly once and no sky pre-fill is needed.
 *
 * Early exit: a column stops at distance d once its y-buffer reaches vcap[d], the highest row
 * any sample at distance >= d could reach. That bound is exact because the projected row is
 * monotone in the map height: k_d > 0, so h -> (float)(h - height) -> k_d*dh + H/2 -> floor
 * and clamp are each non-decreasing (rounding to nearest is monotone), and no sample is
 * higher than the map's maximum. A full column (y-buffer = H >= vcap) stops by the same test.
 */
#include "kernels.h"
#include "retro_internal.h"
#include "retro_scene.h"

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

static void exact_column(const retro_frame *f, int u)
{
    const float rx = f->rx[u], ry = f->ry[u], x0 = f->x0, y0 = f->y0, half_h = f->half_h;
    const int S = f->S, W = f->W, H = f->H, D = f->D;
    const int64_t height = f->height;
    const uint8_t *hm = f->height_map;
    const uint32_t *cm = f->color_map;
    const float *kd = f->kd;
    const int *vcap = f->vcap;
    uint32_t *out = f->out;
    int y = 0;
    for (int d = 1; d < D && y < vcap[d]; d++) {
        float qx = x0 + (float)d * rx;
        float qy = y0 + (float)d * ry;
        size_t idx = (size_t)retro_cell(qy, S) * (size_t)S + (size_t)retro_cell(qx, S);
        int v = retro_exact_row(kd[d], half_h, H, hm[idx] - height);
        if (v > y)
            y = span(out, W, H, u, y, v, cm[idx]);
    }
    span(out, W, H, u, y, H, f->sky);
}

/* Modes truth, fixed and lod: the same walk over the shared sample arithmetic. They are
 * for showing what accuracy costs, so clarity wins over the last cycle here; `mode` is a
 * constant in each caller, so the switch folds away. */
static inline void variant_column(const retro_frame *f, int u, retro_mode mode)
{
    const int W = f->W, H = f->H, n_end = mode == RETRO_MODE_LOD ? f->ndist : f->D;
    const int64_t height = f->height;
    const uint8_t *hm = f->height_map;
    const int *vcap = f->vcap;
    uint32_t *out = f->out;
    int y = 0;
    for (int n = 1; n < n_end && y < vcap[n]; n++) {
        size_t idx;
        int v;
        if (mode == RETRO_MODE_TRUTH) {
            idx = retro_truth_sample(f, u, n);
            v = retro_truth_row(f->kdd[n], 0.5 * (double)H, H, hm[idx] - height);
        } else if (mode == RETRO_MODE_FIXED) {
            idx = retro_fixed_sample(f, u, n);
            v = retro_fixed_row(f->kd_fx[n], f->half_h_fx, H, hm[idx] - height);
        } else {
            int d = f->dist[n];
            idx = retro_exact_sample(f, u, d);
            v = retro_exact_row(f->kd[d], f->half_h, H, hm[idx] - height);
        }
        if (v > y)
            y = span(out, W, H, u, y, v, f->color_map[idx]);
    }
    span(out, W, H, u, y, H, f->sky);
}

/* Modes exact and lod with per-sample effects. Each effect is a compile-time constant in each
 * instantiation below, so the code of an effect a frame does not call for is not in the loop
 * that renders it, and the plain path (exact_column) carries no effect code at all. */
static inline __attribute__((always_inline)) void effect_column(const retro_frame *f, int u, const int lod,
                                                                const int fog, const int bilinear)
{
    const int W = f->W, H = f->H, n_end = lod ? f->ndist : f->D;
    const float rx = f->rx[u], ry = f->ry[u], x0 = f->x0, y0 = f->y0, half_h = f->half_h;
    const int64_t height = f->height;
    const int *vcap = f->vcap;
    uint32_t *out = f->out;
    int y = 0;
    for (int n = 1; n < n_end && y < vcap[n]; n++) {
        const int d = lod ? f->dist[n] : n;
        const float qx = x0 + (float)d * rx, qy = y0 + (float)d * ry;
        uint32_t color;
        int v;
        if (bilinear) {
            retro_bilerp b;
            float hf = retro_bilinear_height(f, qx, qy, &b);
            v = retro_exact_row_f(f->kd[d], half_h, H, retro_bilinear_dh(hf, height));
            if (v <= y)
                continue;
            color = retro_bilinear_color(f, &b);
        } else {
            size_t idx = (size_t)retro_cell(qy, f->S) * (size_t)f->S + (size_t)retro_cell(qx, f->S);
            v = retro_exact_row(f->kd[d], half_h, H, f->height_map[idx] - height);
            if (v <= y)
                continue;
            color = f->color_map[idx];
        }
        if (fog)
            color = retro_fog(color, f->sky, f->fog[d]);
        y = span(out, W, H, u, y, v, color);
    }
    span(out, W, H, u, y, H, f->sky);
}

typedef void (*effect_column_fn)(const retro_frame *f, int u);
#define EFFECT_COLUMN(name, lod, fog, bilinear)                                                    \
    static void name(const retro_frame *f, int u) { effect_column(f, u, lod, fog, bilinear); }
EFFECT_COLUMN(fx_fog, 0, 1, 0)
EFFECT_COLUMN(fx_bilinear, 0, 0, 1)
EFFECT_COLUMN(fx_fog_bilinear, 0, 1, 1)
EFFECT_COLUMN(fx_lod_fog, 1, 1, 0)
EFFECT_COLUMN(fx_lod_bilinear, 1, 0, 1)
EFFECT_COLUMN(fx_lod_fog_bilinear, 1, 1, 1)

/* The instantiation for a frame's per-sample effects (none: NULL, the plain paths). */
static effect_column_fn effect_column_for(const retro_frame *f)
{
    static const effect_column_fn table[2][4] = {
        {NULL, fx_fog, fx_bilinear, fx_fog_bilinear},
        {NULL, fx_lod_fog, fx_lod_bilinear, fx_lod_fog_bilinear},
    };
    int which = ((f->fx & RETRO_FX_FOG) ? 1 : 0) | ((f->fx & RETRO_FX_BILINEAR) ? 2 : 0);
    return table[f->mode == RETRO_MODE_LOD][which];
}

/* Mode course accumulates each line's position column by column (qx += sx after every
 * sample), so the column-major walk keeps one accumulator per distance and advances all of
 * them after each column, including those an early exit skipped, reproducing the row-major
 * sequence of additions exactly. */
static void course_column(const retro_frame *f, float *qx, float *qy, int u)
{
    const int S = f->S, W = f->W, H = f->H, D = f->D, ch2 = f->ch2;
    const float k = (float)(S - 1), inv_k = 1.0f / k, cw2 = f->cw2;
    const int64_t height = f->height;
    const uint8_t *hm = f->height_map;
    const uint32_t *cm = f->color_map;
    const float *sx = f->sx, *sy = f->sy;
    const int *vcap = f->vcap;
    uint32_t *out = f->out;
    int y = 0, d = 1;
    for (; d < D && y < vcap[d]; d++) {
        size_t idx = (size_t)retro_course_cell_fast(qy[d], k, inv_k) * (size_t)S +
                     (size_t)retro_course_cell_fast(qx[d], k, inv_k);
        int v = retro_course_row(cw2, ch2, H, hm[idx] - height, d);
        if (v > y)
            y = span(out, W, H, u, y, v, cm[idx]);
        qx[d] += sx[d];
        qy[d] += sy[d];
    }
    for (; d < D; d++) {
        qx[d] += sx[d];
        qy[d] += sy[d];
    }
    span(out, W, H, u, y, H, f->sky);
}

void retro_strip_ybuffer(const retro_frame *f, float *qx, float *qy, int u0, int u1)
{
    effect_column_fn fx = f->fx ? effect_column_for(f) : NULL;
    if (fx) {
        for (int u = u0; u < u1; u++)
            fx(f, u);
        return;
    }
    for (int u = u0; u < u1; u++) {
        switch (f->mode) {
        case RETRO_MODE_EXACT: exact_column(f, u); break;
        case RETRO_MODE_COURSE: course_column(f, qx, qy, u); break;
        case RETRO_MODE_TRUTH: variant_column(f, u, RETRO_MODE_TRUTH); break;
        case RETRO_MODE_FIXED: variant_column(f, u, RETRO_MODE_FIXED); break;
        default: variant_column(f, u, RETRO_MODE_LOD); break;
        }
    }
}

void retro_kernel_ybuffer(const retro_frame *f, retro_ctx *rc)
{
    retro_course_start(f, rc->qx, rc->qy);
    retro_strip_ybuffer(f, rc->qx, rc->qy, 0, f->W);
}
