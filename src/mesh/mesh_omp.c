/* mesh-omp: the fast kernel's work split over threads by runs of the block list, composited
 * after the fact (sort-last), so that no thread repeats another's work.
 * 1. The blocks traversal does not cull are listed in its order and cut into T contiguous
 *    runs. Thread t draws run t with the fast block stage into a depth and colour buffer of its
 *    own (thread 0 into the frame's), as the serial kernel would draw it into a cleared frame.
 * 2. By rows, the buffers are merged in run order: a later run's pixel replaces the frame's
 *    only where its depth is strictly smaller.
 * 3. The water triangles, each thread's list appended in run order, are drawn by bands of
 *    rows over the merged frame.
 * Why the bytes are the serial kernel's: the terrain only writes (no fragment reads a colour;
 * fog depends on the fragment's own depth), and the depth test is strict, so each pixel keeps
 * the first fragment of least depth in drawing order. Within a run that is the run's own
 * buffer; across runs every fragment of an earlier run was drawn first, so the earlier run
 * wins ties, which the merge's strict test gives. The water list in run order is the serial
 * list, so its sequence numbers, and the water pass's order, are the same. None of this
 * depends on the thread count or where the runs are cut; the cuts follow the previous frame's
 * times (the cost per block is far from uniform: near blocks raster more), which changes
 * only who draws a block. The one thing that does change is `written`: a later run stores
 * fragments an earlier run's terrain hides, so it counts at least mesh-zbuffer's writes,
 * exactly those at one thread (docs/MESH_FAST.md).
 * Threads are pinned with hwloc one per core for the frame and get their former binding back
 * after it. */
#include <hwloc.h>
#include <limits.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_internal.h"

#define MESH_MAX_THREADS 64

/* Extra buffers (8 bytes a pixel per thread after the first) are kept to this many bytes in
 * all: a frame too large for them runs on fewer threads. */
#define MESH_OMP_EXTRA_BYTES ((size_t)1 << 30)

struct mesh_omp {
    retro_mesh_ctx *sub[MESH_MAX_THREADS]; /* per-thread contexts: scratch, water list, stats */
    hwloc_bitmap_t saved[MESH_MAX_THREADS]; /* each thread's binding before the frame */
    float *zbuf[MESH_MAX_THREADS];          /* thread t > 0: its depth and colour buffers ... */
    uint32_t *cbuf[MESH_MAX_THREADS];
    size_t buf_px[MESH_MAX_THREADS];        /* ... of this many pixels */
    int run[MESH_MAX_THREADS + 1];          /* run t: blocks run[t] .. run[t + 1] - 1 */
    double secs[MESH_MAX_THREADS];          /* each run's time in the previous frame */
    int last_T;
    size_t last_n;
    mesh_blocks blocks;                     /* the blocks to draw, in traversal order */
    retro_mesh_stats terrain[MESH_MAX_THREADS]; /* each thread's counts before the water pass */
    hwloc_topology_t topo;
    int have_topo, cores;
};

