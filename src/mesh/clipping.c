/* Clipping: Sutherland-Hodgman against near, far, left, right, bottom and top in turn, then a
 * fan of sub-triangles to scan conversion. An edge shared by two triangles is cut at the same
 * point in both, because the intersection is always computed from its inside end to its
 * outside end, whichever way the polygon runs along it. */
#include "mesh_internal.h"

typedef struct {
    mesh_vert v;
    double d[6];
    int orig; /* the edge from this vertex to the next lies on an edge of the triangle */
} poly_vert;

static void intersect(const mesh_frame *f, const poly_vert *in, const poly_vert *out, int p, poly_vert *r)
{
    double s = rn(f, in->d[p] / rn(f, in->d[p] - out->d[p]));
    const mesh_vert *a = &in->v, *b = &out->v;
    r->v.l = rn(f, a->l + rn(f, s * rn(f, b->l - a->l)));
    r->v.z = rn(f, a->z + rn(f, s * rn(f, b->z - a->z)));
    r->v.e = rn(f, a->e + rn(f, s * rn(f, b->e - a->e)));
    r->v.h = a->h;
    for (int k = 0; k < MESH_NA; k++)
        r->v.a[k] = rn(f, a->a[k] + rn(f, s * rn(f, b->a[k] - a->a[k])));
    mesh_plane_distances(f, &r->v, r->d);
}

/* One plane: n vertices of src to the result in dst; returns the count. */
static int clip_plane(const mesh_frame *f, const poly_vert *src, int n, int p, poly_vert *dst)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        const poly_vert *cur = &src[i], *nxt = &src[i + 1 == n ? 0 : i + 1];
        int cin = cur->d[p] >= 0, nin = nxt->d[p] >= 0;
        if (cin)
            dst[m++] = *cur;
        if (cin && !nin) {
            intersect(f, cur, nxt, p, &dst[m]);
            dst[m++].orig = 0; /* from here the polygon runs along the plane */
        } else if (!cin && nin) {
            intersect(f, nxt, cur, p, &dst[m]);
            dst[m].orig = cur->orig;
            m++;
        }
    }
    return m;
}

static void draw_fan(retro_mesh_ctx *mc, const mesh_tri *t, const poly_vert *P, int n)
{
    int64_t X[MESH_MAXPOLY], Y[MESH_MAXPOLY];
    for (int i = 0; i < n; i++)
        mesh_project(&mc->f, &P[i].v, &X[i], &Y[i]);
    for (int k = 1; k + 1 < n; k++) {
        mesh_sub s;
        int ix[3] = {0, k, k + 1};
        for (int q = 0; q < 3; q++) {
            s.X[q] = X[ix[q]];
            s.Y[q] = Y[ix[q]];
            s.v[q] = &P[ix[q]].v;
        }
        s.edges = (k == 1 && P[0].orig ? 1u : 0u) | (P[k].orig ? 2u : 0u) | (k + 2 == n && P[n - 1].orig ? 4u : 0u);
        s.t = t;
        mesh_scan_convert(mc, &s);
    }
}

void mesh_clip_and_draw(retro_mesh_ctx *mc, const mesh_tri *t, const mesh_snap *s3[3])
{
    const mesh_frame *f = &mc->f;
    unsigned any = s3[0]->out | s3[1]->out | s3[2]->out;
    if (s3[0]->out & s3[1]->out & s3[2]->out) {
        mc->st.clipped_out++;
        return;
    }
    if (!any) { /* inside every plane: the vertex stage's projection is the one clipping makes */
        mesh_sub s;
        for (int q = 0; q < 3; q++) {
            s.X[q] = s3[q]->X;
            s.Y[q] = s3[q]->Y;
            s.v[q] = &t->v[q];
        }
        s.edges = 7;
        s.t = t;
        mesh_scan_convert(mc, &s);
        return;
    }
    poly_vert a[MESH_MAXPOLY], b[MESH_MAXPOLY];
    poly_vert *src = a, *dst = b;
    for (int q = 0; q < 3; q++) {
        src[q].v = t->v[q];
        mesh_plane_distances(f, &src[q].v, src[q].d);
        src[q].orig = 1;
    }
    int n = 3;
    for (int p = 0; p < 6 && n >= 3; p++) {
        int out = 0;
        for (int i = 0; i < n; i++)
            out |= src[i].d[p] < 0;
        if (!out)
            continue;
        n = clip_plane(f, src, n, p, dst);
        poly_vert *tmp = src;
        src = dst;
        dst = tmp;
    }
    if (n < 3) {
        mc->st.clipped_out++;
        return;
    }
    draw_fan(mc, t, src, n);
}
