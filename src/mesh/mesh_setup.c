/* Frame setup of the mesh family: validation, camera constants, effect parameters. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "direction.h"
#include "mesh_internal.h"
#include "retro.h"

static retro_mesh_err fail(retro_mesh_ctx *mc, retro_mesh_err e, const char *msg)
{
    snprintf(mc->err, sizeof mc->err, "%s", msg);
    return e;
}

static int in(double v, double lo, double hi)
{
    return v >= lo && v <= hi; /* false for NaN */
}

/* The ranges of docs/EFFECTS.md (the voxel family's frame setup enforces the same). */
static const char *effects_invalid(const retro_effects *fx)
{
    unsigned f = fx->flags;
    if ((f & RETRO_FX_FOG) && !(fx->fog_exp ? in(fx->fog_density, 1e-30, 1.0)
                                            : in(fx->fog_start, 0, 1e7) && in(fx->fog_end, 0, 1e7)))
        return "fog parameters out of range";
    if (f & RETRO_FX_SHADE) {
        float len2 = fx->sun[0] * fx->sun[0] + fx->sun[1] * fx->sun[1] + fx->sun[2] * fx->sun[2];
        if (!in(len2, 0.99, 1.01) || !in(fx->ambient, 0, 4) || !in(fx->diffuse, 0, 4))
            return "shade parameters out of range";
    }
    if ((f & RETRO_FX_WATER) && !(fx->water_level >= 0 && fx->water_level <= 255 &&
                                  in(fx->water_alpha0, 0, 1) && in(fx->water_alpha_per_unit, 0, 1)))
        return "water parameters out of range";
    if ((f & RETRO_FX_HORIZON) && (fx->pitch < -RETRO_MAX_SCREEN || fx->pitch > RETRO_MAX_SCREEN))
        return "horizon pitch out of range";
    if ((f & RETRO_FX_MORPH) && (!fx->morph_height || !in(fx->morph_t, 0, 1)))
        return "morph needs a second keyframe and t in [0, 1]";
    return NULL;
}

unsigned retro_mesh_supported_fx(retro_mesh_kernel kernel, retro_mesh_mode mode)
{
    (void)mode;
    unsigned all = RETRO_FX_FOG | RETRO_FX_SHADE | RETRO_FX_WATER | RETRO_FX_HORIZON | RETRO_FX_MORPH;
    /* Without a depth buffer, water drawn after the terrain would cover terrain in front of it. */
    return kernel == RETRO_MESH_PAINTER ? all & ~(unsigned)RETRO_FX_WATER : all;
}

unsigned retro_mesh_supported_mesh_fx(retro_mesh_kernel kernel, retro_mesh_mode mode)
{
    (void)kernel;
    (void)mode;
    return RETRO_MESH_FX_ALL;
}

int retro_mesh_supports_mode(retro_mesh_kernel kernel, retro_mesh_mode mode)
{
    if ((unsigned)kernel >= RETRO_MESH_KERNEL_COUNT || (unsigned)mode >= RETRO_MESH_MODE_COUNT)
        return 0;
    return kernel <= RETRO_MESH_PAINTER || mode == RETRO_MESH_BINARY32;
}

unsigned retro_mesh_kernel_isa(retro_mesh_kernel kernel)
{
    switch (kernel) {
    case RETRO_MESH_AVX2: return RETRO_CPU_AVX2;
    case RETRO_MESH_AVX512: return RETRO_CPU_AVX512;
    case RETRO_MESH_OMP: return RETRO_CPU_AVX2;
    default: return 0;
    }
}

static const char *isa_name(unsigned isa)
{
    return (isa & RETRO_CPU_AVX512) ? "AVX-512 (F, BW, VL, DQ)" : (isa & RETRO_CPU_AVX2) ? "AVX2" : "SSE2";
}

static const char *const fx_names[] = {"fog", "shade", "water", "bilinear", "lod", "horizon", "morph"};

/* Every frame reads the whole map here: per-position minima and maxima over chunks of fixed
 * length, which the compiler turns into byte-vector operations, reduced once at the end. */
static void minmax(const uint8_t *h, size_t n, double *lo, double *hi)
{
    enum { CH = 32 };
    uint8_t va[CH], vb[CH];
    memset(va, 255, sizeof va);
    memset(vb, 0, sizeof vb);
    size_t i = 0;
    for (; i + CH <= n; i += CH)
        for (size_t k = 0; k < CH; k++) {
            va[k] = h[i + k] < va[k] ? h[i + k] : va[k];
            vb[k] = h[i + k] > vb[k] ? h[i + k] : vb[k];
        }
    uint8_t a = 255, b = 0;
    for (size_t k = 0; k < CH; k++) {
        a = va[k] < a ? va[k] : a;
        b = vb[k] > b ? vb[k] : b;
    }
    for (; i < n; i++) {
        a = h[i] < a ? h[i] : a;
        b = h[i] > b ? h[i] : b;
    }
    *lo = a < *lo ? a : *lo;
    *hi = b > *hi ? b : *hi;
}

