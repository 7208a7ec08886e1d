/* An independent implementation of mode exact, written from SEMANTICS.md alone (it shares no
 * code with src/): if it and naive agree on poses neither was tuned on, both read the
 * specification the same way. */
#ifndef RETRO_REF_EXACT_H
#define RETRO_REF_EXACT_H

#include <stddef.h>

#include "render.h"

void ref_exact_render(const player_t *p, ctx_t *c);

/* SEMANTICS.md steps 1-2: the view direction by quadrant and the position reduced mod S. */
typedef struct {
    float cs, sn, x0, y0;
} ref_view;
ref_view ref_exact_view(const player_t *p, int S);
/* Steps 3-5: the row-major index of the cell mode exact reads for column u (1-based) at
 * distance d. */
size_t ref_exact_cell(const ref_view *v, int W, int S, int u, int d);

#endif