void mesh_omp_free(struct mesh_omp *o)
{
    if (!o)
        return;
    for (int t = 0; t < MESH_MAX_THREADS; t++)
        if (o->sub[t]) {
            o->sub[t]->depth = NULL; /* the parent's or zbuf[t] */
            retro_mesh_ctx_free(o->sub[t]);
        }
    for (int t = 0; t < MESH_MAX_THREADS; t++) {
        if (o->saved[t])
            hwloc_bitmap_free(o->saved[t]);
        free(o->zbuf[t]);
        free(o->cbuf[t]);
    }
    if (o->have_topo)
        hwloc_topology_destroy(o->topo);
    free(o->blocks.b);
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

/* Where the runs of n blocks are cut for T threads: equal counts on the first frame (or a new
 * count), then where the previous frame's time, taken as uniform over each run's blocks,
 * splits evenly. */
static void plan_runs(struct mesh_omp *o, int T, size_t n)
{
    if (T != o->last_T || n != o->last_n) {
        for (int t = 0; t <= T; t++)
            o->run[t] = (int)((int64_t)n * t / T);
        o->last_T = T;
        o->last_n = n;
        return;
    }
    double total = 0;
    for (int t = 0; t < T; t++)
        total += o->secs[t];
    if (!(total > 0))
        return;
    int cut[MESH_MAX_THREADS + 1];
    cut[0] = 0;
    cut[T] = (int)n;
    double acc = 0;
    int b = 0;
    for (int t = 1; t < T; t++) {
        double goal = total * t / T;
        /* walk runs until the goal falls inside run b, then interpolate a block in it */
        while (b < T - 1 && acc + o->secs[b] < goal)
            acc += o->secs[b++];
        int lo = o->run[b], hi = o->run[b + 1];
        double frac = o->secs[b] > 0 ? (goal - acc) / o->secs[b] : 0.5;
        int k = lo + (int)(frac * (hi - lo) + 0.5);
        cut[t] = k < cut[t - 1] ? cut[t - 1] : k > (int)n ? (int)n : k;
    }
    for (int t = 0; t <= T; t++)
        o->run[t] = cut[t];
}

/* Buffers for threads 1 .. T-1 at npx pixels; returns how many threads have them (at least 1). */
static int thread_buffers(struct mesh_omp *o, int T, size_t npx)
{
    const size_t per = npx * (sizeof(float) + sizeof(uint32_t));
    const size_t most = per ? MESH_OMP_EXTRA_BYTES / per : (size_t)T;
    if ((size_t)(T - 1) > most)
        T = (int)most + 1;
    for (int t = 1; t < T; t++) {
        if (o->buf_px[t] >= npx)
            continue;
        free(o->zbuf[t]);
        free(o->cbuf[t]);
        o->zbuf[t] = malloc(npx * sizeof(float));
        o->cbuf[t] = malloc(npx * sizeof(uint32_t));
        if (!o->zbuf[t] || !o->cbuf[t]) {
            free(o->zbuf[t]);
            free(o->cbuf[t]);
            o->zbuf[t] = NULL;
            o->cbuf[t] = NULL;
            o->buf_px[t] = 0;
            return t;
        }
        o->buf_px[t] = npx;
    }
    return T;
}

static void add_geometry(retro_mesh_stats *d, const retro_mesh_stats *s)
{
    d->submitted += s->submitted;
    d->culled += s->culled;
    d->clipped_out += s->clipped_out;
    d->rasterized += s->rasterized;
}

/* Thread t's band of water rows, [*lo, *hi] in the frame's 1-based rows; empty when *lo > *hi
 * (more threads than rows). The draw and the stats must cut the same bands. */
static void band_rows(int H, int t, int T, int *lo, int *hi)
{
    *lo = (int)((int64_t)H * t / T) + 1;
    *hi = (int)((int64_t)H * (t + 1) / T);
}

/* Appends thread u's water triangles to thread 0's list (run order); 0 when it cannot grow. */
static int append_water(retro_mesh_ctx *to, const retro_mesh_ctx *from)
{
    if (!from->water_n)
        return 1;
    size_t n = to->water_n + from->water_n;
    if (n > to->water_cap) {
        size_t cap = to->water_cap ? to->water_cap : 256;
        while (cap < n)
            cap *= 2;
        mesh_water_tri *w = realloc(to->water, cap * sizeof *w);
        if (!w)
            return 0;
        to->water = w;
        to->water_cap = cap;
    }
    memcpy(to->water + to->water_n, from->water, from->water_n * sizeof *from->water);
    to->water_n = n;
    return 1;
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
    if (o->blocks.oom) {
        strcpy(mc->err, "out of memory");
        return RETRO_MESH_ENOMEM;
    }
    const size_t npx = (size_t)mc->f.W * (size_t)mc->f.H;
    T = thread_buffers(o, T, npx);
    plan_runs(o, T, o->blocks.n);
    for (int t = 0; t < T; t++) {
        retro_mesh_ctx *s = o->sub[t];
        s->f = mc->f; /* every run draws on the whole screen */
        s->depth = t ? (void *)o->zbuf[t] : mc->depth;
        s->out = t ? o->cbuf[t] : mc->out;
        memset(&s->st, 0, sizeof s->st);
        s->water_n = 0;
        s->oom = 0;
    }
    int water_oom = 0;
#pragma omp parallel num_threads(T)
    {
        const int t = omp_get_thread_num();
        retro_mesh_ctx *s = o->sub[t];
        const int bound = bind_core(o, t, o->saved[t]);
        const double t0 = omp_get_wtime();
        if (t) { /* the frame's own buffers were cleared by retro_mesh_render */
            float *z = o->zbuf[t];
            for (size_t i = 0; i < npx; i++)
                z[i] = (float)INFINITY;
        }
        for (int k = o->run[t]; k < o->run[t + 1]; k++)
            mesh_block_draw(s, o->blocks.b[k]);
        o->secs[t] = omp_get_wtime() - t0;
        o->terrain[t] = s->st;
#pragma omp barrier
        { /* the merge, rows split evenly: a later run only where strictly nearer */
            float *z = mc->depth;
            uint32_t *out = mc->out;
            const size_t a = npx * (size_t)t / (size_t)T, e = npx * (size_t)(t + 1) / (size_t)T;
            for (int u = 1; u < T; u++) {
                const float *zu = o->zbuf[u];
                const uint32_t *cu = o->cbuf[u];
                for (size_t i = a; i < e; i++)
                    if (zu[i] < z[i]) {
                        z[i] = zu[i];
                        out[i] = cu[i];
                    }
            }
        }
#pragma omp barrier
#pragma omp single
        {
            for (int u = 1; u < T; u++)
                if (!append_water(o->sub[0], o->sub[u]))
                    water_oom = 1;
        }
        /* (the single's barrier: the list is complete) */
        if (!water_oom) {
            mesh_water_tri *own = s->water;
            const size_t own_n = s->water_n;
            s->water = o->sub[0]->water; /* read only: each band sorts into its own order */
            s->water_n = o->sub[0]->water_n;
            s->depth = mc->depth;
            s->out = mc->out;
            band_rows(mc->f.H, t, T, &s->f.rlo, &s->f.rhi);
            if (s->f.rlo <= s->f.rhi)
                mesh_water_draw(s);
#pragma omp barrier
            s->water = own;
            s->water_n = own_n;
        }
        if (bound)
            hwloc_set_cpubind(o->topo, o->saved[t], HWLOC_CPUBIND_THREAD);
    }
    /* Terrain: every run's counts (each block drawn once). Water: the geometry of its reference
     * stages once, from the first band that ran (every band runs the same ones); fragments and
     * writes from every band, each counting its own rows. */
    memset(&mc->st, 0, sizeof mc->st);
    int first = -1;
    for (int t = 0; t < T; t++) {
        const retro_mesh_stats *a = &o->terrain[t], *b = &o->sub[t]->st;
        add_geometry(&mc->st, a);
        mc->st.fragments += b->fragments;
        mc->st.written += b->written;
        mc->oom |= o->sub[t]->oom;
        int lo, hi;
        band_rows(mc->f.H, t, T, &lo, &hi);
        if (first < 0 && lo <= hi)
            first = t;
    }
    if (first >= 0) {
        retro_mesh_stats w = o->sub[first]->st;
        const retro_mesh_stats *a = &o->terrain[first];
        w.submitted -= a->submitted;
        w.culled -= a->culled;
        w.clipped_out -= a->clipped_out;
        w.rasterized -= a->rasterized;
        add_geometry(&mc->st, &w);
    }
    if (water_oom)
        mc->oom = 1;
    return RETRO_MESH_OK;
}
