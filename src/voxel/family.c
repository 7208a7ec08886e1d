/* The voxel family: height-map terrain by ray marching (SEMANTICS.md), reference naive. Its
 * frames are built by retro_frame_setup() (frame.c); its kernels receive a const retro_frame *. */
#include "ctx.h"
#include "frame.h"
#include "kernels.h"
#include "retro_scene.h"

/* Effects with lod turn mode exact into mode lod (docs/EFFECTS.md). */
static int voxel_effective_mode(int mode, const retro_effects *fx)
{
    return fx && (fx->flags & RETRO_FX_LOD) && mode == RETRO_MODE_EXACT ? RETRO_MODE_LOD : mode;
}

static retro_err voxel_setup(retro_ctx *rc, int mode, const player_t *p, const ctx_t *c, const void **frame)
{
    retro_err e = retro_frame_setup(rc, (retro_mode)mode, p, c);
    *frame = &rc->frame;
    return e;
}

retro_err retro_frame_prepare(retro_ctx *rc, const retro_render_opts *o, const player_t *p, const ctx_t *c,
                              const retro_frame **f)
{
    const retro_kernel *ref = retro_family_reference(&retro_family_voxel);
    *f = &rc->frame;
    retro_err e = retro_render_check(ref, o, NULL, 0);
    if (e)
        return e;
    retro_ctx_take_opts(rc, o);
    e = retro_frame_setup(rc, (retro_mode)retro_render_mode(ref, o), p, c);
    rc->fx = NULL;
    return e;
}

const retro_family retro_family_voxel = {
    .name = "voxel",
    .reference = "naive",
    .mode_count = RETRO_MODE_COUNT,
    .mode_names = retro_voxel_mode_names,
    .fx = RETRO_FX_VOXEL,
    .fx_modes = RETRO_MODE_BIT(RETRO_MODE_EXACT) | RETRO_MODE_BIT(RETRO_MODE_LOD),
    .effective_mode = voxel_effective_mode,
    .setup = voxel_setup,
};
