/* Where the accuracy charts' labels go (accuracy_metrics.c): gnuplot's `with labels` puts every
 * label at the same offset from its point, and variants close in time and error (lod 0.02 and
 * half; exact, fixed and truth against the mesh) printed over each other. */
#ifndef RETRO_CLI_CHART_LABELS_H
#define RETRO_CLI_CHART_LABELS_H

/* A log-log chart's plot area in approximate pixels, and the size of its labels' text there:
 * the widest advance of a character and the height of a line, over the terminals that draw it. */
typedef struct {
    double xlo, xhi, ylo, yhi; /* the axes' ranges, all > 0 */
    double width, height;      /* the plot area */
    double char_w, char_h;
} chart_frame;

typedef struct {
    double x0, y0, x1, y1; /* pixels from the plot's lower left corner */
} chart_box;

typedef struct {
    double x, y; /* pixels from the plot's lower left corner */
} chart_point;

/* A label's place: gnuplot's alignment, the offset from its point in pixels (up positive), and
 * the box it covers. */
typedef struct {
    const char *align; /* "left", "right" or "center" */
    double dx, dy;
    int leader; /* far enough from its point to want a line to it */
    chart_box box;
} chart_place;

/* Places the labels of n points (x[i], y[i]): each at one of 28 places around its point (the
 * four corners, the sides, above and below, near and up to four lines out), first in
 * turn, then moved in rounds to its cheapest place given all the others until none moves. A
 * place costs what it overlaps: the outside of the plot, the marks (the n points and any
 * further m points (mx[j], my[j]), each a box of 10 pixels) and, twice over, the other labels;
 * and it costs more for each of the n points nearer to it than its own.
 * out has n entries. Returns 0, or -1 when out of memory. */
int chart_place_labels(const chart_frame *fr, const double *x, const double *y, const char *const *labels, int n,
                       const double *mx, const double *my, int m, chart_place *out);

/* The overlap of two boxes, in square pixels. */
double chart_box_overlap(chart_box a, chart_box b);

/* Where data point (x, y) sits on the plot, in pixels. */
chart_point chart_pixel(const chart_frame *fr, double x, double y);

/* The distance from a point to the nearer end of a label's text (the middle of its left or
 * right edge): the eye gives a label to the point beside one of its ends, whichever way gnuplot
 * aligned it. */
double chart_end_distance(chart_point p, chart_box b);

#endif
