/* Fractal terrain for the voxel-space renderer: alpine, islands, canyon.
 *
 * Portability of the bytes: randomness comes only from integer hashes, and the float pipeline
 * uses only IEEE-exact operations (+ - * / sqrtf floorf fabsf), evaluated in a fixed order. No
 * libm transcendental (powf, expf, sinf) appears because their last bits differ between libms,
 * and one flipped bit can change a quantised height. Build with -ffp-contract=off so no FMA
 * is fused in on some targets and not on others.
 *
 * Tiling: every noise octave hashes its lattice modulo an integer period p and is sampled at
 * (x / S) * p, so the map is a seamless torus for any S. Domain warping adds offsets in those
 * same torus units, which keeps the warped field periodic too. */
#include "retro_maps.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { ALPINE, ISLANDS, CANYON };

typedef struct gen {
    int style, size;
    int unlit;       /* STYLE-unlit: albedo only, for renderers that light the map themselves */
    int max_period;  /* lattices finer than this only alias: at most half the map's pixels */
    uint32_t seed[12];  /* one per independent use, so no two fields correlate */
    float *h;        /* raw field, then heights in renderer units (0..255) */
    float *aux;      /* a second raw field per style; later scratch, then water depth */
} gen;

typedef struct rgb { float r, g, b; } rgb;

/* ---- hashing and lattice noise ---------------------------------------------------------- */

