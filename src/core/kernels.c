/* The one table of kernels, every family's, each family's rows slowest first:
 * retro_kernel_best() takes the last row this CPU runs. Adding a kernel is its file(s), one
 * prototype in its family's header and one row here (and, for a voxel strip, its row in
 * strips.h); adding a family is its folder, its
 * descriptor in retro_families[] and its rows. */
#include <stdio.h>
#include <string.h>

#include "kernels.h"
#include "strips.h"
#include "mesh_family.h"
#include "retro_scene.h"

/* Every mode, the accuracy variants of docs/ACCURACY.md included. */
#define ALL ((1u << RETRO_MODE_COUNT) - 1)
/* The single-thread voxel rows with a strip point at its row of the strip table (strips.h)
 * and state its ISA level, modes and effects with the same constants; tests/test_strips.c
 * checks that they agree. */
#define FX_ALL RETRO_FX_VOXEL
#define STRIP(id) &retro_strips[RETRO_STRIP_##id]
/* Each ISA level includes the ones below it (isa.h). */
#define ISA_AVX2 RETRO_ISA_CPU_AVX2
#define ISA_AVX512 RETRO_ISA_CPU_AVX512
#define VOXEL &retro_family_voxel
#define MESH &retro_family_mesh
#define MESH_MODES ((1u << RETRO_MESH_MODE_COUNT) - 1)
#define MESH_B32 RETRO_MODE_BIT(RETRO_MESH_BINARY32)
/* The painter has no depth buffer to draw the water plane against (docs/MESH.md). */
#define FX_MESH_PAINTER (RETRO_FX_MESH & ~(unsigned)RETRO_FX_WATER)

const retro_family *const retro_families[] = {&retro_family_voxel, &retro_family_mesh};
const size_t retro_family_count = sizeof retro_families / sizeof retro_families[0];

const retro_kernel retro_kernels[] = {
    {"naive", retro_kernel_naive, 0, ALL, 0, "painter, back to front: the reference", NULL, FX_ALL, VOXEL},
    {"ybuffer", retro_kernel_ybuffer, 0, RETRO_STRIP_MODES_ALL, RETRO_KF_WRITE_ONCE,
     "front to back with a per-column y-buffer, each pixel written once", STRIP(ybuffer), FX_ALL, VOXEL},
    {"simd-sse2", retro_kernel_simd_sse2, RETRO_ISA_CPU_SSE2, RETRO_STRIP_MODES_SIMD, RETRO_KF_WRITE_ONCE,
     "y-buffer, 4 columns per SSE2 vector, packed map, stores lane by lane", STRIP(simd_sse2),
     RETRO_STRIP_FX_SIMD, VOXEL},
    {"simd-avx2", retro_kernel_simd_avx2, RETRO_ISA_CPU_AVX2, RETRO_STRIP_MODES_SIMD, RETRO_KF_WRITE_ONCE,
     "y-buffer, 8 columns per AVX2 vector, packed map, masked row stores", STRIP(simd_avx2),
     RETRO_STRIP_FX_SIMD, VOXEL},
    {"simd-avx512", retro_kernel_simd_avx512, RETRO_ISA_CPU_AVX512, RETRO_STRIP_MODES_SIMD,
     RETRO_KF_WRITE_ONCE, "y-buffer, 16 columns per AVX-512 vector, packed map, masked row stores",
     STRIP(simd_avx512), RETRO_STRIP_FX_SIMD, VOXEL},
    /* The threaded kernels run the frame's strip (retro_frame.strip), chosen by frame setup
     * from the strip table, not from these rows. */
    {"pthreads", retro_kernel_pthreads, 0, ALL, RETRO_KF_WRITE_ONCE | RETRO_KF_THREADED | RETRO_KF_CTX_THREADS,
     "column chunks on POSIX threads kept by the context: the submission's engine", NULL, FX_ALL, VOXEL},
    {"omp", retro_kernel_omp, 0, ALL, RETRO_KF_WRITE_ONCE | RETRO_KF_THREADED,
     "column chunks on every core (OpenMP, pinned with hwloc), each the best strip", NULL, FX_ALL, VOXEL},
    /* mesh: each row a thin wrapper passing the module's kernel id (src/mesh/family.c) */
    {"mesh-zbuffer", retro_kernel_mesh_zbuffer, 0, MESH_MODES, 0,
     "triangles, depth buffer, front to back in grid order: the reference", NULL, RETRO_FX_MESH, MESH},
    {"mesh-painter", retro_kernel_mesh_painter, 0, MESH_MODES, 0,
     "triangles back to front in grid order, no depth buffer", NULL, FX_MESH_PAINTER, MESH},
    {"mesh-avx2", retro_kernel_mesh_avx2, ISA_AVX2, MESH_B32, 0,
     "z-buffer; vertices, culling and triangle setup in 8 lanes, sub-pixel triangles dropped early",
     NULL, RETRO_FX_MESH, MESH},
    {"mesh-avx512", retro_kernel_mesh_avx512, ISA_AVX512, MESH_B32, 0,
     "z-buffer; vertices, culling and triangle setup in 16 lanes, sub-pixel triangles dropped early",
     NULL, RETRO_FX_MESH, MESH},
    {"mesh-omp", retro_kernel_mesh_omp, ISA_AVX2, MESH_B32, RETRO_KF_THREADED,
     "row bands on every core (OpenMP, pinned with hwloc), each the best SIMD block stage", NULL,
     RETRO_FX_MESH, MESH},
};

