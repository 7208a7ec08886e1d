/* A peer algorithm, not a retro kernel: the classic voxel-space demo's traversal (s-macke's
 * VoxelSpace, "front to back" version), so its speed and its error against mode truth sit in the
 * same tables as retro's kernels. It renders its own image: it is outside `retro verify`. */
#ifndef RETRO_PEER_VOXELSPACE_H
#define RETRO_PEER_VOXELSPACE_H

#include "render.h"

/* The demo's step growth: its distance step starts at 1 and grows by this each distance. */
#define PEER_VOXELSPACE_DZ_GROWTH 0.2f

/* Renders p's view into c->out (W*H). ybuf is the caller's scratch of c->scr_width ints, so a
 * frame allocates nothing. Returns 0, or -1 (nothing written) on input retro would refuse:
 * W, H or S below 1, a null map or output, a non-finite position, dz_growth < 0 or not finite. */
int peer_voxelspace_render(const player_t *p, ctx_t *c, float dz_growth, int *ybuf);

#endif
