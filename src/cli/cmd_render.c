/* retro render: one frame of a map or a scene with any kernel in any mode. */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cone_map.h"
#include "ctx.h"
#include "env.h"
#include "hmax_pyramid.h"
#include "isa.h"
#include "kernels.h"
#include "render_columns.h"
#include "render_timing.h"
#include "retro_mesh.h"
#include "scene_args.h"

static void help(void)
{
    char isa[64];
    retro_isa_list(isa, sizeof isa);
    printf("usage: retro render MAP|SCENE [-k KERNEL] [-m MODE] [-s WxH] [-d DISTANCE]\n"
           "                        [-p X,Y] [-z HEIGHT] [-a ANGLE] [--sky RRGGBB] [--isa LEVEL]\n"
           "                        [--threads N] [--lod L] [--no-skip] [--stats]\n"
           "                        [--columns OUT.csv] [--time [N] [--versus ARGS]]\n"
           "                        -o OUT.ppm|OUT.png\n\n"
           "MAP is a prefix: MAP.pgm (heights) and MAP.ppm or MAP.png (colours).\n"
           "SCENE is a file ending in .scene (README, Scenes): its map, camera, screen, sky and\n"
           "effects replace the defaults below, and the options given override the file. A scene\n"
           "with a path but no camera renders the path's first frame (retro fly renders them all).\n"
           "  -k KERNEL   kernel of either family (default: the fastest this CPU runs for the mode;\n"
           "              retro kernels lists them; mesh-zbuffer and mesh-painter draw triangles)\n"
           "  -m MODE     voxel: exact (default), course (bit-compatible with the course), or an\n"
           "              accuracy variant: truth (binary64), fixed (integer inner loop), lod\n"
           "              (docs/ACCURACY.md); a scene with [lod] defaults to lod.\n"
           "              mesh: binary32 (default), binary64, int (docs/MESH.md)\n"
           "  --lod L     mode lod's step growth: step = max(1, floor(d * L)) (default 0.02)\n"
           "  -s WxH      screen size (default 640x480)\n"
           "  -d D        distance %d..%d: samples at d = 1..D-1, D = 1 is sky only (default\n"
           "              800); a scene's [screen] distance follows the same rule\n"
           "  -p X,Y      position (default: the map's centre)\n"
           "  -z HEIGHT   camera height (default: 60 above the terrain and the mean height)\n"
           "  -a ANGLE    degrees, counter-clockwise from +x (default 0)\n"
           "  --sky HEX   sky colour RRGGBB (default 66a3ff)\n"
           "  --isa L     highest ISA level to use: %s (also RETRO_ISA)\n"
           "  --threads N threads for threaded kernels (default OMP_NUM_THREADS or all cores)\n"
           "  --no-skip   evaluate every sample: no occlusion skipping (docs/SKIPPING.md); the\n"
           "              image is the same, only slower\n"
           "  --stats     voxel: also print the samples the ybuffer kernel evaluates and those that\n"
           "              paint, and their share of the frame's samples (W x (D-1)), what\n"
           "              ideal max and plane bounds and an oracle would evaluate\n"
           "              (docs/SKIPPING.md), what the ybuffer walk evaluates given\n"
           "              the ideal's boxes, the ideal's probe schedule or unaligned\n"
           "              windows, what 16-lane groups whose lanes each walked\n"
           "              as the ybuffer column does would, and simd-avx512's where it\n"
           "              runs; mesh: the triangles submitted, after culling, after\n"
           "              clipping, and the fragments\n"
           "  --columns CSV voxel: write per screen column the samples the ybuffer kernel\n"
           "              evaluates and those that paint, with skipping as asked and without:\n"
           "              column,samples,evaluated,painting,evaluated_noskip,painting_noskip\n"
           "              (they add up to --stats' counts); -o is then optional\n"
           "  --time [N]  render N frames (default 50) after one untimed frame and print the\n"
           "              kernel used, the mode, the median and the minimum ms per frame;\n"
           "              -o is then optional (the last frame is written)\n"
           "  --versus ARGS  with --time: also time the configuration ARGS make of this one\n"
           "              (words split at spaces: options that override, a MAP|SCENE that\n"
           "              replaces; e.g. \"--no-skip\", \"-k simd-avx512 --threads 1\"; not -o,\n"
           "              --columns, --stats, --time, --isa), the frames taken in turn, and print\n"
           "              its line and the median and quartiles of the N ratios of its time to\n"
           "              the first's\n"
           "  -o OUT      output image, .ppm or .png; nothing is written on failure\n"
           "A render that would take more than a few seconds (the naive reference at a large\n"
           "distance or screen) prints a one-line warning on stderr first. Input limits and the\n"
           "environment variables read: docs/INPUT.md.\n",
           RETRO_MIN_DISTANCE, RETRO_MAX_DISTANCE, isa);
}

