/* The raster loop of mode int: no floating point per fragment. Per sub-triangle the vertex
 * values become fixed point: Q_i = round(2^28 / z_i), attributes with 16 (plan position) or
 * 8 (colour, light, opacity) fractional bits. Per fragment: barycentrics with 16 bits from
 * the edge functions, perspective-correct weights W_i = L_i * Q_i, depth Q = sum W_i >> 16
 * (1/z with 28 fractional bits: larger is nearer), attributes sum W_i P_i / sum W_i rounded. */
#include <math.h>

#include "mesh_fragment.h"
#include "mesh_internal.h"

#define QBITS 28
#define LBITS 16

static int64_t fixp(double v, int bits)
{
    return llround(v * (double)((int64_t)1 << bits));
}

static inline int clamp255(int64_t v)
{
    return v < 0 ? 0 : v > 255 ? 255 : (int)v;
}

void mesh_raster_int(retro_mesh_ctx *mc, const mesh_sub *s, int64_t A, const int64_t E0[3],
                     const int64_t dx[3], const int64_t dy[3], int c0, int c1, int r0, int r1)
{
    const mesh_frame *f = &mc->f;
    const mesh_tri *t = s->t;
    const int W = f->W, H = f->H, S = f->S;
    const int water = t->water, zb = f->kernel == RETRO_MESH_ZBUFFER;
    const int gouraud = !water && (f->mfx & RETRO_MESH_FX_GOURAUD);
    const int texture = !water && (f->mfx & RETRO_MESH_FX_TEXTURE);
    const int shade = !water && (f->fx & RETRO_FX_SHADE), fog = (f->fx & RETRO_FX_FOG) != 0;
    uint32_t *depth = (uint32_t *)mc->depth;
    uint32_t *out = mc->out;
    int64_t Qv[3], P[3][MESH_NA];
    for (int i = 0; i < 3; i++) {
        const mesh_vert *v = s->v[i];
        int64_t qv = fixp(1.0 / v->z, QBITS);
        Qv[i] = qv < 1 ? 1 : qv > ((int64_t)1 << QBITS) + ((int64_t)1 << 20) ? ((int64_t)1 << QBITS) + ((int64_t)1 << 20) : qv;
        P[i][A_SX] = fixp(v->a[A_SX], 16);
        P[i][A_SY] = fixp(v->a[A_SY], 16);
        for (int k = A_R; k <= A_B; k++)
            P[i][k] = fixp(v->a[k], 8);
        P[i][A_NX] = fixp(v->a[t->back ? A_NY : A_NX], 8); /* light of the side seen */
        P[i][A_ALPHA] = fixp(v->a[A_ALPHA], 8);
        for (int k = 0; k < MESH_NA; k++)
            P[i][k] = P[i][k] < 0 ? 0 : P[i][k] > ((int64_t)1 << 17) ? (int64_t)1 << 17 : P[i][k];
    }
    int64_t thr[3], lim[3], stepx[3], stepy[3], er[3];
    const int wire_on = (f->mfx & RETRO_MESH_FX_WIREFRAME) != 0;
    for (int k = 0; k < 3; k++) {
        thr[k] = (dy[k] < 0 || (dy[k] == 0 && dx[k] < 0)) ? 0 : 1;
        int64_t ax = dx[k] < 0 ? -dx[k] : dx[k], ay = dy[k] < 0 ? -dy[k] : dy[k];
        lim[k] = (s->edges >> k & 1u) ? (ax > ay ? ax : ay) * MESH_ONE : 0;
        stepx[k] = -dy[k] * MESH_ONE;
        stepy[k] = dx[k] * MESH_ONE;
        er[k] = E0[k];
    }
    const int farz = (int)f->far;
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
            /* 0 <= e_k <= A inside, so L_i is in [0, 2^16] and the products fit (MESH.md) */
            int64_t L0 = (e1 << LBITS) / A, L1 = (e2 << LBITS) / A, L2 = ((int64_t)1 << LBITS) - L0 - L1;
            int64_t W0 = L0 * Qv[0], W1 = L1 * Qv[1], W2 = L2 * Qv[2], den = W0 + W1 + W2;
            uint32_t qd = (uint32_t)(den >> LBITS);
            size_t idx = row + (size_t)c;
            if (zb && !(qd > depth[idx]))
                continue; /* ties keep the fragment drawn first */
            if (den <= 0)
                continue; /* unreachable: every Q_i >= 1 and the L_i sum to 2^16 */
            written++;
#define IINTERP(k) ((W0 * P[0][k] + W1 * P[1][k] + W2 * P[2][k] + den / 2) / den)
            int ch[3];
            if (water) {
                mesh_channels(f->water_color, ch);
            } else if (gouraud) {
                ch[0] = clamp255((IINTERP(A_R) + 128) >> 8);
                ch[1] = clamp255((IINTERP(A_G) + 128) >> 8);
                ch[2] = clamp255((IINTERP(A_B) + 128) >> 8);
            } else {
                int64_t sx = IINTERP(A_SX), sy = IINTERP(A_SY);
                if (texture) {
                    int64_t tx = sx - 32768, ty = sy - 32768;
                    tx = tx < 0 ? 0 : tx > 65536 ? 65536 : tx;
                    ty = ty < 0 ? 0 : ty > 65536 ? 65536 : ty;
                    int c4[4][3];
                    mesh_square_colors(f, t->I, t->J, S, c4);
                    for (int k = 0; k < 3; k++) {
                        int64_t top = c4[0][k] * (65536 - tx) + c4[1][k] * tx;
                        int64_t bot = c4[2][k] * (65536 - tx) + c4[3][k] * tx;
                        ch[k] = clamp255((top * (65536 - ty) + bot * ty + ((int64_t)1 << 31)) >> 32);
                    }
                } else {
                    int ci = t->I + (sx >= 65536), cj = t->J + (sy >= 65536);
                    ci -= ci == S ? S : 0;
                    cj -= cj == S ? S : 0;
                    mesh_channels(f->color[(size_t)cj * (size_t)S + (size_t)ci], ch);
                }
            }
            if (shade) { /* the light of each vertex interpolated (Gouraud shading) */
                int64_t light = IINTERP(A_NX);
                for (int k = 0; k < 3; k++)
                    ch[k] = clamp255((ch[k] * light + 128) >> 8);
            }
            if (fog) {
                int64_t zi = ((int64_t)1 << QBITS) / (qd ? qd : 1);
                mesh_fog(ch, f->sky, f->fogtab[zi > farz ? farz : zi]);
            }
            if (water) {
                int64_t a = IINTERP(A_ALPHA);
                a = a > 256 ? 256 : a;
                int dst[3];
                mesh_channels(out[idx], dst);
                for (int k = 0; k < 3; k++)
                    ch[k] = clamp255((ch[k] * a + dst[k] * (256 - a) + 128) >> 8);
            } else if (zb) {
                depth[idx] = qd;
            }
#undef IINTERP
            out[idx] = mesh_pack(ch);
        }
        for (int k = 0; k < 3; k++)
            er[k] += stepy[k];
    }
    mc->st.fragments += frags;
    mc->st.written += written;
}
