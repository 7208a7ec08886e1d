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

#endif
