/* The fast mesh kernels (mesh-avx2, mesh-avx512, mesh-omp) against mesh-zbuffer's bytes and
 * statistics: seeded random maps, poses and effect sets, every ISA level this CPU has, thread
 * counts 1, 2 and 3, hard cases, the course valley; and their refusals. */
#include <stdio.h>

#include "mesh_util.h"
#include "retro.h"
#include "retro_maps.h"
#include "mesh/mesh_internal.h"

static const int thread_counts[3] = {1, 2, 3};

static void random_fx(uint64_t *seed, retro_effects *fx, const uint8_t *morph, unsigned *mfx)
{
    retro_effects_defaults(fx);
    fx->flags = (unsigned)mrng(seed) &
                (RETRO_FX_FOG | RETRO_FX_SHADE | RETRO_FX_HORIZON | RETRO_FX_MORPH | RETRO_FX_WATER);
    if (mrng(seed) % 3 == 0) /* a third of the poses in the fast raster's own colour path */
        fx->flags &= ~(unsigned)(RETRO_FX_SHADE | RETRO_FX_WATER);
    mrandom_fx_params(seed, fx, morph);
    fx->water_level = (int)(mrng(seed) % 200);
    fx->water_color = 0x2040a000u;
    fx->water_alpha0 = 0.3f;
    fx->water_alpha_per_unit = 0.05f;
    *mfx = mrandom_mesh_fx(seed);
    if (mrng(seed) % 3 == 0)
        *mfx &= RETRO_MESH_FX_WIREFRAME | RETRO_MESH_FX_NOCULL;
}

/* Renders with kernel k (threads for mesh-omp) and requires mesh-zbuffer's bytes and counts. */
static void same_as_zbuffer(retro_mesh_ctx *mc, retro_mesh_kernel k, int threads, const player_t *p, ctx_t *c,
                            const retro_effects *fx, unsigned mfx, const uint32_t *ref, const retro_mesh_stats *rst,
                            const char *what)
{
    size_t n = (size_t)c->scr_width * (size_t)c->scr_height;
    uint32_t *out = malloc(n * sizeof *out);
    cr_assert(out);
    uint32_t *keep = c->out;
    c->out = out;
    retro_mesh_opts o = {mfx, threads};
    retro_mesh_stats st;
    retro_mesh_err e = retro_mesh_render(mc, k, RETRO_MESH_BINARY32, p, c, fx, &o, &st);
    cr_assert_eq(e, RETRO_MESH_OK, "%s: mesh-%s failed: %s", what, retro_mesh_kernel_name(k), retro_mesh_error(mc));
    for (size_t i = 0; i < n; i++)
        cr_assert_eq(out[i], ref[i], "%s: mesh-%s (%d threads) fx %x mesh fx %x: pixel %zu is %08x, not %08x", what,
                     retro_mesh_kernel_name(k), threads, fx ? fx->flags : 0u, mfx, i, out[i], ref[i]);
    /* mesh-omp too: each block's geometry is counted once, by the thread that drew it. Its
     * later runs also store what an earlier run's terrain hides (mesh_omp.c), so written is at
     * least mesh-zbuffer's, and the same at one thread. */
    retro_mesh_stats cmp = st;
    if (k == RETRO_MESH_OMP && threads != 1) {
        cr_assert_geq(st.written, rst->written, "%s: mesh-omp (%d threads) wrote %llu fragments, fewer than %llu",
                      what, threads, (unsigned long long)st.written, (unsigned long long)rst->written);
        cmp.written = rst->written;
    }
    cr_assert(!memcmp(&cmp, rst, sizeof cmp),
              "%s: mesh-%s (%d threads) stats differ (submitted %llu vs %llu, culled %llu vs %llu, clipped out %llu "
              "vs %llu, rasterized %llu vs %llu, fragments %llu vs %llu, written %llu vs %llu)",
              what, retro_mesh_kernel_name(k), threads, (unsigned long long)st.submitted,
              (unsigned long long)rst->submitted, (unsigned long long)st.culled, (unsigned long long)rst->culled,
              (unsigned long long)st.clipped_out, (unsigned long long)rst->clipped_out,
              (unsigned long long)st.rasterized, (unsigned long long)rst->rasterized,
              (unsigned long long)st.fragments, (unsigned long long)rst->fragments, (unsigned long long)st.written,
              (unsigned long long)rst->written);
    c->out = keep;
    free(out);
}

