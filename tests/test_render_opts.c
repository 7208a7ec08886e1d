/* The public render interface: an opaque context, one options struct said once per call, and
 * refusals that name exactly the mode, effect or ISA level that is missing. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ref_exact.h"
#include "retro.h"
#include "retro_mesh.h"
#include "retro_scene.h"
#include "test_util.h"

#define SKY 0x66a3ff00u
enum { W = 61, H = 43, D = 120, S = 64 };

/* The refusal of kernel name with o: its status, and why in buf. */
static retro_err refusal(const char *name, const retro_render_opts *o, char *why, size_t n)
{
    const retro_kernel *k = retro_kernel_find(name);
    cr_assert(k, "no kernel %s", name);
    why[0] = 0;
    return retro_render_check(k, o, why, n);
}

/* why contains every one of the words (NULL-terminated). */
static void says(const char *why, const char *const *words)
{
    for (; *words; words++)
        cr_expect(strstr(why, *words), "\"%s\" does not say \"%s\"", why, *words);
}

Test(render_opts, the_default_initialiser_and_function_agree)
{
    retro_render_opts a = RETRO_RENDER_OPTS_DEFAULT, b = retro_render_opts_default();
    cr_assert_eq(a.mode, RETRO_MODE_EXACT);
    cr_assert_null(a.fx);
    cr_assert(a.lod == 0.0f && a.threads == 0 && a.no_skip == 0);
    cr_assert(a.mode == b.mode && a.fx == b.fx && a.lod == b.lod && a.threads == b.threads &&
              a.no_skip == b.no_skip);
}

Test(render_opts, free_and_map_changed_take_null)
{
    retro_ctx_free(NULL);
    retro_ctx_map_changed(NULL);
}

/* A kernel that lacks the mode: the refusal names the kernel and the mode. */
Test(render_opts, a_missing_mode_is_named)
{
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    char why[160];
    o.mode = RETRO_MODE_TRUTH;
    cr_assert_eq(refusal("simd-avx2", &o, why, sizeof why), RETRO_EUNSUPPORTED);
    says(why, (const char *const[]){"simd-avx2", "mode truth", NULL});
    o.mode = 99;
    cr_assert_eq(refusal("naive", &o, why, sizeof why), RETRO_EINVAL);
    says(why, (const char *const[]){"voxel", "no mode 99", NULL});
    /* the lod effect turns mode exact into lod, and the check decides on lod: a kernel with
     * mode lod but without mode exact's other effects takes it */
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = RETRO_FX_LOD;
    o.mode = RETRO_MODE_EXACT;
    o.fx = &fx;
    cr_assert_eq(retro_render_mode(retro_kernel_find("naive"), &o), RETRO_MODE_LOD);
    cr_assert_eq(refusal("ybuffer", &o, why, sizeof why), RETRO_OK, "%s", why);
    /* the lod effect on mode truth: effects are defined on exact and lod only */
    o.mode = RETRO_MODE_TRUTH;
    cr_assert_eq(refusal("naive", &o, why, sizeof why), RETRO_EINVAL);
    says(why, (const char *const[]){"truth", "lod", NULL});
}

/* A kernel that lacks an effect, and effects on a mode that does not define them. */
Test(render_opts, a_missing_effect_is_named)
{
    retro_effects fx;
    retro_effects_defaults(&fx);
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.fx = &fx;
    char why[160];
    fx.flags = RETRO_FX_FOG | RETRO_FX_BILINEAR;
    cr_assert_eq(refusal("mesh-zbuffer", &o, why, sizeof why), RETRO_EUNSUPPORTED);
    says(why, (const char *const[]){"mesh-zbuffer", "bilinear", NULL});
    fx.flags = RETRO_FX_TEXTURE;
    cr_assert_eq(refusal("ybuffer", &o, why, sizeof why), RETRO_EUNSUPPORTED);
    says(why, (const char *const[]){"ybuffer", "texture", NULL});
    fx.flags = RETRO_FX_WATER;
    o.mode = RETRO_MESH_BINARY32;
    cr_assert_eq(refusal("mesh-painter", &o, why, sizeof why), RETRO_EUNSUPPORTED);
    says(why, (const char *const[]){"mesh-painter", "water", NULL});
    /* effects are defined on voxel modes exact and lod only: invalid input, whatever the kernel */
    fx.flags = RETRO_FX_FOG;
    o.mode = RETRO_MODE_COURSE;
    cr_assert_eq(refusal("naive", &o, why, sizeof why), RETRO_EINVAL);
    says(why, (const char *const[]){"effects need mode exact or lod", "course", "fog", NULL});
}

