/* The raster loop of the binary32 and binary64 modes, included with REAL and RASTER_NAME set:
 * edge stepping (scan conversion), perspective-correct interpolation, the fragment stage and
 * the output stage, inlined into one loop so that a fragment costs no call. */
#include <math.h>

#include "mesh_fragment.h"
#include "mesh_internal.h"

#define RSQRT(x) (sizeof(REAL) == sizeof(float) ? (REAL)sqrtf((float)(x)) : (REAL)sqrt((double)(x)))
#define REXP(x) (sizeof(REAL) == sizeof(float) ? (REAL)expf((float)(x)) : (REAL)exp((double)(x)))

/* Interpolation stage: sum w_i a_i / z_i over sum w_i / z_i, the w_i the edge functions. */
#define INTERP(k) (((w0 * p[0][k] + w1 * p[1][k]) + w2 * p[2][k]) / Q)

static inline int RASTER_CH(REAL v)
{
    int i = (int)(v + (REAL)0.5);
    return i < 0 ? 0 : i > 255 ? 255 : i;
}

/* Fog weight F (0..256) at eye depth z, docs/EFFECTS.md's formulas at d = z. */
static inline int RASTER_FOG(const mesh_frame *f, REAL z)
{
    REAL fw;
    if (f->fog_exp)
        fw = (REAL)1 - REXP(-(REAL)f->fog_density * z);
    else if (f->fog_end > f->fog_start)
        fw = (z - (REAL)f->fog_start) / ((REAL)f->fog_end - (REAL)f->fog_start);
    else
        fw = z >= (REAL)f->fog_start ? (REAL)1 : (REAL)0;
    fw = fw < 0 ? 0 : fw > 1 ? 1 : fw;
    return (int)(fw * (REAL)256 + (REAL)0.5);
}

