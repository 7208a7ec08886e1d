/* Mode exact, pixel by pixel: for each pixel the nearest sample whose projected height
 * reaches it. Column-wise to stay fast enough for tests, but the definition is the same. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "ref_exact.h"

static int64_t floor_mod(int64_t a, int64_t m)
{
    int64_t r = a % m;
    return r < 0 ? r + m : r;
}

ref_view ref_exact_view(const player_t *p, int S)
{
    int A = (int)floor_mod(p->angle, 360);
    double deg = (double)(A % 90);
    float c0 = (float)cos(deg * 3.14159265358979323846 / 180.0), s0 = (float)sin(deg * 3.14159265358979323846 / 180.0);
    ref_view v;
    switch (A / 90) {
    case 0: v.cs = c0; v.sn = s0; break;
    case 1: v.cs = -s0; v.sn = c0; break;
    case 2: v.cs = -c0; v.sn = -s0; break;
    default: v.cs = s0; v.sn = -c0; break;
    }
    double wx = fmod((double)p->x, S), wy = fmod((double)p->y, S);
    v.x0 = (float)(wx < 0 ? wx + S : wx);
    v.y0 = (float)(wy < 0 ? wy + S : wy);
    return v;
}

size_t ref_exact_cell(const ref_view *v, int W, int S, int u, int d)
{
    float t = W == 1 ? 0.0f : (float)(2 * (u - 1) - (W - 1)) / (float)(W - 1);
    float rx = v->cs + t * v->sn, ry = t * v->cs - v->sn;
    float qx = v->x0 + (float)d * rx, qy = v->y0 + (float)d * ry;
    int64_t i = floor_mod((int64_t)floorf(qx), S), j = floor_mod((int64_t)floorf(qy), S);
    return (size_t)(j * S + i);
}

void ref_exact_render(const player_t *p, ctx_t *c)
{
    const int W = c->scr_width, H = c->scr_height, S = c->map_size, D = c->distance;
    const ref_view view = ref_exact_view(p, S);
    int *first = malloc(sizeof(int) * (size_t)(H + 1)); /* row -> nearest d reaching it */
    uint32_t *col = malloc(sizeof(uint32_t) * (size_t)(H + 1));
    for (int u = 1; u <= W; u++) {
        for (int r = 1; r <= H; r++)
            first[r] = 0;
        for (int d = D - 1; d >= 1; d--) {
            size_t idx = ref_exact_cell(&view, W, S, u, d);
            float k = (0.5f * (float)W) / (float)d;
            float delta = (float)((int64_t)c->height_map[idx] - (int64_t)p->height);
            float vf = k * delta + 0.5f * (float)H;
            int v = vf >= (float)H ? H : vf >= 0 ? (int)floorf(vf) : 0;
            /* Walking d downward, the last d to reach a row is the smallest. */
            for (int r = 1; r <= v; r++) {
                first[r] = d;
                col[r] = c->color_map[idx];
            }
        }
        for (int r = 1; r <= H; r++)
            c->out[(size_t)(H - r) * (size_t)W + (size_t)(u - 1)] = first[r] ? col[r] : c->sky_color;
    }
    free(first);
    free(col);
}
