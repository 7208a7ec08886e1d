/* retro genmap: procedural terrain and analytic test maps, deterministic from the seed. */
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "cli.h"
#include "retro.h"
#include "retro_maps.h"

static void help(void)
{
    printf("usage: retro genmap STYLE [--size S] [--seed N] [--height-offset N] [--png] -o PREFIX\n\n"
           "Writes PREFIX.pgm (heights) and PREFIX.ppm (colours; PREFIX.png with --png).\n"
           "  STYLE      one of:");
    for (const char *const *s = retro_mapgen_styles; *s; s++)
        printf(" %s", *s);
    printf("\n             and alpine-unlit, islands-unlit, canyon-unlit: the same heights with\n"
           "             colours free of baked sunlight, for a scene's [shade] effect\n"
           "  --size S   map size, any integer 1..%d (default 1024)\n"
           "  --seed N   seed (default 1); the same seed gives the same bytes\n"
           "  --height-offset N  add N (-255..255) to every height, clamped to 0..255; the\n"
           "             colours stay: a second height keyframe for a scene's [morph]\n",
           RETRO_MAX_MAP);
}

int cmd_genmap(int argc, char **argv)
{
    const char *style = NULL, *out = NULL;
    long size = 1024, offset = 0;
    uint64_t seed = 1;
    int png = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            help();
            return 0;
        }
        if (!strcmp(a, "--png")) {
            png = 1;
            continue;
        }
        if (a[0] != '-') {
            if (style)
                return cli_error("genmap", "more than one STYLE: '%s' and '%s'", style, a);
            style = a;
            continue;
        }
        static const char *const names[] = {"--size", "--seed", "--height-offset", "-o", NULL};
        if (!(v = cli_value(argc, argv, &i)))
            return cli_no_value("genmap", a, cli_one_of(a, names));
        if (!strcmp(a, "--size")) {
            if (cli_int(v, 1, RETRO_MAX_MAP, &size))
                return cli_error("genmap", "bad size '%s' (1..%d)", v, RETRO_MAX_MAP);
        } else if (!strcmp(a, "--seed")) {
            if (cli_u64(v, &seed))
                return cli_error("genmap", "bad seed '%s' (a non-negative integer)", v);
        } else if (!strcmp(a, "--height-offset")) {
            if (cli_int(v, -255, 255, &offset))
                return cli_error("genmap", "bad height offset '%s' (-255..255)", v);
        } else if (!strcmp(a, "-o"))
            out = v;
        else
            return cli_error("genmap", "unknown option '%s' (retro genmap --help)", a);
    }
    if (!style)
        return cli_error("genmap", "no STYLE given (retro genmap --help)");
    if (!out)
        return cli_error("genmap", "no output given: -o PREFIX");
    char err[512];
    retro_map m;
    /* A 1x1 map first: an unknown style is refused at once, with the list, before a large
     * map is announced. */
    if (retro_mapgen(style, seed, 1, &m, err, sizeof err)) {
        if (!strstr(err, "unknown map style"))
            return cli_error("genmap", "%s", err);
        char list[512] = "";
        for (const char *const *s = retro_mapgen_styles; *s; s++)
            snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", *s == retro_mapgen_styles[0] ? "" : ", ", *s);
        return cli_error("genmap", "unknown style '%s'; the styles are %s, and alpine-unlit, "
                         "islands-unlit, canyon-unlit", style, list);
    }
    retro_map_free(&m);
    /* Large maps take seconds: say what is being made, then how long it took. */
    int announce = size >= 512;
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    if (announce)
        fprintf(stderr, "retro genmap: generating %s, %ldx%ld, seed %llu...\n", style, size, size,
                (unsigned long long)seed);
    if (retro_mapgen(style, seed, (int)size, &m, err, sizeof err))
        return cli_error("genmap", "%s", err);
    for (size_t i = 0; offset && i < (size_t)m.size * (size_t)m.size; i++) {
        long h = m.height[i] + offset;
        m.height[i] = (uint8_t)(h < 0 ? 0 : h > 255 ? 255 : h);
    }
    int r = retro_map_save(out, &m, png, err, sizeof err);
    retro_map_free(&m);
    if (r)
        return cli_error("genmap", "%s", err);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    if (announce)
        fprintf(stderr, "retro genmap: wrote %s.pgm and %s.%s in %.1f s\n", out, out, png ? "png" : "ppm",
                (double)(t1.tv_sec - t0.tv_sec) + (double)(t1.tv_nsec - t0.tv_nsec) * 1e-9);
    return 0;
}
