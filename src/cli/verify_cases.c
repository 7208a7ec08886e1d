/* Cases chosen to hit every edge SEMANTICS.md names: quadrant angles and their neighbours,
 * degenerate and odd screens, distances that render nothing or one sample, heights that
 * saturate the projection, positions that need wrapping, and every map size class. */
#include <limits.h>
#include <math.h>

#include "retro_scene.h"
#include "verify_cases.h"

#define VIEW NAN, NAN
#define REL 1
#define ABS 0

const verify_case verify_cases[] = {
    /* scenes at several poses */
    {"alpine", "alpine", VIEW, 0, 60, REL, 640, 480, 800, 1},
    {"alpine-pose2", "alpine", 100.5, 900.25, 137, 90, REL, 640, 480, 800, 0},
    {"islands", "islands", VIEW, 30, 60, REL, 640, 480, 800, 0},
    {"islands-pose2", "islands", 700, 300, 250, 40, REL, 640, 480, 800, 0},
    {"canyon", "canyon", VIEW, 300, 60, REL, 640, 480, 800, 0},
    {"canyon-pose2", "canyon", 10.75, 1000.5, 200, 120, REL, 640, 480, 800, 0},
    {"course-valley01", "course/valley", 997.808716, 559.177063, 0, 230, ABS, 640, 480, 800, 1},
    {"course-island01", "course/island", 147.436798, 539.899414, 0, 88, ABS, 800, 600, 600, 0},
    {"course-pyramids01", "course/pyramids", 110.388893, 887.813843, 0, 164, ABS, 640, 480, 800, 0},
    {"course-valley-a77", "course/valley", 512.5, 100.25, 77, 200, ABS, 640, 480, 800, 0},
    {"course-island-a200", "course/island", 800, 800, 200, 120, ABS, 320, 240, 1000, 1},
    /* angles */
    {"angle-0", "test/alpine-200", VIEW, 0, 50, REL, 160, 120, 300, 1},
    {"angle-90", "test/alpine-200", VIEW, 90, 50, REL, 160, 120, 300, 1},
    {"angle-180", "test/alpine-200", VIEW, 180, 50, REL, 160, 120, 300, 1},
    {"angle-270", "test/alpine-200", VIEW, 270, 50, REL, 160, 120, 300, 1},
    {"angle-1", "test/alpine-200", VIEW, 1, 50, REL, 160, 120, 300, 0},
    {"angle-45", "test/alpine-200", VIEW, 45, 50, REL, 160, 120, 300, 1},
    {"angle-89", "test/alpine-200", VIEW, 89, 50, REL, 160, 120, 300, 0},
    {"angle-359", "test/alpine-200", VIEW, 359, 50, REL, 160, 120, 300, 0},
    {"angle--1", "test/alpine-200", VIEW, -1, 50, REL, 160, 120, 300, 1},
    {"angle-725", "test/alpine-200", VIEW, 725, 50, REL, 160, 120, 300, 1},
    /* screens */
    {"screen-1x1", "alpine", VIEW, 10, 60, REL, 1, 1, 800, 1},
    {"screen-1x480", "alpine", VIEW, 10, 60, REL, 1, 480, 800, 1},
    {"screen-640x1", "alpine", VIEW, 10, 60, REL, 640, 1, 800, 1},
    {"screen-2x2", "alpine", VIEW, 10, 60, REL, 2, 2, 800, 1},
    {"screen-641x479", "alpine", VIEW, 10, 60, REL, 641, 479, 800, 0},
    {"screen-640x480", "alpine", VIEW, 10, 60, REL, 640, 480, 800, 0},
    {"screen-1920x1080", "alpine", VIEW, 10, 60, REL, 1920, 1080, 800, 0},
    /* taller than the SIMD course tile (RETRO_SIMD_COURSE_ROWS): painted straight into out */
    {"screen-40x1081", "alpine", VIEW, 10, 60, REL, 40, 1081, 800, 1},
    /* distances */
    {"dist-0", "alpine", VIEW, 20, 60, REL, 320, 240, 0, 1},
    {"dist-1", "alpine", VIEW, 20, 60, REL, 320, 240, 1, 1},
    {"dist-2", "alpine", VIEW, 20, 60, REL, 320, 240, 2, 1},
    {"dist-800", "alpine", VIEW, 20, 60, REL, 320, 240, 800, 0},
    {"dist-5000", "alpine", VIEW, 20, 60, REL, 320, 240, 5000, 0},
    /* heights */
    {"height-below", "alpine", VIEW, 0, -1000, ABS, 320, 240, 800, 1},
    {"height-ground", "alpine", VIEW, 0, 0, REL, 320, 240, 800, 1},
    {"height-above", "alpine", VIEW, 0, 5000, ABS, 320, 240, 800, 0},
    {"height-INT_MIN", "alpine", VIEW, 0, INT_MIN, ABS, 320, 240, 800, 1},
    {"height-INT_MAX", "alpine", VIEW, 0, INT_MAX, ABS, 320, 240, 800, 1},
    /* positions */
    {"pos-negative", "alpine", -300.5, -77.25, 33, 150, ABS, 320, 240, 800, 1},
    {"pos-beyond-S", "alpine", 1024 + 13.5, 3 * 1024 + 1, 210, 150, ABS, 320, 240, 800, 1},
    {"pos-1e6", "alpine", 1e6, 1e6, 123, 150, ABS, 320, 240, 800, 1},
    {"pos-cell-edge", "alpine", 100.0, 200.0, 0, 150, ABS, 320, 240, 800, 1},
    {"pos-cell-edge-90", "test/checker-1000", 8.0, 16.0, 90, 100, ABS, 320, 240, 800, 1},
    /* map sizes */
    {"size-1", "test/flat-1", 0.5, 0.5, 10, 60, ABS, 64, 48, 50, 1},
    {"size-2", "test/checker-2", 0.5, 1.5, 10, 30, ABS, 64, 48, 50, 1},
    {"size-3", "test/ramp-3", 1.5, 1.5, 200, 300, ABS, 64, 48, 50, 1},
    {"size-1000", "test/ramp-1000", VIEW, 45, 80, REL, 320, 240, 800, 0},
    {"size-1000-checker", "test/checker-1000", VIEW, 300, 40, REL, 320, 240, 800, 1},
    {"size-1024", "alpine", VIEW, 135, 60, REL, 320, 240, 800, 0},
};

