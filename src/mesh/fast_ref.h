/* The fast kernels' hand-over to the reference stages (plain C: the block stage of each ISA and
 * mesh-omp's replay include it): a grid vertex's full record, and a triangle inside every
 * frustum plane given to the reference scan conversion. */
#ifndef RETRO_MESH_FAST_REF_H
#define RETRO_MESH_FAST_REF_H

#include <stdint.h>

#include "mesh_internal.h"

static int fast_wrap(int64_t v, int S)
{
    int64_t r = v % S;
    return (int)(r < 0 ? r + S : r);
}

/* The reference's vertex record of grid vertex (i, j), computed when a square first needs it. */
static void fast_full_vertex(retro_mesh_ctx *mc, uint32_t *done, int stride, int Ia, int Ja, int i, int j)
{
    if (done[j] >> i & 1u)
        return;
    done[j] |= 1u << i;
    mesh_grid_vertex(&mc->f, Ia + i, Ja + j, &mc->grid[j * stride + i], &mc->snap[j * stride + i]);
}

/* A triangle of an inside square whose attributes the nearest raster does not carry (shade,
 * texture, gouraud): the reference's triangle record, handed to the reference scan conversion. */
static void fast_generic(retro_mesh_ctx *mc, const int idx[3], const double sx[3], const double sy[3], int I, int J,
                         int back, const int32_t X[3], const int32_t Y[3])
{
    const mesh_frame *f = &mc->f;
    mesh_tri t;
    for (int k = 0; k < 3; k++) {
        t.v[k] = mc->grid[idx[k]];
        t.v[k].a[A_SX] = sx[k];
        t.v[k].a[A_SY] = sy[k];
    }
    t.I = fast_wrap(I, f->S);
    t.J = fast_wrap(J, f->S);
    t.water = 0;
    t.back = back;
    mesh_sub s;
    for (int q = 0; q < 3; q++) {
        s.X[q] = X[q];
        s.Y[q] = Y[q];
        s.v[q] = &t.v[q];
    }
    s.edges = 7;
    s.t = &t;
    mesh_scan_convert(mc, &s);
}

#endif
