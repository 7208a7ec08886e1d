/* retro view's SDL-free parts: the key script parser, held keys to update_player velocities,
 * the built-in font, the frame-time median and the overlay text drawing. */
#include <criterion/criterion.h>
#include <string.h>

#include "cli/view_font.h"
#include "cli/view_keys.h"
#include "cli/view_overlay.h"

static char err[256];

Test(view_keys, script_expands_repeats_in_order)
{
    view_script s;
    cr_assert_eq(view_script_parse("w*3,tab,shift+tab,ctrl+s,f12,none,esc,-,+*2", &s, err, sizeof err), 0, "%s", err);
    const view_action want[] = {VA_FORWARD, VA_FORWARD, VA_FORWARD, VA_KERNEL_NEXT, VA_KERNEL_PREV,
                                VA_SAVE, VA_SAVE, VA_NONE, VA_QUIT, VA_NEAR, VA_FAR, VA_FAR};
    cr_assert_eq(s.n, sizeof want / sizeof want[0]);
    for (size_t i = 0; i < s.n; i++)
        cr_assert_eq(s.frames[i], want[i], "frame %zu", i);
    view_script_free(&s);
    cr_assert_null(s.frames);
}

Test(view_keys, every_name_of_the_help_parses)
{
    const char *names[] = {"w", "s", "a", "d", "q", "e", "up", "down", "left", "right", "pageup",
                           "pagedown", "plus", "minus", "tab", "shift+tab", "m", "f", "t", "p",
                           "o", "h", "ctrl+s", "f12", "esc", "none"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        view_action a;
        cr_assert_eq(view_key_parse(names[i], strlen(names[i]), &a), 0, "%s", names[i]);
    }
}

Test(view_keys, bad_scripts_are_refused_with_a_reason)
{
    const char *bad[] = {"", ",", "w,", ",w", "w*0", "w*", "w*1x", "w**2", "W", "jump", "w*-1",
                         "w* 2", " w", "w*1000001", "w*600000,a*600000", "tab*", "s*99999999",
                         "w\n*3", "a,w*9\ny"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        view_script s = {NULL, 0};
        err[0] = 0;
        cr_assert_eq(view_script_parse(bad[i], &s, err, sizeof err), -1, "'%s' accepted", bad[i]);
        cr_assert_null(s.frames, "'%s'", bad[i]);
        cr_assert(strstr(err, "key script"), "'%s': %s", bad[i], err);
        cr_assert_null(strchr(err, '\n'), "'%s': the reason is more than one line", bad[i]);
    }
}

Test(view_keys, held_keys_give_the_documented_velocities)
{
    unsigned char held[VA_COUNT] = {0};
    view_motion m = view_motion_of(held);
    cr_assert(m.v == 0 && m.v_angular == 0 && m.v_height == 0);
    held[VA_FORWARD] = held[VA_LEFT] = held[VA_DOWN] = 1;
    m = view_motion_of(held);
    cr_assert(m.v == VIEW_SPEED && m.v_angular == VIEW_TURN && m.v_height == -VIEW_CLIMB);
    held[VA_BACK] = held[VA_RIGHT] = held[VA_UP] = 1; /* opposite keys cancel */
    m = view_motion_of(held);
    cr_assert(m.v == 0 && m.v_angular == 0 && m.v_height == 0);
    for (int a = 0; a < VA_COUNT; a++)
        cr_assert_eq(view_is_motion((view_action)a), a >= VA_FORWARD && a <= VA_DOWN);
}

Test(view_font, table_is_well_formed_and_case_folded)
{
    cr_assert(view_font_check());
    uint8_t a[VIEW_FONT_H], b[VIEW_FONT_H], q[VIEW_FONT_H], sp[VIEW_FONT_H];
    for (char c = 'a'; c <= 'z'; c++) {
        view_font_glyph(c, a);
        view_font_glyph((char)(c - 'a' + 'A'), b);
        cr_assert_eq(memcmp(a, b, sizeof a), 0, "%c", c);
    }
    view_font_glyph('?', q);
    view_font_glyph('~', a);
    cr_assert_eq(memcmp(a, q, sizeof a), 0);
    view_font_glyph((char)200, a);
    cr_assert_eq(memcmp(a, q, sizeof a), 0);
    view_font_glyph(' ', sp);
    for (int r = 0; r < VIEW_FONT_H; r++)
        cr_assert_eq(sp[r], 0);
    /* every visible glyph lights something, and no two glyphs of 33..95 are the same */
    for (int c = 33; c <= 95; c++) {
        view_font_glyph((char)c, a);
        int lit = 0;
        for (int r = 0; r < VIEW_FONT_H; r++)
            lit |= a[r];
        cr_assert(lit, "'%c' is blank", c);
        for (int d = c + 1; d <= 95; d++) {
            view_font_glyph((char)d, b);
            cr_assert_neq(memcmp(a, b, sizeof a), 0, "'%c' and '%c' look the same", c, d);
        }
    }
}

Test(view_overlay, median_of_the_last_30)
{
    view_timing t = {{0}, 0, 0};
    cr_assert_eq(view_timing_median(&t), 0.0);
    view_timing_add(&t, 5);
    view_timing_add(&t, 1);
    view_timing_add(&t, 3);
    cr_assert_eq(view_timing_median(&t), 3.0);
    view_timing_add(&t, 10);
    cr_assert_eq(view_timing_median(&t), 4.0);
    view_timing t2 = {{0}, 0, 0};
    for (int i = 40; i >= 1; i--) /* keeps 30 down to 1 */
        view_timing_add(&t2, i);
    cr_assert_eq(t2.n, VIEW_TIMING_N);
    cr_assert_eq(view_timing_median(&t2), 15.5);
}

Test(view_overlay, text_is_yellow_on_a_darkened_box)
{
    enum { W = 40, H = 20 };
    uint32_t f[W * H];
    for (int i = 0; i < W * H; i++)
        f[i] = 0xfffefd00u;
    const char *lines[] = {"I"};
    view_draw_text(f, W, H, 1, lines, 1);
    uint8_t g[VIEW_FONT_H];
    view_font_glyph('I', g);
    int want = 0, yellow = 0, dark = 0, untouched = 0;
    for (int r = 0; r < VIEW_FONT_H; r++)
        want += __builtin_popcount(g[r]);
    for (int i = 0; i < W * H; i++) {
        yellow += f[i] == VIEW_TEXT_COLOR;
        dark += f[i] == 0x7f7f7e00u;
        untouched += f[i] == 0xfffefd00u;
    }
    cr_assert_eq(yellow, want);
    /* box: 3 px padding around one 6 x 9 cell */
    cr_assert_eq(yellow + dark, (6 + 6) * (9 + 6));
    cr_assert_eq(untouched, W * H - (6 + 6) * (9 + 6));
    /* a frame smaller than the box is clipped, not overrun */
    uint32_t tiny[3 * 2] = {0};
    view_draw_text(tiny, 3, 2, 2, lines, 1);
}
