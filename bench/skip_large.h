// Occlusion skipping at a large frame (issue 18's target: at 1920x1080, D 4000, omp at least 4x
// faster than without skipping): omp at the bench's cores, mode exact, on every scene, with the
// kernel's default skipping and with it off, timed side by side in the same run.
#ifndef RETRO_BENCH_SKIP_LARGE_H
#define RETRO_BENCH_SKIP_LARGE_H

#include <ostream>

#include "cases.h"

enum { SKIP_LARGE_W = 1920, SKIP_LARGE_H = 1080, SKIP_LARGE_D = 4000 };

// Adds the pairs for the plan's scenes when mode exact is planned and omp exists.
void plan_skip_large(BenchPlan *plan);

// After the run, per scene whose two cases ran: SKIP_LARGE_PAIRS pairs of their frames timed in
// turn (in_turn.h), into the twin without skipping; one line per scene on stderr.
enum { SKIP_LARGE_PAIRS = 150 };
void skip_large_in_turn(BenchPlan *plan, void (*bind)(int threads));

// BENCH.md's table: per scene the two medians, their ratio and the samples each evaluates, and
// the geometric means, and the ratio timed in turn; nothing when no pair ran.
void skip_large_table(std::ostream &o, const BenchPlan &plan);

#endif
