/* The mesh family in the kernel table: its descriptor and rows, refusals that name what is
 * missing, the scene's mesh-only effects, and retro_render with a mesh kernel giving the very
 * bytes of the module's own entry point (cull from the scene, culling off without it). */
#include <stdio.h>
#include <unistd.h>

#include "mesh_util.h"
#include "retro.h"
#include "retro_scene.h"

Test(mesh_family, descriptor_and_rows)
{
    const retro_family *fam = retro_family_find("mesh");
    cr_assert(fam == &retro_family_mesh);
    cr_assert_str_eq(retro_family_reference(fam)->name, "mesh-zbuffer");
    cr_assert_eq(fam->mode_count, 3);
    int m = -1;
    cr_assert_eq(retro_family_mode_parse(fam, "binary64", &m), 0);
    cr_assert_eq(m, RETRO_MESH_BINARY64);
    cr_assert_eq(retro_family_mode_parse(fam, "exact", &m), -1);
    cr_assert_str_eq(retro_family_mode_name(fam, RETRO_MESH_INT), "int");
    const retro_kernel *z = retro_kernel_find("mesh-zbuffer"), *p = retro_kernel_find("mesh-painter");
    cr_assert(z && p && z->family == fam && p->family == fam);
    cr_assert_eq(z->fx & RETRO_FX_VOXEL & ~RETRO_FX_MESH, 0u, "no voxel-only effect");
    cr_assert_eq(z->fx & RETRO_FX_MESH_ONLY, (unsigned)RETRO_FX_MESH_ONLY);
    cr_assert_str_eq(retro_fx_name(RETRO_FX_TEXTURE), "texture");
    cr_assert_str_eq(retro_fx_name(RETRO_FX_CULL), "cull");
    /* the voxel family's best kernel is never a mesh kernel */
    cr_assert(retro_kernel_best(RETRO_MODE_EXACT)->family == &retro_family_voxel);
}

static void refused(const char *kernel, int mode, unsigned flags, const char *want)
{
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = flags;
    char why[128];
    cr_assert_eq(retro_kernel_check(retro_kernel_find(kernel), mode, &fx, why, sizeof why), RETRO_EUNSUPPORTED,
                 "%s accepted", kernel);
    cr_assert_str_eq(why, want);
}

Test(mesh_family, refusals_name_what_is_missing)
{
    refused("naive", RETRO_MODE_EXACT, RETRO_FX_TEXTURE, "kernel naive does not render texture");
    refused("ybuffer", RETRO_MODE_EXACT, RETRO_FX_CULL | RETRO_FX_FOG, "kernel ybuffer does not render cull");
    refused("mesh-zbuffer", RETRO_MESH_BINARY32, RETRO_FX_BILINEAR, "kernel mesh-zbuffer does not render bilinear");
    refused("mesh-painter", RETRO_MESH_INT, RETRO_FX_WATER, "kernel mesh-painter does not render water");
    char why[128];
    cr_assert_eq(retro_kernel_check(retro_kernel_find("mesh-zbuffer"), 3, NULL, why, sizeof why), RETRO_EINVAL);
    cr_assert_str_eq(why, "mesh has no mode 3");
}

