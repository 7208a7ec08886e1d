/* Part of simd_strip_tpl.h, whose contract applies, included by it once per ISA file: a column
 * of mode course, its lanes consecutive distances. */

/* Rows e+1..v of a column of the tile (col[r - 1] is row r): whole vectors from e on. The
 * stores past v land on rows the column's next span or its sky fill writes again, since a span
 * starts where the last one ended (the y-buffer), or in the column's padding. */
RETRO_SIMD_INLINE void SIMD_NAME(tile_span)(uint32_t *col, int e, int v, uint32_t colour)
{
    const simd_i32 c = v_set1_i((int)colour);
    for (int i = e; i < v; i += SIMD_LANES)
        v_store_i(col + i, c);
}

/* Rows e+1..v of column u get colour: into the tile's column col, or (col NULL) into out. */
RETRO_SIMD_INLINE void SIMD_NAME(course_span)(const retro_frame *f, uint32_t *col, int u, int e, int v,
                                              uint32_t colour)
{
    if (col)
        SIMD_NAME(tile_span)(col, e, v, colour);
    else
        retro_simd_span(f, u, e, v, colour);
}

/* The y-buffer after each lane of v (an inclusive prefix max from y, in log2(LANES) shifted
 * maxes); *e gets the y-buffer before each lane (the exclusive one). */
RETRO_SIMD_INLINE simd_i32 SIMD_NAME(course_prefix)(int y, simd_i32 v, simd_i32 *e)
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
    *e = V_SHIFT_UP(p, fill, 1);
    return p;
}

/* The y-buffer pass over distances d..d+LANES-1 of column u: lane l paints rows e+1..v_l, as a
 * column span, when v_l exceeds e = max(y, v_<l) (course_prefix). Returns the new y-buffer. */
RETRO_SIMD_INLINE int SIMD_NAME(course_scan)(const retro_frame *f, uint32_t *col, int u, int y, simd_i32 v,
                                             simd_i32 at)
{
    simd_i32 e;
    const simd_i32 p = SIMD_NAME(course_prefix)(y, v, &e);
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
            SIMD_NAME(course_span)(f, col, u, es[l], vs[l], SIMD_NAME(colour_of)(f, as[l], 0));
        }
    }
    return v_last_i(p);
}

#ifdef v_compress_store
/* A tile column's spans in the order they were found: span k paints tile entries e[k] ..
 * e[k + 1] - 1 with at[k]'s colour. Spans are short (a few rows each, often several per
 * vector), so painting each as it is found loops over a vector's painting lanes, a loop whose
 * count the branch predictor cannot know; the list is packed without branches (vector
 * compress) and painted in one loop per column whose inner loop almost always runs once. It
 * holds RETRO_SIMD_SPAN_LIST spans before the finished ones are painted, to keep the strip's
 * stack small; the extra entries take a compress's whole-vector store and the closing end. */
typedef struct {
    int n;
    int e[RETRO_SIMD_SPAN_LIST + SIMD_LANES + 1];
    uint32_t at[RETRO_SIMD_SPAN_LIST + SIMD_LANES];
} SIMD_NAME(spans);

/* Paints spans 0..n-1 of s into col; e[n] is where the last one ends. Each vector store may
 * run past its span's end: into the next span, stored after it, or into the rows that the
 * column's sky fill (after every span) or its padding take. */
RETRO_SIMD_INLINE void SIMD_NAME(spans_paint)(const retro_frame *f, uint32_t *col, const SIMD_NAME(spans) *s, int n)
{
    for (int k = 0; k < n; k++) {
        const simd_i32 c = v_set1_i((int)SIMD_NAME(colour_of)(f, s->at[k], 0));
        int i = s->e[k];
        do {
            v_store_i(col + i, c);
            i += SIMD_LANES;
        } while (i < s->e[k + 1]);
    }
}

/* course_scan for a column of the tile: the same y-buffer pass, the painting lanes' spans
 * appended to s instead of painted. */
RETRO_SIMD_INLINE int SIMD_NAME(course_scan_list)(const retro_frame *f, uint32_t *col, SIMD_NAME(spans) *s, int y,
                                                  simd_i32 v, simd_i32 at)
{
    simd_i32 e;
    const simd_i32 p = SIMD_NAME(course_prefix)(y, v, &e);
    const simd_mask up = v_igt(v, e);
    const int m = __builtin_popcount(v_bits(up));
    SIMD_COUNT_LANES(painting, m);
    int n = s->n;
    v_compress_store(s->e + n, up, e);
    v_compress_store((int *)s->at + n, up, at);
    n += m;
    if (n > RETRO_SIMD_SPAN_LIST) { /* all but the last span have their ends */
        SIMD_NAME(spans_paint)(f, col, s, n - 1);
        s->e[0] = s->e[n - 1];
        s->at[0] = s->at[n - 1];
        n = 1;
    }
    s->n = n;
    return v_last_i(p);
}
#endif

