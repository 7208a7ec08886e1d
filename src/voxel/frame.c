/* Frame setup: the formulas of SEMANTICS.md written once. Kernels read only retro_frame
 * (frame.h); the context's options (set by retro_render) say which effects, lod rate and
 * skipping. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "retro.h"
#include "retro_internal.h"
#include "ctx.h"
#include "direction.h"
#include "effects_bake.h"
#include "frame.h"
#include "hmax_cache.h"
#include "kernels.h"
#include "retro_scene.h"
#include "strips.h"
#ifndef RETRO_SUBMISSION /* the submission's kernel does not skip (docs/SKIPPING.md) */
#include "hmax_pyramid.h"
#include "skip_course.h"
#endif

/* Grows a buffer to n elements; memory only ever grows so steady-state frames never allocate. */
static int grow(void **buf, size_t n, size_t elem)
{
    void *p = realloc(*buf, n * elem);
    if (!p)
        return -1;
    *buf = p;
    return 0;
}

static retro_err reserve(retro_ctx *rc, int w, int d)
{
    if (w > rc->cap_w) {
        size_t n = (size_t)w;
        if (grow((void **)&rc->rx, n, sizeof(float)) || grow((void **)&rc->ry, n, sizeof(float)) ||
            grow((void **)&rc->ybuf, n, sizeof(int)) || grow((void **)&rc->rxd, n, sizeof(double)) ||
            grow((void **)&rc->ryd, n, sizeof(double)) || grow((void **)&rc->rx_q, n, sizeof(int64_t)) ||
            grow((void **)&rc->ry_q, n, sizeof(int64_t)))
            return RETRO_ENOMEM;
        rc->cap_w = w;
    }
    if (d > rc->cap_d) {
        size_t n = (size_t)d;
        if (grow((void **)&rc->kd, n, sizeof(float)) || grow((void **)&rc->lx, n, sizeof(float)) ||
            grow((void **)&rc->ly, n, sizeof(float)) || grow((void **)&rc->sx, n, sizeof(float)) ||
            grow((void **)&rc->sy, n, sizeof(float)) || grow((void **)&rc->qx, n, sizeof(float)) ||
            grow((void **)&rc->qy, n, sizeof(float)) || grow((void **)&rc->vcap, n + 1, sizeof(int)) ||
            grow((void **)&rc->kdd, n, sizeof(double)) || grow((void **)&rc->kd_q, n, sizeof(int64_t)) ||
            grow((void **)&rc->dist, n + 1, sizeof(int)) || grow((void **)&rc->fog, n, sizeof(uint16_t)))
            return RETRO_ENOMEM;
        rc->cap_d = d;
    }
    return RETRO_OK;
}

float retro_float_mod(float f, float k)
{
    float res = fmodf(f, k);
    if (res < 0)
        res += k;
    if (res >= k)
        res = 0;
    return res;
}

static double wrap(float v, int s)
{
    double r = fmod((double)v, (double)s);
    if (r < 0)
        r += (double)s;
    return r;
}

/* vcap over the frame's n-th distances (see retro_frame.vcap); row(n) projects hmax there. */
static void cap_rows(retro_ctx *rc, int n, int (*row)(const retro_frame *, int, int64_t))
{
    const retro_frame *f = &rc->frame;
    int64_t dh = (int64_t)f->hmax - f->height;
    rc->vcap[n] = 0;
    for (int i = n - 1; i >= 1; i--) {
        int v = row(f, i, dh);
        rc->vcap[i] = v > rc->vcap[i + 1] ? v : rc->vcap[i + 1];
    }
}

static int row_exact(const retro_frame *f, int d, int64_t dh)
{
    return retro_exact_row(f->kd[d], f->half_h, f->H, dh);
}

static int row_lod(const retro_frame *f, int n, int64_t dh)
{
    return retro_exact_row(f->kd[f->dist[n]], f->half_h, f->H, dh);
}

static int row_truth(const retro_frame *f, int d, int64_t dh)
{
    return retro_truth_row(f->kdd[d], (double)f->H * 0.5, f->H, dh);
}

static int row_fixed(const retro_frame *f, int d, int64_t dh)
{
    return retro_fixed_row(f->kd_q[d], f->half_h_q, f->H, dh);
}

static int64_t to_fixed(double v, int bits)
{
    return llround(v * (double)(1LL << bits));
}

