/* Part of simd_strip_tpl.h, whose contract applies, included by it once per ISA file: the
 * occlusion probe of a group of lanes (docs/SKIPPING.md, "The SIMD strips"), evaluated on every
 * lane at once. Each lane asks the pyramid about its own column with its own y-buffer, as
 * retro_skip_run does for one column; the group skips a run only when every lane may. */

#ifndef RETRO_SUBMISSION /* the submission's frames carry no pyramid */

/* Per-group probe state: the run-length estimate and the level the next probe starts at. */
typedef struct {
    float inv_r; /* 1 / (the largest max(|rx|, |ry|) of the group's columns): an estimate only */
    int level;
} SIMD_NAME(skip_t);

static inline void SIMD_NAME(skip_init)(SIMD_NAME(skip_t) *g, const retro_frame *f, int u0, int width)
{
    float r = 0.0f;
    for (int u = u0; u < u0 + width; u++) {
        const float ax = fabsf(f->rx[u]), ay = fabsf(f->ry[u]);
        r = fmaxf(r, fmaxf(ax, ay));
    }
    g->inv_r = r > 0.0f ? 1.0f / r : 1.0f; /* r > 0.7 for every column in fact */
    g->level = RETRO_PYR_LMIN;
}

/* The first index in [n, n_end) at which some lane may rise above its y-buffer; n_end when
 * none may. The n-th distance is n, or dist[n] in mode lod (lod). rx, ry are the lanes' rays
 * (lanes past the group's width: 0, and y = H there).
 *
 * Proof: per lane, retro_skip_run's for that lane's column (hmax_pyramid.h, points 1 to 4):
 * the positions at d and d1 are computed with sample()'s very operations, v_floor_i is
 * retro_floor for |q| < 2^31, and floor(min(q0, q1)) = min(floor q0, floor q1) since floor is
 * monotone, so the block index comes from the run's smallest corner taken mod S by the
 * kernel's own wraps; the box is confirmed per lane (the length is an estimate). The bound's
 * row: for dh >= 0 the row of M is largest at d (kd[d] >= kd[d1], rounding is monotone), for
 * dh < 0 at d1, and in each case that row is the larger of the two computed, so the maximum of
 * both is exactly retro_skip_run's vf. M - height is exact in int32 (retro_simd_check) and
 * converts as (float)((int64_t)M - height) does. A lane with y >= vcap[d] paints nothing from d
 * on (the early exit's argument: vcap is non-increasing), so it does not hold the group back;
 * lanes past the width have y = H >= vcap. If every other lane's box fits a block and its
 * bound stays <= its y, no lane paints in [d, d1] and their y-buffers are unchanged there, so
 * the run is skipped for the whole group; each lane's proof holds alone, with its own y.
 * Bilinear and mode lod as in retro_skip_run: the box is of the floors of q - 1/2 computed as
 * sample() does, one cell wider, bounded by M + RETRO_BILINEAR_OVER (exact in float) through
 * the sample's own dh (bilinear_dh, whose float subtraction simd_sample_tpl.h proves equal to
 * the definition's double one; it is monotone in the height, so the bound's dh bounds every
 * filtered height's); a run of lod
 * indices samples distances between dist[n] and dist[n1] only, and kd is indexed by distance.
 * Levels: up after a skip, down after a run some lane may paint in, and the probe gives up at
 * RETRO_PYR_LMIN or after RETRO_SKIP_GROUP_TRIES failing windows. */
