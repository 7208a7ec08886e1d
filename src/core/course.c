/* The course's functions (include/render.h). render() is mode course through the pthreads
 * kernel (the fastest strips on every core); it is write-once, so bonus_implemented() is
 * true: each pixel is written once and the sky is never filled first. This file is also the
 * tail of the generated single-file submission (scripts/make-submission.sh). */
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>

#include "render.h"
#include "retro.h"
#include "ctx.h"
#include "frame.h"
#include "kernels.h"
#include "retro_internal.h"

void update_player(player_t *p, ctx_t const *ctx)
{
    int64_t a = ((int64_t)p->angle + p->v_angular) % 360;
    p->angle = (int)(a < 0 ? a + 360 : a);

    double phi = p->angle * 3.14159265358979323846 / 180.0;
    float S = (float)ctx->map_size;
    /* The map's y axis points down, so moving along the view direction decreases y. */
    p->x = retro_float_mod(p->x + (float)(p->v * cos(phi)), S);
    p->y = retro_float_mod(p->y - (float)(p->v * sin(phi)), S);

    int64_t h = (int64_t)p->height + p->v_height;
    if (ctx->height_map && ctx->map_size >= 1) {
        int i = (int)p->x, j = (int)p->y;
        int64_t floor_h = (int64_t)ctx->height_map[(size_t)j * (size_t)ctx->map_size + (size_t)i] + 20;
        if (h < floor_h)
            h = floor_h;
    }
    p->height = (int)(h > INT32_MAX ? INT32_MAX : h < INT32_MIN ? INT32_MIN : h);
}

void draw_line(ctx_t *c, int u, int v_from, int v_to, uint32_t color)
{
    if (u < 1 || u > c->scr_width)
        return;
    int lo = v_from < 0 ? 0 : v_from;
    int hi = v_to > c->scr_height ? c->scr_height : v_to;
    for (int r = lo + 1; r <= hi; r++)
        c->out[retro_pixel(c->scr_width, c->scr_height, u, r)] = color;
}

/* One context for the life of the process, so the pthreads kernel's workers and the scratch
 * are made once, not per frame; the exit handler frees it and joins the workers (leak-free
 * under ASan). The maps may be freed and others loaded at the same addresses between calls,
 * so the caches keyed by map pointer are dropped every call (the course frame keeps none but
 * the map's maximum, recomputed every call). A call made while another is
 * rendering (from another thread) or after the exit handler ran uses a context of its own.
 * The kernel is called directly: the submission has no kernel table. */
static retro_ctx *course_rc;
static atomic_flag course_busy = ATOMIC_FLAG_INIT;
static int course_state; /* 0: not set up, 1: in use, 2: freed at exit or never made */

static void course_exit(void)
{
    if (!atomic_flag_test_and_set(&course_busy)) {
        retro_ctx_free(course_rc);
        course_rc = NULL;
        course_state = 2;
        atomic_flag_clear(&course_busy);
    }
}

static void render_once(retro_ctx *rc, const player_t *p, ctx_t *c)
{
    retro_ctx_map_changed(rc);
    /* The map's maximum (every frame's early exit needs it) is scanned anew each call, so frame
     * setup splits the scan between the pool's threads: read by one thread, the whole map is a
     * sizeable share of a course frame. */
    rc->map_scan = retro_pthreads_map_scan;
    if (retro_frame_setup(rc, RETRO_MODE_COURSE, p, c) == RETRO_OK)
        retro_kernel_pthreads(&rc->frame, rc);
}

void render(const player_t *p, ctx_t *c)
{
    if (!atomic_flag_test_and_set(&course_busy)) {
        if (course_state == 0) {
            course_rc = retro_ctx_new();
            course_state = course_rc && atexit(course_exit) == 0 ? 1 : 2;
            if (course_state == 2) {
                retro_ctx_free(course_rc);
                course_rc = NULL;
            }
        }
        if (course_state == 1) {
            render_once(course_rc, p, c);
            atomic_flag_clear(&course_busy);
            return;
        }
        atomic_flag_clear(&course_busy);
    }
    retro_ctx *rc = retro_ctx_new();
    if (rc)
        render_once(rc, p, c);
    retro_ctx_free(rc);
}

int bonus_implemented(void)
{
    return 1;
}
