/* Mode int's error against binary64 (docs/MESH.md, "Error of mode int"): one triangle with
 * its vertex depths in the ratio rho = zmax / zmin, Gouraud colours spanning 0..255, drawn in
 * both modes; the largest colour difference and the largest relative depth error are measured
 * and held to the bounds the analysis derives, 255 (2^-14 rho + 2^-17) + 1 colour units and
 * 2^-14 rho + 2^-16 relative depth. rho = 4096 (z from 1 to the far cap) is the worst case. */
#include "mesh/mesh_internal.h"
#include "mesh_util.h"

enum { W = 64, H = 48 };

static void draw(retro_mesh_ctx *mc, retro_mesh_mode mode, const mesh_tri *t)
{
    mc->f.mode = mode;
    mc->f.f32 = 0;
    for (int i = 0; i < W * H; i++) {
        mc->out[i] = MSKY;
        if (mode == RETRO_MESH_INT)
            ((uint32_t *)mc->depth)[i] = 0;
        else
            ((double *)mc->depth)[i] = INFINITY;
    }
    mesh_snap s[3];
    const mesh_snap *s3[3] = {&s[0], &s[1], &s[2]};
    for (int k = 0; k < 3; k++) {
        double d[6];
        mesh_plane_distances(&mc->f, &t->v[k], d);
        s[k].out = 0;
        for (int p = 0; p < 6; p++)
            s[k].out |= d[p] < 0 ? 1u << p : 0u;
        s[k].ok = s[k].out == 0;
        if (s[k].ok)
            mesh_project(&mc->f, &t->v[k], &s[k].X, &s[k].Y);
    }
    mesh_clip_and_draw(mc, t, s3);
}

Test(mesh_int_error, interpolation_against_binary64)
{
    static uint8_t h1[1] = {0};
    static uint32_t c1[1] = {0};
    uint32_t out[W * H], ref[W * H];
    static double zref[W * H];
    retro_mesh_ctx *mc = retro_mesh_ctx_new();
    ctx_t c = {W, H, 1, 2, MSKY, h1, c1, out};
    player_t p = {0.5f, 0.5f, 0, 10, 0, 0, 0};
    retro_mesh_opts o = {RETRO_MESH_FX_GOURAUD, 0};
    cr_assert_eq(retro_mesh_render(mc, RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY64, &p, &c, NULL, &o, NULL), 0);
    mc->f.far = RETRO_MESH_MAX_FAR + 1;
    const double rhos[] = {1, 1.5, 2.5, 16, 256, 4096};
    const double X[3] = {1.3, 62.2, 30.7}, V[3] = {1.6, 4.4, 47.1};
    const double col[3][3] = {{0, 255, 0}, {255, 0, 0}, {0, 0, 255}};
    for (size_t n = 0; n < sizeof rhos / sizeof *rhos; n++) {
        double rho = rhos[n], z[3] = {1, rho, rho};
        for (int far_first = 0; far_first < 2; far_first++) {
            mesh_tri t;
            memset(&t, 0, sizeof t);
            for (int k = 0; k < 3; k++) {
                double zk = far_first ? z[2 - k] : z[k];
                t.v[k].z = zk;
                t.v[k].l = (X[k] - mc->f.cx) * zk / mc->f.kx;
                t.v[k].e = (V[k] - mc->f.cy) * zk / mc->f.ky;
                for (int ch = 0; ch < 3; ch++)
                    t.v[k].a[A_R + ch] = col[k][ch];
            }
            draw(mc, RETRO_MESH_BINARY64, &t);
            memcpy(ref, out, sizeof ref);
            memcpy(zref, mc->depth, sizeof zref);
            draw(mc, RETRO_MESH_INT, &t);
            int maxc = 0, pixels = 0;
            double maxz = 0;
            for (int i = 0; i < W * H; i++) {
                cr_assert_eq(out[i] == MSKY, ref[i] == MSKY, "coverage differs at %d", i);
                if (ref[i] == MSKY)
                    continue;
                pixels++;
                for (int sh = 8; sh <= 24; sh += 8) {
                    int d = abs((int)((out[i] >> sh) & 255) - (int)((ref[i] >> sh) & 255));
                    maxc = d > maxc ? d : maxc;
                }
                double qz = ((uint32_t *)mc->depth)[i] / 268435456.0, rz = 1.0 / zref[i];
                maxz = fmax(maxz, fabs(qz - rz) / rz);
            }
            double bound_c = 255 * (ldexp(rho, -14) + ldexp(1, -17)) + 1;
            double bound_z = ldexp(rho, -14) + ldexp(1, -16);
            cr_log_info("mode int, rho %g (%s vertex first), %d pixels: colour error %d (bound %.2f), "
                        "depth relative error %.3g (bound %.3g)",
                        rho, far_first ? "far" : "near", pixels, maxc, bound_c, maxz, bound_z);
            cr_assert_gt(pixels, 500);
            cr_assert_leq(maxc, bound_c, "rho %g: colour error %d above the bound %.2f", rho, maxc, bound_c);
            cr_assert_leq(maxz, bound_z, "rho %g: depth error %g above the bound %g", rho, maxz, bound_z);
            if (rho <= 2.5) /* the terrain's triangles: one unit at most */
                cr_assert_leq(maxc, 1);
        }
    }
    retro_mesh_ctx_free(mc);
}
