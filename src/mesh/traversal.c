/* Traversal: the squares that can fall inside the view, in blocks of MESH_BLOCK x MESH_BLOCK,
 * each block frustum-culled as a box before its vertices are computed. The order is a
 * visibility order of the heightfield (docs/MESH.md, "Order"): the painter visits it as
 * written (back to front), the z-buffer in exact reverse (front to back). */
#include <math.h>
#include <stdlib.h>

#include "mesh_internal.h"

void mesh_grid_vertex(const mesh_frame *f, int I, int J, mesh_vert *v, mesh_snap *s)
{
    mesh_vertex_stage(f, I, J, v);
    double d[6];
    mesh_plane_distances(f, v, d);
    s->out = 0;
    for (int p = 0; p < 6; p++)
        s->out |= d[p] < 0 ? 1u << p : 0u;
    s->ok = s->out == 0;
    if (s->ok)
        mesh_project(f, v, &s->X, &s->Y);
}

/* The block box [x0, x1] x [y0, y1] x [hmin, hmax] lies outside one plane (by a margin that
 * covers the rounding of the vertex stage, so culling never removes a visible triangle). */
static int block_outside(const mesh_frame *f, double x0, double x1, double y0, double y1)
{
    unsigned all = 255;
    for (int k = 0; k < 8 && all; k++) {
        double dx = ((k & 1) ? x1 : x0) - f->x0, dy = ((k & 2) ? y1 : y0) - f->y0;
        double e = ((k & 4) ? f->hmax : f->hmin) - (double)f->height;
        double z = dx * f->cs - dy * f->sn, l = dx * f->sn + dy * f->cs;
        double lx = f->kx * l, ey = f->ky * e;
        /* the six frustum planes, then the bottom and top of this frame's row band */
        double d[8] = {z - 1, f->far - z, lx + f->cl * z, f->cr * z - lx, ey + f->cb * z, f->ct * z - ey,
                       ey + f->bcb * z, f->bct * z - ey};
        double m[8] = {fabs(z), fabs(z), fabs(lx) + fabs(f->cl * z), fabs(lx) + fabs(f->cr * z),
                       fabs(ey) + fabs(f->cb * z), fabs(ey) + fabs(f->ct * z),
                       fabs(ey) + fabs(f->bcb * z), fabs(ey) + fabs(f->bct * z)};
        unsigned out = 0;
        for (int p = 0; p < 8; p++)
            out |= (d[p] < -(1e-5 * m[p] + 1e-3)) ? 1u << p : 0u;
        all &= out;
    }
    return all != 0;
}

/* Squares I in [Ia, Ib], J in [Ja, Jb]; sx, sy = +1 when larger indices are farther from the
 * eye, -1 when smaller are, 0 for a single column or row. */
static void block(retro_mesh_ctx *mc, int Ia, int Ib, int Ja, int Jb, int sx, int sy)
{
    const mesh_frame *f = &mc->f;
    if (block_outside(f, Ia + 0.5, Ib + 1.5, Ja + 0.5, Jb + 1.5))
        return;
    if (mc->collect) {
        mesh_blocks *l = mc->collect;
        if (l->n == l->cap) {
            size_t cap = l->cap ? 2 * l->cap : 1024;
            void *nb = realloc(l->b, cap * sizeof *l->b);
            if (!nb) {
                l->oom = 1;
                return;
            }
            l->b = nb;
            l->cap = cap;
        }
        int32_t *e = l->b[l->n++];
        e[0] = Ia, e[1] = Ib, e[2] = Ja, e[3] = Jb, e[4] = sx, e[5] = sy;
        return;
    }
    if (f->fast == MESH_FAST_AVX512) {
        mesh_fast_block_avx512(mc, Ia, Ib, Ja, Jb, sx, sy);
        return;
    }
    if (f->fast == MESH_FAST_AVX2) {
        mesh_fast_block_avx2(mc, Ia, Ib, Ja, Jb, sx, sy);
        return;
    }
    int ni = Ib - Ia + 1, nj = Jb - Ja + 1, stride = ni + 1;
    for (int j = 0; j <= nj; j++)
        for (int i = 0; i <= ni; i++)
            mesh_grid_vertex(f, Ia + i, Ja + j, &mc->grid[j * stride + i], &mc->snap[j * stride + i]);
    /* painter: farthest row first, farthest square first in a row; z-buffer: the reverse */
    int rev = f->kernel == RETRO_MESH_ZBUFFER;
    int fy = sy >= 0, fx = sx >= 0; /* far rows/columns have larger indices */
    for (int jj = 0; jj < nj; jj++) {
        int j = (fy != rev) ? nj - 1 - jj : jj;
        for (int ii = 0; ii < ni; ii++) {
            int i = (fx != rev) ? ni - 1 - ii : ii;
            mesh_primitive_assembly(mc, mc->grid, mc->snap, stride, j * stride + i, Ia + i, Ja + j);
        }
    }
}

