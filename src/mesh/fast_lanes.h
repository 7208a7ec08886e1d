/* The fast kernels' vertex stage in lanes and the per-triangle tests it feeds (included by
 * fast_tmpl.h after its vector header): every value is the reference's binary32 operation on
 * the same operands, rounded once, so it is the reference's bit for bit. */
#ifndef RETRO_MESH_FAST_LANES_H
#define RETRO_MESH_FAST_LANES_H

#include "fast_ref.h"
#include "mesh_internal.h"

#include "fast_raster.h"
#include "fast_ref.h"
#include "mesh_internal.h"

#define FR 32              /* lanes per vertex row: MESH_BLOCK + 1 rounded up, room to load at +1 */
#define FN (MESH_BLOCK + 1) /* vertex rows */

typedef struct {
    float z[FN][FR], l[FN][FR], e[FN][FR], q[FN][FR], h[FN][FR];
    int32_t X[FN][FR], Y[FN][FR], out[FN][FR];
} fast_soa;

/* Vertex stage of vertex row j (all lanes; lanes past ni repeat the last vertex). */
static void fast_vertex_row(const mesh_frame *f, fast_soa *b, const float *dxv, int Ja, int j, int ni, int ic0)
{
    const int S = f->S, J = Ja + j, jc = fast_wrap(J, S);
    const float cs = (float)f->cs, sn = (float)f->sn;
    const float dy = (float)(((double)J + 0.5) - f->y0);
    const float dysn = dy * sn, dycs = dy * cs;
    const uint8_t *h0 = f->h0 + (size_t)jc * (size_t)S, *h1 = f->h1 ? f->h1 + (size_t)jc * (size_t)S : NULL;
    const float mt = (float)f->morph_t;
    for (int i = 0, ic = ic0; i <= ni; i++) {
        float hv = (float)h0[ic];
        if (h1)
            hv = hv + (float)(h1[ic] - h0[ic]) * mt;
        b->h[j][i] = hv;
        b->e[j][i] = (float)((double)hv - (double)f->height);
        ic = ic + 1 == S ? 0 : ic + 1;
    }
    for (int i = ni + 1; i < FR; i++) {
        b->h[j][i] = b->h[j][ni];
        b->e[j][i] = b->e[j][ni];
    }
    const vf vcs = vf_set1(cs), vsn = vf_set1(sn), kx = vf_set1((float)f->kx), ky = vf_set1((float)f->ky);
    const vf cx = vf_set1((float)f->cx), cy = vf_set1((float)f->cy), cl = vf_set1((float)f->cl);
    const vf cr = vf_set1((float)f->cr), cb = vf_set1((float)f->cb), ct = vf_set1((float)f->ct);
    const vf one = vf_set1(1.0f), far = vf_set1((float)f->far), zero = vf_set1(0.0f);
    const vf k256 = vf_set1((float)MESH_ONE), half = vf_set1(0.5f);
    for (int i0 = 0; i0 <= ni; i0 += VN) {
        vf dx = vf_load(dxv + i0);
        vf z = vf_sub(vf_mul(dx, vcs), vf_set1(dysn));
        vf l = vf_add(vf_mul(dx, vsn), vf_set1(dycs));
        vf e = vf_load(&b->e[j][i0]);
        vf lx = vf_mul(kx, l), ey = vf_mul(ky, e);
        vi out = vi_set1(0);
        out = vi_bit_if_lt(out, vf_sub(z, one), zero, 1);
        out = vi_bit_if_lt(out, vf_sub(far, z), zero, 2);
        out = vi_bit_if_lt(out, vf_add(lx, vf_mul(cl, z)), zero, 4);
        out = vi_bit_if_lt(out, vf_sub(vf_mul(cr, z), lx), zero, 8);
        out = vi_bit_if_lt(out, vf_add(ey, vf_mul(cb, z)), zero, 16);
        out = vi_bit_if_lt(out, vf_sub(vf_mul(ct, z), ey), zero, 32);
        /* X = floor((kx l / z + cx) * 256 + 0.5): the product by 256 is exact */
        vf x = vf_add(vf_mul(vf_add(vf_div(lx, z), cx), k256), half);
        vf y = vf_add(vf_mul(vf_add(vf_div(ey, z), cy), k256), half);
        const float lim = 1073741824.0f;
        vf_store(&b->z[j][i0], z);
        vf_store(&b->l[j][i0], l);
        vf_store(&b->q[j][i0], vf_div(one, z));
        vi_store(&b->out[j][i0], out);
        vi_store(&b->X[j][i0], vf_to_vi(vf_clamp(vf_floor(x), -lim, lim)));
        vi_store(&b->Y[j][i0], vf_to_vi(vf_clamp(vf_floor(y), -lim, lim)));
    }
}

/* v0 . ((v1 - v0) x (v2 - v0)) on (l, e, z), primitive_assembly.c's orientation in lanes. */
static inline vf fast_orient(vf l0, vf e0, vf z0, vf l1, vf e1, vf z1, vf l2, vf e2, vf z2)
{
    vf al = vf_sub(l1, l0), ae = vf_sub(e1, e0), az = vf_sub(z1, z0);
    vf bl = vf_sub(l2, l0), be = vf_sub(e2, e0), bz = vf_sub(z2, z0);
    vf nl = vf_sub(vf_mul(ae, bz), vf_mul(az, be));
    vf ne = vf_sub(vf_mul(az, bl), vf_mul(al, bz));
    vf nz = vf_sub(vf_mul(al, be), vf_mul(ae, bl));
    return vf_add(vf_add(vf_mul(l0, nl), vf_mul(e0, ne)), vf_mul(z0, nz));
}

/* Lanes whose snapped bounding box holds a pixel centre of the screen in this frame's rows; the
 * clamped box's first column and row in *c0, *r0, and the lanes whose box holds at most 2 x 2
 * centres (*small), two columns (*two_c), two rows (*two_r). */
static inline unsigned fast_bbox(const mesh_frame *f, vi x0, vi y0, vi x1, vi y1, vi x2, vi y2, vi *c0o, vi *r0o,
                                 unsigned *small, unsigned *two_c, unsigned *two_r)
{
    vi xmin = vi_min(vi_min(x0, x1), x2), xmax = vi_max(vi_max(x0, x1), x2);
    vi ymin = vi_min(vi_min(y0, y1), y2), ymax = vi_max(vi_max(y0, y1), y2);
    vi k255 = vi_set1(255), one = vi_set1(1);
    vi c0 = vi_max(vi_sra8(vi_add(xmin, k255)), vi_set1(0)), c1 = vi_min(vi_sra8(xmax), vi_set1(f->W - 1));
    vi r0 = vi_max(vi_sra8(vi_add(ymin, k255)), vi_set1(f->rlo)), r1 = vi_min(vi_sra8(ymax), vi_set1(f->rhi));
    *c0o = c0;
    *r0o = r0;
    *two_c = vi_gt(c1, c0);
    *two_r = vi_gt(r1, r0);
    *small = ~(vi_gt(c1, vi_add(c0, one)) | vi_gt(r1, vi_add(r0, one)));
    return ~(vi_gt(c0, c1) | vi_gt(r0, r1));
}

#endif
