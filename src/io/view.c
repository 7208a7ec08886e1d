/* The default camera: somewhere every map shows terrain from, without the caller knowing it. */
#include "retro_maps.h"

void retro_default_view(const retro_map *m, struct retro_view *v)
{
    int S = m->size;
    size_t n = (size_t)S * (size_t)S, sum = 0;
    for (size_t i = 0; i < n; i++)
        sum += m->height[i];
    int mean = (int)(sum / n);
    int here = m->height[(size_t)(S / 2) * (size_t)S + (size_t)(S / 2)];
    v->x = (float)S / 2;
    v->y = (float)S / 2;
    v->angle = 0;
    v->height = (here > mean ? here : mean) + 60;
}
