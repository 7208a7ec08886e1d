/* Saving a frame: the PNG, and a scene that names the map by absolute path, the pose, the
 * screen, the sky and every effect in force with all its parameters, so it needs nothing of
 * the scene it came from. Floats are written with 9 significant digits: they read back to
 * the same binary32. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "view_save.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The absolute form of map prefix `prefix` (whose PGM exists), into out. */
static int abs_prefix(const char *prefix, char *out, size_t n)
{
    char pgm[PATH_MAX], full[PATH_MAX];
    if (snprintf(pgm, sizeof pgm, "%s.pgm", prefix) >= (int)sizeof pgm || !realpath(pgm, full))
        return -1;
    size_t len = strlen(full);
    if (len < 4 || len - 4 >= n)
        return -1;
    memcpy(out, full, len - 4);
    out[len - 4] = 0;
    return 0;
}

static void write_effects(FILE *f, const view_state *v, const char *morph)
{
    const retro_effects *fx = &v->j.scene.fx;
    unsigned on = v->fx_on ? fx->flags : 0;
    if (on & RETRO_FX_FOG) {
        if (fx->fog_exp)
            fprintf(f, "[fog]\ndensity = %.9g\n", (double)fx->fog_density);
        else
            fprintf(f, "[fog]\nstart = %.9g\nend = %.9g\n", (double)fx->fog_start, (double)fx->fog_end);
    }
    if (on & RETRO_FX_SHADE)
        fprintf(f, "[shade]\nsun = %.9g %.9g %.9g\nambient = %.9g\ndiffuse = %.9g\n",
                (double)fx->sun[0], (double)fx->sun[1], (double)fx->sun[2], (double)fx->ambient,
                (double)fx->diffuse);
    if (on & RETRO_FX_WATER)
        fprintf(f, "[water]\nlevel = %d\ncolor = %06x\nalpha0 = %.9g\nalpha_per_unit = %.9g\n",
                fx->water_level, (unsigned)(fx->water_color >> 8), (double)fx->water_alpha0,
                (double)fx->water_alpha_per_unit);
    if (on & RETRO_FX_BILINEAR)
        fprintf(f, "[bilinear]\nenabled = yes\n");
    if (on & RETRO_FX_LOD)
        fprintf(f, "[lod]\nrate = %.9g\n", (double)v->j.scene.lod);
    if (on & RETRO_FX_HORIZON)
        fprintf(f, "[horizon]\npitch = %d\n", fx->pitch);
    if (on & RETRO_FX_MORPH)
        fprintf(f, "[morph]\nmap = %s\nt = %.9g\n", morph, (double)fx->morph_t);
}

static int write_scene(const view_state *v, const char *path, const char *name, char *err, size_t n)
{
    char map[PATH_MAX], morph[PATH_MAX] = "";
    const char *prefix = v->j.is_scene ? v->j.scene.map : v->o.map;
    if (abs_prefix(prefix, map, sizeof map) ||
        (v->fx_on && (v->j.scene.fx.flags & RETRO_FX_MORPH) &&
         abs_prefix(v->j.scene.morph_map, morph, sizeof morph))) {
        snprintf(err, n, "cannot resolve the map path of %s", prefix);
        return -1;
    }
    FILE *f = fopen(path, "wx");
    if (!f) {
        snprintf(err, n, "cannot create %.1200s: %s", path, strerror(errno));
        return -1;
    }
    const ctx_t *c = &v->j.c;
    const player_t *p = &v->pose;
    fprintf(f, "; saved by retro view (kernel %s, mode %s); the frame is %s.png:\n"
               ";   retro render %s.scene -k %s -m %s -o OUT.png\n",
            view_kernel_name(v), view_mode_name(v), name, name, view_kernel_name(v),
            view_mode_name(v));
    fprintf(f, "[scene]\nmap = %s\nsky = %06x\n", map, (unsigned)(c->sky_color >> 8));
    fprintf(f, "[camera]\nx = %.9g\ny = %.9g\nheight = %d\nangle = %d\n", (double)p->x,
            (double)p->y, p->height, p->angle);
    fprintf(f, "[screen]\nwidth = %d\nheight = %d\ndistance = %d\n", c->scr_width, c->scr_height,
            c->distance);
    write_effects(f, v, morph);
    if (fclose(f)) {
        snprintf(err, n, "cannot write %.1200s: %s", path, strerror(errno));
        unlink(path);
        return -1;
    }
    return 0;
}

int view_save(const view_state *v, const char *dir, char *done, size_t n)
{
    const char *src = v->o.map, *base = strrchr(src, '/');
    base = base ? base + 1 : src;
    size_t blen = strlen(base);
    if (blen > 6 && !strcmp(base + blen - 6, ".scene"))
        blen -= 6;
    if (mkdir(dir, 0777) && errno != EEXIST) {
        snprintf(done, n, "cannot create %s: %s", dir, strerror(errno));
        return -1;
    }
    char stem[PATH_MAX], png[PATH_MAX + 8], scene[PATH_MAX + 8], err[1400];
    struct stat st;
    for (int i = 0; i < 1000; i++) {
        snprintf(stem, sizeof stem, "%s/%.*s-%03d", dir, (int)(blen > 200 ? 200 : blen), base, i);
        snprintf(png, sizeof png, "%s.png", stem);
        snprintf(scene, sizeof scene, "%s.scene", stem);
        if (stat(png, &st) == 0 || stat(scene, &st) == 0)
            continue;
        const char *name = strrchr(stem, '/') + 1;
        if (write_scene(v, scene, name, err, sizeof err)) {
            snprintf(done, n, "%s", err);
            return -1;
        }
        if (retro_image_write(png, v->j.out, v->j.c.scr_width, v->j.c.scr_height, err, sizeof err)) {
            unlink(scene);
            snprintf(done, n, "%s", err);
            return -1;
        }
        snprintf(done, n, "%s", png);
        return 0;
    }
    snprintf(done, n, "%s holds 1000 saved frames of %.*s already", dir, (int)blen, base);
    return -1;
}