void RASTER_NAME(retro_mesh_ctx *mc, const mesh_sub *s, int64_t A, const int64_t E0[3],
                 const int64_t dx[3], const int64_t dy[3], int c0, int c1, int r0, int r1)
{
    const mesh_frame *f = &mc->f;
    const mesh_tri *t = s->t;
    const int W = f->W, H = f->H, S = f->S;
    const int water = t->water, zb = f->kernel == RETRO_MESH_ZBUFFER;
    const int gouraud = !water && (f->mfx & RETRO_MESH_FX_GOURAUD);
    const int texture = !water && (f->mfx & RETRO_MESH_FX_TEXTURE);
    const int shade = !water && (f->fx & RETRO_FX_SHADE), fog = (f->fx & RETRO_FX_FOG) != 0;
    REAL *depth = (REAL *)mc->depth;
    uint32_t *out = mc->out;
    REAL q[3], p[3][MESH_NA];
    for (int i = 0; i < 3; i++) {
        q[i] = (REAL)1 / (REAL)s->v[i]->z;
        for (int k = 0; k < MESH_NA; k++)
            p[i][k] = (REAL)s->v[i]->a[k] * q[i];
    }
    const REAL area = (REAL)A, sgn = t->back ? (REAL)-1 : (REAL)1;
    const REAL sun0 = (REAL)f->sun[0], sun1 = (REAL)f->sun[1], sun2 = (REAL)f->sun[2];
    const REAL amb = (REAL)f->ambient, dif = (REAL)f->diffuse;
    int64_t thr[3], lim[3], stepx[3], stepy[3], er[3];
    const int64_t wire_on = (f->mfx & RETRO_MESH_FX_WIREFRAME) != 0;
    for (int k = 0; k < 3; k++) {
        thr[k] = (dy[k] < 0 || (dy[k] == 0 && dx[k] < 0)) ? 0 : 1; /* top-left rule */
        int64_t ax = dx[k] < 0 ? -dx[k] : dx[k], ay = dy[k] < 0 ? -dy[k] : dy[k];
        lim[k] = (s->edges >> k & 1u) ? (ax > ay ? ax : ay) * MESH_ONE : 0;
        stepx[k] = -dy[k] * MESH_ONE;
        stepy[k] = dx[k] * MESH_ONE;
        er[k] = E0[k];
    }
    uint64_t frags = 0, written = 0;
    for (int r = r0; r <= r1; r++) {
        int64_t e0 = er[0], e1 = er[1], e2 = er[2];
        size_t row = (size_t)(H - r) * (size_t)W;
        const int c_end = mesh_row_mine(f, r) ? c1 : c0 - 1; /* another band's row: skipped */
        for (int c = c0; c <= c_end; c++, e0 += stepx[0], e1 += stepx[1], e2 += stepx[2]) {
            if (e0 < thr[0] || e1 < thr[1] || e2 < thr[2])
                continue;
            if (wire_on && !(e0 < lim[0] || e1 < lim[1] || e2 < lim[2]))
                continue;
            frags++;
            /* vertex i's weight is the edge function of the edge opposite it */
            const REAL w0 = (REAL)e1, w1 = (REAL)e2, w2 = (REAL)e0;
            const REAL Q = (w0 * q[0] + w1 * q[1]) + w2 * q[2];
            const REAL z = area / Q;
            size_t idx = row + (size_t)c;
            if (zb && !(z < depth[idx]))
                continue; /* ties keep the fragment drawn first */
            written++;
            int ch[3];
            if (water) {
                mesh_channels(f->water_color, ch);
            } else if (gouraud) {
                ch[0] = RASTER_CH(INTERP(A_R));
                ch[1] = RASTER_CH(INTERP(A_G));
                ch[2] = RASTER_CH(INTERP(A_B));
            } else {
                REAL sx = INTERP(A_SX), sy = INTERP(A_SY);
                if (texture) {
                    REAL tx = sx - (REAL)0.5, ty = sy - (REAL)0.5;
                    tx = tx < 0 ? 0 : tx > 1 ? 1 : tx;
                    ty = ty < 0 ? 0 : ty > 1 ? 1 : ty;
                    int c4[4][3];
                    mesh_square_colors(f, t->I, t->J, S, c4);
                    for (int k = 0; k < 3; k++)
                        ch[k] = RASTER_CH(((REAL)c4[0][k] * ((REAL)1 - tx) + (REAL)c4[1][k] * tx) * ((REAL)1 - ty) +
                                          ((REAL)c4[2][k] * ((REAL)1 - tx) + (REAL)c4[3][k] * tx) * ty);
                } else {
                    int ci = t->I + (sx >= (REAL)1), cj = t->J + (sy >= (REAL)1);
                    ci -= ci == S ? S : 0;
                    cj -= cj == S ? S : 0;
                    mesh_channels(f->color[(size_t)cj * (size_t)S + (size_t)ci], ch);
                }
            }
            if (shade) { /* two-sided Lambert from the interpolated normal */
                REAL nx = sgn * INTERP(A_NX), ny = sgn * INTERP(A_NY), nz = sgn * INTERP(A_NZ);
                REAL len = RSQRT((nx * nx + ny * ny) + nz * nz);
                REAL dot = len > 0 ? ((nx * sun0 + ny * sun1) + nz * sun2) / len : (REAL)0;
                REAL light = amb + dif * (dot > 0 ? dot : (REAL)0);
                for (int k = 0; k < 3; k++) {
                    int v = (int)((REAL)ch[k] * light + (REAL)0.5);
                    ch[k] = v > 255 ? 255 : v;
                }
            }
            if (fog)
                mesh_fog(ch, f->sky, RASTER_FOG(f, z));
            if (water) { /* premultiplied over: a*W + (1 - a)*dst */
                REAL a = INTERP(A_ALPHA);
                a = a < 0 ? 0 : a > 1 ? 1 : a;
                int dst[3];
                mesh_channels(out[idx], dst);
                for (int k = 0; k < 3; k++)
                    ch[k] = RASTER_CH((REAL)ch[k] * a + (REAL)dst[k] * ((REAL)1 - a));
            } else if (zb) {
                depth[idx] = z;
            }
            out[idx] = mesh_pack(ch);
        }
        for (int k = 0; k < 3; k++)
            er[k] += stepy[k];
    }
    mc->st.fragments += frags;
    mc->st.written += written;
}

#undef RSQRT
#undef REXP
#undef INTERP
