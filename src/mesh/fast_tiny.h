/* Tiny triangles in lanes (included by fast_tmpl.h after its vector header): a triangle inside
 * every frustum plane, counter-clockwise after snapping (A > 0), whose bounding box holds at
 * most 2 x 2 pixel centres of this frame's rows. Most surviving triangles are such (the mesh is
 * finer than the pixel grid), and per triangle the reference's raster spends its time in setup,
 * not in its loop. Here the whole raster of VN such triangles is evaluated at once up to the
 * depth test, which alone depends on the drawing order and stays in fast_tmpl.h's draw loop:
 * - the edge functions at each candidate centre, E_k(p) = dx_k (pV - V_k) - dv_k (pX - X_k), in
 *   binary64 lanes from int32 operands (products below 2^46, their difference below 2^47:
 *   exact, the reference's int64 values);
 * - coverage with the top-left rule (E_k > 0, or E_k = 0 on a top-left edge);
 * - per covered centre the reference raster's binary32 operations in its order:
 *   w0 = (float)E_1, w1 = (float)E_2, w2 = (float)E_0, Q = (w0 q0 + w1 q1) + w2 q2,
 *   z = (float)A / Q and sx, sy = ((w0 p0 + w1 p1) + w2 p2) / Q with p_k = a_k q_k (the
 *   reference forms them after the depth test; they do not depend on it). Only sx >= 1 and
 *   sy >= 1 are kept: the nearest colour reads nothing else. */
#ifndef RETRO_MESH_FAST_TINY_H
#define RETRO_MESH_FAST_TINY_H

/* Centre n of a tiny triangle is (c0 + (n & 1), r0 + (n >> 1)), the reference raster's order. */
typedef struct {
    unsigned cov[4];            /* bit i: the triangle of square i of the row covers centre n */
    unsigned sxb[4], syb[4];    /* its fragment there has sx >= 1, sy >= 1 */
    float z[4][MESH_BLOCK];     /* and this depth */
} fast_tiny;
_Static_assert(MESH_BLOCK % VN == 0, "a row of squares is whole vectors");

/* Vertices (x_k, y_k) fixed point, q_k = 1/z_k, attributes (ax_k, ay_k) of the triangle kind;
 * (c0, r0) the clamped bounding box's first centre; lanes: the tiny triangles, two_c / two_r:
 * those whose box has a second column / row; i0 the lanes' first square in the row. Returns the
 * lanes that cover a centre. */
static inline unsigned fast_tiny_lanes(const vi x[3], const vi y[3], const vf q[3], const float ax[3], const float ay[3],
                                   vi c0, vi r0, unsigned lanes, unsigned two_c, unsigned two_r, int i0, fast_tiny *out)
{
    vi dx[3], dy[3], rx[3], ry[3];
    const vi px = vi_sll8(c0), py = vi_sll8(r0);
    unsigned tl[3];
    for (int k = 0; k < 3; k++) {
        const int n = k == 2 ? 0 : k + 1;
        dx[k] = vi_sub(x[n], x[k]);
        dy[k] = vi_sub(y[n], y[k]);
        rx[k] = vi_sub(px, x[k]);
        ry[k] = vi_sub(py, y[k]);
        /* top-left: a left edge (dv < 0) or a top edge (dv = 0, dx < 0) */
        tl[k] = vi_gt(vi_set1(0), dy[k]) | (vi_eq(dy[k], vi_set1(0)) & vi_gt(vi_set1(0), dx[k]));
    }
    const vi ex = vi_sub(x[2], x[0]), ey = vi_sub(y[2], y[0]);
    const unsigned want[4] = {lanes, lanes & two_c, lanes & two_r, lanes & two_c & two_r};
    vd E[4][3][2], A[2];
    const vd k256 = vd_set1((double)MESH_ONE), m256 = vd_set1(-(double)MESH_ONE);
    unsigned cov[4] = {0, 0, 0, 0};
    for (int h = 0; h < 2; h++) {
        const unsigned hm = (1u << VH) - 1, sh = (unsigned)(h * VH);
        A[h] = vd_sub(vd_mul(vd_half(dx[0], h), vd_half(ey, h)), vd_mul(vd_half(dy[0], h), vd_half(ex, h)));
        for (int k = 0; k < 3; k++) {
            const vd ddx = vd_half(dx[k], h), ddy = vd_half(dy[k], h);
            const vd e = vd_sub(vd_mul(ddx, vd_half(ry[k], h)), vd_mul(ddy, vd_half(rx[k], h)));
            const vd sx = vd_mul(ddy, m256), sy = vd_mul(ddx, k256);
            E[0][k][h] = e;
            E[1][k][h] = vd_add(e, sx);
            E[2][k][h] = vd_add(e, sy);
            E[3][k][h] = vd_add(E[1][k][h], sy);
        }
        for (int n = 0; n < 4; n++) {
            unsigned c = (want[n] >> sh) & hm;
            for (int k = 0; k < 3 && c; k++)
                c &= vd_gt0(E[n][k][h]) | (vd_eq0(E[n][k][h]) & (tl[k] >> sh));
            cov[n] |= c << sh;
        }
    }
    const vf area = vf_from_vd(A[0], A[1]), one = vf_set1(1.0f);
    vf px_[3], py_[3];
    for (int k = 0; k < 3; k++) {
        px_[k] = vf_mul(vf_set1(ax[k]), q[k]);
        py_[k] = vf_mul(vf_set1(ay[k]), q[k]);
    }
    for (int n = 0; n < 4; n++) {
        if (!cov[n])
            continue;
        const vf w0 = vf_from_vd(E[n][1][0], E[n][1][1]), w1 = vf_from_vd(E[n][2][0], E[n][2][1]);
        const vf w2 = vf_from_vd(E[n][0][0], E[n][0][1]);
        const vf Q = vf_add(vf_add(vf_mul(w0, q[0]), vf_mul(w1, q[1])), vf_mul(w2, q[2]));
        vf_store(out->z[n] + i0, vf_div(area, Q));
        const vf sx = vf_div(vf_add(vf_add(vf_mul(w0, px_[0]), vf_mul(w1, px_[1])), vf_mul(w2, px_[2])), Q);
        const vf sy = vf_div(vf_add(vf_add(vf_mul(w0, py_[0]), vf_mul(w1, py_[1])), vf_mul(w2, py_[2])), Q);
        out->cov[n] |= cov[n] << i0;
        out->sxb[n] |= (vf_ge(sx, one) & cov[n]) << i0;
        out->syb[n] |= (vf_ge(sy, one) & cov[n]) << i0;
    }
    return cov[0] | cov[1] | cov[2] | cov[3];
}

#endif
