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

chart_point chart_pixel(const chart_frame *fr, double x, double y)
{
    return (chart_point){(log10(x) - log10(fr->xlo)) * fr->width / (log10(fr->xhi) - log10(fr->xlo)),
                         (log10(y) - log10(fr->ylo)) * fr->height / (log10(fr->yhi) - log10(fr->ylo))};
}

/* A point's mark: a box of 10 pixels around it. */
static chart_box mark(chart_point p)
{
    return (chart_box){p.x - 5, p.y - 5, p.x + 5, p.y + 5};
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

static chart_box place_box(const chart_frame *fr, chart_point at, double w, int c)
{
    const double ax = at.x + place_dx(fr, c), ay = at.y + place_dy(fr, c);
    const double x0 = place[c].align[0] == 'l' ? ax : place[c].align[0] == 'r' ? ax - w : ax - w / 2;
    return (chart_box){x0, ay - fr->char_h / 2, x0 + w, ay + fr->char_h / 2};
}

double chart_end_distance(chart_point p, chart_box b)
{
    const double mid = (b.y0 + b.y1) / 2;
    return fmin(hypot(p.x - b.x0, p.y - mid), hypot(p.x - b.x1, p.y - mid));
}

/* What label i at place c overlaps: the plot's outside, the points' marks, and the labels
 * 0..placed-1 (counted twice: covering a label is worse than covering a point), but not its
 * own. A label with an end nearer another point of the n than its own reads as that point's,
 * which costs as much as covering most of a point, unless a leader line ties it to its own;
 * a place further out costs a little more, so that a free near place wins. */
static double cost(const chart_frame *fr, const chart_point *pts, int points, const chart_place *out, int placed,
                   int n, int i, chart_box b, int c)
{
    const chart_box plot = {0, 0, fr->width, fr->height};
    double sum = (b.x1 - b.x0) * (b.y1 - b.y0) - chart_box_overlap(b, plot) + 0.01 * c;
    const double own = chart_end_distance(pts[i], b);
    for (int j = 0; j < points; j++) {
        sum += chart_box_overlap(b, mark(pts[j]));
        if (c < NEAR && j < n && j != i && chart_end_distance(pts[j], b) < own)
            sum += 60;
    }
    for (int j = 0; j < placed; j++)
        if (j != i)
            sum += 2 * chart_box_overlap(b, out[j].box);
    return sum;
}

/* Label i at its cheapest place given labels 0..placed-1; whether that moved it. */
static int best_place(const chart_frame *fr, const chart_point *pts, int points, chart_place *out, int placed, int n,
                      int i, double w)
{
    int best = 0;
    double least = INFINITY;
    for (int c = 0; c < PLACES; c++) {
        const double v = cost(fr, pts, points, out, placed, n, i, place_box(fr, pts[i], w, c), c);
        if (v < least) {
            least = v;
            best = c;
        }
    }
    const int changed = out[i].align != place[best].align || out[i].dx != place_dx(fr, best) ||
                        out[i].dy != place_dy(fr, best);
    out[i] = (chart_place){place[best].align, place_dx(fr, best), place_dy(fr, best), best >= NEAR,
                           place_box(fr, pts[i], w, best)};
    return changed;
}

int chart_place_labels(const chart_frame *fr, const double *x, const double *y, const char *const *labels, int n,
                       const double *mx, const double *my, int m, chart_place *out)
{
    chart_point *pts = malloc(sizeof *pts * (size_t)(n + m + 1));
    if (!pts)
        return -1;
    memset(out, 0, sizeof *out * (size_t)n); /* no place yet: the first choice counts as a move */
    for (int i = 0; i < n + m; i++)
        pts[i] = i < n ? chart_pixel(fr, x[i], y[i]) : chart_pixel(fr, mx[i - n], my[i - n]);
    /* greedily in turn, then rounds in which each label moves to its cheapest place given all
     * the others, until none moves (a label placed early may block a later one's only room) */
    for (int i = 0; i < n; i++)
        best_place(fr, pts, n + m, out, i, n, i, fr->char_w * (double)strlen(labels[i]));
    for (int round = 0, moved = 1; moved && round < 20; round++) {
        moved = 0;
        for (int i = 0; i < n; i++)
            moved |= best_place(fr, pts, n + m, out, n, n, i, fr->char_w * (double)strlen(labels[i]));
    }
    free(pts);
    return 0;
}