/* Mode int's fog: the binary32 weights of docs/EFFECTS.md at integer depths 0..far. */
static int fog_table(retro_mesh_ctx *mc, const retro_effects *fx, int far)
{
    size_t n = (size_t)far + 1;
    if (n > mc->fogtab_cap) {
        uint16_t *t = realloc(mc->fogtab, n * sizeof *t);
        if (!t)
            return -1;
        mc->fogtab = t;
        mc->fogtab_cap = n;
    }
    for (int d = 0; d <= far; d++) {
        float fw;
        if (fx->fog_exp)
            fw = 1.0f - expf(-fx->fog_density * (float)d);
        else if (fx->fog_end > fx->fog_start)
            fw = ((float)d - fx->fog_start) / (fx->fog_end - fx->fog_start);
        else
            fw = (float)d >= fx->fog_start ? 1.0f : 0.0f;
        fw = fw < 0.0f ? 0.0f : fw > 1.0f ? 1.0f : fw;
        mc->fogtab[d] = (uint16_t)(int)(fw * 256.0f + 0.5f);
    }
    return 0;
}

retro_mesh_err mesh_frame_setup(retro_mesh_ctx *mc, retro_mesh_kernel k, retro_mesh_mode mode,
                                const player_t *p, const ctx_t *c, const retro_effects *fx,
                                unsigned mfx)
{
    if (!p || !c || !c->height_map || !c->color_map || !c->out)
        return fail(mc, RETRO_MESH_EINVAL, "missing player, context or map");
    if ((unsigned)k >= RETRO_MESH_KERNEL_COUNT || (unsigned)mode >= RETRO_MESH_MODE_COUNT)
        return fail(mc, RETRO_MESH_EINVAL, "unknown mesh kernel or mode");
    if (!retro_mesh_supports_mode(k, mode)) {
        snprintf(mc->err, sizeof mc->err, "kernel mesh-%s does not render mode %s",
                 retro_mesh_kernel_name(k), retro_mesh_mode_name(mode));
        return RETRO_MESH_EUNSUPPORTED;
    }
    unsigned need = retro_mesh_kernel_isa(k);
    if (need & ~retro_cpu_features()) {
        snprintf(mc->err, sizeof mc->err, "kernel mesh-%s needs %s, which this CPU (or RETRO_ISA) lacks",
                 retro_mesh_kernel_name(k), isa_name(need & ~retro_cpu_features()));
        return RETRO_MESH_EUNSUPPORTED;
    }
    int W = c->scr_width, H = c->scr_height, S = c->map_size;
    if (W < 1 || H < 1 || W > RETRO_MAX_SCREEN || H > RETRO_MAX_SCREEN || (long)W * H > RETRO_MAX_PIXELS)
        return fail(mc, RETRO_MESH_EINVAL, "screen size out of range");
    if (S < 1 || S > RETRO_MAX_MAP)
        return fail(mc, RETRO_MESH_EINVAL, "map size out of range");
    if (c->distance > RETRO_MAX_DISTANCE || !isfinite(p->x) || !isfinite(p->y))
        return fail(mc, RETRO_MESH_EINVAL, "distance or position out of range");
    unsigned flags = fx ? fx->flags : 0;
    if (flags & ~(unsigned)RETRO_FX_ALL)
        return fail(mc, RETRO_MESH_EINVAL, "unknown effect flag");
    /* A scene's mesh-only effects are the same bits as the options' (retro_scene.h); `cull`
     * is the default here, and the options' nocull turns it off. */
    mfx |= flags & (RETRO_FX_MESH_ONLY & ~(unsigned)RETRO_FX_CULL);
    flags &= ~(unsigned)RETRO_FX_MESH_ONLY;
    if (mfx & ~(unsigned)RETRO_MESH_FX_ALL)
        return fail(mc, RETRO_MESH_EINVAL, "unknown mesh effect flag");
    if ((mfx & RETRO_MESH_FX_TEXTURE) && (mfx & RETRO_MESH_FX_GOURAUD))
        return fail(mc, RETRO_MESH_EINVAL, "texture and gouraud are exclusive colour sources");
    unsigned refused = flags & ~retro_mesh_supported_fx(k, mode);
    for (unsigned b = 0; refused && b < sizeof fx_names / sizeof *fx_names; b++)
        if (refused & (1u << b)) {
            snprintf(mc->err, sizeof mc->err, "kernel mesh-%s does not render effect %s",
                     retro_mesh_kernel_name(k), fx_names[b]);
            return RETRO_MESH_EUNSUPPORTED;
        }
    const char *bad = flags ? effects_invalid(fx) : NULL;
    if (bad)
        return fail(mc, RETRO_MESH_EINVAL, bad);

    mesh_frame *f = &mc->f;
    memset(f, 0, sizeof *f);
    /* The fast kernels draw the z-buffer's image through its order and output stage. */
    f->kernel = k == RETRO_MESH_PAINTER ? RETRO_MESH_PAINTER : RETRO_MESH_ZBUFFER;
    f->fast = k == RETRO_MESH_AVX2     ? MESH_FAST_AVX2
              : k == RETRO_MESH_AVX512 ? MESH_FAST_AVX512
              : k == RETRO_MESH_OMP    ? ((retro_cpu_features() & RETRO_CPU_AVX512) ? MESH_FAST_AVX512 : MESH_FAST_AVX2)
                                       : MESH_FAST_NONE;
    f->mode = mode;
    f->f32 = mode == RETRO_MESH_BINARY32;
    f->W = W;
    f->H = H;
    f->S = S;
    int far = c->distance < RETRO_MESH_MAX_FAR ? c->distance : RETRO_MESH_MAX_FAR;
    f->far = far < 1 ? 1 : far;
    f->sky = c->sky_color;
    f->h0 = c->height_map;
    f->h1 = (flags & RETRO_FX_MORPH) ? fx->morph_height : NULL;
    f->morph_t = f->h1 ? rn(f, fx->morph_t) : 0;
    f->color = c->color_map;
    f->height = p->height;
    f->fx = flags;
    f->mfx = mfx;
    f->fxp = fx;
    double cs, sn;
    retro_direction(p->angle, &cs, &sn);
    f->cs = rn(f, cs);
    f->sn = rn(f, sn);
    double x0 = fmod((double)p->x, (double)S), y0 = fmod((double)p->y, (double)S);
    f->x0 = rn(f, x0 < 0 ? x0 + S : x0);
    f->y0 = rn(f, y0 < 0 ? y0 + S : y0);
    /* rounding x0 + S may give S itself: the eye square is then the first of the next period */
    f->kx = W > 1 ? 0.5 * (W - 1) : 0.5;
    f->cx = 0.5 * (W - 1);
    f->ky = 0.5 * W;
    f->cy = 0.5 * H + ((flags & RETRO_FX_HORIZON) ? fx->pitch : 0);
    f->cl = f->cx + 0.5;
    f->cr = W - 0.5 - f->cx;
    f->cb = f->cy - 0.5;
    f->ct = H + 0.5 - f->cy;
    f->rlo = 1;
    f->rhi = H;
    f->bcb = f->cb;
    f->bct = f->ct;
    f->hmin = 255;
    f->hmax = 0;
    minmax(f->h0, (size_t)S * (size_t)S, &f->hmin, &f->hmax);
    if (f->h1)
        minmax(f->h1, (size_t)S * (size_t)S, &f->hmin, &f->hmax);
    if (flags & RETRO_FX_SHADE) {
        for (int i = 0; i < 3; i++)
            f->sun[i] = fx->sun[i];
        f->ambient = fx->ambient;
        f->diffuse = fx->diffuse;
    }
    if (flags & RETRO_FX_FOG) {
        f->fog_exp = fx->fog_exp;
        f->fog_start = fx->fog_start;
        f->fog_end = fx->fog_end;
        f->fog_density = fx->fog_density;
        if (mode == RETRO_MESH_INT && fog_table(mc, fx, far < 1 ? 1 : far))
            return fail(mc, RETRO_MESH_ENOMEM, "out of memory");
        f->fogtab = mc->fogtab;
    }
    if (flags & RETRO_FX_WATER) {
        f->level = fx->water_level;
        f->water_color = fx->water_color;
        f->alpha0 = fx->water_alpha0;
        f->alpha_per_unit = fx->water_alpha_per_unit;
        /* block culling bounds the water plane too */
        f->hmin = f->level < f->hmin ? f->level : f->hmin;
        f->hmax = f->level > f->hmax ? f->level : f->hmax;
    }
    f->Ie = (int)floor(f->x0 - 0.5);
    f->Je = (int)floor(f->y0 - 0.5);
    return RETRO_MESH_OK;
}
