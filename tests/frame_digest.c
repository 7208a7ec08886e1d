/* frame_digest: one line per rendered frame (case, kernel, ISA level, threads, mode, effects,
 * status, FNV-1a 64 of the bytes) over the verify cases and seeded random poses, so two builds
 * of the library can be compared byte for byte (scripts/compare-frames.sh diffs the outputs).
 * Built by that script against each tree's own headers and library: against a tree from
 * before retro_render_opts (no RETRO_RENDER_OPTS_DEFAULT) it uses the older API.
 * usage: frame_digest MAPS_DIR SHARED_DIR [POSES [naive]]: with "naive", naive alone. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "retro.h"
#include "retro_maps.h"
#include "retro_scene.h"
#include "verify_cases.h"

static uint64_t fnv(const uint32_t *p, size_t n)
{
    uint64_t h = 1469598103934665603ull;
    const unsigned char *b = (const unsigned char *)p;
    for (size_t i = 0; i < n * 4; i++)
        h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

/* Renders with the kernel named k at the given threads, lod the rate of mode lod and of the
 * lod effect; returns the library's status. */
static int render_with(const char *k, int threads, int mode, const retro_effects *fx, float lod, const player_t *p,
                       ctx_t *c)
{
#ifdef RETRO_RENDER_OPTS_DEFAULT
    retro_ctx *rc = retro_ctx_new();
    if (!rc)
        return RETRO_ENOMEM;
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = mode;
    o.fx = fx;
    o.lod = lod;
    o.threads = threads;
    int e = retro_render(rc, retro_kernel_find(k), &o, p, c);
    retro_ctx_free(rc);
#else /* the public struct and the rate in the effects */
    retro_effects with_rate;
    if (fx) {
        with_rate = *fx;
        with_rate.lod = lod;
    }
    retro_ctx rc;
    retro_ctx_init(&rc);
    rc.fx = fx ? &with_rate : NULL;
    rc.threads = threads;
    int e = retro_render(&rc, retro_kernel_find(k), (retro_mode)mode, p, c);
    retro_ctx_free(&rc);
#endif
    return e;
}

static const char *const kernels[] = {"naive", "ybuffer", "simd-sse2", "simd-avx2", "simd-avx512", "pthreads", "omp"};

/* Every kernel (all: threaded ones at every ISA level and 1 and 3 threads), or naive alone:
 * each build's own checker proves its variants equal its naive, so equal naives make every
 * variant of both builds equal. */
static int all = 1;
static void all_variants(const char *name, int mode, const retro_effects *fx, float lod, const player_t *p,
                         ctx_t *c)
{
    size_t n = (size_t)c->scr_width * (size_t)c->scr_height;
    for (size_t k = 0; k < (all ? sizeof kernels / sizeof kernels[0] : 1); k++) {
        int threaded = !strcmp(kernels[k], "pthreads") || !strcmp(kernels[k], "omp");
        for (int isa = threaded ? 0 : retro_isa_count - 1; isa < retro_isa_count; isa++)
            for (int t = threaded ? 1 : 0; t <= (threaded ? 3 : 0); t += 2) {
                retro_cpu_limit(retro_isa_names[isa]);
                for (size_t i = 0; i < n; i++)
                    c->out[i] = 0x01020300u ^ (uint32_t)i;
                int e = render_with(kernels[k], t, mode, fx, lod, p, c);
                printf("%s %s %s %d %d %x %d %016llx\n", name, kernels[k], retro_isa_names[isa], t, mode,
                       fx ? fx->flags : 0, e, e ? 0ull : (unsigned long long)fnv(c->out, n));
            }
    }
    retro_cpu_limit(NULL);
}

static retro_map maps[64];
static const char *map_names[64];
static int nmaps;

static const retro_map *get_map(const char *dir, const char *shared, const char *name)
{
    for (int i = 0; i < nmaps; i++)
        if (!strcmp(map_names[i], name))
            return maps[i].size ? &maps[i] : NULL;
    char prefix[1024], err[256];
    if (!strncmp(name, "course/", 7))
        snprintf(prefix, sizeof prefix, "%s/course/%s", shared, name + 7);
    else
        snprintf(prefix, sizeof prefix, "%s/%s", dir, name);
    map_names[nmaps] = name;
    if (retro_map_load(prefix, &maps[nmaps], err, sizeof err))
        memset(&maps[nmaps], 0, sizeof maps[nmaps]);
    nmaps++;
    return maps[nmaps - 1].size ? &maps[nmaps - 1] : NULL;
}

