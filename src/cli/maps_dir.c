/* The suite's generated maps, found or made. The set and its parameters are those of
 * scripts/make-maps.sh, so a cache made here holds the same bytes as maps/ after make maps. */
#include "maps_dir.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"
#include "retro_maps.h"

static const struct {
    const char *name, *style;
    int size;
    unsigned seed;
} suite_maps[] = {
    {"test/flat-64", "flat", 64, 0},          {"test/ramp-64", "ramp", 64, 0},
    {"test/spike-64", "spike", 64, 0},        {"test/checker-1000", "checker", 1000, 0},
    {"test/ramp-1000", "ramp", 1000, 0},      {"test/flat-1", "flat", 1, 0},
    {"test/ramp-3", "ramp", 3, 0},            {"test/checker-2", "checker", 2, 0},
    {"test/alpine-200", "alpine", 200, 7},    {"alpine", "alpine", 1024, 1},
    {"islands", "islands", 1024, 1},          {"canyon", "canyon", 1024, 1},
};
enum { N_MAPS = sizeof suite_maps / sizeof suite_maps[0] };

static int exists(const char *dir, const char *name, const char *ext)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/%s.%s", dir, name, ext);
    return access(path, R_OK) == 0;
}

static int have_map(const char *dir, const char *name)
{
    return exists(dir, name, "pgm") && exists(dir, name, "ppm");
}

/* mkdir -p */
static int make_dirs(const char *path)
{
    char p[1100];
    if (snprintf(p, sizeof p, "%s", path) >= (int)sizeof p)
        return -1;
    for (char *s = p + 1; *s; s++)
        if (*s == '/') {
            *s = 0;
            if (mkdir(p, 0755) && errno != EEXIST)
                return -1;
            *s = '/';
        }
    return mkdir(p, 0755) && errno != EEXIST ? -1 : 0;
}

/* Generates one map under a temporary name, then renames both files into place, so an
 * interrupted run never leaves a half-written map that a later run would trust. */
static int generate(const char *cmd, const char *dir, int i)
{
    char err[512], tmp[1200], from[1300], to[1300];
    snprintf(tmp, sizeof tmp, "%s/%s.partial", dir, suite_maps[i].name);
    char sub[1200];
    snprintf(sub, sizeof sub, "%s/%s", dir, suite_maps[i].name);
    *strrchr(sub, '/') = 0;
    if (make_dirs(sub))
        return cli_error(cmd, "cannot create %s: %s", sub, strerror(errno));
    retro_map m;
    if (retro_mapgen(suite_maps[i].style, suite_maps[i].seed, suite_maps[i].size, &m, err, sizeof err))
        return cli_error(cmd, "%s", err);
    int r = retro_map_save(tmp, &m, 0, err, sizeof err);
    retro_map_free(&m);
    if (r)
        return cli_error(cmd, "%s", err);
    for (int k = 0; k < 2; k++) {
        const char *ext = k ? "ppm" : "pgm";
        snprintf(from, sizeof from, "%s.%s", tmp, ext);
        snprintf(to, sizeof to, "%s/%s.%s", dir, suite_maps[i].name, ext);
        if (rename(from, to))
            return cli_error(cmd, "cannot write %s: %s", to, strerror(errno));
    }
    return 0;
}

int cli_maps_dir(const char *cmd, const char *given, char *dir, size_t n)
{
    if (given) {
        if (snprintf(dir, n, "%s", given) >= (int)n)
            return cli_error(cmd, "maps folder name too long");
        if (access(dir, R_OK | X_OK))
            return cli_error(cmd, "cannot read the maps folder %s: %s", dir, strerror(errno));
        fprintf(stderr, "retro %s: maps from %s\n", cmd, dir);
        return 0;
    }
    if (have_map("maps", "alpine")) {
        snprintf(dir, n, "maps");
        return 0; /* the source tree: make maps keeps it current */
    }
    const char *xdg = getenv("XDG_CACHE_HOME"), *home = getenv("HOME");
    int len = xdg && *xdg ? snprintf(dir, n, "%s/retro/maps", xdg)
              : home && *home ? snprintf(dir, n, "%s/.cache/retro/maps", home)
                              : -1;
    if (len < 0 || len >= (int)n)
        return cli_error(cmd, "no maps/ here and no cache folder (set XDG_CACHE_HOME or HOME, or give --maps DIR)");
    int missing = 0;
    for (int i = 0; i < N_MAPS; i++)
        missing += !have_map(dir, suite_maps[i].name);
    if (missing) {
        if (make_dirs(dir))
            return cli_error(cmd, "cannot create the map cache %s: %s", dir, strerror(errno));
        fprintf(stderr, "retro %s: no maps/ here: generating %d maps into %s (once)\n", cmd, missing, dir);
        for (int i = 0, done = 0; i < N_MAPS; i++) {
            if (have_map(dir, suite_maps[i].name))
                continue;
            fprintf(stderr, "retro %s: [%d/%d] %s (%s, %dx%d)\n", cmd, ++done, missing, suite_maps[i].name,
                    suite_maps[i].style, suite_maps[i].size, suite_maps[i].size);
            if (generate(cmd, dir, i))
                return CLI_EBADINPUT;
        }
    }
    fprintf(stderr, "retro %s: maps from %s\n", cmd, dir);
    return 0;
}