static void setup_exact(retro_ctx *rc, retro_frame *f, int angle, const retro_effects *fx)
{
    unsigned flags = fx ? fx->flags : 0;
    double cs, sn;
    retro_direction(angle, &cs, &sn);
    f->cs = (float)cs;
    f->sn = (float)sn;

    int W = f->W;
    for (int u = 1; u <= W; u++) {
        float t = 0.0f;
        if (W > 1)
            t = (float)(2 * (int64_t)(u - 1) - (W - 1)) / (float)(W - 1);
        rc->rx[u - 1] = f->cs + t * f->sn;
        rc->ry[u - 1] = t * f->cs - f->sn;
    }
    f->half_w = 0.5f * (float)W;
    f->half_h = 0.5f * (float)f->H;
    if (flags & RETRO_FX_HORIZON)
        f->half_h = f->half_h + (float)fx->pitch;
    if (flags & RETRO_FX_FOG)
        retro_fog_table(fx, rc->fog, f->D);
    for (int d = 1; d < f->D; d++)
        rc->kd[d] = f->half_w / (float)d;
    if (f->mode != RETRO_MODE_LOD) {
        cap_rows(rc, f->D, row_exact);
        return;
    }
    /* dist[1..ndist-1] are the sample distances; entry ndist closes vcap. */
    double lambda = rc->lod > 0 ? rc->lod : RETRO_LOD_DEFAULT;
    int n = 1;
    for (int64_t d = 1; d < f->D; n++) {
        rc->dist[n] = (int)d;
        /* Compared in double before converting: a huge lambda would overflow int64_t, and a
         * NaN one has no step (both refused before setup); D ends the walk either way. */
        double step = floor((double)d * lambda);
        d += step > 1 && step < (double)f->D ? (int64_t)step : step >= (double)f->D ? f->D : 1;
    }
    f->ndist = n;
    cap_rows(rc, n, row_lod);
}

static void setup_truth(retro_ctx *rc, retro_frame *f, const player_t *p)
{
    retro_direction(p->angle, &f->cs_d, &f->sn_d);
    f->x0_d = wrap(p->x, f->S);
    f->y0_d = wrap(p->y, f->S);
    int W = f->W;
    for (int u = 1; u <= W; u++) {
        double t = W > 1 ? (double)(2 * (int64_t)(u - 1) - (W - 1)) / (double)(W - 1) : 0.0;
        rc->rxd[u - 1] = f->cs_d + t * f->sn_d;
        rc->ryd[u - 1] = t * f->cs_d - f->sn_d;
    }
    for (int d = 1; d < f->D; d++)
        rc->kdd[d] = 0.5 * (double)W / (double)d;
}

static void setup_fixed(retro_ctx *rc, retro_frame *f, const player_t *p)
{
    setup_truth(rc, f, p);
    f->x0_q = to_fixed(f->x0_d, RETRO_Q_POS);
    f->y0_q = to_fixed(f->y0_d, RETRO_Q_POS);
    for (int u = 0; u < f->W; u++) {
        rc->rx_q[u] = to_fixed(rc->rxd[u], RETRO_Q_POS);
        rc->ry_q[u] = to_fixed(rc->ryd[u], RETRO_Q_POS);
    }
    for (int d = 1; d < f->D; d++)
        rc->kd_q[d] = to_fixed(rc->kdd[d], RETRO_Q_PROJ);
    f->half_h_q = to_fixed(0.5 * (double)f->H, RETRO_Q_PROJ);
    cap_rows(rc, f->D, row_fixed);
}

static int row_course(const retro_frame *f, int d, int64_t dh)
{
    return retro_course_row(f->cw2, f->ch2, f->H, dh, d);
}

static void setup_course(retro_ctx *rc, retro_frame *f, const player_t *p)
{
    float phi = (float)(p->angle * 3.14159265358979323846 / 180.0);
    float c = cosf(phi), s = sinf(phi);
    float fw = (float)f->W;
    for (int d = 1; d < f->D; d++) {
        float a = c * (float)d, b = s * (float)d;
        float lx = (p->x + a) - b, ly = (p->y - b) - a;
        float rx = (p->x + a) + b, ry = (p->y - b) + a;
        rc->lx[d] = lx;
        rc->ly[d] = ly;
        rc->sx[d] = (rx - lx) / fw;
        rc->sy[d] = (ry - ly) / fw;
    }
    f->cw2 = (float)(f->W / 2);
    f->ch2 = f->H / 2;
    cap_rows(rc, f->D, row_course);
}

