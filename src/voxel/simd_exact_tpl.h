/* Part of simd_strip_tpl.h, whose contract applies, included by it once per ISA file: a group
 * of adjacent columns in modes exact and lod, painting by masked row stores or column spans,
 * and with row stores the sky above several finished groups. */

#if SIMD_ROW_STORES
/* The sky above n finished adjacent groups, the first at column u0 and first columns wide, the
 * others SIMD_LANES: y[g] is group g's final y-buffer, H in lanes past its columns. Painted row
 * by row across the groups, so one row's stores are adjacent in out; painted group by group,
 * each store was a frame row away from the last (docs/KERNELS.md, "Where the stores go"). */
static void SIMD_NAME(sky_rows)(const retro_frame *f, int u0, int first, const simd_i32 *y, int n,
                                const SIMD_NAME(consts) *k)
{
    const size_t W = (size_t)f->W;
    const simd_i32 sky = v_set1_i((int)f->sky), all = v_set1_i(f->H + 1);
    int lo = f->H;
    for (int g = 0; g < n; g++) {
        const int m = v_min_where(v_igt(all, y[g]), y[g]);
        lo = m < lo ? m : lo;
    }
    size_t at = (size_t)(f->H - lo - 1) * W + (size_t)u0;
    simd_i32 r = v_set1_i(lo + 1);
    for (int row = lo + 1; row <= f->H; row++, at -= W) {
        size_t a = at;
        for (int g = 0; g < n; a += (size_t)(g ? SIMD_LANES : first), g++) {
            const simd_mask m = v_rows(r, y[g], k->H);
            v_maskstore(f->out + a, m, sky);
            RETRO_SIMD_COUNT(f->out, a, v_bits(m));
        }
        r = v_add_i(r, v_set1_i(1));
    }
}

/* The last K = RETRO_SIMD_PAINT_BATCH painting steps of a group, stored in one pass over their
 * rows. Step k (0..K-1) left the lane's y-buffer at Y[k], with y0 <= Y[0] <= .. <= Y[K-1] (y0:
 * before step 0), so painting step by step, step k wrote rows (Y[k-1], Y[k]] (y0 for Y[-1]) of
 * the lane with c[k], and a lane that step did not raise has Y[k] = Y[k-1] and wrote nothing.
 * Those ranges tile (y0, Y[K-1]], so row r of it gets c[k] for the least k with r <= Y[k]: the
 * same pixels and colours as K separate paints, each pixel still written once. Only the
 * number of stores changes: one per row of the batch instead of one per row per step. */
static void SIMD_NAME(paint_batch)(const retro_frame *f, int u0, simd_i32 y0, const simd_i32 *Y, const simd_i32 *c)
{
    enum { K = RETRO_SIMD_PAINT_BATCH };
    const simd_i32 top = Y[K - 1];
    const simd_mask rose = v_igt(top, y0); /* every step of a batch raised some lane */
    const int lo = v_min_where(rose, y0) + 1, hi = v_max_where(rose, top);
    const size_t W = (size_t)f->W;
    size_t at = (size_t)(f->H - lo) * W + (size_t)u0;
    /* copies the unrolled loops keep in registers: read from Y and c, every row reloads them */
    simd_i32 r = v_set1_i(lo), Yr[K], cr[K];
#pragma GCC unroll 16
    for (int k = 0; k < K; k++) {
        Yr[k] = Y[k];
        cr[k] = c[k];
    }
    for (int row = lo; row <= hi; row++, at -= W) {
        const simd_mask m = v_rows(r, y0, top);
        simd_i32 colour = cr[K - 1];
#pragma GCC unroll 16
        for (int k = K - 2; k >= 0; k--)
            colour = v_select_i(v_igt(r, Yr[k]), colour, cr[k]);
        v_maskstore(f->out + at, m, colour);
        RETRO_SIMD_COUNT(f->out, at, v_bits(m));
        r = v_add_i(r, v_set1_i(1));
    }
}

/* Fog toward the sky by weight F/256 (docs/EFFECTS.md) on every lane: R|B and G in 16-bit
 * halves, x*(256-F) + s*F + 128 stays below 2^16, so 16-bit products are exact and the bytes
 * equal retro_fog()'s. */
