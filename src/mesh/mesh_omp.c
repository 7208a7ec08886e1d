/* mesh-omp: the fast kernel's work split over threads in two passes, so that no thread repeats
 * another's geometry and the raster is shared out by rows.
 * 1. The blocks traversal does not cull are listed in its order; the threads take them
 *    dynamically and run the fast block stage on each in recording mode (mesh_rec.h): vertex
 *    stage, classification, tiny triangles up to their depth tests, all done once per block.
 * 2. Each thread owns one band of contiguous rows and replays every block's record in the list's
 *    order (mesh_replay.c), drawing only its rows: the depth tests of tiny triangles, the raster
 *    of larger ones, the reference stages for squares that need clipping, then the water pass
 *    (every band sorts the same water list and blends only its rows).
 * Each pixel therefore sees exactly the serial kernel's sequence of fragments: the bytes do not
 * depend on the thread count, which thread recorded a block, the band boundaries or the
 * schedule. The boundaries follow the previous frame's second-pass times (the terrain is not
 * spread evenly over the rows); that changes only who draws a row, never what is drawn.
 * Threads are pinned with hwloc one per core for the frame and get their former binding back
 * after it. */
#include <hwloc.h>
#include <limits.h>
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
    mesh_blocks blocks;                    /* pass 1's blocks, in traversal order */
    mesh_recbuf rec[MESH_MAX_THREADS];     /* each thread's records of the blocks it took */
    int *owner;                            /* block k: recorded by thread owner[k] ... */
    size_t *from, *to;                     /* ... as words from[k] .. to[k] of its buffer */
    int (*rows)[2];                        /* drawing in rows rows[k][0] .. rows[k][1] */
    size_t blocks_cap;
    retro_mesh_stats geo[MESH_MAX_THREADS]; /* each thread's counts in pass 1 */
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
    for (int t = 0; t < MESH_MAX_THREADS; t++)
        free(o->rec[t].w);
    free(o->blocks.b);
    free(o->owner);
    free(o->from);
    free(o->to);
    free(o->rows);
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

/* Room for pass 1's index of n blocks. */
static int block_index(struct mesh_omp *o, size_t n)
{
    if (n <= o->blocks_cap)
        return 0;
    int *ow = realloc(o->owner, n * sizeof *ow);
    if (ow)
        o->owner = ow;
    size_t *fr = realloc(o->from, n * sizeof *fr);
    if (fr)
        o->from = fr;
    size_t *to = realloc(o->to, n * sizeof *to);
    if (to)
        o->to = to;
    int(*rows)[2] = realloc(o->rows, n * sizeof *rows);
    if (rows)
        o->rows = rows;
    if (!ow || !fr || !to || !rows)
        return -1;
    o->blocks_cap = n;
    return 0;
}

static void add_geometry(retro_mesh_stats *d, const retro_mesh_stats *s)
{
    d->submitted += s->submitted;
    d->culled += s->culled;
    d->clipped_out += s->clipped_out;
    d->rasterized += s->rasterized;
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
    o->blocks.n = 0;
    o->blocks.oom = 0;
    mc->collect = &o->blocks;
    mesh_traverse(mc);
    mc->collect = NULL;
    if (o->blocks.oom || block_index(o, o->blocks.n)) {
        strcpy(mc->err, "out of memory");
        return RETRO_MESH_ENOMEM;
    }
    plan_bands(o, T, mc->f.H);
    for (int t = 0; t < T; t++) {
        retro_mesh_ctx *s = o->sub[t];
        s->f = mc->f; /* pass 1 records for the whole screen */
        s->depth = mc->depth;
        s->out = mc->out;
        memset(&s->st, 0, sizeof s->st);
        s->water_n = 0;
        s->oom = 0;
        o->rec[t].n = 0;
        o->rec[t].oom = 0;
        s->rec = &o->rec[t];
    }
    const long nb = (long)o->blocks.n;
#pragma omp parallel num_threads(T)
    {
        int t = omp_get_thread_num();
        retro_mesh_ctx *s = o->sub[t];
        int bound = bind_core(o, t, o->saved[t]);
#pragma omp for schedule(dynamic, 4)
        for (long k = 0; k < nb; k++) {
            mesh_recbuf *r = &o->rec[t];
            o->from[k] = r->n;
            r->rmin = INT_MAX;
            r->rmax = INT_MIN;
            mesh_block_draw(s, o->blocks.b[k]);
            o->owner[k] = t;
            o->to[k] = r->n;
            o->rows[k][0] = r->rmin;
            o->rows[k][1] = r->rmax;
        }
        /* (the loop's barrier: every record is complete) */
        o->geo[t] = s->st;
        memset(&s->st, 0, sizeof s->st);
        s->rec = NULL;
        s->f.rlo = o->cut[t] + 1;
        s->f.rhi = o->cut[t + 1];
        double t0 = omp_get_wtime();
        if (s->f.rlo <= s->f.rhi) {
            for (long k = 0; k < nb; k++) {
                const mesh_recbuf *r = &o->rec[o->owner[k]];
                if (!r->oom && o->rows[k][0] <= s->f.rhi && o->rows[k][1] >= s->f.rlo)
                    mesh_replay(s, r->w + o->from[k], o->to[k] - o->from[k]);
            }
            mesh_water_draw(s);
        }
        o->secs[t] = omp_get_wtime() - t0;
        if (bound)
            hwloc_set_cpubind(o->topo, o->saved[t], HWLOC_CPUBIND_THREAD);
    }
    /* Geometry: pass 1's counts, and those of the reference stages (squares that need clipping,
     * generic triangles) once, from the first band that ran (every band runs the same ones);
     * fragments: pass 1's tiny triangles and every band's rows; written: every band's. */
    memset(&mc->st, 0, sizeof mc->st);
    int first = -1, rec_oom = 0;
    for (int t = 0; t < T; t++) {
        const retro_mesh_stats *b = &o->sub[t]->st;
        add_geometry(&mc->st, &o->geo[t]);
        mc->st.fragments += o->geo[t].fragments + b->fragments;
        mc->st.written += b->written;
        mc->oom |= o->sub[t]->oom;
        rec_oom |= o->rec[t].oom;
        if (first < 0 && o->cut[t] + 1 <= o->cut[t + 1])
            first = t;
    }
    if (first >= 0)
        add_geometry(&mc->st, &o->sub[first]->st);
    if (rec_oom) {
        strcpy(mc->err, "out of memory");
        return RETRO_MESH_ENOMEM;
    }
    return RETRO_MESH_OK;
}
