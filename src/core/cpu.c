/* CPU features, detected once and cached; RETRO_ISA or retro_cpu_limit() masks them so the
 * tests and `make verify` can run every kernel at every ISA level this CPU has. */
#include <stdlib.h>
#include <string.h>

#include "env.h"
#include "isa.h"
#include "retro.h"

/* The ISA levels (isa.h), lowest first: their names and the features each allows. */
#define RETRO_ISA_NAME_(level, name, cpu) #name,
const char *const retro_isa_names[] = {RETRO_ISA_LEVELS(RETRO_ISA_NAME_)};
#undef RETRO_ISA_NAME_
const int retro_isa_count = (int)(sizeof retro_isa_names / sizeof retro_isa_names[0]);
#define RETRO_ISA_MASK_(level, name, cpu) cpu,
static const unsigned level_mask[] = {RETRO_ISA_LEVELS(RETRO_ISA_MASK_)};
#undef RETRO_ISA_MASK_

unsigned retro_isa_cpu(int level)
{
    return level >= 0 && level < retro_isa_count ? level_mask[level] : 0;
}

const char *retro_isa_list(char *buf, size_t n)
{
    size_t at = 0;
    if (n)
        buf[0] = 0;
    for (int i = 0; i < retro_isa_count && at + 1 < n; i++) {
        const char *sep = i ? ", " : "";
        size_t len = strlen(sep) + strlen(retro_isa_names[i]);
        if (at + len >= n)
            break;
        strcpy(buf + at, sep);
        strcpy(buf + at + strlen(sep), retro_isa_names[i]);
        at += len;
    }
    return buf;
}

static unsigned detected(void)
{
    static int done;
    static unsigned cached;
    if (!done) {
        unsigned f = 0;
#if defined(__x86_64__) || defined(__i386__)
        __builtin_cpu_init();
        if (__builtin_cpu_supports("sse2"))
            f |= RETRO_CPU_SSE2;
        if (__builtin_cpu_supports("avx2"))
            f |= RETRO_CPU_AVX2;
        if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
            __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq"))
            f |= RETRO_CPU_AVX512;
#endif
        cached = f;
        done = 1;
    }
    return cached;
}

static int level_of(const char *name)
{
    for (int i = 0; i < retro_isa_count; i++)
        if (!strcmp(retro_isa_names[i], name))
            return i;
    return -1;
}

int retro_cpu_level_index(const char *name) { return level_of(name); }

static int limit = -2; /* -2: not read yet, -1: no limit */

retro_err retro_cpu_limit(const char *level)
{
    if (!level) {
        limit = -1;
        return RETRO_OK;
    }
    int l = level_of(level);
    if (l < 0)
        return RETRO_EINVAL;
    limit = l;
    return RETRO_OK;
}

unsigned retro_cpu_features(void)
{
    if (limit == -2) {
        /* A value that names no level limits to none: slower, still exact, and never an ISA
         * the caller meant to exclude (the CLI refuses such a value first, src/core/env.c). */
        const char *env = getenv("RETRO_ISA");
        limit = !env ? -1 : level_of(env) >= 0 ? level_of(env) : 0;
    }
    unsigned f = detected();
    return limit >= 0 ? f & level_mask[limit] : f;
}

int retro_cpu_level(unsigned features)
{
    int level = 0;
    for (int i = 0; i < retro_isa_count; i++)
        if ((features & level_mask[i]) == level_mask[i])
            level = i;
    return level;
}

const char *retro_cpu_level_name(unsigned features)
{
    return retro_isa_names[retro_cpu_level(features)];
}
