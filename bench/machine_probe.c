/* The clock and memory probes of machine_probe.h. */
#define _POSIX_C_SOURCE 200809L
#include "machine_probe.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>

#define PROBE_RUNS 5
#define CLOCK_STEPS 1000000L /* a multiply and an add per step: some 4 million cycles in all */
#define MEMORY_STEPS 100000L /* each an L3 hit once the buffer is warm, when the machine is quiet */

static uint32_t *cycle;
static size_t cycle_len;
/* Where the chains start and end: read and written through volatile, so neither chain's
 * result is known to the compiler and neither loop can be folded or dropped. */
static volatile uint32_t chain_seed = 1, chain_sink;

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int machine_probe_init(void)
{
    if (cycle)
        return 0;
    size_t n = MACHINE_PROBE_BYTES / sizeof *cycle;
    uint32_t *c = malloc(n * sizeof *c);
    if (!c)
        return -1;
    for (size_t i = 0; i < n; i++)
        c[i] = (uint32_t)i;
    /* Sattolo: swapping each i with some j < i leaves a single cycle through every slot, so a
     * chase from anywhere visits all of them in an order the prefetchers cannot guess. */
    uint64_t s = 0x9E3779B97F4A7C15u;
    for (size_t i = n - 1; i > 0; i--) {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        size_t j = (size_t)(s % i);
        uint32_t t = c[i];
        c[i] = c[j];
        c[j] = t;
    }
    cycle = c;
    cycle_len = n;
    return 0;
}

void machine_probe_free(void)
{
    free(cycle);
    cycle = NULL;
    cycle_len = 0;
}

static double median_of(double *t)
{
    qsort(t, PROBE_RUNS, sizeof *t, by_value);
    return t[PROBE_RUNS / 2];
}

double machine_probe_clock_ms(void)
{
    double t[PROBE_RUNS];
    for (int r = 0; r < PROBE_RUNS; r++) {
        uint32_t a = chain_seed;
        double t0 = now_ms();
        for (long i = 0; i < CLOCK_STEPS; i++)
            a = a * 1664525u + 1013904223u;
        t[r] = now_ms() - t0;
        chain_sink = a;
    }
    return median_of(t);
}

double machine_probe_throughput_ms(void)
{
    double t[PROBE_RUNS];
    for (int r = 0; r < PROBE_RUNS; r++) {
        uint32_t a0 = chain_seed, a1 = a0 + 1, a2 = a0 + 2, a3 = a0 + 3, a4 = a0 + 4, a5 = a0 + 5, a6 = a0 + 6,
                 a7 = a0 + 7;
        double t0 = now_ms();
        for (long i = 0; i < CLOCK_STEPS; i++) {
            a0 = a0 * 1664525u + 1013904223u;
            a1 = a1 * 1664525u + 1013904223u;
            a2 = a2 * 1664525u + 1013904223u;
            a3 = a3 * 1664525u + 1013904223u;
            a4 = a4 * 1664525u + 1013904223u;
            a5 = a5 * 1664525u + 1013904223u;
            a6 = a6 * 1664525u + 1013904223u;
            a7 = a7 * 1664525u + 1013904223u;
            /* eight scalar registers, each step: the compiler may not pack the chains into
             * vector lanes, whose multiplies would contend on other units */
            __asm__ volatile("" : "+r"(a0), "+r"(a1), "+r"(a2), "+r"(a3), "+r"(a4), "+r"(a5), "+r"(a6), "+r"(a7));
        }
        t[r] = now_ms() - t0;
        chain_sink = a0 ^ a1 ^ a2 ^ a3 ^ a4 ^ a5 ^ a6 ^ a7;
    }
    return median_of(t);
}

double machine_probe_memory_ms(void)
{
    if (!cycle)
        return NAN;
    uint32_t k = chain_seed % (uint32_t)cycle_len;
    for (size_t i = 0; i < cycle_len; i++) /* the warming pass: the cycle visits every slot */
        k = cycle[k];
    double t[PROBE_RUNS];
    for (int r = 0; r < PROBE_RUNS; r++) {
        double t0 = now_ms();
        for (long i = 0; i < MEMORY_STEPS; i++)
            k = cycle[k];
        t[r] = now_ms() - t0;
        chain_sink = k;
    }
    return median_of(t);
}
