/* The fast kernels' block stage, included by fast_avx2.c / fast_avx512.c after their vector
 * header (vec_*.h: VN lanes, vf/vi/vd types and ops) with FAST_BLOCK set to the function name.
 *
 * A block's vertices go through the vertex stage in lanes (fast_lanes.h). Then each row of
 * squares is classified in lanes: back faces, triangles entirely outside one frustum plane, the
 * exact sign of the snapped area, whether the snapped bounding box holds a pixel centre, and for
 * the tiny ones (at most 2 x 2 centres) coverage, depth and colour cell (fast_tiny.h). At
 * 640x480 most triangles hold no centre: they end here, counted, without a copy, a clip test
 * or a raster setup. The survivors are drawn in the reference's order (docs/MESH_FAST.md):
 * tiny ones by their depth tests only, larger ones by fast_raster.h, squares that need clipping
 * or carry water by the reference stages unchanged. */
#include <string.h>

#include "fast_lanes.h"
#include "fast_raster.h"
#include "fast_ref.h"
#include "fast_tiny.h"
#include "mesh_fragment.h"
#include "mesh_internal.h"

typedef struct {
    unsigned slow, cand[2], tiny[2], back[2];
    fast_tiny tt[2];
    int32_t c0[2][MESH_BLOCK], r0[2][MESH_BLOCK];
} fast_row;

typedef struct {
    uint64_t submitted, culled, clipped_out, rast, frags;
} fast_counts;

/* Row j of squares, in lanes: which squares go to the reference path (slow), which triangles
 * of each kind survive to a raster (cand) or are tiny and cover a centre (tiny). */