RETRO_SIMD_INLINE int SIMD_NAME(skip_probe)(const retro_frame *f, const SIMD_NAME(consts) *k, SIMD_NAME(skip_t) *g,
                                            simd_f32 rx, simd_f32 ry, simd_i32 y, int n, int n_end,
                                            const int pow2, const int bilinear, const int lod)
{
    const retro_pyramid *p = f->pyr;
    const uint8_t *base = p->win[RETRO_PYR_LMIN];
    const simd_i32 need = v_add_i(y, v_set1_i(1));
    /* lanes that can still paint somewhere from n on */
    const simd_mask open = v_igt(v_set1_i(f->vcap[n]), y);
    const simd_f32 fneed = v_cvt_f(need), half = v_set1_f(0.5f);
    int L = g->level, tries = RETRO_SKIP_GROUP_TRIES;
    simd_f32 qx0 = v_zero_f(), qy0 = v_zero_f();
    int at = 0; /* the index qx0, qy0 are of (0: none yet) */
    SIMD_COUNT_LANES(probes, 1);
    while (n < n_end) {
        SIMD_COUNT_LANES(windows, 1);
        const int B = 1 << L;
        /* a bilinear sample reads one cell more per axis: the estimate leaves room for it */
        int len = 1 + (int)((float)(B - 1 - bilinear) * g->inv_r);
        if (lod && n + 1 < n_end) /* in indices, by the step at n (steps never shrink) */
            len = 1 + (len - 1) / (f->dist[n + 1] - f->dist[n]);
        const int n1 = n_end - 1 - n < len - 1 ? n_end - 1 : n + len - 1;
        const int d = lod ? f->dist[n] : n, d1 = lod ? f->dist[n1] : n1;
        if (at != n) {
            const simd_f32 f0 = v_set1_f((float)d);
            qx0 = v_add_f(k->x0, v_mul_f(f0, rx));
            qy0 = v_add_f(k->y0, v_mul_f(f0, ry));
            if (bilinear) { /* the sample's own q - 1/2 */
                qx0 = v_sub_f(qx0, half);
                qy0 = v_sub_f(qy0, half);
            }
            at = n;
        }
        const simd_f32 f1 = v_set1_f((float)d1);
        simd_f32 qx1 = v_add_f(k->x0, v_mul_f(f1, rx)), qy1 = v_add_f(k->y0, v_mul_f(f1, ry));
        if (bilinear) {
            qx1 = v_sub_f(qx1, half);
            qy1 = v_sub_f(qy1, half);
        }
        const simd_i32 I0 = v_floor_i(qx0), I1 = v_floor_i(qx1), J0 = v_floor_i(qy0), J1 = v_floor_i(qy1);
        const simd_i32 wi = v_max_i(v_sub_i(I1, I0), v_sub_i(I0, I1));
        const simd_i32 wj = v_max_i(v_sub_i(J1, J0), v_sub_i(J0, J1));
        const simd_i32 B1 = v_set1_i(B + 1 - bilinear); /* with bilinear, the span + 1 <= B */
        const simd_mask fits = v_mand(v_igt(B1, wi), v_igt(B1, wj));
        const simd_f32 mx = v_min_f(qx0, qx1), my = v_min_f(qy0, qy1);
        const simd_i32 ci = pow2 ? SIMD_NAME(wrap_pow2)(mx, k) : SIMD_NAME(wrap_any)(mx, k);
        const simd_i32 cj = pow2 ? SIMD_NAME(wrap_pow2)(my, k) : SIMD_NAME(wrap_any)(my, k);
        const simd_i32 idx = v_add_i(v_add_i(v_mullo_i(v_srl_i(cj, L), v_set1_i(p->n[L])), v_srl_i(ci, L)),
                                     v_set1_i((int)(p->win[L] - base)));
        const simd_i32 M = v_gather_bytes_pad(base, idx);
        /* bilinear: the sample's own dh, through the same bilinear_dh, of a height above any
         * filtered one (M + RETRO_BILINEAR_OVER is exact in float) */
        const simd_f32 dh = bilinear ? SIMD_NAME(bilinear_dh)(v_add_f(v_cvt_f(M), v_set1_f(RETRO_BILINEAR_OVER)), f, k)
                                     : v_cvt_f(v_sub_i(M, k->height));
        const simd_f32 vf = v_max_f(v_add_f(v_mul_f(v_set1_f(f->kd[d]), dh), k->half_h),
                                    v_add_f(v_mul_f(v_set1_f(f->kd[d1]), dh), k->half_h));
        /* a lane stays below when its box fits and !(vf >= need), the sample kernel's test */
        const simd_mask may = v_mandnot(v_mandnot(v_fge(vf, fneed), fits), open);
        if (!v_bits(may)) {
            n = n1 + 1;
            if (L < p->lmax)
                L++;
            continue;
        }
        if (L == RETRO_PYR_LMIN || --tries == 0)
            break;
        L--;
    }
    g->level = L;
    return n;
}

#endif
