/* Shared by the kernels: cell lookup, row projection and the one pixel store, so that every
 * kernel evaluates SEMANTICS.md with the same float operations in the same order. */
#ifndef RETRO_INTERNAL_H
#define RETRO_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "retro.h"

/* Row v in 0..H of a sample in mode exact (SEMANTICS.md step 6). */
int retro_exact_row(float kd, float half_h, int H, int64_t dh);
/* Row v in 0..H of a sample in mode course. */
int retro_course_row(float cw2, int ch2, int H, int64_t dh, int d);
/* The course's float_mod. */
float retro_float_mod(float f, float k);
/* Releases the thread pool of parallel kernels, if any. */
void retro_pool_free(retro_ctx *rc);

/* floor(q) mod S in [0, S). |q| < 2^31 holds for every valid frame (D <= 2^22). */
static inline int retro_cell(float q, int S)
{
    int i = (int)floorf(q) % S;
    return i < 0 ? i + S : i;
}

/* Course-mode cell: (int)float_mod(q, S - 1). */
static inline int retro_course_cell(float q, int S)
{
    return (int)retro_float_mod(q, (float)(S - 1));
}

/* The pixel (u, r), u and r 1-based, r from the bottom, as an index into out. */
static inline size_t retro_pixel(int W, int H, int u, int r)
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
