/* The strip table: every single-thread voxel strip (columns [u0, u1) of a frame, the unit the
 * threaded kernels hand their threads), with the ISA level it needs and the modes and effects
 * it renders, slowest first. The kernel table's ybuffer and SIMD rows point at their strip
 * here; frame setup picks the frame's strip from it once (retro_frame.strip) and the threaded
 * kernels run that one. The submission carries this same table (scripts/make-submission.sh),
 * so its dispatch is the library's. */
#ifndef RETRO_STRIPS_H
#define RETRO_STRIPS_H

#include "isa.h"
#include "kernels.h"
#include "retro_scene.h"

#define RETRO_STRIP_MODES_ALL ((1u << RETRO_MODE_COUNT) - 1)
#define RETRO_STRIP_MODES_SIMD \
    (RETRO_MODE_BIT(RETRO_MODE_EXACT) | RETRO_MODE_BIT(RETRO_MODE_COURSE) | RETRO_MODE_BIT(RETRO_MODE_LOD))
/* The SIMD strips render every effect themselves, fog and bilinear included (docs/EFFECTS.md). */
#define RETRO_STRIP_FX_SIMD RETRO_FX_VOXEL

/* X(id, ISA level, modes, effects, function), in ascending ISA order: the last row this CPU
 * runs for a frame's mode and effects is the fastest. */
#define RETRO_STRIPS(X)                                                                            \
    X(ybuffer, NONE, RETRO_STRIP_MODES_ALL, RETRO_FX_VOXEL, retro_strip_ybuffer)                   \
    X(simd_sse2, SSE2, RETRO_STRIP_MODES_SIMD, RETRO_STRIP_FX_SIMD, retro_strip_simd_sse2)         \
    X(simd_avx2, AVX2, RETRO_STRIP_MODES_SIMD, RETRO_STRIP_FX_SIMD, retro_strip_simd_avx2)         \
    X(simd_avx512, AVX512, RETRO_STRIP_MODES_SIMD, RETRO_STRIP_FX_SIMD, retro_strip_simd_avx512)

#define RETRO_STRIP_ENUM_(id, level, modes, fx, fn) RETRO_STRIP_##id,
enum { RETRO_STRIPS(RETRO_STRIP_ENUM_) RETRO_STRIP_COUNT };
#undef RETRO_STRIP_ENUM_

typedef struct retro_strip {
    const char *name;  /* the id above: "simd_avx2" */
    int level;         /* ISA level, an index of retro_isa_names */
    unsigned cpu;      /* the CPU features that level allows (RETRO_CPU_*) */
    unsigned modes;    /* RETRO_MODE_BIT() of the modes it renders */
    unsigned fx;       /* the effects (RETRO_FX_*) it renders */
    retro_strip_fn fn;
} retro_strip;

extern const retro_strip retro_strips[RETRO_STRIP_COUNT];

/* The fastest strip this CPU (at its ISA level, RETRO_ISA or retro_cpu_limit()) runs for
 * mode with the per-sample effects fx: the last capable row; ybuffer renders every frame. */
retro_strip_fn retro_strip_best(retro_mode mode, unsigned fx);

#endif
