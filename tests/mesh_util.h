/* Helpers of the mesh tests (static, header-only so the Makefile's test list needs no edit):
 * rendering through the mesh API, seeded maps and poses, and an independent ray-cast
 * reference of the mesh image in binary64 (docs/MESH.md's mesh and camera, nothing of the
 * pipeline's code), which leaves undecided the pixels whose centre lies within a small
 * margin of a triangle edge, the far plane or a cell border. */
#ifndef RETRO_MESH_TEST_UTIL_H
#define RETRO_MESH_TEST_UTIL_H

#include <criterion/criterion.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "retro.h"
#include "retro_mesh.h"

#define MSKY 0x66a3ff00u
#define UNDECIDED 1u /* a colour no map below uses (low byte set) */

static inline uint64_t mrng(uint64_t *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return *s >> 11;
}

/* The parameters of a random effect set that the mesh tests share: fog, sun, pitch and
 * morph, drawn in this order so that a seed names the same case wherever it is used. Which
 * effects are on is the caller's choice. */
static inline void mrandom_fx_params(uint64_t *seed, retro_effects *fx, const uint8_t *morph)
{
    fx->fog_exp = (int)(mrng(seed) & 1);
    fx->fog_start = 5;
    fx->fog_end = 60;
    fx->fog_density = 0.02f;
    fx->sun[0] = -0.6f;
    fx->sun[1] = 0.0f;
    fx->sun[2] = 0.8f;
    fx->ambient = 0.4f;
    fx->diffuse = 0.8f;
    fx->pitch = (int)(mrng(seed) % 21) - 10;
    fx->morph_height = morph;
    fx->morph_t = (float)(mrng(seed) % 101) / 100.0f;
}

/* A random set of the mesh family's own effects: a colour source, wireframe, no culling, each
 * drawn in its own statement (the operands of | are unsequenced, so their draws would not be). */
static inline unsigned mrandom_mesh_fx(uint64_t *seed)
{
    static const unsigned colour[3] = {0, RETRO_MESH_FX_TEXTURE, RETRO_MESH_FX_GOURAUD};
    unsigned f = colour[mrng(seed) % 3];
    f |= (mrng(seed) % 4 == 0) ? RETRO_MESH_FX_WIREFRAME : 0;
    f |= (mrng(seed) % 3 == 0) ? RETRO_MESH_FX_NOCULL : 0;
    return f;
}

typedef struct {
    int S;
    uint8_t *h;
    uint32_t *c;
} mmap_t;

/* Random heights in [lo, hi], random colours (low byte 0). */
static inline mmap_t mmap_random(int S, uint64_t seed, int lo, int hi)
{
    mmap_t m = {S, malloc((size_t)S * S), malloc(sizeof(uint32_t) * S * S)};
    for (int i = 0; i < S * S; i++) {
        m.h[i] = (uint8_t)(lo + (int)(mrng(&seed) % (uint64_t)(hi - lo + 1)));
        m.c[i] = (uint32_t)(mrng(&seed) & 0xffffff) << 8;
    }
    return m;
}

static inline void mmap_free(mmap_t *m)
{
    free(m->h);
    free(m->c);
}

static inline retro_mesh_err mrender(retro_mesh_kernel k, retro_mesh_mode mode, const player_t *p,
                                     const ctx_t *c, const retro_effects *fx, unsigned mfx,
                                     retro_mesh_stats *st)
{
    retro_mesh_ctx *mc = retro_mesh_ctx_new();
    cr_assert(mc);
    retro_mesh_opts o = {mfx, 0};
    retro_mesh_err e = retro_mesh_render(mc, k, mode, p, c, fx, &o, st);
    retro_mesh_ctx_free(mc);
    return e;
}

/* The kernel renders the mode on this CPU (the fast kernels: binary32, their ISA present). */
static inline int mkernel_runs(retro_mesh_kernel k, retro_mesh_mode mode)
{
    return retro_mesh_supports_mode(k, mode) && !(retro_mesh_kernel_isa(k) & ~retro_cpu_features());
}

