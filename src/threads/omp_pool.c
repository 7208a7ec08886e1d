/* Thread pinning with hwloc (the one binding mechanism: OMP_PLACES/OMP_PROC_BIND are left
 * unset) and per-thread scratch for threaded kernels. The topology is loaded once per
 * context, not per frame, because loading it costs milliseconds. */
#include <hwloc.h>
#include <omp.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "omp_pool.h"
#include "retro_internal.h"

struct retro_pool {
    hwloc_topology_t topo;
    int have_topo;
    int can_bind;          /* set_thisthread_cpubind is supported here */
    int cores;
    unsigned long serial;  /* unique per pool in this process, never 0 */
    int cap_threads, cap_d;
    float *qx[RETRO_MAX_THREADS], *qy[RETRO_MAX_THREADS];
    hwloc_bitmap_t caller;   /* the binding the calling thread had before the pool bound it */
    int caller_saved;
    pthread_t caller_thread;
    char binding[160];
};

/* Which core this thread is bound to, so a frame costs no system call once threads are bound.
 * The pool is identified by a serial number, not its address: a freed pool's address can
 * come back for a new one whose threads are not bound yet. */
static _Thread_local int bound_core = -1;
static _Thread_local unsigned long bound_serial;
static _Atomic unsigned long pool_serials;

static void pool_init(retro_pool *p)
{
    p->cores = 1;
    p->serial = ++pool_serials;
    if (hwloc_topology_init(&p->topo) == 0 && hwloc_topology_load(p->topo) == 0) {
        p->have_topo = 1;
        int n = hwloc_get_nbobjs_by_type(p->topo, HWLOC_OBJ_CORE);
        p->cores = n > 0 ? n : 1;
        const struct hwloc_topology_support *s = hwloc_topology_get_support(p->topo);
        p->can_bind = n > 0 && s && s->cpubind && s->cpubind->set_thisthread_cpubind;
    }
    if (p->can_bind)
        snprintf(p->binding, sizeof p->binding, "hwloc: thread t on core t mod %d", p->cores);
    else
        snprintf(p->binding, sizeof p->binding, "unbound: %s", p->have_topo ? "thread binding unsupported here" : "hwloc topology unavailable");
}

retro_pool *retro_pool_get(retro_ctx *rc, int threads, int d)
{
    retro_pool *p = rc->pool;
    if (!p) {
        p = calloc(1, sizeof *p);
        if (!p)
            return NULL;
        pool_init(p);
        rc->pool = p;
    }
    if (threads > p->cap_threads || d > p->cap_d) {
        int t_new = threads > p->cap_threads ? threads : p->cap_threads;
        int d_new = d > p->cap_d ? d : p->cap_d;
        /* Rounded up to whole cache lines so two threads never share one. */
        size_t bytes = ((size_t)d_new * sizeof(float) + 63) / 64 * 64;
        for (int t = 0; t < t_new; t++) {
            free(p->qx[t]);
            free(p->qy[t]);
            p->qx[t] = aligned_alloc(64, bytes);
            p->qy[t] = aligned_alloc(64, bytes);
            if (!p->qx[t] || !p->qy[t])
                return NULL;
        }
        p->cap_threads = t_new;
        p->cap_d = d_new;
    }
    return p;
}

void retro_pool_enter(retro_pool *p)
{
    /* Once per pool: a frame then costs no system call, as with OpenMP's own proc_bind, which
     * binds the initial thread for good. */
    if (!p->can_bind || p->caller_saved)
        return;
    if (!p->caller && !(p->caller = hwloc_bitmap_alloc()))
        return;
    p->caller_saved = hwloc_get_cpubind(p->topo, p->caller, HWLOC_CPUBIND_THREAD) == 0;
    p->caller_thread = pthread_self();
}

/* Gives the thread that rendered its binding back when the context is freed on that thread. */
static void pool_restore_caller(retro_pool *p)
{
    if (!p->caller_saved || !pthread_equal(p->caller_thread, pthread_self()))
        return;
    hwloc_set_cpubind(p->topo, p->caller, HWLOC_CPUBIND_THREAD);
    bound_core = -1;
}

void retro_pool_bind(retro_pool *p, int t)
{
    if (!p->can_bind)
        return;
    int core = t % p->cores;
    if (bound_serial == p->serial && bound_core == core)
        return;
    hwloc_obj_t obj = hwloc_get_obj_by_type(p->topo, HWLOC_OBJ_CORE, (unsigned)core);
    if (!obj)
        return;
    hwloc_bitmap_t set = hwloc_bitmap_dup(obj->cpuset);
    hwloc_bitmap_singlify(set);
    if (hwloc_set_cpubind(p->topo, set, HWLOC_CPUBIND_THREAD) == 0) {
        bound_core = core;
        bound_serial = p->serial;
    }
    hwloc_bitmap_free(set);
}

float *retro_pool_qx(retro_pool *p, int t) { return p->qx[t]; }
float *retro_pool_qy(retro_pool *p, int t) { return p->qy[t]; }

int retro_pool_threads(const retro_ctx *rc)
{
    int t = rc->threads > 0 ? rc->threads : omp_get_max_threads();
    return t < 1 ? 1 : t > RETRO_MAX_THREADS ? RETRO_MAX_THREADS : t;
}

const char *retro_pool_binding(retro_ctx *rc)
{
    retro_pool *p = retro_pool_get(rc, 1, 1);
    return p ? p->binding : "unknown (out of memory)";
}

int retro_ctx_threads(const retro_ctx *rc) { return retro_pool_threads(rc); }
const char *retro_ctx_binding(retro_ctx *rc) { return retro_pool_binding(rc); }

void retro_pool_free(retro_ctx *rc)
{
    retro_pool *p = rc->pool;
    if (!p)
        return;
    for (int t = 0; t < p->cap_threads; t++) {
        free(p->qx[t]);
        free(p->qy[t]);
    }
    pool_restore_caller(p);
    if (p->caller)
        hwloc_bitmap_free(p->caller);
    if (p->have_topo)
        hwloc_topology_destroy(p->topo);
    free(p);
    rc->pool = NULL;
}
