/* retro view's window (SDL2): keys to actions, the frame plus overlay into a streaming
 * texture, and the timing the overlay shows. The renderer itself is view_render.c's. */
#include <SDL.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "view_loop.h"
#include "view_overlay.h"

/* Commands come from key presses (layout-dependent key codes); movement is a held key. */
static view_action key_action(const SDL_Keysym *k)
{
    int ctrl = (k->mod & KMOD_CTRL) != 0, shift = (k->mod & KMOD_SHIFT) != 0;
    switch (k->sym) {
    case SDLK_w: case SDLK_UP: return VA_FORWARD;
    case SDLK_s: return ctrl ? VA_SAVE : VA_BACK;
    case SDLK_DOWN: return VA_BACK;
    case SDLK_a: case SDLK_LEFT: return VA_LEFT;
    case SDLK_d: case SDLK_RIGHT: return VA_RIGHT;
    case SDLK_q: return VA_UP;
    case SDLK_e: return VA_DOWN;
    case SDLK_PAGEUP: case SDLK_PLUS: case SDLK_EQUALS: case SDLK_KP_PLUS: return VA_FAR;
    case SDLK_PAGEDOWN: case SDLK_MINUS: case SDLK_KP_MINUS: return VA_NEAR;
    case SDLK_TAB: return shift ? VA_KERNEL_PREV : VA_KERNEL_NEXT;
    case SDLK_m: return VA_MODE;
    case SDLK_f: return VA_EFFECTS;
    case SDLK_t: return VA_THREADS;
    case SDLK_p: return VA_PAUSE;
    case SDLK_F12: return VA_SAVE;
    case SDLK_o: return VA_OVERLAY;
    case SDLK_h: return VA_HELP;
    case SDLK_ESCAPE: return VA_QUIT;
    default: return VA_NONE;
    }
}

/* Keys held now, or pressed since the last frame (a tap shorter than a frame still moves). */
static void held_keys(unsigned char held[VA_COUNT])
{
    const Uint8 *ks = SDL_GetKeyboardState(NULL);
    int ctrl = (SDL_GetModState() & KMOD_CTRL) != 0;
    held[VA_FORWARD] |= ks[SDL_SCANCODE_W] | ks[SDL_SCANCODE_UP];
    held[VA_BACK] |= (ks[SDL_SCANCODE_S] && !ctrl) | ks[SDL_SCANCODE_DOWN];
    held[VA_LEFT] |= ks[SDL_SCANCODE_A] | ks[SDL_SCANCODE_LEFT];
    held[VA_RIGHT] |= ks[SDL_SCANCODE_D] | ks[SDL_SCANCODE_RIGHT];
    held[VA_UP] |= ks[SDL_SCANCODE_Q];
    held[VA_DOWN] |= ks[SDL_SCANCODE_E];
}

typedef struct window {
    SDL_Window *win;
    SDL_Renderer *ren;
    SDL_Texture *tex;
    uint32_t *pres; /* the frame with the overlay, at the render size */
    int tw, th;
} window;

static int fit_texture(window *w, int W, int H)
{
    if (w->tex && w->tw == W && w->th == H)
        return 0;
    if (w->tex)
        SDL_DestroyTexture(w->tex);
    free(w->pres);
    w->tex = SDL_CreateTexture(w->ren, SDL_PIXELFORMAT_RGBX8888, SDL_TEXTUREACCESS_STREAMING, W, H);
    w->pres = malloc((size_t)W * (size_t)H * sizeof *w->pres);
    w->tw = W;
    w->th = H;
    return w->tex && w->pres ? 0 : -1;
}

static void present(window *w, view_state *v, const view_ui *ui, const view_timing *rt,
                    const view_timing *ft)
{
    int W = v->j.c.scr_width, H = v->j.c.scr_height;
    memcpy(w->pres, v->j.out, (size_t)W * (size_t)H * sizeof *w->pres);
    char text[VIEW_OVERLAY_LINES][96];
    const char *lines[VIEW_OVERLAY_LINES + 32];
    size_t n = 0;
    if (ui->overlay)
        for (size_t i = 0, k = view_overlay_lines(v, rt, ft, ui->paused, text); i < k; i++)
            lines[n++] = text[i];
    if (ui->help)
        for (size_t i = 0; i < view_help_count && n < sizeof lines / sizeof lines[0]; i++)
            lines[n++] = view_help_lines[i];
    view_draw_text(w->pres, W, H, 1 + W / 1000, lines, n);
    SDL_UpdateTexture(w->tex, NULL, w->pres, W * (int)sizeof *w->pres);
    SDL_RenderClear(w->ren);
    SDL_RenderCopy(w->ren, w->tex, NULL, NULL);
    SDL_RenderPresent(w->ren);
}

