/* pthreads: the omp kernel's column chunks on plain POSIX threads, the engine of the
 * single-file submission (make submission), which may link only libc and libm (pt_pool.c says
 * how it links where pthreads are not in libc). The threads are the context's pool
 * (pt_pool.h), started on the first frame and kept until retro_ctx_free(), so a frame pays a
 * wake-up, not a thread start: the submission's run-to-run spread came from starting them.
 *
 * Threads take chunks of columns as omp's do (chunk_runs.h): one run of adjacent chunks per
 * thread, the same every frame, and the back of another run once a thread's own is done (in
 * mode course its front, so a thread's accumulators go back at most once a frame:
 * retro_course_seek replays the columns other threads took, addition by addition). A pool
 * with fewer threads than asked (or none) is still exact: the runs are cut for the threads
 * that started. Scratch lives in the context; the frame allocates nothing once the context
 * has grown. The strip is the frame's (retro_frame.strip, chosen by frame setup). */
#include <stdlib.h>

#include "chunk_runs.h"
#include "column_chunks.h"
#include "env.h"
#include "hmax_cache.h"
#include "kernels.h"
#include "pt_pool.h"

#define PT_CHUNK 64 /* as omp's default chunk (kernel_omp.c says why) */
#define PT_DEFAULT_THREADS 2 /* the course machine's and this suite's core count */

typedef struct {
    const retro_frame *f;
    retro_chunk_run run[RETRO_PT_MAX_THREADS];
    int runs, steal_front;
    retro_column_chunks chunks;
    float *scratch; /* thread t's accumulators at 2t and 2t + 1 strides */
    size_t stride;
} pt_job;

static void pt_task(void *arg, int t)
{
    pt_job *job = arg;
    const retro_frame *f = job->f;
    float *qx = job->scratch + 2 * (size_t)t * job->stride, *qy = qx + job->stride;
    retro_course_start(f, qx, qy);
    int at = 0;
    for (int c; (c = retro_chunk_next(job->run, job->runs, t, job->steal_front)) >= 0;) {
        int u0, u1;
        retro_column_chunk(&job->chunks, c, &u0, &u1);
        retro_course_seek(f, qx, qy, at, u0);
        f->strip(f, qx, qy, u0, u1);
        at = u1;
    }
}

/* Threads: rc->threads if set, else RETRO_PTHREADS (1..RETRO_PT_MAX_THREADS, digits only; a
 * bad value is ignored here and refused by the CLI, src/core/env.c), else 2. */
static int pt_threads(const retro_ctx *rc)
{
    long t = rc->threads;
    if (t <= 0 && retro_env_long("RETRO_PTHREADS", 1, RETRO_PT_MAX_THREADS, &t, NULL, 0) != 1)
        t = PT_DEFAULT_THREADS;
    return t > RETRO_PT_MAX_THREADS ? RETRO_PT_MAX_THREADS : (int)t;
}

/* rc's pool for the thread count asked, made or remade when that count changed (NULL: out of
 * memory, the callers then run on one thread). */
static retro_pt_pool *pt_pool_of(retro_ctx *rc)
{
    int T = pt_threads(rc);
    if (!rc->pt_pool || retro_pt_pool_asked(rc->pt_pool) != T) {
        retro_pt_pool_free(rc->pt_pool);
        rc->pt_pool = retro_pt_pool_new(T);
    }
    return rc->pt_pool;
}

/* The map-maximum job: thread t scans slice t of T, whole 64-byte lines but the last. */
typedef struct {
    const uint8_t *map;
    size_t n;
    int T;
    struct {
        _Alignas(64) uint8_t value; /* a line each: no thread writes another's line */
    } max[RETRO_PT_MAX_THREADS];
} pt_max_job;

static void pt_max_task(void *arg, int t)
{
    pt_max_job *job = arg;
    const size_t T = (size_t)job->T, per = ((job->n + T - 1) / T + 63) / 64 * 64;
    size_t lo = per * (size_t)t, hi = (size_t)t + 1 == T ? job->n : lo + per;
    lo = lo < job->n ? lo : job->n;
    hi = hi < job->n ? hi : job->n;
    job->max[t].value = retro_map_max(job->map + lo, hi - lo);
}

uint8_t retro_pthreads_map_scan(void *ctx, const uint8_t *map, size_t n)
{
    retro_pt_pool *pool = pt_pool_of(ctx);
    if (!pool || retro_pt_pool_threads(pool) == 1)
        return retro_map_max(map, n);
    pt_max_job job = {.map = map, .n = n, .T = retro_pt_pool_threads(pool)};
    retro_pt_pool_run(pool, pt_max_task, &job);
    uint8_t m = 0;
    for (int t = 0; t < job.T; t++)
        m = job.max[t].value > m ? job.max[t].value : m;
    return m;
}

void retro_kernel_pthreads(const void *frame, retro_ctx *rc)
{
    const retro_frame *f = frame;
    retro_pt_pool *pool = pt_pool_of(rc);
    /* Each thread's two accumulator arrays start on their own 64-byte line. */
    size_t stride = ((size_t)f->D + 15) / 16 * 16;
    const int T = pool ? retro_pt_pool_threads(pool) : 1;
    size_t need = 2 * stride * (size_t)T + 16;
    if (need > rc->tscratch_cap) {
        float *p = realloc(rc->tscratch, need * sizeof(float));
        if (p) {
            rc->tscratch = p;
            rc->tscratch_cap = need;
        }
    }
    if (!pool || need > rc->tscratch_cap) { /* out of memory: one thread, the context's own */
        retro_course_start(f, rc->qx, rc->qy);
        f->strip(f, rc->qx, rc->qy, 0, f->W);
        return;
    }
    pt_job job = {.f = f,
                  .runs = T,
                  .steal_front = retro_chunk_steal_front(f),
                  .chunks = retro_column_chunks_of(f, PT_CHUNK),
                  .scratch = rc->tscratch,
                  .stride = stride};
    retro_chunk_runs_init(job.run, job.runs, job.chunks.count);
    retro_simd_offer_packed(rc); /* f is &rc->frame: the strips see the packed map, as omp's */
    retro_pt_pool_run(pool, pt_task, &job);
}
