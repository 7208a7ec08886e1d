/* naive: the specification's painter, back to front. The reference every other kernel is
 * checked against, so it is written to be obviously correct rather than fast: each sample is
 * computed straight from the formulas and painted as a line from row 1 up to its row v, and
 * nearer samples, painted later, cover farther ones. */
#include "kernels.h"
#include "retro_internal.h"
#include "retro_scene.h"

static void fill_sky(const retro_frame *f)
{
    size_t n = (size_t)f->W * (size_t)f->H;
    for (size_t i = 0; i < n; i++)
        RETRO_PUT(f->out, i, f->sky);
}

static void paint(const retro_frame *f, int u, int v, uint32_t color)
{
    for (int r = 1; r <= v; r++)
        RETRO_PUT(f->out, retro_pixel(f->W, f->H, u, r), color);
}

/* Row v and colour of sample (u, d) in modes exact and lod, with the per-sample effects. */
static int sample_exact(const retro_frame *f, int u, int d, uint32_t *color)
{
    int v;
    if (f->fx & RETRO_FX_BILINEAR) {
        retro_bilerp b;
        float qx = f->x0 + (float)d * f->rx[u], qy = f->y0 + (float)d * f->ry[u];
        float hf = retro_bilinear_height(f, qx, qy, &b);
        v = retro_exact_row_f(f->kd[d], f->half_h, f->H, retro_bilinear_dh(hf, f->height));
        *color = retro_bilinear_color(f, &b);
    } else {
        size_t idx = retro_exact_sample(f, u, d);
        v = retro_exact_row(f->kd[d], f->half_h, f->H, f->height_map[idx] - f->height);
        *color = f->color_map[idx];
    }
    if (f->fx & RETRO_FX_FOG)
        *color = retro_fog(*color, f->sky, f->fog[d]);
    return v;
}

/* Row v and colour of sample (u, d), u 0-based, in every mode but course. */
static int sample(const retro_frame *f, int u, int d, uint32_t *color)
{
    size_t idx;
    int v;
    switch (f->mode) {
    case RETRO_MODE_TRUTH:
        idx = retro_truth_sample(f, u, d);
        v = retro_truth_row(f->kdd[d], 0.5 * (double)f->H, f->H, f->height_map[idx] - f->height);
        break;
    case RETRO_MODE_FIXED:
        idx = retro_fixed_sample(f, u, d);
        v = retro_fixed_row(f->kd_q[d], f->half_h_q, f->H, f->height_map[idx] - f->height);
        break;
    default:
        return sample_exact(f, u, d, color);
    }
    *color = f->color_map[idx];
    return v;
}

/* Modes exact, truth, fixed: every d from D-1 down to 1; mode lod: its distances, farthest
 * first. */
static void direct(const retro_frame *f)
{
    int lod = f->mode == RETRO_MODE_LOD;
    for (int n = (lod ? f->ndist : f->D) - 1; n >= 1; n--) {
        int d = lod ? f->dist[n] : n;
        for (int u = 1; u <= f->W; u++) {
            uint32_t color;
            int v = sample(f, u - 1, d, &color);
            paint(f, u, v, color);
        }
    }
}

static void course(const retro_frame *f)
{
    for (int d = f->D - 1; d >= 1; d--) {
        float qx = f->lx[d], qy = f->ly[d];
        for (int u = 1; u <= f->W; u++) {
            size_t idx = (size_t)retro_course_cell(qy, f->S) * (size_t)f->S +
                         (size_t)retro_course_cell(qx, f->S);
            int v = retro_course_row(f->cw2, f->ch2, f->H, f->height_map[idx] - f->height, d);
            paint(f, u, v, f->color_map[idx]);
            qx += f->sx[d];
            qy += f->sy[d];
        }
    }
}

void retro_kernel_naive(const void *frame, retro_ctx *rc)
{
    const retro_frame *f = frame;
    (void)rc;
    fill_sky(f);
    if (f->mode == RETRO_MODE_COURSE)
        course(f);
    else
        direct(f);
}