const int verify_case_count = (int)(sizeof verify_cases / sizeof verify_cases[0]);

/* Each effect alone, then the combinations the default scenes use and a few more. */
const verify_fx_case verify_fx_cases[] = {
    {"fx-fog-linear", "islands", 30, RETRO_FX_FOG, 0, 0, 1},
    {"fx-fog-exp", "islands", 30, RETRO_FX_FOG, 1, 0, 0},
    {"fx-shade", "alpine", 0, RETRO_FX_SHADE, 0, 0, 1},
    {"fx-water", "islands", 200, RETRO_FX_WATER, 0, 0, 1},
    {"fx-bilinear", "canyon", 45, RETRO_FX_BILINEAR, 0, 0, 1},
    {"fx-lod", "alpine", 100, RETRO_FX_LOD, 0, 0, 0},
    {"fx-horizon-up", "canyon", 0, RETRO_FX_HORIZON, 0, 60, 0},
    {"fx-horizon-down", "canyon", 0, RETRO_FX_HORIZON, 0, -80, 0},
    {"fx-morph", "islands", 300, RETRO_FX_MORPH, 0, 0, 0},
    {"fx-water-fog", "islands", 10, RETRO_FX_WATER | RETRO_FX_FOG, 0, 0, 1},
    {"fx-morph-water", "islands", 120, RETRO_FX_MORPH | RETRO_FX_WATER, 0, 0, 1},
    {"fx-lod-fog-bilinear", "alpine", 250, RETRO_FX_LOD | RETRO_FX_FOG | RETRO_FX_BILINEAR, 0, 0, 1},
    {"fx-all", "alpine", 333, RETRO_FX_VOXEL, 1, 25, 1},
};

const int verify_fx_case_count = (int)(sizeof verify_fx_cases / sizeof verify_fx_cases[0]);