static uint64_t splitmix64(uint64_t *state) {
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static inline uint32_t mix32(uint32_t h) {
    h ^= h >> 16; h *= 0x7FEB352Du;
    h ^= h >> 15; h *= 0x846CA68Bu;
    return h ^ (h >> 16);
}

/* Distinct odd multipliers keep (x, y) and (y, x) apart; one mixing round is plenty for
 * picking among 16 gradients. */
static inline uint32_t hash3(uint32_t x, uint32_t y, uint32_t s) {
    return mix32((x * 0x8DA6B343u) ^ (y * 0xD8163841u) ^ s);
}

static inline float clampf(float v, float lo, float hi) { return v < lo ? lo : v > hi ? hi : v; }
static inline float lerpf(float a, float b, float t) { return a + (b - a) * t; }
/* Not fmaxf: that is a libm call on common targets, and NaN never arises here. */
static inline float maxf(float a, float b) { return a > b ? a : b; }
static inline float minf(float a, float b) { return a < b ? a : b; }
static float smooth01(float v) { v = clampf(v, 0.0f, 1.0f); return v * v * (3.0f - 2.0f * v); }
static float ramp(float v, float a, float b) { return smooth01((v - a) / (b - a)); }

/* Flat benches joined by steep risers: v in [0,1], steps bands, sharp = riser share. */
static float terrace(float v, float steps, float sharp) {
    float k = floorf(v * steps), f = v * steps - k;
    return (k + smooth01((f - (1.0f - sharp)) / sharp)) / steps;
}

/* Sixteen evenly spaced unit gradients, written out so no cosf enters the result. */
static const float GRAD[16][2] = {
    {1.0f, 0.0f}, {0.92388f, 0.382683f}, {0.707107f, 0.707107f}, {0.382683f, 0.92388f},
    {0.0f, 1.0f}, {-0.382683f, 0.92388f}, {-0.707107f, 0.707107f}, {-0.92388f, 0.382683f},
    {-1.0f, 0.0f}, {-0.92388f, -0.382683f}, {-0.707107f, -0.707107f}, {-0.382683f, -0.92388f},
    {0.0f, -1.0f}, {0.382683f, -0.92388f}, {0.707107f, -0.707107f}, {0.92388f, -0.382683f}};

static inline float corner(int x, int y, uint32_t s, float dx, float dy) {
    const float *g = GRAD[hash3((uint32_t)x, (uint32_t)y, s) & 15u];
    return g[0] * dx + g[1] * dy;
}

/* Gradient noise in about [-1, 1] on a lattice of period p cells; (u, v) in lattice units. */
static float noise(float u, float v, int p, uint32_t s) {
    float fu = floorf(u), fv = floorf(v), dx = u - fu, dy = v - fv;
    int x0 = (int)fu, y0 = (int)fv;
    if (x0 < 0 || x0 >= p) x0 = (x0 % p + p) % p;  /* only warped samples leave [0, p) */
    if (y0 < 0 || y0 >= p) y0 = (y0 % p + p) % p;
    int x1 = x0 + 1 == p ? 0 : x0 + 1, y1 = y0 + 1 == p ? 0 : y0 + 1;
    float a = dx * dx * dx * (dx * (dx * 6.0f - 15.0f) + 10.0f);
    float b = dy * dy * dy * (dy * (dy * 6.0f - 15.0f) + 10.0f);
    float n0 = lerpf(corner(x0, y0, s, dx, dy), corner(x1, y0, s, dx - 1.0f, dy), a);
    float n1 = lerpf(corner(x0, y1, s, dx, dy - 1.0f), corner(x1, y1, s, dx - 1.0f, dy - 1.0f), a);
    return 1.4f * lerpf(n0, n1, b);
}

/* Octaves from period p, doubling (so every octave's period stays an integer), up to the
 * map's resolution and at most max. */
static int octaves(const gen *g, int p, int max) {
    int n = 1;
    while (n < max && (p << n) <= g->max_period) n++;
    return n;
}

/* (tx, ty) on the unit torus. Result roughly in [-1, 1]. */
static float fbm(float tx, float ty, int p, int oct, float gain, uint32_t s) {
    float sum = 0.0f, amp = 1.0f, norm = 0.0f;
    for (int o = 0; o < oct; o++, p *= 2, amp *= gain) {
        sum += amp * noise(tx * (float)p, ty * (float)p, p, s + (uint32_t)o * 0x9E3779B9u);
        norm += amp;
    }
    return sum / norm;
}

/* Musgrave's ridged multifractal: each octave is weighted by the previous one's ridge value,
 * so fine detail gathers on crests and the valleys between stay smooth. Result in [0, 1]. */
static float ridged(float tx, float ty, int p, int oct, uint32_t s) {
    float sum = 0.0f, amp = 1.0f, norm = 0.0f, weight = 1.0f;
    for (int o = 0; o < oct; o++, p *= 2, amp *= 0.5f) {
        uint32_t so = s + (uint32_t)o * 0x9E3779B9u;
        float n = 1.0f - fabsf(noise(tx * (float)p, ty * (float)p, p, so));
        n = n * n * weight;
        weight = clampf(n * 2.0f, 0.0f, 1.0f);
        sum += n * amp;
        norm += amp;
    }
    return sum / norm;
}

/* ---- raw fields, one cell at a time ----------------------------------------------------- */

static void warp(const gen *g, float *tx, float *ty, int p, float amount) {
    int oct = octaves(g, p, 4);
    float wx = fbm(*tx, *ty, p, oct, 0.5f, g->seed[0]);
    float wy = fbm(*tx, *ty, p, oct, 0.5f, g->seed[1]);
    *tx += amount * wx;
    *ty += amount * wy;
}

/* Approximate distance, in torus units, to the zero set of a smooth field: |n| / |grad n|. A
 * canyon drawn at a fixed distance keeps one width instead of ballooning where n is flat. */
static float zero_distance(const gen *g, float tx, float ty, int p, uint32_t s) {
    const float e = 1.0f / 4096.0f;
    int oct = octaves(g, p, 3);
    float n = fbm(tx, ty, p, oct, 0.5f, s);
    float gx = (fbm(tx + e, ty, p, oct, 0.5f, s) - n) / e;
    float gy = (fbm(tx, ty + e, p, oct, 0.5f, s) - n) / e;
    return fabsf(n) / maxf(sqrtf(gx * gx + gy * gy), 2.0f);  /* floor: saddles stay narrow */
}

static void cell_field(const gen *g, float tx, float ty, float *h, float *aux) {
    const uint32_t *s = g->seed;
    *aux = 0.0f;
    if (g->style == ALPINE) {
        warp(g, &tx, &ty, 2, 0.07f);
        float mass = fbm(tx, ty, 2, octaves(g, 2, 5), 0.5f, s[2]);
        float r = ridged(tx, ty, 3, octaves(g, 3, 8), s[3]);
        *h = r * (0.6f + 0.4f * mass) + 0.3f * mass;
    } else if (g->style == ISLANDS) {
        warp(g, &tx, &ty, 4, 0.05f);
        *h = fbm(tx, ty, 4, octaves(g, 4, 8), 0.52f, s[2]);
        *aux = ridged(tx, ty, 6, octaves(g, 6, 6), s[3]);
    } else {
        /* Canyon heights come out final: the walls need absolute thresholds, not quantiles.
         * A plateau, lowered to a plain in broad basins where only mesas keep its height, and
         * cut through by canyons along the zero set of a strongly warped field, whose level
         * lines wind like incised meanders. */
        warp(g, &tx, &ty, 3, 0.05f);
        float top = 200.0f + 10.0f * fbm(tx, ty, 2, octaves(g, 2, 3), 0.5f, s[2]);
        float basin = ramp(fbm(tx, ty, 2, octaves(g, 2, 3), 0.5f, s[8]), 0.0f, 0.12f);
        float mesa = ramp(fbm(tx, ty, 10, octaves(g, 10, 3), 0.45f, s[9]), 0.18f, 0.24f);
        float land = 118.0f + (top - 118.0f) * terrace(1.0f - basin * (1.0f - mesa), 2.0f, 0.5f);
        float ragged = 0.003f * fbm(tx, ty, 24, octaves(g, 24, 3), 0.5f, s[10]);
        warp(g, &tx, &ty, 5, 0.03f);
        float d = zero_distance(g, tx, ty, 3, s[3]);
        /* Side canyons: a finer network, pinched out away from the main gorges so it
         * branches off them instead of tiling the plateau with closed loops. */
        d = minf(d, 2.5f * zero_distance(g, tx, ty, 7, s[11]) + 0.6f * d);
        float wall = terrace(ramp(d + ragged, 0.005f, 0.02f), 4.0f, 0.4f);
        *h = 64.0f + (land - 64.0f) * wall - 12.0f * (1.0f - ramp(d, 0.0012f, 0.0025f));
    }
}

static void normalize(float *f, size_t n) {
    float lo = f[0], hi = f[0];
    for (size_t i = 1; i < n; i++) { lo = minf(lo, f[i]); hi = maxf(hi, f[i]); }
    float k = hi > lo ? 1.0f / (hi - lo) : 0.0f;
    for (size_t i = 0; i < n; i++) f[i] = (f[i] - lo) * k;
}

/* Values below which fractions q[0..k) of a [0,1] field lie, to a histogram's resolution. Shaping
 * by quantiles rather than raw values gives every seed the same share of sea, valley and peak. */
static void quantiles(const float *f, size_t n, const float *q, float *out, int k) {
    enum { BINS = 4096 };
    size_t hist[BINS] = {0}, acc = 0;
    int b = 0;
    for (size_t i = 0; i < n; i++) hist[(int)clampf(f[i] * (float)(BINS - 1), 0.0f, BINS - 1)]++;
    for (int j = 0; j < k; j++) {
        size_t want = (size_t)((double)n * (double)q[j]);
        while (b < BINS - 1 && acc + hist[b] <= want) acc += hist[b++];
        out[j] = (float)b / (float)(BINS - 1);
    }
}

/* Piecewise-linear map sending quantile q[j] of the field to height hgt[j]; q runs 0 to 1. */
static void remap(float *f, size_t n, const float *q, const float *hgt, int k) {
    float v[8];
    quantiles(f, n, q, v, k);
    v[0] = 0.0f;
    v[k - 1] = 1.0f;
    for (size_t i = 0; i < n; i++) {
        int j = 0;
        while (j < k - 2 && f[i] >= v[j + 1]) j++;
        float span = v[j + 1] - v[j];
        float t = span > 0.0f ? clampf((f[i] - v[j]) / span, 0.0f, 1.0f) : 0.0f;
        f[i] = hgt[j] + (hgt[j + 1] - hgt[j]) * t;
    }
}

/* Turns the normalised raw fields into heights (0..255 units) and returns the water level. */
static float shape(gen *g, size_t n) {
    float *h = g->h, *a = g->aux;
    if (g->style == ALPINE) {
        /* Broad valley floors (lakes in the lowest 4%), steep flanks, a snowy top tenth. */
        static const float q[6] = {0.0f, 0.04f, 0.45f, 0.85f, 0.97f, 1.0f};
        static const float hgt[6] = {14.0f, 34.0f, 100.0f, 175.0f, 222.0f, 280.0f};
        remap(h, n, q, hgt, 6);
        return 34.0f;
    }
    if (g->style == ISLANDS) {
        const float sea = 64.0f, share = 0.68f;
        float q;
        quantiles(h, n, &share, &q, 1);
        for (size_t i = 0; i < n; i++) {
            if (h[i] < q) {
                float d = (q - h[i]) / maxf(q, 1e-6f);  /* q is 0 or 1 only on tiny maps */
                h[i] = sea - 1.0f - 58.0f * d * (0.4f + 0.6f * d);
            } else {
                float e = (h[i] - q) / maxf(1.0f - q, 1e-6f);
                float peaks = 110.0f * a[i] * ramp(e, 0.1f, 0.6f);  /* only inland */
                h[i] = sea + 1.0f + 30.0f * e + (90.0f + peaks) * e * e;
            }
        }
        return sea;
    }
    return 58.0f;
}

/* ---- erosion ---------------------------------------------------------------------------- */

typedef struct tap { size_t i[4]; float w[4]; } tap;

/* Bilinear height and gradient at (x, y) in [0,S)^2, neighbours wrapped around the torus. */
static float sample(const float *h, int S, float x, float y, float *gx, float *gy, tap *t) {
    int ix = (int)x, iy = (int)y;
    float fx = x - (float)ix, fy = y - (float)iy;
    int jx = ix + 1 == S ? 0 : ix + 1, jy = iy + 1 == S ? 0 : iy + 1;
    size_t r0 = (size_t)iy * (size_t)S, r1 = (size_t)jy * (size_t)S;
    t->i[0] = r0 + (size_t)ix; t->i[1] = r0 + (size_t)jx;
    t->i[2] = r1 + (size_t)ix; t->i[3] = r1 + (size_t)jx;
    t->w[0] = (1.0f - fx) * (1.0f - fy); t->w[1] = fx * (1.0f - fy);
    t->w[2] = (1.0f - fx) * fy;          t->w[3] = fx * fy;
    float a = h[t->i[0]], b = h[t->i[1]], c = h[t->i[2]], d = h[t->i[3]];
    *gx = (b - a) * (1.0f - fy) + (d - c) * fy;
    *gy = (c - a) * (1.0f - fx) + (d - b) * fx;
    return a * t->w[0] + b * t->w[1] + c * t->w[2] + d * t->w[3];
}

static float wrapf(float v, float S) {
    if (v < 0.0f) v += S;
    if (v >= S) v -= S;
    return v >= 0.0f && v < S ? v : 0.0f;  /* guards rounding at the seam */
}

/* Droplet ("hydraulic") erosion: each droplet runs downhill, picks up sediment where it speeds
 * up and drops it where it slows or pools, which cuts gullies and fans out valley floors.
 * Count and start points depend only on S and the seed. */
static void erode_droplets(gen *g, size_t count, float strength, float level) {
    const int S = g->size;
    const float fS = (float)S;
    const size_t n = (size_t)S * (size_t)S;
    for (size_t k = 0; k < count; k++) {
        /* Starts sweep the map in row order, jittered, so consecutive droplets reuse cached
         * rows; uniformly random starts were measurably slower for the same look. */
        size_t cell = (size_t)((double)k * (double)n / (double)count);
        uint32_t hk = hash3((uint32_t)k, (uint32_t)(k >> 32), g->seed[5]);
        float x = wrapf((float)(cell % (size_t)S) + (float)(hk >> 16) * (1.0f / 65536.0f), fS);
        float y = wrapf((float)(cell / (size_t)S) + (float)(hk & 0xFFFFu) * (1.0f / 65536.0f), fS);
        float dx = 0.0f, dy = 0.0f, speed = 1.0f, water = 1.0f, sed = 0.0f;
        for (int step = 0; step < 40; step++) {
            float gx, gy, unused;
            tap t, t2;
            float h0 = sample(g->h, S, x, y, &gx, &gy, &t);
            if (h0 < level) break;  /* sediment reaching water is lost, not piled into spits */
            dx = dx * 0.3f - gx * 0.7f;
            dy = dy * 0.3f - gy * 0.7f;
            float len = sqrtf(dx * dx + dy * dy);
            if (len < 1e-6f) break;
            dx /= len; dy /= len;
            x = wrapf(x + dx, fS);
            y = wrapf(y + dy, fS);
            float dh = sample(g->h, S, x, y, &unused, &unused, &t2) - h0;
            float cap = maxf(-dh, 0.05f) * speed * water * 4.0f;
            float amount;
            /* Positive amounts deposit; uphill moves fill the dip they leave, at most. */
            if (dh > 0.0f || sed > cap) amount = dh > 0.0f ? minf(dh, sed) : (sed - cap) * 0.3f;
            else amount = -minf((cap - sed) * 0.3f * strength, -dh);
            sed -= amount;
            for (int c = 0; c < 4; c++) g->h[t.i[c]] += amount * t.w[c];
            speed = sqrtf(maxf(speed * speed - dh * 0.5f, 0.0f));
            water *= 0.97f;
        }
    }
}

/* Thermal erosion: material above the talus slope slides to lower neighbours, rounding the
 * droplets' sharp pixel-scale scars and softening cliff edges a little. */
static void erode_thermal(gen *g, int iterations, float talus, float rate) {
    const int S = g->size;
    float *h = g->h, *d = g->aux;
    size_t n = (size_t)S * (size_t)S;
    for (int it = 0; it < iterations; it++) {
        memset(d, 0, n * sizeof *d);
        for (int y = 0; y < S; y++) {
            size_t row = (size_t)y * (size_t)S, down = (size_t)(y + 1 == S ? 0 : y + 1) * (size_t)S;
            for (int x = 0; x < S; x++) {
                size_t i = row + (size_t)x;
                size_t nb[2] = {row + (size_t)(x + 1 == S ? 0 : x + 1), down + (size_t)x};
                for (int k = 0; k < 2; k++) {
                    float diff = h[i] - h[nb[k]], m;
                    if (fabsf(diff) <= talus) continue;
                    m = rate * (diff - (diff > 0.0f ? talus : -talus));
                    d[i] -= m;
                    d[nb[k]] += m;
                }
            }
        }
        for (size_t i = 0; i < n; i++) h[i] += d[i];
    }
}

/* ---- colour and light ------------------------------------------------------------------- */

static rgb mixc(rgb a, rgb b, float t) {
    return (rgb){lerpf(a.r, b.r, t), lerpf(a.g, b.g, t), lerpf(a.b, b.b, t)};
}

static rgb water_color(int style, float depth) {
    static const rgb shallow[3] = {{70, 120, 125}, {60, 175, 180}, {70, 130, 135}};
    static const rgb deep[3] = {{15, 40, 70}, {10, 40, 100}, {30, 75, 95}};
    return mixc(shallow[style], deep[style], ramp(depth, 0.0f, style == ISLANDS ? 45.0f : 20.0f));
}

/* Base colour of dry land from height h, slope (height units per cell) and a low-frequency
 * variation v in [-1,1] that bends the snow line, tree line and strata. */
static rgb land_color(const gen *g, float h, float slope, float v, float level) {
    if (g->style == ALPINE) {
        rgb meadow = {95, 130, 55}, forest = {45, 80, 40}, rock = {118, 110, 102};
        rgb scree = {150, 142, 130}, snow = {240, 242, 248};
        rgb c = mixc(meadow, forest, ramp(h + 25.0f * v, 60.0f, 95.0f));
        c = mixc(c, scree, ramp(h + 15.0f * v, 125.0f, 150.0f));
        c = mixc(c, rock, ramp(slope, 2.0f, 3.2f));
        float snowy = ramp(h + 20.0f * v, 178.0f, 196.0f) * (1.0f - ramp(slope, 3.0f, 4.5f));
        return mixc(c, snow, snowy);
    }
    if (g->style == ISLANDS) {
        rgb sand = {222, 205, 150}, grass = {105, 160, 60}, forest = {50, 110, 45};
        rgb rock = {130, 118, 100};
        rgb c = mixc(sand, grass, ramp(h, level + 2.0f, level + 6.0f + 2.0f * v));
        c = mixc(c, forest, ramp(h + 20.0f * v, 85.0f, 120.0f));
        return mixc(c, rock, maxf(ramp(h + 15.0f * v, 160.0f, 200.0f), ramp(slope, 2.2f, 3.5f)));
    }
    /* Canyon: horizontal strata picked by height band, their thickness varying by hash. */
    static const rgb strata[6] = {{178, 84, 48}, {205, 120, 70}, {150, 70, 45},
                                  {220, 160, 105}, {190, 100, 60}, {130, 62, 42}};
    float hb = (h + 4.0f * v) / 9.0f;
    int band = (int)floorf(hb);
    rgb lower = strata[mix32((uint32_t)band ^ g->seed[6]) % 6u];
    rgb upper = strata[mix32((uint32_t)(band + 1) ^ g->seed[6]) % 6u];
    rgb c = mixc(lower, upper, ramp(hb - (float)band, 0.8f, 1.0f));
    /* Flats take the dust of their level: red on the plateau and mesa tops, pale sand on the
     * basin plains, olive floodplain near the river. */
    rgb top = {200, 128, 82}, plain = {224, 182, 128}, bank = {112, 118, 62};
    rgb dust = mixc(plain, top, ramp(h + 6.0f * v, 140.0f, 170.0f));
    c = mixc(c, dust, 0.8f * (1.0f - ramp(slope, 0.15f, 0.5f)));
    return mixc(c, bank, 0.8f * (1.0f - ramp(h, level + 2.0f, level + 10.0f)));
}

static uint32_t to8(float v) { return (uint32_t)clampf(v + 0.5f, 0.0f, 255.0f); }

static void colorize(gen *g, retro_map *m, float level) {
    const int S = g->size;
    const float *h = g->h, *depth = g->aux;
    /* Sun from the north-west, 45 degrees up. */
    const float sx = -0.5f, sy = -0.5f, sz = 0.70710678f;
    for (int y = 0; y < S; y++) {
        size_t up = (size_t)(y == 0 ? S - 1 : y - 1) * (size_t)S;
        size_t row = (size_t)y * (size_t)S, down = (size_t)(y + 1 == S ? 0 : y + 1) * (size_t)S;
        float ty = (float)y / (float)S;
        for (int x = 0; x < S; x++) {
            size_t i = row + (size_t)x;
            size_t l = row + (size_t)(x == 0 ? S - 1 : x - 1);
            size_t r = row + (size_t)(x + 1 == S ? 0 : x + 1);
            float gx = 0.5f * (h[r] - h[l]), gy = 0.5f * (h[down + (size_t)x] - h[up + (size_t)x]);
            float slope = sqrtf(gx * gx + gy * gy);
            float v = noise((float)x / (float)S * 16.0f, ty * 16.0f, 16, g->seed[7]);
            rgb c = depth[i] > 0.0f ? water_color(g->style, depth[i])
                                    : land_color(g, h[i], slope, v, level);
            uint32_t hj = hash3((uint32_t)x, (uint32_t)y, g->seed[4]) >> 8;
            float jit = 0.95f + (float)hj * (0.1f / 16777216.0f);  /* per-cell grain, +-5% */
            float ndl = (-gx * sx - gy * sy + sz) / sqrtf(gx * gx + gy * gy + 1.0f);
            float light = g->unlit ? jit : jit * (0.45f + 0.75f * maxf(ndl, 0.0f));
            m->color[i] = to8(c.r * light) << 24 | to8(c.g * light) << 16 | to8(c.b * light) << 8;
        }
    }
}

/* The whole pipeline on allocated buffers: raw fields, shaping, erosion, water, colour. */
static void build(gen *g, retro_map *m) {
    const int S = g->size;
    const size_t n = (size_t)S * (size_t)S;
    for (int y = 0; y < S; y++)
        for (int x = 0; x < S; x++) {
            size_t i = (size_t)y * (size_t)S + (size_t)x;
            cell_field(g, (float)x / (float)S, (float)y / (float)S, &g->h[i], &g->aux[i]);
        }
    if (g->style != CANYON) {
        normalize(g->h, n);
        normalize(g->aux, n);
    }
    float level = shape(g, n);
    /* The canyon skips droplets: they would round off the cliffs and benches it is made of. */
    if (g->style != CANYON) erode_droplets(g, n / 6, g->style == ALPINE ? 1.0f : 0.6f, level);
    erode_thermal(g, g->style == CANYON ? 2 : 3, g->style == CANYON ? 4.0f : 2.5f, 0.25f);
    for (size_t i = 0; i < n; i++) {
        float hh = g->h[i], over = hh - 230.0f;
        if (over > 0.0f) hh = 230.0f + 25.0f * over / (over + 25.0f);  /* no clipped flat peaks */
        hh = clampf(hh, 0.0f, 255.0f);
        g->aux[i] = hh < level ? level - hh : 0.0f;
        g->h[i] = hh < level ? level : hh;
        m->height[i] = (uint8_t)(g->h[i] + 0.5f);
    }
    colorize(g, m, level);
}

/* ---- entry point ------------------------------------------------------------------------ */

int retro_terrain_generate(const char *style, uint64_t seed, retro_map *m) {
    gen g;
    memset(&g, 0, sizeof g);
    if (!style || !m || m->size < 1) return -1;
    size_t len = strlen(style);
    g.unlit = len > 6 && !strcmp(style + len - 6, "-unlit");
    if (g.unlit) len -= 6;
    if (len == 6 && !strncmp(style, "alpine", len)) g.style = ALPINE;
    else if (len == 7 && !strncmp(style, "islands", len)) g.style = ISLANDS;
    else if (len == 6 && !strncmp(style, "canyon", len)) g.style = CANYON;
    else return -1;
    const int S = g.size = m->size;
    if ((size_t)S > SIZE_MAX / sizeof(float) / (size_t)S) return -1;
    const size_t n = (size_t)S * (size_t)S;
    g.max_period = S / 2 > 1 ? S / 2 : 1;
    uint64_t st = seed ^ (UINT64_C(0x5851F42D4C957F2D) * (uint64_t)(g.style + 1));
    for (int k = 0; k < 12; k++) g.seed[k] = (uint32_t)(splitmix64(&st) >> 32);
    g.h = malloc(n * sizeof *g.h);
    g.aux = malloc(n * sizeof *g.aux);
    if (g.h && g.aux) build(&g, m);
    int rc = g.h && g.aux ? 0 : -1;
    free(g.h);
    free(g.aux);
    return rc;
}
