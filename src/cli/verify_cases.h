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

#endif
