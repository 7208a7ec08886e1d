/* The accuracy run's Machine steadiness (accuracy_steady.h). */
#include "accuracy_steady.h"

#include <stdlib.h>

#include "timing.h"

double acc_steady_spread(const acc_steady *s, int ybuf)
{
    if (s->n < 2)
        return 0;
    double v[ACC_STEADY_MAX];
    for (int i = 0; i < s->n; i++)
        v[i] = ybuf ? s->cp[i].ybuf : s->cp[i].best;
    qsort(v, (size_t)s->n, sizeof v[0], cli_cmp_double);
    /* the element at n / 2, as the table's medians are taken */
    double med = v[s->n / 2];
    return med > 0 ? (v[s->n - 1] - v[0]) / med : 0;
}

int acc_steady_noisy(const acc_steady *s)
{
    return acc_steady_spread(s, 0) > ACC_STEADY_NOISY || acc_steady_spread(s, 1) > ACC_STEADY_NOISY;
}

void acc_steady_write_note(FILE *f, const acc_steady *s)
{
    if (!acc_steady_noisy(s))
        return;
    fprintf(f, "> **Noisy run.** The reference frame's time spread %.0f%% with `%s` and %.0f%% with `ybuffer` "
               "across the run's %d checkpoints (Machine steadiness, below), above the %.0f%% that marks a "
               "noisy run: the machine's speed changed during the run, so variants' medians pool poses timed "
               "at different speeds and may be off by as much. `make publish-accuracy` refuses it; rerun on a "
               "quiet machine.\n\n",
            100 * acc_steady_spread(s, 0), s->best_kernel, 100 * acc_steady_spread(s, 1), s->n,
            100 * ACC_STEADY_NOISY);
}

void acc_steady_write_table(FILE *f, const acc_steady *s)
{
    fprintf(f, "\n## Machine steadiness\n\nThe same frame (%s) timed at checkpoints through the run, between "
               "the poses: median ms/frame of the frames of at least %.0f ms (and at least %d frames) after two "
               "untimed ones, with the fastest kernel and with `ybuffer`, and when the checkpoint finished. "
               "Spread: (max − min) / median; above %.0f%% in either column the run is marked noisy.\n\n"
               "| checkpoint | at (s) | `%s` ms | `ybuffer` ms |\n|---|--:|--:|--:|\n",
            s->ref, ACC_STEADY_MIN_MS, ACC_STEADY_MIN_FRAMES, 100 * ACC_STEADY_NOISY, s->best_kernel);
    for (int i = 0; i < s->n; i++)
        fprintf(f, "| %s | %.1f | %.3f | %.3f |\n", s->cp[i].where, s->cp[i].at_s, s->cp[i].best, s->cp[i].ybuf);
    fprintf(f, "\nSpread: %.1f%% with `%s`, %.1f%% with `ybuffer`, over %d checkpoints: %s.\n",
            100 * acc_steady_spread(s, 0), s->best_kernel, 100 * acc_steady_spread(s, 1), s->n,
            acc_steady_noisy(s) ? "noisy" : "steady");
}
