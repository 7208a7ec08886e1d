/* retro render --time: the frame timed alone, or with --versus ARGS beside a second
 * configuration, the two timed frame by frame in turn. On a shared machine the speed changes
 * for a fraction of a second at a time; frames taken in turn meet such a change together, so
 * their ratio stays measurable where two separate runs of each would not (docs/COMMANDS.md). */
#ifndef RETRO_CLI_RENDER_TIMING_H
#define RETRO_CLI_RENDER_TIMING_H

#include "scene_args.h"

/* One untimed frame, then n timed ones; prints what ran and the median and minimum. Returns 0
 * or CLI_EBADINPUT. */
int render_time(render_job *j, const player_t *p, long n);

/* One untimed frame of each, then n pairs in the order A B, B A, A B, ...; when the kernels
 * differ, each timed frame comes after an untimed one of its own (a frame of the other kernel
 * would leave it colder caches and, for a threaded kernel, workers gone to sleep). Prints each one's
 * median and minimum as render_time does (B's line starts "versus: "), then the median of the
 * n ratios B / A and their quartiles. Returns 0 or CLI_EBADINPUT. */
int render_versus(render_job *a, const player_t *pa, render_job *b, const player_t *pb, long n);

#endif
