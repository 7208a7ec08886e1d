/* Who renders which column chunk (column_chunks.h) in the threaded kernels, so that a thread
 * stores into the same lines of out from one frame to the next.
 *
 * A 640x480 frame is 1.2 MB, within one core's L2 on recent server cores (2 MB on the Xeon of
 * the published run). When each frame hands the chunks to whichever thread asks first, a
 * chunk's lines are often in the other core's cache from the frame before, and a store there
 * first fetches its line from that cache (docs/studies/KERNEL_STUDIES.md, "Load balance of the
 * omp kernel"). So the chunks are cut into one run of adjacent chunks per thread, the same
 * runs every frame: thread t takes its run front to back, and a thread whose run is empty
 * takes chunks from the back of another run, the furthest from where that run's owner is.
 * Only the chunks taken that way change hands between frames.
 *
 * Mode course's accumulators only add (retro_course_seek): a thread that takes a chunk behind
 * its last one replays the frame's columns from the first up to it. Taken from the back of
 * another run, every chunk after the first lies behind the one before, and each would replay
 * up to most of the frame; so in mode course thieves take from the front of another run. A
 * thread visits the runs in the order t, t + 1, ... and the runs lie in column order, so its
 * chunks only move forward except once, where it wraps from the last run to the first: one
 * replay from the first column a frame at most. */
#ifndef RETRO_CHUNK_RUNS_H
#define RETRO_CHUNK_RUNS_H

#include <stdatomic.h>
#include <stdint.h>

#include "kernels.h"

/* One run: chunks [front, back), packed as front | back << 32 so one compare-and-swap takes a
 * chunk from either end. On its own 64-byte line: the owners update theirs on every chunk. */
typedef struct {
    _Alignas(64) _Atomic uint64_t span;
} retro_chunk_run;

static inline uint64_t retro_chunk_span(uint32_t front, uint32_t back)
{
    return (uint64_t)front | (uint64_t)back << 32;
}

/* Whether frame f's thieves take from the front of another run (mode course) or its back. */
static inline int retro_chunk_steal_front(const retro_frame *f)
{
    return f->mode == RETRO_MODE_COURSE;
}

/* Cuts chunks [0, count) into `runs` runs of adjacent chunks, as equal as counts allow, run r
 * before run r + 1. Before the threads start: they see the spans through the fork (OpenMP)
 * or the pool's start (pt_pool.c). */
static inline void retro_chunk_runs_init(retro_chunk_run *run, int runs, int count)
{
    for (int r = 0; r < runs; r++) {
        uint32_t lo = (uint32_t)((int64_t)count * r / runs), hi = (uint32_t)((int64_t)count * (r + 1) / runs);
        atomic_init(&run[r].span, retro_chunk_span(lo, hi));
    }
}

/* The next chunk of `run`, from its front (front) or its back (!front), or -1 when it is
 * empty. */
static inline int retro_chunk_run_take(retro_chunk_run *run, int front)
{
    uint64_t s = atomic_load_explicit(&run->span, memory_order_relaxed);
    for (;;) {
        const uint32_t lo = (uint32_t)s, hi = (uint32_t)(s >> 32);
        if (lo >= hi)
            return -1;
        const uint64_t next = front ? retro_chunk_span(lo + 1, hi) : retro_chunk_span(lo, hi - 1);
        if (atomic_compare_exchange_weak_explicit(&run->span, &s, next, memory_order_relaxed,
                                                  memory_order_relaxed))
            return (int)(front ? lo : hi - 1);
    }
}

/* Thread t's next chunk among `runs` runs, or -1 when every run is empty. After its own run, t
 * takes from the backs (or with steal_front, the fronts) of the others, in the order t + 1,
 * t + 2, ... (mod runs). */
static inline int retro_chunk_next(retro_chunk_run *run, int runs, int t, int steal_front)
{
    int c = retro_chunk_run_take(&run[t % runs], 1);
    for (int i = 1; c < 0 && i < runs; i++)
        c = retro_chunk_run_take(&run[(t + i) % runs], steal_front);
    return c;
}

#endif