/* Every fast kernel this CPU (at its current level) runs, and mesh-omp at 1, 2, 3 threads. */
static void all_fast(const player_t *p, ctx_t *c, const retro_effects *fx, unsigned mfx, const char *what)
{
    size_t n = (size_t)c->scr_width * (size_t)c->scr_height;
    uint32_t *ref = malloc(n * sizeof *ref);
    cr_assert(ref);
    uint32_t *keep = c->out;
    c->out = ref;
    retro_mesh_ctx *mc = retro_mesh_ctx_new();
    cr_assert(mc);
    retro_mesh_opts o = {mfx, 0};
    retro_mesh_stats rst;
    cr_assert_eq(retro_mesh_render(mc, RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY32, p, c, fx, &o, &rst), RETRO_MESH_OK,
                 "%s: %s", what, retro_mesh_error(mc));
    c->out = keep;
    unsigned cpu = retro_cpu_features();
    for (int k = RETRO_MESH_AVX2; k < RETRO_MESH_KERNEL_COUNT; k++) {
        if (retro_mesh_kernel_isa((retro_mesh_kernel)k) & ~cpu)
            continue;
        int nt = k == RETRO_MESH_OMP ? 3 : 1;
        for (int t = 0; t < nt; t++) /* one context through every kernel and thread count */
            for (int again = 0; again < (k == RETRO_MESH_OMP ? 2 : 1); again++) /* bands rebalanced */
                same_as_zbuffer(mc, (retro_mesh_kernel)k, thread_counts[t], p, c, fx, mfx, ref, &rst, what);
    }
    retro_mesh_ctx_free(mc);
    free(ref);
}

Test(mesh_fast, equals_zbuffer_on_random_poses)
{
    uint64_t seed = 1717;
    uint32_t buf[1];
    for (int n = 0; n < 48; n++) {
        int S = 1 + (int)(mrng(&seed) % 40);
        mmap_t m = mmap_random(S, mrng(&seed), 0, (int)(mrng(&seed) % 256));
        mmap_t m2 = mmap_random(S, mrng(&seed), 0, 255);
        player_t p = {(float)(mrng(&seed) % 10000) / 97.0f, (float)(mrng(&seed) % 10000) / 89.0f,
                      (int)(mrng(&seed) % 720) - 360, (int)(mrng(&seed) % 300), 0, 0, 0};
        ctx_t c = {1 + (int)(mrng(&seed) % 96), 1 + (int)(mrng(&seed) % 72), S, (int)(mrng(&seed) % 160), MSKY,
                   m.h, m.c, buf};
        retro_effects fx;
        unsigned mfx;
        random_fx(&seed, &fx, m2.h, &mfx);
        char what[64];
        snprintf(what, sizeof what, "pose %d", n);
        all_fast(&p, &c, &fx, mfx, what);
        mmap_free(&m);
        mmap_free(&m2);
    }
}

/* mesh-avx2 (and mesh-omp on it) with the CPU level lowered to AVX2; below it both are refused
 * with a message naming the ISA. */
Test(mesh_fast, isa_levels)
{
    unsigned cpu = retro_cpu_features();
    if (!(cpu & RETRO_CPU_AVX2)) {
        cr_log_info("this CPU lacks AVX2: only the refusal is tested"); /* a warning would fail the run */
    } else {
        cr_assert_eq(retro_cpu_limit("avx2"), RETRO_OK);
        uint64_t seed = 5;
        uint32_t buf[1];
        for (int n = 0; n < 12; n++) {
            int S = 1 + (int)(mrng(&seed) % 33);
            mmap_t m = mmap_random(S, mrng(&seed), 0, 255);
            player_t p = {(float)(mrng(&seed) % 5000) / 31.0f, (float)(mrng(&seed) % 5000) / 37.0f,
                          (int)(mrng(&seed) % 360), 20 + (int)(mrng(&seed) % 250), 0, 0, 0};
            ctx_t c = {80, 60, S, 100, MSKY, m.h, m.c, buf};
            retro_effects fx;
            unsigned mfx;
            random_fx(&seed, &fx, m.h, &mfx);
            all_fast(&p, &c, &fx, mfx, "level avx2");
            mmap_free(&m);
        }
        uint32_t out[4];
        mmap_t m = mmap_random(4, 1, 0, 255);
        player_t p = {1, 1, 0, 100, 0, 0, 0};
        ctx_t c = {2, 2, 4, 50, MSKY, m.h, m.c, out};
        retro_mesh_ctx *mc = retro_mesh_ctx_new();
        cr_assert_eq(retro_mesh_render(mc, RETRO_MESH_AVX512, RETRO_MESH_BINARY32, &p, &c, NULL, NULL, NULL),
                     RETRO_MESH_EUNSUPPORTED);
        cr_assert(strstr(retro_mesh_error(mc), "AVX-512"), "message: %s", retro_mesh_error(mc));
        cr_assert_eq(retro_cpu_limit("sse2"), RETRO_OK);
        for (int k = RETRO_MESH_AVX2; k < RETRO_MESH_KERNEL_COUNT; k++) {
            cr_assert_eq(retro_mesh_render(mc, (retro_mesh_kernel)k, RETRO_MESH_BINARY32, &p, &c, NULL, NULL, NULL),
                         RETRO_MESH_EUNSUPPORTED);
            cr_assert(strstr(retro_mesh_error(mc), k == RETRO_MESH_AVX512 ? "AVX-512" : "AVX2"), "message: %s",
                      retro_mesh_error(mc));
        }
        retro_mesh_ctx_free(mc);
        mmap_free(&m);
    }
    cr_assert_eq(retro_cpu_limit(NULL), RETRO_OK);
}

