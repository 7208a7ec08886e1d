/* The cone map's build (cone_map.h): per sector, the wedge's offsets, then the bound of every
 * cell over them, row by row so that a row of slopes stays in cache across the offsets. */
#include "cone_map.h"

#include <stdlib.h>
#include <string.h>

#include "retro_scene.h"

typedef struct offset {
    int dx, dy;
    float inv_delta; /* 1 / delta, 0 for the neighbours (delta = 0) */
} offset;

/* Whether the square of half side hs around (cx, cy) meets the annular sector
 * {t (cos a, sin a): t >= rmin, a0 <= a <= a1}, a1 - a0 < pi: the square clipped by the
 * sector's two half-planes (Sutherland-Hodgman) is convex, so it reaches radius rmin exactly
 * when one of its vertices does. */
static int square_meets_wedge(double cx, double cy, double hs, double a0, double a1, double rmin)
{
    double px[12], py[12], qx[12], qy[12];
    int n = 4;
    px[0] = cx - hs, py[0] = cy - hs;
    px[1] = cx + hs, py[1] = cy - hs;
    px[2] = cx + hs, py[2] = cy + hs;
    px[3] = cx - hs, py[3] = cy + hs;
    /* inside: cross(u(a0), p) >= 0 (left of the ray at a0), then cross(p, u(a1)) >= 0 */
    const double nx[2] = {-sin(a0), sin(a1)}, ny[2] = {cos(a0), -cos(a1)};
    for (int k = 0; k < 2 && n > 0; k++) {
        int m = 0;
        for (int i = 0; i < n; i++) {
            const int j = (i + 1) % n;
            const double si = nx[k] * px[i] + ny[k] * py[i], sj = nx[k] * px[j] + ny[k] * py[j];
            if (si >= 0) {
                qx[m] = px[i], qy[m] = py[i], m++;
            }
            if ((si >= 0) != (sj >= 0)) {
                const double t = si / (si - sj);
                qx[m] = px[i] + t * (px[j] - px[i]), qy[m] = py[i] + t * (py[j] - py[i]), m++;
            }
        }
        memcpy(px, qx, sizeof qx);
        memcpy(py, qy, sizeof qy);
        n = m;
    }
    for (int i = 0; i < n; i++)
        if (px[i] * px[i] + py[i] * py[i] >= rmin * rmin)
            return 1;
    return 0;
}

/* The offsets of sector sigma's wedge within R, neighbours first; returns their count. */
static int wedge(int sectors, int sigma, int R, offset *out)
{
    const double pi = 3.14159265358979323846, w = pi / sectors;
    const double a = 2.0 * pi * sigma / sectors;
    int n = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int dy = -R - 1; dy <= R + 1; dy++)
            for (int dx = -R - 1; dx <= R + 1; dx++) {
                if (!dx && !dy)
                    continue;
                const int ax = abs(dx) - 1 > 0 ? abs(dx) - 1 : 0, ay = abs(dy) - 1 > 0 ? abs(dy) - 1 : 0;
                const double delta = sqrt((double)(ax * ax + ay * ay));
                if ((pass == 0) != (delta == 0.0) || delta > R)
                    continue;
                /* the wedge's angles are widened by 1e-6 for the sector's own rounding */
                if (!square_meets_wedge(dx, dy, 1.0 + RETRO_CONE_EPS, a - w - 1e-6, a + w + 1e-6, RETRO_CONE_RMIN))
                    continue;
                out[n].dx = dx;
                out[n].dy = dy;
                out[n].inv_delta = delta > 0 ? (float)(1.0 / delta) : 0.0f;
                n++;
            }
    return n;
}

