/* Baked effects (docs/EFFECTS.md): morph, shade and water rewrite the maps once per change of
 * their inputs, into maps a context holds (effects_bake.h), so the frame reads ready-made cells
 * and a kernel's inner loop never pays for them. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "effects_bake.h"
#include "retro.h"
#include "retro_scene.h"

static void morph(const uint8_t *h0, const uint8_t *h1, int T, uint8_t *out, size_t n)
{
    for (size_t i = 0; i < n; i++)
        out[i] = (uint8_t)((h0[i] * (256 - T) + h1[i] * T + 128) >> 8);
}

static uint32_t scale(uint32_t c, float light)
{
    uint32_t out = 0;
    for (int sh = 8; sh <= 24; sh += 8) {
        int v = (int)((float)((c >> sh) & 255) * light + 0.5f);
        out |= (uint32_t)(v > 255 ? 255 : v) << sh;
    }
    return out;
}

static void shade(const retro_effects *fx, const uint8_t *h, const uint32_t *c, uint32_t *out, int S)
{
    for (int j = 0; j < S; j++) {
        const uint8_t *up = h + (size_t)((j + S - 1) % S) * (size_t)S;
        const uint8_t *row = h + (size_t)j * (size_t)S, *down = h + (size_t)((j + 1) % S) * (size_t)S;
        for (int i = 0; i < S; i++) {
            int l = (i + S - 1) % S, r = (i + 1) % S;
            float gx = (float)(row[r] - row[l]) * 0.5f, gy = (float)(down[i] - up[i]) * 0.5f;
            float len = sqrtf(gx * gx + gy * gy + 1.0f);
            float dot = ((-gx) * fx->sun[0] + (-gy) * fx->sun[1] + fx->sun[2]) / len;
            float light = fx->ambient + fx->diffuse * (dot > 0.0f ? dot : 0.0f);
            size_t at = (size_t)j * (size_t)S + (size_t)i;
            out[at] = scale(c[at], light);
        }
    }
}

static void water(const retro_effects *fx, uint8_t *h, uint32_t *c, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        if (h[i] >= fx->water_level)
            continue;
        float a = fx->water_alpha0 + fx->water_alpha_per_unit * (float)(fx->water_level - h[i]);
        a = a < 1.0f ? a : 1.0f;
        uint32_t out = 0;
        for (int sh = 8; sh <= 24; sh += 8) {
            float w = (float)((fx->water_color >> sh) & 255) * a; /* premultiplied */
            int v = (int)(w + (float)((c[i] >> sh) & 255) * (1.0f - a) + 0.5f);
            out |= (uint32_t)(v > 255 ? 255 : v < 0 ? 0 : v) << sh;
        }
        c[i] = out;
        h[i] = (uint8_t)fx->water_level;
    }
}

int retro_effects_bake(retro_fx_bake *b, const retro_effects *fx, const uint8_t *h0, const uint32_t *c0, int S)
{
    retro_fx_bake_key key;
    memset(&key, 0, sizeof key);
    key.h0 = h0;
    key.c0 = c0;
    key.S = S;
    key.flags = fx->flags & (RETRO_FX_MORPH | RETRO_FX_SHADE | RETRO_FX_WATER);
    if (key.flags & RETRO_FX_MORPH) {
        key.h1 = fx->morph_height;
        float t = fx->morph_t < 0 ? 0 : fx->morph_t > 1 ? 1 : fx->morph_t;
        key.T = (int)(t * 256.0f + 0.5f);
    }
    if (key.flags & RETRO_FX_SHADE) {
        memcpy(key.sun, fx->sun, sizeof key.sun);
        key.ambient = fx->ambient;
        key.diffuse = fx->diffuse;
    }
    if (key.flags & RETRO_FX_WATER) {
        key.level = fx->water_level;
        key.water = fx->water_color;
        key.alpha0 = fx->water_alpha0;
        key.alpha_per_unit = fx->water_alpha_per_unit;
    }
    if (b->have_key && !memcmp(&b->key, &key, sizeof key))
        return 0;
    size_t n = (size_t)S * (size_t)S;
    if (n > b->cap) {
        uint8_t *h = realloc(b->height, n);
        if (h)
            b->height = h;
        uint32_t *c = realloc(b->color, n * sizeof *c);
        if (c)
            b->color = c;
        if (!h || !c)
            return -1;
        b->cap = n;
    }
    if (key.flags & RETRO_FX_MORPH)
        morph(h0, key.h1, key.T, b->height, n);
    else
        memcpy(b->height, h0, n);
    if (key.flags & RETRO_FX_SHADE)
        shade(fx, b->height, c0, b->color, S);
    else
        memcpy(b->color, c0, n * sizeof *c0);
    if (key.flags & RETRO_FX_WATER)
        water(fx, b->height, b->color, n);
    memcpy(&b->key, &key, sizeof key); /* padding too: compared with memcmp */
    b->have_key = 1;
    return 1;
}

void retro_effects_bake_stale(retro_fx_bake *b)
{
    b->have_key = 0;
}

void retro_effects_bake_free(retro_fx_bake *b)
{
    free(b->height);
    free(b->color);
    memset(b, 0, sizeof *b);
}

void retro_fog_table(const retro_effects *fx, uint16_t *fog, int D)
{
    for (int d = 1; d < D; d++) {
        float f;
        if (fx->fog_exp)
            f = 1.0f - expf(-fx->fog_density * (float)d);
        else if (fx->fog_end > fx->fog_start)
            f = ((float)d - fx->fog_start) / (fx->fog_end - fx->fog_start);
        else
            f = (float)d >= fx->fog_start ? 1.0f : 0.0f;
        f = f < 0.0f ? 0.0f : f > 1.0f ? 1.0f : f;
        fog[d] = (uint16_t)(int)(f * 256.0f + 0.5f);
    }
}

static int in(float v, float lo, float hi)
{
    return v >= lo && v <= hi; /* false for NaN */
}

int retro_effects_valid(const retro_effects *fx)
{
    unsigned f = fx->flags;
    if ((f & RETRO_FX_FOG) && !(fx->fog_exp ? in(fx->fog_density, 1e-30f, RETRO_FX_FOG_DENSITY_MAX)
                                            : in(fx->fog_start, 0, RETRO_FX_FOG_DIST_MAX) &&
                                                  in(fx->fog_end, 0, RETRO_FX_FOG_DIST_MAX)))
        return 0;
    if (f & RETRO_FX_SHADE) {
        float len2 = fx->sun[0] * fx->sun[0] + fx->sun[1] * fx->sun[1] + fx->sun[2] * fx->sun[2];
        if (!in(len2, 0.99f, 1.01f) || !in(fx->ambient, 0, RETRO_FX_SHADE_GAIN_MAX) ||
            !in(fx->diffuse, 0, RETRO_FX_SHADE_GAIN_MAX))
            return 0;
    }
    if ((f & RETRO_FX_WATER) && !(fx->water_level >= 0 && fx->water_level <= RETRO_FX_WATER_LEVEL_MAX &&
                                  in(fx->water_alpha0, 0, 1) &&
                                  in(fx->water_alpha_per_unit, 0, 1)))
        return 0;
    if ((f & RETRO_FX_HORIZON) && (fx->pitch < -RETRO_MAX_SCREEN || fx->pitch > RETRO_MAX_SCREEN))
        return 0;
    if ((f & RETRO_FX_MORPH) && (!fx->morph_height || !in(fx->morph_t, 0, 1)))
        return 0;
    return 1;
}
