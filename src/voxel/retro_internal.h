/* Shared by the kernels: cell lookup, row projection and the one pixel store, so that every
 * kernel evaluates SEMANTICS.md with the same float operations in the same order. */
#ifndef RETRO_INTERNAL_H
#define RETRO_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "retro.h"
#include "ctx.h"
#include "frame.h"

/* Helpers below are static inline in a header; in the single-file submission they become part
 * of one .c file, where clang would warn about the ones it does not call. */
#define RETRO_HELPER static inline __attribute__((unused))

/* The course's float_mod. */
float retro_float_mod(float f, float k);
/* Releases the thread pool of parallel kernels, if any. */
void retro_pool_free(retro_ctx *rc);

/* Row v in 0..H of a sample in mode exact from a height difference already in float. */
RETRO_HELPER int retro_exact_row_f(float kd, float half_h, int H, float dh)
{
    float vf = kd * dh + half_h;
    if (vf >= (float)H)
        return H;
    if (vf >= 0.0f)
        return (int)vf;
    return 0;
}

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

/* Row v of a sample in mode fixed: VF = K_d * dh + H/2 with RETRO_Q_PROJ fractional bits. */
RETRO_HELPER int retro_fixed_row(int64_t kd, int64_t half_h, int H, int64_t dh)
{
    int64_t vf = kd * dh + half_h;
    if (vf >= (int64_t)H << RETRO_Q_PROJ)
        return H;
    if (vf >= 0)
        return (int)(vf >> RETRO_Q_PROJ);
    return 0;
}

/* floor(q) for |q| < 2^31, which holds for every sample of a valid frame (D <= 2^22): the
 * truncation, one less where it rounded up. Exact, and branch-free where SSE2 has no floor
 * instruction. */
RETRO_HELPER int retro_floor(float q)
{
    int i = (int)q;
    return i - (q < (float)i);
}

/* retro_floor(q) for |q| < 2^31, branching on the sign: for q >= 0 (-0 included) truncation is
 * the floor, which saves the conversion back and its compare where the sign is predictable
 * (a column's positions change sign at most once along its ray). */
RETRO_HELPER int retro_floor_nn(float q)
{
    return q >= 0.0f ? (int)q : retro_floor(q);
}

/* floor(q) mod S in [0, S). */
RETRO_HELPER int retro_cell(float q, int S)
{
    int i = retro_floor(q) % S;
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

/* floor(v / 2^bits) without shifting a negative value (implementation-defined in C). */
RETRO_HELPER int64_t retro_fixed_floor(int64_t v)
{
    return v >= 0 ? v >> RETRO_Q_POS : -((-(v + 1)) >> RETRO_Q_POS) - 1;
}

/* floor(v / 2^bits) mod S. */
RETRO_HELPER int retro_fixed_cell(int64_t v, int S)
{
    int64_t i = retro_fixed_floor(v) % S;
    return (int)(i < 0 ? i + S : i);
}

/* The map cell of sample (u, d), u 0-based, in modes exact/lod, truth and fixed. */
RETRO_HELPER size_t retro_exact_sample(const retro_frame *f, int u, int d)
{
    float qx = f->x0 + (float)d * f->rx[u], qy = f->y0 + (float)d * f->ry[u];
    return (size_t)retro_cell(qy, f->S) * (size_t)f->S + (size_t)retro_cell(qx, f->S);
}

/* floor(q) as an int64_t for |q| < 2^63: truncation for q >= 0 (-0 included), floor() below,
 * so only negative positions pay libm's call on an ISA without a rounding instruction. */
RETRO_HELPER int64_t retro_floor_d(double q)
{
    return q >= 0.0 ? (int64_t)q : (int64_t)floor(q);
}

RETRO_HELPER size_t retro_truth_sample(const retro_frame *f, int u, int d)
{
    double qx = f->x0_d + (double)d * f->rxd[u], qy = f->y0_d + (double)d * f->ryd[u];
    int64_t i = retro_floor_d(qx) % f->S, j = retro_floor_d(qy) % f->S;
    i += i < 0 ? f->S : 0;
    j += j < 0 ? f->S : 0;
    return (size_t)j * (size_t)f->S + (size_t)i;
}

RETRO_HELPER size_t retro_fixed_sample(const retro_frame *f, int u, int d)
{
    int64_t qx = f->x0_q + (int64_t)d * f->rx_q[u], qy = f->y0_q + (int64_t)d * f->ry_q[u];
    return (size_t)retro_fixed_cell(qy, f->S) * (size_t)f->S + (size_t)retro_fixed_cell(qx, f->S);
}

/* Fog (docs/EFFECTS.md): each channel moves toward the sky's by F/256. */
RETRO_HELPER uint32_t retro_fog(uint32_t c, uint32_t sky, int F)
{
    uint32_t out = 0;
    for (int sh = 8; sh <= 24; sh += 8) {
        uint32_t a = (c >> sh) & 255, s = (sky >> sh) & 255;
        out |= ((a * (uint32_t)(256 - F) + s * (uint32_t)F + 128) >> 8) << sh;
    }
    return out;
}

/* Bilinear filtering (docs/EFFECTS.md): the four cells and weights of a sample point. */
typedef struct {
    size_t c[4]; /* (i0,j0), (i1,j0), (i0,j1), (i1,j1) */
    float tx, ty;
} retro_bilerp;

RETRO_HELPER float retro_bilinear_height(const retro_frame *f, float qx, float qy, retro_bilerp *b)
{
    float px = qx - 0.5f, py = qy - 0.5f, fx = floorf(px), fy = floorf(py);
    int S = f->S, i0 = retro_cell(px, S), j0 = retro_cell(py, S);
    int i1 = i0 + 1 == S ? 0 : i0 + 1, j1 = j0 + 1 == S ? 0 : j0 + 1;
    b->tx = px - fx;
    b->ty = py - fy;
    b->c[0] = (size_t)j0 * (size_t)S + (size_t)i0;
    b->c[1] = (size_t)j0 * (size_t)S + (size_t)i1;
    b->c[2] = (size_t)j1 * (size_t)S + (size_t)i0;
    b->c[3] = (size_t)j1 * (size_t)S + (size_t)i1;
    const uint8_t *h = f->height_map;
    return ((float)h[b->c[0]] * (1.0f - b->tx) + (float)h[b->c[1]] * b->tx) * (1.0f - b->ty) +
           ((float)h[b->c[2]] * (1.0f - b->tx) + (float)h[b->c[3]] * b->tx) * b->ty;
}

RETRO_HELPER uint32_t retro_bilinear_color(const retro_frame *f, const retro_bilerp *b)
{
    const uint32_t *c = f->color_map;
    uint32_t out = 0;
    for (int sh = 8; sh <= 24; sh += 8) {
        float v = ((float)((c[b->c[0]] >> sh) & 255) * (1.0f - b->tx) + (float)((c[b->c[1]] >> sh) & 255) * b->tx) *
                      (1.0f - b->ty) +
                  ((float)((c[b->c[2]] >> sh) & 255) * (1.0f - b->tx) + (float)((c[b->c[3]] >> sh) & 255) * b->tx) *
                      b->ty;
        out |= (uint32_t)(int)(v + 0.5f) << sh;
    }
    return out;
}

/* The bilinear height's difference to the camera: exact in double, rounded once. */
RETRO_HELPER float retro_bilinear_dh(float hf, int64_t height)
{
    return (float)((double)hf - (double)height);
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
