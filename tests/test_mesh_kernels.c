/* The mesh family's kernels and modes against each other, its hard cases and its refusals. */
#include "mesh_util.h"
#include "retro.h"

static void random_scene_fx(uint64_t *seed, retro_effects *fx, const uint8_t *morph)
{
    retro_effects_defaults(fx);
    fx->flags = (unsigned)(mrng(seed) % 128) & (RETRO_FX_FOG | RETRO_FX_SHADE | RETRO_FX_HORIZON | RETRO_FX_MORPH);
    mrandom_fx_params(seed, fx, morph);
}

/* Painting back to front in grid order gives the z-buffer's bytes (docs/MESH.md, "Order"):
 * on seeded random maps, poses, modes and effects, with culling on not one pixel differs.
 * With culling off, a back face folds over its front neighbour along a silhouette edge with
 * depths equal at the edge, and there the z-buffer's rounded depths may pick the face the
 * grid order puts behind: such pixels are counted and must stay rare. */
Test(mesh_kernels, painter_equals_zbuffer)
{
    enum { W = 48, H = 36 };
    uint32_t a[W * H], b[W * H];
    uint64_t seed = 21;
    long compared[2] = {0}, differ[2] = {0};
    for (int n = 0; n < 60; n++) {
        int S = 1 + (int)(mrng(&seed) % 24);
        mmap_t m = mmap_random(S, mrng(&seed), 0, (int)(mrng(&seed) % 256));
        mmap_t m2 = mmap_random(S, mrng(&seed), 0, 255);
        player_t p = {(float)(mrng(&seed) % 10000) / 97.0f, (float)(mrng(&seed) % 10000) / 89.0f,
                      (int)(mrng(&seed) % 720) - 360, (int)(mrng(&seed) % 300), 0, 0, 0};
        ctx_t c = {W, H, S, (int)(mrng(&seed) % 120), MSKY, m.h, m.c, a};
        retro_effects fx;
        random_scene_fx(&seed, &fx, m2.h);
        unsigned mfx = mrandom_mesh_fx(&seed);
        for (int cull = 0; cull < 2; cull++)
            for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++) {
                unsigned f = cull ? mfx & ~(unsigned)RETRO_MESH_FX_NOCULL : mfx | RETRO_MESH_FX_NOCULL;
                c.out = a;
                mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &p, &c, &fx, f);
                c.out = b;
                mrender_ok(RETRO_MESH_PAINTER, (retro_mesh_mode)md, &p, &c, &fx, f);
                for (int i = 0; i < W * H; i++) {
                    differ[cull] += a[i] != b[i];
                    cr_assert(!cull || a[i] == b[i], "pose %d mode %s fx %x mesh fx %x: pixel %d differs", n,
                              retro_mesh_mode_name((retro_mesh_mode)md), fx.flags, f, i);
                }
                compared[cull] += W * H;
            }
        mmap_free(&m);
        mmap_free(&m2);
    }
    cr_log_info("painter vs zbuffer: culling on %ld, off %ld of %ld pixels differ", differ[1], differ[0], compared[0]);
    cr_assert_eq(compared[1], 60L * 3 * W * H);
    cr_assert_leq(differ[0], compared[0] / 10000, "culling off: %ld of %ld pixels differ", differ[0], compared[0]);
}

/* binary32 and int against binary64 (the family's truth): few pixels differ, on cell borders
 * and edges (nearest colour), and integer Gouraud colours by at most one unit. */
