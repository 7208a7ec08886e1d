/* Part of simd_strip_tpl.h, whose contract applies, included by it once per ISA file: the
 * frame's broadcast constants, the wraps, the map reads and the projections, and one distance's
 * samples of a group (plain or bilinear) with their colours. */

/* The frame's constants, broadcast once. */
typedef struct {
    simd_i32 tiles;       /* tiles per row of the packed map */
    simd_i32 S;           /* map size, for row-major indices */
    simd_i32 height;      /* camera height, int32 (retro_simd_check checked the range) */
    simd_i32 H;           /* H */
    simd_f32 fH;          /* H */
    /* mode exact */
    simd_f32 x0, y0;      /* position reduced modulo S */
    simd_f32 half_h;      /* 0.5f * H */
    simd_f32 fS, inv_S;   /* S and 1/S, for the float remainder */
    simd_i32 wrap;        /* S - 1 when S is a power of two */
    /* mode course */
    simd_f32 fK, inv_K;   /* the wrap period S - 1 and its reciprocal */
    simd_f32 course_lo, course_hi, course_negK; /* -2K and 3K: course_wrap2's range; -K */
    simd_f32 cw2;         /* (float)(W / 2) */
    simd_i32 ch2;         /* H / 2 */
    /* bilinear */
    simd_f32 fheight;     /* (float)height */
    int dh_f32;           /* |height| <= 2^24: (float)height is exact (bilinear_dh) */
} SIMD_NAME(consts);

static void SIMD_NAME(init_consts)(SIMD_NAME(consts) *k, const retro_frame *f, const retro_simd_frame *sf)
{
    k->tiles = v_set1_i(sf->tiles);
    k->S = v_set1_i(f->S);
    k->height = v_set1_i(sf->height);
    k->H = v_set1_i(f->H);
    k->fH = v_set1_f((float)f->H);
    k->x0 = v_set1_f(f->x0);
    k->y0 = v_set1_f(f->y0);
    k->half_h = v_set1_f(f->half_h);
    k->fS = v_set1_f(sf->fS);
    k->inv_S = v_set1_f(sf->inv_S);
    k->wrap = v_set1_i(sf->pow2_mask);
    k->fK = v_set1_f(sf->fK);
    k->inv_K = v_set1_f(sf->inv_K);
    k->course_lo = v_set1_f(-2.0f * sf->fK);
    k->course_hi = v_set1_f(3.0f * sf->fK);
    k->course_negK = v_set1_f(-sf->fK);
    k->cw2 = v_set1_f(f->cw2);
    k->ch2 = v_set1_i(f->ch2);
    k->fheight = v_set1_f((float)sf->height);
    k->dh_f32 = sf->height >= -(1 << 24) && sf->height <= (1 << 24);
}

/* floor(q) mod S for a power-of-two S: the two's-complement mask is the non-negative remainder. */
RETRO_SIMD_INLINE simd_i32 SIMD_NAME(wrap_pow2)(simd_f32 q, const SIMD_NAME(consts) *k)
{
    return v_and_i(v_floor_i(q), k->wrap);
}

/* floor(q) mod S for any S, in float and exact (docs/KERNELS.md, "Wrap"): |floor(q)| < 2^23,
 * so n = floor(floor(q) / S) computed with 1/S is off by at most one, r = floor(q) - n*S is
 * an exact integer, and one conditional +S and one -S put it in [0, S). */
RETRO_SIMD_INLINE simd_i32 SIMD_NAME(wrap_any)(simd_f32 q, const SIMD_NAME(consts) *k)
{
    simd_f32 fl = v_floor_f(q);
    simd_f32 n = v_floor_f(v_mul_f(fl, k->inv_S));
    simd_f32 r = v_sub_f(fl, v_mul_f(n, k->fS));
    r = v_add_where(v_flt(r, v_zero_f()), r, k->fS);
    r = v_sub_where(v_fge(r, k->fS), r, k->fS);
    return v_cvtt_i(r);
}

/* (int)float_mod(q, S - 1) for |q| < 2^23 (docs/KERNELS.md, "Course wrap"): fmodf by one
 * truncated quotient and one correction, then the course's float_mod steps as written. */