/* The outputs named on the command line: -o and --columns. */
typedef struct render_outputs {
    const char *image, *columns;
} render_outputs;

static int render_extra(void *user, const char *a, const char *v)
{
    render_outputs *o = user;
    if (!strcmp(a, "-o"))
        o->image = v ? v : o->image;
    else if (!strcmp(a, "--columns"))
        o->columns = v ? v : o->columns;
    else
        return 0;
    return 1;
}

/* The mesh frame's counts, kept by the family from the frame just rendered. */
static int print_mesh_stats(const render_job *j)
{
    const retro_mesh_stats *s = retro_mesh_last_stats(j->rc);
    if (!s)
        return cli_error("render", "no mesh frame was rendered");
    uint64_t front = s->submitted - s->culled;
    printf("triangles submitted: %" PRIu64 "\n", s->submitted);
    printf("after culling: %" PRIu64 " (%" PRIu64 " back faces)\n", front, s->culled);
    printf("after clipping: %" PRIu64 " (%" PRIu64 " entirely outside), %" PRIu64 " sub-triangles rasterized\n",
           front - s->clipped_out, s->clipped_out, s->rasterized);
    printf("fragments: %" PRIu64 " (%" PRIu64 " written)\n", s->fragments, s->written);
    return 0;
}

/* What a vector of 16 adjacent columns would evaluate if each lane walked its own distances,
 * skipping exactly as the ybuffer column walk does (docs/studies/SKIPPING_LIMITS.md, "How far a max
 * bound can go"): every step still moves all lanes, so a group takes as many steps as its busiest
 * column, and counts them for its live lanes as the SIMD counting build does. Groups from column 0.
 * Returns 0 or CLI_EBADINPUT. */
static int print_lanes_alone(render_job *j, const player_t *p, double all)
{
    enum { LANES = 16 };
    const int W = j->c.scr_width;
    retro_column_counts *cols = calloc((size_t)W, sizeof *cols);
    if (!cols)
        return cli_error("render", "out of memory");
    if (columns_count(j, p, &j->opts, cols)) {
        free(cols);
        return CLI_EBADINPUT;
    }
    double steps = 0;
    for (int u0 = 0; u0 < W; u0 += LANES) {
        const int width = W - u0 < LANES ? W - u0 : LANES;
        uint64_t most = 0;
        for (int u = u0; u < u0 + width; u++)
            most = cols[u].evaluated > most ? cols[u].evaluated : most;
        steps += (double)width * (double)most;
    }
    free(cols);
    printf("lanes walking alone, 16 to a group: %.2f%% (each group as many steps as its busiest column)\n",
           all > 0 ? 100.0 * steps / all : 0.0);
    return 0;
}

/* The counting ybuffer's own walk given one part of the ideal walk at a time
 * (docs/studies/SKIPPING_LIMITS.md, "Window or schedule"): its share of all (W x (D-1))
 * evaluated with each. Returns 0 or CLI_EBADINPUT. */
