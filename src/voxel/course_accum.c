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

/* Distance-outer in blocks of 8 accumulators held in registers across the columns (GCC/Clang
 * vectors of 4 floats, SSE2 on x86-64): each accumulator still sees its additions in column
 * order, one rounding each, so the values are those of column-by-column stepping, while a block
 * is loaded and stored once instead of once per column. The threaded kernels replay the other
 * threads' columns here, half the frame's on two threads. */
typedef float retro_v4f __attribute__((vector_size(16)));
enum { RETRO_ADVANCE_BLOCK = 8 };
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
/* Accumulators d0..d0+7 of rows qx and qy, stepped over `columns` columns. */
static inline void advance_block(float *qx, float *qy, const float *sx, const float *sy, int columns)
{
    retro_v4f x0 = v4_at(qx), x1 = v4_at(qx + 4), y0 = v4_at(qy), y1 = v4_at(qy + 4);
    const retro_v4f a0 = v4_at(sx), a1 = v4_at(sx + 4), b0 = v4_at(sy), b1 = v4_at(sy + 4);
    for (int u = 0; u < columns; u++) {
        x0 += a0;
        x1 += a1;
        y0 += b0;
        y1 += b1;
    }
    v4_put(qx, x0);
    v4_put(qx + 4, x1);
    v4_put(qy, y0);
    v4_put(qy + 4, y1);
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
