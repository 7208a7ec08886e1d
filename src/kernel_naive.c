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

/* Row v of sample (u, d) and its cell, in every mode but course (u 0-based). */
static int sample(const retro_frame *f, int u, int d, size_t *idx)
{
    switch (f->mode) {
    case RETRO_MODE_TRUTH:
        *idx = retro_truth_sample(f, u, d);
        return retro_truth_row(f->kdd[d], 0.5 * (double)f->H, f->H, f->height_map[*idx] - f->height);
    case RETRO_MODE_FIXED:
        *idx = retro_fixed_sample(f, u, d);
        return retro_fixed_row(f->kd_fx[d], f->half_h_fx, f->H, f->height_map[*idx] - f->height);
    default:
        *idx = retro_exact_sample(f, u, d);
        return retro_exact_row(f->kd[d], f->half_h, f->H, f->height_map[*idx] - f->height);
    }
}

/* Modes exact, truth, fixed: every d from D-1 down to 1; mode lod: its distances, farthest
 * first. */
static void direct(const retro_frame *f)
{
    int lod = f->mode == RETRO_MODE_LOD;
    for (int n = (lod ? f->ndist : f->D) - 1; n >= 1; n--) {
        int d = lod ? f->dist[n] : n;
        for (int u = 1; u <= f->W; u++) {
            size_t idx;
            int v = sample(f, u - 1, d, &idx);
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
        direct(f);
}
