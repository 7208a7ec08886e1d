/* Scan conversion and clipping in isolation (through the family's internal stages): shared
 * edges cover each pixel centre exactly once, and triangles crossing each clip plane cover
 * exactly the pixels a ray-cast of the unclipped triangle finds inside the frustum. */
#include "mesh/mesh_internal.h"
#include "mesh_util.h"

#define MARK 0xff000000u

/* A context whose frame is set up for a W x H screen, map S = 1 (every fragment reads the one
 * colour MARK), painter kernel (no depth test: each covered centre is a write), binary64. */
static retro_mesh_ctx *stage_ctx(int W, int H, uint32_t *out, unsigned mfx)
{
    static uint8_t h1[1] = {0};
    static uint32_t c1[1] = {MARK};
    retro_mesh_ctx *mc = retro_mesh_ctx_new();
    cr_assert(mc);
    ctx_t c = {W, H, 1, 2, 0, h1, c1, out};
    player_t p = {0.5f, 0.5f, 0, 10, 0, 0, 0};
    retro_mesh_opts o = {mfx, 0};
    cr_assert_eq(retro_mesh_render(mc, RETRO_MESH_PAINTER, RETRO_MESH_BINARY64, &p, &c, NULL, &o, NULL), 0);
    mc->f.far = 1000;
    return mc;
}

static mesh_vert flat_vert(double z)
{
    mesh_vert v;
    memset(&v, 0, sizeof v);
    v.z = z;
    v.a[A_SX] = v.a[A_SY] = 1.0;
    return v;
}

/* Draws one triangle given in fixed-point screen coordinates and adds its coverage to count. */
static void draw_screen_tri(retro_mesh_ctx *mc, const int64_t X[3], const int64_t Y[3], uint8_t *count)
{
    cr_assert_gt((X[1] - X[0]) * (Y[2] - Y[0]) - (Y[1] - Y[0]) * (X[2] - X[0]), 0, "test triangle not counter-clockwise");
    int n = mc->f.W * mc->f.H;
    for (int i = 0; i < n; i++)
        mc->out[i] = 0;
    static mesh_tri t;
    memset(&t, 0, sizeof t);
    mesh_vert v = flat_vert(1.0);
    mesh_sub s;
    for (int k = 0; k < 3; k++) {
        s.X[k] = X[k];
        s.Y[k] = Y[k];
        s.v[k] = &v;
    }
    s.edges = 7;
    s.t = &t;
    mesh_scan_convert(mc, &s);
    for (int i = 0; i < n; i++)
        count[i] = (uint8_t)(count[i] + (mc->out[i] == MARK));
}

/* A jittered grid of triangles covering more than the screen, vertices often exactly on pixel
 * centres or on half pixels, both diagonals: every pixel centre is covered exactly once. */
Test(mesh_raster, shared_edges_cover_each_pixel_once)
{
    enum { W = 61, H = 47, CELL = 5, NX = W / CELL + 3, NY = H / CELL + 3 };
    uint32_t out[W * H];
    uint8_t count[W * H];
    retro_mesh_ctx *mc = stage_ctx(W, H, out, 0);
    uint64_t seed = 3;
    for (int round = 0; round < 6; round++) {
        memset(count, 0, sizeof count);
        int64_t gx[NY + 1][NX + 1], gy[NY + 1][NX + 1];
        for (int j = 0; j <= NY; j++)
            for (int i = 0; i <= NX; i++) {
                int64_t x = (int64_t)(i * CELL - 2 * CELL) * MESH_ONE, y = (int64_t)(j * CELL - 2 * CELL) * MESH_ONE;
                int inner = i > 0 && j > 0 && i < NX && j < NY;
                uint64_t r = mrng(&seed) % 3;
                /* jitter within one pixel keeps every 5-pixel quad convex */
                if (inner && r == 0) { /* anywhere in [-1, 1) pixel */
                    x += (int64_t)(mrng(&seed) % (2 * MESH_ONE)) - MESH_ONE;
                    y += (int64_t)(mrng(&seed) % (2 * MESH_ONE)) - MESH_ONE;
                } else if (inner && r == 1) { /* on a half pixel */
                    x += ((int64_t)(mrng(&seed) % 4) - 2) * MESH_ONE / 2;
                    y += ((int64_t)(mrng(&seed) % 4) - 2) * MESH_ONE / 2;
                } /* else on a pixel centre */
                gx[j][i] = x;
                gy[j][i] = y;
            }
        for (int j = 0; j < NY; j++)
            for (int i = 0; i < NX; i++) {
                int64_t X00 = gx[j][i], Y00 = gy[j][i], X10 = gx[j][i + 1], Y10 = gy[j][i + 1];
                int64_t X11 = gx[j + 1][i + 1], Y11 = gy[j + 1][i + 1], X01 = gx[j + 1][i], Y01 = gy[j + 1][i];
                if (mrng(&seed) & 1) {
                    int64_t a[3] = {X00, X10, X11}, b[3] = {Y00, Y10, Y11};
                    int64_t c[3] = {X00, X11, X01}, d[3] = {Y00, Y11, Y01};
                    draw_screen_tri(mc, a, b, count);
                    draw_screen_tri(mc, c, d, count);
                } else {
                    int64_t a[3] = {X00, X10, X01}, b[3] = {Y00, Y10, Y01};
                    int64_t c[3] = {X10, X11, X01}, d[3] = {Y10, Y11, Y01};
                    draw_screen_tri(mc, a, b, count);
                    draw_screen_tri(mc, c, d, count);
                }
            }
        for (int i = 0; i < W * H; i++)
            cr_assert_eq(count[i], 1, "round %d: pixel (%d, %d) covered %d times", round, i % W + 1, H - i / W, count[i]);
    }
    retro_mesh_ctx_free(mc);
}