static double ms_since(Uint64 t0)
{
    return (double)(SDL_GetPerformanceCounter() - t0) * 1000.0 / (double)SDL_GetPerformanceFrequency();
}

/* Events of one frame: commands applied, motion keys marked, resizes followed. */
static int poll(window *w, view_state *v, view_ui *ui, unsigned char held[VA_COUNT])
{
    SDL_Event e;
    int dirty = 0;
    while (SDL_PollEvent(&e)) {
        if (e.type == SDL_QUIT)
            ui->quit = 1;
        else if (e.type == SDL_KEYDOWN) {
            view_action a = key_action(&e.key.keysym);
            if (view_is_motion(a))
                held[a] = 1;
            else if (!e.key.repeat || a == VA_FAR || a == VA_NEAR) /* distance keys repeat */
                dirty |= view_apply(v, ui, a);
        } else if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED &&
                   !v->o.have_size) {
            int W, H;
            SDL_GetRendererOutputSize(w->ren, &W, &H);
            if (view_resize(v, W, H) == 0)
                dirty = 1;
        }
    }
    return dirty;
}

static int run(window *w, view_state *v, view_ui *ui)
{
    view_timing rt = {{0}, 0, 0}, ft = {{0}, 0, 0};
    Uint64 last = SDL_GetPerformanceCounter();
    int dirty = 1;
    while (!ui->quit) {
        unsigned char held[VA_COUNT] = {0};
        dirty |= poll(w, v, ui, held);
        if (ui->quit)
            break;
        held_keys(held);
        if (!ui->paused)
            view_move(v, view_motion_of(held));
        if (!ui->paused || dirty) {
            Uint64 t0 = SDL_GetPerformanceCounter();
            if (view_render(v) == 0)
                view_timing_add(&rt, ms_since(t0));
            else
                memset(v->j.out, 0, (size_t)v->j.c.scr_width * (size_t)v->j.c.scr_height * 4);
        }
        if (ui->save) {
            ui->save = 0;
            view_save_now(v, ui);
        }
        if (fit_texture(w, v->j.c.scr_width, v->j.c.scr_height))
            return cli_error("view", "cannot make the window's texture: %s", SDL_GetError());
        present(w, v, ui, &rt, &ft);
        view_timing_add(&ft, ms_since(last));
        last = SDL_GetPerformanceCounter();
        if (ui->paused && !dirty)
            SDL_Delay(15);
        dirty = 0;
    }
    return 0;
}

/* Whether a window could be seen: SDL would otherwise fall back to its offscreen driver (or
 * print the complaints of the Wayland library it probes) and show nothing. */
static const char *no_display(void)
{
    const char *drv = getenv("SDL_VIDEODRIVER");
    if (drv && (!strcmp(drv, "dummy") || !strcmp(drv, "offscreen")))
        return drv;
    const char *x = getenv("DISPLAY"), *wl = getenv("WAYLAND_DISPLAY");
    if (!drv && (!x || !*x) && (!wl || !*wl)) /* DISPLAY= (empty) names no display either */
        return "neither DISPLAY nor WAYLAND_DISPLAY is set";
    return NULL;
}

int view_window_run(view_state *v, view_ui *ui)
{
    const char *why = no_display();
    if (why)
        return cli_error("view", "no display (%s); --keys replays a key script headless", why);
    if (SDL_Init(SDL_INIT_VIDEO))
        return cli_error("view", "no display (%s); --keys replays a key script headless", SDL_GetError());
    const char *drv = SDL_GetCurrentVideoDriver();
    if (drv && (!strcmp(drv, "dummy") || !strcmp(drv, "offscreen"))) {
        SDL_Quit();
        return cli_error("view", "no display (SDL video driver %s); --keys replays a key script headless", drv);
    }
    window w = {0};
    char title[256];
    snprintf(title, sizeof title, "retro view: %s", v->o.map);
    w.win = SDL_CreateWindow(title, SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                             v->j.c.scr_width, v->j.c.scr_height, SDL_WINDOW_RESIZABLE);
    if (w.win) {
        w.ren = SDL_CreateRenderer(w.win, -1, SDL_RENDERER_PRESENTVSYNC);
        if (!w.ren)
            w.ren = SDL_CreateRenderer(w.win, -1, 0);
    }
    int r;
    if (!w.ren)
        r = cli_error("view", "cannot open a window: %s", SDL_GetError());
    else {
        if (v->o.have_size) /* the fixed render size, scaled to the window, aspect kept */
            SDL_RenderSetLogicalSize(w.ren, v->j.c.scr_width, v->j.c.scr_height);
        r = run(&w, v, ui);
    }
    if (w.tex)
        SDL_DestroyTexture(w.tex);
    if (w.ren)
        SDL_DestroyRenderer(w.ren);
    if (w.win)
        SDL_DestroyWindow(w.win);
    free(w.pres);
    SDL_Quit();
    return r;
}
