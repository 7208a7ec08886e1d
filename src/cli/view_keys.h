/* retro view's keys without SDL: the actions, the names a --keys script uses, the movement a
 * set of held keys asks of update_player, and the help table. The window maps SDL's key codes
 * onto the same actions (view_window.c), so a script replays exactly what the keyboard does. */
#ifndef RETRO_CLI_VIEW_KEYS_H
#define RETRO_CLI_VIEW_KEYS_H

#include <stddef.h>

typedef enum view_action {
    VA_NONE,                                 /* an idle frame */
    VA_FORWARD, VA_BACK, VA_LEFT, VA_RIGHT, VA_UP, VA_DOWN, /* held: movement */
    VA_FAR, VA_NEAR,                         /* distance up, down */
    VA_KERNEL_NEXT, VA_KERNEL_PREV, VA_MODE, VA_EFFECTS, VA_THREADS,
    VA_PAUSE, VA_SAVE, VA_OVERLAY, VA_HELP, VA_QUIT,
    VA_COUNT
} view_action;

/* Per-frame steps of update_player's velocities while a movement key is held. */
#define VIEW_SPEED 4 /* v: map units forward (W) or back (S) */
#define VIEW_TURN 2  /* v_angular: degrees, A turns left (counter-clockwise), D right */
#define VIEW_CLIMB 2 /* v_height: Q up, E down */
/* PageUp/PageDown or +/- change the distance by this much, within [VIEW_D_MIN, VIEW_D_MAX]. */
#define VIEW_D_STEP 100
#define VIEW_D_MIN 100
#define VIEW_D_MAX 65536

/* Velocities for one frame: held[a] is nonzero for each movement action a held down. */
typedef struct view_motion {
    int v, v_height, v_angular;
} view_motion;
view_motion view_motion_of(const unsigned char held[VA_COUNT]);
int view_is_motion(view_action a);

/* The action a script key name stands for ("w", "tab", "shift+tab", "pageup", "f12", ...);
 * returns -1 for an unknown name. */
int view_key_parse(const char *name, size_t len, view_action *a);

/* A parsed --keys script: one action per frame. */
typedef struct view_script {
    view_action *frames;
    size_t n;
} view_script;
#define VIEW_SCRIPT_MAX_FRAMES 1000000
/* Parses "w*30,a*10,tab,q*5": comma-separated key names, each optionally repeated *N times
 * (N from 1). Returns 0, or -1 with a one-line reason in err and *out left empty (nothing to
 * free). tests/fuzz/fuzz_keys.c checks it against the grammar. */
int view_script_parse(const char *s, view_script *out, char *err, size_t errlen);
void view_script_free(view_script *s);

/* The key table for --help and the H overlay: lines of "KEYS  what they do". */
extern const char *const view_help_lines[];
extern const size_t view_help_count;

#endif