static inline void mrender_ok(retro_mesh_kernel k, retro_mesh_mode mode, const player_t *p, const ctx_t *c,
                              const retro_effects *fx, unsigned mfx)
{
    retro_mesh_err e = mrender(k, mode, p, c, fx, mfx, NULL);
    cr_assert_eq(e, RETRO_MESH_OK, "mesh-%s/%s failed: %d", retro_mesh_kernel_name(k), retro_mesh_mode_name(mode), e);
}

/* --- the ray-cast reference -------------------------------------------------------------- */

typedef struct {
    double l, e, z;
} evec;

static inline void mref_dir(int angle, double *cs, double *sn)
{
    double a = fmod((double)angle, 360.0);
    a += a < 0 ? 360 : 0;
    int q = (int)(a / 90), r = (int)a % 90;
    double c0 = cos(r * 3.14159265358979323846 / 180.0), s0 = sin(r * 3.14159265358979323846 / 180.0);
    double C[4] = {c0, -s0, -c0, s0}, Sn[4] = {s0, c0, -s0, -c0};
    *cs = C[q];
    *sn = Sn[q];
}

/* The colour of every pixel: the nearest front-facing triangle hit by the pixel's ray with
 * depth in [1, far], coloured by the map cell under the hit point (nearest sampling), sky if
 * none, UNDECIDED within the margins. Culling on, no effects, camera in front of no
 * triangle that crosses the eye plane on screen (tests keep the camera high). */
