/* Mesh frames whose image is known: a flat map, a single raised vertex, an independent
 * ray-cast reference on seeded random poses, and the crack test. */
#include "mesh_util.h"

/* Flat ground at 50 seen from 80 with D = 40: the ground meets the far plane on the row
 * V(40) = (W/2)(50 - 80)/40 + H/2 = 24 - 24 = 0, below row 1, and nearer ground lies lower
 * still: the frame is all sky at every angle. */
Test(mesh_analytic, flat_map_below_screen)
{
    enum { W = 64, H = 48, S = 16 };
    uint8_t h[S * S];
    uint32_t col[S * S], px[W * H];
    memset(h, 50, sizeof h);
    for (int i = 0; i < S * S; i++)
        col[i] = 0x20a04000u;
    ctx_t c = {W, H, S, 40, MSKY, h, col, px};
    cr_assert_eq(0.5 * W * (50 - 80) / 40 + 0.5 * H, 0.0);
    for (int a = 0; a < 360; a += 45) {
        player_t p = {5.3f, 7.9f, a, 80, 0, 0, 0};
        for (int k = 0; k < RETRO_MESH_KERNEL_COUNT; k++)
            for (int m = 0; m < RETRO_MESH_MODE_COUNT; m++) {
                if (!mkernel_runs((retro_mesh_kernel)k, (retro_mesh_mode)m))
                    continue; /* a mode or ISA the kernel refuses (tests/test_mesh_fast.c) */
                mrender_ok((retro_mesh_kernel)k, (retro_mesh_mode)m, &p, &c, NULL, 0);
                for (int i = 0; i < W * H; i++)
                    cr_assert_eq(px[i], MSKY, "angle %d: pixel %d", a, i);
            }
    }
}

/* The same ground with the far plane at 100: V(100) = 24 - 9.6 = 14.4, so rows 1..14 are
 * ground in every column and rows 15..48 sky. */
Test(mesh_analytic, flat_map_every_column_identical)
{
    enum { W = 64, H = 48, S = 16 };
    uint8_t h[S * S];
    uint32_t col[S * S], px[W * H];
    memset(h, 50, sizeof h);
    for (int i = 0; i < S * S; i++)
        col[i] = 0x20a04000u;
    ctx_t c = {W, H, S, 100, MSKY, h, col, px};
    double v = 0.5 * W * (50.0 - 80.0) / 100.0 + 0.5 * H;
    int top = (int)floor(v);
    cr_assert_eq(top, 14);
    for (int a = 0; a < 360; a += 15)
        for (int k = 0; k < RETRO_MESH_KERNEL_COUNT; k++)
            for (int m = 0; m < RETRO_MESH_MODE_COUNT; m++) {
                if (!mkernel_runs((retro_mesh_kernel)k, (retro_mesh_mode)m))
                    continue; /* a mode or ISA the kernel refuses (tests/test_mesh_fast.c) */
                player_t p = {5.3f + (float)a, 7.9f - (float)a, a, 80, 0, 0, 0};
                mrender_ok((retro_mesh_kernel)k, (retro_mesh_mode)m, &p, &c, NULL, 0);
                for (int r = 1; r <= H; r++)
                    for (int u = 0; u < W; u++)
                        cr_assert_eq(px[(H - r) * W + u], r <= top ? col[0] : MSKY,
                                     "angle %d mesh-%s/%s: pixel (%d,%d)", a,
                                     retro_mesh_kernel_name((retro_mesh_kernel)k),
                                     retro_mesh_mode_name((retro_mesh_mode)m), u + 1, r);
            }
}

/* One vertex raised to 255 on ground at 0, seen along +x from height 100 at distance 20: the
 * raised vertex projects to V = (W/2)(255 - 100)/20 + H/2 and X = cx, so the footprint's top
 * is the pixel below that apex, in the middle column, and no pixel above it is terrain. */
Test(mesh_analytic, single_raised_vertex_footprint)
{
    enum { W = 41, H = 200, S = 64 };
    uint8_t *h = calloc(S * S, 1);
    uint32_t *col = malloc(sizeof(uint32_t) * S * S), *px = malloc(sizeof(uint32_t) * W * H);
    uint32_t *ref = malloc(sizeof(uint32_t) * W * H);
    for (int i = 0; i < S * S; i++)
        col[i] = 0x30303000u;
    h[32 * S + 32] = 255;
    col[32 * S + 32] = 0xff000000u;
    ctx_t c = {W, H, S, 40, MSKY, h, col, px};
    player_t p = {12.5f, 32.5f, 0, 100, 0, 0, 0}; /* the vertex (32, 32) sits at z = 20, l = 0 */
    double apex = 0.5 * W * (255 - 100) / 20.0 + 0.5 * H; /* 258.4: above the screen */
    cr_assert(apex > H);
    mrender_ok(RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY64, &p, &c, NULL, 0);
    /* The spike's six triangles are the only terrain above the ground's horizon row; the
     * ground (height 0, 100 below the eye) lies below row V(40) = 100 - 20.5*100/40. */
    int ground_top = (int)floor(0.5 * H - 0.5 * W * 100.0 / 40.0);
    int spike = 0;
    for (int r = ground_top + 1; r <= H; r++)
        for (int u = 0; u < W; u++) {
            uint32_t v = px[(H - r) * W + u];
            if (v != MSKY) {
                spike++;
                /* inside the spike's footprint: |X - cx| within the widest triangle's span
                 * at that row (the base is +-1 square wide at z = 19..21) */
                double x = u - 0.5 * (W - 1);
                cr_assert(fabs(x) <= 0.5 * (W - 1) * 1.5 / 19.0 + 1, "pixel (%d,%d) outside", u + 1, r);
            }
        }
    cr_assert_gt(spike, 20);
    /* the apex column reaches the top row: the spike passes through the screen's top */
    cr_assert_neq(px[(size_t)0 * W + W / 2], MSKY);
    /* and the independent reference agrees wherever it decides */
    mref_render(&p, &c, ref);
    for (int i = 0; i < W * H; i++)
        if (ref[i] != UNDECIDED)
            cr_assert_eq(px[i], ref[i], "pixel %d: %08x, reference %08x", i, px[i], ref[i]);
    free(h);
    free(col);
    free(px);
    free(ref);
}

