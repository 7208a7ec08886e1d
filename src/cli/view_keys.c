/* retro view's key names, script parser and movement: no SDL here, so tests link it alone. */
#include "view_keys.h"
#include "errf.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Script names: each is what the key is labelled; arrows and +/- alias the letters. S moves
 * back (the course's W, A, S, D), so saving is Ctrl+S or F12. */
static const struct {
    const char *name;
    view_action a;
} NAMES[] = {
    {"none", VA_NONE},        {"w", VA_FORWARD},       {"up", VA_FORWARD},
    {"s", VA_BACK},           {"down", VA_BACK},       {"a", VA_LEFT},
    {"left", VA_LEFT},        {"d", VA_RIGHT},         {"right", VA_RIGHT},
    {"q", VA_UP},             {"e", VA_DOWN},          {"pageup", VA_FAR},
    {"plus", VA_FAR},         {"+", VA_FAR},           {"pagedown", VA_NEAR},
    {"minus", VA_NEAR},       {"-", VA_NEAR},          {"tab", VA_KERNEL_NEXT},
    {"shift+tab", VA_KERNEL_PREV}, {"m", VA_MODE},     {"f", VA_EFFECTS},
    {"t", VA_THREADS},        {"p", VA_PAUSE},         {"ctrl+s", VA_SAVE},
    {"f12", VA_SAVE},         {"o", VA_OVERLAY},       {"h", VA_HELP},
    {"esc", VA_QUIT},
};

const char *const view_help_lines[] = {
    "W S / UP DOWN    FORWARD, BACK",
    "A D / LEFT RIGHT TURN LEFT, RIGHT",
    "Q E              UP, DOWN",
    "PGUP PGDN / + -  DISTANCE",
    "TAB / SHIFT+TAB  NEXT, PREVIOUS KERNEL",
    "M                NEXT MODE OF THE KERNEL",
    "F                SCENE EFFECTS ON/OFF",
    "T                THREAD COUNT",
    "P                PAUSE",
    "CTRL+S / F12     SAVE FRAME .PNG + .SCENE",
    "O                OVERLAY ON/OFF",
    "H                THIS HELP",
    "ESC              QUIT",
};
const size_t view_help_count = sizeof view_help_lines / sizeof view_help_lines[0];

int view_is_motion(view_action a)
{
    return a >= VA_FORWARD && a <= VA_DOWN;
}

view_motion view_motion_of(const unsigned char held[VA_COUNT])
{
    view_motion m;
    m.v = (held[VA_FORWARD] ? VIEW_SPEED : 0) - (held[VA_BACK] ? VIEW_SPEED : 0);
    m.v_angular = (held[VA_LEFT] ? VIEW_TURN : 0) - (held[VA_RIGHT] ? VIEW_TURN : 0);
    m.v_height = (held[VA_UP] ? VIEW_CLIMB : 0) - (held[VA_DOWN] ? VIEW_CLIMB : 0);
    return m;
}

int view_key_parse(const char *name, size_t len, view_action *a)
{
    for (size_t i = 0; i < sizeof NAMES / sizeof NAMES[0]; i++)
        if (strlen(NAMES[i].name) == len && !memcmp(NAMES[i].name, name, len)) {
            *a = NAMES[i].a;
            return 0;
        }
    return -1;
}

/* The repeat count after '*': digits only, 1..VIEW_SCRIPT_MAX_FRAMES. */
static long parse_count(const char *s, size_t len)
{
    long n = 0;
    if (!len || len > 7)
        return -1;
    for (size_t i = 0; i < len; i++) {
        if (s[i] < '0' || s[i] > '9')
            return -1;
        n = n * 10 + (s[i] - '0');
    }
    return n >= 1 && n <= VIEW_SCRIPT_MAX_FRAMES ? n : -1;
}

int view_script_parse(const char *s, view_script *out, char *err, size_t errlen)
{
    out->frames = NULL;
    out->n = 0;
    size_t cap = 0;
    for (const char *p = s;;) {
        const char *end = strchr(p, ',');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        const char *star = memchr(p, '*', len);
        size_t nlen = star ? (size_t)(star - p) : len;
        view_action a;
        long count = star ? parse_count(star + 1, len - nlen - 1) : 1;
        if (!nlen || view_key_parse(p, nlen, &a)) {
            snprintf(err, errlen, "unknown key '%.*s' in the key script (retro view --help lists them)",
                     (int)(nlen > 40 ? 40 : nlen), p);
            goto fail;
        }
        if (count < 0) {
            snprintf(err, errlen, "bad repeat count in '%.*s' in the key script (KEY*N, N from 1 to %d)",
                     (int)(len > 40 ? 40 : len), p, VIEW_SCRIPT_MAX_FRAMES);
            goto fail;
        }
        if (out->n + (size_t)count > VIEW_SCRIPT_MAX_FRAMES) {
            snprintf(err, errlen, "key script longer than %d frames", VIEW_SCRIPT_MAX_FRAMES);
            goto fail;
        }
        if (out->n + (size_t)count > cap) {
            size_t ncap = cap ? cap : 64;
            while (ncap < out->n + (size_t)count)
                ncap *= 2;
            view_action *f = realloc(out->frames, ncap * sizeof *f);
            if (!f) {
                snprintf(err, errlen, "out of memory for the key script");
                goto fail;
            }
            out->frames = f;
            cap = ncap;
        }
        for (long i = 0; i < count; i++)
            out->frames[out->n++] = a;
        if (!end)
            return 0;
        p = end + 1;
    }
fail:
    if (errlen) /* the quoted key may hold a newline */
        retro_one_line(err);
    view_script_free(out);
    return -1;
}

void view_script_free(view_script *s)
{
    free(s->frames);
    s->frames = NULL;
    s->n = 0;
}
