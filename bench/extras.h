// Cases beyond the kernel matrix: the course's plain painter against the generated
// submission (issue: make submission), and what each effect costs, including ybuffer with its
// effect code compiled out (it must cost nothing when a scene does not call for it).
#ifndef RETRO_BENCH_EXTRAS_H
#define RETRO_BENCH_EXTRAS_H

#include <ostream>

#include "cases.h"

// Runs (repetitions) of each submission case: issue 18 bounds the spread of its time across 10
// runs, (max - min) / median, which BENCH.md's submission table reports.
enum { SUBMISSION_RUNS = 10 };
// Least seconds of frames per run. At the run's 0.05 s a run is some 80 frames, and one burst
// from the virtual machine's neighbours moves its mean by more than the 15% the spread allows:
// a run then measures the neighbours, not the submission. A course's timing renders frames for
// longer than that too. For the same reason a run's time is the median of its frames, not
// their mean (BenchCase::frame_median): a burst that holds up a few frames of the run moves the
// mean, not the median.
constexpr double SUBMISSION_RUN_SECONDS = 0.5;

// Adds the extra cases for the plan's scenes: the submission table on the course scenes, the
// effect table on islands. Call after plan_cases().
void plan_extras(BenchPlan *plan);

// After the run: the fastest kernel for each effect set against the fastest for none, EFFECT_PAIRS
// pairs of frames timed in turn (in_turn.h); one line on stderr.
enum { EFFECT_PAIRS = 200 };
void extras_in_turn(BenchPlan *plan, void (*bind)(int threads));

// The two tables, for BENCH.md; nothing when the cases were not planned.
void extras_tables(std::ostream &o, const BenchPlan &plan);

#endif
