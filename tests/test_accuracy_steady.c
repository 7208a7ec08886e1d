/* The accuracy run's steadiness (src/cli/accuracy_steady.h): the spread of its checkpoints, the
 * threshold that marks a run noisy, and the report's note and table. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accuracy_steady.h"

static acc_steady steady_of(const double *best, const double *ybuf, int n)
{
    acc_steady s = {.n = n, .best_kernel = "omp", .ref = "a reference frame"};
    for (int i = 0; i < n; i++) {
        s.cp[i].best = best[i];
        s.cp[i].ybuf = ybuf[i];
        s.cp[i].at_s = i;
        snprintf(s.cp[i].where, sizeof s.cp[i].where, "checkpoint %d", i + 1);
    }
    return s;
}

/* The report written to memory. */
static char *report(const acc_steady *s)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    cr_assert(f);
    acc_steady_write_note(f, s);
    acc_steady_write_table(f, s);
    fclose(f);
    return buf;
}

Test(accuracy_steady, spread_is_range_over_median)
{
    /* sorted 1.0 1.0 1.0 1.05 1.2: median 1.0 */
    const double best[] = {1.2, 1.0, 1.05, 1.0, 1.0}, ybuf[] = {2, 2, 2, 2, 2};
    acc_steady s = steady_of(best, ybuf, 5);
    cr_assert_float_eq(acc_steady_spread(&s, 0), 0.2, 1e-12);
    cr_assert_float_eq(acc_steady_spread(&s, 1), 0.0, 1e-12);
    acc_steady one = steady_of(best, ybuf, 1);
    cr_assert_eq(acc_steady_spread(&one, 0), 0.0, "one checkpoint has no spread");
}

Test(accuracy_steady, either_column_above_ten_percent_is_noisy)
{
    const double flat[] = {1, 1, 1}, below[] = {1.0, 1.0, 1.0999}, above[] = {1.0, 1.0, 1.1001};
    acc_steady s = steady_of(flat, below, 3);
    cr_assert(!acc_steady_noisy(&s), "a spread just below 10%%");
    s = steady_of(flat, above, 3);
    cr_assert(acc_steady_noisy(&s), "the ybuffer column alone above 10%%");
    s = steady_of(above, flat, 3);
    cr_assert(acc_steady_noisy(&s), "the fastest kernel's column alone above 10%%");
}

Test(accuracy_steady, the_report_says_which)
{
    const double flat[] = {0.20, 0.21, 0.20}, slow[] = {0.20, 0.30, 0.20}, y[] = {2.0, 2.0, 2.1};
    acc_steady s = steady_of(flat, y, 3);
    char *r = report(&s);
    cr_assert(!strstr(r, "Noisy run"), "a steady run has no note:\n%s", r);
    cr_assert(strstr(r, "| checkpoint 2 | 1.0 | 0.210 | 2.000 |"), "every checkpoint is listed:\n%s", r);
    cr_assert(strstr(r, "Spread: 5.0% with `omp`, 5.0% with `ybuffer`, over 3 checkpoints: steady."), "%s", r);
    free(r);
    s = steady_of(slow, y, 3);
    r = report(&s);
    /* make publish-accuracy and readme-figures.py read these two lines */
    cr_assert(!strncmp(r, "> **Noisy run.** The reference frame's time spread 50% with `omp`", 64), "%s", r);
    cr_assert(strstr(r, "Spread: 50.0% with `omp`, 5.0% with `ybuffer`, over 3 checkpoints: noisy."), "%s", r);
    free(r);
}