/* Seeded random maps and poses: every kernel and mode agrees with the ray-cast reference on
 * every pixel the reference decides. */
Test(mesh_reference, random_poses_match_raycast)
{
    enum { W = 24, H = 32 };
    uint32_t px[W * H], ref[W * H];
    uint64_t seed = 7;
    long decided = 0, terrain = 0, total = 0;
    for (int n = 0; n < 12; n++) {
        int S = 2 + (int)(mrng(&seed) % 9);
        mmap_t m = mmap_random(S, mrng(&seed), 0, 40);
        /* 5 above the highest vertex keeps every triangle that crosses the eye plane below
         * the screen (V <= 16 - 12 * 5 / 1.5 < 0), which the reference relies on */
        player_t p = {(float)(mrng(&seed) % 1000) / 37.0f, (float)(mrng(&seed) % 1000) / 41.0f,
                      (int)(mrng(&seed) % 720) - 360, 45 + (int)(mrng(&seed) % 10), 0, 0, 0};
        ctx_t c = {W, H, S, 25 + (int)(mrng(&seed) % 35), MSKY, m.h, m.c, px};
        mref_render(&p, &c, ref);
        for (int i = 0; i < W * H; i++)
            terrain += ref[i] != UNDECIDED && ref[i] != MSKY;
        for (int k = 0; k < RETRO_MESH_KERNEL_COUNT; k++)
            for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++) {
                if (!mkernel_runs((retro_mesh_kernel)k, (retro_mesh_mode)md))
                    continue; /* a mode or ISA the kernel refuses (tests/test_mesh_fast.c) */
                mrender_ok((retro_mesh_kernel)k, (retro_mesh_mode)md, &p, &c, NULL, 0);
                for (int i = 0; i < W * H; i++) {
                    if (ref[i] == UNDECIDED)
                        continue;
                    decided += k == 0 && md == 0;
                    cr_assert_eq(px[i], ref[i], "pose %d (S %d, angle %d) mesh-%s/%s pixel %d: %08x, reference %08x", n,
                                 S, p.angle, retro_mesh_kernel_name((retro_mesh_kernel)k),
                                 retro_mesh_mode_name((retro_mesh_mode)md), i, px[i], ref[i]);
                }
            }
        total += W * H;
        mmap_free(&m);
    }
    cr_assert_gt(decided, total * 7 / 10, "the reference decided only %ld of %ld pixels", decided, total);
    cr_assert_gt(terrain, total / 5, "only %ld terrain pixels of %ld", terrain, total);
}

/* With the camera at least 20 above the ground below it, no column has a sky pixel below a
 * terrain pixel: the mesh is closed, with no crack between triangles. */
Test(mesh_cracks, no_sky_below_terrain)
{
    enum { W = 48, H = 36 };
    uint32_t px[W * H];
    uint64_t seed = 11;
    for (int n = 0; n < 40; n++) {
        int S = 1 + (int)(mrng(&seed) % 32);
        mmap_t m = mmap_random(S, mrng(&seed), 0, (int)(mrng(&seed) % 256));
        int hmax = 0;
        for (int i = 0; i < S * S; i++)
            hmax = m.h[i] > hmax ? m.h[i] : hmax;
        player_t p = {(float)(mrng(&seed) % 10000) / 97.0f, (float)(mrng(&seed) % 10000) / 89.0f,
                      (int)(mrng(&seed) % 360), hmax + 20 + (int)(mrng(&seed) % 60), 0, 0, 0};
        ctx_t c = {W, H, S, 10 + (int)(mrng(&seed) % 200), MSKY, m.h, m.c, px};
        for (int k = 0; k < RETRO_MESH_KERNEL_COUNT; k++)
            for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++) {
                if (!mkernel_runs((retro_mesh_kernel)k, (retro_mesh_mode)md))
                    continue; /* a mode or ISA the kernel refuses (tests/test_mesh_fast.c) */
                mrender_ok((retro_mesh_kernel)k, (retro_mesh_mode)md, &p, &c, NULL, 0);
                for (int u = 0; u < W; u++) {
                    int seen_sky = 0;
                    for (int r = 1; r <= H; r++) {
                        int sky = px[(H - r) * W + u] == MSKY;
                        cr_assert(!(seen_sky && !sky), "pose %d mesh-%s/%s: column %d has sky below terrain at row %d",
                                  n, retro_mesh_kernel_name((retro_mesh_kernel)k),
                                  retro_mesh_mode_name((retro_mesh_mode)md), u + 1, r);
                        seen_sky |= sky;
                    }
                }
            }
        mmap_free(&m);
    }
}
