/* What retro view's scripted replay and its window share: the state of the controls that are
 * not the renderer's, and one key's effect on both. */
#ifndef RETRO_CLI_VIEW_LOOP_H
#define RETRO_CLI_VIEW_LOOP_H

#include "view_render.h"

typedef struct view_ui {
    int paused, overlay, help, quit, save; /* save: write the frame once it is rendered */
    const char *save_dir;
} view_ui;

/* Applies a key that is not movement (movement is held, see view_motion_of). Returns whether
 * the frame must be rendered again even when paused. */
int view_apply(view_state *v, view_ui *ui, view_action a);
/* Writes the frame and its scene (Ctrl+S / F12), reporting the paths or the error on stderr
 * and in v->status. */
void view_save_now(view_state *v, const view_ui *ui);

/* The window: runs until Esc or the window is closed. Returns 0, or CLI_EBADINPUT after the
 * one-line error when there is no display. */
int view_window_run(view_state *v, view_ui *ui);

#endif
