/* mesh-omp's record of a block stage's drawing (mesh_internal.h, mesh_recbuf): what the fast
 * block stage (fast_tmpl.h) would draw, in its order, as words, so that the geometry of a
 * block is done once by one thread and its raster by every band (mesh_replay.c).
 * - REC_FRAG, out index, depth bits, colour index: a tiny triangle's covered centre, whose
 *   depth test is all that is left of its raster (fast_tiny.h);
 * - REC_BIG | t << 8, X[3], Y[3], 1/z bits [3], I, J (cells mod S): fast_raster_nearest's input;
 * - REC_GENERIC | t << 8 | back << 16, I, J, X[3], Y[3]: a triangle for the reference raster;
 * - REC_SLOW, I, J: a square for the reference stages (vertex records, assembly, clipping). */
#ifndef RETRO_MESH_REC_H
#define RETRO_MESH_REC_H

#include <stdlib.h>
#include <string.h>

#include "mesh_internal.h"

enum { REC_FRAG = 1, REC_BIG = 2, REC_GENERIC = 3, REC_SLOW = 4 };

/* Room for k more words (a failed growth sets oom and drops the record). */
static inline uint32_t *rec_room(mesh_recbuf *r, size_t k)
{
    if (r->n + k > r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 65536;
        while (cap < r->n + k)
            cap *= 2;
        uint32_t *w = realloc(r->w, cap * sizeof *w);
        if (!w) {
            r->oom = 1;
            return NULL;
        }
        r->w = w;
        r->cap = cap;
    }
    uint32_t *p = r->w + r->n;
    r->n += k;
    return p;
}

/* The records drawn so far may touch rows lo..hi. */
static inline void rec_rows(mesh_recbuf *r, int lo, int hi)
{
    r->rmin = lo < r->rmin ? lo : r->rmin;
    r->rmax = hi > r->rmax ? hi : r->rmax;
}

/* Rows of the snapped bounding box of (Y[0], Y[1], Y[2]) on a screen of H rows. */
static inline void rec_rows_of(mesh_recbuf *r, const int32_t Y[3], int H)
{
    int32_t lo = Y[0] < Y[1] ? Y[0] : Y[1], hi = Y[0] > Y[1] ? Y[0] : Y[1];
    lo = Y[2] < lo ? Y[2] : lo;
    hi = Y[2] > hi ? Y[2] : hi;
    int r0 = (lo + 255) >> 8, r1 = hi >> 8; /* ceil and floor of a / 256 */
    rec_rows(r, r0 < 1 ? 1 : r0, r1 > H ? H : r1);
}

static inline uint32_t rec_fbits(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static inline float rec_float(uint32_t u)
{
    float x;
    memcpy(&x, &u, sizeof x);
    return x;
}

#endif
