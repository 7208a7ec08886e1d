/* Prototypes of the kernels, one per file kernel_<name>.c; the table is in kernels.c. */
#ifndef RETRO_KERNELS_H
#define RETRO_KERNELS_H

#include "retro.h"
#include "ctx.h"
#include "frame.h"

/* Course-mode accumulators at column 1: qx[d] = lx[d], qy[d] = ly[d]. */
void retro_course_start(const retro_frame *f, float *qx, float *qy);
/* Advances the course-mode accumulators over columns [u0, u1) without sampling, with the same
 * float additions a strip performs, so any strip can start at any column bit-exactly. */
void retro_course_advance(const retro_frame *f, float *qx, float *qy, int u0, int u1);
/* Moves accumulators that hold column `at`'s positions to column u's: forward by advancing,
 * or, for a column before `at`, from retro_course_start again (a float addition has no exact
 * inverse). The threaded kernels call it before each chunk; nothing outside mode course. */
void retro_course_seek(const retro_frame *f, float *qx, float *qy, int at, int u);

void retro_strip_ybuffer(const retro_frame *f, float *qx, float *qy, int u0, int u1);
void retro_strip_simd_sse2(const retro_frame *f, float *qx, float *qy, int u0, int u1);
void retro_strip_simd_avx2(const retro_frame *f, float *qx, float *qy, int u0, int u1);
void retro_strip_simd_avx512(const retro_frame *f, float *qx, float *qy, int u0, int u1);

/* Builds rc's packed map when stale and offers it to the strips of rc's frame (they find it
 * through frame.packed; not when the frame cannot use it): threaded kernels call it before
 * their threads start. Writes the context, never the frame. */
void retro_simd_offer_packed(retro_ctx *rc);

void retro_kernel_naive(const void *frame, retro_ctx *rc);
void retro_kernel_ybuffer(const void *frame, retro_ctx *rc);
void retro_kernel_simd_sse2(const void *frame, retro_ctx *rc);
void retro_kernel_simd_avx2(const void *frame, retro_ctx *rc);
void retro_kernel_simd_avx512(const void *frame, retro_ctx *rc);
void retro_kernel_omp(const void *frame, retro_ctx *rc);
void retro_kernel_pthreads(const void *frame, retro_ctx *rc);
/* The largest of the n bytes at map, scanned by the pthreads kernel's threads of context ctx
 * in slices (a retro_map_scan, hmax_cache.h): for callers that cannot keep the map's maximum
 * between frames (retro_ctx.map_scan). */
uint8_t retro_pthreads_map_scan(void *ctx, const uint8_t *map, size_t n);


/* The voxel family's mode names, indexed by retro_mode (src/voxel/frame.c). */
extern const char *const retro_voxel_mode_names[RETRO_MODE_COUNT];

#endif