static inline void mref_render(const player_t *p, const ctx_t *c, uint32_t *out)
{
    int W = c->scr_width, H = c->scr_height, S = c->map_size;
    double far = c->distance < RETRO_MESH_MAX_FAR ? c->distance : RETRO_MESH_MAX_FAR;
    double cs, sn;
    mref_dir(p->angle, &cs, &sn);
    double x0 = fmod((double)p->x, S), y0 = fmod((double)p->y, S);
    x0 += x0 < 0 ? S : 0;
    y0 += y0 < 0 ? S : 0;
    double kx = W > 1 ? 0.5 * (W - 1) : 0.5, cx = 0.5 * (W - 1), ky = 0.5 * W, cy = 0.5 * H;
    int R = (int)(2.2 * far) + 3;
    int I0 = (int)floor(x0) - R, J0 = (int)floor(y0) - R, N = 2 * R;
    double *best = malloc(sizeof(double) * W * H);
    int *amb = calloc((size_t)W * H, sizeof(int));
    double *mz = malloc(sizeof(double) * W * H);
    for (int i = 0; i < W * H; i++) {
        best[i] = mz[i] = INFINITY;
        out[i] = c->sky_color;
    }
    for (int J = J0; J < J0 + N; J++)
        for (int I = I0; I < I0 + N; I++) {
            evec v[4];
            double px[4] = {I + 0.5, I + 1.5, I + 1.5, I + 0.5}, py[4] = {J + 0.5, J + 0.5, J + 1.5, J + 1.5};
            for (int k = 0; k < 4; k++) {
                int ci = (((I + (k == 1 || k == 2)) % S) + S) % S, cj = (((J + (k >= 2)) % S) + S) % S;
                double dx = px[k] - x0, dy = py[k] - y0;
                v[k].z = dx * cs - dy * sn;
                v[k].l = dx * sn + dy * cs;
                v[k].e = (double)c->height_map[cj * S + ci] - p->height;
            }
            const int tri[2][3] = {{0, 2, 1}, {0, 3, 2}}; /* ACB, ADC */
            for (int t = 0; t < 2; t++) {
                evec a = v[tri[t][0]], b = v[tri[t][1]], d = v[tri[t][2]];
                if (a.z < 0.5 && b.z < 0.5 && d.z < 0.5)
                    continue;
                if (a.z > far + 2 && b.z > far + 2 && d.z > far + 2)
                    continue;
                double X[3], V[3];
                evec vv[3] = {a, b, d};
                int front = 1;
                for (int k = 0; k < 3; k++) {
                    if (vv[k].z <= 1e-9)
                        front = 0;
                    X[k] = kx * vv[k].l / vv[k].z + cx;
                    V[k] = ky * vv[k].e / vv[k].z + cy;
                }
                if (!front)
                    continue; /* crosses the eye plane: tests keep it below the screen */
                double A = (X[1] - X[0]) * (V[2] - V[0]) - (V[1] - V[0]) * (X[2] - X[0]);
                /* the triangle's plane in eye space (normal on (l, e, z)) */
                double al = b.l - a.l, ae = b.e - a.e, az = b.z - a.z;
                double bl = d.l - a.l, be = d.e - a.e, bz = d.z - a.z;
                double nl = ae * bz - az * be, ne = az * bl - al * bz, nz = al * be - ae * bl;
                if (!(A > 0))
                    continue;
                double len[3];
                for (int k = 0; k < 3; k++) {
                    int n = (k + 1) % 3;
                    len[k] = hypot(X[n] - X[k], V[n] - V[k]);
                }
                int c0 = (int)fmax(0, floor(fmin(X[0], fmin(X[1], X[2]))) - 1);
                int c1 = (int)fmin(W - 1, ceil(fmax(X[0], fmax(X[1], X[2]))) + 1);
                int r0 = (int)fmax(1, floor(fmin(V[0], fmin(V[1], V[2]))) - 1);
                int r1 = (int)fmin(H, ceil(fmax(V[0], fmax(V[1], V[2]))) + 1);
                for (int r = r0; r <= r1; r++)
                    for (int col = c0; col <= c1; col++) {
                        double E[3], dmin = INFINITY;
                        for (int k = 0; k < 3; k++) {
                            int n = (k + 1) % 3;
                            E[k] = (X[n] - X[k]) * (r - V[k]) - (V[n] - V[k]) * (col - X[k]);
                            dmin = fmin(dmin, E[k] / len[k]);
                        }
                        if (dmin < -0.02)
                            continue;
                        /* perspective-correct depth at the pixel */
                        double w0 = E[1] / A, w1 = E[2] / A, w2 = E[0] / A;
                        double z = 1.0 / (w0 / a.z + w1 / b.z + w2 / d.z);
                        size_t at = (size_t)(H - r) * W + col;
                        int maybe = dmin < 0.02 || fabs(z - far) < 0.02 || fabs(z - 1) < 0.02;
                        if (!maybe && (z < 1 || z > far))
                            continue;
                        if (maybe) {
                            mz[at] = fmin(mz[at], z);
                            continue;
                        }
                        if (fabs(z - best[at]) < 1e-6) {
                            amb[at] = 1; /* two surfaces at one depth */
                        } else if (z < best[at]) {
                            /* the cell under the pixel centre, and whether a shift of
                             * 0.01 pixel (snapping moves vertices by 1/512) changes it */
                            long cell = -1;
                            amb[at] = 0;
                            for (int q = 0; q < 5; q++) {
                                double sx = col + (q == 1 ? 0.01 : q == 2 ? -0.01 : 0);
                                double sv = r + (q == 3 ? 0.01 : q == 4 ? -0.01 : 0);
                                double dl = (sx - cx) / kx, de = (sv - cy) / ky;
                                double zq = (nl * a.l + ne * a.e + nz * a.z) / (nl * dl + ne * de + nz);
                                double lq = zq * dl;
                                double qx = x0 + zq * cs + lq * sn, qy = y0 - zq * sn + lq * cs;
                                long ci = (((long)floor(qx) % S) + S) % S, cj = (((long)floor(qy) % S) + S) % S;
                                if (q == 0)
                                    cell = cj * S + ci;
                                else
                                    amb[at] |= cj * S + ci != cell;
                            }
                            best[at] = z;
                            out[at] = c->color_map[cell];
                        }
                    }
            }
        }
    for (int i = 0; i < W * H; i++)
        amb[i] |= mz[i] < best[i] + 1e-6;
    for (int i = 0; i < W * H; i++)
        if (amb[i])
            out[i] = UNDECIDED;
    free(best);
    free(mz);
    free(amb);
}

#endif
