/* Shared by the kernels: cell lookup, row projection and the one pixel store, so that every
 * kernel evaluates SEMANTICS.md with the same float operations in the same order. */
#ifndef RETRO_INTERNAL_H
#define RETRO_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "retro.h"

/* Helpers below are static inline in a header; in the single-file submission they become part
 * of one .c file, where clang would warn about the ones it does not call. */
#define RETRO_HELPER static inline __attribute__((unused))

/* The course's float_mod. */
float retro_float_mod(float f, float k);
/* Releases the thread pool of parallel kernels, if any. */
void retro_pool_free(retro_ctx *rc);

/* Row v in 0..H of a sample in mode exact (SEMANTICS.md step 6). */
RETRO_HELPER int retro_exact_row(float kd, float half_h, int H, int64_t dh)
{
    float vf = kd * (float)dh + half_h;
    if (vf >= (float)H)
        return H;
    if (vf >= 0.0f)
        return (int)vf; /* vf is non-negative: truncation is the floor */
    return 0;
}

/* Row v in 0..H of a sample in mode course: the course truncates, adds H/2 and clamps; done in
 * double so a huge value saturates instead of overflowing int. */
RETRO_HELPER int retro_course_row(float cw2, int ch2, int H, int64_t dh, int d)
{
    float f = cw2 * (float)dh / (float)d;
    double v = trunc((double)f) + (double)ch2;
    if (v >= (double)H)
        return H;
    if (v <= 0.0)
        return 0;
    return (int)v;
}

/* Row v of a sample in mode truth: step 6 in binary64. */
RETRO_HELPER int retro_truth_row(double kd, double half_h, int H, int64_t dh)
{
    double vf = kd * (double)dh + half_h;
    if (vf >= (double)H)
        return H;
    if (vf >= 0.0)
        return (int)vf;
    return 0;
}

/* Row v of a sample in mode fixed: VF = K_d * dh + H/2 with RETRO_FX_PROJ fractional bits. */
RETRO_HELPER int retro_fixed_row(int64_t kd, int64_t half_h, int H, int64_t dh)
{
    int64_t vf = kd * dh + half_h;
    if (vf >= (int64_t)H << RETRO_FX_PROJ)
        return H;
    if (vf >= 0)
        return (int)(vf >> RETRO_FX_PROJ);
    return 0;
}

/* floor(q) mod S in [0, S). |q| < 2^31 holds for every valid frame (D <= 2^22). */
RETRO_HELPER int retro_cell(float q, int S)
{
    int i = (int)floorf(q) % S;
    return i < 0 ? i + S : i;
}

/* Course-mode cell: (int)float_mod(q, S - 1). A non-finite q (only reachable from positions
 * near FLT_MAX, where the course's C is undefined) reads cell 0 instead of converting NaN. */
RETRO_HELPER int retro_course_cell(float q, int S)
{
    float m = retro_float_mod(q, (float)(S - 1));
    return m >= 0 ? (int)m : 0;
}

/* fmodf(q, k) without the library call or a division, bit for bit, for k a positive integer
 * below 2^15 and inv_k = 1.0f / k. For |q| < 2^22, q * inv_k is within 2^-23 relative of q/k,
 * so n = trunc(q * inv_k) is the true quotient or off by one, and only when q is within that
 * margin of a multiple of k. n*k is an integer below 2^24, so exact. q - n*k is then the true
 * remainder, or differs from it by k: either a value so close to q that the subtraction is
 * exact (Sterbenz), or k plus a remainder tiny against k, which is representable. One
 * correction by k lands on the true remainder, which is representable, so it is exact too.
 * Larger or non-finite q takes the library path. */
RETRO_HELPER float retro_fmod_fast(float q, float k, float inv_k)
{
    if (!(fabsf(q) < 4194304.0f))
        return fmodf(q, k);
    float r = q - truncf(q * inv_k) * k;
    if (q >= 0.0f) {
        if (r < 0.0f)
            r += k;
        else if (r >= k)
            r -= k;
    } else {
        if (r > 0.0f)
            r -= k;
        else if (r <= -k)
            r += k;
    }
    return r == 0.0f ? copysignf(0.0f, q) : r;
}

/* The course's float_mod on top of retro_fmod_fast: the same rounding of res + k. */
RETRO_HELPER float retro_float_mod_fast(float f, float k, float inv_k)
{
    float res = retro_fmod_fast(f, k, inv_k);
    if (res < 0)
        res += k;
    if (res >= k)
        res = 0;
    return res;
}

/* retro_course_cell through retro_float_mod_fast; identical results, for fast kernels.
 * k = S - 1 and inv_k = 1.0f / k are hoisted by the caller. */
RETRO_HELPER int retro_course_cell_fast(float q, float k, float inv_k)
{
    float m = retro_float_mod_fast(q, k, inv_k);
    return m >= 0 ? (int)m : 0;
}

/* floor(v / 2^bits) mod S without shifting a negative value (implementation-defined in C). */
RETRO_HELPER int retro_fixed_cell(int64_t v, int S)
{
    int64_t q = v >= 0 ? v >> RETRO_FX_POS : -((-(v + 1)) >> RETRO_FX_POS) - 1;
    int64_t i = q % S;
    return (int)(i < 0 ? i + S : i);
}

/* The map cell of sample (u, d), u 0-based, in modes exact/lod, truth and fixed. */
RETRO_HELPER size_t retro_exact_sample(const retro_frame *f, int u, int d)
{
    float qx = f->x0 + (float)d * f->rx[u], qy = f->y0 + (float)d * f->ry[u];
    return (size_t)retro_cell(qy, f->S) * (size_t)f->S + (size_t)retro_cell(qx, f->S);
}

RETRO_HELPER size_t retro_truth_sample(const retro_frame *f, int u, int d)
{
    double qx = f->x0_d + (double)d * f->rxd[u], qy = f->y0_d + (double)d * f->ryd[u];
    int64_t i = (int64_t)floor(qx) % f->S, j = (int64_t)floor(qy) % f->S;
    i += i < 0 ? f->S : 0;
    j += j < 0 ? f->S : 0;
    return (size_t)j * (size_t)f->S + (size_t)i;
}

RETRO_HELPER size_t retro_fixed_sample(const retro_frame *f, int u, int d)
{
    int64_t qx = f->x0_fx + (int64_t)d * f->rx_fx[u], qy = f->y0_fx + (int64_t)d * f->ry_fx[u];
    return (size_t)retro_fixed_cell(qy, f->S) * (size_t)f->S + (size_t)retro_fixed_cell(qx, f->S);
}

/* The pixel (u, r), u and r 1-based, r from the bottom, as an index into out. */
RETRO_HELPER size_t retro_pixel(int W, int H, int u, int r)
{
    return (size_t)(H - r) * (size_t)W + (size_t)(u - 1);
}

/* Every store to a frame goes through RETRO_PUT so a test build can count writes per pixel. */
#ifdef RETRO_COUNT_WRITES
void retro_count_write(const uint32_t *out, size_t idx);
#define RETRO_PUT(out, idx, val) (retro_count_write((out), (idx)), (out)[idx] = (val))
#else
#define RETRO_PUT(out, idx, val) ((out)[idx] = (val))
#endif

#endif
