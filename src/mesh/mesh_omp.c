/* mesh-omp: the fast kernel on every thread, each writing only its rows. Rows are dealt in
 * interleaved bands of MESH_BAND (row r to thread ((r - 1) / MESH_BAND) mod T), so the terrain's
 * rows, crowded at the bottom of the screen, spread evenly. Every thread walks the whole
 * geometry in the z-buffer's order (vertex and triangle setup are repeated, the raster is
 * split), so each pixel sees exactly the serial kernel's sequence of fragments, water blends
 * included: the bytes do not depend on the thread count or the schedule. Threads are pinned
 * with hwloc one per core for the frame; the caller's binding is given back after it. */
#include <hwloc.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_internal.h"

#define MESH_MAX_THREADS 64

struct mesh_omp {
    retro_mesh_ctx *sub[MESH_MAX_THREADS]; /* per-thread contexts: scratch, water list, stats */
    hwloc_bitmap_t saved[MESH_MAX_THREADS]; /* each thread's binding before the frame */
    hwloc_topology_t topo;
    int have_topo, cores;
};

void mesh_omp_free(struct mesh_omp *o)
{
    if (!o)
        return;
    for (int t = 0; t < MESH_MAX_THREADS; t++)
        if (o->sub[t]) {
            o->sub[t]->depth = NULL; /* the parent's */
            retro_mesh_ctx_free(o->sub[t]);
        }
    for (int t = 0; t < MESH_MAX_THREADS; t++)
        if (o->saved[t])
            hwloc_bitmap_free(o->saved[t]);
    if (o->have_topo)
        hwloc_topology_destroy(o->topo);
    free(o);
}

static struct mesh_omp *omp_state(retro_mesh_ctx *mc, int threads)
{
    if (!mc->omp) {
        struct mesh_omp *o = calloc(1, sizeof *o);
        if (!o)
            return NULL;
        o->cores = 1;
        if (hwloc_topology_init(&o->topo) == 0) {
            if (hwloc_topology_load(o->topo) == 0) {
                o->have_topo = 1;
                int n = hwloc_get_nbobjs_by_type(o->topo, HWLOC_OBJ_CORE);
                o->cores = n > 0 ? n : 1;
            } else {
                hwloc_topology_destroy(o->topo);
            }
        }
        mc->omp = o;
    }
    for (int t = 0; t < threads; t++)
        if ((!mc->omp->sub[t] && !(mc->omp->sub[t] = retro_mesh_ctx_new())) ||
            (mc->omp->have_topo && !mc->omp->saved[t] && !(mc->omp->saved[t] = hwloc_bitmap_alloc())))
            return NULL;
    return mc->omp;
}

/* Binds the calling thread to core t mod cores; *saved receives its former binding. */
static int bind_core(struct mesh_omp *o, int t, hwloc_bitmap_t saved)
{
    if (!o->have_topo || !saved || hwloc_get_cpubind(o->topo, saved, HWLOC_CPUBIND_THREAD) != 0)
        return 0;
    hwloc_obj_t core = hwloc_get_obj_by_type(o->topo, HWLOC_OBJ_CORE, (unsigned)(t % o->cores));
    return core && hwloc_set_cpubind(o->topo, core->cpuset, HWLOC_CPUBIND_THREAD) == 0;
}

retro_mesh_err mesh_omp_render(retro_mesh_ctx *mc, int threads)
{
    int T = threads > 0 ? threads : omp_get_max_threads();
    T = T < 1 ? 1 : T > MESH_MAX_THREADS ? MESH_MAX_THREADS : T;
    struct mesh_omp *o = omp_state(mc, T);
    if (!o) {
        strcpy(mc->err, "out of memory");
        return RETRO_MESH_ENOMEM;
    }
    for (int t = 0; t < T; t++) {
        retro_mesh_ctx *s = o->sub[t];
        s->f = mc->f;
        s->f.band = t;
        s->f.nband = T;
        s->depth = mc->depth;
        s->out = mc->out;
        memset(&s->st, 0, sizeof s->st);
        s->water_n = 0;
        s->oom = 0;
    }
#pragma omp parallel num_threads(T)
    {
        int t = omp_get_thread_num();
        int bound = bind_core(o, t, o->saved[t]);
        mesh_frame_passes(o->sub[t]);
        if (bound)
            hwloc_set_cpubind(o->topo, o->saved[t], HWLOC_CPUBIND_THREAD);
    }
    /* Geometry is walked by every thread alike: its counts are thread 0's. */
    mc->st = o->sub[0]->st;
    mc->st.fragments = mc->st.written = 0;
    for (int t = 0; t < T; t++) {
        mc->st.fragments += o->sub[t]->st.fragments;
        mc->st.written += o->sub[t]->st.written;
        mc->oom |= o->sub[t]->oom;
    }
    return RETRO_MESH_OK;
}
