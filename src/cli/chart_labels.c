#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chart_labels.h"

enum { PLACES = 28, NEAR = 8 };

double chart_box_overlap(chart_box a, chart_box b)
{
    double w = fmin(a.x1, b.x1) - fmax(a.x0, b.x0), h = fmin(a.y1, b.y1) - fmax(a.y0, b.y0);
    return w > 0 && h > 0 ? w * h : 0;
}

static chart_box mark(const chart_frame *fr, double x, double y)
{
    const double px = (log10(x) - log10(fr->xlo)) * fr->width / (log10(fr->xhi) - log10(fr->xlo));
    const double py = (log10(y) - log10(fr->ylo)) * fr->height / (log10(fr->yhi) - log10(fr->ylo));
    return (chart_box){px - 5, py - 5, px + 5, py + 5};
}

/* Upper right first, as the charts had them; then the other corners, the sides, above, below;
 * then further out, up to four lines away, where a crowd of points leaves no room near them.
 * Places from NEAR on are far enough for the chart to draw a leader line. */
static const struct {
    const char *align;
    double dx, dy;
} place[PLACES] = {{"left", 1, 0.8},    {"left", 1, -0.8},   {"right", -1, 0.8},  {"right", -1, -0.8},
                   {"left", 1, 0},      {"right", -1, 0},    {"center", 0, 1.3},  {"center", 0, -1.3},
                   {"left", 1, 1.8},    {"left", 1, -1.8},   {"right", -1, 1.8},  {"right", -1, -1.8},
                   {"left", 2.5, 0},    {"right", -2.5, 0},  {"center", 0, 2.3},  {"center", 0, -2.3},
                   {"left", 1, 2.8},    {"left", 1, -2.8},   {"right", -1, 2.8},  {"right", -1, -2.8},
                   {"center", 0, 3.3},  {"center", 0, -3.3}, {"left", 1, 3.8},    {"left", 1, -3.8},
                   {"right", -1, 3.8},  {"right", -1, -3.8}, {"center", 0, 4.3},  {"center", 0, -4.3}};

/* The place's offset in pixels: across in characters, up in lines. */
static double place_dx(const chart_frame *fr, int c) { return place[c].dx * fr->char_w; }
static double place_dy(const chart_frame *fr, int c) { return place[c].dy * fr->char_h; }

static chart_box place_box(const chart_frame *fr, chart_box at, double w, int c)
{
    const double ax = (at.x0 + at.x1) / 2 + place_dx(fr, c), ay = (at.y0 + at.y1) / 2 + place_dy(fr, c);
    const double x0 = place[c].align[0] == 'l' ? ax : place[c].align[0] == 'r' ? ax - w : ax - w / 2;
    return (chart_box){x0, ay - fr->char_h / 2, x0 + w, ay + fr->char_h / 2};
}

/* The distance from a point (the centre of its mark) to the nearer end of a label's text (the
 * middle of its left or right edge): the eye gives a label to the point beside one of its ends,
 * whichever way gnuplot aligned it. */
static double end_distance(chart_box m, chart_box b)
{
    const double px = (m.x0 + m.x1) / 2, py = (m.y0 + m.y1) / 2, mid = (b.y0 + b.y1) / 2;
    return fmin(hypot(px - b.x0, py - mid), hypot(px - b.x1, py - mid));
}

/* What label i at place c overlaps: the plot's outside, the points, and the labels of `placed`
 * (counted twice: covering a label is worse than covering a point), but not its own. A label
 * with an end nearer another point of the n than its own reads as that point's, which costs as
 * much as covering most of a point, unless a leader line ties it to its own; a place further out costs a little more, so that a free near
 * place wins. */
static double cost(const chart_frame *fr, const chart_box *marks, int points, const chart_place *out,
                   const int *placed, int n, int i, chart_box b, int c)
{
    const chart_box plot = {0, 0, fr->width, fr->height};
    double sum = (b.x1 - b.x0) * (b.y1 - b.y0) - chart_box_overlap(b, plot) + 0.01 * c;
    const double own = end_distance(marks[i], b);
    for (int j = 0; j < points; j++) {
        sum += chart_box_overlap(b, marks[j]);
        if (c < NEAR && j < n && j != i && end_distance(marks[j], b) < own)
            sum += 60;
    }
    for (int j = 0; j < n; j++)
        if (j != i && placed[j])
            sum += 2 * chart_box_overlap(b, out[j].box);
    return sum;
}

/* The cheapest place for label i given the others placed so far. */
static int best_place(const chart_frame *fr, const chart_box *marks, int points, chart_place *out, const int *placed,
                      int n, int i, double w)
{
    int best = 0;
    double least = INFINITY;
    for (int c = 0; c < PLACES; c++) {
        const chart_box b = place_box(fr, marks[i], w, c);
        const double v = cost(fr, marks, points, out, placed, n, i, b, c);
        if (v < least) {
            least = v;
            best = c;
        }
    }
    const int changed = !placed[i] || out[i].align != place[best].align || out[i].dx != place_dx(fr, best) ||
                        out[i].dy != place_dy(fr, best);
    out[i] = (chart_place){place[best].align, place_dx(fr, best), place_dy(fr, best), best >= NEAR,
                           place_box(fr, marks[i], w, best)};
    return changed;
}

int chart_place_labels(const chart_frame *fr, const double *x, const double *y, const char *const *labels, int n,
                       const double *mx, const double *my, int m, chart_place *out)
{
    chart_box *marks = malloc(sizeof *marks * (size_t)(n + m + 1));
    int *placed = calloc((size_t)n + 1, sizeof *placed);
    if (!marks || !placed) {
        free(marks);
        free(placed);
        return -1;
    }
    int k = 0;
    for (int i = 0; i < n; i++)
        marks[k++] = mark(fr, x[i], y[i]);
    for (int j = 0; j < m; j++)
        marks[k++] = mark(fr, mx[j], my[j]);
    /* greedily in turn, then rounds in which each label moves to its cheapest place given all
     * the others, until none moves (a label placed early may block a later one's only room) */
    for (int i = 0; i < n; i++) {
        best_place(fr, marks, k, out, placed, n, i, fr->char_w * (double)strlen(labels[i]));
        placed[i] = 1;
    }
    for (int round = 0, moved = 1; moved && round < 20; round++) {
        moved = 0;
        for (int i = 0; i < n; i++)
            moved |= best_place(fr, marks, k, out, placed, n, i, fr->char_w * (double)strlen(labels[i]));
    }
    free(marks);
    free(placed);
    return 0;
}
