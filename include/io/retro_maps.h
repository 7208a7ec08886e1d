/* Maps and images: loading height/colour maps, writing frames, generating terrain.
 * Every function that can fail fills err (one line naming the problem) and returns -1. */
#ifndef RETRO_MAPS_H
#define RETRO_MAPS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct retro_map {
    int size;          /* S: both maps hold S*S entries, row-major, entry 0 top-left */
    uint8_t *height;
    uint32_t *color;   /* R<<24 | G<<16 | B<<8 */
} retro_map;

/* Loads PREFIX.pgm and PREFIX.ppm (or PREFIX.png when there is no .ppm). */
int retro_map_load(const char *prefix, retro_map *m, char *err, size_t errlen);
/* Allocates an S*S map (zeroed). */
int retro_map_alloc(retro_map *m, int size, char *err, size_t errlen);
void retro_map_free(retro_map *m);
/* Writes PREFIX.pgm and PREFIX.ppm (PREFIX.png when png is non-zero). */
int retro_map_save(const char *prefix, const retro_map *m, int png, char *err, size_t errlen);

/* 8-bit PGM (P5, maxval 255). *data is malloc'd. */
int retro_pgm_read(const char *path, uint8_t **data, int *w, int *h, char *err, size_t errlen);
/* PPM (P6, maxval 255) or PNG, chosen by the file's magic bytes; *data is packed RGB, malloc'd. */
int retro_rgb_read(const char *path, uint32_t **data, int *w, int *h, char *err, size_t errlen);

/* Writes packed RGB as PPM or PNG (by the path's extension) through a temporary file renamed
 * into place, so a failure leaves nothing at path. */
int retro_image_write(const char *path, const uint32_t *px, int w, int h, char *err,
                      size_t errlen);
int retro_gray_write(const char *path, const uint8_t *px, int w, int h, char *err,
                     size_t errlen);

/* Procedural and analytic maps, deterministic from (style, seed, size).
 * Terrain styles: alpine, islands, canyon. Analytic: flat, ramp, spike, checker. */
int retro_mapgen(const char *style, uint64_t seed, int size, retro_map *m, char *err,
                 size_t errlen);
/* The styles, NULL-terminated, for --help. */
extern const char *const retro_mapgen_styles[];

/* Fractal terrain (tools/mapgen/mapgen_terrain.c): style is alpine, islands or canyon.
 * Returns -1 for another style. The map must already be allocated with m->size set. */
int retro_terrain_generate(const char *style, uint64_t seed, retro_map *m);

/* A good default view of a map: its centre, looking along +x, 60 above the terrain there
 * and never below the map's mean height + 60 (src/io/view.c). Fills x, y, angle, height. */
struct retro_view {
    float x, y;
    int angle, height;
};
void retro_default_view(const retro_map *m, struct retro_view *v);

#ifdef __cplusplus
}
#endif

#endif
