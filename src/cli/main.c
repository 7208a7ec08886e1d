/* retro: render, list and verify the voxel-space kernels. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "env.h"

/* The Makefile passes the version it installs under (retro.pc, the soname). */
#ifndef RETRO_VERSION
#define RETRO_VERSION "unknown"
#endif

static const struct {
    const char *name;
    int (*fn)(int, char **);
    const char *what;
} commands[] = {
    {"render", cmd_render, "render one frame of a map or a scene to PPM or PNG"},
    {"fly", cmd_fly, "render a scene's path or a map's circuit, one image per frame"},
    {"view", cmd_view, "fly through a map or scene in a window, switching kernels live"},
    {"kernels", cmd_kernels, "list the kernels, their modes and whether this CPU runs them"},
    {"verify", cmd_verify, "check every kernel pixel-identical to naive"},
    {"genmap", cmd_genmap, "generate a procedural or analytic map"},
    {"accuracy", cmd_accuracy, "measure what each accuracy variant costs in time and error"},
};

static void usage(FILE *f)
{
    fprintf(f, "usage: retro COMMAND [ARGS]   (retro COMMAND --help for its options)\n"
               "       retro --version\n\n"
               "Voxel-space (Comanche-style) terrain renderer: one frame definition, many kernels\n"
               "proven pixel-identical to the reference.\n\nCommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(f, "  %-8s %s\n", commands[i].name, commands[i].what);
}

static int wants_help(int argc, char **argv)
{
    for (int i = 2; i < argc; i++)
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h"))
            return 1;
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return CLI_EBADINPUT;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage(stdout);
        return 0;
    }
    if (!strcmp(argv[1], "--version") || !strcmp(argv[1], "-V")) {
        printf("retro %s\n", RETRO_VERSION);
        return 0;
    }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (!strcmp(argv[1], commands[i].name)) {
            /* Before any work, as for a bad option; --help still answers. */
            char err[256];
            if (!wants_help(argc, argv) && retro_env_check(err, sizeof err))
                return cli_error(commands[i].name, "%s", err);
            return commands[i].fn(argc - 1, argv + 1);
        }
    fprintf(stderr, "retro: unknown command '%s' (retro --help lists them)\n", argv[1]);
    return CLI_EBADINPUT;
}
