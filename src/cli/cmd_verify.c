/* retro verify: every kernel, in every mode it supports, against naive of the same mode, byte
 * for byte, over the cases of verify_cases.c. Prints a case x kernel table, writes a diff
 * image per mismatch and exits 1 on any difference. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "cli.h"
#include "maps_dir.h"
#include "retro.h"
#include "retro_maps.h"
#include "retro_scene.h"
#include "verify_cases.h"
#include "verify_variants.h"

typedef struct {
    const char *name;
    retro_map map;
    int state; /* 0 not loaded, 1 loaded, -1 absent */
} map_slot;

typedef struct {
    int quick;
    const char *only;      /* a kernel name, or NULL for all */
    const char *outdir;
    const char *shared;
    const char *mapsdir;   /* --maps, ./maps or the cache (maps_dir.h) */
    map_slot maps[32];
    int nmaps;
    int differ, compared, skipped;
} verify_run;

static const retro_map *get_map(verify_run *v, const char *name, char *err, size_t n)
{
    for (int i = 0; i < v->nmaps; i++)
        if (!strcmp(v->maps[i].name, name))
            return v->maps[i].state > 0 ? &v->maps[i].map : NULL;
    map_slot *s = &v->maps[v->nmaps++];
    s->name = name;
    char prefix[1024];
    if (!strncmp(name, "course/", 7))
        snprintf(prefix, sizeof prefix, "%s/course/%s", v->shared, name + 7);
    else
        snprintf(prefix, sizeof prefix, "%s/%s", v->mapsdir, name);
    s->state = retro_map_load(prefix, &s->map, err, n) ? -1 : 1;
    return s->state > 0 ? &s->map : NULL;
}

static void player_for(const verify_case *c, const retro_map *m, player_t *p)
{
    struct retro_view view;
    retro_default_view(m, &view);
    memset(p, 0, sizeof *p);
    p->x = isnan(c->x) ? view.x : (float)c->x;
    p->y = isnan(c->y) ? view.y : (float)c->y;
    p->angle = c->angle;
    int64_t h = c->height;
    if (c->rel_height) {
        double S = m->size;
        double wx = fmod(fmod((double)p->x, S) + S, S), wy = fmod(fmod((double)p->y, S) + S, S);
        size_t i = (size_t)wx % (size_t)m->size, j = (size_t)wy % (size_t)m->size;
        h += m->height[j * (size_t)m->size + i];
    }
    p->height = (int)h;
}

/* Dimmed reference with differing pixels in magenta, so a mismatch can be seen at a glance. */
static void write_diff(verify_run *v, const char *name, const uint32_t *ref, const uint32_t *got,
                       int W, int H)
{
    size_t n = (size_t)W * (size_t)H;
    uint32_t *img = malloc(n * sizeof *img);
    if (!img)
        return;
    for (size_t i = 0; i < n; i++) {
        uint32_t r = ref[i] >> 24 & 255, g = ref[i] >> 16 & 255, b = ref[i] >> 8 & 255;
        uint32_t y = (r + g + b) / 6;
        img[i] = ref[i] == got[i] ? (y << 24 | y << 16 | y << 8) : 0xff00ff00u;
    }
    char path[1024], err[512];
    mkdir("results", 0755);
    mkdir(v->outdir, 0755);
    snprintf(path, sizeof path, "%s/%s.png", v->outdir, name);
    if (retro_image_write(path, img, W, H, err, sizeof err))
        fprintf(stderr, "retro verify: %s\n", err);
    free(img);
}

/* Renders the case with one variant and compares it with ref; prints the cell. */
static void check_variant(verify_run *v, verify_variant *var, retro_mode mode, player_t *p,
                          ctx_t *c, const uint32_t *ref, const char *case_name)
{
    size_t n = (size_t)c->scr_width * (size_t)c->scr_height;
    /* A poison fill exposes a write-once kernel that leaves a pixel unwritten. */
    for (size_t i = 0; i < n; i++)
        c->out[i] = 0x01020300u ^ (uint32_t)i;
    retro_err e = verify_variant_render(var, mode, p, c);
    char cell[64];
    if (e) {
        snprintf(cell, sizeof cell, "error: %s", retro_strerror(e));
        v->differ++;
    } else {
        size_t bad = 0, first = 0;
        for (size_t i = 0; i < n; i++)
            if (c->out[i] != ref[i] && bad++ == 0)
                first = i;
        if (!bad) {
            snprintf(cell, sizeof cell, "identical");
        } else {
            int W = c->scr_width, H = c->scr_height;
            snprintf(cell, sizeof cell, "%zu px differ, first (%d,%d)", bad, (int)(first % (size_t)W) + 1,
                     H - (int)(first / (size_t)W));
            char name[256];
            snprintf(name, sizeof name, "%s-%s-%s", case_name, retro_mode_name(mode), var->label);
            write_diff(v, name, ref, c->out, W, H);
            v->differ++;
        }
    }
    v->compared++;
    printf(" | %-*s", VERIFY_CELL_WIDTH, cell);
}

