/* retro: render, list and verify the voxel-space kernels. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "env.h"

static const struct {
    const char *name;
    int (*fn)(int, char **);
    const char *what;
} commands[] = {
    {"render", cmd_render, "render one frame of a map or a scene to PPM or PNG"},
    {"fly", cmd_fly, "render a scene's fly-through path, one image per frame"},
    {"kernels", cmd_kernels, "list the kernels, their modes and whether this CPU runs them"},
    {"verify", cmd_verify, "check every kernel pixel-identical to naive"},
    {"genmap", cmd_genmap, "generate a procedural or analytic map"},
    {"accuracy", cmd_accuracy, "measure what each accuracy variant costs in time and error"},
};

static void usage(FILE *f)
{
    fprintf(f, "usage: retro COMMAND [ARGS]   (retro COMMAND --help for its options)\n\n");
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
