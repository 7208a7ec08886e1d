// Ratios timed in turn. The medians of two cases are taken minutes apart, and on a shared VM the
// speed changes within seconds, so their ratio can be off by more than either case's own spread
// shows. Timing the two frames one after the other, pair after pair, puts such a change on both
// frames of a pair; the median of the per-pair ratios is what `retro render --time N --versus`
// prints (docs/COMMANDS.md). Used after the run for the tables whose ratios are targets.
#ifndef RETRO_BENCH_IN_TURN_H
#define RETRO_BENCH_IN_TURN_H

#include "cases.h"

// Times `pairs` pairs of frames of the cases a and b (each its own frame, mode, effects,
// threads and skipping, in a context of its own), a then b, the next pair b then a; when the
// kernels differ, each timed frame comes after an untimed one of its own. Stores in b the
// median and quartiles of the ratios b / a and returns true; false, storing nothing, when a
// frame fails or the two would keep two sets of workers each on more than one thread (different
// threaded kernels, or one with RETRO_KF_CTX_THREADS), which slow each other's frames.
// bind(threads) pins the bench thread as the cases were, before any frame.
bool in_turn(const BenchCase *a, BenchCase *b, int pairs, void (*bind)(int threads));

#endif