/* A CPU without the kernel's ISA: the refusal names the level it has and the one needed. */
Test(render_opts, a_missing_isa_is_named)
{
    int level = retro_cpu_level(retro_cpu_features());
    cr_assert_eq(retro_cpu_limit("none"), RETRO_OK);
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    char why[160];
    retro_err e = refusal("simd-sse2", &o, why, sizeof why);
    retro_cpu_limit(retro_isa_names[level]);
    cr_assert_eq(e, RETRO_EUNSUPPORTED);
    says(why, (const char *const[]){"simd-sse2", "ISA level none", "lacks sse2", NULL});
    cr_assert_eq(refusal("naive", &o, why, sizeof why), RETRO_OK);
    cr_assert_str_eq(why, "ok");
}

Test(render_opts, a_bad_lod_rate_is_named)
{
    static const float bad[] = {-1.0f, 100.5f, INFINITY, NAN};
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = RETRO_MODE_LOD;
    char why[160];
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        o.lod = bad[i];
        cr_assert_eq(refusal("naive", &o, why, sizeof why), RETRO_EINVAL, "lod %g", (double)bad[i]);
        says(why, (const char *const[]){"lod rate", NULL});
    }
}

/* retro_render refuses exactly what retro_render_check refuses, and writes no pixel then. */
Test(render_opts, render_refuses_as_the_check_does)
{
    retro_map m;
    noise_map(&m, S, 7);
    uint32_t *out = malloc(sizeof(uint32_t) * W * H);
    cr_assert(out);
    for (int i = 0; i < W * H; i++)
        out[i] = 0xababababu;
    ctx_t c = {W, H, S, D, SKY, m.height, m.color, out};
    player_t p = {10.5f, 20.25f, 33, 180, 0, 0, 0};
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = RETRO_FX_TEXTURE;
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.fx = &fx;
    const retro_kernel *k = retro_kernel_find("simd-avx2");
    cr_assert_eq(retro_render(rc, k, &o, &p, &c), retro_render_check(k, &o, NULL, 0));
    cr_assert_neq(retro_render(rc, k, &o, &p, &c), RETRO_OK);
    for (int i = 0; i < W * H; i++)
        cr_assert_eq(out[i], 0xababababu, "pixel %d written by a refused render", i);
    retro_ctx_free(rc);
    free(out);
    retro_map_free(&m);
}

/* The defaults (and NULL options) render mode exact without effects: the bytes of the
 * independent implementation of SEMANTICS.md, with the fastest kernel and with naive. A
 * context that rendered effects before renders none once the options stop naming them. */
