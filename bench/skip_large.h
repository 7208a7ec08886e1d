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

// BENCH.md's table: per scene the two medians, their ratio and the samples each evaluates, and
// the geometric means; nothing when no pair ran.
void skip_large_table(std::ostream &o, const BenchPlan &plan);

#endif
