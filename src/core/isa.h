/* The ISA levels, lowest first, each allowing the CPU features of the ones below it, as the
 * files are compiled: the one list. cpu.c makes retro_isa_names[] (the only spelling of the
 * names) and the feature masks from it; the kernel and strip tables name levels by
 * RETRO_ISA_<LEVEL> and their features by RETRO_ISA_CPU_<LEVEL>. */
#ifndef RETRO_ISA_H
#define RETRO_ISA_H

#include "retro.h"

/* X(LEVEL, name, CPU features allowed) */
#define RETRO_ISA_LEVELS(X)                                                                        \
    X(NONE, none, 0u)                                                                              \
    X(SSE2, sse2, RETRO_CPU_SSE2)                                                                  \
    X(AVX2, avx2, RETRO_CPU_SSE2 | RETRO_CPU_AVX2)                                                 \
    X(AVX512, avx512, RETRO_CPU_SSE2 | RETRO_CPU_AVX2 | RETRO_CPU_AVX512)

#define RETRO_ISA_ENUM_(level, name, cpu) RETRO_ISA_##level,
enum { RETRO_ISA_LEVELS(RETRO_ISA_ENUM_) RETRO_ISA_LEVEL_COUNT };
#undef RETRO_ISA_ENUM_
#define RETRO_ISA_CPU_(level, name, cpu) RETRO_ISA_CPU_##level = (cpu),
enum { RETRO_ISA_LEVELS(RETRO_ISA_CPU_) };
#undef RETRO_ISA_CPU_

/* The CPU features ISA level (an index of retro_isa_names) allows. */
unsigned retro_isa_cpu(int level);
/* "none, sse2, avx2, avx512" from retro_isa_names, for messages; buf is always terminated. */
const char *retro_isa_list(char *buf, size_t n);

#endif