static uint32_t seed = 12345;
static int rnd(int lo, int hi)
{
    seed = seed * 1664525u + 1013904223u;
    return lo + (int)((seed >> 8) % (uint32_t)(hi - lo + 1));
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: frame_digest MAPS_DIR SHARED_DIR [POSES]\n");
        return 2;
    }
    const char *dir = argv[1], *shared = argv[2];
    int poses = argc > 3 ? atoi(argv[3]) : 200;
    all = !(argc > 4 && !strcmp(argv[4], "naive"));
    size_t most = 320 * 240;
    for (int i = 0; i < verify_case_count; i++)
        if ((size_t)verify_cases[i].W * (size_t)verify_cases[i].H > most)
            most = (size_t)verify_cases[i].W * (size_t)verify_cases[i].H;
    uint32_t *out = malloc(most * sizeof *out);
    if (!out)
        return 2;
    static uint8_t inverted[2048 * 2048];
    for (int i = 0; i < verify_case_count; i++) {
        const verify_case *vc = &verify_cases[i];
        const retro_map *m = get_map(dir, shared, vc->map);
        if (!m)
            continue;
        struct retro_view view;
        retro_default_view(m, &view);
        player_t p = {isnan(vc->x) ? view.x : (float)vc->x, isnan(vc->y) ? view.y : (float)vc->y, vc->angle,
                      (int)vc->height, 0, 0, 0};
        if (vc->rel_height) {
            double S = m->size;
            double wx = fmod(fmod((double)p.x, S) + S, S), wy = fmod(fmod((double)p.y, S) + S, S);
            p.height += m->height[((size_t)wy % (size_t)m->size) * (size_t)m->size + (size_t)wx % (size_t)m->size];
        }
        ctx_t c = {vc->W, vc->H, m->size, vc->D, 0x66a3ff00u, m->height, m->color, out};
        for (int mode = 0; mode < RETRO_MODE_COUNT; mode++)
            all_variants(vc->name, mode, NULL, 0.0f, &p, &c);
    }
    const char *pose_maps[] = {"alpine", "islands", "test/alpine-200", "course/valley"};
    for (int i = 0; i < poses; i++) {
        const retro_map *m = get_map(dir, shared, pose_maps[i % 4]);
        if (!m)
            m = get_map(dir, shared, "alpine");
        if (!m)
            return 2;
        int S = m->size;
        for (size_t j = 0; j < (size_t)S * (size_t)S && j < sizeof inverted; j++)
            inverted[j] = (uint8_t)(255 - m->height[j]);
        player_t p = {(float)rnd(-2 * S, 3 * S) + (float)rnd(0, 3) * 0.25f, (float)rnd(-2 * S, 3 * S) + 0.5f,
                      rnd(-720, 720), rnd(-50, 400), 0, 0, 0};
        ctx_t c = {rnd(1, 200), rnd(1, 150), S, rnd(0, 700), 0x66a3ff00u, m->height, m->color, out};
        char name[64];
        snprintf(name, sizeof name, "pose%d", i);
        for (int mode = 0; mode < RETRO_MODE_COUNT; mode++)
            all_variants(name, mode, NULL, 0.0f, &p, &c);
        retro_effects fx;
        retro_effects_defaults(&fx);
        fx.flags = (unsigned)rnd(1, RETRO_FX_VOXEL);
        fx.fog_exp = rnd(0, 1);
        fx.pitch = rnd(-100, 100);
        float lod = 0.01f * (float)rnd(1, 8);
        fx.morph_height = (size_t)S * (size_t)S <= sizeof inverted ? inverted : NULL;
        fx.morph_t = 0.01f * (float)rnd(0, 100);
        if (!fx.morph_height)
            fx.flags &= ~(unsigned)RETRO_FX_MORPH;
        all_variants(name, RETRO_MODE_EXACT, &fx, lod, &p, &c);
    }
    for (int i = 0; i < verify_fx_case_count; i++) {
        const verify_fx_case *vc = &verify_fx_cases[i];
        const retro_map *m = get_map(dir, shared, vc->map);
        if (!m)
            continue;
        struct retro_view view;
        retro_default_view(m, &view);
        int S = m->size;
        for (size_t j = 0; j < (size_t)S * (size_t)S && j < sizeof inverted; j++)
            inverted[j] = (uint8_t)(255 - m->height[j]);
        retro_effects fx;
        retro_effects_defaults(&fx);
        fx.flags = vc->fx;
        fx.fog_exp = vc->fog_exp;
        fx.pitch = vc->pitch;
        fx.morph_height = inverted;
        fx.morph_t = 0.37f;
        player_t p = {view.x, view.y, vc->angle, view.height, 0, 0, 0};
        ctx_t c = {320, 240, S, 800, 0x66a3ff00u, m->height, m->color, out};
        all_variants(vc->name, RETRO_MODE_EXACT, &fx, RETRO_LOD_DEFAULT, &p, &c);
    }
    for (int i = 0; i < nmaps; i++)
        if (maps[i].size)
            retro_map_free(&maps[i]);
    free(out);
    return 0;
}