/* The cell of fmodf's remainder r: float_mod's rounded addition of K to a negative r, then
 * 0 for a sum that rounded up to K. */
RETRO_SIMD_INLINE simd_i32 SIMD_NAME(course_cell)(simd_f32 r, const SIMD_NAME(consts) *k)
{
    const simd_f32 K = k->fK;
    r = v_add_where(v_flt(r, v_zero_f()), r, K);
    return v_cvtt_i(v_keep_f(v_flt(r, K), r));
}

RETRO_SIMD_INLINE simd_i32 SIMD_NAME(course_wrap)(simd_f32 q, const SIMD_NAME(consts) *k)
{
    const simd_f32 zero = v_zero_f(), K = k->fK;
    simd_f32 n = v_trunc_f(v_mul_f(q, k->inv_K));
    simd_f32 r = v_sub_f(q, v_mul_f(n, K));
    simd_mask neg = v_flt(q, zero);
    /* fmodf: r takes q's sign and |r| < k */
    r = v_add_where(v_mandnot(neg, v_flt(r, zero)), r, K);
    r = v_sub_where(v_mandnot(neg, v_fge(r, K)), r, K);
    r = v_sub_where(v_mand(neg, v_fgt(r, zero)), r, K);
    r = v_add_where(v_mand(neg, v_fle(r, v_sub_f(zero, K))), r, K);
    return SIMD_NAME(course_cell)(r, k);
}

/* course_wrap of q in (-2K, 3K) (course_wrap2, where it is proved). */
RETRO_SIMD_INLINE simd_i32 SIMD_NAME(course_wrap_near)(simd_f32 q, const SIMD_NAME(consts) *k)
{
    const simd_f32 K = k->fK;
    simd_f32 r = v_sub_where(v_fge(q, K), q, K);
    r = v_sub_where(v_fge(r, K), r, K);
    r = v_add_where(v_fle(r, k->course_negK), r, K);
    return SIMD_NAME(course_cell)(r, k);
}

/* course_wrap of x and of z, by fewer steps when every lane of both lies in (-2K, 3K), which
 * the positions of a frame at a usual distance do. Proof that the result is the same: K is an
 * integer below 2^14 (S <= RETRO_MAX_MAP), and for |q| < 3K < 2^24 every float q is a
 * multiple of ulp(q) <= 1, so K is one too, and q - K (or q + K) of magnitude at most |q| is
 * an exact float (a multiple of ulp(q) below 2^(e+1), q in [2^e, 2^(e+1))). So for q in
 * [K, 3K) one or two subtractions of K give q - nK, the exact fmodf, in [0, K); for q in
 * (-2K, -K] one addition gives q + K, fmodf's exact value in (-K, 0] (fmodf gives -0 at
 * q = -K, this +0: both become cell 0 below); for q in (-K, K) fmodf is q. Then course_cell,
 * course_wrap's own last steps, takes the same remainder to its cell. A NaN lane fails the
 * range test and sends the vector through course_wrap. tests/test_hard_cases.c
 * (course_wrap_ranges) puts vectors on every bound. */
RETRO_SIMD_INLINE void SIMD_NAME(course_wrap2)(simd_f32 x, simd_f32 z, const SIMD_NAME(consts) *k, simd_i32 *i,
                                               simd_i32 *j)
{
    const unsigned all = (1u << SIMD_LANES) - 1;
    const simd_f32 lo = k->course_lo, hi = k->course_hi;
    if ((v_bits(v_mand(v_fgt(x, lo), v_flt(x, hi))) & v_bits(v_mand(v_fgt(z, lo), v_flt(z, hi)))) != all) {
        *i = SIMD_NAME(course_wrap)(x, k);
        *j = SIMD_NAME(course_wrap)(z, k);
        return;
    }
    *i = SIMD_NAME(course_wrap_near)(x, k);
    *j = SIMD_NAME(course_wrap_near)(z, k);
}

/* The index of cell (i, j) in the tiled maps (simd_common.h's retro_simd_tiled). */
RETRO_SIMD_INLINE simd_i32 SIMD_NAME(tiled)(const SIMD_NAME(consts) *k, simd_i32 i, simd_i32 j)
{
    const simd_i32 low = v_set1_i(RETRO_SIMD_TILE - 1);
    simd_i32 tile = v_add_i(v_mullo_i(v_srli_i(j, 2), k->tiles), v_srli_i(i, 2));
    simd_i32 within = v_or_i(v_slli_i(v_and_i(j, low), 2), v_and_i(i, low));
    return v_or_i(v_slli_i(tile, 4), within);
}

