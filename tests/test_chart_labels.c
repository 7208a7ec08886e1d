/* The accuracy charts' label places (src/cli/chart_labels.h), on the crowded layouts that made
 * gnuplot's labels overprint: the points of a published accuracy run (results/ACCURACY.md of
 * 25ce297), whose lod, half and peer variants sit within a third of a decade of each other. */
#include <criterion/criterion.h>
#include <math.h>

#include "../src/cli/chart_labels.h"

static const chart_frame frame = {0.01, 100, 0.0005, 100, 665, 425, 8.5, 16};

static void no_overlaps(const chart_frame *fr, const double *x, const double *y, const char *const *labels, int n,
                        const double *mx, const double *my, int m)
{
    chart_place at[16];
    cr_assert_leq(n, 16);
    cr_assert_eq(chart_place_labels(fr, x, y, labels, n, mx, my, m, at), 0);
    const chart_box plot = {0, 0, fr->width, fr->height};
    for (int i = 0; i < n; i++) {
        const chart_box b = at[i].box;
        cr_expect_float_eq(chart_box_overlap(b, plot), (b.x1 - b.x0) * (b.y1 - b.y0), 1e-9, "'%s' leaves the plot",
                           labels[i]);
        for (int j = i + 1; j < n; j++)
            cr_expect_eq(chart_box_overlap(b, at[j].box), 0, "'%s' and '%s' overlap", labels[i], labels[j]);
        /* an end of it nearer its own point than any other it names, so that it reads as its
         * own, or a leader line tying it to its own */
        const double own = chart_end_distance(chart_pixel(fr, x[i], y[i]), b);
        for (int j = 0; j < n; j++)
            cr_expect(j == i || at[i].leader || chart_end_distance(chart_pixel(fr, x[j], y[j]), b) >= own,
                      "'%s' has an end nearer '%s' than its own point", labels[i], labels[j]);
        for (int j = 0; j < n + m; j++) { /* no label covers a point's centre */
            const chart_point c = j < n ? chart_pixel(fr, x[j], y[j]) : chart_pixel(fr, mx[j - n], my[j - n]);
            cr_expect(!(b.x0 < c.x && c.x < b.x1 && b.y0 < c.y && c.y < b.y1), "'%s' covers point %d", labels[i], j);
        }
    }
}

Test(chart_labels, the_pareto_charts_crowded_points_get_apart)
{
    static const char *const labels[] = {"truth", "exact", "course", "fixed", "lod 0.005",
                                         "lod 0.02", "lod 0.05", "half", "peer: classic demo"};
    static const double x[] = {1.39, 0.215, 0.61, 1.06, 0.198, 0.097, 0.061, 0.12, 0.51};
    static const double y[] = {1e-3, 0.044, 25.7, 0.32, 4.0, 22.2, 31.7, 20.3, 36.0};
    static const double xy[] = {2.8, 2.6, 0.67, 2.1, 2.55, 1.14, 0.55, 1.13, 6.9}; /* ybuffer's */
    no_overlaps(&frame, x, y, labels, 9, xy, y, 9);
}

/* The families chart's variants, and its frame: the mesh's points take the time axis to 1000. */
static const char *const families[] = {"truth",    "exact",    "course", "fixed",
                                       "lod 0.005", "lod 0.02", "lod 0.05", "half",
                                       "peer: classic demo", "mesh binary32", "mesh binary64", "mesh int"};
static const chart_frame families_frame = {0.01, 1000, 0.0005, 100, 665, 425, 8.5, 16};

Test(chart_labels, the_families_charts_crowded_points_get_apart)
{
    static const double x[] = {1.39, 0.215, 0.61, 1.06, 0.198, 0.097, 0.061, 0.12, 0.51, 12.1, 77, 96};
    static const double y[] = {20.3, 20.4, 26.0, 20.8, 22.6, 32.3, 36.0, 29.7, 36.0, 0.0015, 0.001, 0.0011};
    no_overlaps(&families_frame, x, y, families, 12, NULL, NULL, 0);
}

/* Another run's: the peer's point just left of fixed's label above fixed's point, and course's
 * point below and right of the peer's. */
Test(chart_labels, a_label_does_not_sit_beside_another_point)
{
    static const double x[] = {1.425, 0.226, 0.638, 1.085, 0.199, 0.093, 0.060, 0.123, 0.607, 12, 77, 97};
    static const double y[] = {20.5, 20.6, 26.6, 20.9, 22.8, 32.3, 36.6, 30.2, 36.7, 0.0015, 0.001, 0.0011};
    no_overlaps(&families_frame, x, y, families, 12, NULL, NULL, 0);
}

/* b's point sits just left of where a's label would start at its first place (13.5 pixels from
 * that end, against 15.4 from a's own point): a's label goes elsewhere. */
Test(chart_labels, a_label_is_not_anchored_beside_another_point)
{
    static const char *const labels[] = {"alpha", "beta"};
    static const double x[] = {0.637, 0.595}, y[] = {0.1562, 0.2269};
    no_overlaps(&frame, x, y, labels, 2, NULL, NULL, 0);
}

/* A label whose point sits in a corner stays inside the plot. */
Test(chart_labels, a_corner_point_keeps_its_label_inside)
{
    static const char *const labels[] = {"top right", "bottom left"};
    static const double x[] = {99, 0.0101}, y[] = {99, 0.00051};
    no_overlaps(&frame, x, y, labels, 2, NULL, NULL, 0);
}
