/* The voxel family's frame: every constant its kernels read for one frame, built once per
 * frame by retro_frame_setup() (frame.c) from SEMANTICS.md's formulas. Kernels receive it
 * const and never write it; what they need beyond it (scratch, the packed map) is the
 * context's. The per-mode groups are anonymous structs, so a kernel names a constant the same
 * way in every mode (f->kd, f->lx) while the definition shows which mode sets it. */
#ifndef RETRO_FRAME_H
#define RETRO_FRAME_H

#include <stdint.h>

#include "retro.h"

struct retro_pyramid;
struct retro_packed_map;

struct retro_frame {
    /* every mode */
    retro_mode mode;
    int W, H, S, D;
    uint32_t sky;
    const uint8_t *height_map;
    const uint32_t *color_map;
    uint32_t *out;
    int64_t height;    /* camera height, widened so h - height never overflows */
    int hmax;          /* maximum of the height map, for exact early exits */
    /* vcap[n] = max over n' >= n of the projected row of a sample of height hmax at the n'-th
     * distance (distance n, or dist[n] in mode lod); no sample from there on can rise above
     * it. The entry past the last distance is 0. */
    const int *vcap;
    /* the context's packed colour|height map (simd_map.h): its strips use it when a threaded
     * kernel offered it for this frame (retro_simd_offer_packed), else read the maps */
    const struct retro_packed_map *packed;
    /* the strip the threaded kernels run: the fastest of the strip table (strips.h) for this
     * frame's mode and effects at the CPU's ISA level, chosen once by setup */
    void (*strip)(const struct retro_frame *f, float *qx, float *qy, int u0, int u1);
    /* the map's maximum-height pyramid when occlusion skipping is on (hmax_pyramid.h,
     * docs/SKIPPING.md), else NULL: of period S in modes exact, lod, truth and fixed, S - 1 in
     * mode course */
    const struct retro_pyramid *pyr;
    struct { /* modes exact and lod (x0, y0 in every mode) */
        float cs, sn;      /* view direction, exact at multiples of 90 degrees */
        float x0, y0;      /* position reduced modulo S */
        float half_w;      /* 0.5f * W */
        float half_h;      /* 0.5f * H (moved by the horizon effect) */
        const float *rx;   /* [W] column ray x: cs + t_u * sn */
        const float *ry;   /* [W] column ray y: t_u * cs - sn */
        const float *kd;   /* [D] projection scale (0.5f*W)/d, entry 0 unused */
        /* per-sample effects in force (RETRO_FX_FOG, RETRO_FX_BILINEAR of retro_scene.h) */
        unsigned fx;
        const uint16_t *fog; /* [D] fog weight 0..256 at distance d */
        /* mode lod: the sample distances, increasing from 1 */
        const int *dist;
        int ndist;
    };
    struct { /* mode course */
        float cw2;         /* (float)(W/2) */
        int ch2;           /* H/2 */
        const float *lx, *ly; /* [D] left endpoint of line d */
        const float *sx, *sy; /* [D] per-column step of line d */
        /* cells a run's box is widened by on each side for the accumulated positions' drift
         * from their straight lines (skip_course.h); set with pyr */
        int course_margin;
    };
    struct { /* mode truth: exact's quantities in binary64 */
        double cs_d, sn_d, x0_d, y0_d;
        const double *rxd, *ryd; /* [W] */
        const double *kdd;       /* [D] (0.5*W)/d */
    };
    struct { /* mode fixed: positions with RETRO_Q_POS fractional bits, projection RETRO_Q_PROJ */
        int64_t x0_q, y0_q, half_h_q;
        const int64_t *rx_q, *ry_q; /* [W] */
        const int64_t *kd_q;         /* [D] */
    };
};

/* Validates (player, ctx) for mode with the options the context holds (effects, lod,
 * skipping: set by retro_render from its retro_render_opts) and fills rc's frame. The mode is
 * the one retro_render_check() decided. Returns RETRO_OK or an error. */
retro_err retro_frame_setup(retro_ctx *rc, retro_mode mode, const player_t *p, const ctx_t *c);

/* What retro_render does before the kernel runs, for tests that inspect the constants: checks
 * o against the reference kernel (retro_render_check), takes o into rc, sets the frame up in
 * the mode o decides, and points *f at it. */
retro_err retro_frame_prepare(retro_ctx *rc, const retro_render_opts *o, const player_t *p, const ctx_t *c,
                              const retro_frame **f);

#endif