static void quadrant(retro_mesh_ctx *mc, int sx, int sy, int ni, int nj)
{
    const mesh_frame *f = &mc->f;
    const int B = MESH_BLOCK, rev = f->kernel == RETRO_MESH_ZBUFFER;
    int nbi = (ni + B - 1) / B, nbj = (nj + B - 1) / B;
    for (int bb = 0; bb < nbj; bb++) {
        int bj = rev ? bb : nbj - 1 - bb;
        int dj0 = bj * B + 1, dj1 = dj0 + B - 1 < nj ? dj0 + B - 1 : nj;
        for (int aa = 0; aa < nbi; aa++) {
            int bi = rev ? aa : nbi - 1 - aa;
            int di0 = bi * B + 1, di1 = di0 + B - 1 < ni ? di0 + B - 1 : ni;
            int Ia = sx > 0 ? f->Ie + di0 : f->Ie - di1, Ib = sx > 0 ? f->Ie + di1 : f->Ie - di0;
            int Ja = sy > 0 ? f->Je + dj0 : f->Je - dj1, Jb = sy > 0 ? f->Je + dj1 : f->Je - dj0;
            block(mc, Ia, Ib, Ja, Jb, sx, sy);
        }
    }
}

/* A half-axis from the eye square: n squares along x (sx != 0) or y. */
static void axis(retro_mesh_ctx *mc, int sx, int sy, int n)
{
    const mesh_frame *f = &mc->f;
    const int B = MESH_BLOCK, rev = f->kernel == RETRO_MESH_ZBUFFER;
    int nb = (n + B - 1) / B;
    for (int bb = 0; bb < nb; bb++) {
        int b = rev ? bb : nb - 1 - bb;
        int d0 = b * B + 1, d1 = d0 + B - 1 < n ? d0 + B - 1 : n;
        if (sx)
            block(mc, sx > 0 ? f->Ie + d0 : f->Ie - d1, sx > 0 ? f->Ie + d1 : f->Ie - d0, f->Je, f->Je, sx, 0);
        else
            block(mc, f->Ie, f->Ie, sy > 0 ? f->Je + d0 : f->Je - d1, sy > 0 ? f->Je + d1 : f->Je - d0, 0, sy);
    }
}

void mesh_traverse(retro_mesh_ctx *mc)
{
    const mesh_frame *f = &mc->f;
    if (f->far <= 1)
        return; /* the near plane at or beyond the far plane: sky only */
    /* The plan bounding box of the view wedge (eye and the far plane's ends), two squares wider. */
    double tmax = f->cr / f->kx, fw = f->far, lat = f->far * tmax;
    double px[3] = {f->x0, f->x0 + fw * f->cs + lat * f->sn, f->x0 + fw * f->cs - lat * f->sn};
    double py[3] = {f->y0, f->y0 - fw * f->sn + lat * f->cs, f->y0 - fw * f->sn - lat * f->cs};
    double xmin = px[0], xmax = px[0], ymin = py[0], ymax = py[0];
    for (int k = 1; k < 3; k++) {
        xmin = fmin(xmin, px[k]);
        xmax = fmax(xmax, px[k]);
        ymin = fmin(ymin, py[k]);
        ymax = fmax(ymax, py[k]);
    }
    int Imin = (int)floor(xmin - 2.5), Imax = (int)ceil(xmax + 1.5);
    int Jmin = (int)floor(ymin - 2.5), Jmax = (int)ceil(ymax + 1.5);
    int ip = Imax - f->Ie > 0 ? Imax - f->Ie : 0, im = f->Ie - Imin > 0 ? f->Ie - Imin : 0;
    int jp = Jmax - f->Je > 0 ? Jmax - f->Je : 0, jm = f->Je - Jmin > 0 ? f->Je - Jmin : 0;
    static const int qs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    static const int as[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    if (f->kernel == RETRO_MESH_ZBUFFER) {
        block(mc, f->Ie, f->Ie, f->Je, f->Je, 0, 0);
        for (int k = 3; k >= 0; k--)
            axis(mc, as[k][0], as[k][1], as[k][0] > 0 ? ip : as[k][0] < 0 ? im : as[k][1] > 0 ? jp : jm);
        for (int k = 3; k >= 0; k--)
            quadrant(mc, qs[k][0], qs[k][1], qs[k][0] > 0 ? ip : im, qs[k][1] > 0 ? jp : jm);
    } else {
        for (int k = 0; k < 4; k++)
            quadrant(mc, qs[k][0], qs[k][1], qs[k][0] > 0 ? ip : im, qs[k][1] > 0 ? jp : jm);
        for (int k = 0; k < 4; k++)
            axis(mc, as[k][0], as[k][1], as[k][0] > 0 ? ip : as[k][0] < 0 ? im : as[k][1] > 0 ? jp : jm);
        block(mc, f->Ie, f->Ie, f->Je, f->Je, 0, 0);
    }
}

void mesh_block_draw(retro_mesh_ctx *mc, const int32_t b[6])
{
    if (mc->f.fast == MESH_FAST_AVX512)
        mesh_fast_block_avx512(mc, b[0], b[1], b[2], b[3], b[4], b[5]);
    else
        mesh_fast_block_avx2(mc, b[0], b[1], b[2], b[3], b[4], b[5]);
}