static int print_walk_parts(render_job *j, const retro_kernel *counted, const player_t *p, double all)
{
    static const struct {
        int window, every;
        const char *name;
    } part[] = {{RETRO_WINDOW_OWN_BOX, 0, "the run's own box"},
                {RETRO_WINDOW_BLOCKS, 1, "one probe per sample"},
                {RETRO_WINDOW_UNALIGNED, 0, "unaligned windows"},
                {RETRO_WINDOW_UNALIGNED, 1, "unaligned windows and one probe per sample"}};
    printf("the column walk evaluates, with");
    for (size_t i = 0; i < sizeof part / sizeof part[0]; i++) {
        memset(&retro_ybuffer_counts, 0, sizeof retro_ybuffer_counts);
        retro_skip_window = part[i].window;
        retro_skip_every = part[i].every;
        retro_err e = retro_render(j->rc, counted, &j->opts, p, &j->c);
        retro_skip_window = RETRO_WINDOW_BLOCKS;
        retro_skip_every = 0;
        if (e)
            return cli_error("render", "%s", retro_strerror(e));
        printf("%s %s: %.2f%% (%" PRIu64 " windows)", i ? "," : "", part[i].name,
               all > 0 ? 100.0 * (double)retro_ybuffer_counts.evaluated / all : 0.0, retro_ybuffer_counts.windows);
    }
    printf("\n");
    return 0;
}

/* The cone steps' study (docs/studies/SKIPPING_LIMITS.md, "Cone steps"): the share of all
 * (W x (D-1)) the column walk evaluates by cone steps alone, with the pyramid's probe before
 * every sample too, and with the ideal max bound's probe (blocks down to 4 cells) instead, for
 * frames of mode exact with plain samples (cone_map.h). RETRO_CONE_SECTORS and RETRO_CONE_R set
 * the map's shape (checked with the other variables at start-up: src/core/env.c). Returns 0 or
 * CLI_EBADINPUT. */
static int print_cone_steps(render_job *j, const retro_kernel *counted, const player_t *p, double all)
{
    const retro_frame *f = retro_ctx_frame(j->rc);
    if (!retro_skip_applies(f) || f->mode != RETRO_MODE_EXACT || (f->fx & RETRO_FX_BILINEAR))
        return 0;
    long sectors = RETRO_CONE_SECTORS_DEFAULT, R = RETRO_CONE_R_DEFAULT;
    char err[160];
    if (retro_env_long("RETRO_CONE_SECTORS", RETRO_CONE_SECTORS_MIN, RETRO_CONE_SECTORS_MAX, &sectors, err,
                       sizeof err) < 0 ||
        retro_env_long("RETRO_CONE_R", 1, RETRO_CONE_R_MAX, &R, err, sizeof err) < 0)
        return cli_error("render", "%s", err);
    /* a study's map of 5 bytes per cell and sector: past 1 GiB it is not built, so that --stats
     * on a large map stays quick */
    const double bytes = 5.0 * (double)f->S * (double)f->S * (double)sectors;
    if (bytes > 1024.0 * 1024.0 * 1024.0) {
        printf("cone steps: not for this map (%ld sectors would take %.0f MiB)\n", sectors, bytes / 1048576.0);
        return 0;
    }
    retro_cone_map m;
    if (retro_cone_build(&m, f->height_map, f->S, (int)sectors, (int)R))
        return cli_error("render", "out of memory");
    if (!retro_cone_applies(&m, f)) {
        retro_cone_free(&m);
        printf("cone steps: not for this frame (a column's step is too short or its positions round too far)\n");
        return 0;
    }
    static const char *const with[] = {"alone", "with the pyramid's probe before every sample",
                                       "with the ideal max bound's (blocks down to 4 cells)"};
    printf("cone steps (%ld sectors, radius %ld cells) evaluate:", sectors, R);
    for (int v = 0; v < 3; v++) {
        memset(&retro_ybuffer_counts, 0, sizeof retro_ybuffer_counts);
        retro_skip_cone = &m;
        retro_skip_cone_pyramid = v > 0;
        retro_skip_ideal = v == 2 ? RETRO_PYR_LMIN : -1;
        retro_err e = retro_render(j->rc, counted, &j->opts, p, &j->c);
        retro_skip_cone = NULL;
        retro_skip_cone_pyramid = 0;
        retro_skip_ideal = -1;
        if (e) {
            retro_cone_free(&m);
            return cli_error("render", "%s", retro_strerror(e));
        }
        printf("%s %.2f%% %s", v ? "," : "", all > 0 ? 100.0 * (double)retro_ybuffer_counts.evaluated / all : 0.0,
               with[v]);
    }
    printf("\n");
    retro_cone_free(&m);
    return 0;
}