/* The rows of distances d..d+LANES-1 (those below D; the others get v = 0) of the column whose
 * positions qx, qy hold, and in *at what the scan needs for colours. */
RETRO_SIMD_INLINE simd_i32
SIMD_NAME(course_sample)(const retro_frame *f, const retro_simd_frame *sf, const SIMD_NAME(consts) *k,
                         const float *qx, const float *qy, int d, simd_i32 *at, const int steps)
{
    const int n = f->D - d;
    const simd_mask live = v_first(n);
    SIMD_COUNT_LANES(evaluated, n < SIMD_LANES ? n : SIMD_LANES);
    simd_f32 x = v_load_first_f(qx + d, n, live), z = v_load_first_f(qy + d, n, live);
    for (int c = 0; c < steps; c++) { /* a later column's positions: the advance's very additions */
        x = v_add_f(x, v_load_first_f(f->sx + d, n, live));
        z = v_add_f(z, v_load_first_f(f->sy + d, n, live));
    }
    /* Dead lanes sample cell 0 (their q is 0). */
    simd_i32 i, j;
    SIMD_NAME(course_wrap2)(x, z, k, &i, &j);
    simd_i32 h;
    if (f->S < 2) {
        h = SIMD_NAME(heights)(f, sf, k, i, j, at, 0);
    } else {
        /* A cell of the course's torus has i, j <= S - 2, so its row-major index is at most
         * S*S - S - 2 and the bytes after it up to index + 3 <= S*S - S + 1 < S*S lie in the
         * map (S >= 2): the padded gather reads only the height map's own bytes. */
        *at = v_add_i(v_mullo_i(j, k->S), i);
        h = v_gather_bytes_pad(f->height_map, *at);
    }
    simd_f32 fd = v_add_f(v_set1_f((float)d), v_iota_f());
    return v_keep_i(live, SIMD_NAME(course_project)(h, fd, k));
}

/* The chains' loops run unrolled, so that their vectors stay in registers (-O2 alone keeps
 * the arrays in memory); the count is at least RETRO_SIMD_COURSE_CHAINS. */
#define RETRO_CHAINS_UNROLLED _Pragma("GCC unroll 4")

/* retro_course_advance(f, qx, qy, u, u + N) at this file's vector width: every accumulator
 * gets its N additions in column order, so the values are the same. The strip advances after
 * every group of columns, and A/B benchmark runs found the baseline-ISA advance (4 floats per
 * vector, out of line) measurably slower here; the threads' replays of whole ranges of
 * columns stay with retro_course_advance. */
RETRO_SIMD_INLINE void SIMD_NAME(course_advance)(const retro_frame *f, float *qx, float *qy, const int N)
{
    for (int e = 1; e < f->D; e += SIMD_LANES) {
        const int n = f->D - e;
        const simd_mask m = v_first(n);
        const simd_f32 sx = v_load_first_f(f->sx + e, n, m), sy = v_load_first_f(f->sy + e, n, m);
        simd_f32 x = v_load_first_f(qx + e, n, m), z = v_load_first_f(qy + e, n, m);
        RETRO_CHAINS_UNROLLED
        for (int c = 0; c < N; c++) {
            x = v_add_f(x, sx);
            z = v_add_f(z, sy);
        }
        v_store_first_f(qx + e, n, m, x);
        v_store_first_f(qy + e, n, m, z);
    }
}

/* Columns u..u+N-1 (N <= RETRO_SIMD_COURSE_CHAINS) of mode course: docs/KERNELS.md's lanes =
 * distances. qx, qy hold column u's positions on entry and column u+N's on return. Column u+c
 * samples column u's accumulators plus c steps, the very additions of SEMANTICS.md in their
 * order, so it samples what column-by-column stepping would; afterwards every accumulator
 * advances N times, in the same order (until its early exit a column samples, and every
 * accumulator advances, past the exit too). The N columns are independent chains walked in one
 * loop, and each column's next two vectors are sampled before the scans' branches: the cell
 * gathers, not the arithmetic, are what a vector waits on, and one column's scan runs while
 * the others' gathers are in flight. A column stops at its own early exit. This column does not
 * skip (docs/SKIPPING.md, mode course). Column c paints into cols[c], a column of the strip's
 * tile (course_group), or into out when cols[c] is NULL; with v_compress_store, a tile column
 * lists its spans as it goes and paints them when it stops (course_scan_list). */
