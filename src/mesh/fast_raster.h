/* The fast kernels' raster of one triangle that lies inside every frustum plane, mode binary32,
 * colour nearest (with fog and wireframe): the loop of raster_tmpl.h with only the attributes
 * this colour source reads (sx, sy), the vertex reciprocals 1/z from the vertex stage's lanes,
 * and the setup deferred until the bounding box is known to hold a pixel centre of its rows.
 * The caller counts the triangle as rasterized (A != 0 with the orientation it draws).
 * Every operation is raster_tmpl.h's, in its order, so the bytes are mesh-zbuffer's. */
#ifndef RETRO_MESH_FAST_RASTER_H
#define RETRO_MESH_FAST_RASTER_H

#include <math.h>

#include "mesh_fragment.h"
#include "mesh_internal.h"

static inline int fast_fog(const mesh_frame *f, float z)
{
    float fw;
    if (f->fog_exp)
        fw = 1.0f - expf(-(float)f->fog_density * z);
    else if (f->fog_end > f->fog_start)
        fw = (z - (float)f->fog_start) / ((float)f->fog_end - (float)f->fog_start);
    else
        fw = z >= (float)f->fog_start ? 1.0f : 0.0f;
    fw = fw < 0 ? 0 : fw > 1 ? 1 : fw;
    return (int)(fw * 256.0f + 0.5f);
}

/* X, Y fixed point, q = 1/z, (sx, sy) the vertices' positions in square (I, J) (reduced mod S). */
static void fast_raster_nearest(retro_mesh_ctx *mc, const int32_t X3[3], const int32_t Y3[3], const float q3[3],
                                const float sx3[3], const float sy3[3], int I, int J)
{
    const mesh_frame *f = &mc->f;
    int64_t X[3], Y[3];
    float q[3], ax[3], ay[3];
    for (int k = 0; k < 3; k++) {
        X[k] = X3[k];
        Y[k] = Y3[k];
        q[k] = q3[k];
        ax[k] = sx3[k];
        ay[k] = sy3[k];
    }
    int64_t A = (X[1] - X[0]) * (Y[2] - Y[0]) - (Y[1] - Y[0]) * (X[2] - X[0]);
    if (A == 0)
        return;
    if (A < 0) { /* only with culling off: reversed to counter-clockwise, as scan conversion */
        if (!(f->mfx & RETRO_MESH_FX_NOCULL))
            return;
        int64_t t;
        float u;
        t = X[1], X[1] = X[2], X[2] = t;
        t = Y[1], Y[1] = Y[2], Y[2] = t;
        u = q[1], q[1] = q[2], q[2] = u;
        u = ax[1], ax[1] = ax[2], ax[2] = u;
        u = ay[1], ay[1] = ay[2], ay[2] = u;
        A = -A;
    }
    int64_t xmin = X[0], xmax = X[0], ymin = Y[0], ymax = Y[0];
    for (int k = 1; k < 3; k++) {
        xmin = X[k] < xmin ? X[k] : xmin;
        xmax = X[k] > xmax ? X[k] : xmax;
        ymin = Y[k] < ymin ? Y[k] : ymin;
        ymax = Y[k] > ymax ? Y[k] : ymax;
    }
    /* ceil and floor of a / 256 by arithmetic shifts (|a| < 2^31) */
    int64_t c0 = (xmin + 255) >> 8, c1 = xmax >> 8, r0 = (ymin + 255) >> 8, r1 = ymax >> 8;
    c0 = c0 < 0 ? 0 : c0;
    c1 = c1 > f->W - 1 ? f->W - 1 : c1;
    r0 = r0 < f->rlo ? f->rlo : r0; /* this frame's rows: 1..H, or mesh-omp's band */
    r1 = r1 > f->rhi ? f->rhi : r1;
    if (c0 > c1 || r0 > r1)
        return;
    const int W = f->W, H = f->H, S = f->S, fog = (f->fx & RETRO_FX_FOG) != 0;
    const int64_t wire_on = (f->mfx & RETRO_MESH_FX_WIREFRAME) != 0;
    int64_t thr[3], lim[3], stepx[3], stepy[3], er[3];
    for (int k = 0; k < 3; k++) {
        int n = k == 2 ? 0 : k + 1;
        int64_t dx = X[n] - X[k], dy = Y[n] - Y[k];
        er[k] = dx * (r0 * MESH_ONE - Y[k]) - dy * (c0 * MESH_ONE - X[k]);
        thr[k] = (dy < 0 || (dy == 0 && dx < 0)) ? 0 : 1; /* top-left rule */
        int64_t adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
        lim[k] = (adx > ady ? adx : ady) * MESH_ONE; /* every edge is an original one */
        stepx[k] = -dy * MESH_ONE;
        stepy[k] = dx * MESH_ONE;
    }
    const float area = (float)A;
    float *depth = (float *)mc->depth;
    uint32_t *out = mc->out;
    float psx[3], psy[3];
    int have_p = 0;
    uint64_t frags = 0, written = 0;
    for (int r = (int)r0; r <= (int)r1; r++) {
        int64_t e0 = er[0], e1 = er[1], e2 = er[2];
        size_t row = (size_t)(H - r) * (size_t)W;
        for (int c = (int)c0; c <= (int)c1; c++, e0 += stepx[0], e1 += stepx[1], e2 += stepx[2]) {
            if (e0 < thr[0] || e1 < thr[1] || e2 < thr[2])
                continue;
            if (wire_on && !(e0 < lim[0] || e1 < lim[1] || e2 < lim[2]))
                continue;
            frags++;
            const float w0 = (float)e1, w1 = (float)e2, w2 = (float)e0;
            const float Q = (w0 * q[0] + w1 * q[1]) + w2 * q[2];
            const float z = area / Q;
            size_t idx = row + (size_t)c;
            if (!(z < depth[idx]))
                continue; /* ties keep the fragment drawn first */
            written++;
            if (!have_p) { /* most triangles write no fragment: their attributes are never formed */
                for (int k = 0; k < 3; k++) {
                    psx[k] = ax[k] * q[k];
                    psy[k] = ay[k] * q[k];
                }
                have_p = 1;
            }
            float sx = ((w0 * psx[0] + w1 * psx[1]) + w2 * psx[2]) / Q;
            float sy = ((w0 * psy[0] + w1 * psy[1]) + w2 * psy[2]) / Q;
            int ci = I + (sx >= 1.0f), cj = J + (sy >= 1.0f);
            ci -= ci == S ? S : 0;
            cj -= cj == S ? S : 0;
            int ch[3];
            mesh_channels(f->color[(size_t)cj * (size_t)S + (size_t)ci], ch);
            if (fog)
                mesh_fog(ch, f->sky, fast_fog(f, z));
            depth[idx] = z;
            out[idx] = mesh_pack(ch);
        }
        for (int k = 0; k < 3; k++)
            er[k] += stepy[k];
    }
    mc->st.fragments += frags;
    mc->st.written += written;
}

#endif
