/* Per-context state of threaded kernels: the hwloc topology for pinning one thread per
 * physical core, and per-thread scratch on separate cache lines. */
#ifndef RETRO_OMP_POOL_H
#define RETRO_OMP_POOL_H

#include "retro.h"

#define RETRO_MAX_THREADS 64

typedef struct retro_pool retro_pool;

/* The context's pool, created on first use; reserves course accumulators for `threads`
 * threads and distances < d. NULL when memory runs out. */
retro_pool *retro_pool_get(retro_ctx *rc, int threads, int d);
/* Saves the calling thread's binding before the pool first binds it as thread 0; it stays
 * bound while the context lives and retro_ctx_free() on the same thread gives it back. */
void retro_pool_enter(retro_pool *pool);
/* Binds the calling thread to core (t mod cores) once, if the system supports binding. */
void retro_pool_bind(retro_pool *pool, int t);
float *retro_pool_qx(retro_pool *pool, int t);
float *retro_pool_qy(retro_pool *pool, int t);
/* Threads a frame of rc uses: rc->threads, else OMP_NUM_THREADS / the core count. */
int retro_pool_threads(const retro_ctx *rc);
/* One line: how threads are bound here, e.g. "hwloc: 1 thread per core, 2 cores". */
const char *retro_pool_binding(retro_ctx *rc);

#endif
