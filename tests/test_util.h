/* Helpers shared by the Criterion tests: locating ../shared/course, loading maps, rendering. */
#ifndef RETRO_TEST_UTIL_H
#define RETRO_TEST_UTIL_H

#include <stdint.h>

#include "retro.h"
#include "retro_maps.h"

/* $RETRO_SHARED/course, default ../shared/course. */
const char *course_dir(void);
/* Loads the course map NAME (valley, island, pyramids); returns 0, or -1 when absent. */
int course_map(const char *name, retro_map *m);
/* Loads maps/NAME or fails the test with a hint to run `make maps`. */
void test_map(const char *name, retro_map *m);
/* Reads a whole file; returns its length or -1. *buf is malloc'd. */
long read_file(const char *path, unsigned char **buf);
/* A pseudo-random map of size S (heights and colours), deterministic from seed. */
void noise_map(retro_map *m, int S, uint64_t seed);
uint64_t rng_next(uint64_t *state);
/* Renders with kernel NAME (the test fails if it does not return RETRO_OK). */
void render_with(const char *kernel, retro_mode mode, const player_t *p, ctx_t *c);
/* The same with a thread count for threaded kernels (0: the default). */
void render_threads(const char *kernel, retro_mode mode, const player_t *p, ctx_t *c, int threads);

#endif
