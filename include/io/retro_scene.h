/* Scenes and effects: a scene file names a map, a camera (or a fly-through path), a screen and
 * the effects it calls for; only those are simulated (docs/EFFECTS.md defines each one). */
#ifndef RETRO_SCENE_H
#define RETRO_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "render.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    RETRO_FX_FOG = 1u << 0,      /* blend toward the sky with distance (per sample) */
    RETRO_FX_SHADE = 1u << 1,    /* Lambert lighting baked into the colour map */
    RETRO_FX_WATER = 1u << 2,    /* a water plane baked into both maps */
    RETRO_FX_BILINEAR = 1u << 3, /* bilinear height and colour (per sample) */
    RETRO_FX_LOD = 1u << 4,      /* distance step growing with distance (mode lod) */
    RETRO_FX_HORIZON = 1u << 5,  /* pitch as a horizon offset (a frame constant) */
    RETRO_FX_MORPH = 1u << 6,    /* blend between two height keyframes (baked per time t) */
    /* mesh-only effects (docs/MESH.md): the voxel family refuses them */
    RETRO_FX_TEXTURE = 1u << 7,   /* colour map as a texture, bilinear between vertices */
    RETRO_FX_GOURAUD = 1u << 8,   /* vertex colours interpolated */
    RETRO_FX_WIREFRAME = 1u << 9, /* only the pixels along triangle edges */
    RETRO_FX_CULL = 1u << 10,     /* back faces culled (without it both sides are drawn) */
    RETRO_FX_VOXEL = (1u << 7) - 1, /* the voxel family's effects */
    RETRO_FX_MESH_ONLY = RETRO_FX_TEXTURE | RETRO_FX_GOURAUD | RETRO_FX_WIREFRAME | RETRO_FX_CULL,
    RETRO_FX_MESH = RETRO_FX_FOG | RETRO_FX_SHADE | RETRO_FX_WATER | RETRO_FX_HORIZON | RETRO_FX_MORPH |
                    RETRO_FX_MESH_ONLY, /* the mesh family's effects */
    RETRO_FX_ALL = (1u << 11) - 1
};
/* Effects that need code in a kernel's inner loop; the others change only frame constants or
 * the maps the frame reads, so every kernel renders them. */
#define RETRO_FX_PER_SAMPLE (RETRO_FX_FOG | RETRO_FX_BILINEAR)

typedef struct retro_effects {
    unsigned flags;            /* RETRO_FX_* the scene calls for */
    /* fog: factor f(d) = clamp((d - start) / (end - start), 0, 1), or 1 - exp(-density * d) */
    int fog_exp;
    float fog_start, fog_end, fog_density;
    /* shade: light = ambient + diffuse * max(0, n . sun) with sun a direction (normalised) */
    float sun[3];
    float ambient, diffuse;
    /* water: a plane at level; opacity alpha0 at the surface plus alpha_per_unit per unit of
     * depth, clamped to 1 */
    int water_level;
    uint32_t water_color;      /* R<<24 | G<<16 | B<<8 */
    float water_alpha0, water_alpha_per_unit;
    /* horizon: rows the horizon moves up (positive pitch looks down) */
    int pitch;
    /* morph: heights h0 + (h1 - h0) * t between the map's heights and morph_height */
    const uint8_t *morph_height; /* S*S, the second keyframe */
    float morph_t;             /* 0..1 */
} retro_effects;

/* The valid ranges of the parameters, stated once: the library refuses effects outside them
 * (RETRO_EINVAL) and the scene parser names the line that leaves them. */
#define RETRO_FX_FOG_DIST_MAX 1e7f   /* fog start and end: 0..this */
#define RETRO_FX_FOG_DENSITY_MAX 1.0f /* fog density: above 0, at most this */
#define RETRO_FX_SHADE_GAIN_MAX 4.0f /* ambient and diffuse: 0..this */
#define RETRO_FX_WATER_LEVEL_MAX 255 /* water level: 0..this; alphas 0..1 */

/* Sets every parameter to its documented default, flags to 0. */
void retro_effects_defaults(retro_effects *fx);

#define RETRO_SCENE_MAX_KEYS 64
/* The one rule for a distance given by a user, in a scene file or to the CLI (-d):
 * RETRO_MIN_DISTANCE..RETRO_MAX_DISTANCE. D = 1 renders sky only (SEMANTICS.md). */
#define RETRO_MIN_DISTANCE 1

typedef struct retro_keyframe {
    float t;                   /* position along the path, 0..1 */
    float x, y;
    int height, angle;
    float morph_t;             /* morph time at this key (if morph is on) */
} retro_keyframe;

typedef struct retro_scene {
    char map[1024];            /* map prefix, resolved relative to the scene file's folder */
    char morph_map[1024];      /* second height keyframe (prefix) for morph, or "" */
    uint32_t sky;
    float x, y;                /* camera */
    int height, angle;
    int W, H, D;               /* screen and distance */
    int frames;                /* fly-through length in frames (0: no path) */
    retro_keyframe keys[RETRO_SCENE_MAX_KEYS];
    int nkeys;
    retro_effects fx;
    /* [lod] rate: mode lod's step max(1, floor(d * lod)), for retro_render_opts.lod (the lod
     * effect, RETRO_FX_LOD in fx.flags, asks for mode lod; its rate is given only there) */
    float lod;
} retro_scene;

/* Parses an INI scene file (inih). On error returns -1 with err as "FILE:LINE: [section] key:
 * problem". Unset values keep the defaults of retro_scene_defaults(). */
int retro_scene_load(const char *path, retro_scene *s, char *err, size_t errlen);
void retro_scene_defaults(retro_scene *s);
/* The camera at frame i of the fly-through (linear between keyframes; angles the short way
 * round); without a path, the scene's camera. Also sets *morph_t when the path has one. */
void retro_scene_pose(const retro_scene *s, int frame, player_t *p, float *morph_t);

#ifdef __cplusplus
}
#endif

#endif
