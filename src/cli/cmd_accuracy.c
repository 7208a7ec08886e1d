/* retro accuracy: what each accuracy variant costs in time and gains in error, measured on
 * seeded random poses of the default and course scenes against mode truth. Writes a Markdown
 * table and a Pareto chart (time against error). Definitions: docs/ACCURACY.md. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "timing.h"
#include "accuracy_mesh.h"
#include "accuracy_metrics.h"
#include "accuracy_steady.h"
#include "cli.h"
#include "maps_dir.h"
#include "peer/peer_voxelspace.h"
#include "retro.h"
#include "retro_maps.h"

enum { W = 640, H = 480, D = 800, MAX_POSES = 4096 };
/* A sky no map colour can equal (map colours have a zero low byte): terrain is told exactly. */
#define SKY 0x000000ffu

typedef struct {
    const char *label;
    retro_mode mode;
    float lod;
    int half; /* mode exact at half resolution, scaled up */
    int peer; /* the classic demo's traversal (src/peer/), not a retro kernel */
    const char *what;
    acc_stats stats;
    acc_stats fam;  /* against the mesh in binary64, on the poses the mesh renders */
    double *ms;   /* per pose, fastest kernel for the mode */
    double *ms_y; /* per pose, ybuffer: the same scalar kernel for every variant */
    int n;
} variant;

/* Renders v's frame at pose p into out (W x H) with rc, timing only the render itself. One
 * context serves every variant: its caches are keyed by mode and map, and a threaded kernel's
 * pool binds its threads once instead of at every switch between contexts. */
static double render_variant(retro_ctx *rc, const retro_kernel *k, variant *v, const retro_map *m,
                             const player_t *p, uint32_t *out, uint32_t *small)
{
    int w = v->half ? (W + 1) / 2 : W, h = v->half ? (H + 1) / 2 : H;
    ctx_t c = {w, h, m->size, D, SKY, m->height, m->color, v->half ? small : out};
    static int peer_ybuf[W]; /* the peer's y-buffer: scratch allocated once */
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = v->mode;
    o.lod = v->lod;
    double t0 = cli_now_ms();
    if (v->peer)
        peer_voxelspace_render(p, &c, PEER_VOXELSPACE_DZ_GROWTH, peer_ybuf);
    else
        retro_render(rc, k, &o, p, &c);
    double t = cli_now_ms() - t0;
    if (v->half)
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++)
                out[y * W + x] = small[(y / 2) * w + x / 2];
    return t;
}


/* Two frames to warm the caches the previous variant evicted, then the median of n (at most
 * 15), as the benchmark times a kernel in a steady state. The last frame stays in out. */
static double time_frames(retro_ctx *rc, const retro_kernel *k, variant *v, const retro_map *m,
                          const player_t *p, uint32_t *out, uint32_t *small, int n)
{
    double t[15];
    for (int i = 0; i < n + 2; i++) {
        double ms = render_variant(rc, k, v, m, p, out, small);
        if (i >= 2)
            t[i - 2] = ms;
    }
    qsort(t, (size_t)n, sizeof t[0], cli_cmp_double);
    return t[n / 2];
}

static double time_variant(retro_ctx *rc, const retro_kernel *k, variant *v, const retro_map *m,
                           const player_t *p, uint32_t *out, uint32_t *small)
{
    return time_frames(rc, k, v, m, p, out, small, 5);
}

/* The reference frame of the run's steadiness (accuracy_steady.h): one fixed frame, timed
 * between poses with the two kernels the table's time columns use. */
typedef struct {
    retro_map map;
    player_t pose;
    variant *exact;
    const retro_kernel *best, *ybuffer;
    double t0;
} ref_frame;

/* The reference frame at a checkpoint: two untimed frames, then the median of the frames of
 * ACC_STEADY_MIN_MS (at least ACC_STEADY_MIN_FRAMES of them). */
static double time_checkpoint(retro_ctx *rc, const retro_kernel *k, variant *v, const retro_map *m,
                              const player_t *p, uint32_t *out, uint32_t *small)
{
    static double t[ACC_STEADY_MAX_FRAMES];
    for (int i = 0; i < 2; i++)
        render_variant(rc, k, v, m, p, out, small);
    int n = 0;
    double sum = 0;
    while (n < ACC_STEADY_MAX_FRAMES && (n < ACC_STEADY_MIN_FRAMES || sum < ACC_STEADY_MIN_MS)) {
        t[n] = render_variant(rc, k, v, m, p, out, small);
        sum += t[n++];
    }
    qsort(t, (size_t)n, sizeof t[0], cli_cmp_double);
    return t[n / 2];
}

