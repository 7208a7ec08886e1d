/* mesh-omp: the fast kernel on every thread, each drawing one band of rows. Bands are
 * contiguous; a thread culls the blocks that lie outside its band (the band's bottom and top
 * planes join the frustum's in block culling), so the geometry is shared out as well as the
 * raster. Each pixel still sees exactly the serial kernel's sequence of fragments, water blends
 * included (every thread sorts the same water list and blends only its rows), so the bytes do
 * not depend on the thread count, the band boundaries or the schedule. The boundaries follow
 * the previous frame's per-thread times (the terrain is not spread evenly over the rows); that
 * changes only who draws a row, never what is drawn. Threads are pinned with hwloc one per
 * core for the frame and get their former binding back after it. */
#include <hwloc.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_internal.h"

#define MESH_MAX_THREADS 64

struct mesh_omp {
    retro_mesh_ctx *sub[MESH_MAX_THREADS]; /* per-thread contexts: scratch, water list, stats */
    hwloc_bitmap_t saved[MESH_MAX_THREADS]; /* each thread's binding before the frame */
    int cut[MESH_MAX_THREADS + 1];         /* band t: rows cut[t] + 1 .. cut[t + 1] */
    double secs[MESH_MAX_THREADS];         /* each band's time in the previous frame */
    int last_T, last_H;
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

/* Band boundaries for T threads over H rows: equal on the first frame (or a new size), then
 * cut where the previous frame's cost, taken as uniform inside each band, splits evenly. */
static void plan_bands(struct mesh_omp *o, int T, int H)
{
    if (T != o->last_T || H != o->last_H) {
        for (int t = 0; t <= T; t++)
            o->cut[t] = (int)((int64_t)H * t / T);
        o->last_T = T;
        o->last_H = H;
        return;
    }
    double total = 0;
    for (int t = 0; t < T; t++)
        total += o->secs[t];
    if (!(total > 0))
        return;
    int cut[MESH_MAX_THREADS + 1];
    cut[0] = 0;
    cut[T] = H;
    double acc = 0;
    int b = 0;
    for (int t = 1; t < T; t++) {
        double goal = total * t / T;
        /* walk bands until the goal falls inside band b, then interpolate a row in it */
        while (b < T - 1 && acc + o->secs[b] < goal)
            acc += o->secs[b++];
        int lo = o->cut[b], hi = o->cut[b + 1];
        double frac = o->secs[b] > 0 ? (goal - acc) / o->secs[b] : 0.5;
        int r = lo + (int)(frac * (hi - lo) + 0.5);
        int minr = cut[t - 1] + (H >= T ? 1 : 0), maxr = H - (H >= T ? T - t : 0);
        cut[t] = r < minr ? minr : r > maxr ? maxr : r;
    }
    for (int t = 0; t <= T; t++)
        o->cut[t] = cut[t];
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
    plan_bands(o, T, mc->f.H);
    for (int t = 0; t < T; t++) {
        retro_mesh_ctx *s = o->sub[t];
        s->f = mc->f;
        s->f.rlo = o->cut[t] + 1;
        s->f.rhi = o->cut[t + 1];
        /* the band's planes: V >= rlo - 0.5 and V <= rhi + 0.5 */
        s->f.bcb = mc->f.cy - (double)s->f.rlo + 0.5;
        s->f.bct = (double)s->f.rhi + 0.5 - mc->f.cy;
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
        double t0 = omp_get_wtime();
        if (o->sub[t]->f.rlo <= o->sub[t]->f.rhi)
            mesh_frame_passes(o->sub[t]);
        o->secs[t] = omp_get_wtime() - t0;
        if (bound)
            hwloc_set_cpubind(o->topo, o->saved[t], HWLOC_CPUBIND_THREAD);
    }
    /* Counts add up over the bands: geometry a band culls or shares is counted per band. */
    memset(&mc->st, 0, sizeof mc->st);
    for (int t = 0; t < T; t++) {
        const retro_mesh_stats *b = &o->sub[t]->st;
        mc->st.submitted += b->submitted;
        mc->st.culled += b->culled;
        mc->st.clipped_out += b->clipped_out;
        mc->st.rasterized += b->rasterized;
        mc->st.fragments += b->fragments;
        mc->st.written += b->written;
        mc->oom |= o->sub[t]->oom;
    }
    return RETRO_MESH_OK;
}