const size_t retro_kernel_count = sizeof retro_kernels / sizeof retro_kernels[0];

int retro_kernels_two_pools(const retro_kernel *a, int ta, const retro_kernel *b, int tb)
{
    const unsigned t = RETRO_KF_THREADED;
    return (a != b || (a->flags & RETRO_KF_CTX_THREADS)) && (a->flags & t) && (b->flags & t) && ta > 1 && tb > 1;
}

const retro_kernel *retro_kernel_find(const char *name)
{
    for (size_t i = 0; i < retro_kernel_count; i++)
        if (!strcmp(retro_kernels[i].name, name))
            return &retro_kernels[i];
    return NULL;
}

const retro_family *retro_family_find(const char *name)
{
    for (size_t i = 0; i < retro_family_count; i++)
        if (!strcmp(retro_families[i]->name, name))
            return retro_families[i];
    return NULL;
}

const retro_kernel *retro_family_reference(const retro_family *fam)
{
    const retro_kernel *k = retro_kernel_find(fam->reference);
    return k && k->family == fam ? k : NULL;
}

const char *retro_family_mode_name(const retro_family *fam, int mode)
{
    return mode >= 0 && mode < fam->mode_count ? fam->mode_names[mode] : "?";
}

int retro_family_mode_parse(const retro_family *fam, const char *name, int *mode)
{
    for (int m = 0; m < fam->mode_count; m++)
        if (!strcmp(name, fam->mode_names[m])) {
            *mode = m;
            return 0;
        }
    return -1;
}

int retro_kernel_runs_here(const retro_kernel *k)
{
    return (k->cpu & retro_cpu_features()) == k->cpu;
}

int retro_kernel_has_mode(const retro_kernel *k, retro_mode mode)
{
    return (int)mode >= 0 && (int)mode < k->family->mode_count && (k->modes & RETRO_MODE_BIT(mode)) != 0;
}

static unsigned fx_flags(const retro_effects *fx)
{
    return fx ? fx->flags & RETRO_FX_ALL : 0;
}

/* "exact or lod": the names of the modes in bits, for a refusal. */
static void mode_list(const retro_family *fam, unsigned bits, char *out, size_t n)
{
    size_t used = 0;
    int left = 0;
    for (int m = 0; m < fam->mode_count; m++)
        left += (bits >> m) & 1;
    out[0] = 0;
    for (int m = 0; m < fam->mode_count && used < n; m++) {
        if (!((bits >> m) & 1))
            continue;
        left--;
        int w = snprintf(out + used, n - used, "%s%s", fam->mode_names[m], left > 1 ? ", " : left == 1 ? " or " : "");
        used += w > 0 ? (size_t)w : 0;
    }
}

retro_err retro_kernel_check(const retro_kernel *k, int mode, const retro_effects *fx, char *why, size_t n)
{
    char buf[160];
    if (!why) {
        why = buf;
        n = sizeof buf;
    }
    const retro_family *fam = k->family;
    if (mode < 0 || mode >= fam->mode_count) {
        snprintf(why, n, "%s has no mode %d", fam->name, mode);
        return RETRO_EINVAL;
    }
    int m = fam->effective_mode(mode, fx);
    unsigned asked = fx_flags(fx), missing = asked & ~k->fx, defined = asked & fam->fx;
    if (defined && fam->fx_modes && !(fam->fx_modes & RETRO_MODE_BIT(m))) {
        char modes[96];
        mode_list(fam, fam->fx_modes, modes, sizeof modes);
        snprintf(why, n, "effects need mode %s, not %s (%s asked for)", modes, retro_family_mode_name(fam, m),
                 retro_fx_name(defined & -defined));
        return RETRO_EINVAL;
    }
    if (!retro_kernel_has_mode(k, (retro_mode)m)) {
        snprintf(why, n, "kernel %s does not render mode %s", k->name, retro_family_mode_name(fam, m));
        return RETRO_EUNSUPPORTED;
    }
    if (missing) {
        snprintf(why, n, "kernel %s does not render %s", k->name, retro_fx_name(missing & -missing));
        return RETRO_EUNSUPPORTED;
    }
    if (!retro_kernel_runs_here(k)) {
        snprintf(why, n, "this CPU (at ISA level %s) lacks %s for kernel %s",
                 retro_cpu_level_name(retro_cpu_features()), retro_cpu_level_name(k->cpu), k->name);
        return RETRO_EUNSUPPORTED;
    }
    snprintf(why, n, "ok");
    return RETRO_OK;
}

const retro_kernel *retro_family_best(const retro_family *fam, int mode, const struct retro_effects *fx)
{
    const retro_kernel *best = NULL;
    for (size_t i = 0; i < retro_kernel_count; i++) {
        const retro_kernel *k = &retro_kernels[i];
        /* a kernel allowed a documented difference from the reference is never the default */
        if (k->family == fam && retro_kernel_check(k, mode, fx, NULL, 0) == RETRO_OK &&
            !(fam->documented_difference && fam->documented_difference(k, mode, fx, 1)))
            best = k;
    }
    return best;
}

const retro_kernel *retro_kernel_best_fx(retro_mode mode, const retro_effects *fx)
{
    return retro_family_best(&retro_family_voxel, (int)mode, fx);
}

const retro_kernel *retro_kernel_best(retro_mode mode)
{
    return retro_kernel_best_fx(mode, NULL);
}