/* Through the table and through the module: the same bytes, for each kernel, mode and cull. */
Test(mesh_family, table_render_is_the_module_render)
{
    enum { W = 48, H = 36 };
    mmap_t m = mmap_random(9, 7, 0, 60);
    uint32_t a[W * H], b[W * H];
    ctx_t c = {W, H, m.S, 40, MSKY, m.h, m.c, a};
    player_t p = {2.25f, 3.5f, 35, 80, 0, 0, 0};
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    retro_effects fx;
    retro_render_opts ro = RETRO_RENDER_OPTS_DEFAULT;
    ro.fx = &fx;
    for (int k = 0; k < 2; k++)
        for (int mode = 0; mode < RETRO_MESH_MODE_COUNT; mode++)
            for (int cull = 0; cull < 2; cull++) {
                retro_effects_defaults(&fx);
                fx.flags = RETRO_FX_GOURAUD | RETRO_FX_FOG | (cull ? RETRO_FX_CULL : 0);
                ro.mode = mode;
                c.out = a;
                const retro_kernel *kr = retro_kernel_find(k ? "mesh-painter" : "mesh-zbuffer");
                cr_assert_eq(retro_render(rc, kr, &ro, &p, &c), RETRO_OK, "%s", retro_mesh_last_error(rc));
                const retro_mesh_stats *st = retro_mesh_last_stats(rc);
                cr_assert(st && st->submitted > 0 && st->fragments > 0);
                cr_assert_eq(cull ? st->culled > 0 : st->culled == 0, 1, "culled %llu", (unsigned long long)st->culled);
                c.out = b;
                retro_effects scene = fx;
                scene.flags = RETRO_FX_FOG;
                retro_mesh_opts o = {RETRO_MESH_FX_GOURAUD | (cull ? 0u : RETRO_MESH_FX_NOCULL), 0};
                retro_mesh_ctx *mc = retro_mesh_ctx_new();
                cr_assert_eq(retro_mesh_render(mc, (retro_mesh_kernel)k, (retro_mesh_mode)mode, &p, &c, &scene, &o, NULL),
                             RETRO_MESH_OK);
                retro_mesh_ctx_free(mc);
                cr_assert_eq(memcmp(a, b, sizeof a), 0, "%s mode %d cull %d differs", kr->name, mode, cull);
            }
    retro_ctx_free(rc);
    mmap_free(&m);
}

Test(mesh_family, invalid_requests_say_why)
{
    enum { W = 8, H = 8 };
    mmap_t m = mmap_random(4, 3, 0, 9);
    uint32_t out[W * H];
    for (int i = 0; i < W * H; i++)
        out[i] = 0x12345678u;
    ctx_t c = {W, H, m.S, 20, MSKY, m.h, m.c, out};
    player_t p = {1, 1, 0, 50, 0, 0, 0};
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = RETRO_FX_TEXTURE | RETRO_FX_GOURAUD;
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = RETRO_MESH_BINARY32;
    o.fx = &fx;
    cr_assert_eq(retro_render(rc, retro_kernel_find("mesh-zbuffer"), &o, &p, &c), RETRO_EINVAL);
    cr_assert(strstr(retro_mesh_last_error(rc), "exclusive"), "%s", retro_mesh_last_error(rc));
    for (int i = 0; i < W * H; i++)
        cr_assert_eq(out[i], 0x12345678u, "written on error");
    o.mode = RETRO_MESH_INT;
    o.fx = NULL;
    c.scr_width = 0;
    cr_assert_eq(retro_render(rc, retro_kernel_find("mesh-painter"), &o, &p, &c), RETRO_EINVAL);
    cr_assert(*retro_mesh_last_error(rc));
    retro_ctx_free(rc);
    mmap_free(&m);
}

Test(mesh_family, scene_sections_turn_mesh_effects_on)
{
    char path[] = "/tmp/retro-mesh-family-XXXXXX";
    int fd = mkstemp(path);
    cr_assert(fd >= 0);
    FILE *f = fdopen(fd, "w");
    fputs("[scene]\nmap = x\n[texture]\n[wireframe]\n[cull]\nenabled = yes\n[gouraud]\nenabled = no\n", f);
    fclose(f);
    retro_scene s;
    char err[256];
    int r = retro_scene_load(path, &s, err, sizeof err);
    unlink(path);
    cr_assert_eq(r, 0, "%s", err);
    cr_assert_eq(s.fx.flags, (unsigned)(RETRO_FX_TEXTURE | RETRO_FX_WIREFRAME | RETRO_FX_CULL));
}

/* The checker covers the family: mesh-painter at every ISA level against mesh-zbuffer on seeded
 * random small maps and poses, every mode, random effects; with `cull` byte-identical, without
 * it within the documented bound (measured and logged). */
#include "check.h"

typedef struct {
    size_t ran, differ, documented_frames;
} tally;

