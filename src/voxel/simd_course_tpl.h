/* Part of simd_strip_tpl.h, whose contract applies, included by it once per ISA file: a column
 * of mode course, its lanes consecutive distances. */

/* The y-buffer pass over distances d..d+LANES-1 of column u: lane l paints rows e+1..v_l, as a
 * column span, when v_l exceeds e = max(y, v_<l), an exclusive prefix max in log2(LANES)
 * shifted maxes. Returns the new y-buffer. */
static inline int SIMD_NAME(course_scan)(const retro_frame *f, int u, int y, simd_i32 v, simd_i32 at,
                                         const int packed)
{
    const simd_i32 fill = v_set1_i(y);
    simd_i32 p = v_max_i(v, fill);
    p = v_max_i(p, V_SHIFT_UP(p, fill, 1));
    p = v_max_i(p, V_SHIFT_UP(p, fill, 2));
#if SIMD_LANES > 4
    p = v_max_i(p, V_SHIFT_UP(p, fill, 4));
#endif
#if SIMD_LANES > 8
    p = v_max_i(p, V_SHIFT_UP(p, fill, 8));
#endif
    simd_i32 e = V_SHIFT_UP(p, fill, 1);
    unsigned up = v_bits(v_igt(v, e));
    SIMD_COUNT_LANES(painting, __builtin_popcount(up));
    if (up) {
        int es[SIMD_LANES], vs[SIMD_LANES];
        uint32_t as[SIMD_LANES];
        v_store_i(es, e);
        v_store_i(vs, v);
        v_store_i((int *)as, at);
        for (; up; up &= up - 1) {
            int l = __builtin_ctz(up);
            retro_simd_span(f, u, es[l], vs[l], SIMD_NAME(colour_of)(f, as[l], packed));
        }
    }
    return v_last_i(p);
}

/* The rows of distances d..d+LANES-1 (those below D; the others get v = 0) of the column whose
 * positions qx, qy hold, and in *at what the scan needs for colours. */
RETRO_SIMD_INLINE simd_i32
SIMD_NAME(course_sample)(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k,
                         const float *qx, const float *qy, int d, simd_i32 *at, const int packed)
{
    const int n = f->D - d;
    const simd_mask live = v_first(n);
    SIMD_COUNT_LANES(evaluated, n < SIMD_LANES ? n : SIMD_LANES);
    simd_f32 x = v_load_first_f(qx + d, n, live), z = v_load_first_f(qy + d, n, live);
    /* Dead lanes sample cell 0 (their q is 0). */
    simd_i32 h = SIMD_NAME(heights)(f, sf, k, SIMD_NAME(course_wrap)(x, k), SIMD_NAME(course_wrap)(z, k), at,
                                    packed);
    simd_f32 fd = v_add_f(v_set1_f((float)d), v_iota_f());
    return v_keep_i(live, SIMD_NAME(course_project)(h, fd, k));
}

/* Column u of mode course: docs/KERNELS.md's lanes = distances. qx, qy hold the column's
 * positions on entry and the next column's on return: every accumulator is sampled (until the
 * early exit), then all advance, the additions of SEMANTICS.md in their order. The loads of the
 * next two vectors issue before the scan's branches: the cell gathers, not the arithmetic, are
 * what a vector waits on. This column does not skip (docs/SKIPPING.md, mode course). */
RETRO_SIMD_INLINE void
SIMD_NAME(course_column)(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k, float *qx,
                         float *qy, int u, const int packed)
{
    const int D = f->D;
    int y = 0, d = 1;
    simd_i32 at0, v0 = SIMD_NAME(course_sample)(f, sf, k, qx, qy, d, &at0, packed);
    simd_i32 at1 = v_zero_i(), v1 = v_zero_i();
    if (d + SIMD_LANES < D)
        v1 = SIMD_NAME(course_sample)(f, sf, k, qx, qy, d + SIMD_LANES, &at1, packed);
    for (; d < D && y < f->vcap[d]; d += SIMD_LANES) {
        simd_i32 at_d = at0, v_d = v0;
        at0 = at1;
        v0 = v1;
        if (d + 2 * SIMD_LANES < D)
            v1 = SIMD_NAME(course_sample)(f, sf, k, qx, qy, d + 2 * SIMD_LANES, &at1, packed);
        y = SIMD_NAME(course_scan)(f, u, y, v_d, at_d, packed);
    }
    retro_simd_span(f, u, y, f->H, f->sky);
    for (int e = 1; e < D; e += SIMD_LANES) {
        const int n = D - e;
        const simd_mask live = v_first(n);
        simd_f32 x = v_load_first_f(qx + e, n, live), z = v_load_first_f(qy + e, n, live);
        v_store_first_f(qx + e, n, live, v_add_f(x, v_load_first_f(f->sx + e, n, live)));
        v_store_first_f(qy + e, n, live, v_add_f(z, v_load_first_f(f->sy + e, n, live)));
    }
}
