/* retro kernels: one line per kernel, its name first; '#' lines say what this CPU has. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "retro.h"

int cmd_kernels(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("usage: retro kernels [--isa LEVEL]\n\n"
                   "One line per kernel: name, modes, whether this CPU runs it (at the ISA level\n"
                   "allowed by --isa or RETRO_ISA), what it needs and what it does.\n");
            return 0;
        }
        if (!strcmp(argv[i], "--isa") && i + 1 < argc) {
            if (retro_cpu_limit(argv[++i]))
                return cli_error("kernels", "unknown ISA level '%s' (none, sse2, avx2, avx512)", argv[i]);
            continue;
        }
        return cli_error("kernels", "unknown argument '%s' (retro kernels --help)", argv[i]);
    }
    for (size_t i = 0; i < retro_kernel_count; i++) {
        const retro_kernel *k = &retro_kernels[i];
        char modes[32] = "";
        for (int m = 0; m < RETRO_MODE_COUNT; m++)
            if (retro_kernel_has_mode(k, (retro_mode)m)) {
                if (*modes)
                    strcat(modes, ",");
                strcat(modes, retro_mode_name((retro_mode)m));
            }
        printf("%-12s %-28s %-4s %-7s %s\n", k->name, modes, retro_kernel_runs_here(k) ? "yes" : "no",
               k->cpu ? retro_cpu_level_name(k->cpu) : "-", k->summary);
    }
    retro_ctx rc;
    retro_ctx_init(&rc);
    printf("# isa: %s (RETRO_ISA or --isa lowers it)\n", retro_cpu_level_name(retro_cpu_features()));
    printf("# threads: %d (OMP_NUM_THREADS or --threads)\n", retro_ctx_threads(&rc));
    printf("# binding: %s\n", retro_ctx_binding(&rc));
    retro_ctx_free(&rc);
    return 0;
}