/* A fan of thin triangles around a point on a pixel centre: the centre itself once. */
Test(mesh_raster, fan_around_a_pixel_centre)
{
    enum { W = 21, H = 21 };
    uint32_t out[W * H];
    uint8_t count[W * H];
    memset(count, 0, sizeof count);
    retro_mesh_ctx *mc = stage_ctx(W, H, out, 0);
    const int n = 24;
    int64_t cx = 10 * MESH_ONE, cy = 11 * MESH_ONE;
    for (int k = 0; k < n; k++) {
        double a0 = 2 * 3.14159265358979 * k / n, a1 = 2 * 3.14159265358979 * (k + 1) / n;
        int64_t X[3] = {cx, cx + (int64_t)llround(cos(a0) * 8 * MESH_ONE), cx + (int64_t)llround(cos(a1) * 8 * MESH_ONE)};
        int64_t Y[3] = {cy, cy + (int64_t)llround(sin(a0) * 8 * MESH_ONE), cy + (int64_t)llround(sin(a1) * 8 * MESH_ONE)};
        draw_screen_tri(mc, X, Y, count);
    }
    for (int r = 1; r <= H; r++)
        for (int u = 0; u < W; u++) {
            double d = hypot(u - 10.0, r - 11.0);
            int c = count[(H - r) * W + u];
            cr_assert(c <= 1, "pixel (%d,%d) covered %d times", u + 1, r, c);
            if (d < 7.5)
                cr_assert_eq(c, 1, "pixel (%d,%d) inside the fan not covered", u + 1, r);
        }
    retro_mesh_ctx_free(mc);
}

/* Ray-cast coverage of one eye-space triangle: +1 inside the frustum part, 0 outside, -1 too
 * close to an edge, the near or the far plane to decide. */
static int ray_inside(const mesh_frame *f, const mesh_vert *v, int col, int r)
{
    double dl = (col - f->cx) / f->kx, de = (r - f->cy) / f->ky;
    double al = v[1].l - v[0].l, ae = v[1].e - v[0].e, az = v[1].z - v[0].z;
    double bl = v[2].l - v[0].l, be = v[2].e - v[0].e, bz = v[2].z - v[0].z;
    double nl = ae * bz - az * be, ne = az * bl - al * bz, nz = al * be - ae * bl;
    double den = nl * dl + ne * de + nz;
    if (fabs(den) < 1e-12)
        return -1;
    double z = (nl * v[0].l + ne * v[0].e + nz * v[0].z) / den;
    double P[3] = {z * dl, z * de, z};
    /* barycentrics by sub-areas against the normal */
    double nn = nl * nl + ne * ne + nz * nz, w[3];
    for (int k = 0; k < 3; k++) {
        const mesh_vert *p1 = &v[(k + 1) % 3], *p2 = &v[(k + 2) % 3];
        double ul = p1->l - P[0], ue = p1->e - P[1], uz = p1->z - P[2];
        double wl = p2->l - P[0], we = p2->e - P[1], wz = p2->z - P[2];
        double cl = ue * wz - uz * we, ce = uz * wl - ul * wz, cz = ul * we - ue * wl;
        w[k] = (cl * nl + ce * ne + cz * nz) / nn;
    }
    double wmin = fmin(w[0], fmin(w[1], w[2]));
    if (fabs(wmin) < 2e-3 || fabs(z - 1) < 1e-3 || fabs(z - f->far) < 1e-3)
        return -1;
    return wmin > 0 && z > 1 && z < f->far ? 1 : 0;
}