static void fast_classify_row(const mesh_frame *f, const fast_soa *b, int j, int ni, fast_row *R, fast_counts *n)
{
    const int nocull = (f->mfx & RETRO_MESH_FX_NOCULL) != 0, water = (f->fx & RETRO_FX_WATER) != 0;
    const int generic = (f->fx & RETRO_FX_SHADE) || (f->mfx & (RETRO_MESH_FX_TEXTURE | RETRO_MESH_FX_GOURAUD));
    const int lanes_ok = !generic && !(f->mfx & RETRO_MESH_FX_WIREFRAME);
    static const float fsx[2][3] = {{0.5f, 1.5f, 1.5f}, {0.5f, 0.5f, 1.5f}}, fsy[2][3] = {{0.5f, 1.5f, 0.5f}, {0.5f, 1.5f, 1.5f}};
    const vi zi = vi_set1(0);
    const vf zf = vf_set1(0.0f);
    R->slow = R->cand[0] = R->cand[1] = R->tiny[0] = R->tiny[1] = R->back[0] = R->back[1] = 0;
    for (int t = 0; t < 2; t++)
        for (int c = 0; c < 4; c++)
            R->tt[t].cov[c] = R->tt[t].sxb[c] = R->tt[t].syb[c] = 0;
    unsigned wet = 0;
    if (water) {
        const float lv = (float)f->level;
        for (int i = 0; i < ni; i++)
            if (b->h[j][i] < lv || b->h[j][i + 1] < lv || b->h[j + 1][i] < lv || b->h[j + 1][i + 1] < lv)
                wet |= 1u << i;
    }
    for (int i0 = 0; i0 < ni; i0 += VN) {
        const unsigned valid = ni - i0 >= VN ? (unsigned)((1ull << VN) - 1) : (1u << (ni - i0)) - 1;
        const unsigned dry = valid & ~(wet >> i0);
        /* corners a = (i, j), b = (i+1, j), c = (i+1, j+1), d = (i, j+1) */
        const int a = i0, bb = i0 + 1;
        vi oa = vi_load(&b->out[j][a]), ob = vi_load(&b->out[j][bb]);
        vi oc = vi_load(&b->out[j + 1][bb]), od = vi_load(&b->out[j + 1][a]);
        const unsigned fastsq = vi_eq(vi_or(vi_or(oa, ob), vi_or(oc, od)), zi) & dry;
        vf la = vf_load(&b->l[j][a]), ea = vf_load(&b->e[j][a]), za = vf_load(&b->z[j][a]);
        vf lb = vf_load(&b->l[j][bb]), eb = vf_load(&b->e[j][bb]), zb = vf_load(&b->z[j][bb]);
        vf lc = vf_load(&b->l[j + 1][bb]), ec = vf_load(&b->e[j + 1][bb]), zc = vf_load(&b->z[j + 1][bb]);
        vf ld = vf_load(&b->l[j + 1][a]), ed = vf_load(&b->e[j + 1][a]), zd = vf_load(&b->z[j + 1][a]);
        /* triangle 0 = ACB, triangle 1 = ADC */
        vf det0 = fast_orient(la, ea, za, lc, ec, zc, lb, eb, zb);
        vf det1 = fast_orient(la, ea, za, ld, ed, zd, lc, ec, zc);
        const unsigned drawn0 = nocull ? valid : vf_gt(det0, zf) & valid;
        const unsigned drawn1 = nocull ? valid : vf_gt(det1, zf) & valid;
        /* dry squares whose drawn triangles all lie outside one plane: clipping drops them */
        const unsigned out0 = ~vi_eq(vi_and(vi_and(oa, oc), ob), zi), out1 = ~vi_eq(vi_and(vi_and(oa, od), oc), zi);
        const unsigned gone = dry & ~fastsq & (~drawn0 | out0) & (~drawn1 | out1);
        const unsigned here = fastsq | gone;
        R->slow |= (valid & ~here) << i0;
        n->submitted += 2 * (uint64_t)__builtin_popcount(here);
        n->culled += (uint64_t)(__builtin_popcount(here & ~drawn0) + __builtin_popcount(here & ~drawn1));
        n->clipped_out += (uint64_t)(__builtin_popcount(gone & drawn0) + __builtin_popcount(gone & drawn1));
        R->back[0] |= (vf_lt(det0, zf) & valid) << i0;
        R->back[1] |= (vf_lt(det1, zf) & valid) << i0;
        if (!fastsq)
            continue;
        vi x[4] = {vi_load(&b->X[j][a]), vi_load(&b->X[j][bb]), vi_load(&b->X[j + 1][bb]), vi_load(&b->X[j + 1][a])};
        vi y[4] = {vi_load(&b->Y[j][a]), vi_load(&b->Y[j][bb]), vi_load(&b->Y[j + 1][bb]), vi_load(&b->Y[j + 1][a])};
        vf q[4] = {vf_load(&b->q[j][a]), vf_load(&b->q[j][bb]), vf_load(&b->q[j + 1][bb]), vf_load(&b->q[j + 1][a])};
        static const int corner[2][3] = {{0, 2, 1}, {0, 3, 2}}; /* ACB, ADC */
        for (int t = 0; t < 2; t++) {
            const int *cn = corner[t];
            const vi x3[3] = {x[cn[0]], x[cn[1]], x[cn[2]]}, y3[3] = {y[cn[0]], y[cn[1]], y[cn[2]]};
            const vf q3[3] = {q[cn[0]], q[cn[1]], q[cn[2]]};
            unsigned zero;
            const unsigned pos = vi_cross(vi_sub(x3[1], x3[0]), vi_sub(y3[2], y3[0]), vi_sub(y3[1], y3[0]),
                                          vi_sub(x3[2], x3[0]), &zero);
            const unsigned ok = (t ? drawn1 : drawn0) & fastsq & (nocull ? ~zero : pos);
            vi c0, r0;
            unsigned small, two_c, two_r;
            const unsigned in = ok & fast_bbox(f, x3[0], y3[0], x3[1], y3[1], x3[2], y3[2], &c0, &r0, &small, &two_c, &two_r);
            const unsigned tiny = lanes_ok ? in & small & pos : 0;
            /* A != 0 with the orientation drawn: rasterized (scan conversion counts the generic ones
             * it draws) */
            n->rast += (uint64_t)__builtin_popcount(generic ? ok & ~in : ok);
            R->cand[t] |= (in & ~tiny) << i0;
            if (!tiny)
                continue;
            vi_store(&R->c0[t][i0], c0);
            vi_store(&R->r0[t][i0], r0);
            R->tiny[t] |= fast_tiny_lanes(x3, y3, q3, fsx[t], fsy[t], c0, r0, tiny, two_c, two_r, i0, &R->tt[t]) << i0;
        }
    }
    for (int t = 0; t < 2; t++)
        for (int c = 0; c < 4; c++)
            n->frags += (uint64_t)__builtin_popcount(R->tt[t].cov[c]);
}

