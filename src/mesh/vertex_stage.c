/* Vertex stage: a grid vertex to eye space with its attributes; the clip-plane distances and
 * the projection to fixed-point screen coordinates that later stages apply to any vertex. */
#include <math.h>

#include "mesh_internal.h"

static int wrapi(int64_t v, int S)
{
    int64_t r = v % S;
    return (int)(r < 0 ? r + S : r);
}

/* The height of cell (i, j) (already reduced mod S): with morph, h0 + (h1 - h0) * t. */
static double cell_height(const mesh_frame *f, size_t at)
{
    double h = f->h0[at];
    if (!f->h1)
        return h;
    return rn(f, h + rn(f, (double)(f->h1[at] - f->h0[at]) * f->morph_t));
}

/* The unit normal of one keyframe at (i, j): central differences as the shade bake. */
static void normal(const mesh_frame *f, const uint8_t *h, int i, int j, double n[3])
{
    int S = f->S, l = (i + S - 1) % S, r = (i + 1) % S, u = (j + S - 1) % S, d = (j + 1) % S;
    double gx = rn(f, (double)(h[(size_t)j * S + r] - h[(size_t)j * S + l]) * 0.5);
    double gy = rn(f, (double)(h[(size_t)d * S + i] - h[(size_t)u * S + i]) * 0.5);
    double len = rn(f, sqrt(rn(f, rn(f, rn(f, gx * gx) + rn(f, gy * gy)) + 1.0)));
    n[0] = rn(f, -gx / len);
    n[1] = rn(f, -gy / len);
    n[2] = rn(f, 1.0 / len);
}

static double light(const mesh_frame *f, const double n[3], double sign)
{
    double dot = rn(f, rn(f, rn(f, n[0] * f->sun[0]) + rn(f, n[1] * f->sun[1])) + rn(f, n[2] * f->sun[2]));
    dot = sign * dot;
    return rn(f, f->ambient + rn(f, f->diffuse * (dot > 0 ? dot : 0)));
}

void mesh_vertex_stage(const mesh_frame *f, int I, int J, mesh_vert *v)
{
    int S = f->S, i = wrapi(I, S), j = wrapi(J, S);
    size_t at = (size_t)j * (size_t)S + (size_t)i;
    double h = cell_height(f, at);
    double dx = rn(f, (I + 0.5) - f->x0), dy = rn(f, (J + 0.5) - f->y0);
    v->z = rn(f, rn(f, dx * f->cs) - rn(f, dy * f->sn));
    v->l = rn(f, rn(f, dx * f->sn) + rn(f, dy * f->cs));
    v->e = rn(f, h - (double)f->height);
    v->h = h;
    uint32_t c = f->color[at];
    v->a[A_SX] = v->a[A_SY] = 0;
    v->a[A_R] = (double)((c >> 24) & 255);
    v->a[A_G] = (double)((c >> 16) & 255);
    v->a[A_B] = (double)((c >> 8) & 255);
    v->a[A_ALPHA] = 0;
    v->a[A_NX] = v->a[A_NY] = v->a[A_NZ] = 0;
    if (!(f->fx & RETRO_FX_SHADE))
        return;
    double n[3];
    normal(f, f->h0, i, j, n);
    if (f->h1) { /* blend the keyframes' normals as their heights */
        double n1[3];
        normal(f, f->h1, i, j, n1);
        for (int k = 0; k < 3; k++)
            n[k] = rn(f, n[k] + rn(f, rn(f, n1[k] - n[k]) * f->morph_t));
    }
    if (f->mode == RETRO_MESH_INT) { /* light per vertex, front and back */
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double u[3] = {n[0] / len, n[1] / len, n[2] / len};
        v->a[A_NX] = light(f, u, 1.0);
        v->a[A_NY] = light(f, u, -1.0);
        return;
    }
    v->a[A_NX] = n[0];
    v->a[A_NY] = n[1];
    v->a[A_NZ] = n[2];
}

void mesh_plane_distances(const mesh_frame *f, const mesh_vert *v, double *d)
{
    double lx = rn(f, f->kx * v->l), ey = rn(f, f->ky * v->e);
    d[0] = rn(f, v->z - 1.0);
    d[1] = rn(f, f->far - v->z);
    d[2] = rn(f, lx + rn(f, f->cl * v->z));
    d[3] = rn(f, rn(f, f->cr * v->z) - lx);
    d[4] = rn(f, ey + rn(f, f->cb * v->z));
    d[5] = rn(f, rn(f, f->ct * v->z) - ey);
}

static int64_t snap(const mesh_frame *f, double x)
{
    double s = floor(rn(f, x * (double)MESH_ONE + 0.5));
    const double lim = 1073741824.0; /* 2^30: far outside any screen, keeps products in int64 */
    return s > lim ? (int64_t)lim : s < -lim ? -(int64_t)lim : s == s ? (int64_t)s : 0;
}

void mesh_project(const mesh_frame *f, const mesh_vert *v, int64_t *X, int64_t *Y)
{
    double x = rn(f, rn(f, rn(f, f->kx * v->l) / v->z) + f->cx);
    double y = rn(f, rn(f, rn(f, f->ky * v->e) / v->z) + f->cy);
    *X = snap(f, x);
    *Y = snap(f, y);
}
