/* The comparison rig of the hard-case and invariance tests: one render context per kernel
 * and thread count, every kernel at every ISA level against naive, and a report of each
 * mismatch that lets the remaining cases run. */
#ifndef RETRO_HARD_RIG_H
#define RETRO_HARD_RIG_H

#include <stddef.h>
#include <stdint.h>

#include "check.h"
#include "test_util.h"

#define SKY 0x66a3ff00u
#define POISON 0xababababu
#define MAX_KERNELS 32
#define MAX_THREADS 3
#define MAX_REPORTS 40

/* One context per kernel and thread count for a whole test: a threaded kernel's pool loads the
 * hwloc topology once per context (milliseconds), which would dominate thousands of tiny
 * frames. The contexts cache per map pointer, so maps stay allocated until the test ends and
 * in-place edits are announced through rig_map_changed(). */
typedef struct {
    retro_ctx *rc[MAX_KERNELS][MAX_THREADS + 1]; /* naive's is rc[0][0] */
    float lod;         /* retro_render_opts.lod of every render; set chk.lod alike */
    retro_check chk;   /* every other variant (src/check/) */
    uint32_t *ref, *out;
    size_t cap;
    int failures, cases, renders;
} rig;

/* The tiny screen most cases use. */
enum { CW = 37, CH = 23, CD = 48 };

/* The map sizes the cases load, and their indices in that list. */
enum { NMAPS = 6 };
extern const int map_sizes[NMAPS];
enum { S1, S2, S3, S5, S64, S1000 };

rig *rig_new(void);
void rig_map_changed(rig *g);
void rig_done(rig *g, const char *test);
void rig_reserve(rig *g, size_t n);
void poison(uint32_t *px, size_t n);
void report(rig *g, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
long first_diff(const uint32_t *a, const uint32_t *b, size_t n);
retro_err rig_render(rig *g, size_t k, int threads, retro_mode mode, const player_t *p,
                            ctx_t *c);
void all_kernels_match(rig *g, const char *what, retro_mode mode, const player_t *p,
                              ctx_t c);
int naive_ref(rig *g, const char *what, retro_mode mode, const player_t *p, ctx_t c);
void describe(char *buf, size_t len, const char *tag, const player_t *p, int W, int H, int D,
                     int S);
void check_case(rig *g, const char *tag, player_t p, int W, int H, int D, const retro_map *m);
player_t pose(float x, float y, int angle, int height);
void load_maps(retro_map *maps);
void free_maps(retro_map *maps, int n);

#endif