retro_err retro_frame_setup(retro_ctx *rc, retro_mode mode, const player_t *p, const ctx_t *c)
{
    if (!rc || !p || !c || !c->height_map || !c->color_map || !c->out)
        return RETRO_EINVAL;
    if ((unsigned)mode >= RETRO_MODE_COUNT)
        return RETRO_EINVAL;
    int W = c->scr_width, H = c->scr_height, S = c->map_size;
    if (W < 1 || H < 1 || W > RETRO_MAX_SCREEN || H > RETRO_MAX_SCREEN ||
        (long)W * H > RETRO_MAX_PIXELS)
        return RETRO_EINVAL;
    if (S < (mode == RETRO_MODE_COURSE ? 2 : 1) || S > RETRO_MAX_MAP)
        return RETRO_EINVAL;
    if (c->distance > RETRO_MAX_DISTANCE || !isfinite(p->x) || !isfinite(p->y))
        return RETRO_EINVAL;
    int D = c->distance < 1 ? 1 : c->distance;
    retro_err e = reserve(rc, W, D);
    if (e)
        return e;

    const retro_effects *fx = rc->fx;
    /* Which effects a mode takes is decided by retro_kernel_check (effects are defined on
     * modes exact and lod); here only their parameters are checked. */
    unsigned flags = fx ? fx->flags & RETRO_FX_VOXEL : 0;
    if (flags && !retro_effects_valid(fx))
        return RETRO_EINVAL;
    const uint8_t *hm = c->height_map;
    const uint32_t *cm = c->color_map;
    if (flags & (RETRO_FX_MORPH | RETRO_FX_SHADE | RETRO_FX_WATER)) {
        int baked = retro_effects_bake(&rc->bake, fx, hm, cm, S);
        if (baked < 0)
            return RETRO_ENOMEM;
        if (baked)
            retro_ctx_maps_rewritten(rc);
        hm = rc->bake.height;
        cm = rc->bake.color;
    }
    int hmax = retro_hmax_get_by(&rc->hmax, hm, S, rc->map_scan, rc);

    retro_frame *f = &rc->frame;
    memset(f, 0, sizeof *f);
    f->mode = mode;
    f->W = W;
    f->H = H;
    f->S = S;
    f->D = D;
    f->sky = c->sky_color;
    f->height_map = hm;
    f->color_map = cm;
    f->fx = flags & RETRO_FX_PER_SAMPLE;
    f->fog = rc->fog;
    f->out = c->out;
    f->height = p->height;
    /* A bilinear height exceeds the maximum by rounding at most: the bound takes one more. */
    f->hmax = hmax + ((flags & RETRO_FX_BILINEAR) ? 1 : 0);
    f->x0 = (float)wrap(p->x, S);
    f->y0 = (float)wrap(p->y, S);
    f->rx = rc->rx;
    f->ry = rc->ry;
    f->kd = rc->kd;
    f->lx = rc->lx;
    f->ly = rc->ly;
    f->sx = rc->sx;
    f->sy = rc->sy;
    f->vcap = rc->vcap;
    f->rxd = rc->rxd;
    f->ryd = rc->ryd;
    f->kdd = rc->kdd;
    f->rx_q = rc->rx_q;
    f->ry_q = rc->ry_q;
    f->kd_q = rc->kd_q;
    f->dist = rc->dist;
    rc->packed.offered = 0; /* until a threaded kernel offers it for this frame */
    f->packed = &rc->packed;
    switch (mode) {
    case RETRO_MODE_COURSE: setup_course(rc, f, p); break;
    case RETRO_MODE_TRUTH: setup_truth(rc, f, p); cap_rows(rc, f->D, row_truth); break;
    case RETRO_MODE_FIXED: setup_fixed(rc, f, p); break;
    default: setup_exact(rc, f, p->angle, fx); break; /* exact and lod */
    }
#ifndef RETRO_SUBMISSION
    /* occlusion skipping (docs/SKIPPING.md), unless switched off: modes exact, lod, truth and
     * fixed on the S x S torus; mode course on its (S - 1) x (S - 1) torus when its positions'
     * drift is small enough to bound (skip_course.h), for the ybuffer strip (the SIMD column
     * does not skip) */
    if ((mode == RETRO_MODE_EXACT || mode == RETRO_MODE_LOD || mode == RETRO_MODE_TRUTH || mode == RETRO_MODE_FIXED) &&
        !rc->no_skip &&
        retro_pyramid_get(&rc->pyr, hm, S, S, &f->pyr))
        return RETRO_ENOMEM;
    if (mode == RETRO_MODE_COURSE && !rc->no_skip && (f->course_margin = retro_course_margin(p->x, p->y, W, D)) &&
        retro_pyramid_get(&rc->pyr_course, hm, S, S - 1, &f->pyr))
        return RETRO_ENOMEM;
#endif
    f->strip = retro_strip_best(mode, f->fx); /* once per frame, for the threaded kernels */
    return RETRO_OK;
}