int retro_cone_build(retro_cone_map *m, const uint8_t *h, int S, int sectors, int R)
{
    memset(m, 0, sizeof *m);
    if (S < 1 || sectors < RETRO_CONE_SECTORS_MIN || sectors > RETRO_CONE_SECTORS_MAX || R < 1 || R > RETRO_CONE_R_MAX)
        return -1;
    const size_t cells = (size_t)S * (size_t)S;
    const size_t side = 2 * (size_t)R + 3;
    offset *offs = malloc(side * side * sizeof *offs);
    m->b = malloc(cells * (size_t)sectors);
    m->s = malloc(cells * (size_t)sectors * sizeof *m->s);
    int16_t *col = malloc((size_t)S * sizeof *col), *base = malloc((size_t)S * sizeof *base);
    if (!offs || !m->b || !m->s || !col || !base) {
        free(offs);
        free(col);
        free(base);
        retro_cone_free(m);
        return -1;
    }
    m->S = S;
    m->sectors = sectors;
    m->R = R;
    for (int sigma = 0; sigma < sectors; sigma++) {
        const int n = wedge(sectors, sigma, R, offs);
        uint8_t *bs = m->b + (size_t)sigma * cells;
        float *ss = m->s + (size_t)sigma * cells;
        for (int j = 0; j < S; j++) {
            const uint8_t *row = h + (size_t)j * (size_t)S;
            uint8_t *brow = bs + (size_t)j * (size_t)S;
            float *srow = ss + (size_t)j * (size_t)S;
            memset(brow, 0, (size_t)S);
            for (int i = 0; i < S; i++) {
                srow[i] = 0.0f;
                base[i] = row[i];
            }
            for (int k = 0; k < n; k++) {
                const offset o = offs[k];
                const int jj = ((j + o.dy) % S + S) % S;
                const uint8_t *other = h + (size_t)jj * (size_t)S;
                /* the offset's column for every i, wrapped once: two straight runs */
                const int sh = ((o.dx % S) + S) % S;
                for (int i = 0; i < S - sh; i++)
                    col[i] = other[i + sh];
                for (int i = S - sh; i < S; i++)
                    col[i] = other[i + sh - S];
                if (o.inv_delta == 0.0f) {
                    for (int i = 0; i < S; i++) {
                        const int up = col[i] - row[i];
                        brow[i] = (uint8_t)(up > brow[i] ? up : brow[i]);
                    }
                    if (k + 1 == n || offs[k + 1].inv_delta != 0.0f) /* the apex is known: heights above it */
                        for (int i = 0; i < S; i++)
                            base[i] = (int16_t)(row[i] + brow[i]);
                } else {
                    const float inv = o.inv_delta;
                    for (int i = 0; i < S; i++) {
                        const float r = (float)(col[i] - base[i]) * inv;
                        srow[i] = r > srow[i] ? r : srow[i];
                    }
                }
            }
        }
    }
    free(offs);
    free(col);
    free(base);
    return 0;
}

void retro_cone_free(retro_cone_map *m)
{
    free(m->b);
    free(m->s);
    memset(m, 0, sizeof *m);
}

int retro_cone_sector(const retro_cone_map *m, float rx, float ry)
{
    const double pi = 3.14159265358979323846;
    const double a = atan2((double)ry, (double)rx);
    int sigma = (int)lround(a / (2.0 * pi / m->sectors));
    return ((sigma % m->sectors) + m->sectors) % m->sectors;
}

int retro_cone_applies(const retro_cone_map *m, const retro_frame *f)
{
    if (!m || !m->b || f->mode != RETRO_MODE_EXACT || (f->fx & RETRO_FX_BILINEAR) || m->S != f->S ||
        m->S * m->S <= 0)
        return 0;
    for (int u = 0; u < f->W; u++) {
        const double rx = f->rx[u], ry = f->ry[u];
        const double ex = 0x1p-23 * (fabs((double)f->x0) + 2.0 * f->D * fabs(rx));
        const double ey = 0x1p-23 * (fabs((double)f->y0) + 2.0 * f->D * fabs(ry));
        if (2.0 * hypot(ex, ey) > RETRO_CONE_EPS || sqrt(rx * rx + ry * ry) * (1.0 - 1e-12) < RETRO_CONE_RMIN)
            return 0;
    }
    return 1;
}
