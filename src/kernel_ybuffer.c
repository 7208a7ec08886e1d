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

/* Paints rows y+1..v of column u (0-based) and returns the new y-buffer. */
static inline int span(const retro_frame *f, int u, int y, int v, uint32_t color)
{
    ptrdiff_t i = (ptrdiff_t)(f->H - y - 1) * f->W + u;
    for (int r = y + 1; r <= v; r++, i -= f->W)
        RETRO_PUT(f->out, (size_t)i, color);
    return v;
}

static void exact_column(const retro_frame *f, int u)
{
    const float rx = f->rx[u], ry = f->ry[u];
    const int S = f->S;
    int y = 0;
    for (int d = 1; d < f->D && y < f->vcap[d]; d++) {
        float qx = f->x0 + (float)d * rx;
        float qy = f->y0 + (float)d * ry;
        size_t idx = (size_t)retro_cell(qy, S) * (size_t)S + (size_t)retro_cell(qx, S);
        int v = retro_exact_row(f->kd[d], f->half_h, f->H, f->height_map[idx] - f->height);
        if (v > y)
            y = span(f, u, y, v, f->color_map[idx]);
    }
    span(f, u, y, f->H, f->sky);
}

/* Mode course accumulates each line's position column by column (qx += sx after every
 * sample), so the column-major walk keeps one accumulator per distance and advances all of
 * them after each column, including those an early exit skipped, reproducing the row-major
 * sequence of additions exactly. */
static void course_column(const retro_frame *f, float *qx, float *qy, int u)
{
    const int S = f->S;
    int y = 0, d = 1;
    for (; d < f->D && y < f->vcap[d]; d++) {
        size_t idx = (size_t)retro_course_cell(qy[d], S) * (size_t)S +
                     (size_t)retro_course_cell(qx[d], S);
        int v = retro_course_row(f->cw2, f->ch2, f->H, f->height_map[idx] - f->height, d);
        if (v > y)
            y = span(f, u, y, v, f->color_map[idx]);
        qx[d] += f->sx[d];
        qy[d] += f->sy[d];
    }
    for (; d < f->D; d++) {
        qx[d] += f->sx[d];
        qy[d] += f->sy[d];
    }
    span(f, u, y, f->H, f->sky);
}

void retro_strip_ybuffer(const retro_frame *f, float *qx, float *qy, int u0, int u1)
{
    for (int u = u0; u < u1; u++) {
        if (f->mode == RETRO_MODE_EXACT)
            exact_column(f, u);
        else
            course_column(f, qx, qy, u);
    }
}

void retro_kernel_ybuffer(const retro_frame *f, retro_ctx *rc)
{
    retro_course_start(f, rc->qx, rc->qy);
    retro_strip_ybuffer(f, rc->qx, rc->qy, 0, f->W);
}
