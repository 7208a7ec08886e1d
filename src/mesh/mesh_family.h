/* The mesh family's state inside retro_ctx and its kernel rows' entry points (family.c). */
#ifndef RETRO_MESH_FAMILY_H
#define RETRO_MESH_FAMILY_H

#include "retro.h"
#include "retro_mesh.h"

/* What setup hands the family's kernels: the module's context and one frame's inputs. */
struct retro_mesh_state {
    retro_mesh_ctx *mc;
    player_t p;
    ctx_t c;
    retro_effects fx;      /* the scene's effects without `cull` (turned into opts) */
    retro_mesh_opts opts;  /* nocull unless the scene asks for cull */
    retro_mesh_mode mode;
    retro_mesh_stats stats; /* the last frame's counts */
    retro_err status;       /* the last setup's or frame's status */
};

void retro_mesh_state_free(retro_mesh_state *st);
/* Renders the frame setup built with the module's kernel: every row's function is this call. */
void retro_mesh_family_run(const void *frame, retro_ctx *rc, retro_mesh_kernel kernel);

void retro_kernel_mesh_zbuffer(const void *frame, retro_ctx *rc);
void retro_kernel_mesh_painter(const void *frame, retro_ctx *rc);
void retro_kernel_mesh_avx2(const void *frame, retro_ctx *rc);
void retro_kernel_mesh_avx512(const void *frame, retro_ctx *rc);
void retro_kernel_mesh_omp(const void *frame, retro_ctx *rc);

#endif