/* The heights of cells (i, j). *at receives what the colours need: the packed cell itself, or
 * the row-major index when the maps are read directly. */
RETRO_SIMD_INLINE simd_i32 SIMD_NAME(heights)(const retro_frame *f, const retro_simd_frame *sf,
                                              const SIMD_NAME(consts) *k, simd_i32 i, simd_i32 j, simd_i32 *at,
                                              const int packed)
{
    if (packed) {
        *at = v_gather_cells(sf->cells, SIMD_NAME(tiled)(k, i, j));
        return v_and_i(*at, v_set1_i(RETRO_SIMD_HEIGHT_MASK));
    }
    *at = v_add_i(v_mullo_i(j, k->S), i);
    return v_gather_bytes(f->height_map, *at);
}

/* SEMANTICS.md step 6 on every lane; clamping to [0, H] before truncating is the same
 * three-way case, since truncation is the floor for 0 <= vf. */
RETRO_SIMD_INLINE simd_i32 SIMD_NAME(exact_project)(simd_i32 h, float kd, const SIMD_NAME(consts) *k)
{
    simd_f32 dh = v_cvt_f(v_sub_i(h, k->height));
    simd_f32 vf = v_add_f(v_mul_f(v_set1_f(kd), dh), k->half_h);
    vf = v_min_f(v_max_f(vf, v_zero_f()), k->fH);
    return v_cvtt_i(vf);
}

/* retro_course_row() on every lane, clamped at RETRO_SIMD_ROW_CLAMP first to stay in int. */
RETRO_SIMD_INLINE simd_i32 SIMD_NAME(course_project)(simd_i32 h, simd_f32 fd, const SIMD_NAME(consts) *k)
{
    simd_f32 dh = v_cvt_f(v_sub_i(h, k->height));
    simd_f32 t = v_div_f(v_mul_f(k->cw2, dh), fd);
    t = v_min_f(v_max_f(t, v_set1_f(-RETRO_SIMD_ROW_CLAMP)), v_set1_f(RETRO_SIMD_ROW_CLAMP));
    simd_i32 v = v_add_i(v_cvtt_i(t), k->ch2);
    return v_min_i(v_max_i(v, v_zero_i()), k->H);
}

/* Bilinear's Δ = (float)((double)hf - height) (docs/EFFECTS.md) by one float subtraction where
 * that is the same value: wherever |height| <= 2^24; else in double, two conversions each way.
 * Proof: with |height| <= 2^24, (float)height is exact, so both compute from the same two
 * binary32 operands hf and height. The float subtraction rounds their exact difference once to
 * nearest. The definition rounds it to binary64 and then to binary32, and for a sum or
 * difference of two binary32 values that double rounding gives the same result as one, since
 * binary64's 53 bits are at least 2 x 24 + 1 (Figueroa, "When is double rounding innocuous?",
 * 1995): however small hf is. skipping/bilinear_height_difference checks frames on both sides
 * of 2^24 and with filtered heights just above 0, skipping/bilinear_float_difference the
 * rounding fact itself. The skip probe's bound goes through here too (simd_skip_tpl.h). */
RETRO_SIMD_INLINE simd_f32 SIMD_NAME(bilinear_dh)(simd_f32 hf, const retro_frame *f, const SIMD_NAME(consts) *k)
{
    if (k->dh_f32)
        return v_sub_f(hf, k->fheight);
    return v_sub_f64(hf, (double)f->height);
}

/* What one distance's samples leave for projecting and painting them. */
typedef struct {
    simd_i32 h;      /* the cells' heights (bilinear: unused) */
    simd_f32 dh;     /* bilinear: the filtered height minus the camera's, rounded once */
    simd_i32 at[4];  /* what the colours need: the packed cells or their row-major indices
                      * (bilinear: the four corners, docs/EFFECTS.md's order; else at[0];
                      * bilinear from quads: i0, i1, j0, j1) */
    simd_f32 tx, ty; /* bilinear: the weights */
} SIMD_NAME(sample_t);