Test(mesh_modes, small_differences_from_binary64)
{
    enum { W = 64, H = 48 };
    uint32_t t[W * H], a[W * H];
    uint64_t seed = 5;
    static const unsigned colour[3] = {0, RETRO_MESH_FX_GOURAUD, RETRO_MESH_FX_TEXTURE};
    for (int f = 0; f < 3; f++) {
        long differ[3] = {0}, total = 0;
        int maxd[3] = {0};
        for (int n = 0; n < 25; n++) {
            int S = 1 + (int)(mrng(&seed) % 40);
            mmap_t m = mmap_random(S, mrng(&seed), 0, (int)(mrng(&seed) % 256));
            player_t p = {(float)(mrng(&seed) % 10000) / 97.0f, (float)(mrng(&seed) % 10000) / 89.0f,
                          (int)(mrng(&seed) % 360), (int)(mrng(&seed) % 300), 0, 0, 0};
            ctx_t c = {W, H, S, 2 + (int)(mrng(&seed) % 150), MSKY, m.h, m.c, t};
            mrender_ok(RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY64, &p, &c, NULL, colour[f]);
            c.out = a;
            for (int md = 0; md < 3; md += 2) {
                mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &p, &c, NULL, colour[f]);
                for (int i = 0; i < W * H; i++) {
                    if (a[i] == t[i])
                        continue;
                    differ[md]++;
                    for (int sh = 8; sh <= 24; sh += 8) {
                        int d = abs((int)((a[i] >> sh) & 255) - (int)((t[i] >> sh) & 255));
                        maxd[md] = d > maxd[md] ? d : maxd[md];
                    }
                }
            }
            total += W * H;
            mmap_free(&m);
        }
        cr_log_info("colour %x: binary32 %ld, int %ld (max channel difference %d) of %ld pixels differ from binary64",
                    colour[f], differ[0], differ[2], maxd[2], total);
        cr_assert_lt(differ[0], total / 1000, "binary32: %ld of %ld", differ[0], total);
        cr_assert_lt(differ[2], total / 100, "int: %ld of %ld", differ[2], total);
        if (colour[f] == RETRO_MESH_FX_GOURAUD)
            cr_assert_leq(maxd[2], 1, "int gouraud differs by %d", maxd[2]);
    }
}

static void all_kernels_all_modes(const player_t *p, ctx_t *c, const retro_effects *fx, unsigned mfx, int expect_sky)
{
    size_t n = (size_t)c->scr_width * (size_t)c->scr_height;
    uint32_t *ref = malloc(n * sizeof *ref), *out = c->out;
    for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++) {
        c->out = ref;
        mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, p, c, fx, mfx);
        c->out = out;
        mrender_ok(RETRO_MESH_PAINTER, (retro_mesh_mode)md, p, c, fx, mfx);
        cr_assert(!memcmp(ref, out, n * sizeof *ref), "painter differs (W %d H %d S %d D %d angle %d)",
                  c->scr_width, c->scr_height, c->map_size, c->distance, p->angle);
        if (expect_sky)
            for (size_t i = 0; i < n; i++)
                cr_assert_eq(out[i], c->sky_color);
    }
    free(ref);
}

/* Quadrant angles, tiny and extreme screens, D from 0 to 2^20, S = 1, 2, 3. */
Test(mesh_hard, angles_screens_distances_maps)
{
    static uint32_t out[16384 * 2];
    mmap_t m = mmap_random(3, 99, 0, 255);
    const int angles[] = {0, 90, 180, 270, 360, -90, 45, 135, 225, 315, 719, -721, 2147483647, -2147483647 - 1};
    for (size_t i = 0; i < sizeof angles / sizeof *angles; i++) {
        player_t p = {1.25f, 2.75f, angles[i], 300, 0, 0, 0};
        ctx_t c = {32, 24, 3, 50, MSKY, m.h, m.c, out};
        all_kernels_all_modes(&p, &c, NULL, 0, 0);
    }
    const int screens[][2] = {{1, 1}, {1, 40}, {40, 1}, {2, 2}, {16384, 1}, {1, 16384}, {16384, 2}};
    for (size_t i = 0; i < sizeof screens / sizeof *screens; i++) {
        player_t p = {1.25f, 2.75f, 30, 270, 0, 0, 0};
        ctx_t c = {screens[i][0], screens[i][1], 3, 30, MSKY, m.h, m.c, out};
        all_kernels_all_modes(&p, &c, NULL, 0, 0);
    }
    /* D <= 1: the far plane at or before the near plane, sky only */
    const int skyD[] = {-5, 0, 1};
    for (size_t i = 0; i < 3; i++) {
        player_t p = {1.25f, 2.75f, 30, 100, 0, 0, 0};
        ctx_t c = {20, 15, 3, skyD[i], MSKY, m.h, m.c, out};
        all_kernels_all_modes(&p, &c, NULL, 0, 1);
    }
    /* D up to 2^20: the far plane is capped at RETRO_MESH_MAX_FAR; a one-row screen with the
     * eye above every height culls the far blocks, so this stays quick */
    const int bigD[] = {2, 3, 1000, RETRO_MESH_MAX_FAR, RETRO_MESH_MAX_FAR + 1, 1 << 20};
    for (size_t i = 0; i < sizeof bigD / sizeof *bigD; i++) {
        player_t p = {1.25f, 2.75f, 30, 300, 0, 0, 0};
        ctx_t c = {8, 1, 3, bigD[i], MSKY, m.h, m.c, out};
        all_kernels_all_modes(&p, &c, NULL, 0, 0);
    }
    for (int S = 1; S <= 3; S++) {
        mmap_t s = mmap_random(S, 7u + (unsigned)S, 0, 255);
        player_t p = {-7.5f, 1e6f, 10, 200, 0, 0, 0};
        ctx_t c = {24, 18, S, 60, MSKY, s.h, s.c, out};
        all_kernels_all_modes(&p, &c, NULL, RETRO_MESH_FX_NOCULL, 0);
        mmap_free(&s);
    }
    mmap_free(&m);
}

