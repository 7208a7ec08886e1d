/* The maximum-height pyramid of hmax_pyramid.h: built once per map, O(S^2), and kept until the
 * map changes (retro_ctx_map_changed marks it stale). */
#include <stdlib.h>
#include <string.h>

#include "hmax_pyramid.h"

void retro_pyramid_free(retro_pyramid *p)
{
    free(p->mem);
    memset(p, 0, sizeof *p);
}

void retro_pyramid_stale(retro_pyramid *p)
{
    p->map = NULL;
}

/* Levels RETRO_PYR_LMIN.. while a side of the torus (P cells) has at least two blocks: at one
 * block the window is the map's maximum, which vcap already uses. */
static int top_level(int P)
{
    int L = RETRO_PYR_LMIN - 1;
    while (L < RETRO_PYR_LMAX && ((P - 1) >> (L + 1)) >= 1)
        L++;
    return L;
}

static int blocks(int S, int L)
{
    return (int)(((unsigned)S + (1u << L) - 1) >> L);
}

/* The blocks whose maxima make the window of block b (hmax_pyramid.h, A(b)); returns how many. */
static int window_blocks(int b, int n, int partial, int *a)
{
    int k = 0;
    a[k++] = b;
    a[k++] = b + 1 == n ? 0 : b + 1;
    if (partial && b == n - 2)
        a[k++] = 0;
    return k;
}

/* win[bj][bi] = max of blk over A(bj) x A(bi), through a row pass into tmp. */
static void windows(uint8_t *win, const uint8_t *blk, uint8_t *tmp, int n, int partial)
{
    int a[3];
    for (int bj = 0; bj < n; bj++)
        for (int bi = 0; bi < n; bi++) {
            int k = window_blocks(bi, n, partial, a);
            uint8_t m = 0;
            for (int t = 0; t < k; t++) {
                uint8_t v = blk[(size_t)bj * (size_t)n + (size_t)a[t]];
                m = v > m ? v : m;
            }
            tmp[(size_t)bj * (size_t)n + (size_t)bi] = m;
        }
    for (int bj = 0; bj < n; bj++) {
        int k = window_blocks(bj, n, partial, a);
        for (int bi = 0; bi < n; bi++) {
            uint8_t m = 0;
            for (int t = 0; t < k; t++) {
                uint8_t v = tmp[(size_t)a[t] * (size_t)n + (size_t)bi];
                m = v > m ? v : m;
            }
            win[(size_t)bj * (size_t)n + (size_t)bi] = m;
        }
    }
}

/* Block maxima of the finest level straight from the map's top-left P x P cells, row stride S
 * (partial blocks at the far edges). */
static void finest_blocks(uint8_t *blk, const uint8_t *h, int S, int P, int L, int n)
{
    memset(blk, 0, (size_t)n * (size_t)n);
    for (int j = 0; j < P; j++) {
        uint8_t *row = blk + (size_t)(j >> L) * (size_t)n;
        const uint8_t *src = h + (size_t)j * (size_t)S;
        for (int i = 0; i < P; i++) {
            uint8_t *m = &row[i >> L];
            *m = src[i] > *m ? src[i] : *m;
        }
    }
}

/* Level L + 1's block maxima from level L's, in place: output k reads only entries >= k. */
static void coarsen(uint8_t *blk, int n, int n2)
{
    for (int bj = 0; bj < n2; bj++)
        for (int bi = 0; bi < n2; bi++) {
            uint8_t m = 0;
            for (int y = 2 * bj; y < 2 * bj + 2 && y < n; y++)
                for (int x = 2 * bi; x < 2 * bi + 2 && x < n; x++) {
                    uint8_t v = blk[(size_t)y * (size_t)n + (size_t)x];
                    m = v > m ? v : m;
                }
            blk[(size_t)bj * (size_t)n2 + (size_t)bi] = m;
        }
}

int retro_pyramid_build(retro_pyramid *p, const uint8_t *h, int S, int P)
{
    if (p->map == h && p->S == S && p->P == P)
        return 0;
    p->map = NULL;
    int top = top_level(P);
    p->lmax = top;
    p->S = S;
    p->P = P;
    if (top < RETRO_PYR_LMIN) {
        p->map = h;
        return 0;
    }
    size_t total = 0;
    for (int L = RETRO_PYR_LMIN; L <= top; L++) {
        p->n[L] = blocks(P, L);
        total += (size_t)p->n[L] * (size_t)p->n[L];
    }
    size_t n0 = (size_t)p->n[RETRO_PYR_LMIN] * (size_t)p->n[RETRO_PYR_LMIN];
    /* the windows, then two scratch planes, which also give the SIMD probe's 4-byte reads of a
     * window (v_gather_bytes_pad, simd_skip_tpl.h) the 3 bytes of slack they need: n0 >= 4 */
    size_t need = total + 2 * n0;
    if (need > p->cap) {
        uint8_t *m = realloc(p->mem, need);
        if (!m)
            return -1;
        p->mem = m;
        p->cap = need;
    }
    uint8_t *blk = p->mem + total, *tmp = blk + n0, *at = p->mem;
    finest_blocks(blk, h, S, P, RETRO_PYR_LMIN, p->n[RETRO_PYR_LMIN]);
    for (int L = RETRO_PYR_LMIN; L <= top; L++) {
        int n = p->n[L];
        windows(at, blk, tmp, n, P % (1 << L) != 0);
        p->win[L] = at;
        at += (size_t)n * (size_t)n;
        if (L < top)
            coarsen(blk, n, p->n[L + 1]);
    }
    p->map = h;
    return 0;
}

int retro_pyramid_get(retro_pyramid **slot, const uint8_t *h, int S, int P, const retro_pyramid **out)
{
    *out = NULL;
    if (!*slot && !(*slot = calloc(1, sizeof **slot)))
        return -1;
    if (retro_pyramid_build(*slot, h, S, P))
        return -1;
    if ((*slot)->lmax >= RETRO_PYR_LMIN)
        *out = *slot;
    return 0;
}
