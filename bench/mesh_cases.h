// The mesh family beside the voxel kernels: every mesh kernel in mode binary32 on the matrix
// scenes and poses at the matrix frame, back faces culled, with the triangles and fragments of
// a frame as counters, and BENCH.md's mesh table (ms/frame, triangles/s, fragments/s, and the
// ratio to the best voxel kernel of the matrix on the same scene).
#ifndef RETRO_BENCH_MESH_CASES_H
#define RETRO_BENCH_MESH_CASES_H

#include <ostream>

#include "cases.h"

// A mesh frame at 640x480, D 800 costs a few hundred voxel frames: fixed iterations and
// repetitions (the google-benchmark flags' defaults would probe for 0.05 s per repetition).
enum { MESH_ITERATIONS = 2, MESH_REPETITIONS = 3, MESH_QUICK_REPETITIONS = 2 };

// Adds one case per mesh kernel and matrix scene (quick: the sweep scene only). Call after
// plan_cases().
void plan_mesh(BenchPlan *plan, bool quick);

// Counters of a mesh case's frame, after the timed loop: triangles submitted, after culling and
// clipping, fragments (per frame), and triangles/s and fragments/s.
struct retro_ctx;
void mesh_counters(void *state, const BenchCase *c, const struct retro_ctx *rc);

// Its table for BENCH.md; nothing when no mesh case ran.
void mesh_table(std::ostream &o, const BenchPlan &plan);

#endif
