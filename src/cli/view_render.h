/* retro view's one door into the library: the render job, the pose, the kernel, mode, effects
 * and threads in force, and what each key changes. Every library call of the viewer is in
 * view_render.c, so a change of the library's API is ported there alone. */
#ifndef RETRO_CLI_VIEW_RENDER_H
#define RETRO_CLI_VIEW_RENDER_H

#include "scene_args.h"
#include "view_keys.h"

typedef struct view_state {
    render_opts o;      /* the command line */
    render_job j;       /* map, scene, frame buffer (j.out at j.c's size), context */
    player_t pose;
    size_t kernel;      /* row of the kernel table */
    retro_mode mode;    /* a mode of the kernel's family, as chosen; the scene's lod effect
                         * renders voxel exact as lod */
    int fx_on;          /* the scene's effects are in force */
    int threads;        /* for threaded kernels */
    char status[160];   /* why the last key did not do what it says, or "" */
} view_state;

/* Opens o's map or scene at its still pose. Returns 0, or CLI_EBADINPUT after the one-line
 * error (nothing to close then). */
int view_open(const char *cmd, const render_opts *o, view_state *v);
void view_close(view_state *v);
/* Sets the render size (the window's, unless -s fixed it). Returns 0, -1 when out of range or
 * out of memory (the old size stays). */
int view_resize(view_state *v, int W, int H);
/* One step of the course's update_player with these velocities. */
void view_move(view_state *v, view_motion m);
void view_next_kernel(view_state *v, int dir);
void view_next_mode(view_state *v);
void view_toggle_effects(view_state *v);
void view_next_threads(view_state *v);
void view_distance(view_state *v, int delta);
/* Renders the pose into v->j.out. Returns 0, or -1 with the reason in v->status. */
int view_render(view_state *v);

/* What the overlay and the saved scene say. */
const char *view_kernel_name(const view_state *v);
const char *view_family_name(const view_state *v);
const char *view_mode_name(const view_state *v); /* the mode the frame is rendered in */
int view_kernel_threaded(const view_state *v);
int view_has_effects(const view_state *v); /* the scene names any */
int view_threads_shown(const view_state *v); /* the count threaded kernels use */

#endif
