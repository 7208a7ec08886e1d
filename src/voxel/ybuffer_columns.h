/* Per-column sample counts of the counting build of ybuffer (kernel_ybuffer.c compiled with
 * RETRO_COUNT_SAMPLES, retro_kernel_ybuffer_counted: hmax_pyramid.h), for the share of samples
 * evaluated along each column (retro render --columns). The frame totals stay in
 * retro_ybuffer_counts; these add the same samples per column, so they sum to those totals. */
#ifndef RETRO_YBUFFER_COLUMNS_H
#define RETRO_YBUFFER_COLUMNS_H

#include <stdint.h>

typedef struct retro_column_counts {
    uint64_t evaluated; /* samples of column u whose cell and row were computed */
    uint64_t painting;  /* samples of column u that raised its y-buffer */
} retro_column_counts;

/* NULL (the default): no per-column counts. Else at least W entries, one per column u of the
 * frames rendered by retro_kernel_ybuffer_counted, added to (not reset) by each frame. Global
 * and unsynchronised like retro_ybuffer_counts: one thread at a time. */
extern retro_column_counts *retro_ybuffer_columns;

#endif