Test(mesh_fast, refusals_and_queries)
{
    for (int k = RETRO_MESH_AVX2; k < RETRO_MESH_KERNEL_COUNT; k++) {
        cr_assert(retro_mesh_supports_mode((retro_mesh_kernel)k, RETRO_MESH_BINARY32));
        cr_assert(!retro_mesh_supports_mode((retro_mesh_kernel)k, RETRO_MESH_BINARY64));
        cr_assert(!retro_mesh_supports_mode((retro_mesh_kernel)k, RETRO_MESH_INT));
        cr_assert_eq(retro_mesh_supported_fx((retro_mesh_kernel)k, RETRO_MESH_BINARY32),
                     retro_mesh_supported_fx(RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY32));
    }
    cr_assert(retro_mesh_supports_mode(RETRO_MESH_PAINTER, RETRO_MESH_INT));
    cr_assert_eq(retro_mesh_kernel_isa(RETRO_MESH_ZBUFFER), 0u);
    cr_assert_eq(retro_mesh_kernel_isa(RETRO_MESH_AVX2), (unsigned)RETRO_CPU_AVX2);
    cr_assert_eq(retro_mesh_kernel_isa(RETRO_MESH_AVX512), (unsigned)RETRO_CPU_AVX512);
    cr_assert_str_eq(retro_mesh_kernel_name(RETRO_MESH_AVX2), "avx2");
    cr_assert_str_eq(retro_mesh_kernel_name(RETRO_MESH_AVX512), "avx512");
    cr_assert_str_eq(retro_mesh_kernel_name(RETRO_MESH_OMP), "omp");
    uint32_t out[16];
    mmap_t m = mmap_random(4, 1, 0, 255);
    player_t p = {1, 1, 0, 100, 0, 0, 0};
    ctx_t c = {4, 4, 4, 50, MSKY, m.h, m.c, out};
    retro_mesh_ctx *mc = retro_mesh_ctx_new();
    cr_assert_eq(retro_mesh_render(mc, RETRO_MESH_AVX2, RETRO_MESH_BINARY64, &p, &c, NULL, NULL, NULL),
                 RETRO_MESH_EUNSUPPORTED);
    cr_assert_str_eq(retro_mesh_error(mc), "kernel mesh-avx2 does not render mode binary64");
    cr_assert_eq(retro_mesh_render(mc, RETRO_MESH_OMP, RETRO_MESH_INT, &p, &c, NULL, NULL, NULL),
                 RETRO_MESH_EUNSUPPORTED);
    cr_assert_str_eq(retro_mesh_error(mc), "kernel mesh-omp does not render mode int");
    retro_mesh_opts o = {0, -1};
    cr_assert_eq(retro_mesh_render(mc, RETRO_MESH_OMP, RETRO_MESH_BINARY32, &p, &c, NULL, &o, NULL), RETRO_MESH_EINVAL);
    o.threads = 65;
    cr_assert_eq(retro_mesh_render(mc, RETRO_MESH_OMP, RETRO_MESH_BINARY32, &p, &c, NULL, &o, NULL), RETRO_MESH_EINVAL);
    retro_mesh_ctx_free(mc);
    mmap_free(&m);
}

/* Tiny and long screens, distances at their edges, maps of 1, 2 and 3 cells, angles on and
 * between the axes, the eye below and far above the terrain. */
