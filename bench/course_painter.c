/* The plain course painter: mode course exactly as SEMANTICS.md writes it (sky fill, then
 * back to front, one draw_line per sample), as a student's render.c would be. It is the
 * baseline of the submission's speed target (issue 9), built with the course's -O3. */
#include <math.h>
#include <stdint.h>

#include "render.h"

static float float_mod(float f, float k)
{
    float res = fmodf(f, k);
    if (res < 0)
        res += k;
    if (res >= k)
        res = 0;
    return res;
}

static void line(ctx_t *c, int u, int v_to, uint32_t color)
{
    for (int r = 1; r <= v_to; r++)
        c->out[(c->scr_height - r) * c->scr_width + (u - 1)] = color;
}

void painter_render(const player_t *p, ctx_t *c)
{
    const int W = c->scr_width, H = c->scr_height, S = c->map_size;
    for (int i = 0; i < W * H; i++)
        c->out[i] = c->sky_color;
    float phi = (float)(p->angle * 3.14159265358979323846 / 180.0);
    for (int d = c->distance - 1; d >= 1; d--) {
        float a = cosf(phi) * (float)d, b = sinf(phi) * (float)d;
        float lx = (p->x + a) - b, ly = (p->y - b) - a, rx = (p->x + a) + b, ry = (p->y - b) + a;
        float sx = (rx - lx) / (float)W, sy = (ry - ly) / (float)W, qx = lx, qy = ly;
        for (int u = 1; u <= W; u++) {
            int i = (int)float_mod(qx, (float)(S - 1)), j = (int)float_mod(qy, (float)(S - 1));
            int idx = j * S + i;
            int v = (int)((float)(W / 2) * (float)(c->height_map[idx] - p->height) / (float)d) + H / 2;
            v = v < 0 ? 0 : v > H ? H : v;
            line(c, u, v, c->color_map[idx]);
            qx += sx;
            qy += sy;
        }
    }
}
