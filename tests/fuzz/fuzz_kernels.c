/* libFuzzer target: every kernel against naive, byte for byte, on a frame decoded from the
 * input. The input picks the pose (any finite x and y, huge ones included, any int angle and
 * height), the screen (1..64 square), the distance, the mode, the ISA level, the thread count
 * of threaded kernels and a small map (S = 1..33), so the fuzzer steers every choice a kernel
 * branches on. The same pose and map also go through the mesh family: its fast kernels against
 * mesh-zbuffer (distance reduced mod 97: a mesh frame costs D^2 triangles). A mismatch, an error return or a pixel left unwritten aborts with the case.
 *
 * Layout (missing bytes read as 0): flags, x[4], y[4], angle[4], height[4], W, H, D[2], S,
 * sky[3], then the cells (height, R, G, B each); cells the input does not cover come from a
 * generator seeded with the input, so short inputs still give varied maps. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "retro.h"
#include "retro_mesh.h"

#define MAX_S 33
#define MAX_WH 64
#define MAX_KERNELS 32
#define MAX_THREADS 3
/* Bounds the samples of one frame (W * D) so one input stays a few milliseconds under the
 * sanitizers; 2x2 screens and smaller may go far beyond that. */
#define MAX_SAMPLES (1 << 14)
#define FAR_SAMPLES (1 << 19)
/* A low byte no colour has, so an unwritten pixel shows (map colours with a low byte, flag
 * bit 6, are kept off this value). */
#define POISON 0xababababu

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

static const char *const levels[] = {"none", "sse2", "avx2", "avx512"};
/* Contexts live across inputs, as in an application; maps are rewritten in place each input,
 * so every context is told (retro_ctx_map_changed). */
static retro_ctx ctxs[MAX_KERNELS][MAX_THREADS + 1];
static uint8_t heights[MAX_S * MAX_S];
static uint32_t colours[MAX_S * MAX_S];
static uint32_t ref[MAX_WH * MAX_WH], out[MAX_WH * MAX_WH];

static void describe(const player_t *p, const ctx_t *c, retro_mode mode, const char *level, int t)
{
    fprintf(stderr, "case: mode %s, isa %s, %d threads, x=%a y=%a angle=%d height=%d, %dx%d, D=%d, S=%d\n",
            retro_mode_name(mode), level, t, (double)p->x, (double)p->y, p->angle, p->height,
            c->scr_width, c->scr_height, c->distance, c->map_size);
}

static retro_mesh_ctx *mesh_ctxs[RETRO_MESH_KERNEL_COUNT];
/* A mesh frame costs about D^2 triangles: its distance is bounded apart from the voxel one. */
#define MESH_MAX_D 96

/* The mesh family's fast kernels against mesh-zbuffer (binary32), byte for byte, on the same
 * pose and map; culling off when the mode number is odd. */
static void mesh_frames(const player_t *p, ctx_t *c, int mode, const char *level, int threads)
{
    for (int k = 0; k < RETRO_MESH_KERNEL_COUNT; k++)
        if (!mesh_ctxs[k] && !(mesh_ctxs[k] = retro_mesh_ctx_new()))
            abort();
    size_t n = (size_t)c->scr_width * (size_t)c->scr_height;
    int D = c->distance;
    c->distance = D < 0 ? D : D % (MESH_MAX_D + 1);
    retro_mesh_opts o = {(mode & 1) ? (unsigned)RETRO_MESH_FX_NOCULL : 0u, threads};
    c->out = ref;
    retro_mesh_err e = retro_mesh_render(mesh_ctxs[0], RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY32, p, c, NULL, &o, NULL);
    if (e) {
        describe(p, c, (retro_mode)mode, level, 0);
        fprintf(stderr, "mesh-zbuffer failed on a valid input: %s\n", retro_mesh_error(mesh_ctxs[0]));
        abort();
    }
    c->out = out;
    for (int k = RETRO_MESH_AVX2; k < RETRO_MESH_KERNEL_COUNT; k++) {
        if (retro_mesh_kernel_isa((retro_mesh_kernel)k) & ~retro_cpu_features())
            continue;
        for (size_t i = 0; i < n; i++)
            out[i] = POISON;
        e = retro_mesh_render(mesh_ctxs[k], (retro_mesh_kernel)k, RETRO_MESH_BINARY32, p, c, NULL, &o, NULL);
        size_t at = 0;
        while (!e && at < n && out[at] == ref[at])
            at++;
        if (e || at < n) {
            describe(p, c, (retro_mode)mode, level, threads);
            fprintf(stderr, "mesh-%s %s at pixel %zu\n", retro_mesh_kernel_name((retro_mesh_kernel)k),
                    e ? retro_mesh_error(mesh_ctxs[k]) : "differs from mesh-zbuffer", at);
            abort();
        }
    }
    c->distance = D;
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
    if (retro_kernel_count > MAX_KERNELS)
        abort();
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
    const char *level = levels[(flags >> 3) & 3];
    int threads = 1 + (int)((flags >> 5) % MAX_THREADS);
    if (mode == RETRO_MODE_COURSE && S < 2)
        S = 2;
    if ((flags & 0x80) && W * H <= 8) /* far: a tiny screen looks up to 2^19 cells away */
        D = (int)(take(&r, 3) % (FAR_SAMPLES / (unsigned)W)) + 1;
    else if ((long)W * D > MAX_SAMPLES)
        D = MAX_SAMPLES / W;
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
    }
    ctx_t c = {W, H, S, D, sky, heights, colours, ref};
    size_t n = (size_t)W * (size_t)H;

    for (int k = 0; k < MAX_KERNELS; k++)
        for (int t = 0; t <= MAX_THREADS; t++)
            retro_ctx_map_changed(&ctxs[k][t]);
    retro_cpu_limit(level);
    for (size_t i = 0; i < n; i++)
        ref[i] = POISON;
    retro_err e = retro_render(&ctxs[0][0], &retro_kernels[0], mode, &p, &c);
    if (e) {
        describe(&p, &c, mode, level, 0);
        fprintf(stderr, "naive failed on a valid input: %s\n", retro_strerror(e));
        abort();
    }
    for (size_t i = 0; i < n; i++)
        if (ref[i] == POISON) {
            describe(&p, &c, mode, level, 0);
            fprintf(stderr, "naive left pixel %zu unwritten\n", i);
            abort();
        }
    c.out = out;
    for (size_t k = 1; k < retro_kernel_count; k++) {
        const retro_kernel *kr = &retro_kernels[k];
        if (!retro_kernel_runs_here(kr) || !retro_kernel_has_mode(kr, mode))
            continue;
        int t = kr->flags & RETRO_KF_THREADED ? threads : 0;
        for (size_t i = 0; i < n; i++)
            out[i] = POISON;
        ctxs[k][t].threads = t;
        e = retro_render(&ctxs[k][t], kr, mode, &p, &c);
        size_t at = 0;
        while (!e && at < n && out[at] == ref[at])
            at++;
        if (e || at < n) {
            describe(&p, &c, mode, level, t);
            if (e)
                fprintf(stderr, "%s failed: %s\n", kr->name, retro_strerror(e));
            else
                fprintf(stderr, "%s differs from naive at pixel (u=%zu, r=%zu): %08x, naive %08x\n",
                        kr->name, at % (size_t)W + 1, (size_t)H - at / (size_t)W, out[at], ref[at]);
            abort();
        }
    }
    mesh_frames(&p, &c, (int)mode, level, threads);
    retro_cpu_limit(NULL);
    return 0;
}
