/* libFuzzer target: every kernel against naive, byte for byte, on a frame decoded from the
 * input. The input picks the pose (any finite x and y, huge ones included, any int angle and
 * height), the screen (1..64 square), the distance, the mode, the ISA level, the thread count
 * of threaded kernels and a small map (S = 1..33), so the fuzzer steers every choice a kernel
 * branches on. A mismatch, an error return or a pixel left unwritten aborts with the case.
 *
 * Layout (missing bytes read as 0): flags, x[4], y[4], angle[4], height[4], W, H, D[2], S,
 * sky[3], (with flags & 0x80 on a tiny screen, the far distance[3],) effects, parameter, then
 * the cells (height, R, G, B each); cells the input does not cover come from a generator
 * seeded with the input, so short inputs still give varied maps. In modes exact and lod, the
 * only ones that take effects, the effects byte picks the voxel effects (fog, bilinear, shade,
 * water, horizon, morph, fog's exponential form) and the parameter byte sets their values, so
 * occlusion skipping's bound is fuzzed with the per-sample effects it extends to (bilinear's
 * wider box and margin) and on the maps the baked effects rewrite.
 *
 * The mesh family's kernels run on the same map and pose against mesh-zbuffer, nearer (a mesh
 * frame holds about D^2 squares): D mod 65, mode (flags & 7) mod 3, back faces culled when
 * flags & 0x40; mesh-painter may differ by what docs/MESH.md bounds (the checker's
 * documented difference), never more. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "retro.h"
#include "retro_scene.h"

#define MAX_S 33
#define MAX_WH 64
#define MAX_THREADS 3
/* Bounds the samples of one frame (W * D) so one input stays a few milliseconds under the
 * sanitizers; 2x2 screens and smaller may go far beyond that. */
#define MAX_SAMPLES (1 << 14)
#define FAR_SAMPLES (1 << 19)

typedef struct {
    const uint8_t *p;
    size_t n;
} reader;

static uint32_t take(reader *r, int bytes)
{
    uint32_t v = 0;
    for (int i = 0; i < bytes; i++) {
        uint8_t b = 0;
        if (r->n) {
            b = *r->p++;
            r->n--;
        }
        v = v << 8 | b;
    }
    return v;
}

/* Any float the bit pattern gives, made finite: non-finite patterns become their integer value. */
static float take_float(reader *r)
{
    uint32_t bits = take(r, 4);
    float f;
    memcpy(&f, &bits, sizeof f);
    return isfinite(f) ? f : (float)(int32_t)bits;
}

static uint64_t mix64(uint64_t *s)
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* The checker's variants and their contexts live across inputs, as in an application; maps
 * are rewritten in place each input, so every context is told (retro_check_map_changed). */
static retro_check chk, mesh_chk;
static int chk_ready;
static uint8_t heights[MAX_S * MAX_S], morph_to[MAX_S * MAX_S];
static uint32_t colours[MAX_S * MAX_S];

typedef struct {
    const player_t *p;
    const ctx_t *c;
    const retro_family *fam;
    int mode;
    unsigned fx; /* the effects' flags, for the case's description */
} fuzz_case;

static void describe(const fuzz_case *fc, const char *variant)
{
    const player_t *p = fc->p;
    const ctx_t *c = fc->c;
    fprintf(stderr, "case: mode %s, %s, x=%a y=%a angle=%d height=%d, %dx%d, D=%d, S=%d, effects 0x%x\n",
            retro_family_mode_name(fc->fam, fc->mode), variant, (double)p->x, (double)p->y, p->angle, p->height,
            c->scr_width, c->scr_height, c->distance, c->map_size, fc->fx);
}

/* Aborts with the case on a variant that failed or differs from naive. */
static void abort_on_mismatch(void *user, const retro_check_variant *v, const retro_check_result *r)
{
    if (!r->ran || (!r->err && r->differ <= r->documented))
        return;
    char line[256];
    retro_check_describe(((const fuzz_case *)user)->fam == &retro_family_mesh ? &mesh_chk : &chk, v, r, line,
                         sizeof line);
    describe(user, v->label);
    fprintf(stderr, "%s\n", line);
    abort();
}

/* OpenMP workers of the omp kernel would otherwise spin for 200 ms (libomp) after every
 * frame, competing on two cores with the next kernel's threads. libomp reads these at its
 * first parallel region, after this. */
