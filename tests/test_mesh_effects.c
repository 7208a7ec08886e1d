/* Each effect of the mesh family against what it must do to a frame. */
#include "mesh_util.h"

enum { W = 40, H = 30, S = 8 };

static void flat(uint8_t *h, uint32_t *c, int level, uint32_t colour)
{
    memset(h, level, S * S);
    for (int i = 0; i < S * S; i++)
        c[i] = colour;
}

static int count_not(const uint32_t *px, uint32_t v)
{
    int n = 0;
    for (int i = 0; i < W * H; i++)
        n += px[i] != v;
    return n;
}

static const player_t pose = {3.3f, 5.6f, 30, 90, 0, 0, 0};

Test(mesh_effects, fog_all_or_nothing)
{
    mmap_t m = mmap_random(S, 1, 0, 60);
    uint32_t a[W * H], b[W * H];
    ctx_t c = {W, H, S, 80, MSKY, m.h, m.c, a};
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = RETRO_FX_FOG;
    for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++) {
        c.out = a;
        fx.fog_start = 0; /* full fog from depth 1e-6 on: every fragment is the sky colour */
        fx.fog_end = 1e-6f;
        mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &pose, &c, &fx, 0);
        cr_assert_eq(count_not(a, MSKY), 0);
        fx.fog_start = fx.fog_end = 1e7f; /* a step beyond every depth: no fog */
        mrender_ok(RETRO_MESH_PAINTER, (retro_mesh_mode)md, &pose, &c, &fx, 0);
        c.out = b;
        mrender_ok(RETRO_MESH_PAINTER, (retro_mesh_mode)md, &pose, &c, NULL, 0);
        cr_assert(!memcmp(a, b, sizeof a));
        cr_assert_gt(count_not(a, MSKY), 100);
        /* exponential fog moves colours toward the sky with depth */
        fx.fog_exp = 1;
        fx.fog_density = 0.05f;
        c.out = a;
        mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &pose, &c, &fx, 0);
        cr_assert(memcmp(a, b, sizeof a));
        fx.fog_exp = 0;
    }
    mmap_free(&m);
}

Test(mesh_effects, shade_flat_ground)
{
    uint8_t h[S * S];
    uint32_t col[S * S], a[W * H];
    flat(h, col, 70, 0xc8643200u); /* 200, 100, 50 */
    ctx_t c = {W, H, S, 80, MSKY, h, col, a};
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = RETRO_FX_SHADE;
    fx.sun[0] = 0;
    fx.sun[1] = 0;
    fx.sun[2] = 1;
    fx.ambient = 0.2f;
    fx.diffuse = 0.5f; /* light 0.7 on flat ground: 140, 70, 35 */
    for (int k = 0; k < RETRO_MESH_KERNEL_COUNT; k++)
        for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++) {
            if (!mkernel_runs((retro_mesh_kernel)k, (retro_mesh_mode)md))
                continue; /* a mode or ISA the kernel refuses (tests/test_mesh_fast.c) */
            mrender_ok((retro_mesh_kernel)k, (retro_mesh_mode)md, &pose, &c, &fx, 0);
            cr_assert_gt(count_not(a, MSKY), 100);
            for (int i = 0; i < W * H; i++)
                cr_assert(a[i] == MSKY || a[i] == 0x8c462300u, "kernel %d mode %d pixel %d: %08x", k, md, i, a[i]);
        }
    fx.ambient = 1; /* ambient 1, diffuse 0 on a random map: the unshaded frame */
    fx.diffuse = 0;
    mmap_t m = mmap_random(S, 2, 0, 80);
    uint32_t b[W * H];
    ctx_t c2 = {W, H, S, 80, MSKY, m.h, m.c, a};
    for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++) {
        c2.out = a;
        mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &pose, &c2, &fx, 0);
        c2.out = b;
        mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &pose, &c2, NULL, 0);
        cr_assert(!memcmp(a, b, sizeof a), "mode %d", md);
    }
    mmap_free(&m);
}

