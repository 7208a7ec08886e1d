/* The rig of tests/test_skipping.c: naive, ybuffer with and without skipping, and the shared
 * checker (src/check/) over every kernel whose strips skip, at every ISA level this CPU runs
 * and at 1 and 2 threads. */
#ifndef RETRO_SKIPPING_RIG_H
#define RETRO_SKIPPING_RIG_H

#include "check.h"
#include "retro.h"
#include "retro_maps.h"
#include "retro_scene.h"

enum { NAIVE, SKIP, NOSKIP, NCTX };
enum { NSIMD = 5 }; /* skipping_kernels[] */

typedef struct {
    retro_ctx *rc[NCTX];
    retro_check chk[NSIMD];
    uint32_t *ref, *out;
    size_t cap;
    long frames, skipped_frames, variants;
} trio;

trio *rig_open(void);
void rig_close(trio *g);
/* A new map may reuse a freed one's address: the contexts must forget their caches. */
void new_map(trio *g);
void make_map(retro_map *m, int S);
/* Renders pose p with naive, ybuffer skipping and not skipping, and every checker variant,
 * and fails the test on any difference; then the same in mode lod (the lod effect added). */
void check(trio *g, const char *what, const retro_map *m, player_t p, int W, int H, int D,
           const retro_effects *fx);
player_t at(float x, float y, int angle, int height);

#endif