int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    setenv("KMP_BLOCKTIME", "0", 0);
    setenv("OMP_WAIT_POLICY", "passive", 0);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!chk_ready) {
        if (retro_check_init(&chk, &retro_family_voxel, NULL, MAX_THREADS) ||
            retro_check_init(&mesh_chk, &retro_family_mesh, NULL, MAX_THREADS))
            abort();
        chk_ready = 1;
    }
    reader r = {data, size};
    unsigned flags = take(&r, 1);
    player_t p = {0};
    p.x = take_float(&r);
    p.y = take_float(&r);
    p.angle = (int32_t)take(&r, 4);
    p.height = (int32_t)take(&r, 4);
    int W = 1 + (int)(take(&r, 1) % MAX_WH), H = 1 + (int)(take(&r, 1) % MAX_WH);
    int D = (int)(take(&r, 2) % 2003) - 2; /* -2..2000: D <= 1 renders sky only */
    int S = 1 + (int)(take(&r, 1) % MAX_S);
    uint32_t sky = take(&r, 3) << 8;
    retro_mode mode = (retro_mode)((flags & 7) % RETRO_MODE_COUNT);
    int level = (int)((flags >> 3) & 3);
    int threads = 1 + (int)((flags >> 5) % MAX_THREADS);
    if (mode == RETRO_MODE_COURSE && S < 2)
        S = 2;
    if ((flags & 0x80) && W * H <= 8) /* far: a tiny screen looks up to 2^19 cells away */
        D = (int)(take(&r, 3) % (FAR_SAMPLES / (unsigned)W)) + 1;
    else if ((long)W * D > MAX_SAMPLES)
        D = MAX_SAMPLES / W;
    const unsigned fx_bits = take(&r, 1), fx_param = take(&r, 1);
    uint64_t seed = size;
    for (size_t i = 0; i < size; i++)
        seed = seed * 131 + data[i];
    int low_byte = (flags & 0x40) && (flags & 0x80) == 0;
    for (int i = 0; i < S * S; i++) {
        uint32_t h, c;
        if (r.n >= 4) {
            h = take(&r, 1);
            c = take(&r, 3) << 8;
        } else {
            uint64_t z = mix64(&seed);
            h = (uint32_t)z & 0xff;
            c = (uint32_t)(z >> 32) & 0xffffff00u;
        }
        /* Colours outside R<<24|G<<16|B<<8: kernels on a packed map must fall back, not drop them. */
        if (low_byte)
            c |= (uint32_t)(i * 29 + 1) & 0x7f;
        heights[i] = (uint8_t)h;
        colours[i] = c;
        morph_to[i] = (uint8_t)(255 - h + (unsigned)i % 7); /* a second keyframe unlike the first */
    }
    ctx_t c = {W, H, S, D, sky, heights, colours, NULL};
    fuzz_case fc = {&p, &c, &retro_family_voxel, (int)mode, 0};

    retro_check_map_changed(&chk);
    /* The input picks one ISA level (levels this CPU lacks run nothing but naive) and one
     * thread count for threaded kernels. */
    chk.select_level = level < chk.level ? level : chk.level;
    chk.select_threads = threads;
    retro_effects vfx;
    retro_effects_defaults(&vfx);
    if (mode == RETRO_MODE_EXACT || mode == RETRO_MODE_LOD) {
        static const unsigned pick[] = {RETRO_FX_FOG,   RETRO_FX_BILINEAR, RETRO_FX_SHADE,
                                        RETRO_FX_WATER, RETRO_FX_HORIZON,  RETRO_FX_MORPH};
        for (unsigned b = 0; b < sizeof pick / sizeof *pick; b++)
            vfx.flags |= (fx_bits >> b & 1u) ? pick[b] : 0;
        /* fog over sixteenths of the distance, or exponential with density up to 1 */
        const float span = (float)(D > 16 ? D : 16) / 16.0f;
        vfx.fog_exp = (fx_bits & 0x40) != 0;
        vfx.fog_start = (float)(fx_param & 15) * span;
        vfx.fog_end = (float)((fx_param & 15) + (fx_param >> 4) + 1) * span;
        vfx.fog_density = (float)(fx_param + 1) / 256.0f;
        vfx.water_level = (int)fx_param;
        vfx.pitch = 2 * (int)(int8_t)fx_param; /* rows up or down, past the screen too */
        vfx.morph_height = morph_to;
        vfx.morph_t = (float)fx_param / 255.0f;
    }
    fc.fx = vfx.flags;
    retro_err e = retro_check_frame(&chk, mode, vfx.flags ? &vfx : NULL, &p, &c, abort_on_mismatch, &fc, NULL);
    if (e) {
        describe(&fc, "naive");
        fprintf(stderr, "naive failed on a valid input or left a pixel unwritten: %s\n", retro_strerror(e));
        abort();
    }

    ctx_t mc = c;
    mc.distance = D < 0 ? D : D % 65;
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = (flags & 0x40) ? RETRO_FX_CULL : 0;
    fuzz_case mfc = {&p, &mc, &retro_family_mesh, (int)((flags & 7) % (unsigned)retro_family_mesh.mode_count),
                     fx.flags};
    retro_check_map_changed(&mesh_chk);
    mesh_chk.select_level = chk.select_level;
    e = retro_check_frame(&mesh_chk, mfc.mode, &fx, &p, &mc, abort_on_mismatch, &mfc, NULL);
    if (e) {
        describe(&mfc, "mesh-zbuffer");
        fprintf(stderr, "mesh-zbuffer failed on a valid input or left a pixel unwritten: %s\n", retro_strerror(e));
        abort();
    }
    return 0;
}
