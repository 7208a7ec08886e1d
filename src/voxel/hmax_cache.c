/* The height map's maximum, cached per map pointer and size (hmax_cache.h). */
#include <stddef.h>

#include "hmax_cache.h"

int retro_hmax_get(retro_hmax_cache *hc, const uint8_t *map, int S)
{
    if (hc->map != map || hc->size != S) {
        size_t n = (size_t)S * (size_t)S;
        uint8_t m = 0;
        for (size_t i = 0; i < n; i++)
            m = map[i] > m ? map[i] : m;
        hc->value = m;
        hc->map = map;
        hc->size = S;
    }
    return hc->value;
}

void retro_hmax_stale(retro_hmax_cache *hc)
{
    hc->map = NULL;
}
