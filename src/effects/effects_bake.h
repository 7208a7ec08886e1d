/* Baked effects (docs/EFFECTS.md): morph, shade and water rewrite the maps once per change of
 * their inputs into maps a context owns; effects_bake.c builds them and owns this state. */
#ifndef RETRO_EFFECTS_BAKE_H
#define RETRO_EFFECTS_BAKE_H

#include <stddef.h>
#include <stdint.h>

struct retro_effects;

/* Everything a bake depends on; equal keys mean the baked maps are still valid. */
typedef struct retro_fx_bake_key {
    const uint8_t *h0, *h1;
    const uint32_t *c0;
    int S, T;
    unsigned flags;
    float sun[3], ambient, diffuse;
    int level;
    uint32_t water;
    float alpha0, alpha_per_unit;
} retro_fx_bake_key;

/* The baked maps of one context (retro_ctx.bake). All zero is empty. */
typedef struct retro_fx_bake {
    uint8_t *height;  /* capacity cap cells */
    uint32_t *color;
    size_t cap;
    int have_key;     /* key holds the inputs height and color were made from */
    retro_fx_bake_key key;
} retro_fx_bake;

/* Bakes morph, shade and water of fx over the maps (h0, c0) of size S into b unless b is
 * current. Returns 0 when b was current, 1 when it was baked again (the same pointers now
 * hold new cells: caches keyed by map pointer must rebuild), -1 when out of memory. */
int retro_effects_bake(retro_fx_bake *b, const struct retro_effects *fx, const uint8_t *h0, const uint32_t *c0,
                       int S);
/* The next bake rebuilds (a source map was edited in place). */
void retro_effects_bake_stale(retro_fx_bake *b);
void retro_effects_bake_free(retro_fx_bake *b);
/* Whether fx's parameters are in the ranges docs/EFFECTS.md gives (the scene parser enforces
 * the same); outside them a float-to-int conversion in the bake or the fog table could
 * overflow. NaN is out of every range. */
int retro_effects_valid(const struct retro_effects *fx);
/* Fog weights F_d (0..256) for d = 1..D-1. */
void retro_fog_table(const struct retro_effects *fx, uint16_t *fog, int D);

#endif