/* D = 2^20 is capped (far plane min(D, RETRO_MESH_MAX_FAR)) and stays quick when the view
 * allows block culling: one row at V = 1 with the horizon 5 rows up (pitch) sees only terrain
 * with e/z in [-1.25, -1], so nothing beyond z = 121 for an eye 121 above the ground: every
 * D from 200 on gives the same frame, with terrain in it. */
Test(mesh_hard, huge_distance)
{
    enum { W = 8, H = 1 };
    uint32_t a[W * H], b[W * H];
    mmap_t m = mmap_random(4, 3, 0, 120);
    player_t p = {1.5f, 2.5f, 20, 121, 0, 0, 0};
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = RETRO_FX_HORIZON;
    fx.pitch = 5;
    const int Ds[] = {RETRO_MESH_MAX_FAR, RETRO_MESH_MAX_FAR + 1, 1 << 20, RETRO_MAX_DISTANCE};
    ctx_t c = {W, H, 4, 200, MSKY, m.h, m.c, a};
    for (int md = 0; md < RETRO_MESH_MODE_COUNT; md++) {
        c.distance = 200;
        c.out = a;
        mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &p, &c, &fx, 0);
        int terrain = 0;
        for (int i = 0; i < W * H; i++)
            terrain += a[i] != MSKY;
        cr_assert_gt(terrain, 0);
        c.out = b;
        for (size_t i = 0; i < sizeof Ds / sizeof *Ds; i++) {
            c.distance = Ds[i];
            mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)md, &p, &c, &fx, 0);
            cr_assert(!memcmp(a, b, sizeof a), "D %d differs", Ds[i]);
        }
    }
    c.distance = RETRO_MAX_DISTANCE + 1;
    cr_assert_eq(mrender(RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY32, &p, &c, &fx, 0, NULL), RETRO_MESH_EINVAL);
    mmap_free(&m);
}

/* Invalid input is refused with EINVAL, an effect a kernel lacks with EUNSUPPORTED naming it,
 * and nothing is written to out in either case. */
