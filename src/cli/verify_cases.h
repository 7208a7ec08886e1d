/* The fixed set of cases `retro verify` renders with every kernel (see README, "verify"). */
#ifndef RETRO_VERIFY_CASES_H
#define RETRO_VERIFY_CASES_H

#include <stdint.h>

typedef struct verify_case {
    const char *name;
    const char *map;   /* maps/NAME, or "course/NAME" for ../shared/course/NAME */
    double x, y;       /* position; NAN = the map's default view */
    int angle;
    int64_t height;    /* camera height, or above the ground when rel_height */
    int rel_height;
    int W, H, D;
    int quick;         /* also in the reduced set `make check` runs */
} verify_case;

extern const verify_case verify_cases[];
extern const int verify_case_count;

/* Effect cases (docs/EFFECTS.md): mode exact at the map's default view turned by angle, with
 * the effects' default parameters; morph blends toward the inverted height map. */
typedef struct verify_fx_case {
    const char *name;
    const char *map;
    int angle;
    unsigned fx;       /* RETRO_FX_* */
    int fog_exp;
    int pitch;
    int quick;
} verify_fx_case;

extern const verify_fx_case verify_fx_cases[];
extern const int verify_fx_case_count;

/* Mesh cases (docs/MESH.md): every mode of the mesh family, mesh-zbuffer against the other
 * mesh kernels; the effects' default parameters (horizon pitch 40, morph toward the inverted
 * heights at t = 0.37). Small screens: the mesh reference is the slowest kernel. */
typedef struct verify_mesh_case {
    const char *name;
    const char *map;
    double x, y;       /* NAN: the map's default view */
    int angle;
    int64_t height;
    int rel_height;
    int W, H, D;
    unsigned fx;       /* RETRO_FX_* of the mesh family */
    int quick;
} verify_mesh_case;

extern const verify_mesh_case verify_mesh_cases[];
extern const int verify_mesh_case_count;

/* Writes OUTDIR/NAME.png (creating results/ and OUTDIR): ref dimmed, pixels where got differs
 * in magenta, so a mismatch can be seen at a glance. Errors are printed, not returned. */
void verify_write_diff(const char *outdir, const char *name, const uint32_t *ref, const uint32_t *got, int W,
                       int H);

#endif
