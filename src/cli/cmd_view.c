/* retro view: fly through a map or scene in a window, or replay a key script headless. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "view_keys.h"
#include "view_loop.h"
#include "view_save.h"

static void help(void)
{
    printf("usage: retro view MAP|SCENE [--keys SCRIPT [--screenshot OUT.png]] [--save-dir DIR]\n"
           "                 [-k KERNEL] [-m MODE] [-s WxH] [-d DISTANCE] [-p X,Y] [-z HEIGHT]\n"
           "                 [-a ANGLE] [--sky RRGGBB] [--isa LEVEL] [--threads N] [--lod L]\n\n"
           "Flies through MAP or SCENE in a window (SDL2), starting at the pose retro render\n"
           "would draw. The frame is rendered at the window's size; -s WxH fixes the render size\n"
           "and scales it to the window. The overlay shows kernel, family, mode, effects,\n"
           "threads, size, distance, pose, the median render time of the last 30 frames (the\n"
           "kernel alone, without presentation) and the frame rate. Keys (docs/VIEW.md):\n\n");
    for (size_t i = 0; i < view_help_count; i++)
        printf("  %s\n", view_help_lines[i]);
    printf("\nMovement is the course's update_player: per frame a held key sets v = +-%d (W/S),\n"
           "v_angular = +-%d degrees (A/D), v_height = +-%d (Q/E); distance steps by %d.\n\n",
           VIEW_SPEED, VIEW_TURN, VIEW_CLIMB, VIEW_D_STEP);
    printf("  --keys SCRIPT      replay keys headless, one per frame, no window: comma-separated\n"
           "                     names w s a d q e up down left right pageup pagedown plus minus\n"
           "                     tab shift+tab m f t p o h ctrl+s f12 esc none, each with an\n"
           "                     optional *N repeat (\"w*30,a*10,tab,q*5\"); prints the final\n"
           "                     pose as \"x y height angle\" and exits 0\n"
           "  --screenshot OUT   with --keys: write the last frame (.png or .ppm) at the render\n"
           "                     size and without the overlay, so it is byte-comparable with\n"
           "                     retro render at the printed pose with the same kernel and mode\n"
           "  --save-dir DIR     where Ctrl+S / F12 write NAME-NNN.png and NAME-NNN.scene\n"
           "                     (default results/view)\n"
           "The other options are retro render's. Without a display and without --keys, retro\n"
           "view exits with status 2.\n");
}

typedef struct view_args {
    const char *keys, *shot, *save_dir;
} view_args;

static int view_extra(void *user, const char *a, const char *v)
{
    view_args *va = user;
    if (!strcmp(a, "--keys"))
        va->keys = v ? v : va->keys;
    else if (!strcmp(a, "--screenshot"))
        va->shot = v ? v : va->shot;
    else if (!strcmp(a, "--save-dir"))
        va->save_dir = v ? v : va->save_dir;
    else
        return 0;
    return 1;
}

int view_apply(view_state *v, view_ui *ui, view_action a)
{
    switch (a) {
    case VA_FAR: view_distance(v, VIEW_D_STEP); break;
    case VA_NEAR: view_distance(v, -VIEW_D_STEP); break;
    case VA_KERNEL_NEXT: view_next_kernel(v, 1); break;
    case VA_KERNEL_PREV: view_next_kernel(v, -1); break;
    case VA_MODE: view_next_mode(v); break;
    case VA_EFFECTS: view_toggle_effects(v); break;
    case VA_THREADS: view_next_threads(v); break;
    case VA_PAUSE: ui->paused = !ui->paused; break;
    case VA_SAVE: ui->save = 1; break;
    case VA_OVERLAY: ui->overlay = !ui->overlay; return 0;
    case VA_HELP: ui->help = !ui->help; return 0;
    case VA_QUIT: ui->quit = 1; return 0;
    default: return 0;
    }
    return 1;
}

void view_save_now(view_state *v, const view_ui *ui)
{
    char done[1600];
    if (view_save(v, ui->save_dir, done, sizeof done)) {
        fprintf(stderr, "retro view: %s\n", done);
        snprintf(v->status, sizeof v->status, "SAVE FAILED (SEE STDERR)");
    } else {
        fprintf(stderr, "retro view: saved %s and its .scene\n", done);
        snprintf(v->status, sizeof v->status, "SAVED %.140s", done);
    }
}

/* The headless replay: each frame applies its key, moves and renders. */
static int replay(view_state *v, view_ui *ui, const view_script *s, const char *shot)
{
    int rendered = 0;
    for (size_t i = 0; i < s->n && !ui->quit; i++) {
        unsigned char held[VA_COUNT] = {0};
        if (view_is_motion(s->frames[i]))
            held[s->frames[i]] = 1;
        else
            view_apply(v, ui, s->frames[i]);
        if (ui->quit)
            break;
        if (!ui->paused)
            view_move(v, view_motion_of(held));
        if (view_render(v))
            return cli_error("view", "frame %zu: %s", i + 1, v->status);
        rendered = 1;
        if (ui->save) {
            ui->save = 0;
            view_save_now(v, ui);
        }
    }
    if (!rendered && view_render(v))
        return cli_error("view", "%s", v->status);
    if (shot) {
        char err[1400];
        if (retro_image_write(shot, v->j.out, v->j.c.scr_width, v->j.c.scr_height, err, sizeof err))
            return cli_error("view", "%s", err);
    }
    printf("%.9g %.9g %d %d\n", (double)v->pose.x, (double)v->pose.y, v->pose.height, v->pose.angle);
    return 0;
}

static int has_image_ext(const char *p)
{
    size_t n = strlen(p);
    return n > 4 && (!strcmp(p + n - 4, ".png") || !strcmp(p + n - 4, ".ppm"));
}

int cmd_view(int argc, char **argv)
{
    view_args va = {NULL, NULL, "results/view"};
    render_opts o;
    render_opts_init(&o);
    int r = render_args("view", "MAP|SCENE", argc, argv, &o, view_extra, &va, help);
    if (r)
        return r == 1 ? 0 : r;
    if (va.shot && !va.keys)
        return cli_error("view", "--screenshot needs --keys (a headless replay)");
    if (va.shot && !has_image_ext(va.shot))
        return cli_error("view", "screenshot '%s' must end in .png or .ppm", va.shot);
    view_script script = {NULL, 0};
    char err[256];
    if (va.keys && view_script_parse(va.keys, &script, err, sizeof err))
        return cli_error("view", "%s", err);
    view_state v;
    if (view_open("view", &o, &v)) {
        view_script_free(&script);
        return CLI_EBADINPUT;
    }
    view_ui ui = {0, 1, 0, 0, 0, va.save_dir};
    r = va.keys ? replay(&v, &ui, &script, va.shot) : view_window_run(&v, &ui);
    view_close(&v);
    view_script_free(&script);
    return r;
}
