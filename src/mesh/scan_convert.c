/* Scan conversion setup: Pineda edge functions over the sub-triangle's bounding box clipped to
 * the screen, in fixed point (RETRO_MESH_SUBPIXEL_BITS), with the top-left fill rule. Pixel
 * (u, r) has its centre at X = u - 1, V = r; the row loops live in the raster_* files. */
#include "mesh_internal.h"

static int64_t floor_div(int64_t a, int64_t b) /* b > 0 */
{
    int64_t q = a / b;
    return q - ((a % b != 0) && (a < 0));
}

static int64_t ceil_div(int64_t a, int64_t b)
{
    return -floor_div(-a, b);
}

void mesh_scan_convert(retro_mesh_ctx *mc, const mesh_sub *in)
{
    const mesh_frame *f = &mc->f;
    mesh_sub s = *in;
    int64_t A = (s.X[1] - s.X[0]) * (s.Y[2] - s.Y[0]) - (s.Y[1] - s.Y[0]) * (s.X[2] - s.X[0]);
    if (A == 0)
        return;
    if (A < 0) {
        /* Only drawn when culling is off (or for water): reversed to counter-clockwise. A
         * front face that snapping turned over is a sliver its neighbours cover. */
        if (!(f->mfx & RETRO_MESH_FX_NOCULL) && !s.t->water)
            return;
        int64_t tx = s.X[1], ty = s.Y[1];
        const mesh_vert *tv = s.v[1];
        s.X[1] = s.X[2];
        s.Y[1] = s.Y[2];
        s.v[1] = s.v[2];
        s.X[2] = tx;
        s.Y[2] = ty;
        s.v[2] = tv;
        s.edges = ((in->edges & 4u) >> 2) | (in->edges & 2u) | ((in->edges & 1u) << 2);
        A = -A;
    }
    mc->st.rasterized++;
    int64_t xmin = s.X[0], xmax = s.X[0], ymin = s.Y[0], ymax = s.Y[0];
    for (int k = 1; k < 3; k++) {
        xmin = s.X[k] < xmin ? s.X[k] : xmin;
        xmax = s.X[k] > xmax ? s.X[k] : xmax;
        ymin = s.Y[k] < ymin ? s.Y[k] : ymin;
        ymax = s.Y[k] > ymax ? s.Y[k] : ymax;
    }
    int64_t c0 = ceil_div(xmin, MESH_ONE), c1 = floor_div(xmax, MESH_ONE);
    int64_t r0 = ceil_div(ymin, MESH_ONE), r1 = floor_div(ymax, MESH_ONE);
    c0 = c0 < 0 ? 0 : c0;
    c1 = c1 > f->W - 1 ? f->W - 1 : c1;
    r0 = r0 < 1 ? 1 : r0;
    r1 = r1 > f->H ? f->H : r1;
    if (c0 > c1 || r0 > r1)
        return;
    int64_t E[3], dx[3], dy[3];
    for (int k = 0; k < 3; k++) {
        int n = k == 2 ? 0 : k + 1;
        dx[k] = s.X[n] - s.X[k];
        dy[k] = s.Y[n] - s.Y[k];
        /* E_k(p) = dx (py - Yk) - dy (px - Xk): positive inside a counter-clockwise triangle */
        E[k] = dx[k] * (r0 * MESH_ONE - s.Y[k]) - dy[k] * (c0 * MESH_ONE - s.X[k]);
    }
    switch (f->mode) {
    case RETRO_MESH_BINARY32: mesh_raster_f32(mc, &s, A, E, dx, dy, (int)c0, (int)c1, (int)r0, (int)r1); break;
    case RETRO_MESH_BINARY64: mesh_raster_f64(mc, &s, A, E, dx, dy, (int)c0, (int)c1, (int)r0, (int)r1); break;
    default: mesh_raster_int(mc, &s, A, E, dx, dy, (int)c0, (int)c1, (int)r0, (int)r1); break;
    }
}