/* The frame rendered again by the counting build of ybuffer (the same bytes, into the same
 * buffer), and its counts. Returns 0 or CLI_EBADINPUT. */
static int print_stats(render_job *j, const player_t *p)
{
    if (j->k->family == &retro_family_mesh)
        return print_mesh_stats(j);
    retro_kernel counted = *retro_kernel_find("ybuffer");
    counted.fn = retro_kernel_ybuffer_counted;
    memset(&retro_ybuffer_counts, 0, sizeof retro_ybuffer_counts);
    retro_err e = retro_render(j->rc, &counted, &j->opts, p, &j->c);
    if (e)
        return cli_error("render", "%s", retro_strerror(e));
    const retro_frame *f = retro_ctx_frame(j->rc);
    int n = f->mode == RETRO_MODE_LOD ? f->ndist : f->D;
    double all = (double)f->W * (double)(n > 1 ? n - 1 : 0);
    const retro_sample_counts *s = &retro_ybuffer_counts;
    /* the ybuffer strip skips whenever the frame carries a pyramid: modes exact and lod, and mode
     * course where its drift is bounded (skip_course.h) */
    printf("samples: %.0f (W x (D-1)), skipping %s\n", all, f->pyr ? "on" : "off");
    printf("evaluated: %" PRIu64 " (%.2f%%)\n", s->evaluated, all > 0 ? 100.0 * (double)s->evaluated / all : 0.0);
    printf("painting: %" PRIu64 " (%.2f%%)\n", s->painting, all > 0 ? 100.0 * (double)s->painting / all : 0.0);
    printf("probes: %" PRIu64 ", pyramid windows read: %" PRIu64 "\n", s->probes, s->windows);
    /* How far a bound on runs could go at all (docs/SKIPPING.md): the same walk with the ideal
     * max bound, a plane and the oracle, with blocks down to 4 cells (the pyramid's finest) and
     * down to 2. */
    static const char *const bound[] = {"max", "plane", "oracle"};
    for (int kind = RETRO_IDEAL_MAX; kind <= RETRO_IDEAL_ORACLE && retro_skip_applies(f); kind++) {
        if (kind == RETRO_IDEAL_PLANE && (f->fx & RETRO_FX_BILINEAR))
            continue; /* the plane bounds plain samples only */
        printf("ideal %s bound evaluates:", bound[kind]);
        for (int l = RETRO_PYR_LMIN; l >= RETRO_PYR_LMIN - 1; l--) {
            memset(&retro_ybuffer_counts, 0, sizeof retro_ybuffer_counts);
            retro_skip_ideal = l;
            retro_skip_ideal_kind = kind;
            e = retro_render(j->rc, &counted, &j->opts, p, &j->c);
            retro_skip_ideal = -1;
            retro_skip_ideal_kind = RETRO_IDEAL_MAX;
            if (e)
                return cli_error("render", "%s", retro_strerror(e));
            printf("%s %.2f%% with blocks down to %d cells", l == RETRO_PYR_LMIN ? "" : ",",
                   all > 0 ? 100.0 * (double)retro_ybuffer_counts.evaluated / all : 0.0, 1 << l);
        }
        printf("\n");
    }
    int r;
    if ((r = print_cone_steps(j, &counted, p, all)))
        return r;
    if (retro_skip_applies(f) && (r = print_walk_parts(j, &counted, p, all)))
        return r;
    if (retro_skip_applies(f) && (r = print_lanes_alone(j, p, all)))
        return r;
    /* The vector path (what omp runs too) skips per group of 16 columns: its own counts. Its
     * groups begin at the first column on a 64-byte line of out (column_chunks.h), so its
     * counts depend on where the frame lies in memory: the frame goes to a line-aligned buffer
     * here, whose groups begin at column 0 as the lanes-alone count's do, whatever the
     * allocator (a sanitizer's included) gave the image. */
    const retro_kernel *vk = retro_kernel_find("simd-avx512");
    if (vk && retro_kernel_runs_here(vk) && !retro_render_check(vk, &j->opts, NULL, 0)) {
        retro_kernel vc = *vk;
        vc.fn = retro_kernel_simd_avx512_counted;
        ctx_t c = j->c;
        const size_t bytes = (size_t)c.scr_width * (size_t)c.scr_height * sizeof *c.out;
        if (!(c.out = aligned_alloc(64, (bytes + 63) / 64 * 64)))
            return cli_error("render", "out of memory");
        memset(&retro_simd_counts, 0, sizeof retro_simd_counts);
        e = retro_render(j->rc, &vc, &j->opts, p, &c);
        free(c.out);
        if (e)
            return cli_error("render", "%s", retro_strerror(e));
        const retro_sample_counts *v = &retro_simd_counts;
        printf("simd-avx512 evaluated: %" PRIu64 " (%.2f%%), painting: %" PRIu64 ", probes: %" PRIu64
               ", windows: %" PRIu64 "\n",
               v->evaluated, all > 0 ? 100.0 * (double)v->evaluated / all : 0.0, v->painting, v->probes, v->windows);
    }
    return 0;
}

