/* The mesh family in the kernel table (docs/MESH.md, "In the kernel table"): its descriptor,
 * its setup and one thin wrapper per kernel row passing the module's kernel id. Until an
 * opaque context exists, the family's state (the module's context, the frame's inputs and the
 * last frame's counts) hangs off retro_ctx.mesh and is freed by retro_ctx_free(). */
#include <stdlib.h>
#include <string.h>

#include "ctx.h"
#include "mesh_family.h"
#include "mesh_internal.h"

static const char *const mesh_mode_names[RETRO_MESH_MODE_COUNT] = {"binary32", "binary64", "int"};

void retro_mesh_state_free(retro_mesh_state *st)
{
    if (!st)
        return;
    retro_mesh_ctx_free(st->mc);
    free(st);
}

static retro_err to_retro_err(retro_mesh_err e)
{
    switch (e) {
    case RETRO_MESH_OK:
        return RETRO_OK;
    case RETRO_MESH_ENOMEM:
        return RETRO_ENOMEM;
    case RETRO_MESH_EUNSUPPORTED:
        return RETRO_EUNSUPPORTED;
    default:
        return RETRO_EINVAL;
    }
}

static int mesh_effective_mode(int mode, const retro_effects *fx)
{
    (void)fx;
    return mode;
}

/* Validates the inputs as the module will (its frame setup, cheap next to a frame) so that a
 * bad request is refused before a kernel runs; keeps copies the kernels render from. */
static retro_err mesh_setup(retro_ctx *rc, int mode, const player_t *p, const ctx_t *c, const void **frame)
{
    *frame = NULL;
    if (!rc->mesh) {
        retro_mesh_state *st = calloc(1, sizeof *st);
        if (!st || !(st->mc = retro_mesh_ctx_new())) {
            free(st);
            return RETRO_ENOMEM;
        }
        rc->mesh = st;
    }
    retro_mesh_state *st = rc->mesh;
    if (!p || !c || mode < 0 || mode >= RETRO_MESH_MODE_COUNT)
        return RETRO_EINVAL;
    st->p = *p;
    st->c = *c;
    st->mode = (retro_mesh_mode)mode;
    unsigned flags = rc->fx ? rc->fx->flags : 0;
    if (rc->fx)
        st->fx = *rc->fx;
    else
        memset(&st->fx, 0, sizeof st->fx);
    st->opts.flags = (flags & RETRO_FX_CULL) ? 0 : RETRO_MESH_FX_NOCULL;
    st->fx.flags = flags & ~(unsigned)RETRO_FX_CULL;
    memset(&st->stats, 0, sizeof st->stats);
    st->status = to_retro_err(
        mesh_frame_setup(st->mc, RETRO_MESH_ZBUFFER, st->mode, &st->p, &st->c, &st->fx, st->opts.flags));
    *frame = st;
    return st->status;
}

/* The frame was validated by setup: what can still fail is memory (the depth buffer, the
 * water list), reported through rc->kernel_err. */
void retro_mesh_family_run(const void *frame, retro_ctx *rc, retro_mesh_kernel kernel)
{
    retro_mesh_state *st = (retro_mesh_state *)frame;
    /* mesh-omp's thread count is the context's, as for the voxel threaded kernels. */
    int threads = kernel == RETRO_MESH_OMP ? retro_ctx_threads(rc) : 0;
    st->opts.threads = threads > 64 ? 64 : threads;
    retro_mesh_err e =
        retro_mesh_render(st->mc, kernel, st->mode, &st->p, &st->c, &st->fx, &st->opts, &st->stats);
    st->status = to_retro_err(e);
    if (e)
        rc->kernel_err = st->status;
}

void retro_kernel_mesh_zbuffer(const void *frame, retro_ctx *rc)
{
    retro_mesh_family_run(frame, rc, RETRO_MESH_ZBUFFER);
}

void retro_kernel_mesh_painter(const void *frame, retro_ctx *rc)
{
    retro_mesh_family_run(frame, rc, RETRO_MESH_PAINTER);
}

void retro_kernel_mesh_avx2(const void *frame, retro_ctx *rc)
{
    retro_mesh_family_run(frame, rc, RETRO_MESH_AVX2);
}

void retro_kernel_mesh_avx512(const void *frame, retro_ctx *rc)
{
    retro_mesh_family_run(frame, rc, RETRO_MESH_AVX512);
}

void retro_kernel_mesh_omp(const void *frame, retro_ctx *rc)
{
    retro_mesh_family_run(frame, rc, RETRO_MESH_OMP);
}

const retro_mesh_stats *retro_mesh_last_stats(const retro_ctx *rc)
{
    return rc && rc->mesh ? &rc->mesh->stats : NULL;
}

const char *retro_mesh_last_error(const retro_ctx *rc)
{
    return rc && rc->mesh && rc->mesh->status ? retro_mesh_error(rc->mesh->mc) : "";
}

/* Without culling a back face folds over its front neighbour along silhouettes at equal
 * depth, and the painter's order and the z-buffer's rounded depths may pick different faces
 * next to that edge: docs/MESH.md bounds it by 1 pixel in 10,000. */
static size_t mesh_documented_difference(const retro_kernel *k, int mode, const retro_effects *fx, size_t npx)
{
    (void)mode;
    if (k->fn != retro_kernel_mesh_painter || (fx && (fx->flags & RETRO_FX_CULL)))
        return 0;
    return (npx + 9999) / 10000;
}

const retro_family retro_family_mesh = {
    .name = "mesh",
    .reference = "mesh-zbuffer",
    .mode_count = RETRO_MESH_MODE_COUNT,
    .mode_names = mesh_mode_names,
    .fx = RETRO_FX_MESH,
    .effective_mode = mesh_effective_mode,
    .setup = mesh_setup,
    .documented_difference = mesh_documented_difference,
};