static int run_case(verify_run *v, const verify_case *vc, verify_variant *vars, int nvars)
{
    char err[512];
    const retro_map *m = get_map(v, vc->map, err, sizeof err);
    if (!m) {
        if (!strncmp(vc->map, "course/", 7)) {
            printf("%-22s skipped: %s/course absent (%s)\n", vc->name, v->shared, err);
            v->skipped++;
            return 0;
        }
        fprintf(stderr, "retro verify: %s (run make maps)\n", err);
        return CLI_EBADINPUT;
    }
    player_t p;
    player_for(vc, m, &p);
    size_t n = (size_t)vc->W * (size_t)vc->H;
    uint32_t *ref = malloc(n * sizeof *ref), *out = malloc(n * sizeof *out);
    if (!ref || !out) {
        free(ref);
        free(out);
        fprintf(stderr, "retro verify: out of memory\n");
        return CLI_EBADINPUT;
    }
    for (int mode = 0; mode < RETRO_MODE_COUNT; mode++) {
        if (mode == RETRO_MODE_COURSE && m->size < 2)
            continue;
        ctx_t c = {vc->W, vc->H, m->size, vc->D, 0x66a3ff00u, m->height, m->color, ref};
        retro_ctx rc;
        retro_ctx_init(&rc);
        retro_err e = retro_render(&rc, retro_kernel_find("naive"), (retro_mode)mode, &p, &c);
        retro_ctx_free(&rc);
        printf("%-22s %-6s", vc->name, retro_mode_name((retro_mode)mode));
        if (e) {
            printf(" | naive failed: %s\n", retro_strerror(e));
            v->differ++;
            continue;
        }
        c.out = out;
        for (int k = 0; k < nvars; k++) {
            if (!retro_kernel_has_mode(vars[k].kernel, (retro_mode)mode))
                printf(" | %-*s", VERIFY_CELL_WIDTH, "-");
            else
                check_variant(v, &vars[k], (retro_mode)mode, &p, &c, ref, vc->name);
        }
        printf("\n");
        fflush(stdout);
    }
    free(ref);
    free(out);
    return 0;
}

/* One effect case: naive with the effects against every variant that renders them. */
static int run_fx_case(verify_run *v, const verify_fx_case *vc, verify_variant *vars, int nvars)
{
    char err[512];
    const retro_map *m = get_map(v, vc->map, err, sizeof err);
    if (!m) {
        fprintf(stderr, "retro verify: %s (run make maps)\n", err);
        return CLI_EBADINPUT;
    }
    size_t cells = (size_t)m->size * (size_t)m->size;
    uint8_t *h1 = malloc(cells);
    enum { W = 320, H = 240 };
    uint32_t *ref = malloc(sizeof(uint32_t) * W * H), *out = malloc(sizeof(uint32_t) * W * H);
    if (!h1 || !ref || !out) {
        free(h1);
        free(ref);
        free(out);
        fprintf(stderr, "retro verify: out of memory\n");
        return CLI_EBADINPUT;
    }
    for (size_t i = 0; i < cells; i++)
        h1[i] = (uint8_t)(255 - m->height[i]);
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = vc->fx;
    fx.fog_exp = vc->fog_exp;
    fx.pitch = vc->pitch;
    fx.morph_height = h1;
    fx.morph_t = 0.37f;
    verify_case pose = {vc->name, vc->map, NAN, NAN, vc->angle, 60, 1, W, H, 800, 1};
    player_t p;
    player_for(&pose, m, &p);
    ctx_t c = {W, H, m->size, 800, 0x66a3ff00u, m->height, m->color, ref};
    retro_ctx rc;
    retro_ctx_init(&rc);
    rc.fx = &fx;
    retro_err e = retro_render(&rc, retro_kernel_find("naive"), RETRO_MODE_EXACT, &p, &c);
    retro_ctx_free(&rc);
    printf("%-22s %-6s", vc->name, "exact");
    if (e) {
        printf(" | naive failed: %s\n", retro_strerror(e));
        v->differ++;
    } else {
        c.out = out;
        for (int k = 0; k < nvars; k++) {
            vars[k].ctx.fx = &fx;
            if (!retro_kernel_has_mode(vars[k].kernel, (fx.flags & RETRO_FX_LOD) ? RETRO_MODE_LOD : RETRO_MODE_EXACT) ||
                ((fx.flags & RETRO_FX_PER_SAMPLE) & ~vars[k].kernel->fx))
                printf(" | %-*s", VERIFY_CELL_WIDTH, "-");
            else
                check_variant(v, &vars[k], RETRO_MODE_EXACT, &p, &c, ref, vc->name);
            vars[k].ctx.fx = NULL;
        }
        printf("\n");
    }
    fflush(stdout);
    free(h1);
    free(ref);
    free(out);
    return 0;
}

