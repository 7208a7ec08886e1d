/* retro view's built-in 5x7 font: ASCII 32..95 drawn for this program; lower case is shown in
 * upper case and any other byte as '?'. */
#ifndef RETRO_CLI_VIEW_FONT_H
#define RETRO_CLI_VIEW_FONT_H

#include <stdint.h>

#define VIEW_FONT_W 5
#define VIEW_FONT_H 7
/* Advance per character and per line, in font pixels (one column and two rows of spacing). */
#define VIEW_FONT_ADVANCE 6
#define VIEW_FONT_LINE 9

/* Rows of character c, top first; bit 4 is the leftmost column. */
void view_font_glyph(char c, uint8_t rows[VIEW_FONT_H]);
/* Whether every glyph of the table is well formed (for the tests). */
int view_font_check(void);

#endif
