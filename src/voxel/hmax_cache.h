/* The height map's maximum, cached per map: every mode's early exits and row caps need it,
 * and scanning S*S cells per frame would cost more than many frames' work. */
#ifndef RETRO_HMAX_CACHE_H
#define RETRO_HMAX_CACHE_H

#include <stddef.h>
#include <stdint.h>

/* One context's cache (retro_ctx.hmax). All zero is empty. */
typedef struct retro_hmax_cache {
    const uint8_t *map; /* the map whose maximum value holds, or NULL */
    int size;
    int value;
} retro_hmax_cache;

/* The largest of the n bytes at map (0 when n is 0). */
uint8_t retro_map_max(const uint8_t *map, size_t n);
/* A scan of the n bytes at map returning their largest, with the caller's arg. */
typedef uint8_t (*retro_map_scan)(void *arg, const uint8_t *map, size_t n);
/* The maximum of map (S*S cells), scanned only when map or S differ from the last call: by
 * scan(arg, ..) when scan is given (the pthreads pool's split scan), else by retro_map_max. */
int retro_hmax_get_by(retro_hmax_cache *hc, const uint8_t *map, int S, retro_map_scan scan, void *arg);
/* retro_hmax_get_by with retro_map_max. */
int retro_hmax_get(retro_hmax_cache *hc, const uint8_t *map, int S);
/* The next call scans again (the map was edited in place). */
void retro_hmax_stale(retro_hmax_cache *hc);

#endif
