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

void ref_exact_render(const player_t *p, ctx_t *c)
{
    const int W = c->scr_width, H = c->scr_height, S = c->map_size, D = c->distance;
    int A = (int)floor_mod(p->angle, 360);
    double deg = (double)(A % 90);
    float c0 = (float)cos(deg * 3.14159265358979323846 / 180.0), s0 = (float)sin(deg * 3.14159265358979323846 / 180.0);
    float cs, sn;
    switch (A / 90) {
    case 0: cs = c0; sn = s0; break;
    case 1: cs = -s0; sn = c0; break;
    case 2: cs = -c0; sn = -s0; break;
    default: cs = s0; sn = -c0; break;
    }
    double wx = fmod((double)p->x, S), wy = fmod((double)p->y, S);
    float x0 = (float)(wx < 0 ? wx + S : wx), y0 = (float)(wy < 0 ? wy + S : wy);
    int *first = malloc(sizeof(int) * (size_t)(H + 1)); /* row -> nearest d reaching it */
    uint32_t *col = malloc(sizeof(uint32_t) * (size_t)(H + 1));
    for (int u = 1; u <= W; u++) {
        float t = W == 1 ? 0.0f : (float)(2 * (u - 1) - (W - 1)) / (float)(W - 1);
        float rx = cs + t * sn, ry = t * cs - sn;
        for (int r = 1; r <= H; r++)
            first[r] = 0;
        for (int d = D - 1; d >= 1; d--) {
            float qx = x0 + (float)d * rx, qy = y0 + (float)d * ry;
            int64_t i = floor_mod((int64_t)floorf(qx), S), j = floor_mod((int64_t)floorf(qy), S);
            int64_t idx = j * S + i;
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
