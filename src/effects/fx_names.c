/* Effect names, as scene files, `retro kernels` and refusals spell them (docs/EFFECTS.md). */
#include "retro.h"
#include "retro_scene.h"

const char *retro_fx_name(unsigned bit)
{
    static const char *const names[] = {"fog", "shade", "water", "bilinear", "lod", "horizon", "morph",
                                         "texture", "gouraud", "wireframe", "cull"};
    for (unsigned i = 0; i < sizeof names / sizeof names[0]; i++)
        if (bit == 1u << i)
            return names[i];
    return "?";
}
