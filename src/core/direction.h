/* The view direction both families derive from the course's integer angle (SEMANTICS.md step
 * 1), kept in one place so the voxel frame and the mesh frame cannot turn differently. Inline in
 * the header, as each frame setup had it before. */
#ifndef RETRO_DIRECTION_H
#define RETRO_DIRECTION_H

#include <math.h>

/* cos and sin of angle degrees in double. A quarter turn only swaps and negates the pair, so
 * reducing to the first quadrant first makes 90, 180 and 270 exact (the remainder is then 0,
 * and cos(0), sin(0) are 1 and 0 on every libm) and any angle agree with its equivalents mod
 * 360. */
static inline void retro_direction(int angle, double *cs, double *sn)
{
    int a = angle % 360;
    if (a < 0)
        a += 360;
    int q = a / 90, r = a % 90;
    double rad = (double)r * 3.14159265358979323846 / 180.0;
    double c0 = cos(rad), s0 = sin(rad);
    static const double csign[4] = {1, -1, -1, 1}, ssign[4] = {1, 1, -1, -1};
    *cs = csign[q] * ((q & 1) ? s0 : c0);
    *sn = ssign[q] * ((q & 1) ? c0 : s0);
}

#endif