RETRO_SIMD_INLINE void SIMD_NAME(course_cols)(const retro_frame *f, const retro_simd_frame *sf,
                                              const SIMD_NAME(consts) *k, float *qx, float *qy, uint32_t *const *cols,
                                              int u, const int N)
{
    const int D = f->D;
    int y[RETRO_SIMD_COURSE_CHAINS] = {0}, d = 1;
    simd_i32 at0[RETRO_SIMD_COURSE_CHAINS], v0[RETRO_SIMD_COURSE_CHAINS];
    simd_i32 at1[RETRO_SIMD_COURSE_CHAINS], v1[RETRO_SIMD_COURSE_CHAINS];
#ifdef v_compress_store /* a tile's columns list their spans */
    SIMD_NAME(spans) spans[RETRO_SIMD_COURSE_CHAINS];
    for (int c = 0; c < N; c++)
        spans[c].n = 0;
#define COURSE_SCAN(c)                                                                                                \
    (cols[0] ? SIMD_NAME(course_scan_list)(f, cols[c], &spans[c], y[c], v[c], at[c])                                 \
             : SIMD_NAME(course_scan)(f, cols[c], u + c, y[c], v[c], at[c]))
#else
#define COURSE_SCAN(c) SIMD_NAME(course_scan)(f, cols[c], u + c, y[c], v[c], at[c])
#endif
    RETRO_CHAINS_UNROLLED
    for (int c = 0; c < N; c++) {
        v0[c] = SIMD_NAME(course_sample)(f, sf, k, qx, qy, d, &at0[c], c);
        at1[c] = v1[c] = v_zero_i();
        if (d + SIMD_LANES < D)
            v1[c] = SIMD_NAME(course_sample)(f, sf, k, qx, qy, d + SIMD_LANES, &at1[c], c);
    }
    for (; d < D; d += SIMD_LANES) {
        const int cap = f->vcap[d], more = d + 2 * SIMD_LANES < D;
        int live = 0;
        simd_i32 at[RETRO_SIMD_COURSE_CHAINS], v[RETRO_SIMD_COURSE_CHAINS];
        RETRO_CHAINS_UNROLLED
        for (int c = 0; c < N; c++) {
            at[c] = at0[c];
            v[c] = v0[c];
            if (y[c] < cap) {
                live |= 1 << c;
                at0[c] = at1[c];
                v0[c] = v1[c];
                if (more)
                    v1[c] = SIMD_NAME(course_sample)(f, sf, k, qx, qy, d + 2 * SIMD_LANES, &at1[c], c);
            }
        }
        if (!live)
            break;
        RETRO_CHAINS_UNROLLED
        for (int c = 0; c < N; c++)
            if (live >> c & 1)
                y[c] = COURSE_SCAN(c);
    }
#ifdef v_compress_store
    if (cols[0]) {
        RETRO_CHAINS_UNROLLED
        for (int c = 0; c < N; c++) {
            spans[c].e[spans[c].n] = y[c];
            SIMD_NAME(spans_paint)(f, cols[c], &spans[c], spans[c].n);
        }
    }
#endif
#undef COURSE_SCAN
    RETRO_CHAINS_UNROLLED
    for (int c = 0; c < N; c++)
        SIMD_NAME(course_span)(f, cols[c], u + c, y[c], f->H, f->sky);
    SIMD_NAME(course_advance)(f, qx, qy, N);
}

/* Columns u..u+n-1 (n <= RETRO_SIMD_COURSE_GROUP) of mode course. Painted straight into out, a
 * column's rows lie W pixels apart, one cache line each, and its spans are scalar stores in
 * loops of data-dependent length; painted into tile (one column every th >= H + LANES
 * entries, row r at r - 1), they are whole-vector stores into a few lines, and out gets each
 * pixel once afterwards, row by row, n adjacent pixels at a time. The tile is the caller's
 * (NULL: paint into out). */
RETRO_SIMD_INLINE void SIMD_NAME(course_group)(const retro_frame *f, const retro_simd_frame *sf,
                                               const SIMD_NAME(consts) *k, float *qx, float *qy, uint32_t *tile,
                                               size_t th, int u, int n)
{
    uint32_t *cols[RETRO_SIMD_COURSE_GROUP];
    for (int c = 0; c < n; c++)
        cols[c] = tile ? tile + (size_t)c * th : NULL;
    int c = 0;
    for (; c + RETRO_SIMD_COURSE_CHAINS <= n; c += RETRO_SIMD_COURSE_CHAINS)
        SIMD_NAME(course_cols)(f, sf, k, qx, qy, cols + c, u + c, RETRO_SIMD_COURSE_CHAINS);
    for (; c < n; c++)
        SIMD_NAME(course_cols)(f, sf, k, qx, qy, cols + c, u + c, 1);
    if (!tile)
        return;
    uint32_t *out = f->out;
    const ptrdiff_t W = f->W;
    ptrdiff_t i = (ptrdiff_t)(f->H - 1) * W + u;
    int r = 0;
#ifdef SIMD_TILE_BLOCK /* the ISA's block transpose (LANES x LANES pixels), for whole groups */
    if (n == RETRO_SIMD_COURSE_GROUP)
        for (; r + SIMD_LANES <= f->H; r += SIMD_LANES, i -= SIMD_LANES * W)
            for (c = 0; c < n; c += SIMD_LANES)
                SIMD_NAME(tile_block)(out, i + c, W, tile + (size_t)c * th + (size_t)r, th);
#endif
    for (; r < f->H; r++, i -= W)
        for (c = 0; c < n; c++)
            RETRO_PUT(out, (size_t)(i + c), tile[(size_t)c * th + (size_t)r]);
}
