/* Mode course's accumulated positions (SEMANTICS.md): line d starts at (lx, ly) and steps by
 * (sx, sy) after every column. Kept in one place so every kernel and every thread performs the
 * same additions in the same order, which is what keeps strips bit-exact. */
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

void retro_course_advance(const retro_frame *f, float *qx, float *qy, int u0, int u1)
{
    if (f->mode != RETRO_MODE_COURSE)
        return;
    /* Column-outer: the inner loop over d has no dependency, so it vectorises; each
     * accumulator still sees its additions in column order. */
    for (int u = u0; u < u1; u++)
        for (int d = 1; d < f->D; d++) {
            qx[d] += f->sx[d];
            qy[d] += f->sy[d];
        }
}
