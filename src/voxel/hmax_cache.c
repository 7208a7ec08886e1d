/* The height map's maximum, cached per map pointer and size (hmax_cache.h). */
#include <stddef.h>
#include <string.h>

#include "hmax_cache.h"

/* 16 bytes in a GCC/Clang vector (SSE2 on x86-64). */
typedef uint8_t retro_v16u8 __attribute__((vector_size(16)));

static inline retro_v16u8 v16_max(retro_v16u8 a, retro_v16u8 b)
{
    const retro_v16u8 gt = (retro_v16u8)(a > b);
    return (a & gt) | (b & ~gt);
}

/* Callers that cannot keep the cache (the submission drops it every call) scan the whole map
 * every frame, so the scan keeps four independent maxima in flight: one running maximum is a
 * chain of dependent steps, and at -O2 the compiler keeps it one byte at a time. */
uint8_t retro_map_max(const uint8_t *map, size_t n)
{
    retro_v16u8 a0 = {0}, a1 = {0}, a2 = {0}, a3 = {0};
    size_t i = 0;
    for (; i + 64 <= n; i += 64) {
        retro_v16u8 x0, x1, x2, x3;
        memcpy(&x0, map + i, 16);
        memcpy(&x1, map + i + 16, 16);
        memcpy(&x2, map + i + 32, 16);
        memcpy(&x3, map + i + 48, 16);
        a0 = v16_max(a0, x0);
        a1 = v16_max(a1, x1);
        a2 = v16_max(a2, x2);
        a3 = v16_max(a3, x3);
    }
    a0 = v16_max(v16_max(a0, a1), v16_max(a2, a3));
    uint8_t m = 0;
    for (int j = 0; j < 16; j++)
        m = a0[j] > m ? a0[j] : m;
    for (; i < n; i++)
        m = map[i] > m ? map[i] : m;
    return m;
}

int retro_hmax_get_by(retro_hmax_cache *hc, const uint8_t *map, int S, retro_map_scan scan, void *arg)
{
    if (hc->map != map || hc->size != S) {
        const size_t n = (size_t)S * (size_t)S;
        hc->value = scan ? scan(arg, map, n) : retro_map_max(map, n);
        hc->map = map;
        hc->size = S;
    }
    return hc->value;
}

int retro_hmax_get(retro_hmax_cache *hc, const uint8_t *map, int S)
{
    return retro_hmax_get_by(hc, map, S, NULL, NULL);
}

void retro_hmax_stale(retro_hmax_cache *hc)
{
    hc->map = NULL;
}

