/* retro render: one frame of a map or a scene with any kernel in any mode. */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "hmax_pyramid.h"
#include "kernels.h"
#include "scene_args.h"

static void help(void)
{
    printf("usage: retro render MAP|SCENE [-k KERNEL] [-m MODE] [-s WxH] [-d DISTANCE]\n"
           "                        [-p X,Y] [-z HEIGHT] [-a ANGLE] [--sky RRGGBB] [--isa LEVEL]\n"
           "                        [--threads N] [--lod L] [--no-skip] [--simd-skip] [--stats]\n"
           "                        -o OUT.ppm|OUT.png\n\n"
           "MAP is a prefix: MAP.pgm (heights) and MAP.ppm or MAP.png (colours).\n"
           "SCENE is a file ending in .scene (README, Scenes): its map, camera, screen, sky and\n"
           "effects replace the defaults below, and the options given override the file. A scene\n"
           "with a path but no camera renders the path's first frame (retro fly renders them all).\n"
           "  -k KERNEL   kernel (default: the fastest this CPU runs for the mode; retro kernels)\n"
           "  -m MODE     exact (default), course (bit-compatible with the course), or an accuracy\n"
           "              variant: truth (binary64), fixed (integer inner loop), lod (docs/ACCURACY.md);\n"
           "              a scene with [lod] defaults to lod\n"
           "  --lod L     mode lod's step growth: step = max(1, floor(d * L)) (default 0.02)\n"
           "  -s WxH      screen size (default 640x480)\n"
           "  -d D        distance %d..%d: samples at d = 1..D-1, D = 1 is sky only (default\n"
           "              800); a scene's [screen] distance follows the same rule\n"
           "  -p X,Y      position (default: the map's centre)\n"
           "  -z HEIGHT   camera height (default: 60 above the terrain and the mean height)\n"
           "  -a ANGLE    degrees, counter-clockwise from +x (default 0)\n"
           "  --sky HEX   sky colour RRGGBB (default 66a3ff)\n"
           "  --isa L     highest ISA level to use: none, sse2, avx2, avx512 (also RETRO_ISA)\n"
           "  --threads N threads for threaded kernels (default OMP_NUM_THREADS or all cores)\n"
           "  --no-skip   evaluate every sample: no occlusion skipping (docs/SKIPPING.md); the\n"
           "              image is the same, only slower\n"
           "  --simd-skip the SIMD strips (and omp, pthreads) skip too, per group of columns;\n"
           "              exact, off by default: not yet faster where measured\n"
           "  --stats     also print the samples the ybuffer kernel evaluates and those that\n"
           "              paint, and their share of the frame's samples (W x (D-1)); and\n"
           "              simd-avx512's, where it runs\n"
           "  -o OUT      output image, .ppm or .png; nothing is written on failure\n"
           "A render that would take more than a few seconds (the naive reference at a large\n"
           "distance or screen) prints a one-line warning on stderr first. Input limits and the\n"
           "environment variables read: docs/INPUT.md.\n",
           RETRO_MIN_DISTANCE, RETRO_MAX_DISTANCE);
}

static int render_extra(void *user, const char *a, const char *v)
{
    if (strcmp(a, "-o"))
        return 0;
    *(const char **)user = v;
    return 1;
}

/* The frame rendered again by the counting build of ybuffer (the same bytes, into the same
 * buffer), and its counts. Returns 0 or CLI_EBADINPUT. */
static int print_stats(render_job *j, const player_t *p)
{
    retro_kernel counted = *retro_kernel_find("ybuffer");
    counted.fn = retro_kernel_ybuffer_counted;
    memset(&retro_ybuffer_counts, 0, sizeof retro_ybuffer_counts);
    retro_err e = retro_render(&j->rc, &counted, j->mode, p, &j->c);
    if (e)
        return cli_error("render", "%s", retro_strerror(e));
    const retro_frame *f = &j->rc.frame;
    int n = f->mode == RETRO_MODE_LOD ? f->ndist : f->D;
    double all = (double)f->W * (double)(n > 1 ? n - 1 : 0);
    const retro_sample_counts *s = &retro_ybuffer_counts;
    printf("samples: %.0f (W x (D-1)), skipping %s\n", all, retro_skip_applies(f) ? "on" : "off");
    printf("evaluated: %" PRIu64 " (%.2f%%)\n", s->evaluated, all > 0 ? 100.0 * (double)s->evaluated / all : 0.0);
    printf("painting: %" PRIu64 " (%.2f%%)\n", s->painting, all > 0 ? 100.0 * (double)s->painting / all : 0.0);
    printf("probes: %" PRIu64 ", pyramid windows read: %" PRIu64 "\n", s->probes, s->windows);
    /* The vector path (what omp runs too) skips per group of 16 columns: its own counts. */
    const retro_kernel *vk = retro_kernel_find("simd-avx512");
    if (vk && retro_kernel_runs_here(vk) && !retro_kernel_check(vk, j->mode, j->rc.fx, NULL, 0)) {
        retro_kernel vc = *vk;
        vc.fn = retro_kernel_simd_avx512_counted;
        memset(&retro_simd_counts, 0, sizeof retro_simd_counts);
        if ((e = retro_render(&j->rc, &vc, j->mode, p, &j->c)))
            return cli_error("render", "%s", retro_strerror(e));
        const retro_sample_counts *v = &retro_simd_counts;
        printf("simd-avx512 evaluated: %" PRIu64 " (%.2f%%), painting: %" PRIu64 ", probes: %" PRIu64
               ", windows: %" PRIu64 "\n",
               v->evaluated, all > 0 ? 100.0 * (double)v->evaluated / all : 0.0, v->painting, v->probes, v->windows);
    }
    return 0;
}

int cmd_render(int argc, char **argv)
{
    const char *out_path = NULL;
    render_opts o;
    render_opts_init(&o);
    /* The two flags without a value are taken out before the shared parser sees argv. */
    int no_skip = 0, simd_skip = 0, stats = 0, n = 0;
    char **args = malloc(((size_t)argc + 1) * sizeof *args);
    if (!args)
        return cli_error("render", "out of memory");
    for (int i = 0; i < argc; i++) {
        if (i > 0 && !strcmp(argv[i], "--no-skip"))
            no_skip = 1;
        else if (i > 0 && !strcmp(argv[i], "--simd-skip"))
            simd_skip = 1;
        else if (i > 0 && !strcmp(argv[i], "--stats"))
            stats = 1;
        else
            args[n++] = argv[i];
    }
    args[n] = NULL;
    int r = render_args("render", "MAP", n, args, &o, render_extra, &out_path, help);
    free(args);
    if (r)
        return r == 1 ? 0 : r;
    if (!out_path)
        return cli_error("render", "no output given: -o OUT.ppm or -o OUT.png");

    render_job j;
    if (job_open("render", &o, &j))
        return CLI_EBADINPUT;
    j.rc.no_skip = no_skip;
    j.rc.simd_skip = simd_skip;
    player_t p;
    job_pose(&j, &o, -1, &p);
    int status = job_write("render", &j, &p, out_path);
    if (!status && stats)
        status = print_stats(&j, &p);
    job_close(&j);
    return status;
}
