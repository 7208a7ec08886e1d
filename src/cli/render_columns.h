/* retro render --columns: the samples the ybuffer kernel evaluates and those that paint, per
 * screen column, with occlusion skipping as the frame asks and without (docs/SKIPPING.md). */
#ifndef RETRO_RENDER_COLUMNS_H
#define RETRO_RENDER_COLUMNS_H

#include "scene_args.h"
#include "ybuffer_columns.h"

/* The counts of one frame, staged in a temporary beside the destination until committed. */
typedef struct render_columns {
    const char *path; /* the CSV's destination */
    char *tmp;        /* the complete temporary, or NULL */
} render_columns;

/* Renders pose p twice with the counting build of ybuffer (as j->opts asks, then with skipping
 * off) and writes the CSV to a temporary: header "column,samples,evaluated,painting,
 * evaluated_noskip,painting_noskip", then one row per column u = 0..W-1, where samples is the
 * column's W x (D-1) share (D-1, or the lod distances). Returns 0, or CLI_EBADINPUT after the
 * one-line error (a mesh kernel, a folder or unwritable destination) with nothing written. */
int columns_stage(render_columns *rc, render_job *j, const player_t *p);
/* One frame of pose p, rendered with opts by the counting build of ybuffer into j's buffer (the
 * same bytes), its per-column counts into cols (W entries, zeroed here). Returns 0 or
 * CLI_EBADINPUT after the error. */
int columns_count(render_job *j, const player_t *p, const retro_render_opts *opts, retro_column_counts *cols);
/* Renames the temporary into place (commit) or removes it (!commit). Returns 0 or
 * CLI_EBADINPUT after the error. */
int columns_finish(render_columns *rc, int commit);

#endif