Test(render_opts, default_options_render_mode_exact)
{
    retro_map m;
    noise_map(&m, S, 11);
    size_t n = (size_t)W * H;
    uint32_t *want = malloc(n * 4), *got = malloc(n * 4);
    cr_assert(want && got);
    player_t p = {40.75f, 3.5f, 250, 160, 0, 0, 0};
    ctx_t c = {W, H, S, D, SKY, m.height, m.color, want};
    ref_exact_render(&p, &c);
    c.out = got;
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    const retro_kernel *best = retro_family_best(&retro_family_voxel, o.mode, o.fx);
    const retro_kernel *ks[] = {best, retro_kernel_find("naive")};
    for (int i = 0; i < 2; i++) {
        memset(got, 0, n * 4);
        cr_assert_eq(retro_render(rc, ks[i], i ? &o : NULL, &p, &c), RETRO_OK);
        cr_assert_eq(memcmp(got, want, n * 4), 0, "%s with %s differs from SEMANTICS.md", ks[i]->name,
                     i ? "RETRO_RENDER_OPTS_DEFAULT" : "NULL options");
    }
    {
        retro_effects fx; /* gone when the block ends: the library must not keep it */
        retro_effects_defaults(&fx);
        fx.flags = RETRO_FX_SHADE | RETRO_FX_FOG;
        retro_render_opts with = RETRO_RENDER_OPTS_DEFAULT;
        with.fx = &fx;
        cr_assert_eq(retro_render(rc, best, &with, &p, &c), RETRO_OK);
        cr_assert_neq(memcmp(got, want, n * 4), 0, "shade and fog changed nothing");
    }
    cr_assert_eq(retro_render(rc, best, &o, &p, &c), RETRO_OK);
    cr_assert_eq(memcmp(got, want, n * 4), 0, "the effects of the previous call stayed in force");
    retro_ctx_free(rc);
    free(want);
    free(got);
    retro_map_free(&m);
}

/* The lod rate is given in one place: the lod effect on mode exact is mode lod at the options'
 * rate, and the rate changes the frame. */
Test(render_opts, the_lod_rate_lives_in_the_options)
{
    retro_map m;
    noise_map(&m, S, 13);
    size_t n = (size_t)W * H;
    uint32_t *a = malloc(n * 4), *b = malloc(n * 4);
    cr_assert(a && b);
    player_t p = {5.5f, 50.5f, 120, 400, 0, 0, 0}; /* above every cell: far samples show */
    ctx_t c = {W, H, S, 400, SKY, m.height, m.color, a};
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    const retro_kernel *naive = retro_kernel_find("naive");
    retro_render_opts lod = RETRO_RENDER_OPTS_DEFAULT;
    lod.mode = RETRO_MODE_LOD;
    lod.lod = 0.25f;
    cr_assert_eq(retro_render(rc, naive, &lod, &p, &c), RETRO_OK);
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = RETRO_FX_LOD;
    retro_render_opts effect = RETRO_RENDER_OPTS_DEFAULT;
    effect.fx = &fx;
    effect.lod = 0.25f;
    c.out = b;
    cr_assert_eq(retro_render(rc, naive, &effect, &p, &c), RETRO_OK);
    cr_assert_eq(memcmp(a, b, n * 4), 0, "the lod effect at rate 0.25 is not mode lod at 0.25");
    effect.lod = 0.0f; /* the default rate, 0.02 */
    cr_assert_eq(retro_render(rc, naive, &effect, &p, &c), RETRO_OK);
    cr_assert_neq(memcmp(a, b, n * 4), 0, "the rate changed nothing");
    retro_ctx_free(rc);
    free(a);
    free(b);
    retro_map_free(&m);
}

/* Which pairs of configurations timed in turn would keep two competing sets of workers
 * (retro_kernels_two_pools): the rule render --versus and the benchmark's pairs refuse by. */
Test(render_opts, two_sets_of_workers_are_named)
{
    static const struct {
        const char *a;
        int ta;
        const char *b;
        int tb, two;
    } cases[] = {
        {"omp", 2, "omp", 2, 0},           /* libgomp's workers belong to the process */
        {"pthreads", 2, "pthreads", 2, 1}, /* each context keeps its own pool */
        {"pthreads", 2, "pthreads", 1, 0}, {"omp", 2, "pthreads", 2, 1}, {"pthreads", 2, "omp", 2, 1},
        {"omp", 2, "pthreads", 1, 0},      {"omp", 1, "pthreads", 2, 0}, {"omp", 2, "ybuffer", 1, 0},
        {"ybuffer", 1, "naive", 1, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const retro_kernel *a = retro_kernel_find(cases[i].a), *b = retro_kernel_find(cases[i].b);
        cr_assert(a && b);
        cr_expect_eq(retro_kernels_two_pools(a, cases[i].ta, b, cases[i].tb), cases[i].two, "%s on %d, %s on %d",
                     cases[i].a, cases[i].ta, cases[i].b, cases[i].tb);
    }
}
