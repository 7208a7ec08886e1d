/* The mesh family's entry point: context, frame, the opaque pass, the water pass. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_internal.h"

retro_mesh_ctx *retro_mesh_ctx_new(void)
{
    retro_mesh_ctx *mc = calloc(1, sizeof *mc);
    if (!mc)
        return NULL;
    size_t n = (size_t)(MESH_BLOCK + 1) * (MESH_BLOCK + 1);
    mc->grid = malloc(n * sizeof *mc->grid);
    mc->snap = malloc(n * sizeof *mc->snap);
    if (!mc->grid || !mc->snap) {
        retro_mesh_ctx_free(mc);
        return NULL;
    }
    return mc;
}

void retro_mesh_ctx_free(retro_mesh_ctx *mc)
{
    if (!mc)
        return;
    free(mc->depth);
    free(mc->grid);
    free(mc->snap);
    free(mc->water);
    free(mc->order);
    free(mc->fogtab);
    mesh_omp_free(mc->omp);
    free(mc);
}

const char *retro_mesh_error(const retro_mesh_ctx *mc)
{
    return mc ? mc->err : "no mesh context";
}

const char *retro_mesh_mode_name(retro_mesh_mode mode)
{
    static const char *const names[] = {"binary32", "binary64", "int"};
    return (unsigned)mode < RETRO_MESH_MODE_COUNT ? names[mode] : "?";
}

const char *retro_mesh_kernel_name(retro_mesh_kernel kernel)
{
    static const char *const names[] = {"zbuffer", "painter", "avx2", "avx512", "omp"};
    return (unsigned)kernel < RETRO_MESH_KERNEL_COUNT ? names[kernel] : "?";
}

/* Water triangles are kept until the opaque terrain is done. */
void mesh_water_add(retro_mesh_ctx *mc, const mesh_tri *t)
{
    if (mc->water_n == mc->water_cap) {
        size_t cap = mc->water_cap ? 2 * mc->water_cap : 1024;
        mesh_water_tri *w = realloc(mc->water, cap * sizeof *w);
        if (!w) {
            mc->oom = 1;
            return;
        }
        mc->water = w;
        mc->water_cap = cap;
    }
    mesh_water_tri *w = &mc->water[mc->water_n++];
    for (int k = 0; k < 3; k++) {
        w->l[k] = t->v[k].l;
        w->z[k] = t->v[k].z;
        w->e[k] = t->v[k].e;
        w->alpha[k] = t->v[k].a[A_ALPHA];
    }
}

typedef struct {
    double key; /* eye-space depth of the centroid */
    size_t seq; /* traversal order: ties keep it */
} water_key;

/* a before b in the water pass: farther first, then traversal order (a total order, so any
 * sorting algorithm gives the same sequence) */
static int before(const water_key *a, const water_key *b)
{
    return a->key != b->key ? a->key > b->key : a->seq < b->seq;
}

static void sift(water_key *o, size_t i, size_t n)
{
    for (;;) {
        size_t c = 2 * i + 1;
        if (c >= n)
            return;
        if (c + 1 < n && before(&o[c], &o[c + 1]))
            c++;
        if (!before(&o[i], &o[c]))
            return;
        water_key t = o[i];
        o[i] = o[c];
        o[c] = t;
        i = c;
    }
}

/* Heapsort in place: no allocation (the C library's qsort may allocate). */
static void sort_keys(water_key *o, size_t n)
{
    for (size_t i = n / 2; i-- > 0;)
        sift(o, i, n);
    for (size_t end = n; end-- > 1;) {
        water_key t = o[0];
        o[0] = o[end];
        o[end] = t;
        sift(o, 0, end);
    }
}

