/* retro view's Ctrl+S / F12: the frame as PNG beside a one-keyframe scene of its pose. */
#ifndef RETRO_CLI_VIEW_SAVE_H
#define RETRO_CLI_VIEW_SAVE_H

#include <stddef.h>

#include "view_render.h"

/* Writes DIR/NAME-NNN.png (the rendered frame, no overlay) and DIR/NAME-NNN.scene, NNN the
 * first number free for both; DIR is created if missing. The scene reproduces the frame with
 * `retro render DIR/NAME-NNN.scene -k KERNEL -m MODE` (its first comment says so). Returns 0
 * with the PNG's path in done, or -1 with the reason in done. */
int view_save(const view_state *v, const char *dir, char *done, size_t n);

#endif
