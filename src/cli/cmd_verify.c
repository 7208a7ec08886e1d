/* retro verify: every variant of every kernel (src/check/: kernel x ISA level x threads), in
 * every mode it supports, against its family's reference in the same mode, byte for byte, over
 * the cases of verify_cases.c. Prints a case x variant table, writes a diff image per
 * mismatch and exits 1 on any difference. */

#define VERIFY_CELL_WIDTH 16
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli.h"
#include "maps_dir.h"
#include "retro.h"
#include "retro_maps.h"
#include "retro_scene.h"
#include "verify_cases.h"
#include "check.h"

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
    int differ, compared, skipped, documented;
    retro_check chk;       /* every variant this CPU runs, and the frames of the current row */
    const char *case_name; /* the row being checked, for diff image names */
    int mode, W, H;
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

/* Prints one variant's cell of the table and writes a diff image for a mismatch. */
static void report_cell(void *user, const retro_check_variant *var, const retro_check_result *r)
{
    verify_run *v = user;
    char cell[64];
    if (!r->ran) {
        snprintf(cell, sizeof cell, "-");
    } else if (r->err) {
        snprintf(cell, sizeof cell, "error: %s", retro_strerror(r->err));
    } else if (!r->differ) {
        snprintf(cell, sizeof cell, "identical");
    } else if (r->differ <= r->documented) { /* measured, within what the family's docs bound */
        snprintf(cell, sizeof cell, "%zu px (doc. <=%zu)", r->differ, r->documented);
        v->documented++;
    } else {
        snprintf(cell, sizeof cell, "%zu px differ, first (%d,%d)", r->differ, r->u, r->r);
        char name[256];
        snprintf(name, sizeof name, "%s-%s-%s", v->case_name, retro_family_mode_name(v->chk.family, v->mode),
                 var->label);
        for (char *q = name; *q; q++)
            *q = *q == '/' ? '_' : *q;
        verify_write_diff(v->outdir, name, v->chk.ref, v->chk.out, v->W, v->H);
    }
    if (r->ran)
        v->compared++;
    printf(" | %-*s", VERIFY_CELL_WIDTH, cell);
}

/* One row of the table: the reference, then every variant through the checker. */
static void check_row(verify_run *v, const char *case_name, int mode, const retro_effects *fx,
                      const player_t *p, const ctx_t *c)
{
    v->case_name = case_name;
    v->mode = mode;
    v->W = c->scr_width;
    v->H = c->scr_height;
    printf("%-22s %-8s", case_name, retro_family_mode_name(v->chk.family, mode));
    retro_err e = retro_check_frame(&v->chk, mode, fx, p, c, report_cell, v, &v->differ);
    if (e) {
        printf(" | %s failed: %s", v->chk.family->reference, retro_strerror(e));
        v->differ++;
    }
    printf("\n");
    fflush(stdout);
}

static int run_case(verify_run *v, const verify_case *vc)
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
    for (int mode = 0; mode < RETRO_MODE_COUNT; mode++) {
        if (mode == RETRO_MODE_COURSE && m->size < 2)
            continue;
        ctx_t c = {vc->W, vc->H, m->size, vc->D, 0x66a3ff00u, m->height, m->color, NULL};
        check_row(v, vc->name, mode, NULL, &p, &c);
    }
    return 0;
}

/* The effects of an effect or mesh case: the defaults with `flags`, and morph's keyframe the
 * inverted heights, as different from the map as a keyframe can be, so a blend that ignored
 * either side would show. Returns that keyframe, which the caller frees; NULL (said) when out
 * of memory. */
static uint8_t *case_effects(const retro_map *m, unsigned flags, retro_effects *fx)
{
    const size_t cells = (size_t)m->size * (size_t)m->size;
    uint8_t *h1 = malloc(cells);
    if (!h1) {
        fprintf(stderr, "retro verify: out of memory\n");
        return NULL;
    }
    for (size_t i = 0; i < cells; i++)
        h1[i] = (uint8_t)(255 - m->height[i]);
    retro_effects_defaults(fx);
    fx->flags = flags;
    fx->morph_height = h1;
    fx->morph_t = 0.37f;
    return h1;
}

/* One effect case: the reference with the effects against every variant that renders them. */
static int run_fx_case(verify_run *v, const verify_fx_case *vc)
{
    char err[512];
    const retro_map *m = get_map(v, vc->map, err, sizeof err);
    if (!m) {
        fprintf(stderr, "retro verify: %s (run make maps)\n", err);
        return CLI_EBADINPUT;
    }
    retro_effects fx;
    uint8_t *h1 = case_effects(m, vc->fx, &fx);
    if (!h1)
        return CLI_EBADINPUT;
    fx.fog_exp = vc->fog_exp;
    fx.pitch = vc->pitch;
    verify_case pose = {vc->name, vc->map, NAN, NAN, vc->angle, 60, 1, 320, 240, 800, 1};
    player_t p;
    player_for(&pose, m, &p);
    ctx_t c = {320, 240, m->size, 800, 0x66a3ff00u, m->height, m->color, NULL};
    check_row(v, vc->name, RETRO_MODE_EXACT, &fx, &p, &c);
    free(h1);
    return 0;
}

