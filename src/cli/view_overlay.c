/* Overlay text and frame-time medians for retro view. */
#include "view_overlay.h"

#include <stdio.h>
#include <string.h>

#include "view_font.h"

void view_timing_add(view_timing *t, double ms)
{
    t->ms[t->next] = ms;
    t->next = (t->next + 1) % VIEW_TIMING_N;
    if (t->n < VIEW_TIMING_N)
        t->n++;
}

double view_timing_median(const view_timing *t)
{
    double s[VIEW_TIMING_N];
    int n = t->n;
    if (!n)
        return 0;
    memcpy(s, t->ms, (size_t)n * sizeof *s);
    for (int i = 1; i < n; i++) /* insertion sort: 30 values at most */
        for (int k = i; k > 0 && s[k - 1] > s[k]; k--) {
            double x = s[k];
            s[k] = s[k - 1];
            s[k - 1] = x;
        }
    return n % 2 ? s[n / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
}

static void fill_box(uint32_t *frame, int W, int H, int x1, int y1)
{
    x1 = x1 < W ? x1 : W;
    y1 = y1 < H ? y1 : H;
    for (int y = 0; y < y1; y++)
        for (int x = 0; x < x1; x++) {
            uint32_t *p = &frame[(size_t)y * (size_t)W + (size_t)x];
            *p = (*p >> 1) & 0x7f7f7f00u;
        }
}

static void draw_char(uint32_t *frame, int W, int H, int x0, int y0, int scale, char c)
{
    uint8_t rows[VIEW_FONT_H];
    view_font_glyph(c, rows);
    for (int r = 0; r < VIEW_FONT_H * scale; r++)
        for (int k = 0; k < VIEW_FONT_W * scale; k++) {
            int x = x0 + k, y = y0 + r;
            if (x < W && y < H && (rows[r / scale] >> (VIEW_FONT_W - 1 - k / scale) & 1))
                frame[(size_t)y * (size_t)W + (size_t)x] = VIEW_TEXT_COLOR;
        }
}

void view_draw_text(uint32_t *frame, int W, int H, int scale, const char *const *lines, size_t n)
{
    size_t widest = 0;
    for (size_t i = 0; i < n; i++)
        widest = strlen(lines[i]) > widest ? strlen(lines[i]) : widest;
    if (!n || widest > 4096)
        return;
    int pad = 3 * scale;
    fill_box(frame, W, H, 2 * pad + (int)widest * VIEW_FONT_ADVANCE * scale,
             2 * pad + (int)n * VIEW_FONT_LINE * scale);
    for (size_t i = 0; i < n; i++)
        for (size_t c = 0; lines[i][c]; c++)
            draw_char(frame, W, H, pad + (int)c * VIEW_FONT_ADVANCE * scale,
                      pad + (int)i * VIEW_FONT_LINE * scale, scale, lines[i][c]);
}

size_t view_overlay_lines(const view_state *v, const view_timing *render_ms,
                          const view_timing *frame_ms, int paused, char lines[][96])
{
    size_t n = 0;
    const player_t *p = &v->pose;
    double rm = view_timing_median(render_ms), fm = view_timing_median(frame_ms);
    snprintf(lines[n++], 96, "KERNEL %s  FAMILY %s", view_kernel_name(v), view_family_name(v));
    snprintf(lines[n++], 96, "MODE %s  EFFECTS %s", view_mode_name(v),
             !view_has_effects(v) ? "NONE" : v->fx_on ? "ON" : "OFF");
    if (view_kernel_threaded(v))
        snprintf(lines[n++], 96, "THREADS %d", view_threads_shown(v));
    else
        snprintf(lines[n++], 96, "THREADS 1 (SINGLE-THREAD KERNEL)");
    snprintf(lines[n++], 96, "SIZE %dX%d  DISTANCE %d", v->j.c.scr_width, v->j.c.scr_height,
             v->j.c.distance);
    snprintf(lines[n++], 96, "POSE X %.1f Y %.1f Z %d A %d", (double)p->x, (double)p->y, p->height,
             p->angle);
    snprintf(lines[n++], 96, "RENDER %.3f MS (MEDIAN OF %d)  %.1f FPS", rm, render_ms->n,
             fm > 0 ? 1000.0 / fm : 0.0);
    if (v->status[0] || paused)
        snprintf(lines[n++], 96, "%s%.80s", paused ? "PAUSED " : "", v->status);
    snprintf(lines[n++], 96, "H: KEYS  O: OVERLAY OFF");
    return n;
}
