/* The per-frame preparation the SIMD kernels share: whether the vector path is exact for this
 * frame, and the packed, tiled map it reads (colour | height in one uint32 per cell). */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "simd_common.h"
#include "simd_map.h"
#include "ctx.h"
#include "retro_scene.h"

/* Packs the maps into pm->cells; returns 0 if a colour has a non-zero low byte (the packing
 * would lose it) or memory is short. */
static int pack_maps(const retro_frame *f, retro_packed_map *pm)
{
    size_t S = (size_t)f->S, T = (S + RETRO_SIMD_TILE - 1) / RETRO_SIMD_TILE;
    size_t n = T * T * RETRO_SIMD_TILE * RETRO_SIMD_TILE * RETRO_SIMD_REGIONS;
    if (n > pm->cap) {
        /* The old cells are not worth copying, so free first: the peak stays one packed map. */
        free(pm->cells);
        pm->cap = 0;
        /* Whole tiles on whole cache lines: n * 4 bytes is a multiple of 64. */
        pm->cells = aligned_alloc(64, n * sizeof *pm->cells);
        if (!pm->cells)
            return 0;
        pm->cap = n;
    }
    const uint8_t *h = f->height_map;
    const uint32_t *c = f->color_map;
    uint32_t low = 0;
    for (size_t j = 0; j < S; j++) {
        for (size_t i = 0; i < S; i++) {
            low |= c[j * S + i];
            pm->cells[retro_simd_tiled(i, j, T)] = c[j * S + i] | h[j * S + i];
        }
    }
#ifndef RETRO_SUBMISSION
    uint32_t *quads = pm->cells + T * T * RETRO_SIMD_TILE * RETRO_SIMD_TILE;
    for (size_t j = 0; j < S; j++) {
        const size_t j1 = j + 1 == S ? 0 : j + 1;
        for (size_t i = 0; i < S; i++) {
            const size_t i1 = i + 1 == S ? 0 : i + 1;
            quads[retro_simd_tiled(i, j, T)] = (uint32_t)h[j * S + i] | (uint32_t)h[j * S + i1] << 8 |
                                               (uint32_t)h[j1 * S + i] << 16 | (uint32_t)h[j1 * S + i1] << 24;
        }
    }
#endif
    return (low & RETRO_SIMD_HEIGHT_MASK) == 0;
}

/* The quad map after the packed cells (RETRO_SIMD_REGIONS), or NULL. */
static const uint32_t *quads_of(const uint32_t *cells, int S)
{
#ifdef RETRO_SUBMISSION
    (void)cells;
    (void)S;
    return NULL;
#else
    size_t T = ((size_t)S + RETRO_SIMD_TILE - 1) / RETRO_SIMD_TILE;
    return cells ? cells + T * T * RETRO_SIMD_TILE * RETRO_SIMD_TILE : NULL;
#endif
}

/* Every accumulator of mode course stays below 2^23 in magnitude: each line starts and ends
 * within RETRO_SIMD_COURSE_BOUND, and W additions, each rounded by at most half an ulp of a
 * value below 2^23 (0.25), drift by at most 2^14 * 0.25 beyond it. Written so that an
 * infinite or NaN line (a position near FLT_MAX) fails the test. */
static int course_in_bound(const retro_frame *f)
{
    const double W = f->W;
    for (int d = 1; d < f->D; d++) {
        double x = fabs((double)f->lx[d]) + W * fabs((double)f->sx[d]);
        double y = fabs((double)f->ly[d]) + W * fabs((double)f->sy[d]);
        if (!(x <= RETRO_SIMD_COURSE_BOUND && y <= RETRO_SIMD_COURSE_BOUND))
            return 0;
    }
    return 1;
}

int retro_simd_check(const retro_frame *f, retro_simd_frame *sf)
{
    if (f->mode != RETRO_MODE_EXACT && f->mode != RETRO_MODE_COURSE && f->mode != RETRO_MODE_LOD)
        return 0;
    if (f->fx & ~(unsigned)(RETRO_FX_FOG | RETRO_FX_BILINEAR))
        return 0;
    /* The vector path converts h - height from int32; below this bound h - height exceeds
     * INT_MAX for h = 255, and only the scalar path rounds the 64-bit difference once. */
    if (f->height < (int64_t)INT_MIN + 256)
        return 0;
    if (f->mode == RETRO_MODE_COURSE && !course_in_bound(f))
        return 0;
    /* the packed map only where a threaded kernel offered it for this frame */
    const retro_packed_map *pm = f->packed;
    sf->cells = pm && pm->offered && pm->ok ? pm->cells : NULL;
    sf->quads = quads_of(sf->cells, f->S);
    sf->tiles = (f->S + RETRO_SIMD_TILE - 1) / RETRO_SIMD_TILE;
    sf->height = (int32_t)f->height;
    sf->pow2_mask = (f->S & (f->S - 1)) == 0 ? f->S - 1 : -1;
    sf->fS = (float)f->S;
    sf->inv_S = 1.0f / (float)f->S;
    sf->fK = (float)(f->S - 1);
    sf->inv_K = f->S > 1 ? 1.0f / sf->fK : 0.0f;
    return 1;
}

/* Packs f's maps into pm unless it holds them already; whether the packing is usable. */
static int pack_current(const retro_frame *f, retro_packed_map *pm)
{
    if (pm->height_map != f->height_map || pm->color_map != f->color_map || pm->size != f->S) {
        pm->ok = pack_maps(f, pm);
        pm->height_map = f->height_map;
        pm->color_map = f->color_map;
        pm->size = f->S;
    }
    return pm->ok;
}

/* Mode course reads the maps directly: there a vector's lanes are one column's consecutive
 * distances, and the direct read costs one height read per lane (one padded gather in the
 * AVX-512 column) and a colour read per painting lane only, where the packed map costs the
 * tile arithmetic on every lane. A/B benchmark runs decided it (docs/KERNELS.md, "Map
 * reads"). */
static int packs(const retro_frame *f)
{
    return f->mode != RETRO_MODE_COURSE;
}

void retro_simd_use_packed(const retro_frame *f, retro_ctx *rc, retro_simd_frame *sf)
{
    sf->cells = packs(f) && pack_current(f, &rc->packed) ? rc->packed.cells : NULL;
    sf->quads = quads_of(sf->cells, f->S);
}

/* The frame is not written: strips find the offer through f->packed, which frame setup
 * points at rc->packed with offered cleared. */
void retro_simd_offer_packed(retro_ctx *rc)
{
    const retro_frame *f = &rc->frame;
    retro_simd_frame sf;
    rc->packed.offered = 0;
    if (!retro_simd_check(f, &sf))
        return;
    rc->packed.offered = packs(f) && pack_current(f, &rc->packed);
}

void retro_packed_map_stale(retro_packed_map *pm)
{
    pm->height_map = NULL;
}

void retro_packed_map_free(retro_packed_map *pm)
{
    free(pm->cells);
    memset(pm, 0, sizeof *pm);
}