static void checkpoint(acc_steady *st, const ref_frame *r, retro_ctx *rc, uint32_t *img, uint32_t *small,
                       const char *where, int pose)
{
    if (st->n == ACC_STEADY_MAX)
        return;
    /* The first checkpoint follows the map loads and an idle machine: a third of a second of
     * each kernel first, so that it times the machine's speed, not the caches and the clock
     * warming up (without it, the first checkpoint was the run's slowest in most runs). */
    for (int k = 0; st->n == 0 && k < 2; k++)
        for (double t0 = cli_now_ms(); cli_now_ms() - t0 < 300;)
            render_variant(rc, k ? r->ybuffer : r->best, r->exact, &r->map, &r->pose, img, small);
    acc_checkpoint *c = &st->cp[st->n++];
    c->best = time_checkpoint(rc, r->best, r->exact, &r->map, &r->pose, img, small);
    c->ybuf = time_checkpoint(rc, r->ybuffer, r->exact, &r->map, &r->pose, img, small);
    c->at_s = (cli_now_ms() - r->t0) / 1000;
    if (pose > 0)
        snprintf(c->where, sizeof c->where, "%.24s, before pose %d", where, pose);
    else
        snprintf(c->where, sizeof c->where, "%.40s", where);
}

static void help(void)
{
    printf("usage: retro accuracy [--poses N] [--mesh-poses M] [--seed S] [-o OUT.md] [--chart OUT.svg]\n"
           "                      [--maps DIR]\n\n"
           "Renders N seeded random poses (default 20) of each default scene (maps/) and course\n"
           "scene ($RETRO_SHARED/course) at 640x480, D 800, with every accuracy variant through\n"
           "the fastest kernel for its mode, and the classic demo's algorithm as a peer (its own\n"
           "code, src/peer/), compares each frame with mode truth and writes a table\n"
           "(default ./ACCURACY.md) and a Pareto chart (default ./accuracy-pareto.svg, and a .png\n"
           "beside it). make accuracy writes them to build/results/.\n"
           "Across families: the first M poses of each scene are also rendered by the mesh family\n"
           "in every mode; every variant of both families is measured against the mesh in binary64\n"
           "in a second table and chart (accuracy-families.svg/.png beside the first), and a\n"
           "picture pair (accuracy-pair-voxel.png, -mesh.png, -diff.png) goes beside the table.\n"
           "The report ends with the run's machine steadiness: one reference frame timed between\n"
           "poses; a spread above 10%% marks the run noisy (make publish-accuracy refuses it).\n"
           "  --poses N      poses per scene (default 20)\n"
           "  --mesh-poses M poses per scene the mesh renders, 0 for none (default 2, at most N)\n"
           "  --seed S       seed of the poses (default 1)\n"
           "  -o OUT.md      the table\n"
           "  --chart OUT.svg  the chart (OUT.png beside it where gnuplot has a PNG terminal)\n"
           "  --maps DIR     the generated maps (default: maps/ if it holds them, as in the\n"
           "                 source tree; else $XDG_CACHE_HOME/retro/maps, made on first use)\n");
}

