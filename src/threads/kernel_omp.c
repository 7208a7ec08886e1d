/* omp: columns split between threads in chunks of whole columns, each chunk rendered by the
 * fastest single-thread kernel's strip. Splitting columns (not the distances of one slice)
 * keeps every thread's work independent: a column's y-buffer lives in one thread's registers,
 * so there is nothing to share, and no barrier per distance.
 *
 * Mode course accumulates each line's position column by column. A thread keeps its own
 * accumulators, starts them at column 1 and, before each chunk it takes, advances them over
 * the columns other threads rendered with the same additions (retro_course_seek; from column 1
 * again for a chunk behind its last), so at every column they hold exactly the values the
 * single-thread reference has there.
 *
 * Schedule: chunks of 64 whole columns with edges on out's 64-byte lines (column_chunks.h),
 * one run of adjacent chunks per thread, the same every frame, with a thread that finishes its
 * run taking chunks from the back of another (chunk_runs.h): so a thread mostly stores into
 * the lines it stored into the frame before, which are still in its core's cache. In mode
 * course a thief takes from another run's front instead, so it goes back at most once a frame.
 * The chunk size was chosen by measuring 60 seeded poses of the default scenes
 * (docs/studies/KERNEL_STUDIES.md, "Load balance of the omp kernel"): chunks of 16-32 lost to
 * the cost each chunk of a strip carries (its constants, its first distances). RETRO_OMP_CHUNK
 * overrides it. */
#include <omp.h>

#include "chunk_runs.h"
#include "env.h"
#include "column_chunks.h"
#include "kernels.h"
#include "omp_pool.h"

/* Columns per chunk: RETRO_OMP_CHUNK if set to 1..RETRO_MAX_SCREEN (for measuring), else 64;
 * the range keeps the chunk arithmetic below from overflowing. */
static int chunk_columns(void)
{
    long c;
    return retro_env_long("RETRO_OMP_CHUNK", 1, RETRO_MAX_SCREEN, &c, NULL, 0) == 1
               ? (int)c : RETRO_OMP_CHUNK_DEFAULT;
}

void retro_kernel_omp(const void *frame, retro_ctx *rc)
{
    const retro_frame *f = frame;
    retro_strip_fn strip = f->strip; /* chosen by frame setup (strips.h) */
    int threads = retro_pool_threads(rc);
    retro_pool *pool = retro_pool_get(rc, threads, f->D);
    if (!pool) { /* out of memory for scratch: render single-threaded, still exact */
        retro_course_start(f, rc->qx, rc->qy);
        strip(f, rc->qx, rc->qy, 0, f->W);
        return;
    }
    const retro_column_chunks cc = retro_column_chunks_of(f, chunk_columns());
    retro_simd_offer_packed(rc); /* f is &rc->frame: the strips see the packed map */
    retro_pool_enter(pool);
    const int steal_front = retro_chunk_steal_front(f);
    retro_chunk_run run[RETRO_MAX_THREADS];
    retro_chunk_runs_init(run, threads, cc.count);
#pragma omp parallel num_threads(threads)
    {
        int t = omp_get_thread_num();
        retro_pool_bind(pool, t);
        float *qx = retro_pool_qx(pool, t), *qy = retro_pool_qy(pool, t);
        retro_course_start(f, qx, qy);
        int at = 0;
        for (int c; (c = retro_chunk_next(run, threads, t, steal_front)) >= 0;) {
            int u0, u1;
            retro_column_chunk(&cc, c, &u0, &u1);
            retro_course_seek(f, qx, qy, at, u0);
            strip(f, qx, qy, u0, u1);
            at = u1;
        }
    }
}
