/* The column chunks the threaded kernels hand out. Chunk edges fall where a 64-byte line of
 * out's first row begins: the first chunk takes the columns before the first such edge as
 * well. Two threads then never store into one line at a chunk edge (a line written by both
 * moves between their caches on every row), and a 16-lane group of the strip stores whole
 * aligned lines (docs/KERNELS.md, "Where the stores go"). When W is a multiple of 16, every row
 * of out is aligned as the first is. */
#ifndef RETRO_COLUMN_CHUNKS_H
#define RETRO_COLUMN_CHUNKS_H

#include <stdint.h>

#include "kernels.h"

typedef struct {
    int lead;  /* columns before the first line edge, 0..15, less than W */
    int size;  /* columns per chunk after the first */
    int count; /* chunks, at least 1 */
    int W;
} retro_column_chunks;

static inline retro_column_chunks retro_column_chunks_of(const retro_frame *f, int size)
{
    const int line = 64 / (int)sizeof *f->out;
    int lead = (int)((line - ((uintptr_t)f->out / sizeof *f->out) % line) % line);
    if (lead >= f->W)
        lead = 0;
    return (retro_column_chunks){lead, size, (f->W - lead + size - 1) / size, f->W};
}

/* Chunk i's columns [*u0, *u1): in increasing order of i, they tile [0, W). */
static inline void retro_column_chunk(const retro_column_chunks *c, int i, int *u0, int *u1)
{
    *u0 = i ? c->lead + i * c->size : 0;
    *u1 = i + 1 < c->count ? c->lead + (i + 1) * c->size : c->W;
}

#endif