/* o2 for --versus ARGS: the first configuration's words (args[0..n), flags taken out) and
 * ARGS' words after them, parsed as the first were, without the first's MAP (map) when ARGS
 * names one; --no-skip among them sets *no_skip. Options that would write, count, time or set
 * a process-wide ISA level are refused. Returns 0, CLI_EBADINPUT after the one-line error.
 * o2's strings point into argv and buf. */
static int versus_opts(const char *versus, char **args, int n, const char *map, char *buf, size_t bufsize,
                       render_opts *o2, int *no_skip)
{
    enum { MAX_WORDS = 64 };
    char *words[MAX_WORDS];
    int nw = cli_words(versus, buf, bufsize, words, MAX_WORDS);
    if (nw < 0)
        return cli_error("render", "bad --versus '%s': give 1 to %d words in one argument of at most %zu characters",
                         versus, MAX_WORDS - 1, bufsize - 1);
    static const struct {
        const char *word, *why;
    } refused[] = {{"-o", "the first configuration's outputs are the only ones"},
                   {"--columns", "the first configuration's outputs are the only ones"},
                   {"--stats", "the first configuration's outputs are the only ones"},
                   {"--time", "both are timed with the first's --time"},
                   {"--versus", "it compares two configurations, not more"},
                   {"--isa", "the ISA level holds for the whole process (time each level in its own run)"},
                   {"--help", "it is not an option of a configuration"},
                   {"-h", "it is not an option of a configuration"}};
    char **all = malloc(((size_t)n + (size_t)nw + 1) * sizeof *all);
    if (!all)
        return cli_error("render", "out of memory");
    /* a MAP or SCENE among the words (a word that is no option's value) replaces the first's */
    int own_map = 0;
    for (int w = 0; w < nw; w++) {
        if (words[w][0] != '-')
            own_map = 1;
        else if (strcmp(words[w], "--no-skip"))
            w++; /* every other option takes a value */
    }
    int m = 0, r = 0;
    for (int i = 0; i < n; i++)
        if (!own_map || args[i] != map)
            all[m++] = args[i];
    for (int w = 0; w < nw && !r; w++) {
        for (size_t k = 0; k < sizeof refused / sizeof *refused && !r; k++)
            if (!strcmp(words[w], refused[k].word))
                r = cli_error("render", "--versus cannot take %s: %s", words[w], refused[k].why);
        if (!strcmp(words[w], "--no-skip"))
            *no_skip = 1;
        else
            all[m++] = words[w];
    }
    all[m] = NULL;
    if (!r) {
        render_outputs ignored = {NULL, NULL};
        render_opts_init(o2);
        r = render_args("render", "MAP", m, all, o2, render_extra, &ignored, help);
    }
    free(all);
    return r;
}