/* A mesh case: every mode of the family, the mesh reference against every other mesh kernel. */
static int run_mesh_case(verify_run *v, const verify_mesh_case *vc)
{
    char err[512];
    const retro_map *m = get_map(v, vc->map, err, sizeof err);
    if (!m) {
        fprintf(stderr, "retro verify: %s (run make maps)\n", err);
        return CLI_EBADINPUT;
    }
    verify_case pose = {vc->name, vc->map, vc->x, vc->y, vc->angle, vc->height, vc->rel_height, vc->W, vc->H, vc->D, 1};
    player_t p;
    player_for(&pose, m, &p);
    retro_effects fx;
    uint8_t *h1 = case_effects(m, vc->fx, &fx);
    if (!h1)
        return CLI_EBADINPUT;
    fx.pitch = 40;
    ctx_t c = {vc->W, vc->H, m->size, vc->D, 0x66a3ff00u, m->height, m->color, NULL};
    for (int mode = 0; mode < v->chk.family->mode_count; mode++)
        check_row(v, vc->name, mode, &fx, &p, &c);
    free(h1);
    return 0;
}

/* The voxel cases, then the mesh cases, each family with its own checker and table. */
static int run_families(verify_run *v)
{
    const retro_kernel *only = v->only ? retro_kernel_find(v->only) : NULL;
    int status = 0;
    for (size_t f = 0; f < retro_family_count && !status; f++) {
        const retro_family *fam = retro_families[f];
        if (only && only->family != fam)
            continue;
        int bad = retro_check_init(&v->chk, fam, v->only, 3);
        if (bad == -2) {
            retro_check_free(&v->chk);
            return cli_error("verify", "out of memory for the checker's contexts");
        }
        if (bad) {
            retro_check_free(&v->chk);
            return cli_error("verify", "kernel '%s' is the %s family's reference: it is what the others are "
                                       "compared with", v->only, fam->name);
        }
        printf("%s# family %s: against %s\n%-22s %-8s", f ? "\n" : "", fam->name, fam->reference, "case", "mode");
        for (int k = 0; k < v->chk.n; k++)
            printf(" | %-*s", VERIFY_CELL_WIDTH, v->chk.v[k].label);
        printf("\n");
        if (fam == &retro_family_voxel) {
            for (int i = 0; i < verify_case_count && !status; i++)
                if (!v->quick || verify_cases[i].quick)
                    status = run_case(v, &verify_cases[i]);
            for (int i = 0; i < verify_fx_case_count && !status; i++)
                if (!v->quick || verify_fx_cases[i].quick)
                    status = run_fx_case(v, &verify_fx_cases[i]);
        } else if (fam == &retro_family_mesh) {
            for (int i = 0; i < verify_mesh_case_count && !status; i++)
                if (!v->quick || verify_mesh_cases[i].quick)
                    status = run_mesh_case(v, &verify_mesh_cases[i]);
        }
        retro_check_free(&v->chk);
    }
    return status;
}

static void help(void)
{
    printf("usage: retro verify [--quick] [-k KERNEL] [--out DIR] [--maps DIR]\n\n"
           "Renders a fixed set of cases (src/cli/verify_cases.c) with every kernel in every mode\n"
           "it supports, at every ISA level and thread count it runs with here (column titles\n"
           "kernel/level[/threads]), and compares each frame with its family's reference of the\n"
           "same mode byte for byte: naive for voxel kernels, mesh-zbuffer for mesh kernels (one\n"
           "table per family). Exit 0 when all are identical, 1 on any difference (a diff image\n"
           "per mismatch goes to DIR, default results/verify). A difference the family's docs\n"
           "explain and bound (mesh-painter without cull, docs/MESH.md) is shown measured,\n"
           "\"N px (doc. <=M)\", and fails only beyond its bound.\n"
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

    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    int status = run_families(&v);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    for (int i = 0; i < v.nmaps; i++)
        if (v.maps[i].state > 0)
            retro_map_free(&v.maps[i].map);
    if (status)
        return status;
    printf("%d comparisons, %d differ, %d documented differences, %d cases skipped, %.1f s\n", v.compared,
           v.differ, v.documented, v.skipped,
           (double)(t1.tv_sec - t0.tv_sec) + (double)(t1.tv_nsec - t0.tv_nsec) * 1e-9);
    return v.differ ? 1 : 0;
}