static void clip_case(const char *name, mesh_vert v[3])
{
    enum { W = 40, H = 30 };
    uint32_t out[W * H];
    retro_mesh_ctx *mc = stage_ctx(W, H, out, RETRO_MESH_FX_NOCULL);
    mc->f.far = 50;
    for (int i = 0; i < W * H; i++)
        out[i] = 0;
    mesh_tri t;
    memset(&t, 0, sizeof t);
    mesh_snap s[3];
    const mesh_snap *s3[3] = {&s[0], &s[1], &s[2]};
    for (int k = 0; k < 3; k++) {
        t.v[k] = v[k];
        t.v[k].a[A_SX] = t.v[k].a[A_SY] = 1.0;
        double d[6];
        mesh_plane_distances(&mc->f, &t.v[k], d);
        s[k].out = 0;
        for (int p = 0; p < 6; p++)
            s[k].out |= d[p] < 0 ? 1u << p : 0u;
        s[k].ok = s[k].out == 0;
        if (s[k].ok)
            mesh_project(&mc->f, &t.v[k], &s[k].X, &s[k].Y);
    }
    cr_assert(s[0].out | s[1].out | s[2].out, "%s: the case crosses no plane", name);
    mesh_clip_and_draw(mc, &t, s3);
    int inside = 0;
    for (int r = 1; r <= H; r++)
        for (int u = 0; u < W; u++) {
            int want = ray_inside(&mc->f, t.v, u, r);
            if (want < 0)
                continue;
            inside += want;
            int got = out[(H - r) * W + u] == MARK;
            cr_assert_eq(got, want, "%s: pixel (%d,%d) drawn %d, ray-cast %d", name, u + 1, r, got, want);
        }
    cr_assert_gt(inside, 0, "%s: nothing on screen", name);
    retro_mesh_ctx_free(mc);
}

static mesh_vert ev(double l, double e, double z)
{
    mesh_vert v = flat_vert(z);
    v.l = l;
    v.e = e;
    return v;
}

/* The screen is X = 19.5 l/z + 19.5 (W = 40), V = 20 e/z + 15 (H = 30), far plane 50. */
Test(mesh_clip, crossing_each_plane)
{
    struct {
        const char *name;
        mesh_vert v[3];
    } cases[] = {
        {"near", {ev(-2, -1, 0.3), ev(2, -1, 4), ev(0, 1, 6)}},
        {"near, a vertex behind the eye", {ev(-1, -0.5, -3), ev(2, -1, 4), ev(-1, 1, 5)}},
        {"far", {ev(-10, -5, 30), ev(10, -5, 40), ev(0, 5, 80)}},
        {"left", {ev(-30, 0, 10), ev(2, -2, 10), ev(2, 2, 12)}},
        {"right", {ev(30, 0, 10), ev(-2, 2, 10), ev(-2, -2, 12)}},
        {"bottom", {ev(0, -30, 10), ev(3, 2, 10), ev(-3, 2, 12)}},
        {"top", {ev(0, 30, 10), ev(-3, -2, 10), ev(3, -2, 12)}},
        /* the plane z = 25 + 2e from z = 0.5 below the eye to z = 425 far to both sides */
        {"near, far, left and right", {ev(0, -12.25, 0.5), ev(1500, 200, 425), ev(-1500, 200, 425)}},
        {"left, right, bottom and top", {ev(-100, -100, 10), ev(100, -100, 10), ev(0, 200, 10)}},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++)
        clip_case(cases[i].name, cases[i].v);
}

/* Through the whole pipeline: flat ground seen from above has no overlap, so the painter's
 * fragments are exactly the terrain pixels (no double hit), in every mode and at many angles. */
Test(mesh_raster, flat_ground_fragments_once)
{
    enum { W = 50, H = 40, S = 8 };
    uint8_t h[S * S];
    uint32_t col[S * S], px[W * H];
    memset(h, 30, sizeof h);
    for (int i = 0; i < S * S; i++)
        col[i] = (uint32_t)(i + 1) << 8;
    ctx_t c = {W, H, S, 60, MSKY, h, col, px};
    for (int a = -45; a < 360; a += 37)
        for (int m = 0; m < RETRO_MESH_MODE_COUNT; m++) {
            player_t p = {3.7f, 1.2f, a, 45, 0, 0, 0};
            retro_mesh_stats st;
            cr_assert_eq(mrender(RETRO_MESH_PAINTER, (retro_mesh_mode)m, &p, &c, NULL, 0, &st), 0);
            uint64_t terrain = 0;
            for (int i = 0; i < W * H; i++)
                terrain += px[i] != MSKY;
            cr_assert_gt(terrain, 100);
            cr_assert_eq(st.fragments, terrain, "angle %d mode %d: %lu fragments for %lu pixels", a, m,
                         (unsigned long)st.fragments, (unsigned long)terrain);
            cr_assert_eq(st.culled, 0);
        }
}
