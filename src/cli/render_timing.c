/* retro render --time and --versus (render_timing.h). */
#include "render_timing.h"

#include <stdio.h>
#include <stdlib.h>

#include "cli.h"
#include "timing.h"

static double median_sorted(const double *v, long n)
{
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Renders one frame of j and returns its milliseconds in *ms; with settle, after an untimed one,
 * so that the timed frame finds the caches and the workers as its own frames leave them. */
static retro_err timed_frame(render_job *j, const player_t *p, double *ms, int settle)
{
    if (settle) {
        retro_err e = retro_render(j->rc, j->k, &j->opts, p, &j->c);
        if (e)
            return e;
    }
    double t0 = cli_now_ms();
    retro_err e = retro_render(j->rc, j->k, &j->opts, p, &j->c);
    *ms = cli_now_ms() - t0;
    return e;
}

/* "kernel K (family F), mode M, WxH, D n[, effects E,..][, no skipping]: median X ms, min Y ms
 * per frame over n frames" after prefix; sorts ms. */
static void time_line(const char *prefix, const render_job *j, double *ms, long n)
{
    qsort(ms, (size_t)n, sizeof *ms, cli_cmp_double);
    printf("%skernel %s (family %s), mode %s, %dx%d, D %d", prefix, j->k->name, j->k->family->name,
           job_mode_name(j), j->c.scr_width, j->c.scr_height, j->c.distance);
    unsigned fx = j->opts.fx ? j->opts.fx->flags : 0;
    for (unsigned bit = 1, first = 1; fx && bit; bit <<= 1)
        if (fx & bit) {
            printf("%s%s", first ? ", effects " : ",", retro_fx_name(bit));
            first = 0;
        }
    printf("%s: median %.3f ms, min %.3f ms per frame over %ld frames\n", j->opts.no_skip ? ", no skipping" : "",
           median_sorted(ms, n), ms[0], n);
}

/* Two sets of workers, each on more than one thread, slow each other's frames (pthreads beside
 * omp ran several times slower: docs/COMMANDS.md). */
static int pools_clash(const render_job *a, const render_job *b)
{
    return retro_kernels_two_pools(a->k, retro_ctx_threads(a->rc), b->k, retro_ctx_threads(b->rc));
}

int render_time(render_job *j, const player_t *p, long n)
{
    double *ms = malloc((size_t)n * sizeof *ms);
    if (!ms)
        return cli_error("render", "out of memory");
    retro_err e = retro_render(j->rc, j->k, &j->opts, p, &j->c);
    for (long i = 0; !e && i < n; i++)
        e = timed_frame(j, p, &ms[i], 0);
    if (!e)
        time_line("", j, ms, n);
    free(ms);
    return e ? job_error("render", j, e) : 0;
}

int render_versus(render_job *a, const player_t *pa, render_job *b, const player_t *pb, long n)
{
    double *ms = malloc(3 * (size_t)n * sizeof *ms);
    if (!ms)
        return cli_error("render", "out of memory");
    double *ta = ms, *tb = ms + n, *ratio = ms + 2 * n;
    render_job *failed = a;
    retro_err e = retro_render(a->rc, a->k, &a->opts, pa, &a->c);
    if (!e) {
        failed = b;
        e = retro_render(b->rc, b->k, &b->opts, pb, &b->c);
    }
    if (!e && pools_clash(a, b)) {
        free(ms);
        return cli_error("render",
                         "--versus cannot time %s and %s on more than one thread each: each keeps its own workers, "
                         "and one's idle workers can slow the other's frames; time them in separate runs",
                         a->k->name, b->k->name);
    }
    /* Two kernels: each timed frame after an untimed one of its own (timed_frame). One kernel
     * leaves its workers and the map's caches as warm for either, and the timed frames then
     * follow each other closely, so the machine's speed changes between them least. A B, then
     * B A, so that neither always runs first in a pair. */
    const int settle = a->k != b->k;
    for (long i = 0; !e && i < n; i++) {
        int b_first = (int)(i & 1);
        failed = b_first ? b : a;
        e = b_first ? timed_frame(b, pb, &tb[i], settle) : timed_frame(a, pa, &ta[i], settle);
        if (!e) {
            failed = b_first ? a : b;
            e = b_first ? timed_frame(a, pa, &ta[i], settle) : timed_frame(b, pb, &tb[i], settle);
        }
        if (!e)
            ratio[i] = tb[i] / ta[i];
    }
    if (e) {
        free(ms);
        return job_error("render", failed, e);
    }
    time_line("", a, ta, n);
    time_line("versus: ", b, tb, n);
    qsort(ratio, (size_t)n, sizeof *ratio, cli_cmp_double);
    printf("versus / first: %.3f (median of %ld per-pair ratios, quartiles %.3f to %.3f; frames taken in turn)\n",
           median_sorted(ratio, n), n, ratio[n / 4], ratio[(3 * n) / 4]);
    free(ms);
    return 0;
}