/* Back to front by the centroid's eye depth, each blended over what is behind it. */
void mesh_water_draw(retro_mesh_ctx *mc)
{
    const mesh_frame *f = &mc->f;
    size_t n = mc->water_n;
    if (!n)
        return;
    if (n > mc->order_cap) {
        water_key *o = realloc(mc->order, n * sizeof *o);
        if (!o) {
            mc->oom = 1;
            return;
        }
        mc->order = o;
        mc->order_cap = n;
    }
    water_key *o = mc->order;
    for (size_t i = 0; i < n; i++) {
        const mesh_water_tri *t = &mc->water[i];
        o[i].key = rn(f, rn(f, rn(f, t->z[0] + t->z[1]) + t->z[2]) / 3.0);
        o[i].seq = i;
    }
    sort_keys(o, n);
    mesh_tri tri;
    memset(&tri, 0, sizeof tri);
    tri.water = 1;
    const mesh_tri *t = &tri;
    for (size_t i = 0; i < n; i++) {
        const mesh_water_tri *w = &mc->water[o[i].seq];
        for (int k = 0; k < 3; k++) {
            tri.v[k].l = w->l[k];
            tri.v[k].z = w->z[k];
            tri.v[k].e = w->e[k];
            tri.v[k].a[A_ALPHA] = w->alpha[k];
        }
        mesh_snap s[3];
        const mesh_snap *s3[3] = {&s[0], &s[1], &s[2]};
        for (int k = 0; k < 3; k++) {
            double d[6];
            mesh_plane_distances(f, &t->v[k], d);
            s[k].out = 0;
            for (int p = 0; p < 6; p++)
                s[k].out |= d[p] < 0 ? 1u << p : 0u;
            s[k].ok = s[k].out == 0;
            if (s[k].ok)
                mesh_project(f, &t->v[k], &s[k].X, &s[k].Y);
        }
        mesh_clip_and_draw(mc, t, s3);
    }
}

void mesh_frame_passes(retro_mesh_ctx *mc)
{
    mesh_traverse(mc);
    mesh_water_draw(mc);
}

retro_mesh_err retro_mesh_render(retro_mesh_ctx *mc, retro_mesh_kernel kernel, retro_mesh_mode mode,
                                 const player_t *p, const ctx_t *c, const retro_effects *fx,
                                 const retro_mesh_opts *opts, retro_mesh_stats *stats)
{
    if (!mc)
        return RETRO_MESH_EINVAL;
    mc->err[0] = 0;
    int threads = opts ? opts->threads : 0;
    if (threads < 0 || threads > 64) {
        strcpy(mc->err, "threads out of range (0..64)");
        return RETRO_MESH_EINVAL;
    }
    retro_mesh_err e = mesh_frame_setup(mc, kernel, mode, p, c, fx, opts ? opts->flags : 0);
    if (e)
        return e;
    const mesh_frame *f = &mc->f;
    const int zb = f->kernel == RETRO_MESH_ZBUFFER;
    size_t npx = (size_t)f->W * (size_t)f->H;
    size_t bytes = npx * (mode == RETRO_MESH_BINARY64 ? sizeof(double) : sizeof(float));
    if (zb && bytes > mc->depth_cap) {
        void *d = realloc(mc->depth, bytes);
        if (!d) {
            strcpy(mc->err, "out of memory");
            return RETRO_MESH_ENOMEM;
        }
        mc->depth = d;
        mc->depth_cap = bytes;
    }
    memset(&mc->st, 0, sizeof mc->st);
    mc->water_n = 0;
    mc->oom = 0;
    mc->out = c->out;
    for (size_t i = 0; i < npx; i++)
        c->out[i] = f->sky;
    if (zb) {
        if (mode == RETRO_MESH_BINARY32)
            for (size_t i = 0; i < npx; i++)
                ((float *)mc->depth)[i] = (float)INFINITY;
        else if (mode == RETRO_MESH_BINARY64)
            for (size_t i = 0; i < npx; i++)
                ((double *)mc->depth)[i] = INFINITY;
        else
            memset(mc->depth, 0, npx * sizeof(uint32_t)); /* 1/z = 0: infinitely far */
    }
    if (kernel == RETRO_MESH_OMP) {
        e = mesh_omp_render(mc, threads);
        if (e)
            return e;
    } else {
        mesh_frame_passes(mc);
    }
    if (stats)
        *stats = mc->st;
    if (mc->oom) {
        strcpy(mc->err, "out of memory for the water triangles");
        return RETRO_MESH_ENOMEM;
    }
    return RETRO_MESH_OK;
}
