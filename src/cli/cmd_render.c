/* retro render: one frame of a map with any kernel in either mode. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "retro.h"
#include "retro_maps.h"

static void help(void)
{
    printf("usage: retro render MAP [-k KERNEL] [-m MODE] [-s WxH] [-d DISTANCE]\n"
           "                        [-p X,Y] [-z HEIGHT] [-a ANGLE] [--sky RRGGBB] [--isa LEVEL]\n"
           "                        [--threads N] [--lod L]\n"
           "                        -o OUT.ppm|OUT.png\n\n"
           "MAP is a prefix: MAP.pgm (heights) and MAP.ppm or MAP.png (colours).\n"
           "  -k KERNEL   kernel (default: the fastest this CPU runs for the mode; retro kernels)\n"
           "  -m MODE     exact (default), course (bit-compatible with the course), or an accuracy\n"
           "              variant: truth (binary64), fixed (integer inner loop), lod (docs/ACCURACY.md)\n"
           "  --lod L     mode lod's step growth: step = max(1, floor(d * L)) (default 0.02)\n"
           "  -s WxH      screen size (default 640x480)\n"
           "  -d D        distance: samples at d = 1..D-1 (default 800)\n"
           "  -p X,Y      position (default: the map's centre)\n"
           "  -z HEIGHT   camera height (default: 60 above the terrain and the mean height)\n"
           "  -a ANGLE    degrees, counter-clockwise from +x (default 0)\n"
           "  --sky HEX   sky colour RRGGBB (default 66a3ff)\n"
           "  --isa L     highest ISA level to use: none, sse2, avx2, avx512 (also RETRO_ISA)\n"
           "  --threads N threads for threaded kernels (default OMP_NUM_THREADS or all cores)\n"
           "  -o OUT      output image, .ppm or .png; nothing is written on failure\n");
}

int cmd_render(int argc, char **argv)
{
    const char *map_path = NULL, *out_path = NULL, *kname = NULL;
    retro_mode mode = RETRO_MODE_EXACT;
    int W = 640, H = 480, have_pos = 0, have_z = 0;
    long D = 800, z = 0, angle = 0, threads = 0;
    float x = 0, y = 0, lod = 0;
    uint32_t sky = 0x66a3ff00u;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            help();
            return 0;
        }
        if (a[0] != '-') {
            if (map_path)
                return cli_error("render", "more than one MAP: '%s' and '%s'", map_path, a);
            map_path = a;
            continue;
        }
        if (!(v = cli_value(argc, argv, &i)))
            return cli_error("render", "option %s needs a value (retro render --help)", a);
        if (!strcmp(a, "-k"))
            kname = v;
        else if (!strcmp(a, "-m")) {
            if (retro_mode_parse(v, &mode))
                return cli_error("render", "unknown mode '%s' (exact, course, truth, fixed, lod)", v);
        } else if (!strcmp(a, "-s")) {
            if (cli_size(v, &W, &H) || W > RETRO_MAX_SCREEN || H > RETRO_MAX_SCREEN ||
                (long)W * H > RETRO_MAX_PIXELS)
                return cli_error("render", "bad screen size '%s' (WxH, 1..%d each, at most %ld pixels)",
                                 v, RETRO_MAX_SCREEN, RETRO_MAX_PIXELS);
        } else if (!strcmp(a, "-d")) {
            if (cli_int(v, -2147483647L - 1, RETRO_MAX_DISTANCE, &D))
                return cli_error("render", "bad distance '%s' (an integer up to %d)", v, RETRO_MAX_DISTANCE);
        } else if (!strcmp(a, "-p")) {
            if (cli_pair(v, &x, &y))
                return cli_error("render", "bad position '%s' (X,Y, finite numbers)", v);
            have_pos = 1;
        } else if (!strcmp(a, "-z")) {
            if (cli_int(v, -2147483647L - 1, 2147483647L, &z))
                return cli_error("render", "bad height '%s' (an int)", v);
            have_z = 1;
        } else if (!strcmp(a, "-a")) {
            if (cli_int(v, -2147483647L - 1, 2147483647L, &angle))
                return cli_error("render", "bad angle '%s' (an int, degrees)", v);
        } else if (!strcmp(a, "--sky")) {
            if (cli_rgb(v, &sky))
                return cli_error("render", "bad sky colour '%s' (RRGGBB)", v);
        } else if (!strcmp(a, "--isa")) {
            if (retro_cpu_limit(v))
                return cli_error("render", "unknown ISA level '%s' (none, sse2, avx2, avx512)", v);
        } else if (!strcmp(a, "--lod")) {
            if (cli_float(v, &lod) || lod < 0 || lod > 100)
                return cli_error("render", "bad lod '%s' (a number from 0 to 100)", v);
        } else if (!strcmp(a, "--threads")) {
            if (cli_int(v, 1, 64, &threads))
                return cli_error("render", "bad thread count '%s' (1..64)", v);
        } else if (!strcmp(a, "-o"))
            out_path = v;
        else
            return cli_error("render", "unknown option '%s' (retro render --help)", a);
    }
    if (!map_path)
        return cli_error("render", "no MAP given (retro render --help)");
    if (!out_path)
        return cli_error("render", "no output given: -o OUT.ppm or -o OUT.png");

    const retro_kernel *k = kname ? retro_kernel_find(kname) : retro_kernel_best(mode);
    if (!k)
        return cli_error("render", "unknown kernel '%s' (retro kernels lists them)", kname);
    if (!retro_kernel_has_mode(k, mode))
        return cli_error("render", "kernel '%s' does not support mode %s", k->name, retro_mode_name(mode));
    if (!retro_kernel_runs_here(k))
        return cli_error("render", "kernel '%s' needs an ISA this CPU (or --isa) lacks", k->name);

    char err[512];
    retro_map m;
    if (retro_map_load(map_path, &m, err, sizeof err))
        return cli_error("render", "%s", err);
    if (mode == RETRO_MODE_COURSE && m.size < 2) {
        retro_map_free(&m);
        return cli_error("render", "mode course needs a map of size 2 or more");
    }
    struct retro_view view;
    retro_default_view(&m, &view);
    player_t p = {0};
    p.x = have_pos ? x : view.x;
    p.y = have_pos ? y : view.y;
    p.angle = (int)angle;
    p.height = have_z ? (int)z : view.height;

    uint32_t *out = malloc((size_t)W * (size_t)H * sizeof *out);
    if (!out) {
        retro_map_free(&m);
        return cli_error("render", "out of memory for a %dx%d frame", W, H);
    }
    ctx_t c = {W, H, m.size, (int)D, sky, m.height, m.color, out};
    retro_ctx rc;
    retro_ctx_init(&rc);
    rc.threads = (int)threads;
    rc.lod = lod;
    retro_err e = retro_render(&rc, k, mode, &p, &c);
    int status = 0;
    if (e)
        status = cli_error("render", "%s", retro_strerror(e));
    else if (retro_image_write(out_path, out, W, H, err, sizeof err))
        status = cli_error("render", "%s", err);
    retro_ctx_free(&rc);
    free(out);
    retro_map_free(&m);
    return status;
}