static inline simd_i32 SIMD_NAME(fog_colours)(simd_i32 c, int F, uint32_t sky)
{
    const simd_i32 low = v_set1_i(0x00ff00ff), byte = v_set1_i(0xff);
    const simd_i32 wc = v_set1_16((short)(256 - F)), ws = v_set1_16((short)F), half = v_set1_16(128);
    simd_i32 rb = v_and_i(v_srli_i(c, 8), low), g = v_and_i(v_srli_i(c, 16), byte);
    simd_i32 srb = v_set1_i((int)((sky >> 8) & 0x00ff00ffu)), sg = v_set1_i((int)((sky >> 16) & 0xffu));
    rb = v_srli_16(v_add_16(v_add_16(v_mullo_16(rb, wc), v_mullo_16(srb, ws)), half), 8);
    g = v_srli_16(v_add_16(v_add_16(v_mullo_16(g, wc), v_mullo_16(sg, ws)), half), 8);
    return v_or_i(v_slli_i(rb, 8), v_slli_i(g, 16));
}
#endif

/* Columns u0..u0+width-1 (width <= SIMD_LANES), front to back: docs/KERNELS.md's mode exact.
 * Lanes past width start full (y = H), so they neither paint nor hold the group back. The n-th
 * distance is n, or dist[n] in mode lod (lod), where vcap is indexed by n as well. With skip,
 * the group probes the pyramid, every lane with its own y-buffer (simd_skip_tpl.h, on
 * simd_common.h's schedule), and jumps over the distances no lane can paint in; s then holds
 * distances the loop no longer wants, and sn says the first of them. With row stores the group
 * leaves the sky to its strip: *top receives its final y-buffer. */