Test(mesh_effects, water_opaque_and_clear)
{
    mmap_t m = mmap_random(S, 3, 0, 60);
    uint32_t a[W * H], b[W * H];
    ctx_t c = {W, H, S, 80, MSKY, m.h, m.c, a};
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = RETRO_FX_WATER;
    fx.water_level = 70; /* above every height */
    fx.water_color = 0x10204000u;
    for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++) {
        fx.water_alpha0 = 1; /* opaque: every terrain pixel is the water colour */
        fx.water_alpha_per_unit = 0;
        c.out = a;
        mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &pose, &c, &fx, 0);
        int water = 0;
        for (int i = 0; i < W * H; i++) {
            cr_assert(a[i] == MSKY || a[i] == fx.water_color, "mode %d pixel %d: %08x", md, i, a[i]);
            water += a[i] == fx.water_color;
        }
        cr_assert_gt(water, 100);
        fx.water_alpha0 = 0; /* clear water: the terrain under it */
        mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &pose, &c, &fx, 0);
        c.out = b;
        mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &pose, &c, NULL, 0);
        cr_assert(!memcmp(a, b, sizeof a), "mode %d", md);
        fx.water_alpha0 = 0.5f; /* half: every terrain pixel changes; the plane, higher than
                                 * the terrain, also reaches farther, over the sky */
        c.out = a;
        mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &pose, &c, &fx, 0);
        int over_sky = 0;
        for (int i = 0; i < W * H; i++) {
            cr_assert(b[i] == MSKY || a[i] != b[i], "mode %d pixel %d unchanged", md, i);
            over_sky += b[i] == MSKY && a[i] != MSKY;
        }
        cr_assert_gt(over_sky, 0);
    }
    mmap_free(&m);
}

Test(mesh_effects, morph_keyframes)
{
    mmap_t m = mmap_random(S, 4, 0, 80), k = mmap_random(S, 5, 0, 80);
    uint32_t a[W * H], b[W * H];
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = RETRO_FX_MORPH;
    fx.morph_height = k.h;
    for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++)
        for (int t = 0; t <= 1; t++) {
            fx.morph_t = (float)t;
            ctx_t c = {W, H, S, 80, MSKY, m.h, m.c, a};
            mrender_ok(RETRO_MESH_PAINTER, (retro_mesh_mode)md, &pose, &c, &fx, 0);
            ctx_t d = {W, H, S, 80, MSKY, t ? k.h : m.h, m.c, b};
            mrender_ok(RETRO_MESH_PAINTER, (retro_mesh_mode)md, &pose, &d, NULL, 0);
            cr_assert(!memcmp(a, b, sizeof a), "mode %d t %d", md, t);
        }
    fx.morph_t = 0.5f; /* half way: neither keyframe */
    ctx_t c = {W, H, S, 80, MSKY, m.h, m.c, a};
    mrender_ok(RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY32, &pose, &c, &fx, 0);
    ctx_t d = {W, H, S, 80, MSKY, k.h, m.c, b};
    mrender_ok(RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY32, &pose, &d, NULL, 0);
    cr_assert(memcmp(a, b, sizeof a));
    mmap_free(&m);
    mmap_free(&k);
}

/* Flat ground at 50 from 80, D = 100: the far edge at V = 14.4 + pitch. */
Test(mesh_effects, horizon_moves_the_far_edge)
{
    uint8_t h[S * S];
    uint32_t col[S * S], a[W * H];
    flat(h, col, 50, 0x20a04000u);
    enum { W2 = 64, H2 = 48 };
    uint32_t px[W2 * H2];
    ctx_t c = {W2, H2, S, 100, MSKY, h, col, px};
    (void)a;
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = RETRO_FX_HORIZON;
    const int pitches[] = {-10, -3, 0, 7, 20};
    const player_t eye80 = {3.3f, 5.6f, 30, 80, 0, 0, 0};
    for (size_t i = 0; i < 5; i++) {
        fx.pitch = pitches[i];
        int top = (int)floor(14.4 + pitches[i]);
        for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++) {
            mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &eye80, &c, &fx, 0);
            for (int r = 1; r <= H2; r++)
                for (int u = 0; u < W2; u++)
                    cr_assert_eq(px[(H2 - r) * W2 + u], r <= top ? col[0] : MSKY, "pitch %d (%d,%d)", pitches[i], u, r);
        }
    }
}

