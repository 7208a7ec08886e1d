/* retro view's overlay: the median frame times and text drawn into a frame. */
#ifndef RETRO_CLI_VIEW_OVERLAY_H
#define RETRO_CLI_VIEW_OVERLAY_H

#include <stddef.h>
#include <stdint.h>

#include "view_render.h"

/* The text colour, R<<24 | G<<16 | B<<8: pure yellow, which the darkened box under the text
 * never holds (every channel there is at most 127). */
#define VIEW_TEXT_COLOR 0xffff0000u

#define VIEW_TIMING_N 30
/* The last VIEW_TIMING_N samples (milliseconds). */
typedef struct view_timing {
    double ms[VIEW_TIMING_N];
    int n, next;
} view_timing;
void view_timing_add(view_timing *t, double ms);
/* The median of the samples held (the mean of the middle two for an even count); 0 if none. */
double view_timing_median(const view_timing *t);

/* Draws lines (n of them) at the top left of the W x H frame: each pixel under the box has its
 * channels halved, the text is VIEW_TEXT_COLOR, each font pixel a scale x scale square.
 * Whatever does not fit is clipped. */
void view_draw_text(uint32_t *frame, int W, int H, int scale, const char *const *lines, size_t n);

/* What the overlay shows of v (kernel, family, mode, effects, threads, resolution, distance,
 * pose, render time and fps) into lines[] of width `width`; returns the line count. */
#define VIEW_OVERLAY_LINES 8
size_t view_overlay_lines(const view_state *v, const view_timing *render_ms,
                          const view_timing *frame_ms, int paused, char lines[][96]);

#endif
