/* The voxel family: height-map terrain by ray marching (SEMANTICS.md), reference naive. Its
 * frames are built by retro_frame_setup() (frame.c); its kernels receive a const retro_frame *. */
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

const retro_family retro_family_voxel = {
    .name = "voxel",
    .reference = "naive",
    .mode_count = RETRO_MODE_COUNT,
    .mode_names = retro_voxel_mode_names,
    .fx = RETRO_FX_VOXEL,
    .effective_mode = voxel_effective_mode,
    .setup = voxel_setup,
};
