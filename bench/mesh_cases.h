// The mesh family beside the voxel kernels: every mesh kernel in mode binary32 (the threaded one
// at each thread count) on the matrix scenes and poses at the matrix frame, back faces culled,
// with the triangles and fragments of a frame as counters; the best single-threaded mesh
// kernel and the threaded one at all cores swept over the voxel sweeps' resolutions and
// distances. BENCH.md's mesh tables (mesh_report.cc): per scene (ms/frame, triangles/s,
// fragments/s, the ratio to the best voxel kernel on the same scene), the geometric means with
// the speedups over mesh-zbuffer and over the best single-threaded mesh kernel, and the two
// sweeps beside the best voxel kernel.
#ifndef RETRO_BENCH_MESH_CASES_H
#define RETRO_BENCH_MESH_CASES_H

#include <ostream>

#include "cases.h"

// A mesh frame at 640x480, D 800 costs a few hundred voxel frames: fixed iterations and
// repetitions (the google-benchmark flags' defaults would probe for 0.05 s per repetition).
enum { MESH_ITERATIONS = 2, MESH_REPETITIONS = 3, MESH_QUICK_REPETITIONS = 2 };

// Adds one case per mesh kernel, thread count and matrix scene (quick: the sweep scene only),
// and the sweep cases. Call after plan_cases().
void plan_mesh(BenchPlan *plan, bool quick);

// Counters of a mesh case's frame, after the timed loop: triangles submitted, after culling and
// clipping, fragments (per frame), and triangles/s and fragments/s.
struct retro_ctx;
void mesh_counters(void *state, const BenchCase *c, const struct retro_ctx *rc);

// The mesh tables for BENCH.md (mesh_report.cc); nothing when no mesh case ran.
void mesh_table(std::ostream &o, const BenchPlan &plan);

// The mesh sweeps' charts (bench-mesh-resolution, bench-mesh-distance) for the gnuplot script.
void mesh_charts(std::ostream &o, const BenchPlan &plan);

#endif
