/* The options retro render and retro fly share, with the have_* marks a scene's defaults need. */
#include <string.h>

#include "cli.h"
#include "isa.h"
#include "scene_args.h"

void render_opts_init(render_opts *o)
{
    memset(o, 0, sizeof *o);
    o->mode = RETRO_MODE_EXACT;
    o->W = 640;
    o->H = 480;
    o->D = 800;
    o->sky = 0x66a3ff00u;
}

int is_scene_file(const char *map)
{
    size_t n = strlen(map);
    return n > 6 && !strcmp(map + n - 6, ".scene");
}

const char *const render_opt_names[] = {"-k", "-m", "-s", "-d", "-p", "-z", "-a", "--sky",
                                        "--isa", "--lod", "--threads", NULL};

int render_opt(const char *cmd, render_opts *o, const char *a, const char *v)
{
    if (!strcmp(a, "-k"))
        o->kernel = v;
    else if (!strcmp(a, "-m")) {
        int m;
        if (retro_mode_parse(v, &o->mode) && retro_family_mode_parse(&retro_family_mesh, v, &m))
            return cli_error(cmd, "unknown mode '%s' (voxel: exact, course, truth, fixed, lod; "
                                  "mesh: binary32, binary64, int)", v);
        o->mode_name = v;
        o->have_mode = 1;
    } else if (!strcmp(a, "-s")) {
        if (cli_size(v, &o->W, &o->H) || o->W > RETRO_MAX_SCREEN || o->H > RETRO_MAX_SCREEN ||
            (long)o->W * o->H > RETRO_MAX_PIXELS)
            return cli_error(cmd, "bad screen size '%s' (WxH, 1..%d each, at most %ld pixels)",
                             v, RETRO_MAX_SCREEN, RETRO_MAX_PIXELS);
        o->have_size = 1;
    } else if (!strcmp(a, "-d")) {
        if (cli_int(v, RETRO_MIN_DISTANCE, RETRO_MAX_DISTANCE, &o->D))
            return cli_error(cmd, "bad distance '%s' (an integer %d..%d)", v, RETRO_MIN_DISTANCE,
                             RETRO_MAX_DISTANCE);
        o->have_d = 1;
    } else if (!strcmp(a, "-p")) {
        if (cli_pair(v, &o->x, &o->y))
            return cli_error(cmd, "bad position '%s' (X,Y, finite numbers)", v);
        o->have_pos = 1;
    } else if (!strcmp(a, "-z")) {
        if (cli_int(v, -2147483647L - 1, 2147483647L, &o->z))
            return cli_error(cmd, "bad height '%s' (an int)", v);
        o->have_z = 1;
    } else if (!strcmp(a, "-a")) {
        if (cli_int(v, -2147483647L - 1, 2147483647L, &o->angle))
            return cli_error(cmd, "bad angle '%s' (an int, degrees)", v);
        o->have_angle = 1;
    } else if (!strcmp(a, "--sky")) {
        if (cli_rgb(v, &o->sky))
            return cli_error(cmd, "bad sky colour '%s' (RRGGBB)", v);
        o->have_sky = 1;
    } else if (!strcmp(a, "--isa")) {
        if (retro_cpu_limit(v)) {
            char levels[64];
            return cli_error(cmd, "unknown ISA level '%s' (%s)", v, retro_isa_list(levels, sizeof levels));
        }
    } else if (!strcmp(a, "--lod")) {
        if (cli_float(v, &o->lod) || o->lod < 0 || o->lod > 100)
            return cli_error(cmd, "bad lod '%s' (a number from 0 to 100)", v);
        o->have_lod = 1;
    } else if (!strcmp(a, "--threads")) {
        if (cli_int(v, 1, 64, &o->threads))
            return cli_error(cmd, "bad thread count '%s' (1..64)", v);
    } else
        return 0;
    return 1;
}

int render_args(const char *cmd, const char *what, int argc, char **argv, render_opts *o,
                int (*extra)(void *user, const char *a, const char *v), void *user, void (*help)(void))
{
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            help();
            return 1;
        }
        if (a[0] != '-') {
            if (o->map)
                return cli_error(cmd, "more than one %s: '%s' and '%s'", what, o->map, a);
            o->map = a;
            continue;
        }
        if (!(v = cli_value(argc, argv, &i)))
            return cli_no_value(cmd, a, cli_one_of(a, render_opt_names) || extra(user, a, NULL));
        int r = render_opt(cmd, o, a, v);
        if (r == 0)
            r = extra(user, a, v);
        if (r == CLI_EBADINPUT)
            return r;
        if (r == 0)
            return cli_error(cmd, "unknown option '%s' (retro %s --help)", a, cmd);
    }
    if (!o->map)
        return cli_error(cmd, "no %s given (retro %s --help)", what, cmd);
    return 0;
}
