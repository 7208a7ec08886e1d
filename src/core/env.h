/* The environment variables retro reads, each parsed strictly and range-checked, like the
 * options (docs/INPUT.md lists them). A variable that is set must hold a valid value: an empty
 * one is an error too. */
#ifndef RETRO_ENV_H
#define RETRO_ENV_H

#include <stddef.h>

/* Columns per chunk of the omp kernel (RETRO_OMP_CHUNK) and their default. */
#define RETRO_OMP_CHUNK_DEFAULT 64
/* RETRO_PTHREADS's largest value: the pthreads kernel's thread count (src/threads/pt_pool.h). */
#define RETRO_PTHREADS_MAX 64
/* The cone steps' study (src/voxel/cone_map.h): RETRO_CONE_SECTORS's and RETRO_CONE_R's ranges. */
#define RETRO_CONE_SECTORS_MIN 4
#define RETRO_CONE_SECTORS_MAX 64
#define RETRO_CONE_R_MAX 32
/* RETRO_SHARED's longest accepted value: room for "/course/NAME" in 512-byte paths. */
#define RETRO_SHARED_MAX 400

/* 0 when name is unset; 1 with *out when it holds a decimal integer (digits, an optional
 * leading minus) in lo..hi; -1 with a one-line err naming the variable otherwise. */
int retro_env_long(const char *name, long lo, long hi, long *out, char *err, size_t errlen);
/* Checks every variable the project reads (RETRO_ISA, RETRO_OMP_CHUNK, RETRO_PTHREADS,
 * RETRO_SHARED, OMP_NUM_THREADS, and outside the submission RETRO_CONE_SECTORS and
 * RETRO_CONE_R): 0, or -1 with err for the first bad one. */
int retro_env_check(char *err, size_t errlen);
/* Index of ISA level name in retro_isa_names, or -1 (src/core/cpu.c). */
int retro_cpu_level_index(const char *name);

#endif
