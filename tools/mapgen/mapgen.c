/* Map generation: the analytic maps whose images tests can predict by reasoning, and the
 * dispatch to the fractal terrain of mapgen_terrain.c. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "retro_maps.h"

const char *const retro_mapgen_styles[] = {"alpine", "islands", "canyon", "flat",
                                           "ramp",   "spike",   "checker", NULL};

#define RGB(r, g, b) ((uint32_t)(r) << 24 | (uint32_t)(g) << 16 | (uint32_t)(b) << 8)

/* flat: height 50 everywhere, one colour, so every column of a frame is the same. */
static void flat(retro_map *m)
{
    size_t n = (size_t)m->size * (size_t)m->size;
    memset(m->height, 50, n);
    for (size_t i = 0; i < n; i++)
        m->color[i] = RGB(60, 140, 60);
}

/* ramp: height rises with x from 0 to 255; colour encodes the column so samples can be traced. */
static void ramp(retro_map *m)
{
    int S = m->size;
    for (int j = 0; j < S; j++)
        for (int i = 0; i < S; i++) {
            int h = S > 1 ? (int)((long)i * 255 / (S - 1)) : 0;
            m->height[(size_t)j * (size_t)S + (size_t)i] = (uint8_t)h;
            m->color[(size_t)j * (size_t)S + (size_t)i] = RGB(h, 255 - h, (i * 7) & 255);
        }
}

/* spike: ground 0, one cell of height 255 at (S/2, S/2) in red. */
static void spike(retro_map *m)
{
    int S = m->size;
    size_t n = (size_t)S * (size_t)S, c = (size_t)(S / 2) * (size_t)S + (size_t)(S / 2);
    for (size_t i = 0; i < n; i++) {
        m->height[i] = 0;
        m->color[i] = RGB(40, 120, 40);
    }
    m->height[c] = 255;
    m->color[c] = RGB(255, 0, 0);
}

/* checker: 8x8-cell blocks alternating height 0 and 64 and two colours. */
static void checker(retro_map *m)
{
    int S = m->size;
    for (int j = 0; j < S; j++)
        for (int i = 0; i < S; i++) {
            int odd = ((i >> 3) ^ (j >> 3)) & 1;
            m->height[(size_t)j * (size_t)S + (size_t)i] = (uint8_t)(odd ? 64 : 0);
            m->color[(size_t)j * (size_t)S + (size_t)i] = odd ? RGB(230, 230, 230) : RGB(30, 30, 30);
        }
}

int retro_mapgen(const char *style, uint64_t seed, int size, retro_map *m, char *err, size_t n)
{
    if (retro_map_alloc(m, size, err, n))
        return -1;
    if (!strcmp(style, "flat"))
        flat(m);
    else if (!strcmp(style, "ramp"))
        ramp(m);
    else if (!strcmp(style, "spike"))
        spike(m);
    else if (!strcmp(style, "checker"))
        checker(m);
    else if (retro_terrain_generate(style, seed, m) != 0) {
        retro_map_free(m);
        if (err && n)
            snprintf(err, n, "unknown map style '%s'", style);
        return -1;
    }
    return 0;
}
