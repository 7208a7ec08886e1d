/* The fast kernels' block stage, included by fast_avx2.c / fast_avx512.c after their vector
 * header (vec_*.h: VN lanes, vf/vi types and ops) with FAST_BLOCK set to the function name.
 *
 * A block's vertices go through the vertex stage in lanes (eye space, plane outcodes, 1/z,
 * projection and snapping: the reference's binary32 operations, each rounded once, so every
 * value is the reference's bit for bit). Then each row of squares is classified in lanes: back
 * faces, the exact sign of the snapped area, and whether the snapped bounding box holds a pixel
 * centre. At 640x480 most triangles are smaller than a pixel and hold none: they end here,
 * counted, without a copy, a clip test or a raster setup. The survivors are drawn in the
 * reference's order (docs/MESH_FAST.md): squares that need clipping or carry water go through
 * the reference stages unchanged. */
#include <string.h>

#include "fast_raster.h"
#include "mesh_internal.h"

#define FR 32              /* lanes per vertex row: MESH_BLOCK + 1 rounded up, room to load at +1 */
#define FN (MESH_BLOCK + 1) /* vertex rows */

typedef struct {
    float z[FN][FR], l[FN][FR], e[FN][FR], q[FN][FR], h[FN][FR];
    int32_t X[FN][FR], Y[FN][FR], out[FN][FR];
} fast_soa;

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
    const mesh_frame *f = &mc->f;
    int at = j * stride + i;
    mesh_vert *v = &mc->grid[at];
    mesh_vertex_stage(f, Ia + i, Ja + j, v);
    double d[6];
    mesh_plane_distances(f, v, d);
    mesh_snap *s = &mc->snap[at];
    s->out = 0;
    for (int p = 0; p < 6; p++)
        s->out |= d[p] < 0 ? 1u << p : 0u;
    s->ok = s->out == 0;
    if (s->ok)
        mesh_project(f, v, &s->X, &s->Y);
}

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

