/* Primitive assembly and culling: the two triangles of a grid square, in visibility order,
 * back faces dropped by the sign of their screen-space determinant. */
#include <string.h>

#include "mesh_internal.h"

/* The homogeneous screen determinant: for vertices in front of the eye its sign is the sign of
 * the screen-space determinant (kx*ky/(z0*z1*z2) > 0 times it), and it stays defined for
 * triangles crossing the eye plane. v0 . ((v1 - v0) x (v2 - v0)) on (l, e, z). */
static double orientation(const mesh_frame *f, const mesh_vert *v0, const mesh_vert *v1, const mesh_vert *v2)
{
    double al = rn(f, v1->l - v0->l), ae = rn(f, v1->e - v0->e), az = rn(f, v1->z - v0->z);
    double bl = rn(f, v2->l - v0->l), be = rn(f, v2->e - v0->e), bz = rn(f, v2->z - v0->z);
    double nl = rn(f, rn(f, ae * bz) - rn(f, az * be));
    double ne = rn(f, rn(f, az * bl) - rn(f, al * bz));
    double nz = rn(f, rn(f, al * be) - rn(f, ae * bl));
    return rn(f, rn(f, rn(f, v0->l * nl) + rn(f, v0->e * ne)) + rn(f, v0->z * nz));
}

/* The water plane over a square: the terrain's plan positions at the water level, opacity from
 * the depth of water above each vertex. */
static void water_tri(retro_mesh_ctx *mc, const mesh_tri *t)
{
    const mesh_frame *f = &mc->f;
    mesh_tri w = *t;
    w.water = 1;
    w.back = 0;
    for (int k = 0; k < 3; k++) {
        double depth = rn(f, (double)f->level - w.v[k].h);
        double a = rn(f, f->alpha0 + rn(f, f->alpha_per_unit * (depth > 0 ? depth : 0)));
        w.v[k].a[A_ALPHA] = a < 1 ? a : 1;
        w.v[k].e = rn(f, (double)f->level - (double)f->height);
    }
    mesh_water_add(mc, &w);
}

static void triangle(retro_mesh_ctx *mc, const mesh_vert *g, const mesh_snap *s, const int idx[3],
                     const double sx[3], const double sy[3], int I, int J, int water)
{
    const mesh_frame *f = &mc->f;
    mc->st.submitted++;
    double det = orientation(f, &g[idx[0]], &g[idx[1]], &g[idx[2]]);
    int drawn = (f->mfx & RETRO_MESH_FX_NOCULL) || det > 0;
    if (!drawn)
        mc->st.culled++;
    if (!drawn && !water)
        return; /* most back faces: nothing copied */
    mesh_tri t;
    for (int k = 0; k < 3; k++) {
        t.v[k] = g[idx[k]];
        t.v[k].a[A_SX] = sx[k];
        t.v[k].a[A_SY] = sy[k];
    }
    t.I = (int)(((int64_t)I % f->S + f->S) % f->S);
    t.J = (int)(((int64_t)J % f->S + f->S) % f->S);
    t.water = 0;
    t.back = det < 0;
    if (water)
        water_tri(mc, &t);
    if (!drawn)
        return;
    const mesh_snap *s3[3] = {&s[idx[0]], &s[idx[1]], &s[idx[2]]};
    mesh_clip_and_draw(mc, &t, s3);
}

void mesh_primitive_assembly(retro_mesh_ctx *mc, const mesh_vert *g, const mesh_snap *s, int stride,
                             int a, int I, int J)
{
    const mesh_frame *f = &mc->f;
    int b = a + 1, c = a + stride + 1, d = a + stride;
    /* Diagonal from A = (I, J) to C = (I+1, J+1). ACB holds corner B, ADC corner D; both are
     * counter-clockwise on screen seen from above. */
    static const double sx1[3] = {0.5, 1.5, 1.5}, sy1[3] = {0.5, 1.5, 0.5};
    static const double sx2[3] = {0.5, 0.5, 1.5}, sy2[3] = {0.5, 1.5, 1.5};
    int t1[3] = {a, c, b}, t2[3] = {a, d, c};
    int water = 0;
    if (f->fx & RETRO_FX_WATER) {
        double lv = f->level;
        water = g[a].h < lv || g[b].h < lv || g[c].h < lv || g[d].h < lv;
    }
    /* The triangle on the eye's side of the diagonal can hide the other: the painter draws it
     * last, the z-buffer first, so that each draws in the other's reverse order. */
    int eye_b = f->x0 - f->y0 > (double)(I - J);
    int near_first = f->kernel == RETRO_MESH_ZBUFFER;
    if (eye_b == near_first) {
        triangle(mc, g, s, t1, sx1, sy1, I, J, water);
        triangle(mc, g, s, t2, sx2, sy2, I, J, water);
    } else {
        triangle(mc, g, s, t2, sx2, sy2, I, J, water);
        triangle(mc, g, s, t1, sx1, sy1, I, J, water);
    }
}
