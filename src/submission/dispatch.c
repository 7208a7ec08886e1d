/* The submission's stand-in for the kernel table (src/kernels.c), which it does not carry:
 * the strip its threads run, by the CPU's features, checked at every call so no state
 * outlives a render. RETRO_ISA=avx2|sse2|none forces a lower level, so tests reach each path
 * (any other value: none).
 * Only compiled into results/submission/render.c. */
#include <stdlib.h>
#include <string.h>

static int isa_allowed(const char *level)
{
    static const char *const order[] = {"none", "sse2", "avx2", "avx512"};
    const char *limit = getenv("RETRO_ISA");
    /* Set to a name of no level, it limits to none, as the library does (src/cpu.c). */
    int want = 3, have = limit ? 0 : 3;
    for (int i = 0; i < 4; i++) {
        if (limit && !strcmp(limit, order[i]))
            have = i;
        if (!strcmp(level, order[i]))
            want = i;
    }
    return want <= have;
}

retro_strip_fn retro_best_strip(retro_mode mode, unsigned fx)
{
    if (fx || (mode != RETRO_MODE_EXACT && mode != RETRO_MODE_COURSE))
        return retro_strip_ybuffer;
    __builtin_cpu_init();
    if (isa_allowed("avx512") && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
        __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx2"))
        return retro_strip_simd_avx512;
    if (isa_allowed("avx2") && __builtin_cpu_supports("avx2"))
        return retro_strip_simd_avx2;
    return retro_strip_ybuffer;
}