/* Lanes whose snapped bounding box holds a pixel centre of the screen in this frame's rows. */
static inline unsigned fast_bbox(const mesh_frame *f, vi x0, vi y0, vi x1, vi y1, vi x2, vi y2)
{
    vi xmin = vi_min(vi_min(x0, x1), x2), xmax = vi_max(vi_max(x0, x1), x2);
    vi ymin = vi_min(vi_min(y0, y1), y2), ymax = vi_max(vi_max(y0, y1), y2);
    vi k255 = vi_set1(255);
    vi c0 = vi_max(vi_sra8(vi_add(xmin, k255)), vi_set1(0)), c1 = vi_min(vi_sra8(xmax), vi_set1(f->W - 1));
    vi r0 = vi_max(vi_sra8(vi_add(ymin, k255)), vi_set1(f->rlo)), r1 = vi_min(vi_sra8(ymax), vi_set1(f->rhi));
    return ~(vi_gt(c0, c1) | vi_gt(r0, r1));
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

typedef struct {
    unsigned slow, cand[2], back[2];
} fast_row;

void FAST_BLOCK(retro_mesh_ctx *mc, int Ia, int Ib, int Ja, int Jb, int sx, int sy)
{
    const mesh_frame *f = &mc->f;
    const int ni = Ib - Ia + 1, nj = Jb - Ja + 1, stride = ni + 1;
    const int nocull = (f->mfx & RETRO_MESH_FX_NOCULL) != 0, water = (f->fx & RETRO_FX_WATER) != 0;
    const int generic = (f->fx & RETRO_FX_SHADE) || (f->mfx & (RETRO_MESH_FX_TEXTURE | RETRO_MESH_FX_GOURAUD));
    fast_soa b;
    float dxv[FR];
    for (int i = 0; i < FR; i++)
        dxv[i] = (float)(((double)(Ia + (i <= ni ? i : ni)) + 0.5) - f->x0);
    const int ic0 = fast_wrap(Ia, f->S);
    for (int j = 0; j <= nj; j++)
        fast_vertex_row(f, &b, dxv, Ja, j, ni, ic0);

    fast_row rows[MESH_BLOCK];
    uint64_t culled = 0, rast = 0, fastsq_n = 0;
    const vi zi = vi_set1(0);
    const vf zf = vf_set1(0.0f);
    for (int j = 0; j < nj; j++) {
        fast_row *R = &rows[j];
        memset(R, 0, sizeof *R);
        unsigned wet = 0;
        if (water) {
            const float lv = (float)f->level;
            for (int i = 0; i < ni; i++)
                if (b.h[j][i] < lv || b.h[j][i + 1] < lv || b.h[j + 1][i] < lv || b.h[j + 1][i + 1] < lv)
                    wet |= 1u << i;
        }
        for (int i0 = 0; i0 < ni; i0 += VN) {
            unsigned valid = ni - i0 >= VN ? (unsigned)((1ull << VN) - 1) : (1u << (ni - i0)) - 1;
            /* corners a = (i, j), b = (i+1, j), c = (i+1, j+1), d = (i, j+1) */
            const int a = i0, bb = i0 + 1;
            vi oa = vi_load(&b.out[j][a]), ob = vi_load(&b.out[j][bb]);
            vi oc = vi_load(&b.out[j + 1][bb]), od = vi_load(&b.out[j + 1][a]);
            unsigned fastsq = vi_eq(vi_or(vi_or(oa, ob), vi_or(oc, od)), zi) & valid & ~(wet >> i0);
            R->slow |= (valid & ~fastsq) << i0;
            fastsq_n += (uint64_t)__builtin_popcount(fastsq);
            if (!fastsq)
                continue;
            vf la = vf_load(&b.l[j][a]), ea = vf_load(&b.e[j][a]), za = vf_load(&b.z[j][a]);
            vf lb = vf_load(&b.l[j][bb]), eb = vf_load(&b.e[j][bb]), zb = vf_load(&b.z[j][bb]);
            vf lc = vf_load(&b.l[j + 1][bb]), ec = vf_load(&b.e[j + 1][bb]), zc = vf_load(&b.z[j + 1][bb]);
            vf ld = vf_load(&b.l[j + 1][a]), ed = vf_load(&b.e[j + 1][a]), zd = vf_load(&b.z[j + 1][a]);
            vi xa = vi_load(&b.X[j][a]), ya = vi_load(&b.Y[j][a]), xb = vi_load(&b.X[j][bb]), yb = vi_load(&b.Y[j][bb]);
            vi xc = vi_load(&b.X[j + 1][bb]), yc = vi_load(&b.Y[j + 1][bb]);
            vi xd = vi_load(&b.X[j + 1][a]), yd = vi_load(&b.Y[j + 1][a]);
            /* triangle 0 = ACB, triangle 1 = ADC */
            vf det0 = fast_orient(la, ea, za, lc, ec, zc, lb, eb, zb);
            vf det1 = fast_orient(la, ea, za, ld, ed, zd, lc, ec, zc);
            unsigned drawn0 = nocull ? fastsq : vf_gt(det0, zf) & fastsq;
            unsigned drawn1 = nocull ? fastsq : vf_gt(det1, zf) & fastsq;
            culled += (uint64_t)(__builtin_popcount(fastsq & ~drawn0) + __builtin_popcount(fastsq & ~drawn1));
            unsigned z0, z1;
            unsigned pos0 = vi_cross(vi_sub(xc, xa), vi_sub(yb, ya), vi_sub(yc, ya), vi_sub(xb, xa), &z0);
            unsigned pos1 = vi_cross(vi_sub(xd, xa), vi_sub(yc, ya), vi_sub(yd, ya), vi_sub(xc, xa), &z1);
            unsigned ok0 = drawn0 & (nocull ? ~z0 : pos0), ok1 = drawn1 & (nocull ? ~z1 : pos1);
            unsigned in0 = ok0 & fast_bbox(f, xa, ya, xc, yc, xb, yb);
            unsigned in1 = ok1 & fast_bbox(f, xa, ya, xd, yd, xc, yc);
            /* the survivors count themselves when scan conversion takes them */
            rast += (uint64_t)(__builtin_popcount(ok0 & ~in0) + __builtin_popcount(ok1 & ~in1));
            R->cand[0] |= in0 << i0;
            R->cand[1] |= in1 << i0;
            R->back[0] |= (vf_lt(det0, zf) & valid) << i0;
            R->back[1] |= (vf_lt(det1, zf) & valid) << i0;
        }
    }
    mc->st.submitted += 2 * fastsq_n;
    mc->st.culled += culled;
    mc->st.rasterized += rast;

    /* The z-buffer's order (traversal.c's block(), drawing front to back). */
    static const double tsx[2][3] = {{0.5, 1.5, 1.5}, {0.5, 0.5, 1.5}}, tsy[2][3] = {{0.5, 1.5, 0.5}, {0.5, 1.5, 1.5}};
    static const float fsx[2][3] = {{0.5f, 1.5f, 1.5f}, {0.5f, 0.5f, 1.5f}}, fsy[2][3] = {{0.5f, 1.5f, 0.5f}, {0.5f, 1.5f, 1.5f}};
    uint32_t done[FN];
    memset(done, 0, sizeof done);
    const int fy = sy >= 0, fx = sx >= 0;
    for (int jj = 0; jj < nj; jj++) {
        const int j = fy ? jj : nj - 1 - jj;
        const fast_row *R = &rows[j];
        unsigned m = R->slow | R->cand[0] | R->cand[1];
        while (m) {
            const int i = fx ? __builtin_ctz(m) : 31 - __builtin_clz(m);
            m &= ~(1u << i);
            const int I = Ia + i, J = Ja + j;
            if (R->slow >> i & 1u) {
                fast_full_vertex(mc, done, stride, Ia, Ja, i, j);
                fast_full_vertex(mc, done, stride, Ia, Ja, i + 1, j);
                fast_full_vertex(mc, done, stride, Ia, Ja, i + 1, j + 1);
                fast_full_vertex(mc, done, stride, Ia, Ja, i, j + 1);
                mesh_primitive_assembly(mc, mc->grid, mc->snap, stride, j * stride + i, I, J);
                continue;
            }
            /* the triangle on the eye's side of the diagonal first (primitive_assembly.c) */
            const int first = f->x0 - f->y0 > (double)(I - J) ? 0 : 1;
            for (int n = 0; n < 2; n++) {
                const int t = n ? 1 - first : first;
                if (!(R->cand[t] >> i & 1u))
                    continue;
                /* ACB = (i,j), (i+1,j+1), (i+1,j); ADC = (i,j), (i,j+1), (i+1,j+1) */
                const int vi_[3] = {i, t ? i : i + 1, i + 1}, vj[3] = {j, j + 1, t ? j + 1 : j};
                int32_t X[3], Y[3];
                for (int k = 0; k < 3; k++) {
                    X[k] = b.X[vj[k]][vi_[k]];
                    Y[k] = b.Y[vj[k]][vi_[k]];
                }
                if (generic) {
                    int idx[3];
                    for (int k = 0; k < 3; k++) {
                        fast_full_vertex(mc, done, stride, Ia, Ja, vi_[k], vj[k]);
                        idx[k] = vj[k] * stride + vi_[k];
                    }
                    fast_generic(mc, idx, tsx[t], tsy[t], I, J, (int)(R->back[t] >> i & 1u), X, Y);
                } else {
                    float q[3];
                    for (int k = 0; k < 3; k++)
                        q[k] = b.q[vj[k]][vi_[k]];
                    fast_raster_nearest(mc, X, Y, q, fsx[t], fsy[t], fast_wrap(I, f->S), fast_wrap(J, f->S));
                }
            }
        }
    }
}
