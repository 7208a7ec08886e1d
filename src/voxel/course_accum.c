/* Mode course's accumulated positions (SEMANTICS.md): line d starts at (lx, ly) and steps by
 * (sx, sy) after every column. Kept in one place so every kernel and every thread performs the
 * same additions in the same order, which is what keeps strips bit-exact. */
#include <string.h>

#include "kernels.h"

void retro_course_start(const retro_frame *f, float *qx, float *qy)
{
    if (f->mode != RETRO_MODE_COURSE)
        return;
    for (int d = 1; d < f->D; d++) {
        qx[d] = f->lx[d];
        qy[d] = f->ly[d];
    }
}

/* Distance-outer in blocks of 16 accumulators held in registers across the columns (GCC/Clang
 * vectors of 4 floats, SSE2 on x86-64): each accumulator still sees its additions in column
 * order, one rounding each, so the values are those of column-by-column stepping, while a block
 * is loaded and stored once instead of once per column. The threaded kernels replay the other
 * threads' columns here. A block of 16 is 8 independent chains of additions per column (4 for
 * x, 4 for y): with the 4 chains of a block of 8, each addition waited on the one before it in
 * its chain instead of issuing at the adders' rate (docs/studies/KERNEL_STUDIES.md, "Mode course
 * on threads", has the measurement). */
typedef float retro_v4f __attribute__((vector_size(16)));
enum { RETRO_ADVANCE_VECTORS = 4, RETRO_ADVANCE_BLOCK = 4 * RETRO_ADVANCE_VECTORS };
static inline retro_v4f v4_at(const float *p)
{
    retro_v4f v;
    memcpy(&v, p, sizeof v);
    return v;
}
static inline void v4_put(float *p, retro_v4f v)
{
    memcpy(p, &v, sizeof v);
}
/* Accumulators d0..d0+15 of rows qx and qy, stepped over `columns` columns. The loops over the
 * vectors are unrolled so that the chains stay in registers (-O2 alone keeps arrays in memory). */
#define RETRO_ADVANCE_UNROLLED _Pragma("GCC unroll 4")
static inline void advance_block(float *qx, float *qy, const float *sx, const float *sy, int columns)
{
    retro_v4f x[RETRO_ADVANCE_VECTORS], y[RETRO_ADVANCE_VECTORS], a[RETRO_ADVANCE_VECTORS], b[RETRO_ADVANCE_VECTORS];
    RETRO_ADVANCE_UNROLLED
    for (int k = 0; k < RETRO_ADVANCE_VECTORS; k++) {
        x[k] = v4_at(qx + 4 * k);
        y[k] = v4_at(qy + 4 * k);
        a[k] = v4_at(sx + 4 * k);
        b[k] = v4_at(sy + 4 * k);
    }
    for (int u = 0; u < columns; u++) {
        RETRO_ADVANCE_UNROLLED
        for (int k = 0; k < RETRO_ADVANCE_VECTORS; k++) {
            x[k] += a[k];
            y[k] += b[k];
        }
    }
    RETRO_ADVANCE_UNROLLED
    for (int k = 0; k < RETRO_ADVANCE_VECTORS; k++) {
        v4_put(qx + 4 * k, x[k]);
        v4_put(qy + 4 * k, y[k]);
    }
}

void retro_course_advance(const retro_frame *f, float *qx, float *qy, int u0, int u1)
{
    if (f->mode != RETRO_MODE_COURSE || u1 <= u0)
        return;
    const int D = f->D, columns = u1 - u0;
    int d = 1;
    for (; d + RETRO_ADVANCE_BLOCK <= D; d += RETRO_ADVANCE_BLOCK)
        advance_block(qx + d, qy + d, f->sx + d, f->sy + d, columns);
    if (d < D) { /* the last D - d accumulators, through a zero-padded block */
        const size_t n = (size_t)(D - d);
        float t[4][RETRO_ADVANCE_BLOCK] = {{0}};
        memcpy(t[0], qx + d, n * sizeof(float));
        memcpy(t[1], qy + d, n * sizeof(float));
        memcpy(t[2], f->sx + d, n * sizeof(float));
        memcpy(t[3], f->sy + d, n * sizeof(float));
        advance_block(t[0], t[1], t[2], t[3], columns);
        memcpy(qx + d, t[0], n * sizeof(float));
        memcpy(qy + d, t[1], n * sizeof(float));
    }
}

void retro_course_seek(const retro_frame *f, float *qx, float *qy, int at, int u)
{
    if (f->mode != RETRO_MODE_COURSE)
        return;
    if (u < at) { /* the accumulators only add: start them again at the first column */
        retro_course_start(f, qx, qy);
        at = 0;
    }
    retro_course_advance(f, qx, qy, at, u);
}