static void help(void)
{
    printf("usage: retro verify [--quick] [-k KERNEL] [--out DIR] [--maps DIR]\n\n"
           "Renders a fixed set of cases (src/cli/verify_cases.c) with every kernel in every mode\n"
           "it supports, at every ISA level and thread count it runs with here, and compares each\n"
           "frame with naive of the same mode byte for byte. Exit 0 when all are identical, 1 on\n"
           "any difference (a diff image per mismatch goes to DIR, default results/verify).\n"
           "  --quick     the reduced set `make check` runs\n"
           "  -k KERNEL   only this kernel\n"
           "  --out DIR   where diff images of mismatches go (default results/verify)\n"
           "  --maps DIR  the generated maps (default: maps/ if it holds them, as in the source\n"
           "              tree after make maps; else $XDG_CACHE_HOME/retro/maps, made on first use)\n"
           "Course maps come from $RETRO_SHARED/course (default ../shared); cases on them are\n"
           "skipped when it is absent.\n");
}

int cmd_verify(int argc, char **argv)
{
    verify_run v;
    memset(&v, 0, sizeof v);
    const char *maps_given = NULL;
    char mapsdir[1024];
    v.outdir = "results/verify";
    v.shared = getenv("RETRO_SHARED") ? getenv("RETRO_SHARED") : "../shared";
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            help();
            return 0;
        } else if (!strcmp(a, "--quick"))
            v.quick = 1;
        else if (!strcmp(a, "-k") && i + 1 < argc)
            v.only = argv[++i];
        else if (!strcmp(a, "--out") && i + 1 < argc)
            v.outdir = argv[++i];
        else if (!strcmp(a, "--maps") && i + 1 < argc)
            maps_given = argv[++i];
        else
            return cli_error("verify", "unknown argument '%s' (retro verify --help)", a);
    }
    if (v.only && !retro_kernel_find(v.only))
        return cli_error("verify", "unknown kernel '%s' (retro kernels lists them)", v.only);
    if (cli_maps_dir("verify", maps_given, mapsdir, sizeof mapsdir))
        return CLI_EBADINPUT;
    v.mapsdir = mapsdir;

    verify_variant vars[VERIFY_MAX_VARIANTS];
    int nvars = verify_variants(vars, VERIFY_MAX_VARIANTS, v.only);
    printf("%-22s %-6s", "case", "mode");
    for (int k = 0; k < nvars; k++)
        printf(" | %-*s", VERIFY_CELL_WIDTH, vars[k].label);
    printf("\n");

    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    int status = 0;
    for (int i = 0; i < verify_case_count && !status; i++)
        if (!v.quick || verify_cases[i].quick)
            status = run_case(&v, &verify_cases[i], vars, nvars);
    for (int i = 0; i < verify_fx_case_count && !status; i++)
        if (!v.quick || verify_fx_cases[i].quick)
            status = run_fx_case(&v, &verify_fx_cases[i], vars, nvars);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    for (int i = 0; i < v.nmaps; i++)
        if (v.maps[i].state > 0)
            retro_map_free(&v.maps[i].map);
    verify_variants_free(vars, nvars);
    if (status)
        return status;
    printf("%d comparisons, %d differ, %d cases skipped, %.1f s\n", v.compared, v.differ, v.skipped,
           (double)(t1.tv_sec - t0.tv_sec) + (double)(t1.tv_nsec - t0.tv_nsec) * 1e-9);
    return v.differ ? 1 : 0;
}
