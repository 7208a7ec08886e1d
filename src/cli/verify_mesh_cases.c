/* The mesh family's verify cases: the voxel cases' edges (quadrant angles, degenerate
 * screens, distances, heights, wrapped positions, map sizes 1, 2, 3) at sizes the mesh
 * reference renders quickly, and each effect, with and without back-face culling (the
 * painter's documented difference appears only without it). */
#include <limits.h>
#include <math.h>

#include "retro_scene.h"
#include "verify_cases.h"

#define VIEW NAN, NAN
#define REL 1
#define ABS 0
#define CULL RETRO_FX_CULL

const verify_mesh_case verify_mesh_cases[] = {
    {"mesh-alpine", "alpine", VIEW, 0, 60, REL, 160, 120, 400, CULL, 1},
    {"mesh-alpine-nocull", "alpine", VIEW, 0, 60, REL, 160, 120, 400, 0, 1},
    {"mesh-course-island", "course/island", 800, 800, 200, 120, ABS, 160, 120, 400, CULL, 0},
    {"mesh-angle-0", "test/alpine-200", VIEW, 0, 50, REL, 96, 72, 200, CULL, 1},
    {"mesh-angle-90", "test/alpine-200", VIEW, 90, 50, REL, 96, 72, 200, CULL, 1},
    {"mesh-angle-180", "test/alpine-200", VIEW, 180, 50, REL, 96, 72, 200, 0, 0},
    {"mesh-angle-270", "test/alpine-200", VIEW, 270, 50, REL, 96, 72, 200, CULL, 0},
    {"mesh-angle-45", "test/alpine-200", VIEW, 45, 50, REL, 96, 72, 200, 0, 1},
    {"mesh-angle--1", "test/alpine-200", VIEW, -1, 50, REL, 96, 72, 200, CULL, 0},
    {"mesh-screen-1x1", "test/alpine-200", VIEW, 10, 60, REL, 1, 1, 200, CULL, 1},
    {"mesh-screen-1x72", "test/alpine-200", VIEW, 10, 60, REL, 1, 72, 200, 0, 1},
    {"mesh-screen-97x1", "test/alpine-200", VIEW, 10, 60, REL, 97, 1, 200, CULL, 1},
    {"mesh-dist-0", "test/alpine-200", VIEW, 20, 60, REL, 64, 48, 0, CULL, 1},
    {"mesh-dist-1", "test/alpine-200", VIEW, 20, 60, REL, 64, 48, 1, 0, 1},
    {"mesh-dist-2", "test/alpine-200", VIEW, 20, 60, REL, 64, 48, 2, CULL, 1},
    {"mesh-height-below", "test/alpine-200", VIEW, 0, -1000, ABS, 96, 72, 200, CULL, 1},
    {"mesh-height-ground", "test/alpine-200", VIEW, 0, 0, REL, 96, 72, 200, 0, 1},
    {"mesh-height-INT_MIN", "test/alpine-200", VIEW, 0, INT_MIN, ABS, 64, 48, 200, CULL, 0},
    {"mesh-height-INT_MAX", "test/alpine-200", VIEW, 0, INT_MAX, ABS, 64, 48, 200, CULL, 0},
    {"mesh-pos-negative", "test/alpine-200", -300.5, -77.25, 33, 150, ABS, 96, 72, 200, CULL, 1},
    {"mesh-pos-1e6", "test/alpine-200", 1e6, 1e6, 123, 150, ABS, 96, 72, 200, 0, 0},
    {"mesh-size-1", "test/flat-1", 0.5, 0.5, 10, 60, ABS, 64, 48, 50, CULL, 1},
    {"mesh-size-2", "test/checker-2", 0.5, 1.5, 10, 30, ABS, 64, 48, 50, 0, 1},
    {"mesh-size-3", "test/ramp-3", 1.5, 1.5, 200, 300, ABS, 64, 48, 50, CULL, 1},
    /* effects at the default view of a 200-cell map */
    {"mesh-fx-fog", "test/alpine-200", VIEW, 30, 50, REL, 96, 72, 200, CULL | RETRO_FX_FOG, 1},
    {"mesh-fx-shade", "test/alpine-200", VIEW, 60, 50, REL, 96, 72, 200, CULL | RETRO_FX_SHADE, 1},
    {"mesh-fx-water", "test/alpine-200", VIEW, 200, 50, REL, 96, 72, 200, CULL | RETRO_FX_WATER, 1},
    {"mesh-fx-morph", "test/alpine-200", VIEW, 300, 50, REL, 96, 72, 200, CULL | RETRO_FX_MORPH, 0},
    {"mesh-fx-horizon", "test/alpine-200", VIEW, 0, 50, REL, 96, 72, 200, CULL | RETRO_FX_HORIZON, 0},
    {"mesh-fx-texture", "test/alpine-200", VIEW, 45, 50, REL, 96, 72, 200, CULL | RETRO_FX_TEXTURE, 1},
    {"mesh-fx-gouraud-nocull", "test/alpine-200", VIEW, 135, 50, REL, 96, 72, 200, RETRO_FX_GOURAUD, 1},
    {"mesh-fx-wireframe", "test/alpine-200", VIEW, 225, 50, REL, 96, 72, 200, CULL | RETRO_FX_WIREFRAME, 1},
    {"mesh-fx-all", "test/alpine-200", VIEW, 333, 50, REL, 96, 72, 200,
     RETRO_FX_MESH & ~(unsigned)RETRO_FX_GOURAUD, 1},
    /* the same without water, so that mesh-painter renders it too */
    {"mesh-fx-all-dry", "test/alpine-200", VIEW, 333, 50, REL, 96, 72, 200,
     RETRO_FX_MESH & ~(unsigned)(RETRO_FX_GOURAUD | RETRO_FX_WATER), 1},
};

const int verify_mesh_case_count = (int)(sizeof verify_mesh_cases / sizeof verify_mesh_cases[0]);
