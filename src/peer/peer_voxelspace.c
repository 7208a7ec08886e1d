/* The classic voxel-space traversal, written from its published description: for z from 1
 * while z < D, with a step dz that starts at 1 and grows by a constant after every distance
 * (0.2 in the demo), take the view line from the left end L = (x + a − b, y − b − a) to the
 * right end R = (x + a + b, y − b + a) (a = z·cos φ, b = z·sin φ), walk it in W steps of
 * (R − L)/W, sample the map, project, and draw each column only above what nearer distances
 * drew (the y-buffer).
 *
 * What it shares with retro, so the comparison measures the traversal and not conventions:
 * the camera and angle of mode exact (SEMANTICS.md step 1), the torus wrap floor(q) mod S, the
 * projection (0.5·W/z)·(h − height) + 0.5·H floored and clamped to [0, H], binary32. What it
 * keeps of the demo: sample distances 1, 2, 3.2, 4.6, ... (a step growing by a constant, where
 * retro's lod grows it in proportion to the distance), the position accumulated along the line,
 * and the line divided into W steps. */
#include "peer_voxelspace.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>

static float wrap_pos(float v, int S)
{
    double w = fmod((double)v, (double)S);
    return (float)(w < 0 ? w + S : w);
}

static int cell(float q, int S)
{
    long long i = (long long)floorf(q) % S;
    return (int)(i < 0 ? i + S : i);
}

int peer_voxelspace_render(const player_t *p, ctx_t *c, float dz_growth, int *ybuf)
{
    const int W = c->scr_width, H = c->scr_height, S = c->map_size, D = c->distance;
    if (W < 1 || H < 1 || S < 1 || !c->height_map || !c->color_map || !c->out || !ybuf ||
        !isfinite(p->x) || !isfinite(p->y) || !(dz_growth >= 0) || !isfinite(dz_growth))
        return -1;
    /* Mode exact's angle: exact quadrants, the remainder's cosine and sine rounded once. */
    int A = p->angle % 360;
    A += A < 0 ? 360 : 0;
    const double rad = (A % 90) * 3.14159265358979323846 / 180.0;
    const float c0 = (float)cos(rad), s0 = (float)sin(rad);
    const float cs[4] = {c0, -s0, -c0, s0}, sn[4] = {s0, c0, -s0, -c0};
    const float cphi = cs[A / 90], sphi = sn[A / 90];
    const float x0 = wrap_pos(p->x, S), y0 = wrap_pos(p->y, S);

    for (size_t i = 0; i < (size_t)W * (size_t)H; i++)
        c->out[i] = c->sky_color;
    for (int u = 0; u < W; u++)
        ybuf[u] = 0; /* rows 1..ybuf[u], from the bottom, are drawn */

    const float half_w = 0.5f * (float)W, half_h = 0.5f * (float)H;
    float z = 1.0f, dz = 1.0f;
    while (z < (float)D) {
        const float a = z * cphi, b = z * sphi;
        float qx = x0 + a - b, qy = y0 - b - a;
        const float sx = 2.0f * b / (float)W, sy = 2.0f * a / (float)W;
        const float k = half_w / z;
        for (int u = 0; u < W; u++, qx += sx, qy += sy) {
            const size_t idx = (size_t)cell(qy, S) * (size_t)S + (size_t)cell(qx, S);
            const float vf = k * (float)((int64_t)c->height_map[idx] - (int64_t)p->height) + half_h;
            const int v = vf >= (float)H ? H : vf >= 0 ? (int)floorf(vf) : 0;
            if (v <= ybuf[u])
                continue;
            const uint32_t col = c->color_map[idx];
            for (int r = ybuf[u] + 1; r <= v; r++)
                c->out[(size_t)(H - r) * (size_t)W + (size_t)u] = col;
            ybuf[u] = v;
        }
        if (z + dz == z) /* past 2^24 a float step of 1 no longer moves */
            break;
        z += dz;
        dz += dz_growth;
    }
    return 0;
}
