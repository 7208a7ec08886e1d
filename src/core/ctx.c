/* The rendering context's lifetime (ctx.h): made empty, each cache freed by the file that owns
 * it, and every per-map cache dropped together when a map changes. */
#include <stdlib.h>

#include "ctx.h"
#include "pt_pool.h"
#include "retro_internal.h"
#ifndef RETRO_SUBMISSION /* the submission has no pool, pyramid or mesh family */
#include "hmax_pyramid.h"
#include "mesh_family.h"
#endif

retro_ctx *retro_ctx_new(void)
{
    return calloc(1, sizeof(retro_ctx));
}

void retro_ctx_free(retro_ctx *rc)
{
    if (!rc)
        return;
    free(rc->rx);
    free(rc->ry);
    free(rc->kd);
    free(rc->lx);
    free(rc->ly);
    free(rc->sx);
    free(rc->sy);
    free(rc->vcap);
    free(rc->ybuf);
    free(rc->qx);
    free(rc->qy);
    free(rc->tscratch);
    free(rc->rxd);
    free(rc->ryd);
    free(rc->kdd);
    free(rc->rx_q);
    free(rc->ry_q);
    free(rc->kd_q);
    free(rc->dist);
    free(rc->fog);
    retro_effects_bake_free(&rc->bake);
    retro_packed_map_free(&rc->packed);
    retro_pt_pool_free(rc->pt_pool);
#ifndef RETRO_SUBMISSION
    retro_pool_free(rc);
    retro_mesh_state_free(rc->mesh);
    if (rc->pyr)
        retro_pyramid_free(rc->pyr);
    free(rc->pyr);
    if (rc->pyr_course)
        retro_pyramid_free(rc->pyr_course);
    free(rc->pyr_course);
#endif
    free(rc);
}

void retro_ctx_map_changed(retro_ctx *rc)
{
    if (!rc)
        return;
    retro_effects_bake_stale(&rc->bake);
    retro_ctx_maps_rewritten(rc);
}

void retro_ctx_maps_rewritten(retro_ctx *rc)
{
    retro_hmax_stale(&rc->hmax);
    retro_packed_map_stale(&rc->packed);
#ifndef RETRO_SUBMISSION
    if (rc->pyr)
        retro_pyramid_stale(rc->pyr);
    if (rc->pyr_course)
        retro_pyramid_stale(rc->pyr_course);
#endif
}

const retro_frame *retro_ctx_frame(const retro_ctx *rc)
{
    return &rc->frame;
}
