/* retro kernels: a header row, then one line per kernel grouped by family, its name first;
 * '#' lines say what this CPU has. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "isa.h"
#include "retro.h"

/* names of the set bits of mask, comma-separated, by name(bit); "-" when none. */
static void list(char *buf, size_t n, unsigned mask, const char *(*name)(const void *, int), const void *arg)
{
    buf[0] = '\0';
    for (int b = 0; b < 32; b++)
        if (mask & (1u << b)) {
            size_t at = strlen(buf);
            snprintf(buf + at, n - at, "%s%s", at ? "," : "", name(arg, b));
        }
    if (!buf[0])
        snprintf(buf, n, "-");
}

static const char *mode_name(const void *fam, int m)
{
    return retro_family_mode_name(fam, m);
}

static const char *fx_name(const void *unused, int b)
{
    (void)unused;
    return retro_fx_name(1u << b);
}

int cmd_kernels(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("usage: retro kernels [--isa LEVEL]\n\n"
                   "One line per kernel, grouped by family: name, family, modes, whether this CPU\n"
                   "runs it (at the ISA level allowed by --isa or RETRO_ISA), the ISA it needs, the\n"
                   "effects it renders and what it does. A '#' line names each family's reference.\n");
            return 0;
        }
        if (!strcmp(argv[i], "--isa") && i + 1 < argc) {
            if (retro_cpu_limit(argv[++i])) {
                char levels[64];
                return cli_error("kernels", "unknown ISA level '%s' (%s)", argv[i],
                                 retro_isa_list(levels, sizeof levels));
            }
            continue;
        }
        return cli_error("kernels", "unknown argument '%s' (retro kernels --help)", argv[i]);
    }
    printf("%-12s %-6s %-28s %-4s %-7s %-44s %s\n", "kernel", "family", "modes", "runs", "isa", "effects",
           "summary");
    for (size_t f = 0; f < retro_family_count; f++)
        for (size_t i = 0; i < retro_kernel_count; i++) {
            const retro_kernel *k = &retro_kernels[i];
            if (k->family != retro_families[f])
                continue;
            char modes[64], fx[128];
            list(modes, sizeof modes, k->modes, mode_name, k->family);
            list(fx, sizeof fx, k->fx, fx_name, NULL);
            printf("%-12s %-6s %-28s %-4s %-7s %-44s %s\n", k->name, k->family->name, modes,
                   retro_kernel_runs_here(k) ? "yes" : "no", k->cpu ? retro_cpu_level_name(k->cpu) : "-", fx,
                   k->summary);
        }
    for (size_t f = 0; f < retro_family_count; f++)
        printf("# family %s: reference %s\n", retro_families[f]->name, retro_families[f]->reference);
    retro_ctx *rc = retro_ctx_new();
    if (!rc)
        return cli_error("kernels", "out of memory");
    printf("# isa: %s (RETRO_ISA or --isa lowers it)\n", retro_cpu_level_name(retro_cpu_features()));
    printf("# threads: %d (OMP_NUM_THREADS or --threads)\n", retro_ctx_threads(rc));
    printf("# binding: %s\n", retro_ctx_binding(rc));
    retro_ctx_free(rc);
    return 0;
}
