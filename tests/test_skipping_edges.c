/* The probes' boxes at block edges (docs/SKIPPING.md, "The traversal and why it is exact", point
 * 2): a run is skipped only when the cells it samples span at most B per axis, the widest box
 * the window of its first block covers. A box one cell wider escapes that window exactly when
 * the run starts on a block's last cell, so random maps rarely catch a probe that allows it.
 * Here a single spike stands on every cell just past such runs, a ray runs along a row of the
 * map from every quarter-cell offset within a block, and the run-length estimate is stretched
 * through every span up to a few blocks: every distance a probe skips must be one whose sample
 * paints nothing, in modes exact, truth and fixed. */
#include <criterion/criterion.h>
#include <string.h>

#include "ctx.h"
#include "frame.h"
#include "hmax_pyramid.h"
#include "skip_wide.h"
#include "skipping_rig.h"

enum { S = 64, ROW = 32, W = 1, H = 100, D = 48, CAMERA = 10 };

/* The row of column 0's sample at distance d in the frame's mode, brute force. */
static int sample_row(const retro_frame *f, int d)
{
    const int64_t dh0 = -f->height;
    if (f->mode == RETRO_MODE_TRUTH) {
        size_t idx = retro_truth_sample(f, 0, d);
        return retro_truth_row(f->kdd[d], 0.5 * (double)f->H, f->H, f->height_map[idx] + dh0);
    }
    if (f->mode == RETRO_MODE_FIXED) {
        size_t idx = retro_fixed_sample(f, 0, d);
        return retro_fixed_row(f->kd_q[d], f->half_h_q, f->H, f->height_map[idx] + dh0);
    }
    size_t idx = retro_exact_sample(f, 0, d);
    return retro_exact_row(f->kd[d], f->half_h, f->H, f->height_map[idx] + dh0);
}

Test(skipping, probe_boxes_at_block_edges)
{
    static const retro_mode modes[] = {RETRO_MODE_EXACT, RETRO_MODE_TRUTH, RETRO_MODE_FIXED};
    retro_map m;
    make_map(&m, S);
    uint32_t out[W * H];
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    long probes = 0, skipped = 0;
    for (int spike = 8; spike < 28; spike++) {
        memset(m.height, 0, (size_t)S * S);
        m.height[(size_t)ROW * S + (size_t)spike] = 255;
        retro_ctx_map_changed(rc);
        for (int mi = 0; mi < 3; mi++)
            for (int q = 0; q < 32; q++) { /* x0 = q / 4: every quarter cell of two blocks of 4 */
                retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
                o.mode = (int)modes[mi];
                /* angle 0 and one column: the ray is (1, 0) exactly, along the spike's row */
                player_t p = at(0.25f * (float)q, (float)ROW + 0.5f, 0, CAMERA);
                ctx_t c = {W, H, S, D, 0, m.height, m.color, out};
                const retro_frame *f = NULL;
                cr_assert_eq(retro_frame_prepare(rc, &o, &p, &c, &f), RETRO_OK);
                cr_assert_not_null(f->pyr);
                /* the ground (below the camera) projects below the middle row, the spike above */
                const int y = H / 2;
                for (int L = RETRO_PYR_LMIN; L <= RETRO_PYR_LMIN + 1 && L <= f->pyr->lmax; L++)
                    for (int stretch = 0; stretch <= 20; stretch++)
                        for (int d = 1; d < 16; d++) {
                            retro_skip_col col;
                            if (modes[mi] == RETRO_MODE_EXACT)
                                retro_skip_col_init(&col, f, 0);
                            else
                                retro_skip_wide_init(&col, f, 0);
                            col.level = L;
                            col.inv_r *= 1.0f + 0.2f * (float)stretch; /* estimates up to 5 times too long */
                            int e;
                            if (modes[mi] == RETRO_MODE_EXACT)
                                e = retro_skip_column(f->pyr, f, &col, d, D, y, 1, 0);
                            else
                                e = retro_skip_run_wide(f->pyr, f, &col, 0, d, D, y, modes[mi] == RETRO_MODE_FIXED);
                            probes++;
                            for (int dd = d; dd < e; dd++)
                                cr_assert_leq(sample_row(f, dd), y,
                                              "mode %d, spike at %d, x0 %g, level %d, stretch %d: the probe from %d "
                                              "skipped distance %d, whose sample paints",
                                              (int)modes[mi], spike, 0.25 * q, L, stretch, d, dd);
                            skipped += e - d;
                        }
            }
    }
    retro_ctx_free(rc);
    retro_map_free(&m);
    cr_assert_gt(skipped, probes, "the probes skipped too little to test anything (%ld distances in %ld probes)",
                 skipped, probes);
}