Test(mesh_fast, hard_cases)
{
    static const int screens[][2] = {{1, 1}, {2, 1}, {1, 2}, {3, 200}, {300, 2}, {640, 8}, {17, 480}};
    static const int dists[] = {0, 1, 2, 3, 50, 4096, 1 << 20};
    static const int angles[] = {0, 45, 90, 135, 180, 270, 359, -90};
    uint64_t seed = 99;
    uint32_t buf[1];
    int cases = 0;
    for (int S = 1; S <= 3; S++) {
        mmap_t m = mmap_random(S, mrng(&seed), 0, 255);
        for (int s = 0; s < (int)(sizeof screens / sizeof *screens); s++)
            for (int d = 0; d < (int)(sizeof dists / sizeof *dists); d++) {
                if (dists[d] >= 4096 && (screens[s][0] > 300 || screens[s][1] > 200))
                    continue; /* far planes at the cap are costly on wide screens: covered below */
                player_t p = {(float)(mrng(&seed) % 300) / 100.0f, (float)(mrng(&seed) % 300) / 100.0f,
                              angles[(s + d) % 8], (int)(mrng(&seed) % 2 ? 300 : 5), 0, 0, 0};
                ctx_t c = {screens[s][0], screens[s][1], S, dists[d], MSKY, m.h, m.c, buf};
                char what[96];
                snprintf(what, sizeof what, "S %d, %dx%d, D %d, angle %d, height %d", S, c.scr_width, c.scr_height,
                         c.distance, p.angle, p.height);
                all_fast(&p, &c, NULL, 0, what);
                cases++;
            }
        mmap_free(&m);
    }
    cr_log_info("mesh_fast hard cases: %d", cases);
}

/* The course's valley pose at 640x480, D 800 (the benchmark's workload, mostly triangles smaller
 * than a pixel: the tiny-triangle lanes), plain, with fog, and without culling. */
Test(mesh_fast, course_valley)
{
    uint8_t *h = NULL;
    uint32_t *col = NULL;
    int w, hh, w2, h2;
    char err[200];
    if (retro_pgm_read("../shared/course/valley.pgm", &h, &w, &hh, err, sizeof err) ||
        retro_rgb_read("../shared/course/valley.ppm", &col, &w2, &h2, err, sizeof err)) {
        free(h);
        cr_skip_test("course data absent (../shared/course/valley.*): %s", err);
    }
    uint32_t buf[1];
    player_t p = {997.808716f, 559.177063f, 0, 230, 0, 0, 0};
    ctx_t c = {640, 480, w, 800, MSKY, h, col, buf};
    all_fast(&p, &c, NULL, 0, "valley");
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = RETRO_FX_FOG;
    fx.fog_start = 100;
    fx.fog_end = 700;
    all_fast(&p, &c, &fx, 0, "valley fog");
    /* both faces: the triangles snapping turns over take the raster of larger ones */
    all_fast(&p, &c, NULL, RETRO_MESH_FX_NOCULL, "valley nocull");
    free(h);
    free(col);
}

/* The view direction is rounded to binary32 in mode binary32 (docs/MESH.md, "The camera").
 * gcc 12's SLP vectorizer dropped that rounding at -O2 (the Makefile builds the mesh objects
 * without it): then mesh-zbuffer's image depended on the compiler, and the fast kernels, which
 * compute in binary32 lanes, counted other triangles than it at angle 359. */
Test(mesh_fast, binary32_direction_is_rounded)
{
    uint8_t h[4] = {10, 200, 30, 90};
    uint32_t col[4] = {0}, out[1];
    retro_mesh_ctx *mc = retro_mesh_ctx_new();
    cr_assert(mc);
    for (int a = -400; a <= 400; a += 7) {
        player_t p = {0.5f, 1.5f, a, 5, 0, 0, 0};
        ctx_t c = {1, 1, 2, 100, MSKY, h, col, out};
        cr_assert_eq(mesh_frame_setup(mc, RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY32, &p, &c, NULL, 0), RETRO_MESH_OK);
        cr_assert_eq(mc->f.cs, (double)(float)mc->f.cs, "angle %d: cos not rounded to binary32", a);
        cr_assert_eq(mc->f.sn, (double)(float)mc->f.sn, "angle %d: sin not rounded to binary32", a);
        cr_assert_eq(mc->f.x0, (double)(float)mc->f.x0);
    }
    retro_mesh_ctx_free(mc);
}
