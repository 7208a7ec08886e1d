/* What retro render and retro fly share: their options, and a render job that takes its
 * defaults from a scene file (a plain MAP is a scene without effects) and lets explicit
 * command-line options override them. */
#ifndef RETRO_CLI_SCENE_ARGS_H
#define RETRO_CLI_SCENE_ARGS_H

#include <stdint.h>

#include "retro.h"
#include "retro_maps.h"
#include "retro_scene.h"

typedef struct render_opts {
    const char *map;    /* MAP prefix, or a .scene file */
    const char *kernel; /* NULL: the fastest this CPU runs for the mode */
    retro_mode mode;    /* the voxel mode -m names, when it names one */
    const char *mode_name; /* -m as given: a mode of the kernel's family (voxel or mesh) */
    int W, H;
    long D, z, angle, threads;
    float x, y, lod;
    uint32_t sky;
    /* what the command line set: those override the scene */
    int have_mode, have_size, have_d, have_pos, have_z, have_angle, have_sky, have_lod;
} render_opts;

void render_opts_init(render_opts *o);
/* Parses option a with value v when it is one of the shared options. Returns 1 if it was, 0 if
 * a is not a shared option, CLI_EBADINPUT after printing the error for a bad value. */
int render_opt(const char *cmd, render_opts *o, const char *a, const char *v);
/* The shared options render_opt takes, NULL-ended. */
extern const char *const render_opt_names[];
/* Parses argv[1..] of `retro CMD` into o: one positional (`what`, MAP or SCENE), the shared
 * options, and the command's own through extra(user, option, value), which returns 1 when it
 * took the option, 0 when it does not know it, CLI_EBADINPUT after printing a bad value; with
 * value NULL (given last, without one) it only says whether the option is its own, 1 or 0,
 * and changes nothing.
 * Returns 0; 1 after --help (printed by help); CLI_EBADINPUT after printing the error. */
int render_args(const char *cmd, const char *what, int argc, char **argv, render_opts *o,
                int (*extra)(void *user, const char *a, const char *v), void *user, void (*help)(void));
/* Whether MAP names a scene file (it ends in .scene). */
int is_scene_file(const char *map);

typedef struct render_job {
    retro_scene scene;   /* from the file, or retro_scene_defaults() for a plain MAP */
    int is_scene;
    retro_map map;
    uint8_t *morph;      /* the morph keyframe's heights, or NULL */
    const retro_kernel *k;
    /* what every frame asks for, said once: the mode (of k's family, as it renders: a scene's
     * lod effect makes it lod), the scene's effects (NULL for a plain MAP), lod rate, threads */
    retro_render_opts opts;
    struct retro_view view; /* the map's default view: what neither file nor flags set */
    uint32_t *out;
    ctx_t c;
    retro_ctx *rc;
    int chosen;          /* the kernel was picked for the CPU and mode, not named by -k */
    int said;            /* the "what ran" line is printed */
} render_job;

/* Loads the scene (if o->map is one), the map and the morph keyframe, and picks the kernel.
 * Returns 0, or CLI_EBADINPUT after printing the one-line error (nothing to close then). */
int job_open(const char *cmd, const render_opts *o, render_job *j);
/* The camera of path frame i, or for i < 0 the still: the scene's camera, or the path's first
 * frame when the scene gives a path but no camera position. Unset values come from the map's
 * default view; command-line options override. Also sets the morph time of the frame. */
void job_pose(render_job *j, const render_opts *o, int frame, player_t *p);
/* Renders pose p and writes it to path (.ppm or .png). Returns 0 or CLI_EBADINPUT. */
int job_write(const char *cmd, render_job *j, const player_t *p, const char *path);
void job_close(render_job *j);
/* The one-line error for a failed render (a mesh frame's message names what is wrong). */
int job_error(const char *cmd, const render_job *j, retro_err e);
/* j->opts.mode's name in its kernel's family. */
const char *job_mode_name(const render_job *j);

#endif
