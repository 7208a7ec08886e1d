/* The scenes the benchmark renders: a map and the camera pose to render it from. */
#ifndef RETRO_BENCH_SCENES_H
#define RETRO_BENCH_SCENES_H

#include "render.h"
#include "retro_maps.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SCENES_MAX 16

typedef struct bench_scene {
    char name[32];  /* the map's base name: column title and part of the benchmark name */
    char origin[8]; /* "gen" for a generated map at its default view, "course" for a course
                       map at the course's test pose */
    retro_map map;
    player_t pose;  /* only x, y, angle and height matter to a frame */
} bench_scene;

/* Loads maps/alpine, maps/islands, maps/canyon at their default view, then the course maps
 * under SHARED/course at their test poses. A scene that cannot be loaded is left out with
 * a note on stderr. Returns the number of scenes stored in out (at most max). */
int scenes_load_default(bench_scene *out, int max, const char *shared);

/* Loads one map PREFIX at its default view (for tiny smoke-test scenes). Returns 0, or -1
 * with a note on stderr. */
int scenes_load_one(bench_scene *s, const char *prefix);

void scenes_free(bench_scene *s, int n);

#ifdef __cplusplus
}
#endif

#endif
