/* The threaded kernels' chunk hand-out (src/threads/chunk_runs.h): every chunk goes to exactly
 * one thread, a thread takes its own run front to back before anything else, and with one
 * shared run (mode course) each thread's chunks come in increasing order, which mode course's
 * accumulators need. The frames themselves are checked against naive at 1 to 3 threads by
 * test_frames.c and retro verify. */
#include <criterion/criterion.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>

#include "chunk_runs.h"

enum { MAX_RUNS = 8, THREADS = 4, MANY = 20000 };

static int span_lo(retro_chunk_run *r) { return (int)(uint32_t)atomic_load(&r->span); }
static int span_hi(retro_chunk_run *r) { return (int)(uint32_t)(atomic_load(&r->span) >> 32); }

Test(chunk_runs, runs_tile_the_chunks_evenly)
{
    retro_chunk_run run[MAX_RUNS];
    for (int count = 0; count <= 70; count++)
        for (int runs = 1; runs <= MAX_RUNS; runs++) {
            retro_chunk_runs_init(run, runs, count);
            int at = 0;
            for (int r = 0; r < runs; r++) {
                cr_assert_eq(span_lo(&run[r]), at, "count %d runs %d: run %d starts at %d", count, runs, r,
                             span_lo(&run[r]));
                int n = span_hi(&run[r]) - span_lo(&run[r]);
                cr_assert(n == count / runs || n == count / runs + 1, "count %d runs %d: run %d holds %d", count,
                          runs, r, n);
                at = span_hi(&run[r]);
            }
            cr_assert_eq(at, count);
        }
}

/* One thread alone: its own run front to back, then the next runs' from their backs. */
Test(chunk_runs, a_lone_thread_takes_its_run_then_the_others_from_the_back)
{
    retro_chunk_run run[3];
    retro_chunk_runs_init(run, 3, 9);
    const int want[] = {3, 4, 5, 8, 7, 6, 2, 1, 0};
    for (int i = 0; i < 9; i++)
        cr_assert_eq(retro_chunk_next(run, 3, 1), want[i], "take %d", i);
    cr_assert_eq(retro_chunk_next(run, 3, 1), -1);
    cr_assert_eq(retro_chunk_next(run, 3, 0), -1);
}

Test(chunk_runs, one_shared_run_goes_front_to_back)
{
    retro_chunk_run run[1];
    retro_chunk_runs_init(run, 1, 12);
    for (int i = 0; i < 12; i++)
        cr_assert_eq(retro_chunk_next(run, 1, i % 3), i);
    cr_assert_eq(retro_chunk_next(run, 1, 0), -1);
}

typedef struct {
    retro_chunk_run *run;
    int runs, t;
    atomic_int *owner; /* per chunk: the thread that took it, + 1 */
    int *order, n;      /* the chunks this thread took, in order */
    int twice;          /* chunks it found taken already (Criterion asserts on the main thread) */
} taker;

static void *take_all(void *arg)
{
    taker *k = arg;
    for (int c; (c = retro_chunk_next(k->run, k->runs, k->t)) >= 0;) {
        int none = 0;
        if (!atomic_compare_exchange_strong(&k->owner[c], &none, k->t + 1))
            k->twice++;
        k->order[k->n++] = c;
    }
    return NULL;
}

/* THREADS threads at once, with as many runs, fewer (2) and one: every chunk once; a thread's
 * chunks of its own run in increasing order (it is the only one taking from their front); and
 * with one run, all of a thread's chunks in increasing order. */
static void race(int runs)
{
    static retro_chunk_run run[MAX_RUNS];
    atomic_int *owner = calloc(MANY, sizeof *owner);
    cr_assert(owner);
    retro_chunk_runs_init(run, runs, MANY);
    int lo[MAX_RUNS], hi[MAX_RUNS];
    for (int r = 0; r < runs; r++) {
        lo[r] = span_lo(&run[r]);
        hi[r] = span_hi(&run[r]);
    }
    taker k[THREADS];
    pthread_t th[THREADS];
    for (int t = 0; t < THREADS; t++) {
        k[t] = (taker){run, runs, t, owner, malloc(MANY * sizeof(int)), 0, 0};
        cr_assert(k[t].order);
        cr_assert_eq(pthread_create(&th[t], NULL, take_all, &k[t]), 0);
    }
    int taken = 0;
    for (int t = 0; t < THREADS; t++) {
        pthread_join(th[t], NULL);
        cr_assert_eq(k[t].twice, 0, "runs %d: thread %d took %d chunks taken before", runs, t, k[t].twice);
        taken += k[t].n;
    }
    cr_assert_eq(taken, MANY);
    for (int c = 0; c < MANY; c++)
        cr_assert_neq(atomic_load(&owner[c]), 0, "chunk %d never taken", c);
    for (int t = 0; t < THREADS; t++) {
        int last = -1;
        for (int i = 0; i < k[t].n; i++) {
            int c = k[t].order[i];
            int own = runs == 1 || (c >= lo[t % runs] && c < hi[t % runs]);
            if (own) {
                cr_assert_gt(c, last, "runs %d: thread %d took %d after %d", runs, t, c, last);
                last = c;
            }
        }
        free(k[t].order);
    }
    free(owner);
}

Test(chunk_runs, racing_threads_take_every_chunk_once)
{
    race(THREADS);
    race(2);
    race(1);
}