static void count(void *user, const retro_check_variant *v, const retro_check_result *r)
{
    (void)v;
    tally *t = user;
    t->ran += (size_t)r->ran;
    t->differ += r->differ;
    t->documented_frames += r->differ > 0 && r->differ <= r->documented;
}

Test(mesh_family, checker_on_random_poses)
{
    retro_check chk;
    cr_assert_eq(retro_check_init(&chk, &retro_family_mesh, NULL, 2), 0);
    cr_assert(chk.n >= 1, "no mesh variant besides the reference");
    for (int i = 0; i < chk.n; i++)
        cr_assert(chk.v[i].kernel->family == &retro_family_mesh);
    static const int sizes[] = {1, 2, 3, 7, 16, 33};
    static const unsigned colour[] = {0, RETRO_FX_TEXTURE, RETRO_FX_GOURAUD};
    uint64_t seed = 15;
    tally t = {0, 0, 0};
    int bad = 0;
    size_t pixels = 0;
    for (int n = 0; n < 18; n++) {
        int S = sizes[n % 6];
        mmap_t m = mmap_random(S, seed + (uint64_t)n, 0, 120);
        uint8_t *h1 = malloc((size_t)S * (size_t)S);
        for (int k = 0; k < S * S; k++)
            h1[k] = (uint8_t)(255 - m.h[k]);
        int W = 8 + (int)(mrng(&seed) % 56), H = 8 + (int)(mrng(&seed) % 40);
        ctx_t c = {W, H, S, 10 + (int)(mrng(&seed) % 70), MSKY, m.h, m.c, NULL};
        player_t p = {(float)(mrng(&seed) % 4000) / 37.0f, (float)(mrng(&seed) % 4000) / 41.0f,
                      (int)(mrng(&seed) % 720) - 360, 60 + (int)(mrng(&seed) % 150), 0, 0, 0};
        retro_effects fx;
        retro_effects_defaults(&fx);
        fx.flags = colour[mrng(&seed) % 3] | (n % 2 ? RETRO_FX_CULL : 0) | (mrng(&seed) % 2 ? RETRO_FX_FOG : 0) |
                   (mrng(&seed) % 2 ? RETRO_FX_SHADE : 0) | (mrng(&seed) % 3 ? 0 : RETRO_FX_WIREFRAME) |
                   (mrng(&seed) % 3 ? 0 : RETRO_FX_MORPH) | (mrng(&seed) % 3 ? 0 : RETRO_FX_HORIZON);
        fx.morph_height = h1;
        fx.morph_t = 0.6f;
        fx.pitch = -20;
        for (int mode = 0; mode < RETRO_MESH_MODE_COUNT; mode++) {
            int before = bad;
            cr_assert_eq(retro_check_frame(&chk, mode, &fx, &p, &c, count, &t, &bad), RETRO_OK);
            cr_assert_eq(bad, before, "case %d mode %d: a variant differs beyond the documented bound", n, mode);
            pixels += (size_t)W * (size_t)H * (size_t)chk.n;
        }
        free(h1);
        mmap_free(&m);
    }
    cr_assert(t.ran > 0);
    cr_log_info("mesh-painter without cull: %zu px differ in %zu (%zu frames)", t.differ, pixels,
                t.documented_frames);
    retro_check_free(&chk);
}

Test(mesh_family, documented_difference_only_without_cull)
{
    const retro_family *fam = &retro_family_mesh;
    const retro_kernel *painter = retro_kernel_find("mesh-painter"), *z = retro_kernel_find("mesh-zbuffer");
    retro_effects fx;
    retro_effects_defaults(&fx);
    cr_assert_eq(fam->documented_difference(painter, 0, NULL, 311040), 32u);
    cr_assert_eq(fam->documented_difference(painter, 2, &fx, 1), 1u);
    fx.flags = RETRO_FX_CULL;
    cr_assert_eq(fam->documented_difference(painter, 0, &fx, 311040), 0u);
    cr_assert_eq(fam->documented_difference(z, 0, NULL, 311040), 0u);
    cr_assert_null(retro_family_voxel.documented_difference);
}
