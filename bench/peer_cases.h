// The peer-algorithm row: the classic voxel-space demo's traversal (src/peer/), timed on the
// matrix scenes beside retro's kernels in mode exact. A separate table, clearly labelled: the
// peer renders its own image (docs/ACCURACY.md measures its error against truth).
#ifndef RETRO_BENCH_PEER_CASES_H
#define RETRO_BENCH_PEER_CASES_H

#include <ostream>

#include "cases.h"

// Adds one peer case per matrix scene. Call after plan_cases().
void plan_peer(BenchPlan *plan);

// Its table for BENCH.md; nothing when the cases were not planned or did not run.
void peer_table(std::ostream &o, const BenchPlan &plan);

#endif