/* The depth tests of a tiny triangle's covered centres (fast_tiny.h), colour cell (I, J). */
static inline void fast_tiny_draw(retro_mesh_ctx *mc, const fast_row *R, int t, int i, int I, int J, uint64_t *written)
{
    const mesh_frame *f = &mc->f;
    const fast_tiny *T = &R->tt[t];
    float *depth = (float *)mc->depth;
    const int S = f->S;
    for (int n = 0; n < 4; n++) {
        if (!(T->cov[n] >> i & 1u))
            continue;
        const int r = R->r0[t][i] + (n >> 1), c = R->c0[t][i] + (n & 1);
        const size_t idx = (size_t)(f->H - r) * (size_t)f->W + (size_t)c;
        const float z = T->z[n][i];
        if (!(z < depth[idx]))
            continue; /* ties keep the fragment drawn first */
        ++*written;
        int ci = I + (int)(T->sxb[n] >> i & 1u), cj = J + (int)(T->syb[n] >> i & 1u);
        ci -= ci == S ? S : 0;
        cj -= cj == S ? S : 0;
        int ch[3];
        mesh_channels(f->color[(size_t)cj * (size_t)S + (size_t)ci], ch);
        if (f->fx & RETRO_FX_FOG)
            mesh_fog(ch, f->sky, fast_fog(f, z));
        depth[idx] = z;
        mc->out[idx] = mesh_pack(ch);
    }
}

void FAST_BLOCK(retro_mesh_ctx *mc, int Ia, int Ib, int Ja, int Jb, int sx, int sy)
{
    const mesh_frame *f = &mc->f;
    const int ni = Ib - Ia + 1, nj = Jb - Ja + 1, stride = ni + 1;
    const int generic = (f->fx & RETRO_FX_SHADE) || (f->mfx & (RETRO_MESH_FX_TEXTURE | RETRO_MESH_FX_GOURAUD));
    fast_soa b;
    float dxv[FR];
    for (int i = 0; i < FR; i++)
        dxv[i] = (float)(((double)(Ia + (i <= ni ? i : ni)) + 0.5) - f->x0);
    const int ic0 = fast_wrap(Ia, f->S);
    for (int j = 0; j <= nj; j++)
        fast_vertex_row(f, &b, dxv, Ja, j, ni, ic0);
    int iw[MESH_BLOCK], jw[MESH_BLOCK]; /* the squares' cells, mod S */
    for (int i = 0, c = ic0; i < ni; i++, c = c + 1 == f->S ? 0 : c + 1)
        iw[i] = c;
    for (int j = 0, c = fast_wrap(Ja, f->S); j < nj; j++, c = c + 1 == f->S ? 0 : c + 1)
        jw[j] = c;

    fast_row rows[MESH_BLOCK];
    fast_counts cnt = {0, 0, 0, 0, 0};
    for (int j = 0; j < nj; j++)
        fast_classify_row(f, &b, j, ni, &rows[j], &cnt);
    mc->st.submitted += cnt.submitted;
    mc->st.culled += cnt.culled;
    mc->st.clipped_out += cnt.clipped_out;
    mc->st.rasterized += cnt.rast;
    mc->st.fragments += cnt.frags;

    /* The z-buffer's order (traversal.c's block(), drawing front to back). */
    static const double tsx[2][3] = {{0.5, 1.5, 1.5}, {0.5, 0.5, 1.5}}, tsy[2][3] = {{0.5, 1.5, 0.5}, {0.5, 1.5, 1.5}};
    static const float fsx[2][3] = {{0.5f, 1.5f, 1.5f}, {0.5f, 0.5f, 1.5f}}, fsy[2][3] = {{0.5f, 1.5f, 0.5f}, {0.5f, 1.5f, 1.5f}};
    uint32_t done[FN];
    memset(done, 0, sizeof done);
    uint64_t written = 0;
    const int fy = sy >= 0, fx = sx >= 0;
    for (int jj = 0; jj < nj; jj++) {
        const int j = fy ? jj : nj - 1 - jj;
        const fast_row *R = &rows[j];
        unsigned m = R->slow | R->cand[0] | R->cand[1] | R->tiny[0] | R->tiny[1];
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
                if (R->tiny[t] >> i & 1u) {
                    fast_tiny_draw(mc, R, t, i, iw[i], jw[j], &written);
                    continue;
                }
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
                    fast_raster_nearest(mc, X, Y, q, fsx[t], fsy[t], iw[i], jw[j]);
                }
            }
        }
    }
    mc->st.written += written;
}
