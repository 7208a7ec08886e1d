/* retro fly: a scene's fly-through path, one numbered image per frame. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "scene_args.h"

#define MAX_FRAMES 100000

static void help(void)
{
    printf("usage: retro fly MAP|SCENE [-o PATTERN] [--frames N] [-k KERNEL] [-m MODE] [-s WxH]\n"
           "                 [-d DISTANCE] [-p X,Y] [-z HEIGHT] [-a ANGLE] [--sky RRGGBB]\n"
           "                 [--isa LEVEL] [--threads N] [--lod L]\n\n"
           "Renders the fly-through [path] of SCENE (a .scene file, README, Scenes), one image per\n"
           "frame, with a progress line per frame on stderr. Without a path it renders the scene's\n"
           "camera once. A plain MAP (MAP.pgm and MAP.ppm or .png) is flown round a default\n"
           "circuit: one counter-clockwise circle of radius S/4 round the map's centre, looking\n"
           "along it, at the default view's height, in 60 frames.\n"
           "  -o PATTERN  output files, .ppm or .png, with one %%d, %%Nd or %%0Nd for the frame\n"
           "              number from 0 (default results/fly/NAME-%%03d.png)\n"
           "  --frames N  resample the path to N frames (default: the scene's [path] frames)\n"
           "The other options are retro render's and override the scene's values in every frame.\n");
}

/* An output pattern split around its one frame-number conversion. */
typedef struct pattern {
    char pre[1024];
    const char *post;
    int width, zero;
} pattern;

static int parse_pattern(const char *s, pattern *pt)
{
    const char *pc = strchr(s, '%'), *q;
    if (!pc || (size_t)(pc - s) >= sizeof pt->pre)
        return -1;
    q = pc + 1;
    pt->zero = *q == '0';
    q += pt->zero;
    pt->width = 0;
    while (*q >= '0' && *q <= '9' && pt->width < 100)
        pt->width = pt->width * 10 + (*q++ - '0');
    if (*q != 'd' || strchr(q + 1, '%'))
        return -1;
    memcpy(pt->pre, s, (size_t)(pc - s));
    pt->pre[pc - s] = 0;
    pt->post = q + 1;
    return 0;
}

static int frame_path(const pattern *pt, int i, char *out, size_t n)
{
    int len = snprintf(out, n, pt->zero ? "%s%0*d%s" : "%s%*d%s", pt->pre, pt->width, i, pt->post);
    return len < 0 || (size_t)len >= n ? -1 : 0;
}

/* results/fly/NAME-%03d.png, NAME the scene file's name without .scene, or the map's name. */
static int default_pattern(const char *scene, char *out, size_t n)
{
    const char *base = strrchr(scene, '/');
    base = base ? base + 1 : scene;
    int keep = (int)strlen(base) - (is_scene_file(scene) ? 6 : 0);
    int len = snprintf(out, n, "results/fly/%.*s-%%03d.png", keep, base);
    return len < 0 || (size_t)len >= n ? -1 : 0;
}

static int make_dirs(void)
{
    if ((mkdir("results", 0777) && errno != EEXIST) || (mkdir("results/fly", 0777) && errno != EEXIST))
        return cli_error("fly", "cannot create results/fly: %s", strerror(errno));
    return 0;
}

/* A plain map's default path: one counter-clockwise circle of radius S/4 round the map's
 * centre, looking along it, at the default view's height, in CIRCUIT_FRAMES frames. */
enum { CIRCUIT_FRAMES = 60 };
static void default_circuit(render_job *j)
{
    retro_scene *s = &j->scene;
    const float c = 0.5f * (float)j->map.size, r = 0.25f * (float)j->map.size;
    s->nkeys = 9;
    s->frames = CIRCUIT_FRAMES;
    for (int i = 0; i < s->nkeys; i++) {
        int deg = 45 * i; /* steps of 45 degrees: the path interpolates linearly between keys */
        double a = deg * 3.14159265358979323846 / 180.0;
        retro_keyframe *k = &s->keys[i];
        k->t = (float)i / (float)(s->nkeys - 1);
        k->x = c + r * (float)cos(a);
        k->y = c - r * (float)sin(a); /* the map's y axis points down */
        k->height = j->view.height;
        k->angle = (deg + 90) % 360;
        k->morph_t = 0;
    }
    s->x = s->y = NAN; /* the path, not a still camera */
}

static int fly(const render_opts *o, const pattern *pt, long frames, int default_dirs)
{
    render_job j;
    if (job_open("fly", o, &j))
        return CLI_EBADINPUT;
    retro_scene *s = &j.scene;
    if (!j.is_scene)
        default_circuit(&j);
    int n = frames ? (int)frames : s->nkeys ? s->frames : 1, status = 0;
    if (s->nkeys)
        s->frames = n;
    if (default_dirs)
        status = make_dirs();
    for (int i = 0; i < n && !status; i++) {
        char path[4096];
        player_t p;
        if (frame_path(pt, i, path, sizeof path)) {
            status = cli_error("fly", "output path for frame %d is too long", i);
            break;
        }
        job_pose(&j, o, s->nkeys ? i : -1, &p);
        status = job_write("fly", &j, &p, path);
        if (!status)
            fprintf(stderr, "retro fly: %d/%d %s (x %.1f, y %.1f, height %d, angle %d)\n", i + 1,
                    n, path, (double)p.x, (double)p.y, p.height, p.angle);
    }
    job_close(&j);
    return status;
}

/* retro fly's own options. */
typedef struct {
    const char *out;
    long frames;
} fly_args;

static int fly_extra(void *user, const char *a, const char *v)
{
    fly_args *f = user;
    if (!strcmp(a, "-o")) {
        f->out = v ? v : f->out;
        return 1;
    }
    if (strcmp(a, "--frames"))
        return 0;
    if (v && cli_int(v, 1, MAX_FRAMES, &f->frames))
        return cli_error("fly", "bad frame count '%s' (1..%d)", v, MAX_FRAMES);
    return 1;
}

int cmd_fly(int argc, char **argv)
{
    fly_args fa = {NULL, 0};
    render_opts o;
    render_opts_init(&o);
    int r = render_args("fly", "MAP|SCENE", argc, argv, &o, fly_extra, &fa, help);
    if (r)
        return r == 1 ? 0 : r;
    const char *out = fa.out;
    long frames = fa.frames;
    char def[2048];
    if (!out && default_pattern(o.map, def, sizeof def))
        return cli_error("fly", "scene path too long: %s", o.map);
    pattern pt;
    if (parse_pattern(out ? out : def, &pt))
        return cli_error("fly", "bad output pattern '%s' (one %%d, %%Nd or %%0Nd, e.g. out-%%03d.png)",
                         out ? out : def);
    return fly(&o, &pt, frames, !out);
}
