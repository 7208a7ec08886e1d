/* libFuzzer target: scene files and their effects. The input is a scene file's text: it is
 * parsed (retro_scene_load), and if valid, rendered at its first and last path frame with
 * every kernel that renders its effects, each compared with naive byte for byte. A parse error
 * must be one line naming the file; a valid scene must render with every capable kernel.
 *
 * The scene's map is not read (it names files the fuzzer does not have): a fixed generated
 * map of size S stands in, with a second height keyframe for [morph]. The screen and the
 * distance are capped so one input stays a few milliseconds under the sanitizers. */
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
#define MAX_KERNELS 32

static char path[64];
static uint8_t heights[S * S], morph[S * S];
static uint32_t colours[S * S];
static uint32_t ref[MAX_W * MAX_H], out[MAX_W * MAX_H];
static retro_ctx ctxs[MAX_KERNELS];

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
        retro_ctx_init(&ctxs[k]);
    return 0;
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
    float lod = s->fx.flags & RETRO_FX_LOD ? s->fx.lod : 0.0f;
    for (size_t k = 0; k < retro_kernel_count; k++) {
        retro_ctx *rc = &ctxs[k];
        rc->fx = &s->fx;
        rc->lod = lod;
        c.out = k ? out : ref;
        retro_err e = retro_render(rc, &retro_kernels[k], RETRO_MODE_EXACT, &p, &c);
        if (e == RETRO_EUNSUPPORTED && k)
            continue;
        if (e) {
            fprintf(stderr, "%s failed on a valid scene: %s\n", retro_kernels[k].name, retro_strerror(e));
            abort();
        }
        if (k && memcmp(out, ref, sizeof(uint32_t) * (size_t)W * (size_t)H)) {
            fprintf(stderr, "%s differs from naive: frame %d, x=%a y=%a angle=%d height=%d, %dx%d D=%d, effects %#x\n",
                    retro_kernels[k].name, frame, (double)p.x, (double)p.y, p.angle, p.height, W, H, D,
                    s->fx.flags);
            abort();
        }
        rc->fx = NULL;
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