RETRO_SIMD_INLINE void
SIMD_NAME(exact_group)(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k, int u0,
                       int width, const int pow2, const int packed, const int fog, const int skip, const int lod,
                       const int bilinear, simd_i32 *top)
{
    const simd_mask live = v_first(width);
    const int n_end = lod ? f->ndist : f->D;
    simd_f32 rx = v_load_first_f(f->rx + u0, width, live), ry = v_load_first_f(f->ry + u0, width, live);
    simd_i32 y = v_select_i(live, v_zero_i(), k->H);
    /* s[i] holds the sample of index sn + i, P indices loaded ahead (RETRO_SIMD_AHEAD) */
    const int P = bilinear ? 1 : RETRO_SIMD_AHEAD;
    SIMD_NAME(sample_t) s[RETRO_SIMD_AHEAD], s_d;
    /* mode lod: dist[n] exists for n < n_end only; a sample past it is loaded but never used */
#define SIMD_DIST(n) (lod ? f->dist[(n) < n_end ? (n) : 1] : (n))
#pragma GCC unroll 8
    for (int i = 0; i < P; i++)
        SIMD_NAME(sample)(f, sf, k, rx, ry, n_end > 1 + i ? SIMD_DIST(1 + i) : 1 + i, &s[i], pow2, packed, bilinear);
#ifndef RETRO_SUBMISSION
    SIMD_NAME(skip_t) g;
    int probe = 1, batch = RETRO_SIMD_SKIP_NEAR; /* the next probe's index, the batch after it */
    if (skip)
        SIMD_NAME(skip_init)(&g, f, u0, width);
#endif
    int sn = 1;
#if SIMD_ROW_STORES
    /* the painting steps not yet stored (paint_batch): the y-buffer before them, and after and
     * the colours of each */
    simd_i32 y_painted = y, pY[RETRO_SIMD_PAINT_BATCH], pc[RETRO_SIMD_PAINT_BATCH];
    int pm = 0;
#endif
    for (int n = 1; n < n_end;) {
        if (!v_bits(v_igt(v_set1_i(f->vcap[n]), y)))
            break;
#ifndef RETRO_SUBMISSION
        if (skip && n >= probe) { /* some lane has y < vcap[n] <= H */
            const int e = SIMD_NAME(skip_probe)(f, k, &g, rx, ry, y, n, n_end, pow2, bilinear, lod);
            if (e > n) {
                n = e;
                probe = e;
                batch = RETRO_SIMD_SKIP_NEAR;
                continue;
            }
            probe = n + batch;
            batch = batch < RETRO_SIMD_SKIP_FAR ? 2 * batch : batch;
        }
#endif
        const int d = SIMD_DIST(n);
        if (skip && sn != n) { /* a skip: what was loaded ahead is of distances jumped over */
#pragma GCC unroll 8
            for (int i = 0; i < P; i++)
                SIMD_NAME(sample)(f, sf, k, rx, ry, SIMD_DIST(n + i), &s[i], pow2, packed, bilinear);
        }
        simd_i32 v = SIMD_NAME(project)(&s[0], f->kd[d], k, bilinear);
        s_d = s[0];
        /* The loads of distance n + P issue before this step's paint branch, so they and those
         * of the distances between are in flight when it mispredicts. An index at or past
         * n_end samples a valid cell that is never used (SIMD_DIST keeps lod's in dist). */
#if defined(__clang__)
        /* clang makes the loop of the #else a memmove of the whole array before it unrolls it,
         * which keeps every sample in memory; written out, they stay in registers. gcc keeps
         * them there with the loop, whose code the published runs timed
         * (docs/studies/KERNEL_STUDIES.md, "Which compiler"; tests/clang_strips.sh). */
        _Static_assert(RETRO_SIMD_AHEAD <= 4, "the copies below shift at most 4 samples");
        if (P > 1)
            s[0] = s[1];
        if (P > 2)
            s[1] = s[2];
        if (P > 3)
            s[2] = s[3];
#else
#pragma GCC unroll 8
        for (int i = 0; i + 1 < P; i++)
            s[i] = s[i + 1];
#endif
        SIMD_NAME(sample)(f, sf, k, rx, ry, SIMD_DIST(n + P), &s[P - 1], pow2, packed, bilinear);
        sn = n + 1;
        const simd_mask up = v_igt(v, y);
        SIMD_COUNT_LANES(evaluated, width);
        SIMD_COUNT_LANES(painting, __builtin_popcount(v_bits(up)));
        if (v_bits(up)) {
#if SIMD_ROW_STORES
            /* a lane that does not rise keeps its Y, so no row takes its colour of this step */
            simd_i32 c = SIMD_NAME(colours)(f, sf, k, &s_d, up, packed, bilinear);
            pc[pm] = fog ? SIMD_NAME(fog_colours)(c, f->fog[d], f->sky) : c;
            pY[pm] = v_max_i(y, v);
            if (++pm == RETRO_SIMD_PAINT_BATCH) {
                SIMD_NAME(paint_batch)(f, u0, y_painted, pY, pc);
                y_painted = pY[RETRO_SIMD_PAINT_BATCH - 1];
                pm = 0;
            }
#else
            int ys[SIMD_LANES], vs[SIMD_LANES];
            uint32_t cs[SIMD_LANES];
            v_store_i(ys, y);
            v_store_i(vs, v);
            v_store_i((int *)cs, bilinear ? SIMD_NAME(colours)(f, sf, k, &s_d, up, packed, 1) : s_d.at[0]);
            for (unsigned m = v_bits(up); m; m &= m - 1) {
                int l = __builtin_ctz(m);
                uint32_t c = bilinear ? cs[l] : SIMD_NAME(colour_of)(f, cs[l], packed);
                retro_simd_span(f, u0 + l, ys[l], vs[l], fog ? retro_fog(c, f->sky, f->fog[d]) : c);
            }
#endif
            y = v_max_i(y, v);
        }
        n++;
    }
#undef SIMD_DIST
#if SIMD_ROW_STORES
    if (pm) { /* slots left repeat the last step: no row passes its Y, so none picks them */
        for (int i = pm; i < RETRO_SIMD_PAINT_BATCH; i++) {
            pY[i] = pY[pm - 1];
            pc[i] = pc[pm - 1];
        }
        SIMD_NAME(paint_batch)(f, u0, y_painted, pY, pc);
    }
    *top = y; /* the strip paints the sky (sky_rows) */
#else
    (void)top;
    int ys[SIMD_LANES];
    v_store_i(ys, y);
    for (int l = 0; l < width; l++)
        retro_simd_span(f, u0 + l, ys[l], f->H, f->sky);
#endif
}
