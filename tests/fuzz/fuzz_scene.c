/* libFuzzer target: scene files and their effects. The input is a scene file's text: it is
 * parsed (retro_scene_load), and if valid, rendered at its first and last path frame with
 * every kernel that renders its effects, each compared with naive byte for byte. A parse error
 * must be one line naming the file; a valid scene must render with every capable kernel.
 *
 * The scene's map is not read (it names files the fuzzer does not have): a fixed generated
 * map of size S stands in, with a second height keyframe for [morph]. The screen and the
 * distance are capped so one input stays within milliseconds under the sanitizers: a mesh
 * frame holds about D^2 squares of the torus, so the mesh family's distance is capped far
 * lower than the voxel family's (as in fuzz_kernels). At the voxel family's cap the mesh
 * kernels made each input so costly that the fuzzer got little past its seed corpus. */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "retro.h"
#include "retro_scene.h"

#define S 64
#define MAX_W 48
#define MAX_H 36
#define MAX_D 400
#define MAX_MESH_D 32
#define MAX_KERNELS 32

static char path[64];
static uint8_t heights[S * S], morph[S * S];
static uint32_t colours[S * S];
static uint32_t ref[MAX_W * MAX_H], out[MAX_W * MAX_H];
static retro_ctx *ctxs[MAX_KERNELS];

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    setenv("KMP_BLOCKTIME", "0", 0); /* as fuzz_kernels: no spinning OpenMP workers */
    setenv("OMP_WAIT_POLICY", "passive", 0);
    char dir[] = "/tmp/retro-fuzz-scene-XXXXXX";
    if (!mkdtemp(dir))
        abort();
    snprintf(path, sizeof path, "%s/in.scene", dir);
    uint64_t z = 12345;
    for (int i = 0; i < S * S; i++) {
        z = z * 6364136223846793005ull + 1442695040888963407ull;
        heights[i] = (uint8_t)(z >> 56);
        morph[i] = (uint8_t)(z >> 48);
        colours[i] = (uint32_t)(z >> 8) & 0xffffff00u;
    }
    for (int k = 0; k < MAX_KERNELS; k++)
        if (!(ctxs[k] = retro_ctx_new()))
            abort();
    return 0;
}

/* Renders with kernel k on its own context (each keeps its caches), in its family's mode 0. */
static retro_err render_with(const retro_kernel *k, const retro_effects *fx, float lod, const player_t *p,
                             ctx_t *c)
{
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = 0;
    o.fx = fx;
    o.lod = lod;
    return retro_render(ctxs[k - retro_kernels], k, &o, p, c);
}

static void render_pose(retro_scene *s, int frame)
{
    player_t p;
    float morph_t;
    retro_scene_pose(s, frame, &p, &morph_t);
    if (isnan(p.x))
        p.x = S / 2;
    if (isnan(p.y))
        p.y = S / 2;
    if (p.height == INT_MIN)
        p.height = 200;
    s->fx.morph_t = morph_t;
    s->fx.morph_height = morph;
    int W = s->W < MAX_W ? s->W : MAX_W, H = s->H < MAX_H ? s->H : MAX_H;
    int D = s->D < MAX_D ? s->D : MAX_D;
    ctx_t c = {W, H, S, D, s->sky, heights, colours, ref};
    float lod = s->lod;
    size_t npx = (size_t)W * (size_t)H;
    /* Each family's kernels against that family's reference, in the family's first mode (voxel
     * exact, mesh binary32); a family whose reference refuses the scene's effects is skipped. */
    for (size_t fi = 0; fi < retro_family_count; fi++) {
        const retro_family *fam = retro_families[fi];
        const retro_kernel *refk = retro_family_reference(fam);
        c.out = ref;
        c.distance = fam == &retro_family_mesh && D > MAX_MESH_D ? MAX_MESH_D : D;
        retro_err e = render_with(refk, &s->fx, lod, &p, &c);
        /* a scene the family cannot render (the scene parser accepts effects of both families,
         * and the mesh refuses some combinations as invalid, texture with gouraud) */
        if (e == RETRO_EUNSUPPORTED || (e == RETRO_EINVAL && fi > 0))
            continue;
        c.out = out;
        for (size_t k = 0; !e && k < retro_kernel_count; k++) {
            const retro_kernel *kr = &retro_kernels[k];
            if (kr->family != fam || kr == refk || (e = render_with(kr, &s->fx, lod, &p, &c)) == RETRO_EUNSUPPORTED) {
                e = RETRO_OK;
                continue;
            }
            size_t differ = 0;
            for (size_t i = 0; !e && i < npx; i++)
                differ += out[i] != ref[i];
            size_t allowed = fam->documented_difference ? fam->documented_difference(kr, 0, &s->fx, npx) : 0;
            if (!e && differ > allowed) {
                fprintf(stderr, "%s differs from %s in %zu pixels: frame %d, x=%a y=%a angle=%d height=%d, "
                        "%dx%d D=%d, effects %#x\n", kr->name, refk->name, differ, frame, (double)p.x,
                        (double)p.y, p.angle, p.height, W, H, c.distance, s->fx.flags);
                abort();
            }
        }
        if (e) {
            fprintf(stderr, "a kernel of family %s failed on a valid scene: %s\n", fam->name, retro_strerror(e));
            abort();
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (retro_kernel_count > MAX_KERNELS)
        abort();
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size || fclose(f))
        abort();
    retro_scene s;
    char err[1400];
    if (retro_scene_load(path, &s, err, sizeof err)) {
        if (strncmp(err, path, strlen(path)) || strchr(err, '\n')) {
            fprintf(stderr, "a scene error must be one line naming the file: %s\n", err);
            abort();
        }
        return 0;
    }
    render_pose(&s, 0);
    if (s.nkeys && s.frames > 1)
        render_pose(&s, s.frames - 1);
    return 0;
}