/* Steps 4-5 of SEMANTICS.md at distance d for every lane (with bilinear, docs/EFFECTS.md's
 * filtered height, each float operation in the order written there). */
RETRO_SIMD_INLINE void
SIMD_NAME(sample)(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k, simd_f32 rx,
                  simd_f32 ry, int d, SIMD_NAME(sample_t) *s, const int pow2, const int packed, const int bilinear)
{
    simd_f32 fd = v_set1_f((float)d);
    simd_f32 qx = v_add_f(k->x0, v_mul_f(fd, rx));
    simd_f32 qy = v_add_f(k->y0, v_mul_f(fd, ry));
    if (!bilinear) {
        simd_i32 i = pow2 ? SIMD_NAME(wrap_pow2)(qx, k) : SIMD_NAME(wrap_any)(qx, k);
        simd_i32 j = pow2 ? SIMD_NAME(wrap_pow2)(qy, k) : SIMD_NAME(wrap_any)(qy, k);
        s->h = SIMD_NAME(heights)(f, sf, k, i, j, &s->at[0], packed);
        return;
    }
    const simd_f32 half = v_set1_f(0.5f), one = v_set1_f(1.0f);
    const simd_i32 one_i = v_set1_i(1);
    simd_f32 px = v_sub_f(qx, half), py = v_sub_f(qy, half);
    simd_i32 i0 = pow2 ? SIMD_NAME(wrap_pow2)(px, k) : SIMD_NAME(wrap_any)(px, k);
    simd_i32 j0 = pow2 ? SIMD_NAME(wrap_pow2)(py, k) : SIMD_NAME(wrap_any)(py, k);
    simd_i32 i1 = v_add_i(i0, one_i), j1 = v_add_i(j0, one_i);
    i1 = v_keep_i(v_igt(k->S, i1), i1); /* i0 + 1 == S wraps to 0 */
    j1 = v_keep_i(v_igt(k->S, j1), j1);
    s->tx = v_sub_f(px, v_floor_f(px));
    s->ty = v_sub_f(py, v_floor_f(py));
    simd_f32 h00, h10, h01, h11;
    if (packed && sf->quads) { /* one load for the four heights; colours when painting */
        const simd_i32 byte = v_set1_i(0xff);
        simd_i32 q = v_gather_cells(sf->quads, SIMD_NAME(tiled)(k, i0, j0));
        h00 = v_cvt_f(v_and_i(q, byte));
        h10 = v_cvt_f(v_byte_i(q, 1));
        h01 = v_cvt_f(v_byte_i(q, 2));
        h11 = v_cvt_f(v_srli_i(q, 24));
        s->at[0] = i0;
        s->at[1] = i1;
        s->at[2] = j0;
        s->at[3] = j1;
    } else {
        h00 = v_cvt_f(SIMD_NAME(heights)(f, sf, k, i0, j0, &s->at[0], packed));
        h10 = v_cvt_f(SIMD_NAME(heights)(f, sf, k, i1, j0, &s->at[1], packed));
        h01 = v_cvt_f(SIMD_NAME(heights)(f, sf, k, i0, j1, &s->at[2], packed));
        h11 = v_cvt_f(SIMD_NAME(heights)(f, sf, k, i1, j1, &s->at[3], packed));
    }
    simd_f32 wx = v_sub_f(one, s->tx), wy = v_sub_f(one, s->ty);
    simd_f32 hf = v_add_f(v_mul_f(v_add_f(v_mul_f(h00, wx), v_mul_f(h10, s->tx)), wy),
                          v_mul_f(v_add_f(v_mul_f(h01, wx), v_mul_f(h11, s->tx)), s->ty));
    s->dh = SIMD_NAME(bilinear_dh)(hf, f, k);
}

/* The row of each lane's sample: step 6 on the height or, with bilinear, on dh. */
RETRO_SIMD_INLINE simd_i32 SIMD_NAME(project)(const SIMD_NAME(sample_t) *s, float kd, const SIMD_NAME(consts) *k,
                                          const int bilinear)
{
    if (!bilinear)
        return SIMD_NAME(exact_project)(s->h, kd, k);
    simd_f32 vf = v_add_f(v_mul_f(v_set1_f(kd), s->dh), k->half_h);
    vf = v_min_f(v_max_f(vf, v_zero_f()), k->fH);
    return v_cvtt_i(vf);
}