Test(mesh_api, refusals)
{
    uint32_t out[16];
    mmap_t m = mmap_random(4, 1, 0, 255);
    player_t p = {1, 1, 0, 100, 0, 0, 0};
    ctx_t c = {4, 4, 4, 10, MSKY, m.h, m.c, out};
    retro_mesh_ctx *mc = retro_mesh_ctx_new();
    retro_effects fx;
    retro_effects_defaults(&fx);
    struct {
        ctx_t c;
        player_t p;
        unsigned flags, mfx;
        retro_mesh_kernel k;
        retro_mesh_err want;
        const char *word;
    } cases[] = {
        {{0, 4, 4, 10, MSKY, m.h, m.c, out}, p, 0, 0, RETRO_MESH_ZBUFFER, RETRO_MESH_EINVAL, "screen"},
        {{4, 4, 0, 10, MSKY, m.h, m.c, out}, p, 0, 0, RETRO_MESH_ZBUFFER, RETRO_MESH_EINVAL, "map"},
        {{4, 4, 4, 10, MSKY, NULL, m.c, out}, p, 0, 0, RETRO_MESH_ZBUFFER, RETRO_MESH_EINVAL, "map"},
        {c, {NAN, 1, 0, 100, 0, 0, 0}, 0, 0, RETRO_MESH_ZBUFFER, RETRO_MESH_EINVAL, "position"},
        {c, p, RETRO_FX_WATER, 0, RETRO_MESH_PAINTER, RETRO_MESH_EUNSUPPORTED, "water"},
        {c, p, RETRO_FX_BILINEAR, 0, RETRO_MESH_ZBUFFER, RETRO_MESH_EUNSUPPORTED, "bilinear"},
        {c, p, RETRO_FX_LOD, 0, RETRO_MESH_PAINTER, RETRO_MESH_EUNSUPPORTED, "lod"},
        {c, p, 0, RETRO_MESH_FX_TEXTURE | RETRO_MESH_FX_GOURAUD, RETRO_MESH_ZBUFFER, RETRO_MESH_EINVAL, "exclusive"},
        {c, p, 0, 1u << 20, RETRO_MESH_ZBUFFER, RETRO_MESH_EINVAL, "mesh effect"},
        {c, p, RETRO_FX_MORPH, 0, RETRO_MESH_ZBUFFER, RETRO_MESH_EINVAL, "morph"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        for (int k = 0; k < 16; k++)
            out[k] = 0x12345600u;
        fx.flags = cases[i].flags;
        retro_mesh_opts o = {cases[i].mfx, 0};
        retro_mesh_err e = retro_mesh_render(mc, cases[i].k, RETRO_MESH_BINARY32, &cases[i].p, &cases[i].c, &fx, &o, NULL);
        cr_assert_eq(e, cases[i].want, "case %zu: %d (%s)", i, e, retro_mesh_error(mc));
        cr_assert(strstr(retro_mesh_error(mc), cases[i].word), "case %zu: message '%s' lacks '%s'", i,
                  retro_mesh_error(mc), cases[i].word);
        for (int k = 0; k < 16; k++)
            cr_assert_eq(out[k], 0x12345600u, "case %zu wrote out", i);
    }
    cr_assert_eq(retro_mesh_render(mc, RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY32, &p, &c, NULL, NULL, NULL), 0);
    cr_assert_str_empty(retro_mesh_error(mc));
    retro_mesh_ctx_free(mc);
    mmap_free(&m);
}

/* The counts: submitted = culled + clipped out + those drawn; fragments >= written. */
Test(mesh_api, stats_add_up)
{
    enum { W = 40, H = 30 };
    uint32_t out[W * H];
    mmap_t m = mmap_random(16, 5, 0, 200);
    player_t p = {3, 4, 60, 150, 0, 0, 0};
    ctx_t c = {W, H, 16, 80, MSKY, m.h, m.c, out};
    retro_mesh_stats st;
    cr_assert_eq(mrender(RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY32, &p, &c, NULL, 0, &st), 0);
    cr_assert_gt(st.submitted, 1000);
    cr_assert_gt(st.culled, 0);
    cr_assert_gt(st.clipped_out, 0);
    cr_assert_leq(st.culled + st.clipped_out, st.submitted);
    cr_assert_geq(st.rasterized, 1);
    cr_assert_geq(st.fragments, st.written);
    cr_assert_gt(st.written, 0);
    long terrain = 0;
    for (int i = 0; i < W * H; i++)
        terrain += out[i] != MSKY;
    cr_assert_leq(terrain, (long)st.written);
    mmap_free(&m);
}