int cmd_accuracy(int argc, char **argv)
{
    long poses = 20, mesh_poses = 2;
    uint64_t seed = 1;
    const char *out_md = "ACCURACY.md", *out_svg = "accuracy-pareto.svg", *maps_given = NULL;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *val;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            help();
            return 0;
        }
        static const char *const names[] = {"--poses", "--mesh-poses", "--seed", "-o", "--chart", "--maps", NULL};
        if (!(val = cli_value(argc, argv, &i)))
            return cli_no_value("accuracy", a, cli_one_of(a, names));
        if (!strcmp(a, "--poses")) {
            if (cli_int(val, 1, MAX_POSES, &poses))
                return cli_error("accuracy", "bad pose count '%s' (1..%d)", val, MAX_POSES);
        } else if (!strcmp(a, "--mesh-poses")) {
            if (cli_int(val, 0, MAX_POSES, &mesh_poses))
                return cli_error("accuracy", "bad mesh pose count '%s' (0..%d)", val, MAX_POSES);
        } else if (!strcmp(a, "--seed")) {
            if (cli_u64(val, &seed))
                return cli_error("accuracy", "bad seed '%s'", val);
        } else if (!strcmp(a, "-o") || !strcmp(a, "--chart")) {
            if (!acc_path_ok(val))
                return cli_error("accuracy", "bad output path for %s: empty, over %d bytes, or with a "
                                 "control character", a, ACC_PATH_MAX - 1);
            *(!strcmp(a, "-o") ? &out_md : &out_svg) = val;
        } else if (!strcmp(a, "--maps"))
            maps_given = val;
        else
            return cli_error("accuracy", "unknown option '%s' (retro accuracy --help)", a);
    }

    variant vars[] = {
        {.label = "truth", .mode = RETRO_MODE_TRUTH, .lod = 0, .half = 0, .what = "binary64, exact floor and wrap"},
        {.label = "exact", .mode = RETRO_MODE_EXACT, .lod = 0, .half = 0, .what = "binary32 (SEMANTICS.md)"},
        {.label = "course", .mode = RETRO_MODE_COURSE, .lod = 0, .half = 0, .what = "the course's arithmetic"},
        {.label = "fixed", .mode = RETRO_MODE_FIXED, .lod = 0, .half = 0, .what = "integer-only inner loop, 24+16 fraction bits"},
        {.label = "lod 0.005", .mode = RETRO_MODE_LOD, .lod = 0.005f, .half = 0, .what = "step max(1, d/200)"},
        {.label = "lod 0.02", .mode = RETRO_MODE_LOD, .lod = 0.02f, .half = 0, .what = "step max(1, d/50)"},
        {.label = "lod 0.05", .mode = RETRO_MODE_LOD, .lod = 0.05f, .half = 0, .what = "step max(1, d/20)"},
        {.label = "half", .mode = RETRO_MODE_EXACT, .lod = 0, .half = 1, .what = "exact at 320x240, scaled 2x"},
        {.label = "peer: classic demo", .mode = RETRO_MODE_EXACT, .peer = 1,
         .what = "s-macke's VoxelSpace traversal: step 1, +0.2 per distance (a peer, not a retro mode)"},
    };
    const int nv = (int)(sizeof vars / sizeof vars[0]);
    const char *shared = getenv("RETRO_SHARED") ? getenv("RETRO_SHARED") : "../shared";
    char scenes[6][1100], mapsdir[1024];
    if (cli_maps_dir("accuracy", maps_given, mapsdir, sizeof mapsdir))
        return CLI_EBADINPUT;
    int ns = 0;
    for (int i = 0; i < 3; i++)
        snprintf(scenes[ns++], sizeof scenes[0], "%s/%s", mapsdir, (const char *[]){"alpine", "islands", "canyon"}[i]);
    for (int i = 0; i < 3; i++)
        snprintf(scenes[ns++], sizeof scenes[0], "%s/course/%s", shared, (const char *[]){"valley", "island", "pyramids"}[i]);

    /* The families chart beside the first chart, the picture pair beside the table. */
    char fam_svg[1100], pair_dir[1100], pair_prefix[1200];
    const char *cs = strrchr(out_svg, '/'), *ms = strrchr(out_md, '/');
    snprintf(fam_svg, sizeof fam_svg, "%.*saccuracy-families.svg", cs ? (int)(cs - out_svg + 1) : 0, out_svg);
    snprintf(pair_dir, sizeof pair_dir, "%.*s", ms ? (int)(ms - out_md) : 1, ms ? out_md : ".");
    snprintf(pair_prefix, sizeof pair_prefix, "%s/accuracy-pair", pair_dir);
    uint32_t *truth = malloc(sizeof(uint32_t) * W * H), *img = malloc(sizeof(uint32_t) * W * H);
    uint32_t *small = malloc(sizeof(uint32_t) * W * H);
    const retro_kernel *ybuffer = retro_kernel_find("ybuffer");
    for (int k = 0; k < nv; k++) {
        vars[k].ms = malloc(sizeof(double) * (size_t)poses * (size_t)ns);
        vars[k].ms_y = malloc(sizeof(double) * (size_t)poses * (size_t)ns);
    }
    mesh_poses = mesh_poses < poses ? mesh_poses : poses;
    acc_mesh am;
    if (acc_mesh_init(&am, (int)mesh_poses * ns, W, H))
        return cli_error("accuracy", "out of memory");
    retro_ctx *rc = retro_ctx_new();
    if (!rc) {
        acc_mesh_free(&am);
        return cli_error("accuracy", "out of memory");
    }
    int total = 0, status = 0;
    char err[512];
    uint64_t rng = seed;
    /* The reference frame: the first scene's first pose (drawn from its own copy of the seed,
     * so the poses stay those of the seed), in mode exact, with its map kept for the run. */
    static acc_steady steady;
    ref_frame ref = {.exact = NULL, .best = retro_kernel_best(RETRO_MODE_EXACT), .ybuffer = ybuffer,
                     .t0 = cli_now_ms()};
    for (int k = 0; k < nv; k++)
        if (!strcmp(vars[k].label, "exact"))
            ref.exact = &vars[k];
    steady.n = 0;
    steady.best_kernel = ref.best->name;
    steady.ref = "mode exact, the first pose of the first scene, 640x480, D 800";
    uint64_t ref_rng = seed;
    if (retro_map_load(scenes[0], &ref.map, err, sizeof err))
        status = cli_error("accuracy", "%s (run make maps)", err);
    else
        acc_pose(&ref_rng, ref.map.size, ref.map.height, &ref.pose);
    for (int s = 0; s < ns && !status; s++) {
        retro_map m;
        if (retro_map_load(scenes[s], &m, err, sizeof err)) {
            if (s < 3)
                status = cli_error("accuracy", "%s (run make maps)", err);
            else
                fprintf(stderr, "accuracy: skipped %s: %s\n", scenes[s], err);
            continue;
        }
        /* The previous scene's buffers were freed: this map may sit at the same address, which
         * the contexts' caches (map maximum, packed map) would take for the same map. */
        retro_ctx_map_changed(rc);
        fprintf(stderr, "accuracy: %s, %ld poses...\n", scenes[s], poses);
        const char *name = strrchr(scenes[s], '/') ? strrchr(scenes[s], '/') + 1 : scenes[s];
        for (int n = 0; n < poses; n++) {
            if (n % 5 == 0)
                checkpoint(&steady, &ref, rc, img, small, name, n + 1);
            player_t p;
            acc_pose(&rng, m.size, m.height, &p);
            int mesh = n < mesh_poses;
            if (mesh) {
                ctx_t c = {W, H, m.size, D, SKY, m.height, m.color, NULL};
                acc_mesh_pose(&am, &c, &p);
            }
            for (int k = 0; k < nv; k++) {
                vars[k].ms_y[vars[k].n] = time_variant(rc, ybuffer, &vars[k], &m, &p, img, small);
                vars[k].ms[vars[k].n++] = time_variant(rc, retro_kernel_best(vars[k].mode), &vars[k], &m, &p,
                                                       img, small);
                if (k == 0)
                    memcpy(truth, img, sizeof(uint32_t) * W * H);
                acc_compare(&vars[k].stats, truth, img, W, H, SKY);
                if (mesh)
                    acc_compare(&vars[k].fam, am.ref, img, W, H, SKY);
            }
            total++;
        }
        if (s == 0 && mesh_poses > 0 && acc_write_pair(pair_dir, &m, W, H, D, 0x66a3ff00u, err, sizeof err))
            status = cli_error("accuracy", "%s", err);
        retro_map_free(&m);
    }
    if (!status) {
        checkpoint(&steady, &ref, rc, img, small, "end of the run", 0);
        double exact_ms = 0, exact_y = 0;
        for (int k = 0; k < nv; k++) {
            qsort(vars[k].ms, (size_t)vars[k].n, sizeof(double), cli_cmp_double);
            qsort(vars[k].ms_y, (size_t)vars[k].n, sizeof(double), cli_cmp_double);
            if (vars[k].mode == RETRO_MODE_EXACT && !vars[k].half && !vars[k].peer) {
                exact_ms = vars[k].ms[vars[k].n / 2];
                exact_y = vars[k].ms_y[vars[k].n / 2];
            }
        }
        acc_row rows[16], fam_rows[16];
        for (int k = 0; k < nv; k++) {
            rows[k].label = vars[k].label;
            rows[k].what = vars[k].what;
            rows[k].kernel = vars[k].peer ? "its own (scalar)" : retro_kernel_best(vars[k].mode)->name;
            rows[k].ms = vars[k].ms[vars[k].n / 2];
            rows[k].speedup = exact_ms / rows[k].ms;
            rows[k].ms_y = vars[k].ms_y[vars[k].n / 2];
            rows[k].speedup_y = exact_y / rows[k].ms_y;
            acc_summary(&vars[k].stats, &rows[k]);
            rows[k].family = "voxel";
            fam_rows[k] = rows[k];
            acc_summary(&vars[k].fam, &fam_rows[k]);
        }
        acc_mesh_rows(&am, fam_rows + nv, exact_ms);
        acc_families fam = {fam_rows, nv + ACC_MESH_MODES, am.n, fam_svg, pair_prefix};
        if (acc_write_report(out_md, out_svg, rows, nv, total, seed, am.n ? &fam : NULL, &steady, err, sizeof err))
            status = cli_error("accuracy", "%s", err);
        else
            printf("accuracy: %d poses; wrote %s and %s\n", total, out_md, out_svg);
    }
    for (int k = 0; k < nv; k++) {
        free(vars[k].ms);
        free(vars[k].ms_y);
    }
    retro_map_free(&ref.map);
    retro_ctx_free(rc);
    acc_mesh_free(&am);
    free(truth);
    free(img);
    free(small);
    return status;
}
