/* The SIMD kernels' packed map: colour | height in one uint32 per cell, tiled, so one load or
 * gather fetches both. simd_map.c builds it and owns this state; a context holds one. */
#ifndef RETRO_SIMD_MAP_H
#define RETRO_SIMD_MAP_H

#include <stddef.h>
#include <stdint.h>

/* One context's packed map (retro_ctx.packed). Rebuilt only when the map pointers or S
 * change; like the height maximum, retro_ctx_map_changed() after editing a map in place. All
 * zero is empty. */
typedef struct retro_packed_map {
    uint32_t *cells;              /* capacity cap cells, 64-byte aligned */
    size_t cap;
    const uint8_t *height_map;    /* the maps cells was built from */
    const uint32_t *color_map;
    int size;
    int ok;                       /* every colour had a zero low byte: packing is lossless */
    /* a threaded kernel offered cells to the strips of the frame just set up (frame setup
     * clears it, retro_simd_offer_packed sets it): strips read the maps themselves otherwise */
    int offered;
} retro_packed_map;

/* The next use packs again (a map was edited in place). */
void retro_packed_map_stale(retro_packed_map *pm);
void retro_packed_map_free(retro_packed_map *pm);

#endif
