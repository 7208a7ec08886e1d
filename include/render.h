/* The course API, field for field: a submission's render.c compiles against this header. */
#ifndef RENDER_H
#define RENDER_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    float x, y;    /* position on the map */
    int angle;     /* view direction in degrees, counter-clockwise from the x axis */
    int height;    /* camera height */
    int v;         /* velocity in the view direction */
    int v_height;  /* height change per update */
    int v_angular; /* angle change per update */
} player_t;

typedef struct {
    int scr_width;      /* W */
    int scr_height;     /* H */
    int map_size;       /* S: both maps hold S*S entries */
    int distance;       /* D: samples are taken at d = 1 .. D-1 */
    uint32_t sky_color; /* R<<24 | G<<16 | B<<8 */
    uint8_t *height_map;  /* row-major, entry 0 top-left */
    uint32_t *color_map;  /* row-major, entry 0 top-left */
    uint32_t *out;        /* W*H, rows top to bottom */
} ctx_t;

void update_player(player_t *p, ctx_t const *ctx);
void draw_line(ctx_t *c, int u, int v_from, int v_to, uint32_t color);
void render(const player_t *p, ctx_t *c);
int bonus_implemented(void);

#ifdef __cplusplus
}
#endif

#endif
