/* The viewer's adapter to the library (see view_render.h): kernel table walks, mode and effect
 * rules, the render call. The rules are the library's (retro_render_check, retro_render_mode):
 * a kernel must render the scene's effects, modes are its family's (Tab into another family
 * starts at the family's first mode), effects are defined on some modes only (voxel: exact and
 * lod), and the scene's lod effect makes voxel mode exact render as lod. */
#include "view_render.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "retro_mesh.h"

static const retro_kernel *kernel(const view_state *v)
{
    return &retro_kernels[v->kernel];
}

static unsigned scene_fx(const view_state *v)
{
    return v->j.is_scene ? v->j.scene.fx.flags : 0;
}

static int is_voxel(const view_state *v)
{
    return kernel(v)->family == &retro_family_voxel;
}

/* What a frame in mode m asks for: the job's options with the viewer's effects switch and
 * thread count. */
static retro_render_opts opts_for(const view_state *v, retro_mode m)
{
    retro_render_opts o = v->j.opts;
    o.mode = (int)m;
    o.fx = v->fx_on ? &v->j.scene.fx : NULL;
    o.threads = v->threads;
    return o;
}

static retro_mode effective(const view_state *v, retro_mode m)
{
    retro_render_opts o = opts_for(v, m);
    return (retro_mode)retro_render_mode(kernel(v), &o);
}

/* Whether the effects (when on) are defined on mode m: the library refuses them with
 * RETRO_EINVAL otherwise. */
static int fx_mode_ok(const view_state *v, retro_mode m)
{
    retro_render_opts o = opts_for(v, m);
    return retro_render_check(kernel(v), &o, NULL, 0) != RETRO_EINVAL;
}

/* Whether k renders the scene's effects (when they are on) in the mode chosen. */
static int renders_fx(const view_state *v, const retro_kernel *k)
{
    retro_render_opts o = opts_for(v, v->mode);
    return !v->fx_on || retro_render_check(k, &o, NULL, 0) != RETRO_EUNSUPPORTED;
}

int view_open(const char *cmd, const render_opts *o, view_state *v)
{
    memset(v, 0, sizeof *v);
    v->o = *o;
    if (job_open(cmd, &v->o, &v->j))
        return CLI_EBADINPUT;
    job_pose(&v->j, &v->o, -1, &v->pose);
    v->kernel = (size_t)(v->j.k - retro_kernels);
    v->mode = (retro_mode)v->j.opts.mode;
    v->fx_on = v->j.opts.fx != NULL;
    if (!renders_fx(v, kernel(v))) { /* as retro render refuses it */
        job_close(&v->j);
        return cli_error(cmd, "kernel '%s' cannot render the effects of %s", kernel(v)->name, o->map);
    }
    /* Always an explicit count, so the overlay says what every threaded kernel uses (their
     * defaults differ). */
    v->threads = o->threads ? (int)o->threads : retro_ctx_threads(v->j.rc);
    return 0;
}

void view_close(view_state *v)
{
    job_close(&v->j);
}

int view_resize(view_state *v, int W, int H)
{
    if (W < 1 || H < 1 || W > RETRO_MAX_SCREEN || H > RETRO_MAX_SCREEN || (long)W * H > RETRO_MAX_PIXELS)
        return -1;
    uint32_t *out = realloc(v->j.out, (size_t)W * (size_t)H * sizeof *out);
    if (!out)
        return -1;
    v->j.out = v->j.c.out = out;
    v->j.c.scr_width = W;
    v->j.c.scr_height = H;
    return 0;
}

void view_move(view_state *v, view_motion m)
{
    v->pose.v = m.v;
    v->pose.v_height = m.v_height;
    v->pose.v_angular = m.v_angular;
    update_player(&v->pose, &v->j.c);
}

void view_next_kernel(view_state *v, int dir)
{
    size_t n = retro_kernel_count, i = v->kernel;
    const retro_family *was = kernel(v)->family;
    do
        i = (i + n + (size_t)(dir < 0 ? n - 1 : 1)) % n;
    while (!retro_kernel_runs_here(&retro_kernels[i]));
    v->kernel = i;
    v->status[0] = 0;
    /* mode numbers are per family: another family starts at its first mode (voxel exact,
     * mesh binary32) */
    if (kernel(v)->family != was || !retro_kernel_has_mode(kernel(v), effective(v, v->mode)))
        v->mode = RETRO_MODE_EXACT;
    if (!renders_fx(v, kernel(v))) {
        v->fx_on = 0;
        snprintf(v->status, sizeof v->status, "%s cannot render the scene's effects: effects off",
                 kernel(v)->name);
    }
}

void view_next_mode(view_state *v)
{
    retro_mode m = v->mode;
    int count = kernel(v)->family->mode_count;
    v->status[0] = 0;
    for (int i = 0; i < count; i++) {
        m = (retro_mode)((m + 1) % count);
        if (!fx_mode_ok(v, m))
            continue; /* effects are not defined on m (voxel: only exact and lod) */
        if (effective(v, m) != m)
            continue; /* exact would render as lod: no new mode */
        if (retro_kernel_has_mode(kernel(v), m))
            break;
    }
    v->mode = m;
}

void view_toggle_effects(view_state *v)
{
    v->status[0] = 0;
    if (!scene_fx(v)) {
        snprintf(v->status, sizeof v->status, "no effects in this scene");
        return;
    }
    retro_mode old = v->mode;
    v->fx_on = !v->fx_on;
    if (!fx_mode_ok(v, v->mode))
        v->mode = RETRO_MODE_EXACT; /* the family's first mode: effects are defined there */
    if (!renders_fx(v, kernel(v))) {
        v->fx_on = 0;
        v->mode = old;
        snprintf(v->status, sizeof v->status, "%s cannot render the scene's effects", kernel(v)->name);
    }
}

void view_next_threads(view_state *v)
{
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    int n = cores < 1 ? 1 : cores > 64 ? 64 : (int)cores;
    v->threads = v->threads >= n ? 1 : v->threads + 1;
}

void view_distance(view_state *v, int delta)
{
    long d = (long)v->j.c.distance + delta;
    v->j.c.distance = (int)(d < VIEW_D_MIN ? VIEW_D_MIN : d > VIEW_D_MAX ? VIEW_D_MAX : d);
}

int view_render(view_state *v)
{
    retro_render_opts o = opts_for(v, v->mode);
    retro_err e = retro_render(v->j.rc, kernel(v), &o, &v->pose, &v->j.c);
    if (e) {
        const char *why = is_voxel(v) ? "" : retro_mesh_last_error(v->j.rc);
        snprintf(v->status, sizeof v->status, "%s", *why ? why : retro_strerror(e));
        return -1;
    }
    return 0;
}

const char *view_kernel_name(const view_state *v)
{
    return kernel(v)->name;
}

const char *view_family_name(const view_state *v)
{
    return kernel(v)->family->name;
}

const char *view_mode_name(const view_state *v)
{
    return retro_family_mode_name(kernel(v)->family, (int)effective(v, v->mode));
}

int view_kernel_threaded(const view_state *v)
{
    return (kernel(v)->flags & RETRO_KF_THREADED) != 0;
}

int view_has_effects(const view_state *v)
{
    return scene_fx(v) != 0;
}

int view_threads_shown(const view_state *v)
{
    return v->threads;
}
