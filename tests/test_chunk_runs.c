/* The threaded kernels' chunk hand-out (src/threads/chunk_runs.h): every chunk goes to exactly
 * one thread, a thread takes its own run front to back before anything else, thieves take from
 * the back of another run or (mode course) its front; and mode course's accumulators, moved by
 * retro_course_seek, give every strip the positions of column-by-column stepping whatever order
 * a thread's chunks come in. The threaded frames themselves are checked against naive at 1 to 3
 * threads by test_frames.c and retro verify, but which thread takes which chunk there depends
 * on timing; the course test below walks chosen orders instead. */
#include <criterion/criterion.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "chunk_runs.h"
#include "isa.h"
#include "strips.h"
#include "test_util.h"

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

/* One thread alone: its own run front to back, then the next runs' from their backs, or in
 * mode course from their fronts (so only forward within a run). */
Test(chunk_runs, a_lone_thread_takes_its_run_then_the_others)
{
    const int want[2][9] = {{3, 4, 5, 8, 7, 6, 2, 1, 0}, {3, 4, 5, 6, 7, 8, 0, 1, 2}};
    for (int front = 0; front < 2; front++) {
        retro_chunk_run run[3];
        retro_chunk_runs_init(run, 3, 9);
        for (int i = 0; i < 9; i++)
            cr_assert_eq(retro_chunk_next(run, 3, 1, front), want[front][i], "front %d, take %d", front, i);
        cr_assert_eq(retro_chunk_next(run, 3, 1, front), -1);
        cr_assert_eq(retro_chunk_next(run, 3, 0, front), -1);
    }
}

/* One run (one thread) goes front to back either way. */
Test(chunk_runs, one_run_goes_front_to_back)
{
    for (int front = 0; front < 2; front++) {
        retro_chunk_run run[1];
        retro_chunk_runs_init(run, 1, 12);
        for (int i = 0; i < 12; i++)
            cr_assert_eq(retro_chunk_next(run, 1, 0, front), i);
        cr_assert_eq(retro_chunk_next(run, 1, 0, front), -1);
    }
}

/* A mode course frame drawn strip by strip in orders a thread can meet (its own run, then a
 * later run's front, then an earlier run's front; and every chunk backwards), with
 * retro_course_seek before each strip, at every ISA level: byte for byte naive's. Backwards,
 * each seek goes behind the accumulators and has to start them again. */
Test(chunk_runs, course_strips_in_a_thiefs_order_match_naive)
{
    enum { W = 160, H = 120, STEP = 16, N = W / STEP };
    retro_map m;
    noise_map(&m, 100, 7); /* S not a power of two: the course's wrap by fmod */
    static uint32_t want[W * H], got[W * H];
    ctx_t c = {W, H, 100, 300, 0x4080c0u, m.height, m.color, want};
    player_t p = {37.25f, 61.5f, 90, 60, 0, 0, 0};
    memset(want, 0x5a, sizeof want);
    render_with("naive", RETRO_MODE_COURSE, &p, &c);
    const int orders[][N] = {
        {5, 6, 7, 8, 9, 0, 1, 2, 3, 4}, /* thread 1 of 2: its run, then run 0 from its front */
        {0, 1, 2, 3, 4, 7, 8, 9, 5, 6}, /* an owner that lost 5 and 6 to a thief */
        {9, 8, 7, 6, 5, 4, 3, 2, 1, 0}, /* every chunk behind the one before */
    };
    float *qx = calloc(c.distance + 1, sizeof(float)), *qy = calloc(c.distance + 1, sizeof(float));
    cr_assert(qx && qy);
    for (int l = 0; l < retro_isa_count; l++) {
        retro_cpu_limit(retro_isa_names[l]);
        for (size_t o = 0; o < sizeof orders / sizeof orders[0]; o++) {
            retro_ctx *rc = retro_ctx_new();
            cr_assert(rc);
            retro_render_opts ro = RETRO_RENDER_OPTS_DEFAULT;
            ro.mode = RETRO_MODE_COURSE;
            c.out = got;
            memset(got, 0x5a, sizeof got);
            const retro_frame *f = NULL;
            cr_assert_eq(retro_frame_prepare(rc, &ro, &p, &c, &f), RETRO_OK);
            retro_course_start(f, qx, qy);
            int at = 0;
            for (int i = 0; i < N; i++) {
                const int u0 = orders[o][i] * STEP;
                retro_course_seek(f, qx, qy, at, u0);
                f->strip(f, qx, qy, u0, u0 + STEP);
                at = u0 + STEP;
            }
            cr_assert(memcmp(got, want, sizeof got) == 0, "level %s, order %zu: differs from naive",
                      retro_isa_names[l], o);
            retro_ctx_free(rc);
        }
    }
    retro_cpu_limit(NULL);
    free(qx);
    free(qy);
    retro_map_free(&m);
}

typedef struct {
    retro_chunk_run *run;
    int runs, t;
    atomic_int *owner; /* per chunk: the thread that took it, + 1 */
    int *order, n;      /* the chunks this thread took, in order */
    int twice;          /* chunks it found taken already (Criterion asserts on the main thread) */
    int front;          /* thieves take from the front (mode course) */
} taker;

static void *take_all(void *arg)
{
    taker *k = arg;
    for (int c; (c = retro_chunk_next(k->run, k->runs, k->t, k->front)) >= 0;) {
        int none = 0;
        if (!atomic_compare_exchange_strong(&k->owner[c], &none, k->t + 1))
            k->twice++;
        k->order[k->n++] = c;
    }
    return NULL;
}

/* THREADS threads at once, with as many runs, fewer (2) and one, thieves taking from the back
 * and from the front: every chunk once; a thread's chunks of its own run in increasing order
 * (it is the only one taking from their front); and with front thieves (mode course), at most
 * one chunk of a thread's behind the one it took before (when it moves on from the last run to
 * the first), none with one run. */
static void race(int runs, int front)
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
        k[t] = (taker){run, runs, t, owner, malloc(MANY * sizeof(int)), 0, 0, front};
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
        int last = -1, prev = -1, behind = 0;
        for (int i = 0; i < k[t].n; i++) {
            int c = k[t].order[i];
            if (c >= lo[t % runs] && c < hi[t % runs]) {
                cr_assert_gt(c, last, "runs %d: thread %d took %d after %d", runs, t, c, last);
                last = c;
            }
            behind += c < prev;
            prev = c;
        }
        if (front)
            cr_assert_leq(behind, runs > 1, "runs %d, front thieves: thread %d went back %d times", runs, t,
                          behind);
        free(k[t].order);
    }
    free(owner);
}

Test(chunk_runs, racing_threads_take_every_chunk_once)
{
    for (int front = 0; front < 2; front++) {
        race(THREADS, front);
        race(2, front);
        race(1, front);
    }
}
