/* The strip table (strips.h) and the one choice of a frame's strip. */
#include "strips.h"

#define RETRO_STRIP_ROW_(id, lvl, m, f, func)                                                      \
    {.name = #id, .level = RETRO_ISA_##lvl, .cpu = RETRO_ISA_CPU_##lvl, .modes = (m), .fx = (f), .fn = func},
const retro_strip retro_strips[RETRO_STRIP_COUNT] = {RETRO_STRIPS(RETRO_STRIP_ROW_)};
#undef RETRO_STRIP_ROW_

retro_strip_fn retro_strip_best(retro_mode mode, unsigned fx)
{
    unsigned cpu = retro_cpu_features();
    retro_strip_fn best = retro_strips[0].fn;
    for (int i = 0; i < RETRO_STRIP_COUNT; i++) {
        const retro_strip *s = &retro_strips[i];
        if ((s->cpu & cpu) == s->cpu && (s->modes & RETRO_MODE_BIT(mode)) && !(fx & ~s->fx))
            best = s->fn;
    }
    return best;
}