Test(mesh_effects, texture_and_gouraud)
{
    uint8_t h[S * S];
    uint32_t col[S * S], a[W * H], b[W * H];
    mmap_t m = mmap_random(S, 6, 0, 60);
    memcpy(h, m.h, sizeof h);
    for (int i = 0; i < S * S; i++)
        col[i] = 0x40608000u;
    ctx_t c = {W, H, S, 80, MSKY, h, col, a};
    const unsigned fl[2] = {RETRO_MESH_FX_TEXTURE, RETRO_MESH_FX_GOURAUD};
    for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++)
        for (int f = 0; f < 2; f++) { /* one colour everywhere: the same as nearest sampling */
            c.out = a;
            mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &pose, &c, NULL, fl[f]);
            c.out = b;
            mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &pose, &c, NULL, 0);
            cr_assert(!memcmp(a, b, sizeof a), "mode %d flag %x", md, fl[f]);
        }
    for (int i = 0; i < S * S; i++) /* black and white cells: filtering gives greys between */
        col[i] = ((i + i / S) & 1) ? 0xffffff00u : 0;
    for (int f = 0; f < 2; f++) {
        c.out = a;
        mrender_ok(RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY64, &pose, &c, NULL, fl[f]);
        int grey = 0;
        for (int i = 0; i < W * H; i++)
            grey += a[i] != MSKY && a[i] != 0 && a[i] != 0xffffff00u;
        cr_assert_gt(grey, 50, "flag %x: %d grey pixels", fl[f], grey);
    }
    mmap_free(&m);
}

Test(mesh_effects, wireframe_edges_only)
{
    uint8_t h[S * S];
    uint32_t col[S * S], a[W * H], b[W * H];
    flat(h, col, 40, 0);
    for (int i = 0; i < S * S; i++)
        col[i] = (uint32_t)(i + 1) << 8;
    ctx_t c = {W, H, S, 30, MSKY, h, col, a};
    player_t p = {3.3f, 5.6f, 30, 45, 0, 0, 0};
    for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++) {
        c.out = a;
        mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &p, &c, NULL, RETRO_MESH_FX_WIREFRAME);
        c.out = b;
        mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &p, &c, NULL, 0);
        int wire = count_not(a, MSKY), fill = count_not(b, MSKY);
        cr_assert(wire > 50 && wire < fill, "mode %d: %d wire pixels, %d filled", md, wire, fill);
        /* flat ground has no overlap: every wire pixel is the filled frame's pixel */
        for (int i = 0; i < W * H; i++)
            cr_assert(a[i] == MSKY || a[i] == b[i], "mode %d pixel %d", md, i);
    }
}

/* From below a ceiling at 100 (eye at 90), every triangle is a back face: culled, sky only;
 * with culling off, the ceiling fills the rows above its far edge. */
Test(mesh_effects, cull_back_faces)
{
    uint8_t h[S * S];
    uint32_t col[S * S], a[W * H];
    flat(h, col, 100, 0x80808000u); /* V = 15 + 20 * 10 / z: the far edge at 17.5 */
    ctx_t c = {W, H, S, 80, MSKY, h, col, a};
    for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++) {
        mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &pose, &c, NULL, 0);
        cr_assert_eq(count_not(a, MSKY), 0);
        mrender_ok(RETRO_MESH_PAINTER, (retro_mesh_mode)md, &pose, &c, NULL, RETRO_MESH_FX_NOCULL);
        for (int r = 1; r <= H; r++)
            for (int u = 0; u < W; u++)
                cr_assert_eq(a[(H - r) * W + u] != MSKY, r >= 18, "mode %d (%d,%d)", md, u + 1, r);
    }
}
