/* A pool of POSIX worker threads started once and kept until it is freed, so a frame pays
 * a wake-up and a wait, not a thread start (the pthreads kernel, the submission's engine). */
#ifndef RETRO_PT_POOL_H
#define RETRO_PT_POOL_H

#include "env.h"

#define RETRO_PT_MAX_THREADS RETRO_PTHREADS_MAX

typedef struct retro_pt_pool retro_pt_pool;
/* One thread's share of a task: t is 0 for the calling thread, 1.. for the workers. */
typedef void (*retro_pt_task)(void *arg, int t);

/* A pool for `threads` threads in all (the caller and threads - 1 workers, at most
 * RETRO_PT_MAX_THREADS), or NULL when out of memory. It may hold fewer workers than asked,
 * none when this program is linked without pthreads (retro_pt_available); the task then
 * runs on fewer threads, which the kernels' chunk runs make correct (chunk_runs.h). */
retro_pt_pool *retro_pt_pool_new(int threads);
/* The threads a task runs on: 1 + the workers that started. */
int retro_pt_pool_threads(const retro_pt_pool *p);
/* The threads asked for at creation (the pool is kept while the count asked stays). */
int retro_pt_pool_asked(const retro_pt_pool *p);
/* Runs fn(arg, t) on every thread of the pool, the caller's as t = 0, and returns when all
 * have returned. One task at a time per pool. */
void retro_pt_pool_run(retro_pt_pool *p, retro_pt_task fn, void *arg);
/* Stops and joins the workers and frees the pool (NULL: nothing). */
void retro_pt_pool_free(retro_pt_pool *p);
/* Whether this program has the pthreads functions the pool needs (see pt_pool.c). */
int retro_pt_available(void);

#endif