/* One channel of the bilinear colour, its four corners' bytes in float: (int)(value + 0.5f). */
static inline simd_i32 SIMD_NAME(bilerp_channel)(simd_i32 c00, simd_i32 c10, simd_i32 c01, simd_i32 c11,
                                                 const SIMD_NAME(sample_t) *s)
{
    const simd_f32 one = v_set1_f(1.0f);
    simd_f32 wx = v_sub_f(one, s->tx), wy = v_sub_f(one, s->ty);
    simd_f32 v = v_add_f(v_mul_f(v_add_f(v_mul_f(v_cvt_f(c00), wx), v_mul_f(v_cvt_f(c10), s->tx)), wy),
                         v_mul_f(v_add_f(v_mul_f(v_cvt_f(c01), wx), v_mul_f(v_cvt_f(c11), s->tx)), s->ty));
    return v_cvtt_i(v_add_f(v, v_set1_f(0.5f)));
}

/* The colours of the lanes in m (bilinear: filtered per channel, docs/EFFECTS.md). */
RETRO_SIMD_INLINE simd_i32 SIMD_NAME(colours)(const retro_frame *f, const retro_simd_frame *sf,
                                              const SIMD_NAME(consts) *k, const SIMD_NAME(sample_t) *s,
                                              simd_mask m, const int packed, const int bilinear)
{
    if (!bilinear)
        return packed ? v_and_i(s->at[0], v_set1_i((int)RETRO_SIMD_COLOR_MASK))
                      : v_gather_colours(f->color_map, s->at[0], m);
    simd_i32 c[4];
    if (packed && sf->quads) { /* at holds i0, i1, j0, j1; the shifts drop a cell's height byte */
        c[0] = v_gather_colours(sf->cells, SIMD_NAME(tiled)(k, s->at[0], s->at[2]), m);
        c[1] = v_gather_colours(sf->cells, SIMD_NAME(tiled)(k, s->at[1], s->at[2]), m);
        c[2] = v_gather_colours(sf->cells, SIMD_NAME(tiled)(k, s->at[0], s->at[3]), m);
        c[3] = v_gather_colours(sf->cells, SIMD_NAME(tiled)(k, s->at[1], s->at[3]), m);
    } else
        for (int i = 0; i < 4; i++) /* a packed cell's low byte is its height: the shifts drop it */
            c[i] = packed ? s->at[i] : v_gather_colours(f->color_map, s->at[i], m);
/* byte 3 by a shift alone; the others by one byte shuffle where the ISA has one (v_byte_i), not
 * a shift and a mask: a painting step extracts twelve of them */
#define SIMD_BYTE(x, sh) ((sh) == 24 ? v_srli_i(x, 24) : v_byte_i(x, (sh) / 8))
    simd_i32 r = SIMD_NAME(bilerp_channel)(SIMD_BYTE(c[0], 24), SIMD_BYTE(c[1], 24), SIMD_BYTE(c[2], 24),
                                           SIMD_BYTE(c[3], 24), s);
    simd_i32 g = SIMD_NAME(bilerp_channel)(SIMD_BYTE(c[0], 16), SIMD_BYTE(c[1], 16), SIMD_BYTE(c[2], 16),
                                           SIMD_BYTE(c[3], 16), s);
    simd_i32 b = SIMD_NAME(bilerp_channel)(SIMD_BYTE(c[0], 8), SIMD_BYTE(c[1], 8), SIMD_BYTE(c[2], 8),
                                           SIMD_BYTE(c[3], 8), s);
#undef SIMD_BYTE
    return v_or_i(v_or_i(v_slli_i(r, 24), v_slli_i(g, 16)), v_slli_i(b, 8));
}

/* The colour of one lane, from its entry of what heights() left in at. */
RETRO_SIMD_INLINE uint32_t SIMD_NAME(colour_of)(const retro_frame *f, uint32_t at, const int packed)
{
    return packed ? at & RETRO_SIMD_COLOR_MASK : f->color_map[at];
}
