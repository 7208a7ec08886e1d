/* naive: the specification's painter, back to front. The reference every other kernel is
 * checked against, so it is written to be obviously correct rather than fast: each sample is
 * computed straight from the formulas and painted as a line from row 1 up to its row v, and
 * nearer samples, painted later, cover farther ones. */
#include "kernels.h"
#include "retro_internal.h"

static void fill_sky(const retro_frame *f)
{
    size_t n = (size_t)f->W * (size_t)f->H;
    for (size_t i = 0; i < n; i++)
        RETRO_PUT(f->out, i, f->sky);
}

static void paint(const retro_frame *f, int u, int v, size_t idx)
{
    for (int r = 1; r <= v; r++)
        RETRO_PUT(f->out, retro_pixel(f->W, f->H, u, r), f->color_map[idx]);
}

static void exact(const retro_frame *f)
{
    for (int d = f->D - 1; d >= 1; d--) {
        for (int u = 1; u <= f->W; u++) {
            float qx = f->x0 + (float)d * f->rx[u - 1];
            float qy = f->y0 + (float)d * f->ry[u - 1];
            size_t idx = (size_t)retro_cell(qy, f->S) * (size_t)f->S + (size_t)retro_cell(qx, f->S);
            int v = retro_exact_row(f->kd[d], f->half_h, f->H, f->height_map[idx] - f->height);
            paint(f, u, v, idx);
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
            paint(f, u, v, idx);
            qx += f->sx[d];
            qy += f->sy[d];
        }
    }
}

void retro_kernel_naive(const retro_frame *f, retro_ctx *rc)
{
    (void)rc;
    fill_sky(f);
    if (f->mode == RETRO_MODE_COURSE)
        course(f);
    else
        exact(f);
}
