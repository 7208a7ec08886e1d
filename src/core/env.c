/* Strict parsing of the environment (src/core/env.h). The library, which cannot report, falls back
 * to the safe default on a bad value (cpu.c, kernel_omp.c); the CLI calls retro_env_check()
 * first and refuses the run with one line, so the fallback is never silent there. */
#include "errf.h"
#include "env.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "isa.h"
#include "retro.h"


/* Digits only, at most 18 of them (no overflow), an optional leading minus. No blanks, no
 * plus sign, no 0x: what strtol would quietly accept is refused. */
static int parse_long(const char *s, long *out)
{
    const char *p = s + (*s == '-');
    size_t digits = strspn(p, "0123456789");
    if (!digits || p[digits] || digits > 18)
        return -1;
    long v = strtol(s, NULL, 10);
    *out = v;
    return 0;
}

int retro_env_long(const char *name, long lo, long hi, long *out, char *err, size_t n)
{
    const char *v = getenv(name);
    long x;
    if (!v)
        return 0;
    if (parse_long(v, &x) || x < lo || x > hi)
        return retro_errf(err, n, "environment: %s='%.40s' is not an integer in %ld..%ld", name, v, lo, hi);
    *out = x;
    return 1;
}

/* OpenMP's syntax: positive integers separated by commas (one per nesting level). */
static int check_omp_threads(char *err, size_t n)
{
    const char *v = getenv("OMP_NUM_THREADS");
    if (!v)
        return 0;
    for (const char *p = v;; p++) {
        size_t digits = strspn(p, "0123456789");
        long x;
        char num[16];
        if (!digits || digits >= sizeof num)
            break;
        memcpy(num, p, digits);
        num[digits] = 0;
        if (parse_long(num, &x) || x < 1 || x > 1048576)
            break;
        p += digits;
        if (!*p)
            return 0;
        if (*p != ',')
            break;
    }
    return retro_errf(err, n, "environment: OMP_NUM_THREADS='%.40s' is not a list of thread counts "
                       "1..1048576 (e.g. 4 or 4,2)", v);
}

int retro_env_check(char *err, size_t n)
{
    const char *isa = getenv("RETRO_ISA"), *shared = getenv("RETRO_SHARED");
    long chunk;
    if (isa && retro_cpu_level_index(isa) < 0) {
        char levels[64];
        return retro_errf(err, n, "environment: RETRO_ISA='%.40s' is not one of %s", isa,
                          retro_isa_list(levels, sizeof levels));
    }
    if (retro_env_long("RETRO_OMP_CHUNK", 1, RETRO_MAX_SCREEN, &chunk, err, n) < 0)
        return -1;
    if (retro_env_long("RETRO_PTHREADS", 1, RETRO_PTHREADS_MAX, &chunk, err, n) < 0)
        return -1;
#ifndef RETRO_SUBMISSION /* the submission has no --stats */
    if (retro_env_long("RETRO_CONE_SECTORS", RETRO_CONE_SECTORS_MIN, RETRO_CONE_SECTORS_MAX, &chunk, err, n) < 0)
        return -1;
    if (retro_env_long("RETRO_CONE_R", 1, RETRO_CONE_R_MAX, &chunk, err, n) < 0)
        return -1;
#endif
    if (shared && (!*shared || strlen(shared) > RETRO_SHARED_MAX))
        return retro_errf(err, n, "environment: RETRO_SHARED must be a folder's path of 1..%d bytes",
                   RETRO_SHARED_MAX);
    return check_omp_threads(err, n);
}
