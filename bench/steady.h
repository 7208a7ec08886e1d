// Machine steadiness: one reference frame timed at checkpoints spread through the run. A case's
// spread over its own repetitions (cv) only sees noise that changes within its fraction of a
// second; a machine that runs slower for minutes, or whose second core does, shifts whole
// tables without raising any cv. The checkpoints see that: the same frame, by the same kernel,
// should take the same time at the start, the middle and the end of a run.
#ifndef RETRO_BENCH_STEADY_H
#define RETRO_BENCH_STEADY_H

#include <ostream>
#include <string>

#include "cases.h"

// A run whose reference frame's time spreads more than this across the checkpoints, (max −
// min) / median at one thread count, is marked noisy, like a row whose cv exceeds NOISY_CV.
constexpr double NOISY_DRIFT = 0.10;

// Inserts the checkpoints into plan->cases: before the first case, after every `every` cases
// and after the last. Each is the plan's fastest mode exact kernel on the sweep scene at the
// matrix frame, at one thread and (threaded kernels) at every core. Call after every other
// case is planned; nothing without a sweep scene.
void plan_steady(BenchPlan *plan, int every);

// Whether the largest spread over the thread counts exceeds NOISY_DRIFT; *threads and *drift
// get that count and spread. False when fewer than three checkpoints of every count ran.
bool steady_noisy(const BenchPlan &plan, int *threads, double *drift);

// The sentences for BENCH.md's noisy note ("The reference frame ... spread ...", then what the
// machine probes saw: machine_probe.h), or "" when the drift is within NOISY_DRIFT or unknown.
std::string steady_note(const BenchPlan &plan);

// BENCH.md's section: the reference frame's median at each checkpoint, when it ran, the probes
// timed after its 1-thread frames, and the spread of each column; nothing when fewer than three
// checkpoints ran.
void steady_table(std::ostream &o, const BenchPlan &plan);

#endif