int cmd_render(int argc, char **argv)
{
    render_outputs outs = {NULL, NULL};
    render_opts o;
    render_opts_init(&o);
    /* The flags the shared parser does not know are taken out before it sees argv. */
    int no_skip = 0, stats = 0, n = 0;
    long time_n = 0; /* --time: frames to time, 0 when not asked */
    const char *versus = NULL; /* --versus ARGS */
    char **args = malloc(((size_t)argc + 1) * sizeof *args);
    if (!args)
        return cli_error("render", "out of memory");
    for (int i = 0; i < argc; i++) {
        if (i > 0 && !strcmp(argv[i], "--no-skip"))
            no_skip = 1;
        else if (i > 0 && !strcmp(argv[i], "--stats"))
            stats = 1;
        else if (i > 0 && !strcmp(argv[i], "--versus")) {
            if (i + 1 >= argc) {
                free(args);
                return cli_error("render", "option --versus needs ARGS (retro render --help)");
            }
            versus = argv[++i];
        } else if (i > 0 && !strcmp(argv[i], "--time")) {
            time_n = 50;
            /* an optional count: the next argument when it is a number */
            long v;
            if (i + 1 < argc && argv[i + 1][0] != '-' && !cli_int(argv[i + 1], -2147483647L, 2147483647L, &v)) {
                if (v < 1 || v > 100000) {
                    free(args);
                    return cli_error("render", "bad frame count '%s' for --time (1..100000)", argv[i + 1]);
                }
                time_n = v;
                i++;
            }
        }
        else
            args[n++] = argv[i];
    }
    args[n] = NULL;
    int r = render_args("render", "MAP", n, args, &o, render_extra, &outs, help);
    if (!r && versus && !time_n)
        r = cli_error("render", "--versus times two configurations: it needs --time");
    /* the second configuration: the same words with ARGS' after them (the later ones win) */
    render_opts o2;
    int no_skip2 = no_skip;
    char words_buf[1024];
    if (!r && versus)
        r = versus_opts(versus, args, n, o.map, words_buf, sizeof words_buf, &o2, &no_skip2);
    free(args);
    if (r)
        return r == 1 ? 0 : r;
    const char *out_path = outs.image;
    if (!out_path && !time_n && !outs.columns)
        return cli_error("render", "no output given: -o OUT.ppm or -o OUT.png");

    render_job j, j2;
    if (job_open("render", &o, &j))
        return CLI_EBADINPUT;
    if (versus && job_open("render", &o2, &j2)) {
        job_close(&j);
        return CLI_EBADINPUT;
    }
    j.opts.no_skip = no_skip;
    player_t p, p2;
    job_pose(&j, &o, -1, &p);
    if (versus) {
        j2.opts.no_skip = no_skip2;
        job_pose(&j2, &o2, -1, &p2);
    }
    /* The column counts are staged before the image is written, so a bad --columns leaves
     * no image either, and committed only when everything else succeeded. */
    render_columns cols = {outs.columns, NULL};
    int status = outs.columns ? columns_stage(&cols, &j, &p) : 0;
    if (!status && time_n)
        status = versus ? render_versus(&j, &p, &j2, &p2, time_n) : render_time(&j, &p, time_n);
    if (!status && out_path)
        status = job_write("render", &j, &p, out_path);
    if (!status && stats)
        status = print_stats(&j, &p);
    int cs = columns_finish(&cols, !status);
    status = status ? status : cs;
    if (versus)
        job_close(&j2);
    job_close(&j);
    return status;
}
