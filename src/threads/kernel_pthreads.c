/* pthreads: the omp kernel's column chunks with plain POSIX threads, started per frame. It
 * is the engine of the single-file submission (make submission), which may link only libc
 * and libm: since glibc 2.34 pthread_create lives in libc, so no -pthread flag is needed.
 *
 * Threads take chunks of columns from an atomic counter, so chunks reach each thread in
 * increasing order and mode course's per-thread accumulators only move forward
 * (retro_course_advance replays the columns other threads took, addition by addition). If a
 * thread cannot be created the calling thread does all the remaining chunks: still exact.
 * Scratch lives in the context; the frame allocates nothing once the context has grown. */
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>

#include "kernels.h"

#define PT_MAX_THREADS 8
#define PT_CHUNK 32

typedef struct {
    const retro_frame *f;
    retro_strip_fn strip;
    atomic_int next; /* next chunk to hand out */
    int chunks;
} pt_job;

typedef struct {
    pt_job *job;
    float *qx, *qy;
} pt_worker;

static void *pt_run(void *arg)
{
    pt_worker *w = arg;
    pt_job *job = w->job;
    const retro_frame *f = job->f;
    retro_course_start(f, w->qx, w->qy);
    int at = 0;
    for (;;) {
        int c = atomic_fetch_add(&job->next, 1);
        if (c >= job->chunks)
            break;
        int u0 = c * PT_CHUNK, u1 = u0 + PT_CHUNK < f->W ? u0 + PT_CHUNK : f->W;
        retro_course_advance(f, w->qx, w->qy, at, u0);
        job->strip(f, w->qx, w->qy, u0, u1);
        at = u1;
    }
    return NULL;
}

/* Threads: rc->threads if set, else 2 (the course machine's and this suite's core count). */
static int pt_threads(const retro_ctx *rc)
{
    int t = rc->threads > 0 ? rc->threads : 2;
    return t > PT_MAX_THREADS ? PT_MAX_THREADS : t;
}

void retro_kernel_pthreads(const void *frame, retro_ctx *rc)
{
    const retro_frame *f = frame;
    int T = pt_threads(rc);
    /* Each thread's two accumulator arrays start on their own 64-byte line. */
    size_t stride = ((size_t)f->D + 15) / 16 * 16;
    size_t need = 2 * stride * (size_t)T + 16;
    int own = 0; /* out of memory: one thread on the context's own accumulators */
    if (need > rc->tscratch_cap) {
        float *p = realloc(rc->tscratch, need * sizeof(float));
        if (!p) {
            T = 1;
            own = 1;
        } else {
            rc->tscratch = p;
            rc->tscratch_cap = need;
        }
    }
    pt_job job = {f, f->strip, 0, (f->W + PT_CHUNK - 1) / PT_CHUNK};
    atomic_init(&job.next, 0);
    pt_worker w[PT_MAX_THREADS];
    pthread_t tid[PT_MAX_THREADS];
    int started[PT_MAX_THREADS] = {0};
    for (int t = 0; t < T; t++) {
        w[t].job = &job;
        w[t].qx = own ? rc->qx : rc->tscratch + (2 * (size_t)t) * stride;
        w[t].qy = own ? rc->qy : rc->tscratch + (2 * (size_t)t + 1) * stride;
    }
    for (int t = 1; t < T; t++)
        started[t] = pthread_create(&tid[t], NULL, pt_run, &w[t]) == 0;
    pt_run(&w[0]);
    for (int t = 1; t < T; t++)
        if (started[t])
            pthread_join(tid[t], NULL);
}
