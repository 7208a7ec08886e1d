/* A render job: a plain MAP or a scene file, the command line overriding the scene's values. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "retro_mesh.h"
#include "scene_args.h"
#include "work_estimate.h"

/* The morph keyframe: only its heights are blended, so only its .pgm is read. */
static int load_morph(const char *cmd, render_job *j)
{
    char path[sizeof j->scene.morph_map + 8], err[1400];
    int w, h;
    snprintf(path, sizeof path, "%s.pgm", j->scene.morph_map);
    if (retro_pgm_read(path, &j->morph, &w, &h, err, sizeof err))
        return cli_error(cmd, "%s", err);
    if (w != j->map.size || h != j->map.size)
        return cli_error(cmd, "%s is %dx%d but the map %s is %dx%d", path, w, h, j->scene.map,
                         j->map.size, j->map.size);
    j->scene.fx.morph_height = j->morph;
    return 0;
}

static int open_maps(const char *cmd, const char *prefix, render_job *j)
{
    char err[1400];
    if (retro_map_load(prefix, &j->map, err, sizeof err))
        return cli_error(cmd, "%s", err);
    if (j->k->family == &retro_family_voxel && j->opts.mode == RETRO_MODE_COURSE && j->map.size < 2)
        return cli_error(cmd, "mode course needs a map of size 2 or more");
    if ((j->scene.fx.flags & RETRO_FX_MORPH) && load_morph(cmd, j))
        return CLI_EBADINPUT;
    retro_default_view(&j->map, &j->view);
    return 0;
}

/* The kernel and the options of every frame; the library decides the mode a frame renders in
 * and whether the kernel can (retro_render_check), and says why not. */
static int pick_kernel(const char *cmd, const render_opts *o, render_job *j)
{
    const retro_kernel *named = o->kernel ? retro_kernel_find(o->kernel) : NULL;
    if (o->kernel && !named)
        return cli_error(cmd, "unknown kernel '%s' (retro kernels lists them)", o->kernel);
    /* The family: the named kernel's, else the one whose mode -m names (voxel first). */
    int m = 0;
    const retro_family *fam = named ? named->family : &retro_family_voxel;
    if (!named && o->have_mode && retro_family_mode_parse(fam, o->mode_name, &m))
        fam = &retro_family_mesh;
    if (o->have_mode && retro_family_mode_parse(fam, o->mode_name, &m))
        return cli_error(cmd, "kernel %s (family %s) has no mode '%s'", named->name, fam->name, o->mode_name);
    /* the family's first mode (voxel exact, mesh binary32) unless -m names one */
    j->opts.mode = o->have_mode ? m : 0;
    /* A plain map renders exactly as before scenes existed: no effects block at all. */
    j->opts.fx = j->is_scene ? &j->scene.fx : NULL;
    j->opts.lod = j->scene.lod;
    j->opts.threads = (int)o->threads;
    j->k = named ? named : retro_family_best(fam, j->opts.mode, j->opts.fx);
    if (!j->k)
        j->k = retro_family_reference(fam); /* refused below, with the reason */
    char why[160];
    if (retro_render_check(j->k, &j->opts, why, sizeof why))
        return cli_error(cmd, "%s: %s", o->map, why);
    j->opts.mode = retro_render_mode(j->k, &j->opts); /* a scene's lod effect: mode lod */
    return 0;
}

static int open_job(const char *cmd, const render_opts *o, render_job *j)
{
    char err[1400];
    const char *prefix = o->map;
    j->is_scene = is_scene_file(o->map);
    if (!j->is_scene)
        retro_scene_defaults(&j->scene);
    else if (retro_scene_load(o->map, &j->scene, err, sizeof err))
        return cli_error(cmd, "%s", err);
    else
        prefix = j->scene.map;
    retro_scene *s = &j->scene;
    if (o->have_lod) /* --lod 0 means the default, as for a plain map */
        s->lod = o->lod > 0 ? o->lod : RETRO_LOD_DEFAULT;
    if (pick_kernel(cmd, o, j) || open_maps(cmd, prefix, j))
        return CLI_EBADINPUT;

    int W = o->have_size ? o->W : s->W, H = o->have_size ? o->H : s->H;
    long D = o->have_d ? o->D : s->D;
    j->out = malloc((size_t)W * (size_t)H * sizeof *j->out);
    if (!j->out)
        return cli_error(cmd, "out of memory for a %dx%d frame", W, H);
    ctx_t c = {W, H, j->map.size, (int)D, o->have_sky ? o->sky : s->sky, j->map.height,
               j->map.color, j->out};
    j->c = c;
    work_warn(cmd, j->k, W, H, D);
    return 0;
}

int job_open(const char *cmd, const render_opts *o, render_job *j)
{
    memset(j, 0, sizeof *j);
    j->opts = retro_render_opts_default();
    if (!(j->rc = retro_ctx_new()))
        return cli_error(cmd, "out of memory");
    if (open_job(cmd, o, j)) {
        job_close(j);
        return CLI_EBADINPUT;
    }
    j->chosen = o->kernel == NULL;
    return 0;
}

void job_pose(render_job *j, const render_opts *o, int frame, player_t *p)
{
    const retro_scene *s = &j->scene;
    if (frame < 0 && s->nkeys && isnan(s->x) && isnan(s->y))
        frame = 0;
    float morph_t;
    if (frame < 0) {
        retro_scene still = *s;
        still.nkeys = 0;
        retro_scene_pose(&still, 0, p, &morph_t);
    } else
        retro_scene_pose(s, frame, p, &morph_t);
    if (isnan(p->x))
        p->x = j->view.x;
    if (isnan(p->y))
        p->y = j->view.y;
    if (p->height == INT_MIN)
        p->height = j->view.height;
    if (o->have_pos) {
        p->x = o->x;
        p->y = o->y;
    }
    if (o->have_z)
        p->height = (int)o->z;
    if (o->have_angle)
        p->angle = (int)o->angle;
    j->scene.fx.morph_t = morph_t;
}

int job_error(const char *cmd, const render_job *j, retro_err e)
{
    const char *why = j->k->family == &retro_family_mesh ? retro_mesh_last_error(j->rc) : "";
    return cli_error(cmd, "%s", *why ? why : retro_strerror(e));
}

const char *job_mode_name(const render_job *j)
{
    return retro_family_mode_name(j->k->family, j->opts.mode);
}

int job_write(const char *cmd, render_job *j, const player_t *p, const char *path)
{
    char err[1400];
    retro_err e = retro_render(j->rc, j->k, &j->opts, p, &j->c);
    if (e)
        return job_error(cmd, j, e);
    if (retro_image_write(path, j->out, j->c.scr_width, j->c.scr_height, err, sizeof err))
        return cli_error(cmd, "%s", err);
    /* Say what ran, once, after the first image is written (a failure prints only its error):
     * the kernel is chosen per CPU and mode unless -k names it. */
    if (!j->said++)
        fprintf(stderr, "retro %s: kernel %s%s, mode %s, %dx%d, D %d%s\n", cmd, j->k->name,
                j->chosen ? " (the fastest here for the mode)" : "", job_mode_name(j), j->c.scr_width,
                j->c.scr_height, j->c.distance, j->is_scene && j->scene.fx.flags ? ", with the scene's effects" : "");
    return 0;
}

void job_close(render_job *j)
{
    retro_ctx_free(j->rc);
    free(j->out);
    free(j->morph);
    retro_map_free(&j->map);
}
